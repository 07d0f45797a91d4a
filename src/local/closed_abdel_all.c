/*
 * Abdel-All et al. (2012), section 3 (docs/references.md): transversal
 * intersection of two implicit surfaces f = 0 and h = 0, the curve
 * parametrised by x1 as beta(x1) = (x1, x2(x1), x3(x1)). Equation numbers
 * are the paper's.
 *
 * The paper assumes d(f, h)/d(x2, x3) = A23 != 0. Here the axes are
 * relabelled cyclically (which keeps cross products, hence orientations) so
 * that A23 is the largest of |A23|, |A13|, |A12|; results are mapped back.
 */
#include "local_internal.h"
#include "common/vec3.h"

#include <math.h>
#include <string.h>

typedef struct {
    double g[3];       /* f_i */
    double H[3][3];    /* f_ij */
    double T[3][3][3]; /* f_ijk */
} implicit_data;

/* Derivatives of a sheet in the relabelled axes: new axis i is old axis
 * (i + shift) mod 3. */
static void load(implicit_data *d, const ic_sheet *sh, int shift)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            for (int k = 0; k < 3; k++) {
                int e[3] = {0, 0, 0};
                e[(i + shift) % 3]++, e[(j + shift) % 3]++, e[(k + shift) % 3]++;
                d->T[i][j][k] = ic_sheet_fpartial(sh, e[0], e[1], e[2]);
            }
    for (int i = 0; i < 3; i++) {
        int e1[3] = {0, 0, 0};
        e1[(i + shift) % 3] = 1;
        d->g[i] = ic_sheet_fpartial(sh, e1[0], e1[1], e1[2]);
        for (int j = 0; j < 3; j++) {
            int e2[3] = {0, 0, 0};
            e2[(i + shift) % 3]++, e2[(j + shift) % 3]++;
            d->H[i][j] = ic_sheet_fpartial(sh, e2[0], e2[1], e2[2]);
        }
    }
}

/* (3.17) B_ijk = |f_i h_i; f_jk h_jk| (0-based indices) */
static double B(const implicit_data *f, const implicit_data *h, int i, int j, int k)
{
    return f->g[i] * h->H[j][k] - h->g[i] * f->H[j][k];
}

/* (3.21) c_11, c_12, c_13 of one surface (c_21.. are the same for h). */
static void c_coefficients(const implicit_data *f, double A12, double A13, double A23,
                           double *c1, double *c2, double *c3)
{
    const double a2 = A23 * A23, a3 = a2 * A23;
    *c1 = 3 * (a3 * f->H[0][1] - A13 * a2 * f->H[1][1] + A12 * a2 * f->H[1][2]);
    *c2 = 3 * (a3 * f->H[0][2] - A13 * a2 * f->H[1][2] + A12 * a2 * f->H[2][2]);
    const double (*T)[3][3] = f->T;
    *c3 = a3 * T[0][0][0] - 6 * A12 * A13 * A23 * T[0][1][2] - A13 * A13 * A13 * T[1][1][1] +
          A12 * A12 * A12 * T[2][2][2] +
          3 * (A12 * a2 * T[0][0][2] - A13 * a2 * T[0][0][1] + A13 * A13 * A23 * T[0][1][1] +
               A12 * A12 * A23 * T[0][2][2] - A13 * A12 * A12 * T[1][2][2] +
               A12 * A13 * A13 * T[1][1][2]);
}

