/*
 * The whole intersection (ic_trace): every start candidate not yet covered by
 * a traced curve starts one, traced in both directions; tangential curve ends
 * are located and recorded. The singular points (singular.c), the joining
 * (join.c) and the shapes (shape.c) have their own files.
 */
#include "common/args.h"
#include "core/trace_constants.h"
#include "exact/exact.h"
#include "trace_internal.h"
#include "march_ahead.h"
#include "workers.h"
#include "common/vec3.h"
#include "local/local_internal.h"

#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Marks the candidates within radius of the point x as covered. */
static void cover_point(ic_candidate *c, int n, const double *x, double radius)
{
    ic_trace_point one;
    memset(&one, 0, sizeof one);
    memcpy(one.xyz, x, sizeof one.xyz);
    ic_trace_cover(c, n, &one, 1, radius);
}

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
    (void)ic_pair_nomem_check(pair, pair->nomem, st, NULL);
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
    if (!locate_end(pair, &opt->local, &near, &P)) {
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
    const ic_status added = ic_trace_add_special(r, pair, &P, 0, opt, &index);
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
    if (ic_trace_out_of_time(&r->budget))
        ic_trace_failure(&r->report, "curve from (%g, %g, %g)%s: stopped at the time limit",
                         pt->xyz[0], pt->xyz[1], pt->xyz[2], way);
    else
        ic_trace_failure(&r->report, "curve from (%g, %g, %g)%s: stopped at the budget of %d points",
                         pt->xyz[0], pt->xyz[1], pt->xyz[2], way, opt->max_points);
}

/* The curve of the marches m from pt (ic_trace_march_both) into a new
 * curve of r: its ends located and recorded, the failures listed; the
 * points are taken from m. */
static ic_status add_marches(ic_trace_result *r, ic_pair *pair, const ic_local_point *pt,
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
    if (m->st[0] != IC_OK)
        ic_trace_failure(&r->report, "curve from (%g, %g, %g): %s", pt->xyz[0], pt->xyz[1],
                         pt->xyz[2], err ? m->err[0].message : "failed");
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
        ic_trace_failure(&r->report, "curve from (%g, %g, %g), backwards: %s", pt->xyz[0],
                         pt->xyz[1], pt->xyz[2], err ? m->err[1].message : "failed");
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
        st = add_marches(r, pair, pt, opt, &m, pts_out, n_out, err);
    ic_trace_marches_free(&m);
    return st;
}

/* Traces a curve from every start candidate that no curve traced so far
 * covers; a tangential candidate is recorded (or its tangential curve
 * traced). */
static int defer_failure(ic_trace_result *r, const ic_candidate *c, const char *why)
{
    if (r->ndeferred == r->capd) {
        const int cap = r->capd ? 2 * r->capd : 8;
        ic_candidate *p = realloc(r->deferred, (size_t)cap * sizeof *p);
        if (p)
            r->deferred = p;
        char(*q)[200] = realloc(r->deferred_why, (size_t)cap * sizeof *q);
        if (q)
            r->deferred_why = q;
        if (!p || !q)
            return -1;
        r->capd = cap;
    }
    r->deferred[r->ndeferred] = *c;
    snprintf(r->deferred_why[r->ndeferred++], sizeof r->deferred_why[0], "%s", why);
    return 0;
}

/* The deferred start candidates that nothing traced passes near, listed
 * (one per place). */
static void list_deferred(ic_trace_result *r, double radius)
{
    for (int i = 0; i < r->ndeferred; i++) {
        const double *x = r->deferred[i].xyz;
        int dup = 0;
        for (int j = 0; j < i && !dup; j++) {
            double d[3];
            ic_axpy3(d, r->deferred[j].xyz, -1.0, x);
            dup = ic_norm3(d) <= 1e-10 * (r->scale + ic_norm3(x));
        }
        if (!dup && !ic_trace_point_near_found(r, x, radius))
            ic_trace_failure(&r->report, "start candidate (%g, %g, %g): %s", x[0], x[1], x[2],
                             r->deferred_why[i]);
    }
}

