/* Exact rational NURBS nets written here from their closed forms, for the
 * tests of the recognised nets (test_nurbs_recognize.c, test_nurbs_exact.c):
 * the standard CAD circles (9 points over quarter arcs, 7 over thirds),
 * a sphere's half circle, segments; each curve degree-elevated or given an
 * extra knot by the textbook algorithms on homogeneous points (Piegl and
 * Tiller 1997, eq. 5.36 for a Bezier segment's elevation, eq. 5.15 for
 * Boehm's insertion), its knots scaled and shifted; a circle and a profile
 * revolved as a tensor product at any place, size and turn; a plane as an
 * affine grid. None of this uses the library. */
#ifndef IC_TEST_NURBS_NETS_H
#define IC_TEST_NURBS_NETS_H

#include <math.h>
#include <string.h>

#include "harness.h"
#include "intercurve.h"

#define NET_PI 3.14159265358979323846
enum { NET_MAX_CTRL = 40, NET_MAX_KNOTS = 60 };

/* A plane rational curve: degree, points (x, y) with weights w. */
typedef struct {
    int degree, count;
    double knots[NET_MAX_KNOTS];
    double x[NET_MAX_CTRL], y[NET_MAX_CTRL], w[NET_MAX_CTRL];
} net_curve;

static inline void curve_set(net_curve *c, int degree, int count, const double *knots,
                             const double *x, const double *y, const double *w)
{
    memset(c, 0, sizeof *c);
    c->degree = degree, c->count = count;
    memcpy(c->knots, knots, sizeof(double) * (size_t)(count + degree + 1));
    for (int i = 0; i < count; i++)
        c->x[i] = x[i], c->y[i] = y[i], c->w[i] = w ? w[i] : 1.0;
}

/* The unit circle from (1, 0), counterclockwise: four quarter arcs, their
 * middle points the square's corners with weight cos(pi/4). */
static inline void circle9(net_curve *c)
{
    static const double k[] = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
    static const double x[] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, y[] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
    double w[9];
    for (int i = 0; i < 9; i++)
        w[i] = i % 2 ? sqrt(0.5) : 1.0;
    curve_set(c, 2, 9, k, x, y, w);
}

/* The unit circle as three arcs of 2 pi / 3: their middle points at
 * distance 1 / cos(pi/3) = 2 with weight cos(pi/3) = 1/2. */
static inline void circle7(net_curve *c)
{
    static const double k[] = {0, 0, 0, 1.0 / 3, 1.0 / 3, 2.0 / 3, 2.0 / 3, 1, 1, 1};
    double x[7], y[7], w[7];
    for (int i = 0; i < 7; i++) {
        const double a = NET_PI / 3 * i, r = i % 2 ? 2.0 : 1.0;
        x[i] = r * cos(a), y[i] = r * sin(a), w[i] = i % 2 ? 0.5 : 1.0;
    }
    x[6] = 1, y[6] = 0;
    curve_set(c, 2, 7, k, x, y, w);
}

/* The half circle of radius r about (0, zc) from its south pole to its
 * north pole through (r, zc): two quarter arcs. */
static inline void half_circle(net_curve *c, double r, double zc)
{
    static const double k[] = {0, 0, 0, 0.5, 0.5, 1, 1, 1};
    const double x[] = {0, r, r, r, 0}, y[] = {zc - r, zc - r, zc, zc + r, zc + r};
    const double w[] = {1, sqrt(0.5), 1, sqrt(0.5), 1};
    curve_set(c, 2, 5, k, x, y, w);
}

/* The segment from (x0, y0) to (x1, y1), degree 1. */
static inline void segment(net_curve *c, double x0, double y0, double x1, double y1)
{
    static const double k[] = {0, 0, 1, 1};
    const double x[] = {x0, x1}, y[] = {y0, y1};
    curve_set(c, 1, 2, k, x, y, NULL);
}

/* The curve moved by (dx, dy) and scaled by s about the origin first. */
static inline void curve_place(net_curve *c, double s, double dx, double dy)
{
    for (int i = 0; i < c->count; i++)
        c->x[i] = s * c->x[i] + dx, c->y[i] = s * c->y[i] + dy;
}

