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
static void basis_taylor(double taylor[MAXP][MAXP], const double *k, int s, int p, double t, int m)
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
        const double t = ic_nurbs_wrap(pt, d, at[d]);
        span[d] = ic_nurbs_find_span(pt, d, t, side[d]);
        m[d] = K < pt->p[d] ? K : pt->p[d];
        basis_taylor(b[d], pt->knots[d], span[d], pt->p[d], t, m[d]);
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