/* Whether x lies within gap of a curve end that left a parameter domain
 * (at a pole of a parametrization, say): the joining bridges that gap
 * (ic_trace_join_curves, max_gap), and a curve started there would be a
 * sliver of the same curve. */
static int in_pole_gap(const ic_trace_result *r, const double *x, double gap)
{
    for (int c = 0; c < r->ncurves; c++)
        for (int e = 0; e < 2; e++) {
            const ic_trace_curve *cv = &r->curves[c];
            if (cv->closed || cv->ends[e] != IC_TRACE_LEFT_DOMAIN)
                continue;
            double d[3];
            ic_axpy3(d, cv->points[e ? cv->npoints - 1 : 0].xyz, -1.0, x);
            if (ic_norm3(d) <= gap)
                return 1;
        }
    return 0;
}

/* An exact (located) singular point within bound of x. */
static int near_exact_special(const ic_trace_result *r, const double *x, double bound)
{
    for (int k = 0; k < r->nspecials; k++) {
        double d[3];
        ic_axpy3(d, r->specials[k].xyz, -1.0, x);
        if (!r->specials[k].approximate && ic_norm3(d) <= bound)
            return 1;
    }
    return 0;
}

/* A parametric sheet degenerate at pt (R_u x R_v = 0, a pole): its
 * parameters moved IC_TRACE_POLE_NUDGE_REL of the domain along a parameter
 * to where the normal exists, and pt's position with them. 0 when no sheet
 * is degenerate there or no nudge helps. */
static int nudge_off_pole(ic_pair *pair, ic_local_point *pt)
{
    for (int s = 0; s < 2; s++) {
        ic_surface *S = ic_pair_surface(pair, s);
        ic_surface_geometry g;
        if (ic_surface_get_kind(S) != IC_PARAMETRIC ||
            ic_surface_normal_at(S, &g, pt->params[s], NULL) == IC_OK)
            continue;
        double dom[2][2];
        ic_surface_get_domain(S, dom, NULL);
        for (int k = 0; k < 4; k++) { /* +v, -v, +u, -u */
            const int i = k < 2 ? 1 : 0;
            const double width = isfinite(dom[i][1] - dom[i][0]) ? dom[i][1] - dom[i][0] : 1;
            double uv[2] = {pt->params[s][0], pt->params[s][1]}, x[3];
            uv[i] += (k % 2 ? -1 : 1) * IC_TRACE_POLE_NUDGE_REL * width;
            if (uv[i] < dom[i][0] || uv[i] > dom[i][1] ||
                ic_surface_normal_at(S, &g, uv, NULL) != IC_OK ||
                ic_surface_eval(S, x, uv, NULL) != IC_OK)
                continue;
            memcpy(pt->params[s], uv, sizeof uv);
            memcpy(pt->xyz, x, sizeof x);
            return 1;
        }
    }
    return 0;
}

/* A candidate the locator refused because a parametrisation degenerates
 * there (a contact at a sphere's pole): classified from just beside the
 * pole, as an approximate point at the candidate's place. 1 if recorded. */
static int record_at_pole(ic_trace_result *r, ic_pair *pair, const ic_candidate *c,
                          const ic_trace_options *opt, ic_status *st)
{
    ic_local_point pt;
    memset(&pt, 0, sizeof pt);
    memcpy(pt.xyz, c->xyz, sizeof pt.xyz);
    memcpy(pt.params, c->params, sizeof pt.params);
    if (!nudge_off_pole(pair, &pt))
        return 0;
    /* only a contact: curves through a pole are joined across it
     * (in_pole_gap), and nothing but the search leads to a contact */
    ic_local_options o = opt->local;
    o.tangential_angle = 1e-3; /* as for any approximate point (ic_trace_add_special) */
    ic_local_result res;
    if (ic_local_apparatus(pair, &res, &pt, 3, IC_METHOD_AUTO, &o, NULL) != IC_OK ||
        (res.type != IC_POINT_ISOLATED_CONTACT && res.type != IC_POINT_HIGHER_ORDER_CONTACT))
        return 0;
    int index = -1;
    *st = ic_trace_add_special(r, pair, &pt, 1, opt, &index);
    if (*st != IC_OK || index < 0)
        return 0;
    memcpy(r->specials[index].xyz, c->xyz, sizeof c->xyz);
    return 1;
}

