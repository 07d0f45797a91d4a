/* An ellipse of the conic paths as points on recognised patches
 * (exact_ellipse_nets.h): the plan's points (exact_ellipse.c), a point put
 * in on every knot line crossed (a parameter curve is only C^1, or C^0,
 * across one: the B-spline fit keeps a node there, as on the general
 * path's points), its arc length by the plan's quadrature from the plan
 * point before it; then every point's parameters, set exactly on the
 * lines crossed. */
#include "exact_ellipse_nets.h"
#include "common/mathconst.h"
#include "common/vec3.h"
#include "surface/surface_access.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* radians (of phi): a knot line crossed this near a plan point (or
 * another crossing) is crossed there: one point carries both */
#define EXACT_SAME_ANGLE 1e-12

static int by_angle(const void *a, const void *b)
{
    const double x = ((const ic_exact_knot *)a)->phi, y = ((const ic_exact_knot *)b)->phi;
    return (x > y) - (x < y);
}

/* The crossings' angles theta turned to the plan's phi (tan theta = r tan
 * phi), in [0, 2 pi), one at the end of the turn at its start; sorted. */
static void to_phi(ic_exact_knot *k, int nk, const ic_ellipse_plan *plan)
{
    for (int i = 0; i < nk; i++) {
        double phi = atan2(sin(k[i].phi), plan->r * cos(k[i].phi));
        phi = phi < 0 ? phi + 2 * IC_PI : phi;
        k[i].phi = phi > 2 * IC_PI - EXACT_SAME_ANGLE ? 0 : phi;
    }
    if (nk > 1)
        qsort(k, (size_t)nk, sizeof *k, by_angle);
}

/* The crossing's point, after the plan point j (at phi_j). */
static void crossing_point(ic_trace_point *p, const ic_trace_point *before, double phi_j,
                           const ic_exact_knot *k, const ic_exact_ellipse *e,
                           const ic_ellipse_plan *plan)
{
    double binormal[3], ct, st;
    ic_cross3(binormal, e->u, e->v);
    ic_ellipse_theta(plan, cos(k->phi), sin(k->phi), &ct, &st);
    memset(p, 0, sizeof *p);
    ic_exact_ellipse_point(p, e, binormal, ct, st, 1);
    p->s = before->s + ic_exact_ellipse_arc(e, plan, phi_j, k->phi);
}

/* The plan's n + 1 points and the sorted crossings merged into out (room
 * for n + nk + 1), at[j] the point crossing j is on. Returns the count. */
static int merge(const ic_trace_point *plan_pts, const ic_exact_knot *k, int nk,
                 const ic_exact_ellipse *e, const ic_ellipse_plan *plan, ic_trace_point *out,
                 int *at)
{
    const int n = plan->n;
    int m = 0, j = 0;
    for (int i = 0; i < n; i++) {
        const double phi_i = 2 * IC_PI * i / n, next = 2 * IC_PI * (i + 1) / n;
        out[m] = plan_pts[i];
        for (; j < nk && k[j].phi <= phi_i + EXACT_SAME_ANGLE; j++)
            at[j] = m;
        m++;
        for (; j < nk && k[j].phi < next - EXACT_SAME_ANGLE; j++) {
            if (!(j > 0 && at[j - 1] == m - 1 && k[j].phi - k[j - 1].phi <= EXACT_SAME_ANGLE))
                crossing_point(&out[m++], &plan_pts[i], phi_i, &k[j], e, plan);
            at[j] = m - 1;
        }
    }
    for (; j < nk; j++) /* at the end of the turn: its start */
        at[j] = 0;
    out[m] = plan_pts[n];
    return m + 1;
}

/* Point i's parameters on crossing j's patch set on its line, and checked
 * there against the patch: 0, or 1. */
static int on_line(ic_trace_point *p, const ic_exact_knot *k, const ic_exact_source src[2],
                   double L)
{
    const int s = k->sheet;
    double S[3], d[3];
    ic_exact_knot_snap(&src[s], k, &p->params[s][k->dir]);
    p->knot_line |= 1 << s;
    p->knot_side = 1;
    ic_surface_nurbs_point(src[s].surface, p->params[s], S);
    ic_axpy3(d, S, -1.0, p->xyz);
    return !(ic_norm3(d) <= IC_EXACT_ON_NET * L);
}

/* The points turned to run along N_A x N_B where the normals are furthest
 * from parallel (away from any branch point), as the general path runs. */
static void orient(ic_pair *pair, ic_trace_point *pts, int np)
{
    int best = 0;
    for (int i = 1; i < np; i++)
        best = pts[i].angle > pts[best].angle ? i : best;
    ic_exact_orient_at(pair, pts, np, best);
}

int ic_exact_ellipse_net_points(ic_pair *pair, const ic_exact_source src[2],
                                const ic_exact_ellipse *e, const ic_ellipse_plan *plan, double L,
                                ic_trace_point **pts, int *np)
{
    *pts = NULL;
    ic_exact_knot *k = NULL;
    int nk = 0;
    const int st = ic_exact_ellipse_knots(e, src, L, &k, &nk);
    if (st != 0)
        return st;
    to_phi(k, nk, plan);
    ic_trace_point *plan_pts = NULL;
    ic_trace_point *out = malloc(sizeof *out * (size_t)(plan->n + nk + 1));
    int *at = malloc(sizeof *at * (size_t)(nk + 1));
    int res = !out || !at || ic_exact_ellipse_points(e, plan, &plan_pts) != 0 ? -1 : 0;
    if (res == 0) {
        *np = merge(plan_pts, k, nk, e, plan, out, at);
        res = ic_exact_curve_params(src, out, *np, L);
        for (int j = 0; res == 0 && j < nk; j++) {
            res = on_line(&out[at[j]], &k[j], src, L);
            if (res == 0 && at[j] == 0) /* the start again at the end */
                res = on_line(&out[*np - 1], &k[j], src, L);
        }
    }
    free(k), free(at), free(plan_pts);
    if (res != 0) {
        free(out);
        return res;
    }
    orient(pair, out, *np);
    *pts = out;
    return 0;
}
