/*
 * From arc-length derivatives to the Frenet apparatus and the Darboux
 * quantities (docs/local.md, "Outputs").
 *
 * c' = t, c'' = kappa n, b = t x n,
 * c''' = -kappa^2 t + kappa' n + kappa tau b            (so tau = det(c', c'', c''')/kappa^2),
 * c'''' = -3 kappa kappa' t + (kappa'' - kappa^3 - kappa tau^2) n
 *         + (2 kappa' tau + kappa tau') b                (so tau' = (b . c'''' - 2 kappa' tau)/kappa).
 */
#include "local_internal.h"
#include "common/vec3.h"

#include <string.h>

double ic_sheet_second_form(const ic_sheet *sh, const double *X, const double *Y)
{
    const double E = sh->geo.first[0], F = sh->geo.first[1], G = sh->geo.first[2];
    const double det = E * G - F * F;
    double x[2], y[2];
    const double px = ic_dot3(X, sh->geo.basis[0]), qx = ic_dot3(X, sh->geo.basis[1]);
    const double py = ic_dot3(Y, sh->geo.basis[0]), qy = ic_dot3(Y, sh->geo.basis[1]);
    x[0] = (G * px - F * qx) / det, x[1] = (E * qx - F * px) / det;
    y[0] = (G * py - F * qy) / det, y[1] = (E * qy - F * py) / det;
    const double L = sh->geo.second[0], M = sh->geo.second[1], N = sh->geo.second[2];
    return L * x[0] * y[0] + M * (x[0] * y[1] + x[1] * y[0]) + N * x[1] * y[1];
}

void ic_branch_finish(ic_branch *br, const ic_sheet sh[2], const ic_local_options *opt)
{
    const int K = br->order;
    const double *c1 = br->derivs[0];
    memcpy(br->t, c1, sizeof br->t);
    br->frame_defined = br->tau_defined = 0;
    br->kappa_prime_defined = br->tau_prime_defined = 0;
    memset(br->n, 0, sizeof br->n);
    memset(br->b, 0, sizeof br->b);
    br->kappa = br->tau = br->kappa_prime = br->tau_prime = 0.0;
    if (K >= 2) {
        const double *c2 = br->derivs[1];
        br->kappa = ic_norm3(c2);
        if (br->kappa > opt->kappa_zero) {
            br->frame_defined = 1;
            ic_scale3(br->n, c2, 1.0 / br->kappa);
            ic_cross3(br->b, br->t, br->n);
        }
        for (int s = 0; s < 2; s++) {
            const double *N = sh[s].geo.normal;
            double Nt[3];
            ic_cross3(Nt, N, br->t);
            br->surface[s].kappa_n = ic_dot3(c2, N);
            br->surface[s].kappa_g = ic_dot3(c2, Nt);
            br->surface[s].tau_g = ic_sheet_second_form(&sh[s], br->t, Nt);
        }
    }
    if (K >= 3 && br->frame_defined) {
        const double *c3 = br->derivs[2];
        br->tau = ic_det3(c1, br->derivs[1], c3) / (br->kappa * br->kappa);
        br->kappa_prime = ic_dot3(c3, br->n);
        br->tau_defined = br->kappa_prime_defined = 1;
    }
    if (K >= 4 && br->frame_defined) {
        br->tau_prime =
            (ic_dot3(br->b, br->derivs[3]) - 2.0 * br->kappa_prime * br->tau) / br->kappa;
        br->tau_prime_defined = 1;
    }
}

void ic_branch_reverse(ic_branch *br)
{
    if (!br)
        return;
    ic_scale3(br->t, br->t, -1.0);
    ic_scale3(br->b, br->b, -1.0);
    br->kappa_prime = -br->kappa_prime;
    br->tau_prime = -br->tau_prime;
    for (int k = 1; k <= br->order; k++) {
        const double sign = k % 2 ? -1.0 : 1.0;
        ic_scale3(br->derivs[k - 1], br->derivs[k - 1], sign);
        for (int s = 0; s < 2; s++)
            for (int v = 0; v < 2; v++)
                br->param_derivs[s][k - 1][v] *= sign;
    }
    for (int s = 0; s < 2; s++)
        br->surface[s].kappa_g = -br->surface[s].kappa_g;
}

int ic_branch_is_line(const ic_branch *br, double tol)
{
    return br && br->order >= 2 && br->kappa <= tol;
}

int ic_branch_is_planar(const ic_branch *br, double tol)
{
    return br && br->tau_defined && fabs(br->tau) <= tol;
}
