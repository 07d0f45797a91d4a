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
 * written with cross products, made once (ic_frame_solver).
 *
 * [R(alpha(s))]_k and [f(c(s))]_k come from each surface's Taylor polynomial
 * of order K at the point, composed with the curve one degree at a time
 * (jet/jet_chain.h): the jet's lower coefficients are final, so each order
 * adds its own coefficients only (per order, one convolution per power
 * product and one sum over the terms), instead of pushing the whole jet
 * through the surface again at every order. A primitive follows the curve
 * with its own one-variable series instead (ic_primitive_along), and makes
 * the next order's [.]_k as soon as a_k is solved (ic_primitive_along_advance,
 * which takes a_k in registers): the orders follow each other as closely
 * as the arithmetic allows, which for two quadrics is what bounds the
 * method's time (docs/performance.md, "Jets").
 */
#include "local_internal.h"
#include "common/vec3.h"
#include "jet/jet_chain.h"
#include "surface/surface_jets.h"

#include <stdlib.h>
#include <string.h>

typedef struct {
    double a[IC_LOCAL_MAX_ORDER + 1][3];              /* Taylor coefficients of c */
    double alpha[2][IC_LOCAL_MAX_ORDER + 1][2];       /* of the parameter curves */
} curve_jet;

/* One sheet along the curve: its surface's Taylor polynomial at the curve's
 * point (parametric: at the parameters), the surface's inputs along the
 * curve as jets of the curve's space (coefficients final below the current
 * order, zero from it on), and their power products. A formula is instead
 * evaluated on the inputs' jets at every order: its tape on one-variable
 * jets costs less than its Taylor polynomial in two or three variables. A
 * primitive follows the curve with its own one-variable series, one order
 * at a time (ic_primitive_along), without a Taylor polynomial at all. */
typedef struct {
    int direct; /* a formula: composed with the curve's jet at every order */
    int along;  /* a primitive: pa */
    ic_primitive_along pa;
    /* [R(alpha(s))]_k or [f(c(s))]_k at the current order k, the curve's
     * order-k coefficients still zero (a primitive's: made by its advance
     * at the end of the order before) */
    double q[3];
    double at[3]; /* the expansion point: c(0) or alpha(0) */
    const ic_jet_space *sp_p;
    int nout;
    double *taylor;                                /* nout jets of sp_p */
    double in[3][IC_LOCAL_MAX_ORDER + 1];          /* c(s) - c(0) or alpha(s) - alpha(0)
                                                      (a primitive's are pa's) */
    ic_jet_chain chain;
} sheet_jet;

/* The sheet's Taylor polynomial at `at` (heading: the parameter curve's
 * direction, for a NURBS on a knot line) into sj->taylor, and its chain
 * over the inputs' jets in `work`. */
static ic_status sheet_start(const ic_sheet *sh, sheet_jet *sj, const double *heading,
                             const ic_jet_space *sp, double *work, ic_error *err)
{
    const int n = ic_jet_space_len(sj->sp_p);
    ic_status st = ic_surface_taylor_toward(sh->s, sj->taylor, sj->at, heading, sj->sp_p, err);
    if (st != IC_OK)
        return st;
    const double *P[3], *ins[3] = {sj->in[0], sj->in[1], sj->in[2]};
    for (int c = 0; c < sj->nout; c++)
        P[c] = sj->taylor + (size_t)c * n;
    ic_jet_chain_init_upto(&sj->chain, sj->sp_p, P, sj->nout,
                           ic_surface_polynomial_degree(sh->s), ins, sp, work);
    return IC_OK;
}

/* [R(alpha(s))]_k or [f(c(s))]_k by the surface on the inputs' jets of
 * order k (their order-k coefficients still zero). */
static ic_status sheet_compose(ic_pair *pair, const ic_sheet *sh, const sheet_jet *sj, int k,
                               double Qk[3], ic_error *err)
{
    const ic_jet_space *sp = pair->curve[k];
    double in[3][IC_LOCAL_MAX_ORDER + 1], out[3][IC_LOCAL_MAX_ORDER + 1];
    const double *ins[3] = {in[0], in[1], in[2]};
    for (int v = 0; v < (sh->parametric ? 2 : 3); v++) {
        memcpy(in[v], sj->in[v], (size_t)k * sizeof in[v][0]);
        in[v][0] = sj->at[v];
        in[v][k] = 0.0;
    }
    ic_status st = ic_surface_compose(sh->s, &out[0][0], ins, sp, err);
    /* out holds consecutive jets of k + 1 coefficients */
    for (int c = 0; c < sj->nout && st == IC_OK; c++)
        Qk[c] = (&out[0][0])[c * (k + 1) + k];
    return st;
}

/* Right-hand side r_S for sheet S at order k, from sj->q (made here
 * unless the sheet is a primitive). */
