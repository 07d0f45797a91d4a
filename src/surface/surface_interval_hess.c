/* Second-order enclosures of formula surfaces and of the implicit quadric
 * primitives (surface.h). */
#include "common/args.h"
#include "surface_internal.h"

#include <stdlib.h>
#include <string.h>

/* Work registers on the stack; longer formulas allocate. */
#define STACK_REGISTERS 64

/* An implicit quadric primitive: f_local = sum_i A_i d_i^2 + B_i d_i + C
 * in local coordinates d = frame (x - center), so its Hessian is the
 * constant frame^T diag(2 A) frame, each column e_j taken to local
 * coordinates, scaled and taken back in interval arithmetic. */
static ic_status quadric_hess(ic_surface *s, ic_interval_hess *out, const ic_interval *in,
                              ic_error *err)
{
    if (s->kind != IC_IMPLICIT || s->prim.kind == IC_PRIM_TORUS)
        return ic_error_set(err, IC_ERR_UNABLE, 0,
                            "second-order enclosures of this primitive are not written");
    ic_interval_grad g;
    ic_primitive_interval_grad(s, &g, in);
    memset(out, 0, sizeof *out);
    out->v = g.v;
    for (int k = 0; k < 3; k++)
        out->d[k] = g.d[k];
    double A[3], B[3], C;
    ic_primitive_quadric_coefficients(&s->prim, A, B, &C);
    for (int j = 0; j < 3; j++) {
        ic_interval col[3] = {{0, 0}, {0, 0}, {0, 0}};
        col[j] = (ic_interval){1.0, 1.0};
        if (s->placed)
            ic_placement_interval_to_local(s->frame, col);
        for (int i = 0; i < 3; i++)
            col[i] = ic_interval_mul((ic_interval){2 * A[i], 2 * A[i]}, col[i]);
        if (s->placed)
            ic_placement_interval_to_space(s->frame, col);
        for (int i = j; i < 3; i++) /* the lower triangle: H is symmetric */
            out->h[ic_interval_hess_index(j, i)] = col[i];
    }
    return IC_OK;
}

ic_status ic_surface_eval_interval_hess(ic_surface *s, ic_interval_hess *out, const ic_interval *in,
                                        ic_error *err)
{
    IC_ARG_NOT_NULL(s, "s");
    IC_ARG_NOT_NULL(out, "out");
    IC_ARG_NOT_NULL(in, "in");
    if (s->backend == BACKEND_PRIMITIVE)
        return quadric_hess(s, out, in, err);
    if (s->backend != BACKEND_FORMULA)
        return ic_error_set(err, IC_ERR_UNABLE, 0,
                            "second-order enclosures need a formula surface or a quadric");
    const int nin = s->kind == IC_PARAMETRIC ? 2 : 3;
    ic_interval_hess x[3];
    memset(x, 0, sizeof x);
    for (int i = 0; i < nin; i++) {
        x[i].v = in[i];
        x[i].d[i] = (ic_interval){1.0, 1.0};
    }
    ic_interval_hess work[STACK_REGISTERS];
    ic_interval_hess *w = work;
    const size_t len = ic_expr_interval_hess_work_len(s->expr);
    if (len > STACK_REGISTERS) {
        w = malloc(len * sizeof *w);
        if (!w)
            return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory");
    }
    const int whole = ic_expr_eval_interval_hess(s->expr, out, x, nin, w);
    if (w != work)
        free(w);
    if (!whole)
        return ic_error_set(err, IC_ERR_DOMAIN, 0,
                            "the surface's formula has no second derivatives over the whole box");
    return IC_OK;
}
