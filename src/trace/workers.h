/*
 * The threads of one trace (workers.c): a pool of threads, each with its
 * own copy of the pair (surfaces are not safe to share: their evaluations
 * write workspaces), that run a batch of independent jobs while the calling
 * thread takes part with the pair itself. The jobs write only their own
 * outputs; the caller merges them in their order, so that the trace is the
 * same whatever the number of threads (docs/tracing.md, "Threads").
 */
#ifndef IC_TRACE_WORKERS_H
#define IC_TRACE_WORKERS_H

#include "intercurve/trace.h"

typedef struct ic_trace_workers ic_trace_workers;

/* The threads a trace with ic_trace_options.threads = `threads` uses:
 * threads itself, or for 0 the machine's online cores; 1..IC_TRACE_MAX_THREADS. */
int ic_trace_thread_count(int threads);

/* A pool for n threads in all, the caller one of them. *out is NULL (and
 * IC_OK) when n <= 1, when a surface cannot be copied (a callback: the
 * trace then runs in one thread) or when no thread could be started.
 * IC_ERR_NOMEM out of memory. */
ic_status ic_trace_workers_new(ic_trace_workers **out, ic_pair *pair, int n, ic_error *err);
void ic_trace_workers_free(ic_trace_workers *w);

/* How many threads run a batch: 1 for NULL. */
int ic_trace_workers_count(const ic_trace_workers *w);

/* One job of a batch: job i, on a pair that no other thread uses now. */
typedef void ic_trace_job(void *ctx, int i, ic_pair *pair);

/* Runs job(ctx, i, ...) for every i in 0..n-1 over the pool's threads and
 * the caller's (which uses `pair`); returns when all are done. With a NULL
 * pool the caller runs them all, in order. */
void ic_trace_workers_run(ic_trace_workers *w, ic_pair *pair, ic_trace_job *job, void *ctx,
                          int n);

#endif
