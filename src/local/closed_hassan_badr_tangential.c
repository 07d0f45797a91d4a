/*
 * Hassan and Badr (2016), section 4 (docs/references.md): tangential
 * intersection of two parametric surfaces P(v1, v2), Q(w1, w2) (or the
 * self-intersection of R), N_1 = delta N_2 (4.1). Equation numbers are the
 * paper's; the corrections are docs/ERRATA.md's items 4-6 and its section on
 * these formulas:
 *  - (4.7)-(4.10): with a_ij as in (4.8), the directions v2' = lambda v1' solve
 *    a22 lambda^2 + 2 a12 lambda + a11 = 0 (the printed form swaps a11, a22);
 *  - (4.8): the middle term of a12 is -(A11 A22 + A12 A21) L^2_12;
 *  - (4.22): no factor 3 on v2' L^1_22 and w2' L^2_22;
 *  - (4.29): the Q-side terms mirror the P side,
 *    -6 (2 w1' w2' w1'' + w1'^2 w2'') <Q112, N2> - 6 (w1'' w2'^2 + 2 w1' w2' w2'') <Q122, N2>.
 * Each unknown pair is solved from two scalar equations: (4.20) or (4.26)
 * give w'' (w''') in terms of v'' (v'''), then (4.22) and (4.24) (resp.
 * (4.28) and <alpha', alpha'''> = -kappa^2 (4.30)) are two equations for v''
 * (v''').
 */
#include "tangential.h"
#include "common/vec3.h"

#include <math.h>
#include <string.h>

/* sum_ij P_ij a_i b_j */
static void second(double *out, const ic_param_data *p, const double *a, const double *b)
{
    memset(out, 0, 3 * sizeof *out);
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++)
            ic_axpy3(out, out, a[i] * b[j], p->d2[i][j]);
}

/* sum_ijk P_ijk a_i a_j b_k (symmetric: P_111, P_112, P_122, P_222) */
static void third(double *out, const ic_param_data *p, const double *a, const double *b)
{
    const double x = a[0], y = a[1];
    memset(out, 0, 3 * sizeof *out);
    ic_axpy3(out, out, x * x * b[0], p->d3[0]);
    ic_axpy3(out, out, 2 * x * y * b[0] + x * x * b[1], p->d3[1]);
    ic_axpy3(out, out, y * y * b[0] + 2 * x * y * b[1], p->d3[2]);
    ic_axpy3(out, out, y * y * b[1], p->d3[3]);
}

/* sum P_ijkl a_i a_j a_k a_l */
static void fourth(double *out, const ic_param_data *p, const double *a)
{
    static const double binom[5] = {1, 4, 6, 4, 1};
    memset(out, 0, 3 * sizeof *out);
    for (int k = 0; k < 5; k++)
        ic_axpy3(out, out, binom[k] * pow(a[0], 4 - k) * pow(a[1], k), p->d4[k]);
}

static double quad(const double L[2][2], const double *a, const double *b)
{
    return L[0][0] * a[0] * b[0] + L[0][1] * (a[0] * b[1] + a[1] * b[0]) + L[1][1] * a[1] * b[1];
}

/* v'' or v''': from the two scalar equations r1 . x = s1, r2 . x = s2 */
static int solve2(double *x, const double *r1, double s1, const double *r2, double s2)
{
    const double det = r1[0] * r2[1] - r1[1] * r2[0];
    if (det == 0.0 || !isfinite(det))
        return -1;
    x[0] = (s1 * r2[1] - s2 * r1[1]) / det;
    x[1] = (r1[0] * s2 - r2[0] * s1) / det;
    return 0;
}

