/* Exact Taylor coefficients of a NURBS patch at a point: the B-spline basis
 * and its derivatives on the point's span (Cox-de Boor recursion, Piegl and
 * Tiller 1997, eqs. 2.5 and 2.9), the homogeneous tensor sums, then the
 * quotient x = X / W by jet division (their eq. 4.8 to every order). */
#include "nurbs.h"

#include <math.h>
#include <string.h>

enum { MAXP = IC_NURBS_MAX_DEGREE + 1 };

/* d/dt^r of the degree-p functions nonzero on span s, divided by r!:
 * taylor[r][i] for N_{s-p+i,p}(t), r = 0..m (m <= p), i = 0..p. */
void ic_basis_taylor(double taylor[][IC_NURBS_MAX_DEGREE + 1], const double *k, int s, int p,
                     double t, int m)
{
    /* der[r][d][i]: r-th derivative of the degree-d functions N_{s-d+i,d} */
    double der[MAXP][MAXP][MAXP];
    der[0][0][0] = 1.0;
    for (int d = 1; d <= p; d++)
        for (int i = 0; i <= d; i++) {
            const int g = s - d + i;
            const double hl = k[g + d] - k[g], hr = k[g + d + 1] - k[g + 1];
            double v = 0;
            if (i >= 1 && hl > 0)
                v += (t - k[g]) / hl * der[0][d - 1][i - 1];
            if (i <= d - 1 && hr > 0)
                v += (k[g + d + 1] - t) / hr * der[0][d - 1][i];
            der[0][d][i] = v;
        }
    for (int r = 1; r <= m; r++)
        for (int d = r; d <= p; d++)
            for (int i = 0; i <= d; i++) {
                const int g = s - d + i;
                const double hl = k[g + d] - k[g], hr = k[g + d + 1] - k[g + 1];
                double v = 0;
                if (i >= 1 && hl > 0)
                    v += der[r - 1][d - 1][i - 1] / hl;
                if (i <= d - 1 && hr > 0)
                    v -= der[r - 1][d - 1][i] / hr;
                der[r][d][i] = d * v;
            }
    double fact = 1.0;
    for (int r = 0; r <= m; r++) {
        if (r > 0)
            fact *= r;
        for (int i = 0; i <= p; i++)
            taylor[r][i] = der[r][p][i] / fact;
    }
}

size_t ic_nurbs_taylor_work_len(int n) { return 4 * (size_t)n; }

ic_status ic_nurbs_taylor(const ic_nurbs_patch *pt, double *out, const double at[2],
                          const ic_nurbs_side side[2], const ic_jet_space *sp, double *work,
                          ic_error *err)
{
    const int K = ic_jet_space_order(sp), n = ic_jet_space_len(sp);
    int span[2], m[2];
    double b[2][MAXP][MAXP];
    for (int d = 0; d < 2; d++) {
        const double t = ic_nurbs_wrap_side(pt, d, at[d], side[d]);
        span[d] = ic_nurbs_find_span(pt, d, t, side[d]);
        m[d] = K < pt->p[d] ? K : pt->p[d];
        ic_basis_taylor(b[d], pt->knots[d], span[d], pt->p[d], t, m[d]);
    }
    double *hom = work; /* X, Y, Z, W jets */
    memset(hom, 0, sizeof(double) * 4 * (size_t)n);
    const int p = pt->p[0], q = pt->p[1], nv = pt->n[1];
    for (int a = 0; a <= m[0]; a++)
        for (int c = 0; c <= m[1] && a + c <= K; c++) {
            const int alpha[2] = {a, c};
            const int idx = ic_jet_index(sp, alpha);
            for (int i = 0; i <= p; i++)
                for (int j = 0; j <= q; j++) {
                    const double f = b[0][a][i] * b[1][c][j];
                    const double *P = pt->hom + 4 * ((span[0] - p + i) * nv + span[1] - q + j);
                    for (int e = 0; e < 4; e++)
                        hom[e * n + idx] += f * P[e];
                }
        }
    if (!pt->rational) { /* W is the constant common weight */
        const double w = pt->hom[3];
        for (int e = 0; e < 3; e++)
            for (int i = 0; i < n; i++)
                out[e * n + i] = w == 1.0 ? hom[e * n + i] : hom[e * n + i] / w;
        return IC_OK;
    }
    for (int e = 0; e < 3; e++) {
        const ic_status st = ic_jet_div(out + e * n, hom + e * n, hom + 3 * n, sp, err);
        if (st != IC_OK)
            return st;
    }
    return IC_OK;
}

