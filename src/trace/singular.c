/* Singular points in the whole trace: tangential points located and
 * classified, isolated contacts found in the unresolved cells, tangential
 * curves started, every branch out of a singular point followed. */
#include "trace_internal.h"
#include "common/vec3.h"
#include "local/pair_access.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Traces the curve through pt; a failure is listed in the report (then
 * IC_ERR_UNABLE), only running out of memory stops the trace. */
static ic_status start_curve(ic_trace_result *r, ic_tracer *tr, ic_pair *pair,
                             const ic_local_point *pt, const ic_trace_options *opt,
                             const char *what)
{
    ic_trace_point *pts;
    int n;
    ic_error e;
    const ic_status st = ic_trace_both_ways(r, tr, pair, pt, opt, &pts, &n, &e);
    if (st == IC_OK || st == IC_ERR_NOMEM)
        return st;
    double at[3];
    ic_frame_shown(&r->frame, pt->xyz, at);
    ic_trace_failure(&r->report, "%s through (%.6g, %.6g, %.6g): %s", what, at[0], at[1], at[2],
                     e.message);
    return IC_ERR_UNABLE;
}

/* Whether a traced curve or a recorded point passes within the cell's radius. */
int ic_trace_found_near(const ic_trace_result *r, const ic_unresolved *u)
{
    return ic_trace_point_near_found(r, u->xyz, u->radius);
}

/* Records a tangential point near `near`: located to full precision on the
 * collinear-normals condition (ic_local_locate_tangential, within reach) and
 * classified. Where the location fails, the point is dropped, or kept as
 * approximate when keep_unrefined. A point of a tangential curve starts the
 * trace of that curve instead (*curve: its index, else -1). */
/* The two preimages of a self-intersection point are one, to within
 * `tol` in parameters, modulo the sheet's periods and across its glued
 * edges (pairing_glue.c): (u, v) and (u, v + 2 pi) on a sheet periodic in
 * v are the same point of it (a figure-8 Klein bottle's cells beside the
 * domain's edge gave such pairs, recorded as unclassified tangential
 * points where the surface does not meet itself). */
static int one_preimage(const ic_pair *pair, const ic_local_point *pt, double tol)
{
    const double z[4] = {pt->params[0][0], pt->params[0][1], pt->params[1][0],
                         pt->params[1][1]};
    return ic_pairing_self_gap(ic_pair_pairing(pair), z) <= tol;
}

ic_status ic_trace_record_tangential(ic_trace_result *r, ic_tracer *tr, ic_pair *pair,
                                     const ic_local_point *near, double reach, int keep_unrefined,
                                     const ic_trace_options *opt, int *curve)
{
    *curve = -1;
    ic_local_point pt;
    ic_local_options lo = opt->local;
    int approximate = 0;
    if (ic_local_locate_tangential(pair, &pt, near, reach, &lo, NULL) != IC_OK) {
        if (!keep_unrefined)
            return IC_OK;
        pt = *near;
        approximate = 1;
    }
    /* a self-intersection's trivial solution: one preimage twice (every
     * point of the diagonal has parallel normals), also a period apart */
    if (ic_pair_is_self(pair) && one_preimage(pair, &pt, lo.distinct_params))
        return IC_OK;
    /* two surfaces that coincide around it: a region, not a point */
    if (ic_trace_in_coincident(r, pt.xyz))
        return IC_OK;
    if (!approximate && ic_trace_coincident_at(pair, &pt, r->scale))
        return ic_trace_add_coincident(r, pt.xyz) == 0 ? IC_OK : IC_ERR_NOMEM;
    ic_local_result res;
    if (!approximate &&
        ic_local_apparatus(pair, &res, &pt, opt->order, IC_METHOD_JET, &lo, NULL) == IC_OK &&
        res.type == IC_POINT_TANGENTIAL_CURVE && res.nbranches >= 1) {
        const int before = r->ncurves;
        const ic_status st = start_curve(r, tr, pair, &pt, opt, "the tangential curve");
        if (st != IC_OK || r->ncurves == before) /* failed, or a point of the boundary */
            return st == IC_ERR_NOMEM ? st : IC_OK;
        /* its shape is classified with the others after the joining */
        *curve = r->ncurves - 1;
        r->curves[*curve].tangential = 1;
        return IC_OK;
    }
    return ic_trace_add_special(r, pair, &pt, approximate, opt, NULL);
}

/* A branch's first point is tried at delta along it, then at a quarter of
 * that, up to this many times: in a domain or box narrower than delta
 * (a strip 7e-4 wide beside a branch point) the first tries lie outside. */
#define IC_TRACE_BRANCH_SHRINKS 6

/* The point to start branch br out of the singular point `at` in direction
 * sgn, a little way along it (second order): 1 found (*pt, transversal,
 * inside the domains and box), 0 none or a traced curve passes there. */
