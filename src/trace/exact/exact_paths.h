/* The exact paths one by one, behind the door of exact.h: each the pair in
 * closed form or *done = 0 (exact.h says how), and the report's method
 * strings. */
#ifndef IC_TRACE_EXACT_PATHS_H
#define IC_TRACE_EXACT_PATHS_H

#include "exact.h"

/* exact_revolution.c: coaxial surfaces of revolution, implicit primitives or
 * NURBS patches recognised as them. */
ic_status ic_trace_exact_revolution(ic_trace_result *r, ic_pair *pair,
                                    const ic_trace_options *user_opt, int *done, ic_error *err);
extern const char ic_trace_method_revolution[];
extern const char ic_trace_method_revolution_nets[];

/* exact_conic.c: a plane and a quadric primitive meeting in an ellipse, and
 * two cylinders of equal radius whose axes meet, implicit or NURBS patches
 * recognised as them; and the same on the two implicit primitives
 * themselves. */
ic_status ic_trace_exact_conic(ic_trace_result *r, ic_pair *pair,
                               const ic_trace_options *user_opt, int *done, ic_error *err);
ic_status ic_trace_exact_conic_primitives(ic_trace_result *r, const ic_primitive *pa,
                                          const ic_primitive *pb,
                                          const ic_trace_options *user_opt, int *done,
                                          ic_error *err);
extern const char ic_trace_method_conic[];
extern const char ic_trace_method_conic_nets[];

#endif
