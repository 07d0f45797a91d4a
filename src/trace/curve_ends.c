/*
 * One curve of the trace: marched both ways from a point, its ends finished
 * where they meet a tangential point (located precisely and recorded) or a
 * singular point of a surface, and added to the result. Below both the
 * pipeline's start candidates (candidates.c) and the singular points'
 * branches (singular.c), which trace their curves through it.
 */
#include "common/vec3.h"
#include "core/trace_constants.h"
#include "local/pair_access.h"
#include "crossing.h"
#include "curve_ends.h"
#include "march_ahead.h"
#include "trace_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Adds the curve of the points pts (the result's from now on, freed with it
 * even when this fails), its shape classified. */
static ic_status add_curve(ic_trace_result *r, ic_trace_point *pts, int n, int closed,
                           ic_trace_event e0, ic_trace_event e1, double shape_tol, int at0, int at1,
                           ic_error *err)
{
    const ic_shape shape = ic_trace_shape(pts, n, pts[n - 1].s - pts[0].s, shape_tol, 0);
    return ic_trace_add_shaped_curve(r, pts, n, closed, e0, e1, shape_tol, shape, at0, at1, err);
}

/* Out of memory where the curve goes on regardless: noted in the pair, for
 * ic_trace to answer (tests/test_nomem.c, "trace, implicit": a branch
 * point was left out). */
static void note_nomem(ic_pair *pair, ic_status st)
{
    (void)ic_pair_nomem_check(pair, ic_pair_nomem_count(pair), st, NULL);
}

/* The tangential point ahead of a curve end `near`; 0 when it cannot be
 * located (then the end is recorded approximately). Gauss-Newton on the
 * collinear normals within 1e-4 L (the march stops about 2e-6 L before a branch
 * point); where it fails (a tacnode, whose end stops about 2e-3 away and
 * where Gauss-Newton is ill-conditioned along the curve), or "converges"
 * next to a cusp (to about 1e-8 for u^3 = v^2, a point that classifies as a
 * branch point with two nearly tangent branches), the degenerate locator
 * decides. */
static int locate_end(ic_pair *pair, const ic_local_options *lopt, const ic_local_point *near,
                      ic_local_point *P)
{
    const double L = lopt->scale;
    if (ic_local_locate_tangential(pair, P, near, IC_TRACE_END_REACH * L, lopt, NULL) != IC_OK)
        return ic_local_locate_degenerate(pair, P, near, IC_TRACE_DEGENERATE_REACH * L, lopt,
                                          NULL) == IC_OK;
    ic_local_result q;
    ic_local_options o = *lopt;
    ic_local_point D;
    if (ic_local_apparatus(pair, &q, P, 2, IC_METHOD_AUTO, &o, NULL) == IC_OK &&
        q.type == IC_POINT_BRANCH && q.nbranches == 2 &&
        fabs(ic_dot3(q.branches[0].t, q.branches[1].t)) > 1 - 1e-3 &&
        ic_local_locate_degenerate(pair, &D, near, IC_TRACE_DEGENERATE_REACH * L, lopt, NULL) ==
            IC_OK)
        *P = D;
    return 1;
}

/* Records a singular point of a surface (once: within 1e-8 L of one
 * recorded) and appends it to the curve: the last step is straight to it
 * (the march stops where the point's neighbourhood begins). Returns its
 * special index, or -1 out of memory. */
static int end_at_surface_singular(ic_trace_result *r, ic_trace_point *pts, int *np,
                                   const double *X)
{
    int index = -1;
    for (int i = 0; i < r->nspecials && index < 0; i++) {
        double d[3];
        ic_axpy3(d, r->specials[i].xyz, -1.0, X);
        if (r->specials[i].type == IC_POINT_SURFACE_SINGULAR &&
            ic_norm3(d) <= IC_TRACE_ON_CURVE * r->scale)
            index = i;
    }
    if (index < 0) { /* a point known exactly, with no apparatus */
        if (ic_trace_add_exact_special(r, X, IC_POINT_SURFACE_SINGULAR) != 0)
            return -1;
        index = r->nspecials - 1;
    }
    /* the points nearer than IC_TRACE_SINGULAR_CLEARANCE L carry the
     * apparatus of a vanishing normal (errors about eps (L/d)^2) and go */
    int n = *np;
    while (n > 1) {
        double d[3];
        ic_axpy3(d, X, -1.0, pts[n - 1].xyz);
        if (ic_norm3(d) >= IC_TRACE_SINGULAR_CLEARANCE * r->scale)
            break;
        n--;
    }
    ic_trace_point *last = &pts[n - 1], *extra = &pts[n];
    *extra = *last;
    memcpy(extra->xyz, X, sizeof extra->xyz);
    extra->s = last->s + ic_trace_gap_length(last, last->t, extra, last->t);
    r->specials[index].nbranches++; /* half-branches now; halved after the joining */
    *np = n + 1;
    return index;
}

