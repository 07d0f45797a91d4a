/* Adding to the result of a trace and reading it: curves, special points
 * (classified by the local analysis where they were located), points where
 * the surfaces coincide, the failure list, and the public accessors. */
#include "common/vec3.h"
#include "curve_index.h"
#include "local/pair_access.h"
#include "result.h"
#include "trace_constants.h"

#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void ic_trace_failure(ic_trace_report *rep, const char *fmt, ...)
{
    if (rep->nfailures >= IC_TRACE_MAX_FAILURES)
        return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(rep->failures[rep->nfailures++], sizeof rep->failures[0], fmt, ap);
    va_end(ap);
}

static int is_contact(ic_point_type t)
{
    return t == IC_POINT_ISOLATED_CONTACT || t == IC_POINT_HIGHER_ORDER_CONTACT;
}

/* A point located only to within radius (above IC_TRACE_PLACE_REL L for a
 * contact, IC_TRACE_CROSSING_PLACE_REL L for a crossing): approximate, and
 * the report says why. */
static void not_placed(ic_trace_result *r, ic_trace_special *s, ic_trace_located *loc,
                       double radius, const char *why)
{
    s->approximate = 1;
    loc->place_radius = radius;
    double at[3];
    ic_frame_shown(&r->frame, s->xyz, at);
    ic_trace_failure(&r->report,
                     "a contact point near (%.6g, %.6g, %.6g) is located only to about %.2g (%s): "
                     "its place and type are approximate",
                     at[0], at[1], at[2], radius, why);
}

/* An isolated contact is located by Gauss-Newton on a root of multiplicity
 * m - 1 (m its order): where its formulas cancel, only to the radius where
 * the residuals sink into rounding (ic_local_tangential_place). The point is
 * classified again knowing that radius (a quadratic part that a shift this
 * small could make is no contact term) and, beyond IC_TRACE_PLACE_REL, it is
 * approximate and the report says so. */
static void check_contact_place(ic_trace_result *r, ic_trace_special *s, ic_trace_located *loc,
                                ic_pair *pair, ic_local_options *o)
{
    double radius;
    if (!is_contact(s->type) || ic_local_tangential_place(pair, &loc->pt, o, &radius, NULL) != IC_OK)
        return;
    if (radius > o->place_tol) {
        o->place_tol = radius;
        ic_local_result res;
        if (ic_local_apparatus(pair, &res, &loc->pt, 3, IC_METHOD_AUTO, o, NULL) == IC_OK) {
            loc->res = res;
            s->type = res.type;
            s->nbranches = res.nbranches;
        }
    }
    if (radius > IC_TRACE_PLACE_REL * r->scale)
        not_placed(r, s, loc, radius, "a contact of high order, a multiple root");
}

/* Room for one more special point (and its located record): 0, or -1 out
 * of memory. */
static int grow_specials(ic_trace_result *r)
{
    if (r->nspecials < r->caps)
        return 0;
    const int cap = r->caps ? 2 * r->caps : 8;
    ic_trace_special *p = realloc(r->specials, (size_t)cap * sizeof *p);
    if (p)
        r->specials = p;
    ic_trace_located *q = realloc(r->located, (size_t)cap * sizeof *q);
    if (q)
        r->located = q;
    if (!p || !q)
        return -1;
    r->caps = cap;
    return 0;
}

/* The first of the points 0 .. n - 1 that is the same as xyz (within
 * IC_TRACE_SAME_APPROX L when either is approximate; two crossings, xyz's
 * known to place, within IC_TRACE_SAME_PLACES of their places), or -1. */
static int same_special(const ic_trace_result *r, int n, const double xyz[3], int approximate,
                        double place)
{
    for (int i = 0; i < n; i++) {
        double d[3];
        ic_axpy3(d, r->specials[i].xyz, -1.0, xyz);
        double same = (r->specials[i].approximate || approximate ? IC_TRACE_SAME_APPROX
                                                                  : IC_TRACE_SAME_EXACT) *
                      r->scale;
        if (place >= 0 && r->located[i].crossing) /* two crossings */
            same = fmax(same, IC_TRACE_SAME_PLACES * fmax(place, r->located[i].place_radius));
        if (ic_norm3(d) < same)
            return i;
    }
    return -1;
}

/* The first of the points before n that cannot be told from the
 * approximate contact n: within IC_TRACE_SAME_APPROX L, or within twice
 * the sum of the radii both are located to (ic_local_tangential_place
 * gives them "about"); -1 when none. */
