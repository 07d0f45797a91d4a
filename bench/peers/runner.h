/* Runs one engine on one case in a child process with a time limit. */
#ifndef IC_PEERS_RUNNER_H
#define IC_PEERS_RUNNER_H

#include "metrics.h"

/* timed runs per engine and case, at most (the median time is reported) */
#define PEER_MAX_RUNS 5
/* seconds: no further timed run starts after this much has been spent */
#define PEER_REPEAT_BUDGET 10.0

/* Forks, runs the engine up to PEER_MAX_RUNS times in the child (alarm at
 * time_limit seconds), scores the last run and passes the summary up a pipe.
 * Fills *sum in every case: a timeout or a crash is a status, not an error.
 * Returns -1 only when the child could not be started. */
int peer_run(const peer_engine *e, const bench_case *c, unsigned time_limit,
             peer_summary *sum);

/* The same runs in this process, without a time limit: for a debugger or the
 * sanitizers (a forked child leaves by _exit, unchecked for leaks). */
void peer_run_here(const peer_engine *e, const bench_case *c, peer_summary *sum);

#endif
