/*
 * A self-intersection's sheet whose two opposite domain edges are one
 * curve of the surface (pairing.h, ic_pairing_glue): R(e0, w) = R(e1, g(w))
 * along the edges z[axis] = e0 and e1 of a parameter not marked periodic,
 * g(w) = c - w (the edges glued with the other parameter reversed: a
 * figure-8 Klein bottle, R(u + 2 pi, v) = R(u, -v)) or g(w) = w + c (a
 * periodic parameter not marked so). Every point of such an edge has two
 * preimages, one on each edge: not a self-intersection of the surface but
 * the same point of it, as on a periodic seam. Without this the tracer
 * recorded hundreds of "tangential points" along the glued edge (a
 * figure-8 Klein bottle on [1, 1 + 2 pi] x [0.5, 0.5 + 2 pi]: 206, 100 s).
 *
 * Found by sampling, as a periodic parameter is checked (problem files):
 * one of the first IC_GLUE_SEEDS samples along edge e0 matched on edge e1
 * by a search and Newton's method, which gives c; then every one of
 * IC_GLUE_SAMPLES points of e0 must be where g puts it on e1, to
 * IC_GLUE_MATCH of its points' magnitude, and so must the points of the lines
 * 1/16 of the width inside and outside both edges. The identity R(u, w) =
 * R(u + T, g(w)) is then taken as the surface's, as periodicity is.
 */
#include "common/vec3.h"
#include "pairing.h"

#include <math.h>
#include <string.h>

enum { IC_GLUE_SAMPLES = 9, IC_GLUE_SEEDS = 3, IC_GLUE_SCAN = 64, IC_GLUE_NEWTON = 30 };
/* where in its ninth of the edge each sample lies (1 - the golden ratio's
 * inverse): no sample at the middle or a simple fraction of the edge */
#define IC_GLUE_OFFSET 0.3819660112501051
/* fraction of the glued parameter's width: the lines beside the edges where
 * the glue must hold too */
#define IC_GLUE_BAND (1.0 / 16)
/* fraction of the largest magnitude of the edge's points (rounding of R is
 * about 1e-16 of it): a match closer than this is the same point */
#define IC_GLUE_MATCH 1e-11

/* R at (edge value e along axis, w along the other parameter). */
static int edge_point(const ic_pairing *p, int axis, double e, double w, double R[3],
                      double Rw[3])
{
    double uv[2], Ru[3], Rv[3];
    uv[axis] = e, uv[1 - axis] = w;
    if (ic_pairing_sheet_eval1(p, 0, uv, R, Ru, Rv, NULL) != IC_OK)
        return 0;
    if (Rw)
        memcpy(Rw, axis == 0 ? Rv : Ru, sizeof(double) * 3);
    return isfinite(R[0] + R[1] + R[2]);
}

/* The w on edge e1 whose point is nearest P: a scan, then Newton on
 * (R(w) - P) . R_w(w) = 0 by Gauss-Newton steps; its distance in *dist. */
static double match_on(const ic_pairing *p, int axis, double e1, const double w01[2],
                       const double P[3], double *dist)
{
    double best = w01[0], bd = INFINITY, R[3], Rw[3], d[3];
    for (int i = 0; i <= IC_GLUE_SCAN; i++) {
        const double w = w01[0] + (w01[1] - w01[0]) * i / IC_GLUE_SCAN;
        if (edge_point(p, axis, e1, w, R, NULL) &&
            (ic_axpy3(d, R, -1.0, P), ic_norm3(d) < bd))
            bd = ic_norm3(d), best = w;
    }
    for (int it = 0; it < IC_GLUE_NEWTON && edge_point(p, axis, e1, best, R, Rw); it++) {
        ic_axpy3(d, R, -1.0, P);
        const double g2 = ic_dot3(Rw, Rw);
        if (!(g2 > 0))
            break;
        best -= ic_dot3(d, Rw) / g2;
    }
    *dist = edge_point(p, axis, e1, best, R, NULL) ? (ic_axpy3(d, R, -1.0, P), ic_norm3(d))
                                                   : INFINITY;
    return best;
}

