/*
 * Crossings of a tangential curve (crossing.h; docs/tracing.md). Along a
 * tangential curve the height difference of the surfaces is (bend / 2) w^2
 * across it (ic_local_tangential_bend); where a transversal curve crosses,
 * the bend passes through zero (g ~ w^2 (b' s + c w) there, the transversal
 * curve b' s + c w = 0). The transversal curve's march stops where the
 * normals come parallel, short of the crossing by about the square root of
 * the march's angle threshold; this finds the crossing itself.
 */
#include "crossing.h"
#include "common/mathconst.h"
#include "common/vec3.h"
#include "local/pair_access.h"

#include <float.h>
#include <math.h>
#include <string.h>

/* Steps along the tangential curve per reach, each way, looking for the
 * bend's change of sign. */
#define IC_TRACE_CROSSING_STEPS 64
/* Directions of the tangent plane tried for the tangential curve's. */
#define IC_TRACE_CROSSING_PROBES 12
/* Bisections of the bracket: from up to 2 reach down to rounding. */
#define IC_TRACE_CROSSING_BISECTIONS 60
/* A bend below this (1/length, relative to 1 / L) is noise: a contact of
 * higher order all along the curve has none to change sign. */
#define IC_TRACE_BEND_FLOOR 1e-8

typedef struct {
    ic_pair *pair;
    const ic_local_options *lopt;
    double floor; /* IC_TRACE_BEND_FLOOR / L */
} walk;

/* A point of the tangential curve and the bend there. */
typedef struct {
    ic_local_point p;
    double bend;
} bent;

/* The tangential curve's point from X (params as a guess), within reach,
 * and its bend: 1, or 0 where either fails. */
static int point_and_bend(const walk *w, const double X[3], const double params[2][2],
                          double reach, bent *q)
{
    ic_local_point near;
    memset(&near, 0, sizeof near);
    memcpy(near.xyz, X, sizeof near.xyz);
    memcpy(near.params, params, sizeof near.params);
    /* a parametric sheet's locator starts from its parameters: X's own */
    const ic_pairing *pg = ic_pair_pairing(w->pair);
    for (int s = 0; s < 2; s++) {
        double dist;
        if (pg->par[s] &&
            ic_local_project(w->pair, s, near.params[s], X, w->lopt, &dist) != IC_OK)
            return 0;
    }
    if (ic_local_locate_tangential(w->pair, &q->p, &near, reach, w->lopt, NULL) != IC_OK)
        return 0;
    return ic_local_tangential_bend(w->pair, &q->p, &q->bend, NULL) == IC_OK;
}

/* The bend's zero between a and b (bends of opposite signs), by bisection,
 * each midpoint put back on the tangential curve; *place the last
 * bracket's length and the band where the bend is noise. */
static ic_local_point bisect(const walk *w, bent a, bent b, double *place)
{
    const double tiny = 4 * DBL_EPSILON * w->lopt->scale;
    /* where the bend is below its noise (the floor) its sign says nothing:
     * that band about the root, by the first bracket's slope */
    const double band = 2 * w->floor * ic_dist3(a.p.xyz, b.p.xyz) / fabs(a.bend - b.bend);
    for (int it = 0; it < IC_TRACE_CROSSING_BISECTIONS; it++) {
        const double len = ic_dist3(a.p.xyz, b.p.xyz);
        if (!(len > tiny))
            break;
        double X[3];
        for (int i = 0; i < 3; i++)
            X[i] = 0.5 * (a.p.xyz[i] + b.p.xyz[i]);
        bent m; /* the parameters from a's: a and b may lie across a seam */
        if (!point_and_bend(w, X, a.p.params, 4 * len, &m))
            break; /* the tangential curve, a double root, is known to about
                    * sqrt(eps) L: the bracket stops there */
        double am[3], ab[3];
        ic_axpy3(am, m.p.xyz, -1.0, a.p.xyz);
        ic_axpy3(ab, b.p.xyz, -1.0, a.p.xyz);
        const double along = ic_dot3(am, ab) / (len * len);
        if (!(along > 0.0 && along < 1.0))
            break; /* the locator slid out of the bracket: it stays honest */
        if (m.bend == 0.0) {
            *place = band;
            return m.p;
        }
        if ((m.bend < 0) == (a.bend < 0))
            a = m;
        else
            b = m;
    }
    *place = ic_dist3(a.p.xyz, b.p.xyz) + band;
    return fabs(a.bend) <= fabs(b.bend) ? a.p : b.p;
}

/* The tangential curve's direction at Q: of the tangent plane's directions
 * (normal N), the one whose step of h the locator keeps most of, there on
 * a tangential curve. 1 and T, or 0. */