/* A candidate the locator refused (a pole's many preimages, say):
 * recorded at the pole, or deferred with the locator's reason. */
static ic_status unlocated_candidate(ic_trace_result *r, ic_pair *pair, ic_candidate *cand,
                                     int nc, int i, const ic_trace_options *opt, const char *why,
                                     ic_error *err)
{
    /* the candidates at the same place would fail the same way: one is kept */
    cover_point(cand, nc, cand[i].xyz, 1e-10 * (r->scale + ic_norm3(cand[i].xyz)));
    cand[i].covered = 1;
    ic_status st = IC_OK;
    if (record_at_pole(r, pair, &cand[i], opt, &st)) {
        cover_point(cand, nc, cand[i].xyz, fmax(2 * opt->chord, 2 * r->report.cell_size));
        return st;
    }
    if (st == IC_OK && defer_failure(r, &cand[i], why) != 0)
        st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory");
    return st;
}

/* A tangential candidate: recorded (or its tangential curve traced), and
 * covered around it; beside a singular point already located (a finer
 * search's Newton lands there) it is that point. */
static ic_status tangential_candidate(ic_trace_result *r, ic_tracer *tr, ic_pair *pair,
                                      ic_candidate *cand, int nc, const ic_local_point *pt,
                                      const ic_trace_options *opt, ic_error *err)
{
    const double radius = IC_TRACE_ON_CURVE * r->scale;
    const double near_point = 2 * opt->chord; /* beside a singular point */
    if (near_exact_special(r, pt->xyz, fmax(near_point, 2 * r->first_cell_size)) ||
        ic_trace_in_coincident(r, pt->xyz))
        return IC_OK;
    /* surfaces that coincide around it: a region, not a point */
    if (ic_trace_coincident_at(pair, pt, r->scale))
        return ic_trace_add_coincident(r, pt->xyz) != 0
                   ? ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory")
                   : IC_OK;
    int curve;
    /* within about a first-search cell (in space) */
    const double reach = 4 * r->scale / (1 << opt->depth) + 1e-7 * r->scale;
    const ic_status st = ic_trace_record_tangential(r, tr, pair, pt, reach, 1, opt, &curve);
    cover_point(cand, nc, pt->xyz, fmax(near_point, 2 * r->report.cell_size));
    if (curve >= 0)
        ic_trace_cover(cand, nc, r->curves[curve].points, r->curves[curve].npoints, radius);
    return st;
}

/* The curve through candidate i marched ahead or, if it was not, here. */
static ic_status trace_candidate(ic_trace_result *r, ic_tracer *tr, ic_pair *pair,
                                 const ic_local_point *pt, ic_trace_ahead *ahead,
                                 const ic_trace_options *opt, ic_trace_point **pts, int *n,
                                 ic_error *err)
{
    if (!ahead || !ahead->valid)
        return ic_trace_both_ways(r, tr, pair, pt, opt, pts, n, err);
    const ic_status st = add_marches(r, pair, pt, opt, &ahead->m, pts, n, err);
    ic_trace_marches_free(&ahead->m);
    ahead->valid = 0;
    return st;
}