static ic_status sheet_rhs(ic_pair *pair, const ic_sheet *sh, sheet_jet *sj, int k, double *r,
                           ic_error *err)
{
    if (sj->direct) {
        ic_status st = sheet_compose(pair, sh, sj, k, sj->q, err);
        if (st != IC_OK)
            return st;
    } else if (!sj->along) {
        const int n = ic_jet_space_len(sj->sp_p);
        double out[IC_LOCAL_MAX_ORDER + 1];
        ic_jet_chain_extend(&sj->chain, k);
        for (int c = 0; c < sj->nout; c++) {
            ic_jet_chain_part(&sj->chain, out, sj->taylor + (size_t)c * n, k);
            sj->q[c] = out[k];
        }
    }
    if (sh->parametric)
        *r = ic_dot3(sh->geo.normal, sj->q);
    else
        *r = -sj->q[0] / sh->geo.normal_length;
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

/* The inputs of sheet s along the curve gain their order-k coefficients;
 * a primitive's series, which hold their own, are completed at that order
 * and take the step of the next (its sj->q). */
static void sheet_advance(const ic_sheet *sh, sheet_jet *sj, const curve_jet *cj, int s, int k,
                          int order)
{
    const double *ak = sh->parametric ? cj->alpha[s][k] : cj->a[k];
    const int nin = sh->parametric ? 2 : 3;
    if (!sj->along) {
        for (int v = 0; v < nin; v++)
            sj->in[v][k] = ak[v];
    } else if (k < order) { /* after the last order the series are not read */
        ic_primitive_along_advance(&sj->pa, k, ak[0], ak[1], nin == 3 ? ak[2] : 0.0, sj->q);
    }
}

/* Both sheets' Taylor polynomials of order K at the curve's point, then
 * their chains over the inputs, known to order 1, in *mem (the caller frees
 * it): the chains only go up to the polynomials' degrees. */
static ic_status sheets_open(ic_pair *pair, const ic_sheet sh[2], sheet_jet sj[2],
                             const curve_jet *cj, int order, double **mem, ic_error *err)
{
    const ic_jet_space *sp = pair->curve[order];
    size_t len = 0;
    *mem = NULL;
    for (int s = 0; s < 2; s++) {
        sj[s].taylor = NULL;
        sj[s].nout = sh[s].parametric ? 3 : 1;
        memcpy(sj[s].at, sh[s].parametric ? cj->alpha[s][0] : cj->a[0], sizeof sj[s].at);
        sj[s].direct = ic_surface_is_formula(sh[s].s);
        sj[s].along = ic_primitive_along_serves(sh[s].s);
        /* not the whole struct: a primitive's series hold their own inputs */
        if (sj[s].along)
            ic_primitive_along_start(&sj[s].pa, sh[s].s, sj[s].at);
        else
            memset(sj[s].in, 0, sizeof sj[s].in);
        sheet_advance(&sh[s], &sj[s], cj, s, 1, order);
        if (sj[s].direct || sj[s].along)
            continue;
        sj[s].sp_p = ic_surface_space(sh[s].s, order, err);
        if (!sj[s].sp_p)
            return err ? err->code : IC_ERR_NOMEM;
        len += (size_t)sj[s].nout * (size_t)ic_jet_space_len(sj[s].sp_p) +
               ic_jet_chain_len(sj[s].sp_p, order, sp);
    }
    if (!len)
        return IC_OK;
    /* one block sized for the densest chains; a chain uses only what its
     * polynomials need */
    double *block = malloc(len * sizeof *block);
    if (!block)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory in the jet method");
    *mem = block;
    for (int s = 0; s < 2; s++) {
        if (sj[s].direct || sj[s].along)
            continue;
        sj[s].taylor = block;
        block += (size_t)sj[s].nout * (size_t)ic_jet_space_len(sj[s].sp_p);
        const double *heading = sh[s].parametric ? cj->alpha[s][1] : NULL;
        ic_status st = sheet_start(&sh[s], &sj[s], heading, sp, block, err);
        if (st != IC_OK)
            return st;
        block += ic_jet_chain_len(sj[s].sp_p, order, sp);
    }
    return IC_OK;
}

/* t . a_k from |c'| = 1: -1/(2k) sum_{i=1..k-2} (i+1)(k-i) a_{i+1} . a_{k-i}. */
static double unit_speed_rhs(const double a[][3], int k)
{
    double r = 0.0;
    for (int i = 1; i <= k - 2; i++)
        r -= (i + 1) * (k - i) * ic_dot3(a[i + 1], a[k - i]);
    return r / (2.0 * k);
}

/* c^(k) = k! a_k, and the parameter curves' derivatives likewise. */
static void branch_store(ic_branch *br, const ic_sheet sh[2], const curve_jet *cj, int order)
{
    double fact = 1.0;
    br->order = order;
    br->param_order = order;
    for (int k = 1; k <= order; k++) {
        fact *= k;
        ic_scale3(br->derivs[k - 1], cj->a[k], fact);
        for (int s = 0; s < 2; s++)
            for (int v = 0; v < 2; v++)
                br->param_derivs[s][k - 1][v] = sh[s].parametric ? fact * cj->alpha[s][k][v] : 0.0;
    }
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
    ic_frame_solver fs;
    ic_frame_solver_init(&fs, t, NA, NB);
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
    sheet_jet sj[2];
    double *mem = NULL;
    ic_status st = order >= 2 ? sheets_open(pair, sh, sj, &cj, order, &mem, err) : IC_OK;
    for (int k = 2; k <= order && st == IC_OK; k++) {
        double r[3] = {unit_speed_rhs(cj.a, k), 0, 0};
        for (int s = 0; s < 2 && st == IC_OK; s++)
            st = sheet_rhs(pair, &sh[s], &sj[s], k, &r[1 + s], err);
        if (st != IC_OK)
            break;
        ic_frame_solve(&fs, cj.a[k], r);
        for (int s = 0; s < 2; s++) {
            if (sh[s].parametric) {
                double w[3];
                ic_axpy3(w, cj.a[k], -1.0, sj[s].q);
                tangent_to_params(&sh[s], w, cj.alpha[s][k]);
            }
            sheet_advance(&sh[s], &sj[s], &cj, s, k, order);
        }
    }
    free(mem);
    if (st == IC_OK)
        branch_store(br, sh, &cj, order);
    return st;
}