static int curve_direction(const walk *w, const ic_local_point *Q, const double N[3], double h,
                           double T[3])
{
    double e1[3], e2[3];
    ic_plane_basis3(N, e1, e2);
    double best = 0.5 * h;
    int found = 0;
    ic_local_point far;
    memset(&far, 0, sizeof far);
    for (int k = 0; k < IC_TRACE_CROSSING_PROBES; k++) {
        const double phi = IC_PI * k / IC_TRACE_CROSSING_PROBES;
        double dir[3], X[3];
        ic_scale3(dir, e1, cos(phi));
        ic_axpy3(dir, dir, sin(phi), e2);
        ic_axpy3(X, Q->xyz, h, dir);
        bent q;
        if (!point_and_bend(w, X, Q->params, h, &q))
            continue;
        double d[3];
        ic_axpy3(d, q.p.xyz, -1.0, Q->xyz);
        const double kept = fabs(ic_dot3(d, dir));
        if (kept > best)
            best = kept, found = 1, memcpy(T, d, sizeof d), far = q.p;
    }
    /* the point kept lies on a tangential curve (not in the flat
     * neighbourhood of a contact of high order) */
    ic_local_result res;
    ic_local_options o = *w->lopt;
    return found && ic_normalize3(T) > 0.0 &&
           ic_local_apparatus(w->pair, &res, &far, 2, IC_METHOD_AUTO, &o, NULL) == IC_OK &&
           res.type == IC_POINT_TANGENTIAL_CURVE;
}

/* From Q along the tangential curve in direction T, steps of h up to
 * reach: the first point whose bend is above noise (*first, *anchored)
 * and the bracket of the first change of sign after it, between the last
 * two points above noise (1 and *lo, *hi). */
static int walk_along(const walk *w, bent Q, const double T[3], double h, double reach,
                      bent *first, int *anchored, bent *lo, bent *hi)
{
    double dir[3];
    memcpy(dir, T, sizeof dir);
    *anchored = fabs(Q.bend) > w->floor;
    if (*anchored)
        *first = Q;
    bent last = Q, ref = Q; /* the walk's last point, and its last above the floor */
    for (double gone = 0.0; gone < reach; gone += h) {
        double X[3];
        ic_axpy3(X, last.p.xyz, h, dir);
        bent next;
        if (!point_and_bend(w, X, last.p.params, h, &next))
            return 0;
        double d[3];
        ic_axpy3(d, next.p.xyz, -1.0, last.p.xyz);
        const double len = ic_norm3(d);
        if (!(len > 0.25 * h) || ic_dot3(d, dir) <= 0)
            return 0; /* stuck, or turned back: not a curve here */
        ic_scale3(dir, d, 1.0 / len);
        if (fabs(next.bend) > w->floor) {
            if (*anchored && (next.bend < 0) != (ref.bend < 0)) {
                *lo = ref, *hi = next; /* across any steps in the noise band */
                return 1;
            }
            if (!*anchored)
                *first = next;
            ref = next, *anchored = 1;
        }
        last = next;
    }
    return 0;
}

int ic_trace_locate_crossing(ic_pair *pair, const ic_local_options *lopt,
                             const ic_local_point *near, double reach, ic_local_point *P,
                             double *place)
{
    const walk w = {pair, lopt, IC_TRACE_BEND_FLOOR / lopt->scale};
    bent Q;
    if (!point_and_bend(&w, near->xyz, near->params, reach, &Q))
        return 0;
    ic_local_result res;
    ic_local_options o = *lopt;
    double T[3];
    const double h = reach / IC_TRACE_CROSSING_STEPS;
    if (ic_local_apparatus(pair, &res, &Q.p, 2, IC_METHOD_AUTO, &o, NULL) != IC_OK ||
        res.type == IC_POINT_TRANSVERSAL)
        return 0;
    if (res.type == IC_POINT_TANGENTIAL_CURVE && res.nbranches >= 1)
        memcpy(T, res.branches[0].t, sizeof T);
    else if (!curve_direction(&w, &Q.p, res.normals[0], h, T))
        return 0; /* an isolated point: no curve through it */
    bent anchor[2], lo[2], hi[2];
    int anchored[2], found[2];
    double back[3];
    ic_scale3(back, T, -1.0);
    found[0] = walk_along(&w, Q, T, h, reach, &anchor[0], &anchored[0], &lo[0], &hi[0]);
    found[1] = walk_along(&w, Q, back, h, reach, &anchor[1], &anchored[1], &lo[1], &hi[1]);
    /* Q itself at the crossing, its bend noise: the first bends either side
     * bracket it, at distance 0 from Q */
    if (!(fabs(Q.bend) > w.floor) && anchored[0] && anchored[1] &&
        (anchor[0].bend < 0) != (anchor[1].bend < 0)) {
        *P = bisect(&w, anchor[0], anchor[1], place);
        return 1;
    }
    int k = found[0] ? 0 : 1;
    if (found[0] && found[1]) /* the nearer to the end */
        k = ic_dist3(lo[0].p.xyz, near->xyz) <= ic_dist3(lo[1].p.xyz, near->xyz) ? 0 : 1;
    if (!found[k])
        return 0;
    *P = bisect(&w, lo[k], hi[k], place);
    return 1;
}