/* A curve's end this many chord heights or less before a singular point
 * located already, heading at it, ends there: the branches out of a point
 * start up to 20 chord heights from it (singular.c), and one started inside
 * the region where the normals are nearly parallel stops at once, beyond
 * the locator's reach (a strip 7e-4 wide beside a branch point). */
#define IC_TRACE_KNOWN_END_CHORDS 24
/* ... within this angle of the end's tangent (its cosine) */
#define IC_TRACE_KNOWN_END_COS 0.9

/* A curve's end this many chord heights or less beside a tangential curve
 * ends at the crossing of the two (crossing.c): the march stops where the
 * normals come parallel, 0.0046 to 0.008 (16 to 28 chord heights) short of
 * the crossing for circles across a sphere's tangential equator. */
#define IC_TRACE_CROSSING_CHORDS 64

/* The exact singular point ahead of the end `last`, as above: 1 and *P. */
static int known_end(const ic_trace_result *r, const ic_trace_point *last,
                     const ic_trace_options *opt, ic_local_point *P)
{
    const double reach = IC_TRACE_KNOWN_END_CHORDS * opt->chord;
    for (int k = 0; k < r->nspecials; k++) {
        if (r->specials[k].approximate || !r->located[k].res_ok)
            continue;
        double d[3];
        ic_axpy3(d, r->located[k].pt.xyz, -1.0, last->xyz);
        const double dist = ic_norm3(d);
        if (dist > 0.0 && dist <= reach && ic_dot3(d, last->t) >= IC_TRACE_KNOWN_END_COS * dist) {
            *P = r->located[k].pt;
            return 1;
        }
    }
    return 0;
}

/* The crossing of a tangential curve beside the end `last` (crossing.c),
 * when it lies ahead of the end as known_end asks of a point: 1, *P and
 * *place. */
static int crossing_ahead(ic_pair *pair, const ic_trace_options *opt, const ic_local_point *near,
                          const ic_trace_point *last, ic_local_point *P, double *place)
{
    if (!ic_trace_locate_crossing(pair, &opt->local, near, IC_TRACE_CROSSING_CHORDS * opt->chord,
                                  P, place))
        return 0;
    double d[3];
    ic_axpy3(d, P->xyz, -1.0, last->xyz);
    const double dist = ic_norm3(d);
    if (dist == 0.0 || ic_dot3(d, last->t) >= IC_TRACE_KNOWN_END_COS * dist)
        return 1;
    *place = -1.0;
    return 0;
}

/* A curve end at a tangential point: the point located precisely, appended
 * (the last step, about 2e-5, is straight to 1e-16) with the apparatus of
 * the branch continuing the curve, and recorded. Returns the special index,
 * or -1 (then the end is recorded approximately). */
