/* Internal layout of a jet space: monomial tables shared by jet_*.c. */
#ifndef IC_JET_INTERNAL_H
#define IC_JET_INTERNAL_H

#include "intercurve/jet.h"

struct ic_jet_space {
    int m;           /* number of variables */
    int K;           /* total degree */
    int n;           /* number of coefficients */
    int *deg_start;  /* [K + 2]: first index of each total degree */
    int *exps;       /* [n * m]: exponents of each monomial */
    double *fact;    /* [n]: alpha! */
    int *lookup;     /* [(K + 1)^m]: mixed-radix exponent code -> index */
    /* Products of homogeneous parts: for degrees j + k <= K, block (j, k)
     * holds, for every pair (p, q) of monomials of degrees j and k (row-major
     * over p, then q), the index of x^(alpha_p + alpha_q). */
    int *pair_idx;
    size_t *block_off; /* [(K + 1) * (K + 1)] */
    /* For |alpha| >= 1: the first variable v with alpha_v > 0 and the index
     * of x^(alpha - e_v), so that x^alpha = x_v x^(alpha - e_v) (jet_chain.c). */
    int *lower_var;
    int *lower;
};

/* out[deg j+k part] += f * (deg-j part of a) * (deg-k part of b). */
static inline void ic_jet_hacc(const ic_jet_space *sp, double *out, const double *a, int j,
                               const double *b, int k, double f)
{
    const int *idx = sp->pair_idx + sp->block_off[j * (sp->K + 1) + k];
    const int p0 = sp->deg_start[j], p1 = sp->deg_start[j + 1];
    const int q0 = sp->deg_start[k], q1 = sp->deg_start[k + 1];
    const int width = q1 - q0;
    for (int p = p0; p < p1; p++, idx += width) {
        const double ap = f * a[p];
        if (ap == 0.0)
            continue;
        for (int q = 0; q < width; q++)
            out[idx[q]] += ap * b[q0 + q];
    }
}

/* c = a b on the degrees <= D only (the higher parts of c are zeroed): the
 * series reversions need one more degree per step, not the whole product. */
static inline void ic_jet_mul_upto(double *c, const double *a, const double *b,
                                   const ic_jet_space *sp, int D)
{
    for (int i = 0; i < sp->n; i++)
        c[i] = 0.0;
    for (int j = 0; j <= D; j++)
        for (int k = 0; j + k <= D; k++)
            ic_jet_hacc(sp, c, a, j, b, k, 1.0);
}

/* Operations on the homogeneous part of degree d. */
static inline void ic_jet_part_zero(const ic_jet_space *sp, double *c, int d)
{
    for (int i = sp->deg_start[d]; i < sp->deg_start[d + 1]; i++)
        c[i] = 0.0;
}

static inline void ic_jet_part_scale(const ic_jet_space *sp, double *c, int d, double s)
{
    for (int i = sp->deg_start[d]; i < sp->deg_start[d + 1]; i++)
        c[i] *= s;
}

/* c[part d] += s * a[part d] */
static inline void ic_jet_part_axpy(const ic_jet_space *sp, double *c, int d, double s,
                                    const double *a)
{
    for (int i = sp->deg_start[d]; i < sp->deg_start[d + 1]; i++)
        c[i] += s * a[i];
}

#endif
