/*
 * An ellipse of an exact path as a traced curve (exact_ellipse.h): points
 * equally spaced in theta, each with its exact apparatus, and the arc
 * length between them by Gauss-Legendre quadrature with a proven bound.
 * p(theta) = c + a cos(theta) u + b sin(theta) v; the speed |p'| =
 * sqrt(a^2 sin^2 + b^2 cos^2), t = p' / |p'|, n = -(b cos u + a sin v) /
 * |p'| (towards the centre), b = u x v, kappa = a b / |p'|^3, tau = 0.
 */
#include "exact_ellipse.h"
#include "exact_common.h"
#include "common/mathconst.h"
#include "common/vec3.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* relative: the bound allowed on the quadrature error of an ellipse's
 * whole length, one rounding of it */
#define IC_EXACT_ARC_REL DBL_EPSILON
/* count: the most equal parts an arc is split into for its quadrature;
 * where even that cannot bound the error (an ellipse some 1e5 times longer
 * than wide at the default step), the general path traces the curve */
#define IC_EXACT_MAX_SPLIT 64

/* Gauss-Legendre, 8 nodes on [-1, 1] (Abramowitz and Stegun (1964), table
 * 25.4; checked against the roots of P_8 with mpmath at 40 digits): the
 * positive nodes and their weights, the rule symmetric. */
static const double GAUSS_X[4] = {0.18343464249564980494, 0.52553240991632898582,
                                  0.79666647741362673959, 0.96028985649753623168};
static const double GAUSS_W[4] = {0.36268378337836198297, 0.31370664587788728734,
                                  0.22238103445337447054, 0.10122853629037625915};
#define GAUSS_NODES 8

void ic_exact_ellipse_extent(const ic_exact_ellipse *e, double extent[3])
{
    for (int k = 0; k < 3; k++)
        extent[k] = hypot(e->a * e->u[k], e->b * e->v[k]);
}

/* The step in theta. The marching's rules (ic_exact_circle_step) with the
 * local radius of curvature rho = |p'|^3 / (a b) ask for an arc h with h /
 * |p'| growing with |p'| (the chord rule sqrt(8 chord rho) / |p'| ~
 * |p'|^(1/2), a truncation term of order k ~ |p'|^((2k-3)/k)): the
 * tightest place is the end of the major axis, rho = b^2 / a and |p'| = b
 * (b the smaller semi-axis, a the larger). The longest step bounds the arc
 * where |p'| is largest, a. */
static double theta_step(const ic_trace_options *opt, double a, double b)
{
    return fmin(ic_exact_circle_step(opt, b * b / a) / b, opt->max_step / a);
}

/* A bound on the error of 8-node Gauss-Legendre over `parts` intervals of
 * width w of the speed of the ellipse with semi-axes a >= b (Trefethen
 * (2008), theorem 4.5: 64 M / (15 (1 - rho^-2) rho^16) on [-1, 1] for a
 * function analytic inside the Bernstein ellipse E_rho, |f| <= M there;
 * times w / 2 on an interval of width w). The speed squared, b^2 + (a^2 -
 * b^2) sin^2 z, has a positive real part in the strip |Im z| < y0 =
 * asinh(b / sqrt(a^2 - b^2)): the speed is analytic there. The ellipse of
 * semi-minor axis y0 / 2 about an interval has rho = (y0/2 + sqrt((y0/2)^2
 * + (w/2)^2)) / (w/2), and there |speed| <= a cosh(y0 / 2). */
static double gauss_bound(double a, double b, double w, double parts)
{
    if (!(a > b))
        return 0.0; /* a circle: the speed is constant, the rule exact */
    const double y = 0.5 * asinh(b / sqrt((a - b) * (a + b))), hw = 0.5 * w;
    const double rho = (y + sqrt(y * y + hw * hw)) / hw, M = a * cosh(y);
    return parts * hw * 64 * M / (15 * (1 - 1 / (rho * rho)) * pow(rho, 2 * GAUSS_NODES));
}

