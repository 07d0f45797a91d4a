/* Tensor-product Bernstein polynomials on a sub-box, with a bound on their
 * coefficients' rounding error: products (Farouki and Rajan 1988: the
 * coefficients of a product are binomially weighted sums of products of
 * coefficients), degree elevation, and the enclosure of a quotient N / D
 * with D > 0 by its coefficient ratios (a rational Bezier function with
 * positive weights lies in the hull of its points N_k / D_k). */
#include "nurbs_bernstein.h"

#include <float.h>
#include <math.h>

/* the larger and smaller of two finite numbers (fmax and fmin are calls) */
static inline double max2(double a, double b) { return a > b ? a : b; }
static inline double min2(double a, double b) { return a < b ? a : b; }
#include <string.h>

/* Pascal's triangle up to the degree of a product. */
typedef struct {
    double c[IC_BPOLY_MAX][IC_BPOLY_MAX];
} binomials;

static void make_binomials(binomials *b, int n)
{
    for (int i = 0; i <= n; i++) {
        b->c[i][0] = b->c[i][i] = 1;
        for (int k = 1; k < i; k++)
            b->c[i][k] = b->c[i - 1][k - 1] + b->c[i - 1][k]; /* exact: below 2^53 */
    }
}

/* w[i][k] = C(m, i) C(n, k) / C(m + n, i + k): the weights of a product. */
static void product_weights(double w[][IC_BPOLY_MAX], const binomials *b, int m, int n)
{
    for (int i = 0; i <= m; i++)
        for (int k = 0; k <= n; k++)
            w[i][k] = b->c[m][i] * b->c[n][k] / b->c[m + n][i + k];
}

static double largest(const ic_bpoly *f)
{
    double m = 0;
    for (int i = 0; i < (f->du + 1) * (f->dv + 1); i++)
        m = max2(m, fabs(f->c[i]));
    return m;
}

void ic_bpoly_mul(ic_bpoly *h, const ic_bpoly *f, const ic_bpoly *g)
{
    h->du = f->du + g->du, h->dv = f->dv + g->dv;
    const int nv = h->dv + 1, fv = f->dv + 1, gv = g->dv + 1;
    binomials b;
    make_binomials(&b, h->du > h->dv ? h->du : h->dv);
    double wu[IC_BPOLY_MAX][IC_BPOLY_MAX], wv[IC_BPOLY_MAX][IC_BPOLY_MAX];
    product_weights(wu, &b, f->du, g->du);
    product_weights(wv, &b, f->dv, g->dv);
    memset(h->c, 0, sizeof(double) * (size_t)(h->du + 1) * (size_t)nv);
    for (int i = 0; i <= f->du; i++)
        for (int k = 0; k <= g->du; k++)
            for (int j = 0; j <= f->dv; j++) {
                const double fij = wu[i][k] * f->c[i * fv + j];
                double *row = h->c + (i + k) * nv + j;
                const double *gk = g->c + k * gv;
                for (int l = 0; l <= g->dv; l++)
                    row[l] += wv[j][l] * fij * gk[l];
            }
    /* each coefficient sums at most (f->du + 1)(f->dv + 1) terms whose
     * absolute values add to at most max|f| max|g| (the weights of one
     * coefficient sum to 1), each term rounded in 5 operations */
    const double terms = (double)(f->du + 1) * (f->dv + 1) + 5;
    const double mf = largest(f), mg = largest(g);
    h->err = f->err * mg + g->err * mf + f->err * g->err + 2 * terms * DBL_EPSILON * mf * mg;
}

void ic_bpoly_sub(ic_bpoly *h, const ic_bpoly *f, const ic_bpoly *g)
{
    h->du = f->du, h->dv = f->dv; /* same degrees */
    const int n = (f->du + 1) * (f->dv + 1);
    for (int i = 0; i < n; i++)
        h->c[i] = f->c[i] - g->c[i];
    h->err = f->err + g->err + DBL_EPSILON * (largest(f) + largest(g));
}

void ic_bpoly_elevate(ic_bpoly *h, const ic_bpoly *f, int dir)
{
    const int du = f->du + (dir == 0), dv = f->dv + (dir == 1), fv = f->dv + 1;
    const int d = dir == 0 ? du : dv;
    for (int i = 0; i <= du; i++)
        for (int j = 0; j <= dv; j++) {
            const int k = dir == 0 ? i : j; /* b_k = k/d f_(k-1) + (1 - k/d) f_k */
            const double a = (double)k / d;
            const double lo = k > 0 ? f->c[(dir == 0 ? i - 1 : i) * fv + (dir == 0 ? j : j - 1)] : 0;
            const double hi = k < d ? f->c[i * fv + j] : 0;
            h->c[i * (dv + 1) + j] = a * lo + (1 - a) * hi;
        }
    h->du = du, h->dv = dv;
    h->err = f->err + 4 * DBL_EPSILON * largest(f);
}

ic_interval ic_quotient_positive(double n, double en, double d, double ed)
{
    /* n' / d' with |n' - n| <= en, |d' - d| <= ed < d lies within
     * (en + |n / d| ed) / (d - ed) of n / d; the rounding of q = n / d and of
     * this bound (a few ulps of each, relative) is covered by 4 ulps of q
     * and the factor on the bound */
    const double q = n / d;
    const double e = (en + fabs(q) * ed) / (d - ed) * (1 + 8 * DBL_EPSILON) +
                     4 * DBL_EPSILON * fabs(q);
    return (ic_interval){q - e, q + e};
}

ic_interval ic_bpoly_ratio_hull(const ic_bpoly *N, const ic_bpoly *D)
{
    ic_interval hull = {INFINITY, -INFINITY};
    for (int i = 0; i < (N->du + 1) * (N->dv + 1); i++) {
        if (!(D->c[i] - D->err > 0))
            return (ic_interval){-INFINITY, INFINITY}; /* no bound */
        const ic_interval q = ic_quotient_positive(N->c[i], N->err, D->c[i], D->err);
        hull.lo = min2(hull.lo, q.lo);
        hull.hi = max2(hull.hi, q.hi);
    }
    return hull;
}
