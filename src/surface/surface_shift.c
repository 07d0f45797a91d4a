/*
 * A surface moved to a new origin (surface_copy.h, ic_surface_shifted):
 * the same surface in coordinates x' = x - origin and, for a parametric
 * one, parameters u' = u - param_at, exactly, so that a problem far from
 * the origin is traced and certified with the digits of its own size
 * (docs/tracing.md, "Far from the origin"). Only what moves without a
 * rounding moves: a formula (its constants combined exactly,
 * expr/shift.c), a primitive whose centre and a domain whose bounds
 * subtract exactly; a NURBS patch or a callback is not moved.
 */
#include "common/frame.h"
#include "expr/expr_access.h"
#include "surface_copy.h"
#include "surface_internal.h"

#include <math.h>
#include <stdlib.h>

static ic_status unable(ic_error *err, const char *what)
{
    return ic_error_set(err, IC_ERR_UNABLE, 0, "%s is not moved to the problem's origin", what);
}

/* The moved domain, or UNABLE where a bound does not subtract exactly. */
static ic_status move_domain(ic_surface *c, const double param_at[2], ic_error *err)
{
    for (int k = 0; k < 2; k++)
        for (int e = 0; e < 2; e++) {
            const double d = ic_exact_difference(c->domain[k][e], param_at[k]);
            if (isnan(d))
                return unable(err, "a domain bound");
            c->domain[k][e] = d;
        }
    return IC_OK;
}

/* The formula moved: an implicit one's variables by the origin, a
 * parametric one's parameters by param_at and its values by the origin. */
static ic_status move_formula(ic_surface *c, const double origin[3], const double param_at[2],
                              ic_error *err)
{
    ic_expr *moved = NULL;
    const int implicit = c->kind == IC_IMPLICIT;
    ic_status st = ic_expr_shifted(&moved, c->expr, implicit ? origin : param_at,
                                   implicit ? NULL : origin, err);
    if (st != IC_OK)
        return st;
    ic_expr_free(c->expr);
    c->expr = moved;
    return implicit ? IC_OK : move_domain(c, param_at, err);
}

static ic_status move_primitive(ic_surface *c, const double origin[3], const double param_at[2],
                                ic_error *err)
{
    if (param_at[0] != 0.0 || param_at[1] != 0.0)
        return unable(err, "a primitive's angles");
    for (int k = 0; k < 3; k++) {
        const double d = ic_exact_difference(c->prim.center[k], origin[k]);
        if (isnan(d))
            return unable(err, "a primitive's centre");
        c->prim.center[k] = d;
    }
    return IC_OK;
}

ic_status ic_surface_shifted(ic_surface **out, const ic_surface *s, const double origin[3],
                             const double param_at[2], ic_error *err)
{
    *out = NULL;
    if (s->backend != BACKEND_FORMULA && s->backend != BACKEND_PRIMITIVE)
        return unable(err, "a NURBS patch or a callback surface");
    ic_surface *c = NULL;
    ic_status st = ic_surface_copy(&c, s, err);
    if (st != IC_OK)
        return st;
    st = s->backend == BACKEND_FORMULA ? move_formula(c, origin, param_at, err)
                                       : move_primitive(c, origin, param_at, err);
    if (st != IC_OK) {
        ic_surface_free(c);
        return st;
    }
    *out = c;
    return IC_OK;
}