int ic_exact_ellipse_plan(const ic_trace_options *opt, const ic_exact_ellipse *e,
                          ic_ellipse_plan *plan)
{
    const double a = fmax(e->a, e->b), b = fmin(e->a, e->b);
    double n = ceil(2 * IC_PI / theta_step(opt, a, b) / 8) * 8;
    n = n < IC_EXACT_MIN_ARCS ? IC_EXACT_MIN_ARCS : n;
    if (!(n + 1 <= opt->max_points))
        return -1;
    plan->n = (int)n;
    /* the perimeter is at least 4 a (twice the major axis) */
    for (int m = 1; m <= IC_EXACT_MAX_SPLIT; m *= 2)
        if (gauss_bound(a, b, 2 * IC_PI / (n * m), n * m) <= IC_EXACT_ARC_REL * 4 * a) {
            plan->split = m;
            return 0;
        }
    return -1;
}

/* The cosine and sine of theta_j = 2 pi j / n for j = 0..n/4 from those
 * of the first octant (oct[j], j = 0..n/8), reflected about pi/4. */
static void quarter_angle(const double (*oct)[2], int n, int j, double *cs, double *sn)
{
    const int q = n / 4;
    if (j <= n / 8)
        *cs = oct[j][0], *sn = oct[j][1];
    else
        *cs = oct[q - j][1], *sn = oct[q - j][0];
}

/* The arc length S[j] from theta = 0 to theta_j, j = 0..n/4: each arc by
 * Gauss-Legendre on plan->split parts, summed with Kahan's compensation.
 * The speed depends on sin^2 only: the other quadrants are reflections. */
static void quarter_lengths(const ic_exact_ellipse *e, const ic_ellipse_plan *plan,
                            const double (*oct)[2], double *S)
{
    const int n = plan->n, m = plan->split;
    const double w = 2 * IC_PI / n / m, b2 = e->b * e->b, d2 = e->a * e->a - b2;
    /* the nodes' offsets from an arc's start, their cosines and sines */
    double cd[IC_EXACT_MAX_SPLIT * GAUSS_NODES], sd[IC_EXACT_MAX_SPLIT * GAUSS_NODES];
    double wt[IC_EXACT_MAX_SPLIT * GAUSS_NODES];
    for (int i = 0; i < m; i++)
        for (int k = 0; k < GAUSS_NODES; k++) {
            const double x = k < 4 ? -GAUSS_X[3 - k] : GAUSS_X[k - 4];
            const double delta = (i + 0.5 * (1 + x)) * w;
            cd[i * GAUSS_NODES + k] = cos(delta), sd[i * GAUSS_NODES + k] = sin(delta);
            wt[i * GAUSS_NODES + k] = 0.5 * w * GAUSS_W[k < 4 ? 3 - k : k - 4];
        }
    double sum = 0, carry = 0;
    S[0] = 0;
    for (int j = 0; j < n / 4; j++) {
        double cs, sn, arc = 0;
        quarter_angle(oct, n, j, &cs, &sn);
        for (int k = 0; k < m * GAUSS_NODES; k++) {
            const double s = sn * cd[k] + cs * sd[k];
            arc += wt[k] * sqrt(b2 + d2 * s * s);
        }
        const double y = arc - carry, t = sum + y;
        carry = (t - sum) - y;
        S[j + 1] = sum = t;
    }
}

/* The arc length at point k of n from the quarter's table (q = n/4). */
static double arc_at(const double *S, int q, int k)
{
    if (k <= q)
        return S[k];
    if (k <= 2 * q)
        return 2 * S[q] - S[2 * q - k];
    if (k <= 3 * q)
        return 2 * S[q] + S[k - 2 * q];
    return 4 * S[q] - S[4 * q - k];
}

/* The angle between two normals, either way round: in [0, pi/2]. atan of
 * the quotient rather than atan2: half the time, within an ulp. */
static double normal_angle(const double *g, const double *h)
{
    double x[3];
    ic_cross3(x, g, h);
    const double sine = ic_norm3(x), cosine = fabs(ic_dot3(g, h));
    return sine == 0 ? 0.0 : cosine == 0 ? 0.5 * IC_PI : atan(sine / cosine);
}

/* The point at the angle of cosine cs and sine sn, its apparatus (not s;
 * the angle between the normals only when `angle` is set). The point was
 * zeroed (calloc: no parameters, no knot line): a memset of each point
 * here took a third of the time. */