static int branch_start(const ic_trace_result *r, const ic_tracer *tr, ic_pair *pair,
                        const ic_local_point *at, const ic_branch *br, int sgn, double delta,
                        ic_local_options *lo, ic_local_point *pt)
{
    for (int shrink = 0; shrink <= IC_TRACE_BRANCH_SHRINKS; shrink++, delta *= 0.25) {
        double q[3], d[3], e[3];
        ic_axpy3(q, at->xyz, sgn * delta, br->t);
        if (br->frame_defined)
            ic_axpy3(q, q, 0.5 * delta * delta * br->kappa, br->n);
        if (ic_trace_curves_near(r, q, 0.25 * delta))
            return 0;
        if (ic_local_locate(pair, pt, q, lo, NULL) != IC_OK)
            continue;
        ic_axpy3(d, pt->xyz, -1.0, q);
        ic_axpy3(e, pt->xyz, -1.0, at->xyz);
        if (ic_norm3(d) > 0.25 * delta || ic_norm3(e) < 0.5 * delta || ic_tracer_outside(tr, pt))
            continue; /* the locator went elsewhere, or outside */
        ic_local_result there;
        return ic_local_apparatus(pair, &there, pt, 2, IC_METHOD_JET, lo, NULL) == IC_OK &&
               there.type == IC_POINT_TRANSVERSAL;
    }
    return 0;
}

/* Every branch out of every recorded singular point is traced, even when no
 * start candidate lay on it: a point a little way along each branch (second
 * order), in both directions, that no traced curve passes near, starts a
 * curve, which then ends at the singular point and is joined through it. */
ic_status ic_trace_complete_branches(ic_trace_result *r, ic_tracer *tr, ic_pair *pair,
                                     const ic_trace_options *opt)
{
    ic_local_options lo = opt->local;
    for (int k = 0; k < r->nspecials && !ic_trace_out_of_time(&r->budget); k++) {
        if (r->specials[k].approximate || r->specials[k].nbranches < 1)
            continue;
        if (!r->located[k].res_ok)
            continue;
        const ic_local_point at = r->located[k].pt;
        const ic_local_result res = r->located[k].res;
        for (int b = 0; b < res.nbranches; b++)
            for (int sgn = -1; sgn <= 1; sgn += 2) {
                const ic_branch *br = &res.branches[b];
                const double delta = fmin(20 * opt->chord, 0.2 / fmax(br->kappa, 1e-300));
                ic_local_point pt;
                if (!branch_start(r, tr, pair, &at, br, sgn, delta, &lo, &pt))
                    continue;
                if (start_curve(r, tr, pair, &pt, opt, "a branch out of a singular point") ==
                    IC_ERR_NOMEM)
                    return IC_ERR_NOMEM;
            }
    }
    return IC_OK;
}

/* A kind of tangential point that a tangential curve's own points can be
 * taken for (a branch point is a curve meeting it: kept), its own kind
 * included: a march's end beside the curve located onto it (the net's
 * search beside a sphere's tangential equator, tests/test_certificate_
 * crossings.c, recorded two, which the checker refuted as no singular
 * point before it could restart from the loop it saw untraced). */
static int point_of_tangential_curve(ic_point_type t)
{
    return t == IC_POINT_ISOLATED_CONTACT || t == IC_POINT_CUSP || t == IC_POINT_TACNODE ||
           t == IC_POINT_HIGHER_ORDER_CONTACT || t == IC_POINT_TANGENTIAL ||
           t == IC_POINT_TANGENTIAL_CURVE;
}

/* x lies within radius of a tangential curve, and of no curve's end and
 * no transversal curve (a crossing of the tangential curve, crossing.c,
 * where the transversal curve is joined through). */
static int inside_tangential(const ic_trace_result *r, const double *x, double radius)
{
    int on = 0;
    for (int c = 0; c < r->ncurves; c++) {
        const ic_trace_curve *cv = &r->curves[c];
        if (!cv->closed && (ic_dist3(cv->points[0].xyz, x) <= radius ||
                            ic_dist3(cv->points[cv->npoints - 1].xyz, x) <= radius))
            return 0;
        if (!cv->tangential &&
            ic_trace_polyline_distance(cv->points, cv->npoints, x, radius) <= radius)
            return 0;
        on = on || (cv->tangential &&
                    ic_trace_polyline_distance(cv->points, cv->npoints, x, radius) <= radius);
    }
    return on;
}

/* A point found on its own beside a tangential curve (located within
 * rounding of it, where the jet's classification sees the curve's
 * neighbourhood askew: a tacnode on a torus's contact circle) is that
 * curve's point. */
void ic_trace_drop_points_on_tangential(ic_trace_result *r, double radius)
{
    int n = 0;
    for (int k = 0; k < r->nspecials; k++) {
        const int keep = !point_of_tangential_curve(r->specials[k].type) ||
                         !inside_tangential(r, r->specials[k].xyz, radius);
        /* the curve ends' indices follow their points (no end is at a
         * dropped one: inside_tangential keeps the points at curve ends) */
        for (int c = 0; c < r->ncurves; c++)
            for (int e = 0; e < 2; e++)
                if (r->at[c][e] == k)
                    r->at[c][e] = keep ? n : -1;
        if (keep) {
            r->located[n] = r->located[k];
            r->specials[n++] = r->specials[k];
        }
    }
    r->nspecials = n;
}

/* Looks for a tangential point in an unresolved cell: this is how isolated
 * contacts, which have no curve to lead to them, are found. */
ic_status ic_trace_tangential_in_cell(ic_trace_result *r, ic_tracer *tr, ic_pair *pair,
                                      const ic_unresolved *u, const ic_trace_options *opt)
{
    int curve;
    ic_local_point near;
    memset(&near, 0, sizeof near);
    memcpy(near.xyz, u->xyz, sizeof near.xyz);
    memcpy(near.params, u->params, sizeof near.params);
    return ic_trace_record_tangential(r, tr, pair, &near, u->radius, 0, opt, &curve);
}
