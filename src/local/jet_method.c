/*
 * The jet method (docs/local.md; the algorithm of Patrikalakis and Maekawa
 * (2002), section 6.3.4, eqs. (6.47)-(6.55)): arc-length derivatives of any
 * order.
 *
 * With c(s) = sum_k a_k s^k (a_k = c^(k)/k!), each order k >= 2 gives three
 * linear equations for a_k:
 *   t . a_k   = -1/(2k) sum_{i=1..k-2} (i+1)(k-i) a_{i+1} . a_{k-i}   (|c'| = 1)
 *   N_S . a_k = r_S on each sheet S, where, pushing the known lower-order
 *     jet (a_k = 0) through the surface,
 *     implicit f:   r = -[f(c(s))]_k / |grad f|,
 *     parametric R: r = N . [R(alpha(s))]_k, and afterwards the parameter
 *                   curve's alpha_k solves R_u alpha_k^u + R_v alpha_k^v
 *                   = a_k - [R(alpha(s))]_k.
 * The matrix M = [t; N_A; N_B] is the same at every order; its inverse is
 * written with cross products (ic_solve_frame).
 */
#include "local_internal.h"
#include "common/vec3.h"

#include <string.h>

typedef struct {
    double a[IC_LOCAL_MAX_ORDER + 1][3];              /* Taylor coefficients of c */
    double alpha[2][IC_LOCAL_MAX_ORDER + 1][2];       /* of the parameter curves */
} curve_jet;

/* Right-hand side r_S for sheet S at order k, and [R(alpha)]_k (parametric). */
static ic_status sheet_rhs(ic_pair *pair, const ic_sheet *sh, int which, const curve_jet *cj,
                           int k, double *r, double Qk[3], ic_error *err)
{
    const ic_jet_space *sp = pair->curve[k];
    double in[3][IC_LOCAL_MAX_ORDER + 1], out[3][IC_LOCAL_MAX_ORDER + 1];
    const double *ins[3] = {in[0], in[1], in[2]};
    const int nin = sh->parametric ? 2 : 3;
    for (int v = 0; v < nin; v++) {
        for (int i = 0; i < k; i++)
            in[v][i] = sh->parametric ? cj->alpha[which][i][v] : cj->a[i][v];
        in[v][k] = 0.0;
    }
    ic_status st = ic_surface_compose(sh->s, &out[0][0], ins, sp, err);
    if (st != IC_OK)
        return st;
    /* out holds consecutive jets of k+1 coefficients */
    const double *flat = &out[0][0];
    if (sh->parametric) {
        for (int c = 0; c < 3; c++)
            Qk[c] = flat[c * (k + 1) + k];
        *r = ic_dot3(sh->geo.normal, Qk);
    } else {
        *r = -flat[k] / sh->geo.normal_length;
    }
    return IC_OK;
}

/* alpha_k from R_u x + R_v y = w (w tangent), by the first fundamental form. */
static void tangent_to_params(const ic_sheet *sh, const double *w, double *xy)
{
    const double E = sh->geo.first[0], F = sh->geo.first[1], G = sh->geo.first[2];
    const double p = ic_dot3(w, sh->geo.basis[0]), q = ic_dot3(w, sh->geo.basis[1]);
    const double det = E * G - F * F;
    xy[0] = (G * p - F * q) / det;
    xy[1] = (E * q - F * p) / det;
}

ic_status ic_jet_method(ic_pair *pair, ic_branch *br, const ic_sheet sh[2], int order,
                        ic_error *err)
{
    curve_jet cj;
    memset(&cj, 0, sizeof cj);
    const double *NA = sh[0].geo.normal, *NB = sh[1].geo.normal;
    double t[3];
    ic_cross3(t, NA, NB);
    ic_normalize3(t);
    /* order 0 and 1 */
    const ic_sheet *first = sh[0].parametric ? &sh[0] : &sh[1];
    for (int c = 0; c < 3; c++)
        cj.a[0][c] = first->parametric ? first->geo.point[c] : sh[0].at[c];
    memcpy(cj.a[1], t, sizeof t);
    for (int s = 0; s < 2; s++)
        if (sh[s].parametric) {
            memcpy(cj.alpha[s][0], sh[s].at, 2 * sizeof(double));
            tangent_to_params(&sh[s], t, cj.alpha[s][1]);
        }
    for (int k = 2; k <= order; k++) {
        double r[3] = {0, 0, 0}, Q[2][3];
        for (int i = 1; i <= k - 2; i++)
            r[0] -= (i + 1) * (k - i) * ic_dot3(cj.a[i + 1], cj.a[k - i]);
        r[0] /= 2.0 * k;
        for (int s = 0; s < 2; s++) {
            ic_status st = sheet_rhs(pair, &sh[s], s, &cj, k, &r[1 + s], Q[s], err);
            if (st != IC_OK)
                return st;
        }
        ic_solve_frame(cj.a[k], t, NA, NB, r);
        for (int s = 0; s < 2; s++)
            if (sh[s].parametric) {
                double w[3];
                ic_axpy3(w, cj.a[k], -1.0, Q[s]);
                tangent_to_params(&sh[s], w, cj.alpha[s][k]);
            }
    }
    /* c^(k) = k! a_k */
    double fact = 1.0;
    br->order = order;
    br->param_order = order;
    for (int k = 1; k <= order; k++) {
        fact *= k;
        ic_scale3(br->derivs[k - 1], cj.a[k], fact);
        for (int s = 0; s < 2; s++)
            for (int v = 0; v < 2; v++)
                br->param_derivs[s][k - 1][v] = sh[s].parametric ? fact * cj.alpha[s][k][v] : 0.0;
    }
    return IC_OK;
}
