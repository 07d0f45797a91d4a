/*
 * The marches of a curve from a start point, apart from what the trace
 * makes of them (march_ahead.c): a march depends on the pair and the start
 * alone, so the start candidates that the trace will likely trace next can
 * be marched ahead in other threads and taken in the serial order
 * (docs/tracing.md, "Threads").
 */
#ifndef IC_TRACE_MARCH_AHEAD_H
#define IC_TRACE_MARCH_AHEAD_H

#include "trace_internal.h"

/* The two marches of ic_trace_both_ways: forward, then, unless it closed
 * or failed hard, backward; each with its status, event, message and a
 * copy of its points (room for one more, the end's tangential point). */
typedef struct {
    ic_status st[2]; /* [0] forward, [1] backward */
    ic_trace_event e[2];
    ic_error err[2]; /* what the tracer said */
    ic_trace_point *pts[2];
    int n[2];
} ic_trace_marches;

/* The marches from pt with the tracer: IC_OK, or IC_ERR_NOMEM (err set)
 * when the copies cannot be made; a march that fails is recorded in m. */
ic_status ic_trace_march_both(ic_tracer *tr, const ic_local_point *pt, ic_trace_marches *m,
                              ic_error *err);
void ic_trace_marches_free(ic_trace_marches *m);

/* A start candidate marched ahead: where it was located and its marches;
 * valid 0 where the trace must do it itself (not located, not transversal,
 * out of memory, not marched). */
typedef struct {
    int done;  /* marched ahead, valid or not */
    int valid;
    ic_local_point pt;
    ic_trace_marches m;
} ic_trace_ahead;

/* Marches ahead, in the trace's threads, candidate i and the next ones
 * that no curve traced so far covers and that lie apart from each other
 * (ahead[k] for candidate k; those already done are kept); as many as the
 * marches done ahead so far earn: `used` were traced, `lost` skipped. */
void ic_trace_march_ahead(ic_trace_result *r, ic_pair *pair, const ic_trace_options *opt,
                          const ic_candidate *cand, int nc, int i, int used, int lost,
                          ic_trace_ahead *ahead);

#endif
