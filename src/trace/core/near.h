/* Whether something found passes near a point (near.c). */
#ifndef IC_TRACE_NEAR_H
#define IC_TRACE_NEAR_H

#include "result.h"

/* Whether a traced curve passes within bound of x. */
int ic_trace_curves_near(const ic_trace_result *r, const double *x, double bound);
/* Whether a traced curve or recorded singular point lies within bound of x. */
int ic_trace_point_near_found(const ic_trace_result *r, const double *x, double bound);

#endif
