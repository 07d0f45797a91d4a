/*
 * Where an ellipse's points go and the arc length between them
 * (exact_ellipse.h). The points are equally spaced in the angle phi with
 * tan(theta) = r tan(phi), r = (b/a)^x (SPACING_EXPONENT): denser in theta
 * near the ends of the major axis, where the curvature is largest.
 * Their number is the fewest that the marching's step rules
 * (ic_exact_circle_step at the local radius of curvature) allow everywhere
 * on the ellipse. The arc length between points is Gauss-Legendre
 * quadrature in phi with a proven bound, summed over the first quadrant
 * (the others are its reflections).
 */
#include "exact_ellipse.h"
#include "exact_common.h"
#include "common/mathconst.h"

#include <float.h>
#include <math.h>

/* exponents: the spacing's r = (b/a)^x takes, of these three, the x that
 * needs the fewest points. With the default options and the ellipse's
 * size as the problem's that is 1.0, 1.1, 1.3, 2.6 and 4.6 times the
 * fewest the rules allow (each point's step at its own rule) at the
 * aspects 1.5, 4, 10, 30 and 100; equal spacing in theta (x = 0) takes 1.3,
 * 2.9, 6.4, 17 and 48 times (measured once by summing ds / h along the
 * ellipse; not asserted). */
static const double SPACING_EXPONENT[3] = {0.45, 0.55, 0.7};
/* relative: the bound allowed on the quadrature error of an ellipse's
 * whole length, one rounding of it */
#define IC_EXACT_ARC_REL DBL_EPSILON
/* count: the most equal parts an arc is split into for its quadrature;
 * where even that cannot bound the error the general path traces the
 * curve. With the default options an ellipse of aspect 1e3 (the most the
 * conic paths accept) needs 4; only coarse steps on long ellipses need
 * more (8 arcs at aspect 100: 64) */
#define IC_EXACT_MAX_SPLIT 64

/* Gauss-Legendre, 8 nodes on [-1, 1] (Abramowitz and Stegun (1964), table
 * 25.4; checked against the roots of P_8 with mpmath at 40 digits): the
 * positive nodes and their weights, the rule symmetric. */
static const double GAUSS_X[4] = {0.18343464249564980494, 0.52553240991632898582,
                                  0.79666647741362673959, 0.96028985649753623168};
static const double GAUSS_W[4] = {0.36268378337836198297, 0.31370664587788728734,
                                  0.22238103445337447054, 0.10122853629037625915};
#define GAUSS_NODES 8

/* The largest step in phi the rules allow at the point where u =
 * sin^2(theta): the arc h(rho) over the speed v = sqrt(b^2 + (a^2 - b^2)
 * u), times dphi/dtheta = r / (r^2 + (1 - r^2) u); rho = v^3 / (a b). */
static double phi_step_at(const ic_trace_options *opt, const ic_exact_ellipse *e, double r,
                          double u)
{
    const double v = sqrt(e->b * e->b + (e->a * e->a - e->b * e->b) * u);
    const double rho = v * v * v / (e->a * e->b);
    return ic_exact_circle_step(opt, rho) / v * r / (r * r + (1 - r * r) * u);
}

/* The smallest of phi_step_at over the ellipse: at the end of an axis, u =
 * 0 or 1. Each rule is a power of rho, h = C rho^x (the longest step x =
 * 0, the chord height 1/2, a truncation term of order k (k-1)/k), so its
 * phi step is C' (alpha + beta u)^p / (gamma + delta u) with p = (3x - 1)
 * / 2, alpha = b^2, beta = a^2 - b^2, gamma = r^2, delta = 1 - r^2. Where
 * the logarithm's derivative p beta / (alpha + beta u) - delta / (gamma +
 * delta u) vanishes, its second derivative is (p^2 - p) (beta / (alpha +
 * beta u))^2: negative for the chord and the truncation terms (0 < p < 1),
 * a maximum. The longest step (p = -1/2) has both factors of the same
 * monotony in u (beta and delta have the sign of a - b). The smallest of
 * all rules over [0, 1] is the smallest of their smallest: at an end. */
static double phi_step(const ic_trace_options *opt, const ic_exact_ellipse *e, double r)
{
    return fmin(phi_step_at(opt, e, r, 0), phi_step_at(opt, e, r, 1));
}

