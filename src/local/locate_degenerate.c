/*
 * Locating a degenerate tangential point (a cusp, a tacnode, ...) from a
 * nearby point of the curve. The collinear-normals equations have a
 * multiple root there (for y^2 = x^4 the x error of Gauss-Newton is about
 * eps^(1/3)), but the point is a simple root of h^(m-1), where h(r) =
 * g(r, phi(r)) is the height difference along dg/dw = 0 and m the contact
 * order along the kernel (docs/tracing.md). Each step re-expands at the new
 * point (ic_height_degenerate_step), which converges quadratically; the
 * highest m whose point classifies with contact order m wins.
 */
#include "common/args.h"
#include "local_internal.h"
#include "tangential.h"
#include "common/vec3.h"

#include <math.h>
#include <string.h>

enum { MAX_DEGENERATE_ORDER = 8, MAX_STEPS = 10 };

/* The parameters of Q on each parametric sheet, from their previous values. */
static int project_params(ic_pair *pair, ic_local_point *Q, const ic_local_options *opt)
{
    double worst = 0.0;
    for (int s = 0; s < 2; s++) {
        if (ic_surface_get_kind(ic_pair_surface(pair, s)) != IC_PARAMETRIC)
            continue;
        double dist;
        if (ic_local_project(pair, s, Q->params[s], Q->xyz, opt, &dist) != IC_OK)
            return 0;
        worst = fmax(worst, dist);
    }
    Q->residual = worst;
    return 1;
}

/* Steps towards the point of contact order m; 1 when the steps converged. */
static int converge(ic_pair *pair, ic_local_point *Q, const ic_local_point *near, int m,
                    double reach, const ic_local_options *opt)
{
    for (int it = 0; it < MAX_STEPS; it++) {
        ic_sheet sh[2];
        double X[3], d[3];
        if (ic_sheet_at(pair, &sh[0], 0, Q, NULL) != IC_OK ||
            ic_sheet_at(pair, &sh[1], 1, Q, NULL) != IC_OK ||
            ic_height_degenerate_step(sh, m, reach, opt, X, NULL) != IC_OK)
            return 0;
        ic_axpy3(d, X, -1.0, Q->xyz);
        const double step = ic_norm3(d);
        memcpy(Q->xyz, X, sizeof X);
        ic_axpy3(d, X, -1.0, near->xyz);
        if (ic_norm3(d) > reach || !project_params(pair, Q, opt))
            return 0;
        if (step <= 1e-14 * (1 + ic_norm3(X)))
            return 1;
    }
    return 0;
}

static ic_status locate_degenerate(ic_pair *pair, ic_local_point *pt, const ic_local_point *near,
                                   double reach, const ic_local_options *opt, ic_error *err)
{
    for (int m = MAX_DEGENERATE_ORDER; m >= 3; m--) {
        ic_local_point Q = *near;
        if (!converge(pair, &Q, near, m, reach, opt))
            continue;
        ic_local_result res;
        ic_local_options o = *opt;
        if (ic_local_apparatus(pair, &res, &Q, 2, IC_METHOD_AUTO, &o, NULL) != IC_OK)
            continue;
        if (res.type != IC_POINT_TRANSVERSAL && res.contact_order == m) {
            *pt = Q;
            return IC_OK;
        }
    }
    double at[3];
    ic_frame_shown(&pair->pairing.frame, near->xyz, at);
    return ic_error_set(err, IC_ERR_UNABLE, 0,
                        "no degenerate tangential point (contact order 3..%d) within %g of "
                        "(%g, %g, %g)",
                        MAX_DEGENERATE_ORDER, reach, at[0], at[1], at[2]);
}

/* (a contact order whose apparatus fails is passed over: out of memory
 * there is the pair's to tell) */
ic_status ic_local_locate_degenerate(ic_pair *pair, ic_local_point *pt, const ic_local_point *near,
                                     double reach, const ic_local_options *opt, ic_error *err)
{
    IC_ARG_NOT_NULL(pair, "pair");
    IC_ARG_NOT_NULL(pt, "pt");
    IC_ARG_NOT_NULL(near, "near");
    const long before = pair->nomem;
    const ic_status st = locate_degenerate(pair, pt, near, reach, opt, err);
    return ic_pair_nomem_check(pair, before, st, err);
}