/* One branch along the direction v' (unit in the first form). */
static int branch(ic_branch *br, const ic_param_data *P, const ic_param_data *Q, const double *N2,
                  double delta, const double C[2][2], double B12, const double *v1)
{
    /* (4.5) w' = C v' / B12, C = [[A12, A22], [-A11, -A21]] */
    const double w1[2] = {(C[0][0] * v1[0] + C[0][1] * v1[1]) / B12,
                          (C[1][0] * v1[0] + C[1][1] * v1[1]) / B12};
    double t[3];
    ic_scale3(t, P->d1[0], v1[0]);
    ic_axpy3(t, t, v1[1], P->d1[1]); /* (4.13) */
    double QxQ[3];
    ic_cross3(QxQ, Q->d1[0], Q->d1[1]);
    const double area = ic_norm3(QxQ);
    /* (4.20): w'' = W v'' + (c12, c11)/|Q1 x Q2| */
    const double W[2][2] = {{ic_det3(P->d1[0], Q->d1[1], N2) / area,
                             ic_det3(P->d1[1], Q->d1[1], N2) / area},
                            {ic_det3(Q->d1[0], P->d1[0], N2) / area,
                             ic_det3(Q->d1[0], P->d1[1], N2) / area}};
    double SP[3], SQ[3], D[3];
    second(SP, P, v1, v1);
    second(SQ, Q, w1, w1);
    ic_axpy3(D, SP, -1.0, SQ);
    const double w0[2] = {ic_det3(D, Q->d1[1], N2) / area, ic_det3(Q->d1[0], D, N2) / area};
    /* (4.22) corrected: delta L^1(v', v'') = L^2(w', w'') + c13/3 */
    double TP[3], TQ[3];
    third(TP, P, v1, v1);
    third(TQ, Q, w1, w1);
    const double c13 = ic_dot3(TQ, N2) - ic_dot3(TP, N2);
    const double alpha[2] = {delta * (P->L[0][0] * v1[0] + P->L[0][1] * v1[1]),
                             delta * (P->L[0][1] * v1[0] + P->L[1][1] * v1[1])};
    const double beta[2] = {Q->L[0][0] * w1[0] + Q->L[0][1] * w1[1],
                            Q->L[0][1] * w1[0] + Q->L[1][1] * w1[1]};
    const double r1[2] = {alpha[0] - (W[0][0] * beta[0] + W[1][0] * beta[1]),
                          alpha[1] - (W[0][1] * beta[0] + W[1][1] * beta[1])};
    const double s1 = beta[0] * w0[0] + beta[1] * w0[1] + c13 / 3;
    /* (4.24): (g v') . v'' = -t . sum P_ij v_i' v_j' */
    const double gv[2] = {P->g[0][0] * v1[0] + P->g[0][1] * v1[1],
                          P->g[0][1] * v1[0] + P->g[1][1] * v1[1]};
    double v2[2];
    if (solve2(v2, r1, s1, gv, -ic_dot3(t, SP)) != 0)
        return -1;
    const double w2[2] = {W[0][0] * v2[0] + W[0][1] * v2[1] + w0[0],
                          W[1][0] * v2[0] + W[1][1] * v2[1] + w0[1]};
    double c2[3];
    ic_axpy3(c2, SP, v2[0], P->d1[0]);
    ic_axpy3(c2, c2, v2[1], P->d1[1]); /* (2.13) */
    /* third order: alpha''' = S3 + v1''' P1 + v2''' P2 (4.25) */
    double S3P[3], S3Q[3], tmp[3];
    third(S3P, P, v1, v1);
    second(tmp, P, v1, v2);
    ic_axpy3(S3P, S3P, 3.0, tmp);
    third(S3Q, Q, w1, w1);
    second(tmp, Q, w1, w2);
    ic_axpy3(S3Q, S3Q, 3.0, tmp);
    ic_axpy3(D, S3P, -1.0, S3Q);
    /* (4.26): w''' = W v''' + (c15, c14)/|Q1 x Q2| */
    const double w0b[2] = {ic_det3(D, Q->d1[1], N2) / area, ic_det3(Q->d1[0], D, N2) / area};
    /* (4.28), (4.29) corrected: L^2(w', w''') = delta L^1(v', v''') + c16/4 */
    double FP[3], FQ[3], GP[3], GQ[3];
    fourth(FP, P, v1);
    fourth(FQ, Q, w1);
    third(GP, P, v1, v2);
    third(GQ, Q, w1, w2);
    const double c16 = ic_dot3(FP, N2) + 6 * ic_dot3(GP, N2) + 3 * delta * quad(P->L, v2, v2) -
                       ic_dot3(FQ, N2) - 6 * ic_dot3(GQ, N2) - 3 * quad(Q->L, w2, w2);
    const double r3[2] = {W[0][0] * beta[0] + W[1][0] * beta[1] - alpha[0],
                          W[0][1] * beta[0] + W[1][1] * beta[1] - alpha[1]};
    const double s3 = c16 / 4 - (beta[0] * w0b[0] + beta[1] * w0b[1]);
    /* (4.30): <alpha', alpha'''> = -kappa^2 */
    double v3[2];
    if (solve2(v3, r3, s3, gv, -ic_dot3(c2, c2) - ic_dot3(t, S3P)) != 0)
        return -1;
    double c3[3];
    ic_axpy3(c3, S3P, v3[0], P->d1[0]);
    ic_axpy3(c3, c3, v3[1], P->d1[1]);
    memset(br, 0, sizeof *br);
    br->order = 3;
    br->regular = 1;
    memcpy(br->derivs[0], t, sizeof t);
    memcpy(br->derivs[1], c2, sizeof c2);
    memcpy(br->derivs[2], c3, sizeof c3);
    memcpy(br->param_derivs[0][0], v1, 2 * sizeof(double));
    memcpy(br->param_derivs[0][1], v2, 2 * sizeof(double));
    memcpy(br->param_derivs[1][0], w1, 2 * sizeof(double));
    memcpy(br->param_derivs[1][1], w2, 2 * sizeof(double));
    br->param_order = 2;
    /* the orientation of the other tangential methods */
    for (int k = 0; k < 3; k++)
        if (fabs(t[k]) > 1e-9) {
            if (t[k] < 0) {
                ic_scale3(br->derivs[0], br->derivs[0], -1.0);
                ic_scale3(br->derivs[2], br->derivs[2], -1.0);
                for (int s = 0; s < 2; s++)
                    for (int v = 0; v < 2; v++)
                        br->param_derivs[s][0][v] = -br->param_derivs[s][0][v];
            }
            break;
        }
    return 0;
}

