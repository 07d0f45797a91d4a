/* Joining traced curves through the singular points at their ends, and
 * dropping arcs traced twice. */
#include "trace_internal.h"
#include "core/trace_constants.h"
#include "common/vec3.h"
#include "local/pair_access.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Two ends at one place of the sheets' parameters too (each parametric
 * sheet's within IC_TRACE_TOUCH_GAP of its domain's width): not the two
 * sides of a seam that is a plain domain edge, which meet in space only. */
static int same_params(const ic_pairing *pg, const ic_trace_point *a, const ic_trace_point *b)
{
    for (int s = 0; s < 2; s++) {
        if (!pg->par[s])
            continue;
        double dom[2][2];
        int periodic[2];
        ic_surface_get_domain(pg->S[s], dom, periodic);
        for (int k = 0; k < 2; k++)
            if (!(fabs(a->params[s][k] - b->params[s][k]) <=
                  IC_TRACE_TOUCH_GAP * (dom[k][1] - dom[k][0])))
                return 0;
    }
    return 1;
}

/* Outgoing direction at end e of curve c (into the curve): +t at its start,
 * -t at its end; *p the end point. */
static void outgoing(const ic_trace_curve *c, int e, double *o, const ic_trace_point **p)
{
    *p = e ? &c->points[c->npoints - 1] : &c->points[0];
    ic_scale3(o, (*p)->t, e ? -1.0 : 1.0);
}

/* Joins end ea of curve a to end eb of curve b: the two end points are the
 * same point (gap 0), gap apart along the curve (then both are kept), or
 * -gap past each other (an overlap where both stopped beyond a touch of
 * the domain's edge: b's end is dropped, and the arc lengths after it less
 * the overlap). A curve joined to itself closes. */
static ic_status merge(ic_trace_result *r, int a, int ea, int b, int eb, double gap)
{
    ic_trace_curve *ca = &r->curves[a], *cb = &r->curves[b];
    ic_trace_point *A = r->storage[a];
    const int na = ca->npoints, shared = gap <= 0.0;
    if (b == a) { /* both ends of one curve: it closes (the start repeated last) */
        if (gap < 0.0) { /* the overshooting last point becomes the start */
            const double s = A[na - 1].s + gap;
            A[na - 1] = A[0];
            A[na - 1].s = s;
        } else if (!shared) {
            ic_trace_point *J = realloc(A, (size_t)(na + 1) * sizeof *J);
            if (!J)
                return IC_ERR_NOMEM;
            J[na] = J[0];
            J[na].s = J[na - 1].s + gap;
            r->storage[a] = J;
            ca->points = J;
            ca->npoints = na + 1;
        }
        ca->closed = 1;
        ca->ends[0] = ca->ends[1] = IC_TRACE_CLOSED;
        r->at[a][0] = r->at[a][1] = -1;
        return IC_OK;
    }
    /* a's joining end last, b's joining end first */
    if (ea == 0)
        ic_trace_points_reverse(A, na);
    ic_trace_point *B = r->storage[b];
    const int nb = cb->npoints;
    if (eb == 1)
        ic_trace_points_reverse(B, nb);
    const int n = na + nb - shared;
    ic_trace_point *J = realloc(A, (size_t)n * sizeof *J);
    if (!J)
        return IC_ERR_NOMEM;
    const double shift = J[na - 1].s + gap - B[0].s;
    for (int i = shared; i < nb; i++) {
        J[na - shared + i] = B[i];
        J[na - shared + i].s += shift;
    }
    const int at0 = r->at[a][ea == 0 ? 1 : 0], at1 = r->at[b][eb == 1 ? 0 : 1];
    const ic_trace_event e0 = ca->ends[ea == 0 ? 1 : 0];
    const ic_trace_event e1 = cb->ends[eb == 1 ? 0 : 1];
    free(B);
    /* b leaves the list; a becomes the joined curve */
    r->storage[a] = J;
    r->curves[b] = r->curves[r->ncurves - 1];
    r->storage[b] = r->storage[r->ncurves - 1];
    r->at[b][0] = r->at[r->ncurves - 1][0];
    r->at[b][1] = r->at[r->ncurves - 1][1];
    const int ai = a == r->ncurves - 1 ? b : a;
    r->ncurves--;
    ic_trace_curve *c = &r->curves[ai];
    r->storage[ai] = J;
    c->points = J;
    c->npoints = n;
    c->ends[0] = e0;
    c->ends[1] = e1;
    r->at[ai][0] = at0;
    r->at[ai][1] = at1;
    return IC_OK;
}