ic_status ic_closed_abdel_all(ic_branch *br, const ic_sheet sh[2], ic_paper_values *paper,
                              ic_error *err)
{
    if (sh[0].parametric || sh[1].parametric)
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            "Abdel-All et al. (2012), section 3, needs two implicit sheets");
    /* choose the relabelling with the largest A23 */
    int shift = 0;
    double best = -1.0;
    for (int r = 0; r < 3; r++) {
        const double *fg = sh[0].geo.normal, *hg = sh[1].geo.normal;
        const int a = (1 + r) % 3, b = (2 + r) % 3;
        const double m = fabs(fg[a] * hg[b] - fg[b] * hg[a]);
        if (m > best)
            best = m, shift = r;
    }
    implicit_data f, h;
    load(&f, &sh[0], shift);
    load(&h, &sh[1], shift);
    /* (3.10) A_ij = |f_i f_j; h_i h_j| */
    const double A12 = f.g[0] * h.g[1] - f.g[1] * h.g[0];
    const double A13 = f.g[0] * h.g[2] - f.g[2] * h.g[0];
    const double A23 = f.g[1] * h.g[2] - f.g[2] * h.g[1];
    if (A23 == 0.0)
        return ic_error_set(err, IC_ERR_UNABLE, 0,
                            "Abdel-All et al. (2012), section 3: the normals are parallel");
    const double S = A12 * A12 + A13 * A13 + A23 * A23;
    /* (3.9) beta' = (A23, -A13, A12)/A23 */
    const double b1[3] = {1.0, -A13 / A23, A12 / A23};
    /* (3.16) */
    const double a23_3 = A23 * A23 * A23;
    const double x2dd = (B(&f, &h, 2, 0, 0) * A23 * A23 + B(&f, &h, 2, 1, 1) * A13 * A13 +
                         B(&f, &h, 2, 2, 2) * A12 * A12 +
                         2 * (B(&f, &h, 2, 0, 2) * A12 * A23 - B(&f, &h, 2, 0, 1) * A13 * A23 -
                              B(&f, &h, 2, 1, 2) * A13 * A12)) /
                        a23_3;
    const double x3dd = -(B(&f, &h, 1, 0, 0) * A23 * A23 + B(&f, &h, 1, 1, 1) * A13 * A13 +
                          B(&f, &h, 1, 2, 2) * A12 * A12 +
                          2 * (B(&f, &h, 1, 0, 2) * A12 * A23 - B(&f, &h, 1, 0, 1) * A13 * A23 -
                               B(&f, &h, 1, 1, 2) * A13 * A12)) /
                        a23_3;
    /* (3.18) kappa n */
    const double pre = (A23 / S) * (A23 / S);
    double c2[3] = {pre * (A23 * A13 * x2dd - A23 * A12 * x3dd),
                    pre * ((A12 * A12 + A23 * A23) * x2dd + A13 * A12 * x3dd),
                    pre * ((A13 * A13 + A23 * A23) * x3dd + A13 * A12 * x2dd)};
    /* (3.19) */
    const double quad = (A12 * A12 + A23 * A23) * x2dd * x2dd +
                        (A13 * A13 + A23 * A23) * x3dd * x3dd + 2 * A12 * A13 * x2dd * x3dd;
    const double kappa = A23 * A23 * sqrt(quad / (S * S * S));
    /* (3.21), (3.22) */
    double c11, c12, c13, c21, c22, c23;
    c_coefficients(&f, A12, A13, A23, &c11, &c12, &c13);
    c_coefficients(&h, A12, A13, A23, &c21, &c22, &c23);
    const double a23_4 = a23_3 * A23;
    const double x2ddd = ((f.g[2] * c21 - h.g[2] * c11) * x2dd +
                          (f.g[2] * c22 - h.g[2] * c12) * x3dd + f.g[2] * c23 - h.g[2] * c13) /
                         a23_4;
    const double x3ddd = -((f.g[1] * c21 - h.g[1] * c11) * x2dd +
                           (f.g[1] * c22 - h.g[1] * c12) * x3dd + f.g[1] * c23 - h.g[1] * c13) /
                         a23_4;
    /* (3.23) */
    const double tau = A23 * A23 * (x2dd * x3ddd - x3dd * x2ddd) / quad;
    /* c', c'', c''' from beta', beta'', beta''' by the chain rule (not in the
     * paper, which stops at tau); (3.18) is the same c'' written out */
    const double b2[3] = {0.0, x2dd, x3dd}, b3[3] = {0.0, x2ddd, x3ddd};
    double cc[3][3];
    ic_arc_length_derivs(cc, b1, b2, b3);
    const double *c1 = cc[0], *c3 = cc[2];
    /* back to the original axes: new axis i is old axis (i + shift) mod 3 */
    memset(br, 0, sizeof *br);
    br->order = 3;
    for (int i = 0; i < 3; i++) {
        br->derivs[0][(i + shift) % 3] = c1[i];
        br->derivs[1][(i + shift) % 3] = c2[i];
        br->derivs[2][(i + shift) % 3] = c3[i];
    }
    if (paper) {
        paper->kappa = kappa;
        paper->tau = tau;
    }
    ic_orient_closed(br, sh[0].geo.normal, sh[1].geo.normal);
    return IC_OK;
}