/* Knots t -> a t + b (a > 0): the same curve. */
static inline void curve_rescale(net_curve *c, double a, double b)
{
    for (int i = 0; i < c->count + c->degree + 1; i++)
        c->knots[i] = a * c->knots[i] + b;
}

/* Degree raised by one, for a curve made of Bezier segments (clamped ends,
 * every interior knot of multiplicity the degree): each segment's
 * homogeneous points Q_i = i/(p+1) P_(i-1) + (1 - i/(p+1)) P_i, every
 * distinct knot one more time. */
static inline void curve_elevate(net_curve *c)
{
    const int p = c->degree, segs = (c->count - 1) / p;
    net_curve e;
    memset(&e, 0, sizeof e);
    e.degree = p + 1, e.count = segs * (p + 1) + 1;
    for (int s = 0; s < segs; s++)
        for (int i = 0; i <= p + 1; i++) {
            const double a = (double)i / (p + 1);
            const int lo = s * p + i - 1, hi = s * p + i;
            double h[3] = {0, 0, 0};
            if (i > 0)
                h[0] += a * c->w[lo] * c->x[lo], h[1] += a * c->w[lo] * c->y[lo],
                    h[2] += a * c->w[lo];
            if (i <= p)
                h[0] += (1 - a) * c->w[hi] * c->x[hi], h[1] += (1 - a) * c->w[hi] * c->y[hi],
                    h[2] += (1 - a) * c->w[hi];
            const int at = s * (p + 1) + i;
            e.x[at] = h[0] / h[2], e.y[at] = h[1] / h[2], e.w[at] = h[2];
        }
    int n = 0;
    for (int i = 0; i < c->count + p + 1; i++) {
        e.knots[n++] = c->knots[i];
        if (i + 1 == c->count + p + 1 || c->knots[i + 1] != c->knots[i])
            e.knots[n++] = c->knots[i]; /* the last of a run: once more */
    }
    *c = e;
}

/* The knot t inserted (Boehm): the points of the span's p homogeneous
 * blends, Q_i = a_i P_i + (1 - a_i) P_(i-1), a_i = (t - k_i) / (k_(i+p) -
 * k_i); t strictly inside the domain. */
static inline void curve_insert(net_curve *c, double t)
{
    const int p = c->degree;
    int s = p;
    while (!(c->knots[s] <= t && t < c->knots[s + 1]))
        s++;
    net_curve e = *c;
    e.count = c->count + 1;
    for (int i = 0; i <= c->count; i++) {
        double h[3];
        if (i <= s - p) {
            h[0] = c->w[i] * c->x[i], h[1] = c->w[i] * c->y[i], h[2] = c->w[i];
        } else if (i > s) {
            h[0] = c->w[i - 1] * c->x[i - 1], h[1] = c->w[i - 1] * c->y[i - 1], h[2] = c->w[i - 1];
        } else {
            const double a = (t - c->knots[i]) / (c->knots[i + p] - c->knots[i]);
            h[0] = a * c->w[i] * c->x[i] + (1 - a) * c->w[i - 1] * c->x[i - 1];
            h[1] = a * c->w[i] * c->y[i] + (1 - a) * c->w[i - 1] * c->y[i - 1];
            h[2] = a * c->w[i] + (1 - a) * c->w[i - 1];
        }
        e.x[i] = h[0] / h[2], e.y[i] = h[1] / h[2], e.w[i] = h[2];
    }
    for (int i = 0; i <= s; i++)
        e.knots[i] = c->knots[i];
    e.knots[s + 1] = t;
    for (int i = s + 1; i < c->count + p + 1; i++)
        e.knots[i + 1] = c->knots[i];
    *c = e;
}

/* A place in space: origin, scale, and the right-handed frame e1, e2, e3. */
typedef struct {
    double o[3], s, e[3][3];
} net_place;

static inline void net_cross(double *c, const double *a, const double *b)
{
    c[0] = a[1] * b[2] - a[2] * b[1], c[1] = a[2] * b[0] - a[0] * b[2],
    c[2] = a[0] * b[1] - a[1] * b[0];
}

static inline void net_unit(double *a)
{
    const double n = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    a[0] /= n, a[1] /= n, a[2] /= n;
}