ic_status ic_trace_from_candidates(ic_trace_result *r, ic_tracer *tr, ic_pair *pair,
                                   ic_candidate *cand, int nc, const ic_trace_options *opt,
                                   ic_error *err)
{
    /* a start candidate is a point of the intersection (Newton converged
     * there): it lies on a traced curve when within the curve's sagitta
     * (ic_trace_polyline_distance) and this fraction of L. A wider radius
     * would take a second curve beside the first for the first. */
    const double radius = IC_TRACE_ON_CURVE * r->scale;
    /* with threads, candidates marched ahead (none where this fails) */
    ic_trace_ahead *ahead = r->workers && nc > 1 ? calloc((size_t)nc, sizeof *ahead) : NULL;
    int used = 0, lost = 0;
    ic_status st = IC_OK;
    for (int i = 0; st == IC_OK && i < nc; i++) {
        if (cand[i].covered || ic_trace_point_near_found(r, cand[i].xyz, radius) ||
            in_pole_gap(r, cand[i].xyz, 50 * opt->chord)) {
            lost += ahead && ahead[i].valid;
            continue;
        }
        if (ic_trace_out_of_time(&r->budget))
            break;
        ic_trace_progress(r, opt, "tracing start points", i, nc);
        if (ahead && !ahead[i].done)
            ic_trace_march_ahead(r, pair, opt, cand, nc, i, used, lost, ahead);
        ic_local_point pt;
        ic_local_options lo = opt->local;
        ic_error e2;
        ic_local_result res;
        if (ahead && ahead[i].valid) /* located and transversal */
            pt = ahead[i].pt, used++;
        else if (ic_local_locate_guess(pair, &pt, cand[i].xyz, cand[i].params, &lo, &e2) != IC_OK) {
            st = unlocated_candidate(r, pair, cand, nc, i, opt, e2.message, err);
            continue;
        } else if (ic_local_apparatus(pair, &res, &pt, 2, IC_METHOD_JET, &lo, &e2) != IC_OK ||
                   res.type != IC_POINT_TRANSVERSAL) {
            st = tangential_candidate(r, tr, pair, cand, nc, &pt, opt, err);
            continue;
        }
        ic_trace_point *pts = NULL;
        int np2 = 0;
        st = trace_candidate(r, tr, pair, &pt, ahead ? &ahead[i] : NULL, opt, &pts, &np2, err);
        if (st == IC_OK && np2 > 0)
            ic_trace_cover(cand, nc, pts, np2, radius);
        cand[i].covered = 1;
    }
    for (int i = 0; ahead && i < nc; i++)
        ic_trace_marches_free(&ahead[i].m);
    free(ahead);
    return st;
}

/* The dimension of the search space of the pair: 3 (x, y, z), 2 (u, v)
 * or 4 (u, v, p, q). */
static int search_dim(ic_pair *pair) { return ic_pair_pairing(pair)->kind->dim; }

/* complete: the search was proven, every cell decided, nothing failed and
 * no work limit was reached (docs/tracing.md, "Completeness"). */
static void set_complete(ic_trace_result *r)
{
    const ic_trace_report *rep = &r->report;
    r->report.complete = rep->proven && rep->nfailures == 0 && !r->budget.stopped &&
                         rep->uncovered_cells == 0 && rep->unproven_cells == 0 &&
                         rep->undecided_loop_cells == 0 && rep->coincident_cells == 0;
}

