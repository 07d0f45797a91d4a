/* The geometry of traced polylines: distances to a chord less its sagitta,
 * a polyline's box, the candidates a curve covers, and reversing a curve. */
#include "common/vec3.h"
#include "polyline.h"

#include <math.h>

static double point_segment(const double *p, const double *a, const double *b)
{
    double ab[3], ap[3];
    ic_axpy3(ab, b, -1.0, a);
    ic_axpy3(ap, p, -1.0, a);
    const double l2 = ic_dot3(ab, ab);
    double t = l2 > 0 ? ic_dot3(ap, ab) / l2 : 0.0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    double q[3];
    ic_axpy3(q, a, t, ab);
    ic_axpy3(q, p, -1.0, q);
    return ic_norm3(q);
}

/* Distance from x to the box around points [k0, k1] (0 inside). */
static double box_distance(const ic_trace_point *pts, int k0, int k1, const double *x)
{
    double d2 = 0.0;
    for (int i = 0; i < 3; i++) {
        double lo = pts[k0].xyz[i], hi = lo;
        for (int k = k0 + 1; k <= k1; k++) {
            const double v = pts[k].xyz[i];
            lo = v < lo ? v : lo;
            hi = v > hi ? v : hi;
        }
        const double e = x[i] < lo ? lo - x[i] : x[i] > hi ? x[i] - hi : 0.0;
        d2 += e * e;
    }
    return sqrt(d2);
}

/* How far the curve between two traced points may stray from their chord:
 * the sagitta kappa h^2 / 8 of an arc of curvature kappa over a chord h,
 * doubled for the curvature's change along the step. */
double ic_trace_segment_sagitta(const ic_trace_point *p, const ic_trace_point *q)
{
    double d[3];
    ic_axpy3(d, q->xyz, -1.0, p->xyz);
    const double h2 = ic_dot3(d, d), k = fmax(fabs(p->kappa), fabs(q->kappa));
    const double s = 0.25 * k * h2;
    return isfinite(s) ? s : 0.5 * sqrt(h2);
}

double ic_trace_segment_distance(const ic_trace_point *p, const ic_trace_point *q, const double *x)
{
    return fmax(0.0, point_segment(x, p->xyz, q->xyz) - ic_trace_segment_sagitta(p, q));
}

double ic_trace_polyline_distance(const ic_trace_point *pts, int np, const double *x, double bound)
{
    if (np == 1)
        return point_segment(x, pts[0].xyz, pts[0].xyz);
    /* the distance to the curve itself, not to its polyline: each segment's
     * distance less the segment's sagitta. Chunks of 16 segments whose
     * bounding box is farther than the bound and their largest sagitta are
     * skipped, and the first segment within it ends the search (the coverage
     * checks call this for every cell and candidate against every curve) */
    enum { CHUNK = 16 };
    double best = INFINITY;
    for (int k0 = 0; k0 + 1 < np; k0 += CHUNK) {
        const int k1 = k0 + CHUNK < np - 1 ? k0 + CHUNK : np - 1;
        double sag[CHUNK], most = 0.0;
        for (int k = k0; k < k1; k++)
            most = fmax(most, sag[k - k0] = ic_trace_segment_sagitta(&pts[k], &pts[k + 1]));
        if (box_distance(pts, k0, k1, x) - most > bound)
            continue;
        for (int k = k0; k < k1; k++) {
            const double d = fmax(0.0, point_segment(x, pts[k].xyz, pts[k + 1].xyz) - sag[k - k0]);
            if (d <= bound)
                return d;
            best = d < best ? d : best;
        }
    }
    return best;
}

void ic_trace_curve_box(const ic_trace_point *pts, int np, double pad, double *lo, double *hi)
{
    double sag = 0.0;
    for (int k = 0; k + 1 < np; k++)
        sag = fmax(sag, ic_trace_segment_sagitta(&pts[k], &pts[k + 1]));
    for (int i = 0; i < 3; i++)
        lo[i] = hi[i] = pts[0].xyz[i];
    for (int k = 1; k < np; k++)
        for (int i = 0; i < 3; i++)
            lo[i] = fmin(lo[i], pts[k].xyz[i]), hi[i] = fmax(hi[i], pts[k].xyz[i]);
    for (int i = 0; i < 3; i++)
        lo[i] -= sag + pad, hi[i] += sag + pad;
}

int ic_trace_in_box(const double *x, const double *lo, const double *hi)
{
    return x[0] >= lo[0] && x[0] <= hi[0] && x[1] >= lo[1] && x[1] <= hi[1] && x[2] >= lo[2] &&
           x[2] <= hi[2];
}

void ic_trace_cover(ic_candidate *c, int n, const ic_trace_point *pts, int np, double radius)
{
    /* the curve's box first: a batch of candidates meets every curve */
    double lo[3], hi[3];
    ic_trace_curve_box(pts, np, radius, lo, hi);
    for (int i = 0; i < n; i++)
        if (!c[i].covered && ic_trace_in_box(c[i].xyz, lo, hi) &&
            ic_trace_polyline_distance(pts, np, c[i].xyz, radius) <= radius)
            c[i].covered = 1;
}

void ic_trace_points_reverse(ic_trace_point *p, int n)
{
    if (!p || n < 1)
        return;
    const double L = p[n - 1].s + p[0].s;
    for (int i = 0; i < n / 2; i++) {
        const ic_trace_point tmp = p[i];
        p[i] = p[n - 1 - i];
        p[n - 1 - i] = tmp;
    }
    for (int i = 0; i < n; i++) {
        ic_scale3(p[i].t, p[i].t, -1.0);
        ic_scale3(p[i].b, p[i].b, -1.0);
        p[i].s = L - p[i].s;
        p[i].knot_side = -p[i].knot_side;
    }
}
