/* What the layers above the expression layer (surface) may use of a
 * compiled formula beyond the public API, without its tape's layout
 * (expr_internal.h keeps that to the expr folder). */
#ifndef IC_EXPR_ACCESS_H
#define IC_EXPR_ACCESS_H

#include "intercurve/expr.h"

/* A deep copy of a compiled expression (its own tape): what a worker
 * thread of a trace evaluates (trace/workers.c). IC_ERR_NOMEM. */
ic_status ic_expr_copy(ic_expr **out, const ic_expr *e, ic_error *err);

/* The formula g(y) = f(var_at + y) - out_at moved to a new origin
 * (shift.c): equal to f's in real arithmetic, every constant combined
 * exactly, so a feature far from the origin keeps its digits. var_at has
 * f's nvars offsets, out_at its noutputs (NULL: none). IC_ERR_NOMEM. */
ic_status ic_expr_shifted(ic_expr **out, const ic_expr *f, const double *var_at,
                          const double *out_at, ic_error *err);

/* One term of a formula written as a sum: coef times register reg. */
typedef struct {
    int reg;
    ic_interval coef;
} ic_expr_term;

/* Formula `output` of e as sum_i terms[i].coef * register terms[i].reg + K
 * through its sums, differences, negations and products and quotients by
 * constants (linear_terms.c; constants combined in interval arithmetic,
 * so the sum encloses the formula): the number of terms, or -1 beyond max. */
int ic_expr_linear_terms(const ic_expr *e, int output, ic_expr_term *terms, int max,
                         ic_interval *K);

/* 1 when register ra of a and register rb of b compute the same function
 * of the same variables (the same instructions and constants throughout;
 * 0 also when the comparison runs beyond its budget). */
int ic_expr_same_register(const ic_expr *a, int ra, const ic_expr *b, int rb);

#endif