/* The length of the last step at end e of curve c. */
static double last_step(const ic_trace_curve *c, int e)
{
    if (c->npoints < 2)
        return 0.0;
    const ic_trace_point *p = e ? &c->points[c->npoints - 1] : &c->points[0];
    const ic_trace_point *q = e ? &c->points[c->npoints - 2] : &c->points[1];
    return fabs(p->s - q->s);
}

/* The arc length across a gap from point p (travelling along t0) to q
 * (travelling along t1): the trapezoid rule with its end correction,
 * q - p = L (t0 + t1)/2 - L^2 (k1 - k0)/12 + O(L^5), solved for L by
 * fixed-point iteration (k the curvature vectors kappa n). */
double ic_trace_gap_length(const ic_trace_point *p, const double *t0, const ic_trace_point *q,
                           const double *t1)
{
    double d[3], k[3] = {0, 0, 0}, tm[3];
    ic_axpy3(d, q->xyz, -1.0, p->xyz);
    if (p->frame_defined)
        ic_axpy3(k, k, -p->kappa, p->n);
    if (q->frame_defined)
        ic_axpy3(k, k, q->kappa, q->n);
    ic_axpy3(tm, t0, 1.0, t1);
    const double half = 0.5 * ic_norm3(tm);
    double L = ic_norm3(d);
    for (int it = 0; it < 8; it++) {
        double v[3];
        ic_axpy3(v, d, L * L / 12, k);
        L = ic_norm3(v) / half;
    }
    return L;
}

/* The difference of the curvature vectors c'' = kappa n (independent of
 * the orientation) at two curve ends. */
static double curvature_jump(const ic_trace_curve *ca, int ea, const ic_trace_curve *cb, int eb)
{
    const ic_trace_point *pa = ea ? &ca->points[ca->npoints - 1] : &ca->points[0];
    const ic_trace_point *pb = eb ? &cb->points[cb->npoints - 1] : &cb->points[0];
    double d[3] = {0, 0, 0};
    if (pa->frame_defined)
        ic_scale3(d, pa->n, pa->kappa);
    if (pb->frame_defined)
        ic_axpy3(d, d, -pb->kappa, pb->n);
    return ic_norm3(d);
}

/* Whether end eb of curve b continues end ea of curve a at least as well as
 * every other end at the same point with the opposite tangent: at a tacnode
 * two do, and the one with the same curvature vector is the branch. */
static int best_continuation(const ic_trace_result *r, int a, int ea, int b, int eb)
{
    const double jump = curvature_jump(&r->curves[a], ea, &r->curves[b], eb);
    const ic_trace_point *pa;
    double oa[3];
    outgoing(&r->curves[a], ea, oa, &pa);
    for (int c = 0; c < r->ncurves; c++)
        for (int ec = 0; ec < 2; ec++) {
            const ic_trace_point *pc;
            double oc[3];
            if ((c == a && ec == ea) || (c == b && ec == eb) || r->curves[c].closed ||
                r->at[c][ec] != r->at[a][ea])
                continue;
            outgoing(&r->curves[c], ec, oc, &pc);
            if (ic_dot3(oa, oc) <= -1 + 1e-6 &&
                curvature_jump(&r->curves[a], ea, &r->curves[c], ec) < jump)
                return 0;
        }
    return 1;
}

/* Joins curves through the tangential points at their ends where a branch
 * continues smoothly (the outgoing directions of the two ends opposite), and
 * across the small gaps a curve leaves where it passes through a degenerate
 * point of a parametrization (a sphere patch's pole: both ends left the
 * domain there, meet within max_gap or two steps each side, and continue
 * each other). A curve
 * joined to itself is closed. */