static int finish_end(ic_trace_result *r, ic_pair *pair, const ic_trace_options *opt,
                      ic_trace_point *pts, int *np)
{
    const int n = *np;
    ic_trace_point *last = &pts[n - 1], *extra = &pts[n];
    ic_local_point near, P;
    memset(&near, 0, sizeof near);
    memcpy(near.xyz, last->xyz, sizeof near.xyz);
    memcpy(near.params, last->params, sizeof near.params);
    int index = -1;
    double place = -1.0; /* not known: measured where it is a contact */
    if (!crossing_ahead(pair, opt, &near, last, &P, &place) &&
        !locate_end(pair, &opt->local, &near, &P) && !known_end(r, last, opt, &P)) {
        double X[3];
        if (ic_trace_locate_surface_singular(pair, near.xyz, r->scale, X)) {
            index = end_at_surface_singular(r, pts, np, X);
            if (index < 0)
                note_nomem(pair, IC_ERR_NOMEM);
            return index;
        }
        note_nomem(pair, ic_trace_add_special(r, pair, &near, 1, opt, NULL));
        return -1;
    }
    /* classified once, where it was first recorded */
    const ic_status added = ic_trace_add_placed_special(r, pair, &P, 0, place, opt, &index);
    note_nomem(pair, added);
    if (added != IC_OK || !r->located[index].res_ok)
        return -1;
    const ic_local_result res = r->located[index].res;
    double d[3];
    ic_axpy3(d, P.xyz, -1.0, last->xyz);
    *extra = *last;
    extra->s = last->s + ic_norm3(d);
    memcpy(extra->xyz, P.xyz, sizeof P.xyz);
    memcpy(extra->params, P.params, sizeof P.params);
    extra->angle = res.angle;
    /* the branch through P that continues the curve: the nearest tangent
     * line, then (at a tacnode, where the branches share it) the nearest
     * curvature vector c'' = kappa n, which does not depend on orientation */
    int best = -1;
    double bd = -1;
    for (int b = 0; b < res.nbranches; b++) {
        const ic_branch *br = &res.branches[b];
        double dk[3] = {0, 0, 0};
        if (br->frame_defined)
            ic_scale3(dk, br->n, br->kappa);
        if (last->frame_defined)
            ic_axpy3(dk, dk, -last->kappa, last->n);
        const double score = fabs(ic_dot3(br->t, last->t)) - 1e-6 * ic_norm3(dk);
        if (score > bd)
            bd = score, best = b;
    }
    if (best >= 0 && res.branches[best].regular) {
        const ic_branch *br = &res.branches[best];
        const double sg = ic_dot3(br->t, last->t) < 0 ? -1.0 : 1.0;
        ic_scale3(extra->t, br->t, sg);
        memcpy(extra->n, br->n, sizeof extra->n);
        ic_scale3(extra->b, br->b, sg);
        extra->kappa = br->kappa;
        extra->tau = br->tau;
        extra->frame_defined = br->frame_defined;
        /* the arc length of the last step, end-corrected (join.c) */
        extra->s = last->s + ic_trace_gap_length(last, last->t, extra, extra->t);
        ic_trace_refit_near_special(pts, n, br, sg);
    } else if (best >= 0 && res.type == IC_POINT_CUSP) {
        /* the last gap to a cusp: along the cusp's tangent T the arc is
         * y = a x^(3/2), whose length from 0 to x is
         * 8/(27 a^2) ((1 + 9 a^2 x/4)^(3/2) - 1) (the chord misses d^2/16) */
        double e[3], T[3];
        ic_axpy3(e, last->xyz, -1.0, P.xyz);
        memcpy(T, res.branches[best].t, sizeof T);
        const double x = fabs(ic_dot3(e, T));
        ic_axpy3(e, e, -ic_dot3(e, T), T);
        const double y = ic_norm3(e), a2 = x > 0 ? y * y / (x * x * x) : 0.0;
        const double arc = a2 * x > 1e-12 ? 8 / (27 * a2) * (pow(1 + 2.25 * a2 * x, 1.5) - 1) : x;
        extra->s = last->s + arc;
        /* at the cusp itself: the one-sided tangent along the arrival, the
         * curvature infinite, no n, b or torsion (written null; before, the
         * neighbour's finite kappa and frame were copied here) */
        const double sg = ic_dot3(T, last->t) < 0 ? -1.0 : 1.0;
        ic_scale3(extra->t, T, sg);
        extra->kappa = NAN;
        extra->tau = NAN;
        extra->frame_defined = 0;
    }
    *np = n + 1;
    return index;
}

/* A curve stopped at IC_TRACE_BUDGET: by the time limit or by its points. */
static void report_budget(ic_trace_result *r, const ic_trace_options *opt,
                          const ic_local_point *pt, const char *way)
{
    double at[3];
    ic_frame_shown(&r->frame, pt->xyz, at);
    if (ic_trace_out_of_time(&r->budget))
        ic_trace_failure(&r->report, "curve from (%g, %g, %g)%s: stopped at the time limit",
                         at[0], at[1], at[2], way);
    else
        ic_trace_failure(&r->report, "curve from (%g, %g, %g)%s: stopped at the budget of %d points",
                         at[0], at[1], at[2], way, opt->max_points);
}

