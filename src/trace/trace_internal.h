/* Internal pieces of the tracer. */
#ifndef IC_TRACE_INTERNAL_H
#define IC_TRACE_INTERNAL_H

#include "intercurve/trace.h"

/* A start candidate: a point on both surfaces found in a cell the interval
 * test could not exclude. */
typedef struct {
    double xyz[3];
    double params[2][2];
    int covered;
} ic_candidate;

/* A leaf cell that intervals could not exclude but where Newton found no
 * point: its centre in space (and on the parametric sheets) and a radius
 * covering it. */
typedef struct {
    double xyz[3];
    double params[2][2];
    double radius;
    int converged_elsewhere; /* Newton from the centre left the cell */
} ic_unresolved;

/* Start candidates by subdivision (search.c); fills the report's search part.
 * *out and *unres are malloc'ed (free them). */
ic_status ic_trace_candidates(ic_pair *pair, const ic_trace_options *opt, ic_candidate **out,
                              int *n, ic_unresolved **unres, int *nunres, ic_trace_report *rep,
                              ic_error *err);

#endif