size_t ic_nurbs_compose_work_len(const ic_nurbs_patch *pt, int n)
{
    /* the two parameter offsets, every basis function's jet, a row sum, a
     * product and the four homogeneous coordinates */
    return (size_t)n * (size_t)(2 + pt->p[0] + 1 + pt->p[1] + 1 + 2 + 4);
}

/* The jet of the polynomial sum_k a[k] delta^k (k = 0..deg) by Horner's
 * rule in jet arithmetic (tmp: one jet). */
static void horner(double *out, const double a[MAXP], int deg, const double *delta,
                   const ic_jet_space *sp, double *tmp)
{
    ic_jet_set_const(out, a[deg], sp);
    for (int k = deg - 1; k >= 0; k--) {
        ic_jet_mul(tmp, out, delta, sp);
        ic_jet_add_const(out, tmp, a[k], sp);
    }
}

ic_status ic_nurbs_compose(const ic_nurbs_patch *pt, double *out, const double *const *in,
                           const ic_nurbs_side side[2], const ic_jet_space *sp, double *work,
                           ic_error *err)
{
    const int n = ic_jet_space_len(sp), p = pt->p[0], q = pt->p[1], nv = pt->n[1];
    double *delta[2] = {work, work + n}, *basis[2] = {work + 2 * n, work + (3 + p) * n};
    double *row = work + (4 + p + q) * n, *prod = row + n, *hom = prod + n;
    int span[2];
    for (int d = 0; d < 2; d++) {
        /* the piece's whole polynomial about the point: Taylor to its degree */
        double b[MAXP][MAXP], a[MAXP];
        const double t = ic_nurbs_wrap_side(pt, d, in[d][0], side[d]);
        span[d] = ic_nurbs_find_span(pt, d, t, side[d]);
        ic_basis_taylor(b, pt->knots[d], span[d], pt->p[d], t, pt->p[d]);
        ic_jet_copy(delta[d], in[d], sp);
        delta[d][0] = 0;
        for (int i = 0; i <= pt->p[d]; i++) {
            for (int k = 0; k <= pt->p[d]; k++)
                a[k] = b[k][i];
            horner(basis[d] + (size_t)i * n, a, pt->p[d], delta[d], sp, prod);
        }
    }
    for (int e = 0; e < 4; e++) { /* X = sum_i N_i (sum_j P_ij M_j) */
        double *acc = hom + (size_t)e * n;
        ic_jet_zero(acc, sp);
        for (int i = 0; i <= p; i++) {
            ic_jet_zero(row, sp);
            for (int j = 0; j <= q; j++) {
                const double c = pt->hom[4 * ((span[0] - p + i) * nv + span[1] - q + j) + e];
                const double *M = basis[1] + (size_t)j * n;
                for (int k = 0; k < n; k++)
                    row[k] += c * M[k];
            }
            ic_jet_mul(prod, basis[0] + (size_t)i * n, row, sp);
            for (int k = 0; k < n; k++)
                acc[k] += prod[k];
        }
    }
    for (int e = 0; e < 3; e++) {
        if (!pt->rational) {
            ic_jet_scale(out + (size_t)e * n, hom + (size_t)e * n, 1 / pt->hom[3], sp);
            continue;
        }
        const ic_status st = ic_jet_div(out + (size_t)e * n, hom + (size_t)e * n, hom + 3 * (size_t)n,
                                        sp, err);
        if (st != IC_OK)
            return st;
    }
    return IC_OK;
}

void ic_nurbs_point(const ic_nurbs_patch *pt, const double uv[2], const ic_nurbs_side side[2],
                    double out[3])
{
    int span[2];
    double b[2][1][IC_NURBS_MAX_DEGREE + 1], h[4] = {0, 0, 0, 0};
    for (int d = 0; d < 2; d++) {
        const double t = ic_nurbs_wrap_side(pt, d, uv[d], side[d]);
        span[d] = ic_nurbs_find_span(pt, d, t, side[d]);
        ic_basis_taylor(b[d], pt->knots[d], span[d], pt->p[d], t, 0);
    }
    const int p = pt->p[0], q = pt->p[1], nv = pt->n[1];
    for (int i = 0; i <= p; i++)
        for (int j = 0; j <= q; j++) {
            const double f = b[0][0][i] * b[1][0][j];
            const double *P = pt->hom + 4 * ((span[0] - p + i) * nv + span[1] - q + j);
            for (int e = 0; e < 4; e++)
                h[e] += f * P[e];
        }
    /* as ic_nurbs_taylor's constant terms, to the last bit: the common
     * weight of a polynomial patch, else the jet quotient's reciprocal */
    const double w = pt->hom[3], inv = 1.0 / h[3];
    for (int e = 0; e < 3; e++)
        out[e] = !pt->rational ? (w == 1.0 ? h[e] : h[e] / w) : h[e] * inv;
}