/* A bound on the error of 8-node Gauss-Legendre over `parts` intervals of
 * width w of ds/dphi = r sqrt(N) / (q sqrt(q)), N = b^2 cos^2 + a^2 r^2
 * sin^2 and q = cos^2 + r^2 sin^2 of phi (Trefethen (2008), theorem 4.5: 64 M / (15 (1
 * - rho^-2) rho^16) on [-1, 1] for a function analytic inside the Bernstein
 * ellipse E_rho, |f| <= M there; times w / 2 on an interval of width w).
 * q = (1 + r^2) / 2 + (1 - r^2) / 2 cos(2 phi) and likewise N; where |Im
 * phi| <= y, |cos(2 phi)| <= cosh(2 y). Taking cosh(2 y) halfway between 1
 * and the least ratio R of the constant to the cosine's coefficient keeps
 * Re q >= min(1, r^2) / 2 and Re N > 0: the principal roots are analytic
 * there, so is ds/dphi, |ds/dphi| <= r sqrt(max |N|) / min(Re q)^(3/2), and the
 * ellipse of semi-minor axis y about an interval has rho = (y + sqrt(y^2 +
 * (w/2)^2)) / (w/2). */
static double gauss_bound(const ic_exact_ellipse *e, double r, double w, double parts)
{
    const double r2 = r * r, b2 = e->b * e->b, ar2 = e->a * e->a * r2;
    const double dq = fabs(1 - r2), dn = fabs(b2 - ar2);
    if (dq == 0 && dn == 0)
        return 0.0; /* a circle: ds/dphi is constant, the rule exact */
    const double R = fmin(dq > 0 ? (1 + r2) / dq : INFINITY, dn > 0 ? (b2 + ar2) / dn : INFINITY);
    const double ch = 0.5 * (1 + R), y = 0.5 * acosh(ch), hw = 0.5 * w;
    const double qlow = 0.5 * (1 + r2) - 0.5 * dq * ch, nmax = 0.5 * (b2 + ar2) + 0.5 * dn * ch;
    const double M = r * sqrt(nmax / (qlow * qlow * qlow));
    const double rho = (y + sqrt(y * y + hw * hw)) / hw;
    return parts * hw * 64 * M / (15 * (1 - 1 / (rho * rho)) * pow(rho, 2 * GAUSS_NODES));
}

int ic_exact_ellipse_plan(const ic_trace_options *opt, const ic_exact_ellipse *e,
                          ic_ellipse_plan *plan)
{
    double n = INFINITY;
    for (int i = 0; i < 3; i++) {
        const double r = pow(e->b / e->a, SPACING_EXPONENT[i]);
        const double m = ceil(2 * IC_PI / phi_step(opt, e, r) / 8) * 8;
        if (m < n)
            n = m, plan->r = r;
    }
    n = n < IC_EXACT_MIN_ARCS ? IC_EXACT_MIN_ARCS : n;
    if (!(n + 1 <= opt->max_points))
        return -1;
    plan->n = (int)n;
    /* the perimeter is at least 4 max(a, b), twice the major axis */
    for (int m = 1; m <= IC_EXACT_MAX_SPLIT; m *= 2)
        if (gauss_bound(e, plan->r, 2 * IC_PI / (n * m), n * m) <=
            IC_EXACT_ARC_REL * 4 * fmax(e->a, e->b)) {
            plan->split = m;
            return 0;
        }
    return -1;
}

void ic_exact_quarter_lengths(const ic_exact_ellipse *e, const ic_ellipse_plan *plan,
                              const double (*phi)[2], double *S)
{
    const int n = plan->n, m = plan->split;
    const double w = 2 * IC_PI / n / m, r = plan->r, b2 = e->b * e->b;
    const double ar2 = e->a * e->a * r * r;
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
    double sum = 0, carry = 0; /* Kahan's compensated sum */
    S[0] = 0;
    for (int j = 0; j < n / 4; j++) {
        double arc = 0;
        for (int k = 0; k < m * GAUSS_NODES; k++) {
            const double c = phi[j][0] * cd[k] - phi[j][1] * sd[k];
            const double s = phi[j][1] * cd[k] + phi[j][0] * sd[k];
            const double q = c * c + r * r * s * s;
            arc += wt[k] * r * sqrt((b2 * c * c + ar2 * s * s) / (q * q * q));
        }
        const double y = arc - carry, t = sum + y;
        carry = (t - sum) - y;
        S[j + 1] = sum = t;
    }
}

double ic_exact_ellipse_arc(const ic_exact_ellipse *e, const ic_ellipse_plan *plan, double phi0,
                            double phi1)
{
    const int m = plan->split;
    const double w = (phi1 - phi0) / m, r = plan->r, b2 = e->b * e->b;
    const double ar2 = e->a * e->a * r * r;
    double arc = 0;
    for (int i = 0; i < m; i++)
        for (int k = 0; k < GAUSS_NODES; k++) {
            const double x = k < 4 ? -GAUSS_X[3 - k] : GAUSS_X[k - 4];
            const double at = phi0 + (i + 0.5 * (1 + x)) * w, c = cos(at), s = sin(at);
            const double q = c * c + r * r * s * s;
            arc += 0.5 * w * GAUSS_W[k < 4 ? 3 - k : k - 4] * r *
                   sqrt((b2 * c * c + ar2 * s * s) / (q * q * q));
        }
    return arc;
}
