/*
 * Any mix of parametric and implicit surfaces (docs/references.md):
 *  - Bendrici and Boumedien-Zidani (2022), after Ye and Maekawa (1999),
 *    eqs. (2.4)-(2.9): t = N_A x N_B / |.|, the parameter derivatives (2.5),
 *    the normal curvatures, and the curvature vector
 *    K = [(kn_A - kn_B cos) N_A + (kn_B - kn_A cos) N_B] / sin^2;
 *  - Patrikalakis and Maekawa (2002), section 6.3.3, eqs. (6.35)-(6.46): the
 *    normal projections lambda_n = c''' . N of each surface give
 *    c''' = -kappa^2 t + gamma N_A + delta N_B (6.37) and the torsion (6.46).
 * cos = N_A . N_B, sin^2 = 1 - cos^2 (theta is the angle between the normals).
 */
#include "local_internal.h"
#include "common/vec3.h"

#include <math.h>
#include <string.h>

/* The first and second parameter derivatives and lambda_n on a parametric
 * sheet, given t and K. */
static double lambda_parametric(const ic_sheet *sh, const double *t, const double *K,
                                double *u1, double *u2)
{
    double ru[3], rv[3], ruu[3], ruv[3], rvv[3], r3[4][3];
    ic_sheet_partial(sh, 1, 0, ru);
    ic_sheet_partial(sh, 0, 1, rv);
    ic_sheet_partial(sh, 2, 0, ruu);
    ic_sheet_partial(sh, 1, 1, ruv);
    ic_sheet_partial(sh, 0, 2, rvv);
    ic_sheet_partial(sh, 3, 0, r3[0]);
    ic_sheet_partial(sh, 2, 1, r3[1]);
    ic_sheet_partial(sh, 1, 2, r3[2]);
    ic_sheet_partial(sh, 0, 3, r3[3]);
    const double *N = sh->geo.normal;
    const double E = ic_dot3(ru, ru), F = ic_dot3(ru, rv), G = ic_dot3(rv, rv);
    const double det = E * G - F * F;
    /* (2.5) u' = (G (t.r_u) - F (t.r_v)) / (EG - F^2), v' = (E (t.r_v) - F (t.r_u)) / (EG - F^2) */
    const double tu = ic_dot3(t, ru), tv = ic_dot3(t, rv);
    u1[0] = (G * tu - F * tv) / det;
    u1[1] = (E * tv - F * tu) / det;
    /* (6.40), (6.41) with E_u = 2 r_uu.r_u, E_v = 2 r_uv.r_u, F_u = r_uu.r_v + r_u.r_uv,
     * F_v = r_uv.r_v + r_u.r_vv, G_u = 2 r_uv.r_v, G_v = 2 r_vv.r_v */
    const double Eu = 2 * ic_dot3(ruu, ru), Ev = 2 * ic_dot3(ruv, ru);
    const double Fu = ic_dot3(ruu, rv) + ic_dot3(ru, ruv), Fv = ic_dot3(ruv, rv) + ic_dot3(ru, rvv);
    const double Gu = 2 * ic_dot3(ruv, rv), Gv = 2 * ic_dot3(rvv, rv);
    const double a = u1[0], b = u1[1];
    const double p = ic_dot3(K, ru) - Eu / 2 * a * a - Ev * a * b - (Fv - Gu / 2) * b * b;
    const double q = ic_dot3(K, rv) - (Fu - Ev / 2) * a * a - Gu * a * b - Gv / 2 * b * b;
    u2[0] = (G * p - F * q) / det;
    u2[1] = (E * q - F * p) / det;
    /* (6.38), (6.39) */
    const double L = ic_dot3(ruu, N), M = ic_dot3(ruv, N), Nn = ic_dot3(rvv, N);
    const double III = ic_dot3(r3[0], N) * a * a * a + 3 * ic_dot3(r3[1], N) * a * a * b +
                       3 * ic_dot3(r3[2], N) * a * b * b + ic_dot3(r3[3], N) * b * b * b;
    return 3 * (L * a * u2[0] + M * (u2[0] * b + a * u2[1]) + Nn * b * u2[1]) + III;
}

