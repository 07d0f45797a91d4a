/*
 * A cell proven empty by the mean value form (system.h): for any point
 * row y and the cell's centre c,
 *   y.F(X)  is in  y.F(c) + sum_k (y.J(X))_k (X_k - c_k)
 * (the mean value theorem on the convex cell; Moore 1966, the centred
 * form), so 0 outside that interval proves the cell empty. Near a singular
 * point or a tangential curve the surfaces touch, every component of F is
 * small there and the plain enclosure of each excludes 0 only on cells of
 * width of order d^2 at distance d. The row y that annihilates J(c) best
 * (its least left singular vector) makes y.J(X) of order d + width, so the
 * form excludes cells of width of order d: the cover near a touching point
 * grows linearly, not quadratically.
 */
#include "system.h"

#include "imat.h"
#include "surface/surface_access.h"

#include <math.h>
#include <string.h>

/* Inverse iterations for the least left singular vector (3 x 3 case):
 * any y is valid, a good one only proves more. */
#define IC_CERTIFY_ROW_ITERATIONS 4

/* The least eigenvector of the symmetric m x m matrix A (m <= 3), unit. */
static int least_vector(const double A[4][4], int m, double *y)
{
    if (m == 1) {
        y[0] = 1.0;
        return 1;
    }
    if (m == 2) { /* closed form of the 2 x 2 eigenproblem */
        const double a = A[0][0], b = A[0][1], c = A[1][1];
        const double lam = 0.5 * (a + c) - hypot(0.5 * (a - c), b);
        const double u[2] = {b, lam - a}, v[2] = {lam - c, b};
        const double nu = hypot(u[0], u[1]), nv = hypot(v[0], v[1]);
        if (!(fmax(nu, nv) > 0.0))
            return 0;
        const double *w = nu >= nv ? u : v;
        const double n = fmax(nu, nv);
        y[0] = w[0] / n, y[1] = w[1] / n;
        return 1;
    }
    double Y[4][4], S[4][4];
    memcpy(S, A, sizeof S);
    const double shift = 1e-14 * (fabs(A[0][0]) + fabs(A[1][1]) + fabs(A[2][2]));
    for (int i = 0; i < m; i++)
        S[i][i] += shift; /* A may be singular: that is the point */
    if (!ic_imat_point_inverse(S, m, Y))
        return 0;
    double v[3] = {1.0, 0.7548776662, 0.5698402910}; /* no special direction */
    for (int it = 0; it < IC_CERTIFY_ROW_ITERATIONS; it++) {
        double w[3] = {0, 0, 0}, n = 0.0;
        for (int i = 0; i < m; i++) {
            for (int j = 0; j < m; j++)
                w[i] += Y[i][j] * v[j];
            n += w[i] * w[i];
        }
        n = sqrt(n);
        if (!(n > 0.0) || !isfinite(n))
            return 0;
        for (int i = 0; i < m; i++)
            v[i] = w[i] / n;
    }
    memcpy(y, v, (size_t)m * sizeof *y);
    return 1;
}

/* 0 outside y.F(c) + sum_k (y.J(X))_k (X_k - c_k). */
static int row_excludes(const double *y, int m, int dim, const ic_certify_eval *at,
                        const ic_certify_eval *over, const ic_interval *X, const double *c)
{
    ic_interval g = {0.0, 0.0};
    for (int i = 0; i < m; i++)
        g = ic_interval_add(g, ic_interval_mul((ic_interval){y[i], y[i]}, at->F[i]));
    for (int k = 0; k < dim; k++) {
        ic_interval d = {0.0, 0.0};
        for (int i = 0; i < m; i++)
            d = ic_interval_add(d, ic_interval_mul((ic_interval){y[i], y[i]}, over->J[i][k]));
        const ic_interval cc = {c[k], c[k]};
        g = ic_interval_add(g, ic_interval_mul(d, ic_interval_sub(X[k], cc)));
    }
    return g.lo > 0.0 || g.hi < 0.0;
}

