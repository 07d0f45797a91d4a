/* Plane rational curves of a net (net_curve.h): evaluation, and the two
 * identities the recognition checks: on a line (control points on it) and
 * on a circle (a polynomial identity, its Bernstein coefficients on every
 * span). */
#include "net_curve.h"
#include "nurbs.h"
#include "nurbs_bernstein.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>

enum { MAXP = IC_NURBS_MAX_DEGREE + 1 };

/* relative to the largest coordinate of a span's control points: the
 * rounding of one blossom level (nurbs_interval.c's bound), over the
 * degree's levels and one more */
#define NET_ROUNDING_PER_LEVEL (16 * DBL_EPSILON)

int ic_net_curve_alloc(ic_net_curve *c, int p, int n, const double *knots)
{
    c->p = p, c->n = n, c->knots = knots;
    c->hom = malloc(sizeof *c->hom * (size_t)n);
    return c->hom ? 0 : -1;
}

void ic_net_curve_free(ic_net_curve *c)
{
    free(c->hom);
    c->hom = NULL;
}

void ic_net_curve_point(const ic_net_curve *c, double t, double out[2])
{
    const int s = ic_knot_span(c->knots, c->p, c->n, t, IC_NURBS_RIGHT);
    double b[1][IC_NURBS_MAX_DEGREE + 1], h[3] = {0, 0, 0};
    ic_basis_taylor(b, c->knots, s, c->p, t, 0);
    for (int i = 0; i <= c->p; i++)
        for (int e = 0; e < 3; e++)
            h[e] += b[0][i] * c->hom[s - c->p + i][e];
    out[0] = h[0] / h[2], out[1] = h[1] / h[2];
}

double ic_net_curve_line_gap(const ic_net_curve *c, const double c0[2], const double d[2])
{
    double gap = 0;
    for (int i = 0; i < c->n; i++) {
        const double x = c->hom[i][0] / c->hom[i][2] - c0[0];
        const double y = c->hom[i][1] / c->hom[i][2] - c0[1];
        gap = fmax(gap, fabs(x * d[1] - y * d[0]));
    }
    return gap;
}

/* The Bernstein forms of X - cx W, Y - cy W and W on span s over [a, b]. */
static void span_forms(const ic_net_curve *c, int s, double a, double b, const double centre[2],
                       ic_bpoly f[3])
{
    double net[MAXP][3], big = 0;
    ic_nurbs_blossom(&net[0][0], 3, &c->hom[s - c->p][0], 3, 3, c->p, c->knots, s, a, b);
    for (int k = 0; k <= c->p; k++)
        for (int e = 0; e < 3; e++)
            big = fmax(big, fabs(net[k][e]));
    for (int e = 0; e < 3; e++) {
        f[e].du = c->p, f[e].dv = 0;
        f[e].err = NET_ROUNDING_PER_LEVEL * (c->p + 1) * big * (1 + fabs(centre[e % 2]));
    }
    for (int k = 0; k <= c->p; k++) {
        f[0].c[k] = net[k][0] - centre[0] * net[k][2];
        f[1].c[k] = net[k][1] - centre[1] * net[k][2];
        f[2].c[k] = net[k][2];
    }
}

static double largest(const ic_bpoly *f)
{
    double m = 0;
    for (int k = 0; k <= f->du; k++)
        m = fmax(m, fabs(f->c[k]));
    return m;
}

double ic_net_curve_circle_gap(const ic_net_curve *c, const double centre[2], double r)
{
    double worst = 0;
    for (int s = c->p; s < c->n; s++) {
        if (!(c->knots[s] < c->knots[s + 1]))
            continue;
        ic_bpoly f[3], xx, yy, ww, sum, rw, poly;
        span_forms(c, s, c->knots[s], c->knots[s + 1], centre, f);
        double wmin = INFINITY;
        for (int k = 0; k <= c->p; k++)
            wmin = fmin(wmin, f[2].c[k]);
        wmin -= f[2].err;
        if (!(wmin > 0) || !(r > 0))
            return INFINITY;
        rw = f[2];
        for (int k = 0; k <= c->p; k++)
            rw.c[k] *= r;
        rw.err = f[2].err * r + DBL_EPSILON * largest(&rw);
        ic_bpoly_mul(&xx, &f[0], &f[0]);
        ic_bpoly_mul(&yy, &f[1], &f[1]);
        ic_bpoly_mul(&ww, &rw, &rw);
        for (int k = 0; k <= xx.du; k++) /* x^2 + y^2: both of degree 2p */
            sum.c[k] = xx.c[k] + yy.c[k];
        sum.du = xx.du, sum.dv = 0;
        sum.err = xx.err + yy.err + DBL_EPSILON * largest(&sum);
        ic_bpoly_sub(&poly, &sum, &ww);
        /* |P| <= max |coefficient| (the Bernstein basis sums to 1), and
         * | |C - centre| - r | = |P| / (W^2 (|C - centre| + r)) */
        worst = fmax(worst, (largest(&poly) + poly.err) / (wmin * wmin * r));
    }
    return worst;
}
