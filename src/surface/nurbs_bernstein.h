/* Tensor-product Bernstein polynomials over a parameter sub-box, for the
 * derivative enclosures of rational patches (nurbs_bernstein.c). */
#ifndef IC_SURFACE_NURBS_BERNSTEIN_H
#define IC_SURFACE_NURBS_BERNSTEIN_H

#include "intercurve/surface.h"

enum { IC_BPOLY_MAX = 2 * IC_NURBS_MAX_DEGREE + 1 };

/* Degrees du, dv; coefficient (i, j) at c[i * (dv + 1) + j]; every
 * coefficient within err of the exact one. */
typedef struct {
    int du, dv;
    double c[IC_BPOLY_MAX * IC_BPOLY_MAX];
    double err;
} ic_bpoly;

/* h = f g (degrees add; the sum at most 2 IC_NURBS_MAX_DEGREE each way). */
void ic_bpoly_mul(ic_bpoly *h, const ic_bpoly *f, const ic_bpoly *g);
/* h = f - g, both of the same degrees. */
void ic_bpoly_sub(ic_bpoly *h, const ic_bpoly *f, const ic_bpoly *g);
/* h = f raised one degree along dir (0: u, 1: v); h and f distinct. */
void ic_bpoly_elevate(ic_bpoly *h, const ic_bpoly *f, int dir);
/* Encloses N / D over the box, N and D of the same degrees and D > 0 there:
 * the hull of the ratios of their coefficients; everything if some
 * coefficient of D cannot be proven positive. */
ic_interval ic_bpoly_ratio_hull(const ic_bpoly *N, const ic_bpoly *D);

/* Encloses n' / d' for every n' within en of n and d' within ed of d,
 * given d - ed > 0 (cheaper than interval division, as sound). */
ic_interval ic_quotient_positive(double n, double en, double d, double ed);

#endif
