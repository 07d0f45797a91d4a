/* The exact paths' one door (docs/tracing.md, "Exact paths"): the closed
 * forms tried before the search, on implicit primitives and on NURBS
 * patches recognised as the standard surfaces they are. They fill the
 * result through trace/core/ and never call the general path. */
#ifndef IC_TRACE_EXACT_H
#define IC_TRACE_EXACT_H

#include "trace/core/result.h"

/* The pair in closed form, when one applies (the user's options, relative;
 * r->scale the problem's size L): coaxial surfaces of revolution first
 * (exact_revolution.c), then a plane and a quadric meeting in an ellipse and
 * two cylinders of equal radius whose axes meet (exact_conic.c, after the
 * revolution path, which keeps the coaxial cases). *done = 1 with r filled,
 * its scale that of what was found and its report complete; else *done = 0
 * and r untouched; IC_ERR_NOMEM out of memory. */
ic_status ic_trace_exact(ic_trace_result *r, ic_pair *pair, const ic_trace_options *user_opt,
                         int *done, ic_error *err);

#endif