/* The curve of the marches m from pt (ic_trace_march_both) into a new
 * curve of r: its ends located and recorded, the failures listed; the
 * points are taken from m. */
ic_status ic_trace_add_marches(ic_trace_result *r, ic_pair *pair, const ic_local_point *pt,
                               const ic_trace_options *opt, ic_trace_marches *m,
                               ic_trace_point **pts_out, int *n_out, ic_error *err)
{
    const ic_trace_event e1 = m->e[0], e0 = m->e[1];
    /* out of memory ends the trace, never just this curve */
    if (m->st[0] != IC_OK && (e1 != IC_TRACE_FAILED || m->st[0] == IC_ERR_NOMEM)) {
        if (err)
            *err = m->err[0];
        return m->st[0];
    }
    double at[3];
    ic_frame_shown(&r->frame, pt->xyz, at);
    if (m->st[0] != IC_OK)
        ic_trace_failure(&r->report, "curve from (%g, %g, %g): %s", at[0], at[1], at[2],
                         err ? m->err[0].message : "failed");
    if (e1 == IC_TRACE_BUDGET)
        report_budget(r, opt, pt, "");
    int n1 = m->n[0];
    ic_trace_point *fwd = m->pts[0];
    m->pts[0] = NULL;
    int at1 = -1, at0 = -1;
    if (e1 == IC_TRACE_TANGENTIAL)
        at1 = finish_end(r, pair, opt, fwd, &n1);
    if (e1 == IC_TRACE_CLOSED) {
        *pts_out = fwd;
        *n_out = n1;
        return add_curve(r, fwd, n1, 1, e1, e1, opt->shape_tol, -1, -1, err);
    }
    if (m->st[1] == IC_ERR_NOMEM) {
        free(fwd);
        if (err)
            *err = m->err[1];
        return IC_ERR_NOMEM;
    }
    if (m->st[1] != IC_OK)
        ic_trace_failure(&r->report, "curve from (%g, %g, %g), backwards: %s", at[0], at[1],
                         at[2], err ? m->err[1].message : "failed");
    if (e0 == IC_TRACE_BUDGET)
        report_budget(r, opt, pt, ", backwards");
    int n0 = m->n[1];
    ic_trace_point *back = m->pts[1];
    m->pts[1] = NULL;
    if (e0 == IC_TRACE_TANGENTIAL)
        at0 = finish_end(r, pair, opt, back, &n0);
    ic_trace_point *all = malloc((size_t)(n0 + n1 - 1) * sizeof *all);
    if (!all) {
        free(fwd);
        free(back);
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory");
    }
    /* the backward part reversed: order, orientation (t, b) and arc length
     * (its start, s = 0, becomes its end, S0) */
    const double S0 = back[n0 - 1].s - back[0].s;
    memcpy(all, back, (size_t)n0 * sizeof *all);
    ic_trace_points_reverse(all, n0);
    for (int i = 1; i < n1; i++) {
        all[n0 - 1 + i] = fwd[i];
        all[n0 - 1 + i].s += S0;
    }
    free(fwd);
    free(back);
    *pts_out = all;
    *n_out = n0 + n1 - 1;
    /* a start point that leaves the region both ways at once is a point of
     * its boundary, not a curve: no zero-length one-point curve */
    if (n0 + n1 - 1 < 2 && e0 != IC_TRACE_TANGENTIAL && e1 != IC_TRACE_TANGENTIAL) {
        free(all);
        *pts_out = NULL;
        *n_out = 0;
        return IC_OK;
    }
    return add_curve(r, all, n0 + n1 - 1, 0, e0, e1, opt->shape_tol, at0, at1, err);
}

/* Traces the curve through pt: forward, and backward unless it closed. */
ic_status ic_trace_both_ways(ic_trace_result *r, ic_tracer *tr, ic_pair *pair,
                             const ic_local_point *pt, const ic_trace_options *opt,
                             ic_trace_point **pts_out, int *n_out, ic_error *err)
{
    ic_trace_marches m;
    ic_status st = ic_trace_march_both(tr, pt, &m, err);
    if (st == IC_OK)
        st = ic_trace_add_marches(r, pair, pt, opt, &m, pts_out, n_out, err);
    ic_trace_marches_free(&m);
    return st;
}
