/* The closed-form method: the papers' formulas, dispatched by pairing
 * (docs/local.md): Hassan and Badr (2016) for parametric/parametric and
 * self-intersections, Abdel-All et al. (2012) for implicit/implicit,
 * Bendrici and Boumedien-Zidani (2022) with Patrikalakis and Maekawa (2002)
 * (which work for any mix) for parametric/implicit. */
#include "local_internal.h"
#include "common/vec3.h"

void ic_frame_solver_init(ic_frame_solver *fs, const double *t, const double *NA,
                          const double *NB)
{
    ic_cross3(fs->ab, NA, NB);
    ic_cross3(fs->bt, NB, t);
    ic_cross3(fs->ta, t, NA);
    fs->det = ic_dot3(t, fs->ab);
}

void ic_solve_frame(double *x, const double *t, const double *NA, const double *NB,
                    const double *r)
{
    ic_frame_solver fs;
    ic_frame_solver_init(&fs, t, NA, NB);
    ic_frame_solve(&fs, x, r);
}

void ic_arc_length_derivs(double c[3][3], const double *b1, const double *b2, const double *b3)
{
    /* c' = b1/v, c'' = (b2 v - b1 v1)/v^3 and c''' = b3/v^3 - 3 v1 b2/v^4 - v2 b1/v^4
     * + 3 v1^2 b1/v^5, with v = |b1|, v1 = b1.b2/v, v2 = (|b2|^2 + b1.b3)/v - (b1.b2)^2/v^3 */
    const double v = ic_norm3(b1), bb = ic_dot3(b1, b2);
    const double v1 = bb / v;
    const double v2 = (ic_dot3(b2, b2) + ic_dot3(b1, b3)) / v - bb * bb / (v * v * v);
    const double v3 = v * v * v, v4 = v3 * v, v5 = v4 * v;
    for (int i = 0; i < 3; i++) {
        c[0][i] = b1[i] / v;
        c[1][i] = (b2[i] * v - b1[i] * v1) / v3;
        c[2][i] = b3[i] / v3 - 3 * v1 * b2[i] / v4 - v2 * b1[i] / v4 + 3 * v1 * v1 * b1[i] / v5;
    }
}

void ic_orient_closed(ic_branch *br, const double *NA, const double *NB)
{
    double w[3];
    ic_cross3(w, NA, NB);
    if (ic_dot3(w, br->derivs[0]) >= 0.0)
        return;
    ic_scale3(br->derivs[0], br->derivs[0], -1.0);
    ic_scale3(br->derivs[2], br->derivs[2], -1.0);
    for (int s = 0; s < 2; s++)
        for (int v = 0; v < 2; v++) {
            br->param_derivs[s][0][v] = -br->param_derivs[s][0][v];
            br->param_derivs[s][2][v] = -br->param_derivs[s][2][v];
        }
}

ic_status ic_closed_form_method(ic_branch *br, const ic_sheet sh[2], int order, ic_error *err)
{
    ic_status st;
    if (sh[0].parametric && sh[1].parametric)
        st = ic_closed_hassan_badr(br, sh, NULL, err);
    else if (!sh[0].parametric && !sh[1].parametric)
        st = ic_closed_abdel_all(br, sh, NULL, err);
    else
        st = ic_closed_patrikalakis_maekawa(br, sh, NULL, err);
    br->order = order; /* the closed forms give 3 orders; keep what was asked */
    return st;
}