static const net_place NET_STANDARD = {{0, 0, 0}, 1, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};

/* A random place: origin in [-1, 1]^3, scale in [0.5, 2], any turn. */
static inline net_place net_random_place(harness_rng *g)
{
    net_place p;
    double a[3], r[3];
    for (int k = 0; k < 3; k++) {
        p.o[k] = harness_uniform(g, -1, 1);
        a[k] = harness_uniform(g, -1, 1), r[k] = harness_uniform(g, -1, 1);
    }
    p.s = harness_uniform(g, 0.5, 2);
    net_unit(a);
    memcpy(p.e[2], a, sizeof a);
    net_cross(p.e[1], a, r);
    net_unit(p.e[1]);
    net_cross(p.e[0], p.e[1], a);
    return p;
}

/* The point of local coordinates (x, y, z). */
static inline void net_to_space(const net_place *p, double x, double y, double z, double out[3])
{
    for (int k = 0; k < 3; k++)
        out[k] = p->o[k] + p->s * (x * p->e[0][k] + y * p->e[1][k] + z * p->e[2][k]);
}

/* A patch description with its arrays. */
typedef struct {
    int degree[2], count[2], periodic[2];
    double knots[2][NET_MAX_KNOTS];
    double points[3 * NET_MAX_CTRL * NET_MAX_CTRL];
    double weights[NET_MAX_CTRL * NET_MAX_CTRL];
} net_patch;

/* The circle (x, y) revolved with the profile (rho, z), placed: P = o + s
 * (rho_j (x_i e1 + y_i e2) + z_j e3), weights multiplied. `around`: the
 * parameter the circle runs along (0: u, 1: v). */
static inline void revolve(net_patch *n, const net_curve *circle, const net_curve *profile,
                           const net_place *pl, int around, int profile_periodic)
{
    memset(n, 0, sizeof *n);
    const net_curve *c[2] = {around ? profile : circle, around ? circle : profile};
    for (int d = 0; d < 2; d++) {
        n->degree[d] = c[d]->degree, n->count[d] = c[d]->count;
        memcpy(n->knots[d], c[d]->knots, sizeof(double) * (size_t)(c[d]->count + c[d]->degree + 1));
    }
    n->periodic[around] = 1, n->periodic[1 - around] = profile_periodic;
    for (int i = 0; i < circle->count; i++)
        for (int j = 0; j < profile->count; j++) {
            const int at = around ? j * circle->count + i : i * profile->count + j;
            net_to_space(pl, profile->x[j] * circle->x[i], profile->x[j] * circle->y[i],
                         profile->y[j], n->points + 3 * at);
            n->weights[at] = circle->w[i] * profile->w[j];
        }
}

/* The plane z = 0 of the place as the affine grid f_i e1 + g_j (cos a e1 +
 * sin a e2) (curves fu, fv of degree and knots their own, their x the
 * coordinates; a the angle between the edges). */
static inline void plane_grid(net_patch *n, const net_curve *fu, const net_curve *fv, double a,
                              const net_place *pl)
{
    memset(n, 0, sizeof *n);
    const net_curve *c[2] = {fu, fv};
    for (int d = 0; d < 2; d++) {
        n->degree[d] = c[d]->degree, n->count[d] = c[d]->count;
        memcpy(n->knots[d], c[d]->knots, sizeof(double) * (size_t)(c[d]->count + c[d]->degree + 1));
    }
    for (int i = 0; i < fu->count; i++)
        for (int j = 0; j < fv->count; j++) {
            const int at = i * fv->count + j;
            net_to_space(pl, fu->x[i] + cos(a) * fv->x[j], sin(a) * fv->x[j], 0,
                         n->points + 3 * at);
            n->weights[at] = 1;
        }
}

static inline ic_status net_surface(ic_surface **s, const net_patch *n, ic_error *err)
{
    const ic_nurbs d = {.degree = {n->degree[0], n->degree[1]},
                        .count = {n->count[0], n->count[1]},
                        .knots = {n->knots[0], n->knots[1]},
                        .points = n->points,
                        .weights = n->weights,
                        .periodic = {n->periodic[0], n->periodic[1]}};
    return ic_surface_new_nurbs(s, &d, err);
}

#endif