ic_status ic_trace_join_curves(ic_trace_result *r, ic_pair *pair, double shape_tol,
                               double max_gap)
{
    for (int changed = 1; changed;) {
        changed = 0;
        for (int a = 0; a < r->ncurves && !changed; a++)
            for (int ea = 0; ea < 2 && !changed; ea++) {
                const int k = r->at[a][ea];
                const int gap_end = k < 0 && r->curves[a].ends[ea] == IC_TRACE_LEFT_DOMAIN;
                if ((k < 0 && !gap_end) || r->curves[a].closed)
                    continue;
                for (int b = a; b < r->ncurves && !changed; b++)
                    for (int eb = 0; eb < 2 && !changed; eb++) {
                        if (b == a && eb == ea)
                            continue;
                        const ic_trace_point *pa, *pb;
                        double oa[3], ob[3];
                        outgoing(&r->curves[a], ea, oa, &pa);
                        outgoing(&r->curves[b], eb, ob, &pb);
                        double gap = 0.0;
                        if (!gap_end) {
                            if (r->at[b][eb] != k || ic_dot3(oa, ob) > -1 + 1e-6 ||
                                !best_continuation(r, a, ea, b, eb))
                                continue;
                        } else {
                            if (r->at[b][eb] >= 0 || r->curves[b].ends[eb] != IC_TRACE_LEFT_DOMAIN)
                                continue;
                            /* across the gap: from pa along -oa to pb, then along ob */
                            double d[3], t0[3];
                            ic_axpy3(d, pb->xyz, -1.0, pa->xyz);
                            ic_scale3(t0, oa, -1.0);
                            const double dist = ic_norm3(d);
                            /* up to about two steps each side: the last steps
                             * before the degenerate point */
                            const double reach = fmax(max_gap, 2 * (last_step(&r->curves[a], ea) +
                                                                    last_step(&r->curves[b], eb)));
                            /* the turn allowed across the gap: four times
                             * what the ends' curvature turns over it (at
                             * least 1/L) */
                            const double kappa = fmax(fmax(pa->kappa, pb->kappa), 1 / r->scale);
                            const double turn = fmin(0.5, 4 * kappa * dist);
                            /* a gap where the parametrization does not
                             * degenerate is the curve leaving the domain
                             * (a cap past an edge): not joined, unless
                             * it is a touch of the edge */
                            const int touch =
                                dist <= IC_TRACE_TOUCH_GAP * r->scale &&
                                same_params(ic_pair_pairing(pair), pa, pb);
                            if (dist > reach || ic_dot3(oa, ob) > -cos(turn) ||
                                fabs(ic_dot3(d, t0)) < 0.9 * dist ||
                                (!touch && ic_dot3(d, t0) < 0) ||
                                (!touch && !ic_pairing_gap_may_degenerate(ic_pair_pairing(pair),
                                                                          pa->xyz, pa->params,
                                                                          pb->xyz, pb->params)))
                                continue;
                            /* past a touch both ends may overshoot each
                             * other: the overlap is taken off */
                            gap = touch && ic_dot3(d, t0) < 0 ? -dist
                                                               : ic_trace_gap_length(pa, t0, pb, ob);
                            if (!(gap > 0) && !(touch && gap < 0))
                                continue;
                        }
                        if (merge(r, a, ea, b, eb, gap) != IC_OK)
                            return IC_ERR_NOMEM;
                        changed = 1;
                    }
            }
    }
    for (int i = 0; i < r->ncurves; i++) {
        ic_trace_curve *c = &r->curves[i];
        c->points = r->storage[i];
        c->length = c->points[c->npoints - 1].s - c->points[0].s;
        c->shape = ic_trace_shape(c->points, c->npoints, c->length, shape_tol, c->tangential);
    }
    return IC_OK;
}

/* Drops a curve that runs along another, longer one all the way (traced
 * twice from two start points: it happens where one trace stopped early, at a
 * degenerate point of a parametrization, before covering the other start).
 * IC_ERR_NOMEM (nothing changed) when its table does not fit. */
ic_status ic_trace_drop_duplicates(ic_trace_result *r, double radius)
{
    /* each curve's box once: thousands of small loops meet each other */
    double(*box)[2][3] = malloc((size_t)(r->ncurves > 0 ? r->ncurves : 1) * sizeof *box);
    if (!box) /* duplicates kept would be another result: the caller reports it */
        return IC_ERR_NOMEM;
    for (int c = 0; c < r->ncurves; c++)
        ic_trace_curve_box(r->curves[c].points, r->curves[c].npoints, radius, box[c][0],
                           box[c][1]);
    for (int a = 0; a < r->ncurves; a++) {
        const ic_trace_curve *ca = &r->curves[a];
        int inside = 0;
        for (int b = 0; b < r->ncurves && !inside; b++) {
            const ic_trace_curve *cb = &r->curves[b];
            if (b == a || cb->length < ca->length ||
                !ic_trace_in_box(ca->points[0].xyz, box[b][0], box[b][1]))
                continue;
            inside = 1;
            for (int k = 0; k < ca->npoints && inside; k++)
                inside = ic_trace_polyline_distance(cb->points, cb->npoints, ca->points[k].xyz,
                                                    radius) <= radius;
        }
        if (!inside)
            continue;
        free(r->storage[a]);
        const int last = --r->ncurves;
        r->curves[a] = r->curves[last];
        r->storage[a] = r->storage[last];
        r->at[a][0] = r->at[last][0], r->at[a][1] = r->at[last][1];
        memcpy(box[a], box[last], sizeof box[a]);
        a--;
    }
    free(box);
    return IC_OK;
}