/* lambda_n on an implicit sheet (6.42)-(6.45), with x' = t, x'' = K. */
static double lambda_implicit(const ic_sheet *sh, const double *t, const double *K)
{
#define FD(a, b, c) ic_sheet_fpartial(sh, a, b, c)
    const double x = t[0], y = t[1], z = t[2], xx = K[0], yy = K[1], zz = K[2];
    const double F1 = FD(3, 0, 0) * x * x * x + FD(0, 3, 0) * y * y * y + FD(0, 0, 3) * z * z * z;
    const double F2 = 3 * (FD(2, 1, 0) * x * x * y + FD(2, 0, 1) * x * x * z +
                           FD(1, 2, 0) * x * y * y + FD(0, 2, 1) * y * y * z +
                           FD(1, 0, 2) * x * z * z + FD(0, 1, 2) * y * z * z +
                           2 * FD(1, 1, 1) * x * y * z);
    const double F3 = 3 * (FD(2, 0, 0) * x * xx + FD(0, 2, 0) * y * yy + FD(0, 0, 2) * z * zz +
                           FD(1, 1, 0) * (xx * y + x * yy) + FD(0, 1, 1) * (yy * z + y * zz) +
                           FD(1, 0, 1) * (xx * z + x * zz));
#undef FD
    return -(F1 + F2 + F3) / sh->geo.normal_length;
}

/* Normal curvature of the direction t on a sheet: parametric by (2.5) and
 * II(u', v'); implicit -t^T Hess(f) t / |grad f| (from f(c(s)) = 0). */
static double normal_curvature(const ic_sheet *sh, const double *t)
{
    if (sh->parametric) {
        double ru[3], rv[3];
        ic_sheet_partial(sh, 1, 0, ru);
        ic_sheet_partial(sh, 0, 1, rv);
        const double E = sh->geo.first[0], F = sh->geo.first[1], G = sh->geo.first[2];
        const double det = E * G - F * F, tu = ic_dot3(t, ru), tv = ic_dot3(t, rv);
        const double a = (G * tu - F * tv) / det, b = (E * tv - F * tu) / det;
        return sh->geo.second[0] * a * a + 2 * sh->geo.second[1] * a * b +
               sh->geo.second[2] * b * b;
    }
    double q = 0.0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            int e[3] = {0, 0, 0};
            e[i]++, e[j]++;
            q += ic_sheet_fpartial(sh, e[0], e[1], e[2]) * t[i] * t[j];
        }
    return -q / sh->geo.normal_length;
}

ic_status ic_closed_patrikalakis_maekawa(ic_branch *br, const ic_sheet sh[2],
                                         ic_paper_values *paper, ic_error *err)
{
    const double *NA = sh[0].geo.normal, *NB = sh[1].geo.normal;
    double t[3];
    ic_cross3(t, NA, NB); /* (2.4) */
    if (!(ic_normalize3(t) > 0.0))
        return ic_error_set(err, IC_ERR_UNABLE, 0,
                            "Bendrici and Boumedien-Zidani (2022), eq. (2.4): parallel normals");
    const double cs = ic_dot3(NA, NB), sn2 = 1.0 - cs * cs;
    /* (2.7), (2.8) and the formula for K after them */
    const double knA = normal_curvature(&sh[0], t), knB = normal_curvature(&sh[1], t);
    double K[3];
    ic_scale3(K, NA, (knA - knB * cs) / sn2);
    ic_axpy3(K, K, (knB - knA * cs) / sn2, NB);
    const double kappa = ic_norm3(K);
    /* lambda_n on each sheet */
    double lam[2], u1[2][2] = {{0}}, u2[2][2] = {{0}};
    for (int s = 0; s < 2; s++)
        lam[s] = sh[s].parametric ? lambda_parametric(&sh[s], t, K, u1[s], u2[s])
                                  : lambda_implicit(&sh[s], t, K);
    /* (6.37) */
    const double gamma = (lam[0] - lam[1] * cs) / sn2, delta = (lam[1] - lam[0] * cs) / sn2;
    double c3[3];
    ic_scale3(c3, t, -kappa * kappa);
    ic_axpy3(c3, c3, gamma, NA);
    ic_axpy3(c3, c3, delta, NB);
    memset(br, 0, sizeof *br);
    br->order = 3;
    memcpy(br->derivs[0], t, sizeof t);
    memcpy(br->derivs[1], K, sizeof K);
    memcpy(br->derivs[2], c3, sizeof c3);
    for (int s = 0; s < 2; s++) {
        memcpy(br->param_derivs[s][0], u1[s], sizeof u1[s]);
        memcpy(br->param_derivs[s][1], u2[s], sizeof u2[s]);
    }
    br->param_order = 2;
    if (paper) {
        paper->kappa = kappa;
        /* (6.46) with b = t x n, n = K / kappa (2.9) */
        double n[3], b[3];
        ic_scale3(n, K, 1.0 / kappa);
        ic_cross3(b, t, n);
        paper->tau = (gamma * ic_dot3(b, NA) + delta * ic_dot3(b, NB)) / kappa;
    }
    return IC_OK;
}
