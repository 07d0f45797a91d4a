/* One engine's result on one case, scored against the closed forms: a plain
 * struct, so the child process that ran the engine can pass it up a pipe. */
#ifndef IC_PEERS_METRICS_H
#define IC_PEERS_METRICS_H

#include "peers.h"

typedef enum {
    RUN_OK,      /* the engine ran and returned */
    RUN_ERROR,   /* the engine returned an error (note says which) */
    RUN_TIMEOUT, /* killed at the time limit */
    RUN_CRASH    /* the child died otherwise (note names the signal) */
} run_status;

typedef struct {
    run_status status;
    int runs;              /* timed runs; the median of their times is reported */
    double median_seconds;
    int ncurves, npoints, nsamples;
    double length;           /* total length of the curves found */
    double max_surface_dist; /* largest distance of a sample or point from either surface */
    double max_curve_dist;   /* largest distance of a sample from the exact curves */
    double max_kappa_err;    /* largest |kappa - exact| over samples with a curvature */
    double max_tau_err;      /* largest |tau - exact| over samples with a torsion */
    double median_kappa_err, median_tau_err; /* over the same samples */
    int kappa_count, tau_count;
    int stationary; /* samples without curvature: the parametrisation stands still */
    double point_err; /* distance of the nearest isolated point found from the exact one */
    char note[200];
} peer_summary;

/* Scores what one run found (the timing fields are the runner's). */
void peer_summarize(const bench_case *c, const peer_output *out, peer_summary *sum);

#endif
