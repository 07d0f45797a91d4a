/* A curve made of marches done already (curve_ends.c): the start
 * candidates marched ahead by the workers become curves through it. */
#ifndef IC_TRACE_CURVE_ENDS_H
#define IC_TRACE_CURVE_ENDS_H

#include "march_ahead.h"
#include "trace_internal.h"

/* The curve of the marches m from pt (ic_trace_march_both) into a new
 * curve of r: its ends located and recorded, the failures listed; the
 * points are taken from m. */
ic_status ic_trace_add_marches(ic_trace_result *r, ic_pair *pair, const ic_local_point *pt,
                               const ic_trace_options *opt, ic_trace_marches *m,
                               ic_trace_point **pts_out, int *n_out, ic_error *err);

#endif