static void ellipse_point(ic_trace_point *p, const ic_exact_ellipse *e, const double *binormal,
                          double cs, double sn, int angle)
{
    const double ac = e->a * cs, bs = e->b * sn, as = e->a * sn, bc = e->b * cs;
    const double speed = sqrt(as * as + bc * bc), inv = 1 / speed;
    double g[2][3];
    for (int i = 0; i < 3; i++) {
        p->xyz[i] = e->c[i] + ac * e->u[i] + bs * e->v[i];
        p->t[i] = (bc * e->v[i] - as * e->u[i]) * inv;
        p->n[i] = -(bc * e->u[i] + as * e->v[i]) * inv;
        p->b[i] = binormal[i];
        for (int s = 0; s < 2; s++)
            g[s][i] = e->grad[s][0][i] + cs * e->grad[s][1][i] + sn * e->grad[s][2][i];
    }
    p->kappa = e->a * e->b * inv * inv * inv;
    p->tau = 0.0;
    if (angle)
        p->angle = normal_angle(g[0], g[1]);
    p->frame_defined = 1;
}

/* The n + 1 points (the last the first again), their apparatus from the
 * cosines and sines of the first octant reflected to all eight (as the
 * circles of exact_revolution.c), their arc length from the quarter's. */
static void ellipse_points(ic_trace_point *pts, const ic_exact_ellipse *e, int n,
                           const double (*oct)[2], const double *S)
{
    double binormal[3];
    ic_cross3(binormal, e->u, e->v);
    const int q = n / 4;
    for (int j = 0; j <= n / 8; j++) {
        const double cs = oct[j][0], sn = oct[j][1];
        const int k[8] = {j, q - j, q + j, 2 * q - j, 2 * q + j, 3 * q - j, 3 * q + j, (n - j) % n};
        const double cc[8] = {cs, sn, -sn, -cs, -cs, -sn, sn, cs};
        const double ss[8] = {sn, cs, cs, sn, -sn, -cs, -cs, -sn};
        for (int m = 0; m < 8; m++) {
            /* symmetric: the angle at theta_j (m = 0) serves pi - theta_j,
             * pi + theta_j and 2 pi - theta_j (m = 3, 4, 7), the one at
             * pi/2 - theta_j (m = 1) the others */
            const int own = !e->symmetric || m < 2;
            ellipse_point(&pts[k[m]], e, binormal, cc[m], ss[m], own);
            if (!own)
                pts[k[m]].angle = pts[k[m == 3 || m == 4 || m == 7 ? 0 : 1]].angle;
            pts[k[m]].s = arc_at(S, q, k[m]);
        }
    }
    if (e->branch_ends) /* the normals are parallel there: exactly, not to rounding */
        pts[0].angle = pts[2 * q].angle = 0.0;
    pts[n] = pts[0];
    pts[n].s = 4 * S[q];
}

ic_status ic_exact_add_ellipse(ic_trace_result *r, const ic_exact_ellipse *e,
                               const ic_ellipse_plan *plan, const ic_trace_options *opt,
                               ic_error *err)
{
    const int n = plan->n;
    ic_trace_point *pts = calloc((size_t)n + 1, sizeof *pts);
    /* scratch: the octant's cosines and sines, the quarter's arc lengths */
    double(*oct)[2] = malloc((size_t)(n / 8 + 1) * sizeof *oct);
    double *S = malloc((size_t)(n / 4 + 1) * sizeof *S);
    if (!pts || !oct || !S) {
        free(pts), free(oct), free(S);
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory adding a curve");
    }
    for (int j = 0; j <= n / 8; j++)
        oct[j][0] = cos(2 * IC_PI * j / n), oct[j][1] = sin(2 * IC_PI * j / n);
    quarter_lengths(e, plan, (const double(*)[2])oct, S);
    ellipse_points(pts, e, n, (const double(*)[2])oct, S);
    free(oct), free(S);
    /* the shape test's verdict (shape.c), read from the semi-axes: tau is 0
     * exactly, so planar, or a circle where kappa, between b / a^2 and a /
     * b^2 at the ends of the axes (points of every ellipse: n is a multiple
     * of 4), varies by at most shape_tol of its largest value */
    const double lo = fmin(e->a, e->b), hi = fmax(e->a, e->b);
    const double kmax = hi / (lo * lo), kmin = lo / (hi * hi);
    const ic_shape shape = kmax - kmin <= opt->shape_tol * kmax ? IC_SHAPE_CIRCLE : IC_SHAPE_PLANAR;
    return ic_trace_add_shaped_curve(r, pts, n + 1, 1, IC_TRACE_CLOSED, IC_TRACE_CLOSED,
                                     opt->shape_tol, shape, -1, -1, err);
}