int ic_certify_centre(const ic_pairing *pg, const ic_interval *X, double *c,
                      ic_certify_eval *at)
{
    ic_interval C[4];
    for (int k = 0; k < pg->kind->dim; k++) {
        c[k] = X[k].lo + 0.5 * (X[k].hi - X[k].lo); /* inside X: any point would do */
        C[k] = (ic_interval){c[k], c[k]};
    }
    return ic_certify_enclose(pg, C, at);
}

/* The same to second order (ic_pairing_taylor2_excludes), for two implicit
 * surfaces with second-order enclosures: where they nearly coincide, y.J
 * over X is of the order of the cell's width, y.H of the gap. */
static int row_excludes_second(const ic_pairing *pg, const double *y, const ic_interval *hc,
                               const ic_interval *gc, const ic_interval *X, const double *c)
{
    ic_interval_hess H[2];
    for (int s = 0; s < 2; s++)
        if (ic_surface_eval_interval_hess(pg->S[s], &H[s], X, NULL) != IC_OK)
            return 0;
    ic_interval Hy[IC_INTERVAL_HESS_LEN];
    for (int i = 0; i < IC_INTERVAL_HESS_LEN; i++) {
        Hy[i] = (ic_interval){0.0, 0.0};
        for (int s = 0; s < 2; s++)
            Hy[i] = ic_interval_add(Hy[i], ic_interval_mul((ic_interval){y[s], y[s]}, H[s].h[i]));
    }
    return ic_pairing_taylor2_excludes(*hc, gc, Hy, X, c, 3);
}


/* y.F over X with the terms the two implicit formulas share enclosed
 * once (ic_surface_combined_interval): surfaces written alike a gap apart. */
static int row_excludes_common(const ic_pairing *pg, const double *y, const ic_interval *X)
{
    ic_interval h;
    return pg->kind->dim == 3 &&
           ic_surface_combined_interval(pg->S[0], (ic_interval){y[0], y[0]}, pg->S[1],
                                        (ic_interval){y[1], y[1]}, X, &h) &&
           (h.lo > 0.0 || h.hi < 0.0);
}

/* The two tighter forms for two implicit surfaces, tried only where y.F(c)
 * is beyond its slope across the cell (ic_pairing_gap_beyond_slope). */
static int row_excludes_closer(const ic_pairing *pg, const double *y, const ic_certify_eval *at,
                               const ic_interval *X, const double *c)
{
    if (pg->kind->dim != 3)
        return 0;
    ic_interval hc = {0.0, 0.0}, gc[3];
    for (int s = 0; s < 2; s++)
        hc = ic_interval_add(hc, ic_interval_mul((ic_interval){y[s], y[s]}, at->F[s]));
    for (int k = 0; k < 3; k++) {
        gc[k] = (ic_interval){0.0, 0.0};
        for (int s = 0; s < 2; s++)
            gc[k] = ic_interval_add(gc[k], ic_interval_mul((ic_interval){y[s], y[s]}, at->J[s][k]));
    }
    return ic_pairing_gap_beyond_slope(hc, gc, X, c, 3) &&
           (row_excludes_common(pg, y, X) || row_excludes_second(pg, y, &hc, gc, X, c));
}

int ic_certify_excludes_centred(const ic_pairing *pg, const ic_interval *X,
                                const ic_certify_eval *over, const double *c,
                                const ic_certify_eval *at)
{
    const int dim = pg->kind->dim, m = dim - 1;
    double A[4][4] = {{0}}, y[3];
    for (int a = 0; a < m; a++)
        for (int b = 0; b < m; b++)
            for (int k = 0; k < dim; k++) {
                const double ja = 0.5 * (at->J[a][k].lo + at->J[a][k].hi);
                const double jb = 0.5 * (at->J[b][k].lo + at->J[b][k].hi);
                A[a][b] += ja * jb;
            }
    const int have_row = least_vector(A, m, y);
    if (have_row && row_excludes(y, m, dim, at, over, X, c))
        return 1;
    for (int i = 0; i < m; i++) { /* each equation alone, centred */
        double e[3] = {0, 0, 0};
        e[i] = 1.0;
        if (row_excludes(e, m, dim, at, over, X, c))
            return 1;
    }
    return have_row && row_excludes_closer(pg, y, at, X, c);
}
