/* Where a transversal curve crosses a tangential one (crossing.c;
 * docs/tracing.md, "Crossings of a tangential curve"). */
#ifndef IC_TRACE_CROSSING_H
#define IC_TRACE_CROSSING_H

#include "intercurve/local.h"

/* The crossing of a tangential curve that a transversal curve's end `near`
 * stopped beside: the tangential curve's point within reach (a length) of
 * near, then along that curve, within reach again, the point where the bend
 * across it changes sign, to rounding: 1, *P and *place (the length
 * within which it is known: the tangential curve is a double root, known
 * to about sqrt(eps) L in general), or 0 when near is not
 * beside a tangential curve or no crossing lies within reach. */
int ic_trace_locate_crossing(ic_pair *pair, const ic_local_options *lopt,
                             const ic_local_point *near, double reach, ic_local_point *P,
                             double *place);

#endif