void ic_closed_hassan_badr_coefficients(ic_local_result *res, const ic_sheet sh[2])
{
    const ic_point_type type = res->type;
    ic_local_result tmp = *res;
    tmp.type = IC_POINT_TANGENTIAL; /* coefficients only: stop before the branches */
    (void)ic_closed_hassan_badr_tangential(&tmp, sh, NULL, NULL);
    res->npaper = tmp.npaper;
    memcpy(res->paper_names, tmp.paper_names, sizeof tmp.paper_names);
    memcpy(res->paper_values, tmp.paper_values, sizeof tmp.paper_values);
    res->type = type;
}

ic_status ic_closed_hassan_badr_tangential(ic_local_result *res, const ic_sheet sh[2],
                                           const ic_local_options *opt, ic_error *err)
{
    if (!sh[0].parametric || !sh[1].parametric)
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            "the closed form at tangential points covers two parametric "
                            "surfaces (Hassan and Badr (2016), section 4); use "
                            "height-difference");
    ic_param_data P, Q;
    ic_param_data_load(&P, &sh[0]);
    ic_param_data_load(&Q, &sh[1]);
    const double *N2 = sh[1].geo.normal;
    const double delta = ic_dot3(sh[0].geo.normal, N2) < 0 ? -1.0 : 1.0; /* (4.1) */
    /* rows {l, m}: the largest |B12| (4.6) */
    int l = 0, m = 1;
    double best = -1.0;
    for (int k = 0; k < 3; k++) {
        const int ll = (k + 1) % 3, mm = (k + 2) % 3;
        const double b = fabs(Q.d1[0][ll] * Q.d1[1][mm] - Q.d1[0][mm] * Q.d1[1][ll]);
        if (b > best)
            best = b, l = ll, m = mm;
    }
    double A[2][2];
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++)
            A[i][j] = P.d1[i][l] * Q.d1[j][m] - P.d1[i][m] * Q.d1[j][l];
    const double B12 = Q.d1[0][l] * Q.d1[1][m] - Q.d1[0][m] * Q.d1[1][l];
    const double C[2][2] = {{A[0][1], A[1][1]}, {-A[0][0], -A[1][0]}};
    /* (4.8), a12 corrected */
    const double (*L2)[2] = Q.L, (*L1)[2] = P.L;
    const double b2 = B12 * B12;
    const double a11 = A[0][1] * A[0][1] * L2[0][0] - 2 * A[0][1] * A[0][0] * L2[0][1] +
                       A[0][0] * A[0][0] * L2[1][1] - delta * b2 * L1[0][0];
    const double a12 = A[0][1] * A[1][1] * L2[0][0] - (A[0][0] * A[1][1] + A[0][1] * A[1][0]) * L2[0][1] +
                       A[0][0] * A[1][0] * L2[1][1] - delta * b2 * L1[0][1];
    const double a22 = A[1][1] * A[1][1] * L2[0][0] - 2 * A[1][0] * A[1][1] * L2[0][1] +
                       A[1][0] * A[1][0] * L2[1][1] - delta * b2 * L1[1][1];
    const double Delta = a12 * a12 - a11 * a22;
    res->npaper = 4;
    res->paper_names[0] = "a11", res->paper_values[0] = a11;
    res->paper_names[1] = "a12", res->paper_values[1] = a12;
    res->paper_names[2] = "a22", res->paper_values[2] = a22;
    res->paper_names[3] = "Delta", res->paper_values[3] = Delta;
    const double scale = fmax(fmax(fabs(a11), fabs(a22)), fabs(a12));
    if (scale == 0.0 || !(res->type == IC_POINT_BRANCH || res->type == IC_POINT_TANGENTIAL_CURVE))
        return ic_error_set(err, IC_ERR_UNABLE, 0,
                            "the closed form (Hassan and Badr (2016), section 4) gives the "
                            "branches of branch points and tangential curves; this point is %s",
                            ic_point_type_name(res->type));
    /* directions: a11 v1'^2 + 2 a12 v1' v2' + a22 v2'^2 = 0 (Lemmas 1, 2) */
    const int nroots = res->type == IC_POINT_BRANCH ? 2 : 1;
    const double root = nroots == 2 ? sqrt(fmax(Delta, 0.0)) : 0.0;
    res->nbranches = 0;
    for (int k = 0; k < nroots; k++) {
        const double sgn = k ? -1.0 : 1.0;
        double v1[2];
        if (fabs(a22) >= fabs(a11))
            v1[0] = a22, v1[1] = -a12 + sgn * root; /* lambda = (-a12 +- sqrt)/a22 */
        else
            v1[0] = -a12 + sgn * root, v1[1] = a11; /* mu = v1'/v2' = (-a12 +- sqrt)/a11 */
        const double norm = sqrt(v1[0] * v1[0] * P.g[0][0] + 2 * v1[0] * v1[1] * P.g[0][1] +
                                 v1[1] * v1[1] * P.g[1][1]); /* (4.11) */
        v1[0] /= norm, v1[1] /= norm;
        if (branch(&res->branches[res->nbranches], &P, &Q, N2, delta, C, B12, v1) != 0)
            return ic_error_set(err, IC_ERR_UNABLE, 0,
                                "Hassan and Badr (2016), eqs. (4.20)-(4.24): the system for v'' "
                                "is singular");
        res->nbranches++;
    }
    (void)opt;
    return IC_OK;
}