static int same_approximate(const ic_trace_result *r, int n)
{
    for (int i = 0; i < n; i++) {
        double d[3];
        ic_axpy3(d, r->specials[i].xyz, -1.0, r->specials[n].xyz);
        const double reach = 2.0 * (r->located[i].place_radius + r->located[n].place_radius);
        if (ic_norm3(d) < fmax(IC_TRACE_SAME_APPROX * r->scale, reach))
            return i;
    }
    return -1;
}

ic_status ic_trace_add_special(ic_trace_result *r, ic_pair *pair, const ic_local_point *pt,
                               int approximate, const ic_trace_options *opt, int *index)
{
    return ic_trace_add_placed_special(r, pair, pt, approximate, -1.0, opt, index);
}

ic_status ic_trace_add_placed_special(ic_trace_result *r, ic_pair *pair, const ic_local_point *pt,
                                      int approximate, double place, const ic_trace_options *opt,
                                      int *index)
{
    int dummy;
    if (!index)
        index = &dummy;
    const int earlier = same_special(r, r->nspecials, pt->xyz, approximate, place);
    if (earlier >= 0) { /* the same point met from another curve */
        *index = earlier;
        return IC_OK;
    }
    *index = r->nspecials;
    if (grow_specials(r) != 0)
        return IC_ERR_NOMEM;
    ic_trace_located *loc = &r->located[r->nspecials];
    loc->pt = *pt;
    loc->place_radius = 0.0;
    loc->crossing = 0;
    ic_trace_special *s = &r->specials[r->nspecials++];
    memcpy(s->xyz, pt->xyz, sizeof s->xyz);
    s->approximate = approximate;
    /* classify: at a curve end the point is just off the tangential point,
     * so the threshold is relaxed there (docs/tracing.md) */
    ic_local_options o = opt->local;
    if (approximate)
        o.tangential_angle = IC_TRACE_APPROX_TANGENTIAL_ANGLE;
    else /* located to a few units in the last place of L */
        o.place_tol = fmax(IC_TRACE_PLACE_ULPS * DBL_EPSILON * r->scale, place);
    /* order 12: the branches' series also serve the curve points nearby
     * (ic_trace_refit_near_special) */
    loc->res_ok = ic_local_apparatus(pair, &loc->res, pt, 12, IC_METHOD_AUTO, &o, NULL) == IC_OK;
    /* a contact of high order has fewer valid orders: its branches to 3 */
    if (!loc->res_ok)
        loc->res_ok = ic_local_apparatus(pair, &loc->res, pt, 3, IC_METHOD_AUTO, &o, NULL) == IC_OK;
    if (loc->res_ok) {
        s->type = loc->res.type;
        s->nbranches = loc->res.nbranches;
        if (!approximate) {
            loc->crossing = place >= 0;
            if (place >= 0)
                loc->place_radius = place;
            if (place < 0) /* the place not known: measured */
                check_contact_place(r, s, loc, pair, &o);
            else if (place > IC_TRACE_CROSSING_PLACE_REL * r->scale)
                not_placed(r, s, loc, place,
                           "a crossing of a tangential curve, its bend's bracket that wide");
            /* located only approximately: the same as a point met before
             * within IC_TRACE_SAME_APPROX L or within both places' radii */
            const int j = s->approximate ? same_approximate(r, *index) : -1;
            if (j >= 0) {
                r->nspecials--;
                *index = j;
            }
        }
    } else if (ic_pairing_point_may_degenerate(ic_pair_pairing(pair), pt->xyz, pt->params,
                                               IC_TRACE_SINGULAR_CLEARANCE)) {
        /* where the parametrization degenerates (R_u x R_v = 0: the pinch
         * point of Whitney's umbrella) the surface itself is singular; its
         * exact place is not located */
        s->type = IC_POINT_SURFACE_SINGULAR;
        s->nbranches = 0;
        s->approximate = 1;
    } else { /* not classified: kept as an approximate place, and said */
        s->type = IC_POINT_TANGENTIAL;
        s->nbranches = 0;
        s->approximate = 1;
        double at[3];
        ic_frame_shown(&r->frame, s->xyz, at);
        ic_trace_failure(&r->report,
                         "a tangential point near (%.6g, %.6g, %.6g) could not be classified",
                         at[0], at[1], at[2]);
    }
    return IC_OK;
}

int ic_trace_add_exact_special(ic_trace_result *r, const double *xyz, ic_point_type type)
{
    if (grow_specials(r) != 0)
        return -1;
    ic_trace_located *loc = &r->located[r->nspecials];
    memset(loc, 0, sizeof *loc);
    memcpy(loc->pt.xyz, xyz, sizeof loc->pt.xyz);
    ic_trace_special *s = &r->specials[r->nspecials++];
    memset(s, 0, sizeof *s);
    memcpy(s->xyz, xyz, sizeof s->xyz);
    s->type = type;
    return 0;
}

