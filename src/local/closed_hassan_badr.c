/*
 * Hassan and Badr (2016), section 3 (docs/references.md): transversal
 * intersection of two parametric surfaces P(v1, v2) and Q(w1, w2), and the
 * self-intersection of R (P = R(v), Q = R(w)). Equation numbers are the
 * paper's.
 *
 * The paper takes the rows {l, m} of (3.2) where Q's 2x2 minor B12 is not
 * zero "without loss of generality"; here {l, m} is the pair with the largest
 * |B12| and q the remaining row.
 */
#include "local_internal.h"
#include "common/vec3.h"

#include <math.h>
#include <string.h>

/* (3.18): the normal curvature v'^T L v'. */
static double normal_curvature(const ic_param_data *p, const double *v1)
{
    return v1[0] * v1[0] * p->L[0][0] + 2 * v1[0] * v1[1] * p->L[0][1] +
           v1[1] * v1[1] * p->L[1][1];
}

/* (3.22)/(3.23): v'' from alpha'' = sum v_i' v_j' P_ij + v_1'' P_1 + v_2'' P_2 (3.20),
 * crossing with P_2 (P_1) and projecting on N. */
static void second_param_derivs(const ic_param_data *p, const double *v1, const double *c2,
                                double *v2)
{
    double rest[3];
    memcpy(rest, c2, sizeof rest);
    ic_axpy3(rest, rest, -v1[0] * v1[0], p->d2[0][0]);
    ic_axpy3(rest, rest, -2 * v1[0] * v1[1], p->d2[0][1]);
    ic_axpy3(rest, rest, -v1[1] * v1[1], p->d2[1][1]);
    v2[0] = ic_det3(rest, p->d1[1], p->N) / p->area; /* |alpha'' - ..., P_2, N| */
    v2[1] = ic_det3(p->d1[0], rest, p->N) / p->area; /* |P_1, alpha'' - ..., N| */
}

/* (3.26): psi = alpha''' . N. */
static double psi(const ic_param_data *p, const double *v1, const double *v2)
{
    const double a = v1[0], b = v1[1];
    const double third = a * a * a * ic_dot3(p->d3[0], p->N) +
                         3 * a * a * b * ic_dot3(p->d3[1], p->N) +
                         3 * a * b * b * ic_dot3(p->d3[2], p->N) +
                         b * b * b * ic_dot3(p->d3[3], p->N);
    return third + 3 * a * v2[0] * p->L[0][0] + 3 * (v2[0] * b + a * v2[1]) * p->L[0][1] +
           3 * b * v2[1] * p->L[1][1];
}

ic_status ic_closed_hassan_badr(ic_branch *br, const ic_sheet sh[2], ic_paper_values *paper,
                                ic_error *err)
{
    if (!sh[0].parametric || !sh[1].parametric)
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            "Hassan and Badr (2016), section 3, needs two parametric sheets");
    ic_param_data P, Q;
    ic_param_data_load(&P, &sh[0]);
    ic_param_data_load(&Q, &sh[1]);
    /* rows {l, m}: the largest |B12| = |Q_1^l Q_2^m - Q_1^m Q_2^l| (3.5) */
    int l = 0, m = 1, q = 2;
    double best = -1.0;
    for (int k = 0; k < 3; k++) {
        const int ll = (k + 1) % 3, mm = (k + 2) % 3;
        const double b = fabs(Q.d1[0][ll] * Q.d1[1][mm] - Q.d1[0][mm] * Q.d1[1][ll]);
        if (b > best)
            best = b, l = ll, m = mm, q = k;
    }
    /* (3.5) A_ij = |P_i^l P_i^m; Q_j^l Q_j^m|, B12 = |Q_1^l Q_1^m; Q_2^l Q_2^m| */
    double A[2][2];
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++)
            A[i][j] = P.d1[i][l] * Q.d1[j][m] - P.d1[i][m] * Q.d1[j][l];
    const double B12 = Q.d1[0][l] * Q.d1[1][m] - Q.d1[0][m] * Q.d1[1][l];
    const double eta = Q.d1[0][q] * A[0][1] - Q.d1[1][q] * A[0][0] - B12 * P.d1[0][q];
    const double zeta = Q.d1[0][q] * A[1][1] - Q.d1[1][q] * A[1][0] - B12 * P.d1[1][q];
    /* (3.9) t = (zeta P_1 - eta P_2) / |zeta P_1 - eta P_2| */
    double t[3];
    ic_scale3(t, P.d1[0], zeta);
    ic_axpy3(t, t, -eta, P.d1[1]);
    const double D = ic_normalize3(t);
    if (!(D > 0.0) || B12 == 0.0)
        return ic_error_set(err, IC_ERR_UNABLE, 0,
                            "Hassan and Badr (2016), eq. (3.9): the tangent vanishes");
    /* (3.10), (3.11) */
    const double v1[2] = {zeta / D, -eta / D};
    const double w1[2] = {(zeta * A[0][1] - eta * A[1][1]) / (B12 * D),
                          (eta * A[1][0] - zeta * A[0][0]) / (B12 * D)};
    /* (3.18), (3.19): c'' from t . c'' = 0 and the normal curvatures */
    const double r2[3] = {0.0, normal_curvature(&P, v1), normal_curvature(&Q, w1)};
    double c2[3];
    ic_solve_frame(c2, t, P.N, Q.N, r2);
    const double kappa2 = ic_dot3(c2, c2);
    /* (3.22), (3.23), (3.26), (3.27) */
    double v2[2], w2[2];
    second_param_derivs(&P, v1, c2, v2);
    second_param_derivs(&Q, w1, c2, w2);
    const double r3[3] = {-kappa2, psi(&P, v1, v2), psi(&Q, w1, w2)};
    double c3[3];
    ic_solve_frame(c3, t, P.N, Q.N, r3);
    memset(br, 0, sizeof *br);
    br->order = 3;
    memcpy(br->derivs[0], t, sizeof t);
    memcpy(br->derivs[1], c2, sizeof c2);
    memcpy(br->derivs[2], c3, sizeof c3);
    memcpy(br->param_derivs[0][0], v1, sizeof v1);
    memcpy(br->param_derivs[0][1], v2, sizeof v2);
    memcpy(br->param_derivs[1][0], w1, sizeof w1);
    memcpy(br->param_derivs[1][1], w2, sizeof w2);
    br->param_order = 2; /* the paper stops at v'', w'' */
    if (paper) {
        /* kappa^2 = <alpha'', alpha''>; tau by (2.7) = det(t, c'', c''')/kappa^2 */
        paper->kappa = sqrt(kappa2);
        paper->tau = ic_det3(t, c2, c3) / kappa2;
    }
    ic_orient_closed(br, sh[0].geo.normal, sh[1].geo.normal);
    return IC_OK;
}