/* Sample s of IC_GLUE_SAMPLES along [w0, w1], off the symmetric places (a
 * figure-8's double point at the middle matches two places of the far
 * edge). */
static double sample_at(const double w01[2], int s)
{
    return w01[0] + (w01[1] - w01[0]) * (s + IC_GLUE_OFFSET) / IC_GLUE_SAMPLES;
}

/* Every sample of edge e0 is where g_c puts it on edge e1, to tol, and so
 * are the samples of the lines IC_GLUE_BAND of the width inside and outside
 * the edge: the checker uses R(u, w) = R(u + T, g(w)) beside the edges too
 * (certify/leaf.c), so the surface must continue across them as one sheet,
 * not merely share the edge curve (a crease where two pieces meet). */
static int glue_holds(const ic_pairing *p, int axis, int flip, double c, const double dom[2][2],
                      double tol)
{
    const int j = 1 - axis;
    const double band = IC_GLUE_BAND * (dom[axis][1] - dom[axis][0]);
    for (int line = -1; line <= 1; line++)
        for (int s = 0; s < IC_GLUE_SAMPLES; s++) {
            const double w = sample_at(dom[j], s), e = line * band;
            double P[3], Q[3], d[3];
            if (!edge_point(p, axis, dom[axis][0] + e, w, P, NULL) ||
                !edge_point(p, axis, dom[axis][1] + e, flip ? c - w : w + c, Q, NULL))
                return 0;
            ic_axpy3(d, Q, -1.0, P);
            if (!(ic_norm3(d) <= tol))
                return 0;
        }
    return 1;
}

/* The glue along `axis` with g flipped or shifted: its c from a match of
 * one of the first IC_GLUE_SEEDS samples on the far edge, held by every
 * sample; 1 and *c so. */
static int glued(const ic_pairing *p, int axis, int flip, const double dom[2][2], double *c)
{
    const int j = 1 - axis;
    double size = 0.0, P[3];
    for (int s = 0; s < IC_GLUE_SAMPLES; s++) {
        if (!edge_point(p, axis, dom[axis][0], sample_at(dom[j], s), P, NULL))
            return 0;
        size = fmax(size, ic_norm3(P));
    }
    const double tol = IC_GLUE_MATCH * fmax(size, 1e-300);
    for (int s = 0; s < IC_GLUE_SEEDS; s++) {
        const double w = sample_at(dom[j], s);
        double dist;
        edge_point(p, axis, dom[axis][0], w, P, NULL);
        const double m = match_on(p, axis, dom[axis][1], dom[j], P, &dist);
        *c = flip ? w + m : m - w;
        if (dist <= tol && glue_holds(p, axis, flip, *c, dom, tol))
            return 1;
    }
    return 0;
}

void ic_pairing_find_glue(ic_pairing *p)
{
    p->glue.axis = -1;
    double dom[2][2];
    int periodic[2];
    ic_surface_get_domain(p->S[0], dom, periodic);
    for (int axis = 0; axis < 2; axis++) {
        if (periodic[axis] || !isfinite(dom[0][1] - dom[0][0]) ||
            !isfinite(dom[1][1] - dom[1][0]))
            continue;
        for (int flip = 1; flip >= 0; flip--) {
            double c;
            if (glued(p, axis, flip, dom, &c)) {
                p->glue = (ic_pairing_glue){axis, flip, dom[axis][1] - dom[axis][0], c};
                return;
            }
        }
    }
}

void ic_pairing_glue_back(const ic_pairing *p, const double b[2], double out[2])
{
    const ic_pairing_glue *g = &p->glue;
    const int j = 1 - g->axis;
    out[g->axis] = b[g->axis] - g->T;
    out[j] = g->flip ? g->c - b[j] : b[j] - g->c;
}
