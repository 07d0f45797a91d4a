/* What the layers above the expression layer (surface) may use of a
 * compiled formula beyond the public API, without its tape's layout
 * (expr_internal.h keeps that to the expr folder). */
#ifndef IC_EXPR_ACCESS_H
#define IC_EXPR_ACCESS_H

#include "intercurve/expr.h"

/* A deep copy of a compiled expression (its own tape): what a worker
 * thread of a trace evaluates (trace/workers.c). IC_ERR_NOMEM. */
ic_status ic_expr_copy(ic_expr **out, const ic_expr *e, ic_error *err);

#endif
