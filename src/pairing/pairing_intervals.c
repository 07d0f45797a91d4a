/*
 * Interval pieces the kinds' proofs share (pairing.h): the loop test's
 * one-sided tangent cone and the centred form of a function over a cell.
 *
 * Loop test (normal cones, docs/tracing.md): a closed intersection curve
 * inside a cell of two surfaces in space has a tangent parallel to
 * T = N_A x N_B; if T . v keeps one sign over the cell for a fixed v, x . v
 * is strictly monotone along every curve in the cell, so none closes there.
 *
 * Centred form: for h with interval gradient G over the cell X and centre
 * c, h(X) is inside h(c) + sum_k G_k (X_k - c_k) (mean value theorem), whose
 * width shrinks like the cell squared where the gradient varies little.
 * Every value at c is an interval (outward rounded): exclusion is proven.
 */
#include "pairing.h"

#include <math.h>

ic_interval ic_pairing_point(double x) { return (ic_interval){x, x}; }

ic_interval ic_pairing_mid(ic_interval a) { return ic_pairing_point(0.5 * (a.lo + a.hi)); }

void ic_pairing_cross(ic_interval *c, const ic_interval *a, const ic_interval *b)
{
    for (int i = 0; i < 3; i++) {
        const int j = (i + 1) % 3, k = (i + 2) % 3;
        c[i] = ic_interval_sub(ic_interval_mul(a[j], b[k]), ic_interval_mul(a[k], b[j]));
    }
}

/* Does T . v keep one sign for v = the midpoint direction of T, or for a
 * coordinate axis? */
int ic_pairing_one_sided(const ic_interval *T)
{
    double v[3], len = 0;
    for (int i = 0; i < 3; i++) {
        if (ic_pairing_excludes_zero(T[i]))
            return 1;
        v[i] = 0.5 * (T[i].lo + T[i].hi);
        len += v[i] * v[i];
    }
    if (!(len > 0) || !isfinite(len))
        return 0;
    ic_interval dot = {0, 0};
    for (int i = 0; i < 3; i++)
        dot = ic_interval_add(dot, ic_interval_mul(T[i], ic_pairing_point(v[i])));
    return ic_pairing_excludes_zero(dot);
}

int ic_pairing_param_normal(ic_surface *s, const double *lo, const double *hi, ic_interval *N)
{
    const ic_interval box[2] = {{lo[0], hi[0]}, {lo[1], hi[1]}};
    ic_interval_grad R[3];
    if (ic_surface_eval_interval_grad(s, R, box, NULL) != IC_OK)
        return 0;
    ic_interval Ru[3], Rv[3];
    for (int i = 0; i < 3; i++)
        Ru[i] = R[i].d[0], Rv[i] = R[i].d[1];
    ic_pairing_cross(N, Ru, Rv);
    return 1;
}

int ic_pairing_sheet_may_degenerate(ic_surface *s, const double *lo, const double *hi)
{
    ic_interval N[3];
    if (!ic_pairing_param_normal(s, lo, hi, N))
        return 1;
    return !ic_pairing_excludes_zero(N[0]) && !ic_pairing_excludes_zero(N[1]) &&
           !ic_pairing_excludes_zero(N[2]);
}

int ic_pairing_centred_excludes(ic_interval hc, const ic_interval *G, const double *lo,
                                const double *hi, int n)
{
    ic_interval sum = hc;
    for (int k = 0; k < n; k++) {
        const double c = 0.5 * (lo[k] + hi[k]);
        const ic_interval dx = ic_interval_sub((ic_interval){lo[k], hi[k]}, ic_pairing_point(c));
        sum = ic_interval_add(sum, ic_interval_mul(G[k], dx));
    }
    return ic_pairing_excludes_zero(sum);
}

int ic_pairing_taylor2_excludes(ic_interval hc, const ic_interval *gc, const ic_interval *H,
                                const ic_interval *X, const double *c, int n)
{
    ic_interval dx[4], sum = hc;
    for (int k = 0; k < n; k++) {
        dx[k] = ic_interval_sub(X[k], ic_pairing_point(c[k]));
        sum = ic_interval_add(sum, ic_interval_mul(gc[k], dx[k]));
    }
    const ic_interval half = {0.5, 0.5};
    for (int j = 0; j < n; j++)
        for (int k = j; k < n; k++) {
            const ic_interval h = H[ic_interval_hess_index(j, k)];
            const ic_interval term = j == k ? ic_interval_mul(half, ic_interval_pow_int(dx[j], 2))
                                            : ic_interval_mul(dx[j], dx[k]);
            sum = ic_interval_add(sum, ic_interval_mul(h, term));
        }
    return ic_pairing_excludes_zero(sum);
}

int ic_pairing_gap_beyond_slope(ic_interval hc, const ic_interval *gc, const ic_interval *X,
                                const double *c, int n)
{
    if (!(hc.lo > 0.0 || hc.hi < 0.0))
        return 0;
    double slope = 0.0;
    for (int k = 0; k < n; k++) {
        const double g = fmax(fabs(gc[k].lo), fabs(gc[k].hi));
        slope += g * fmax(fabs(X[k].hi - c[k]), fabs(c[k] - X[k].lo));
    }
    return fmin(fabs(hc.lo), fabs(hc.hi)) > slope;
}
