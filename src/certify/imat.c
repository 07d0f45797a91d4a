/* Small interval matrices (imat.h). */
#include "imat.h"

#include <math.h>
#include <string.h>

static ic_interval point(double x) { return (ic_interval){x, x}; }

int ic_imat_point_inverse(const double a[4][4], int m, double y[4][4])
{
    double w[4][8];
    for (int i = 0; i < m; i++)
        for (int j = 0; j < m; j++) {
            w[i][j] = a[i][j];
            w[i][m + j] = i == j ? 1.0 : 0.0;
        }
    for (int c = 0; c < m; c++) {
        int p = c;
        for (int i = c + 1; i < m; i++)
            if (fabs(w[i][c]) > fabs(w[p][c]))
                p = i;
        if (!(fabs(w[p][c]) > 0.0) || !isfinite(w[p][c]))
            return 0;
        for (int j = 0; j < 2 * m; j++) {
            const double t = w[c][j];
            w[c][j] = w[p][j], w[p][j] = t;
        }
        const double piv = w[c][c];
        for (int j = 0; j < 2 * m; j++)
            w[c][j] /= piv;
        for (int i = 0; i < m; i++)
            if (i != c && w[i][c] != 0.0) {
                const double f = w[i][c];
                for (int j = 0; j < 2 * m; j++)
                    w[i][j] -= f * w[c][j];
            }
    }
    for (int i = 0; i < m; i++)
        for (int j = 0; j < m; j++) {
            y[i][j] = w[i][m + j];
            if (!isfinite(y[i][j]))
                return 0;
        }
    return 1;
}

void ic_imat_mid(const ic_interval M[4][4], int m, double a[4][4])
{
    for (int i = 0; i < m; i++)
        for (int j = 0; j < m; j++)
            a[i][j] = 0.5 * M[i][j].lo + 0.5 * M[i][j].hi;
}

/* I - Y M, each entry an enclosure. */
static void residual_matrix(const double y[4][4], const ic_interval M[4][4], int m,
                            ic_interval R[4][4])
{
    for (int i = 0; i < m; i++)
        for (int j = 0; j < m; j++) {
            ic_interval s = point(i == j ? 1.0 : 0.0);
            for (int k = 0; k < m; k++)
                s = ic_interval_sub(s, ic_interval_mul(point(y[i][k]), M[k][j]));
            R[i][j] = s;
        }
}

/* The midpoint inverse of M; 0 when M's midpoint is singular or M is not
 * finite. */
static int midpoint_inverse(const ic_interval M[4][4], int m, double y[4][4])
{
    double a[4][4];
    for (int i = 0; i < m; i++)
        for (int j = 0; j < m; j++)
            if (!isfinite(M[i][j].lo) || !isfinite(M[i][j].hi))
                return 0;
    ic_imat_mid(M, m, a);
    return ic_imat_point_inverse(a, m, y);
}

int ic_imat_regular(const ic_interval M[4][4], int m)
{
    double y[4][4];
    if (!midpoint_inverse(M, m, y))
        return 0;
    ic_interval R[4][4];
    residual_matrix(y, M, m, R);
    for (int i = 0; i < m; i++) {
        ic_interval s = point(0.0);
        for (int j = 0; j < m; j++)
            s = ic_interval_add(s, ic_interval_abs(R[i][j]));
        if (!(s.hi < 1.0))
            return 0;
    }
    return 1;
}

int ic_imat_krawczyk(const ic_interval *X, const ic_interval *Fc, const ic_interval M[4][4], int m,
                     ic_interval *K)
{
    double y[4][4];
    if (!midpoint_inverse(M, m, y))
        return 0;
    ic_interval R[4][4];
    residual_matrix(y, M, m, R);
    double c[4];
    ic_interval d[4];
    for (int j = 0; j < m; j++) {
        c[j] = 0.5 * X[j].lo + 0.5 * X[j].hi;
        d[j] = ic_interval_sub(X[j], point(c[j]));
    }
    for (int i = 0; i < m; i++) {
        ic_interval s = point(c[i]);
        for (int k = 0; k < m; k++) {
            s = ic_interval_sub(s, ic_interval_mul(point(y[i][k]), Fc[k]));
            s = ic_interval_add(s, ic_interval_mul(R[i][k], d[k]));
        }
        if (!(s.lo <= s.hi))
            return 0;
        K[i] = s;
    }
    return 1;
}

int ic_imat_strictly_inside(const ic_interval *K, const ic_interval *X, int m)
{
    for (int j = 0; j < m; j++)
        if (!(K[j].lo > X[j].lo && K[j].hi < X[j].hi))
            return 0;
    return 1;
}

int ic_imat_disjoint(const ic_interval *K, const ic_interval *X, int m)
{
    for (int j = 0; j < m; j++)
        if (K[j].hi < X[j].lo || K[j].lo > X[j].hi)
            return 1;
    return 0;
}
