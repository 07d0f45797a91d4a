/* The Bezier net of one polynomial piece of a B-spline over any interval
 * [a, b] of its span, from the blossom (Ramshaw 1989: the net of a degree-p
 * polynomial over [a, b] is f(a^(p-k), b^k), k = 0..p), each blossom value
 * by de Boor's triangle with the arguments a and b in turn. Used by the
 * interval enclosures (nurbs_interval.c) and the recognition of nets
 * (net_curve.c). */
#include "nurbs.h"

enum { MAXP = IC_NURBS_MAX_DEGREE + 1, MAXDIM = 4 };

void ic_nurbs_blossom(double *out, int ostride, const double *ctrl, int cstride, int dim, int deg,
                      const double *kn, int s, double a, double b)
{
    for (int k = 0; k <= deg; k++) {
        double d[MAXP][MAXDIM];
        for (int i = 0; i <= deg; i++)
            for (int e = 0; e < dim; e++)
                d[i][e] = ctrl[i * cstride + e];
        for (int j = 1; j <= deg; j++) {
            const double x = j <= deg - k ? a : b;
            for (int r = deg; r >= j; r--) {
                const int i = s - deg + r;
                const double h = kn[s + r - j + 1] - kn[i];
                const double alpha = h > 0 ? (x - kn[i]) / h : 0.0;
                for (int e = 0; e < dim; e++)
                    d[r][e] = (1 - alpha) * d[r - 1][e] + alpha * d[r][e];
            }
        }
        for (int e = 0; e < dim; e++)
            out[k * ostride + e] = d[deg][e];
    }
}