static ic_status trace(ic_trace_result **out, ic_pair *pair, const ic_trace_options *user_opt,
                       ic_error *err)
{
    if (!out || !pair || !user_opt)
        return ic_error_set(err, IC_ERR_INVALID, 0, "ic_trace needs a result, a pair and options");
    *out = NULL;
    ic_status valid = ic_trace_check_options(user_opt, err);
    if (valid != IC_OK)
        return valid;
    ic_trace_result *r = calloc(1, sizeof *r);
    if (!r)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory tracing");
    r->budget.cells_left = IC_TRACE_MAX_CELLS;
    /* every length below is absolute: the user's fractions times L */
    r->scale = ic_trace_problem_scale(pair, user_opt);
    ic_trace_options eff = ic_trace_absolute_options(user_opt, r->scale);
    const ic_trace_options *opt = &eff;
    r->report.method = ic_trace_method_search;
    int exact = 0;
    ic_status st = ic_trace_exact(r, pair, user_opt, &exact, err);
    if (st != IC_OK || exact) {
        if (st != IC_OK)
            ic_trace_result_free(r);
        else
            *out = r;
        return st;
    }
    if (opt->time_limit > 0)
        r->budget.deadline = ic_trace_now() + opt->time_limit;
    ic_candidate *cand = NULL;
    ic_unresolved *unres = NULL;
    int nc = 0, nu = 0;
    ic_tracer *tr = NULL;
    st = ic_trace_workers_new(&r->workers, pair, ic_trace_thread_count(opt->threads), err);
    if (st == IC_OK)
        st = ic_trace_candidates(pair, opt, NULL, r->workers, NULL, &cand, &nc, &unres, &nu,
                                 &r->report, &r->budget, err);
    r->first_cell_size = r->report.cell_size;
    /* the scale of the rest: where the first search left the intersection
     * (a parametric surface may reach far beyond it) */
    r->scale = ic_trace_found_scale(r->scale, cand, nc, unres, nu);
    eff = ic_trace_absolute_options(user_opt, r->scale);
    r->index = ic_curve_index_new(r->scale / 128);
    if (st == IC_OK && !r->index)
        st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory tracing");
    if (st == IC_OK)
        st = ic_tracer_new_absolute(&tr, pair, opt, err);
    if (st == IC_OK) {
        ic_tracer_set_deadline(tr, r->budget.deadline);
        st = ic_trace_from_candidates(r, tr, pair, cand, nc, opt, err);
    }
    /* open cells that nothing found passes near: a tangential point is
     * looked for in each (an isolated contact has no curve to find it by);
     * every branch out of the singular points found is traced; then every
     * open cell is refined until decided; what is left is listed */
    for (int i = 0; st == IC_OK && i < nu && !ic_trace_out_of_time(&r->budget); i++)
        /* a loop-free cell has N_A x N_B != 0 throughout (or grad F != 0):
         * no tangential point there (the pairing's loop test) */
        if ((unres[i].loop || !r->report.proven) && !unres[i].has_candidate &&
            unres[i].radius > 0 && !ic_trace_found_near(r, &unres[i]))
            st = ic_trace_tangential_in_cell(r, tr, pair, &unres[i], opt);
    if (st == IC_OK)
        st = ic_trace_complete_branches(r, tr, pair, opt);
    if (st == IC_OK)
        st = ic_trace_resolve_cells(r, tr, pair, opt, &unres, &nu, err);
    if (st == IC_OK)
        st = ic_trace_complete_branches(r, tr, pair, opt);
    if (st == IC_OK && ic_trace_drop_duplicates(r, IC_TRACE_ON_CURVE * r->scale) != IC_OK)
        st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory dropping duplicate curves");
    if (st == IC_OK && ic_trace_join_curves(r, opt->shape_tol, 50 * opt->chord) != IC_OK)
        st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory joining curves");
    /* a surface's singular point counted the curve ends met there: two a branch */
    for (int k = 0; k < r->nspecials; k++)
        if (r->specials[k].type == IC_POINT_SURFACE_SINGULAR)
            r->specials[k].nbranches = (r->specials[k].nbranches + 1) / 2;
    /* the curves changed: indexed anew */
    if (st == IC_OK) {
        ic_curve_index_clear(r->index);
        for (int c = 0; c < r->ncurves && st == IC_OK; c++)
            if (ic_curve_index_add(r->index, c, r->curves[c].points, r->curves[c].npoints) != 0)
                st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory");
    }
    /* after joining: the arcs meeting at a pole of a parametrization are
     * bridged there, and the cells around the pole are near the bridge */
    if (st == IC_OK) {
        list_deferred(r, 2 * opt->chord);
        ic_trace_report_open_cells(r, unres, nu, search_dim(pair));
    }
    set_complete(r);
    ic_tracer_free(tr);
    ic_trace_workers_free(r->workers);
    r->workers = NULL;
    free(cand);
    free(unres);
    if (st != IC_OK) {
        ic_trace_result_free(r);
        return st;
    }
    *out = r;
    return IC_OK;
}

/* Out of memory ends the trace, wherever it struck: the searches and the
 * march try another way after a failed step, so it is asked of the pair at
 * the end (ic_pair_nomem_check; tests/test_nomem.c). */
ic_status ic_trace(ic_trace_result **out, ic_pair *pair, const ic_trace_options *user_opt,
                   ic_error *err)
{
    IC_ARG_NOT_NULL(out, "res");
    IC_ARG_NOT_NULL(pair, "pair");
    IC_ARG_NOT_NULL(user_opt, "opt");
    const long before = pair->nomem;
    ic_status st = ic_pair_nomem_check(pair, before, trace(out, pair, user_opt, err), err);
    if (st == IC_ERR_NOMEM) {
        ic_trace_result_free(*out);
        *out = NULL;
        if (err && err->code != IC_ERR_NOMEM) /* a stage that said nothing */
            ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory tracing");
    }
    return st;
}