ic_status ic_trace_add_shaped_curve(ic_trace_result *r, ic_trace_point *pts, int n, int closed,
                                    ic_trace_event e0, ic_trace_event e1, double shape_tol,
                                    ic_shape shape, int at0, int at1, ic_error *err)
{
    if (r->ncurves == r->capc) {
        const int cap = r->capc ? 2 * r->capc : 8;
        ic_trace_curve *c = realloc(r->curves, (size_t)cap * sizeof *c);
        ic_trace_point **s = realloc(r->storage, (size_t)cap * sizeof *s);
        int(*at)[2] = realloc(r->at, (size_t)cap * sizeof *at);
        if (c)
            r->curves = c;
        if (s)
            r->storage = s;
        if (at)
            r->at = at;
        if (!c || !s || !at) { /* (tests/test_nomem.c, "trace, mixed": pts leaked) */
            free(pts);
            return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory adding a curve");
        }
        r->capc = cap;
    }
    r->at[r->ncurves][0] = at0;
    r->at[r->ncurves][1] = at1;
    ic_trace_curve *c = &r->curves[r->ncurves];
    r->storage[r->ncurves++] = pts;
    memset(c, 0, sizeof *c);
    c->closed = closed;
    c->npoints = n;
    c->points = pts;
    c->length = pts[n - 1].s - pts[0].s;
    c->ends[0] = e0;
    c->ends[1] = e1;
    c->shape_tol = shape_tol;
    c->shape = shape;
    if (r->index && ic_curve_index_add(r->index, r->ncurves - 1, pts, n) != 0)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory indexing a curve");
    return IC_OK;
}

int ic_trace_add_coincident(ic_trace_result *r, const double *x)
{
    if (r->ncoincident == r->capk) {
        const int cap = r->capk ? 2 * r->capk : 16;
        double(*p)[3] = realloc(r->coincident, (size_t)cap * sizeof *p);
        if (!p)
            return -1;
        r->coincident = p;
        r->capk = cap;
    }
    memcpy(r->coincident[r->ncoincident++], x, 3 * sizeof *x);
    return 0;
}

int ic_trace_in_coincident(const ic_trace_result *r, const double *x)
{
    const double reach = IC_TRACE_COINCIDENT_REACH * r->scale;
    for (int k = 0; k < r->ncoincident; k++) {
        double d[3];
        ic_axpy3(d, r->coincident[k], -1.0, x);
        if (ic_norm3(d) <= reach)
            return 1;
    }
    return 0;
}

void ic_trace_result_free(ic_trace_result *r)
{
    if (!r)
        return;
    for (int i = 0; i < r->ncurves; i++)
        free(r->storage[i]);
    free(r->storage);
    free(r->curves);
    free(r->at);
    free(r->specials);
    free(r->located);
    free(r->deferred);
    free(r->coincident);
    free(r->certificate);
    ic_curve_index_free(r->index);
    free(r->deferred_why);
    /* the fits are the curve layer's (ic_trace_fit), freed as it says; the
     * workers live only during ic_trace, which frees them */
    if (r->fits && r->free_fits)
        r->free_fits(r->fits, r->ncurves);
    free(r);
}

const ic_curve_fit *ic_trace_result_fit(const ic_trace_result *r, int i)
{
    return r && r->fits && i >= 0 && i < r->ncurves ? r->fits[i] : NULL;
}

int ic_trace_result_num_curves(const ic_trace_result *r) { return r ? r->ncurves : 0; }

const ic_trace_curve *ic_trace_result_curve(const ic_trace_result *r, int i)
{
    return r && i >= 0 && i < r->ncurves ? &r->curves[i] : NULL;
}

int ic_trace_result_num_specials(const ic_trace_result *r) { return r ? r->nspecials : 0; }

const ic_trace_special *ic_trace_result_special(const ic_trace_result *r, int i)
{
    return r && i >= 0 && i < r->nspecials ? &r->specials[i] : NULL;
}

const ic_trace_report *ic_trace_result_report(const ic_trace_result *r)
{
    return r ? &r->report : NULL;
}

const char *ic_trace_result_certificate(const ic_trace_result *r)
{
    return r ? r->certificate : NULL;
}

/* The report's method (ic_trace_report.method): the search's, and this
 * file's. */
const char ic_trace_method_search[] = "search";
