/* The page of a long trace, for bench/bench_page.mjs (docs/plots.md, "The
 * interactive page"): the problem traced with the longest step shrunk until
 * it has at least POINTS points, then written as an interactive page.
 *   bench_page_trace PROBLEM.json OUT.html POINTS */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "intercurve.h"
#include "intercurve/plot.h"

static double seconds_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

/* rounds of shrinking the longest step; each about halves the miss */
#define ROUNDS 6

static int total_points(const ic_trace_result *r)
{
    int n = 0;
    for (int i = 0; i < ic_trace_result_num_curves(r); i++)
        n += ic_trace_result_curve(r, i)->npoints;
    return n;
}

/* Traces with max_step shrunk until the trace has `target` points or more. */
static ic_status long_trace(ic_trace_result **out, ic_pair *pair, ic_trace_options *opt,
                            int target, ic_error *err)
{
    opt->max_points = 2 * target;
    for (int round = 0; round < ROUNDS; round++) {
        ic_trace_result *r = NULL;
        const ic_status st = ic_trace(&r, pair, opt, err);
        if (st != IC_OK)
            return st;
        const int n = total_points(r);
        if (n >= target) {
            *out = r;
            return IC_OK;
        }
        ic_trace_result_free(r);
        /* where every step is the longest, points ~ 1 / max_step */
        opt->max_step *= 0.97 * (n > 0 ? (double)n : 1.0) / target;
    }
    return ic_error_set(err, IC_ERR_UNABLE, 0, "no trace of %d points in %d rounds", target, ROUNDS);
}

int main(int argc, char **argv)
{
    if (argc != 4 || atoi(argv[3]) < 1) {
        fprintf(stderr, "usage: bench_page_trace PROBLEM.json OUT.html POINTS\n");
        return 2;
    }
    ic_problem *p = NULL;
    ic_pair *pair = NULL;
    ic_trace_result *r = NULL;
    ic_error err;
    ic_error_clear(&err);
    ic_trace_options opt;
    ic_trace_defaults(&opt);
    ic_status st = ic_problem_load(&p, argv[1], &err);
    if (st == IC_OK) {
        opt.has_box = ic_problem_box(p, opt.box);
        st = ic_pair_new(&pair, ic_problem_surface(p, 0),
                         ic_problem_is_self(p) ? NULL : ic_problem_surface(p, 1), &err);
    }
    const double t0 = seconds_now();
    if (st == IC_OK)
        st = long_trace(&r, pair, &opt, atoi(argv[3]), &err);
    const double t1 = seconds_now();
    if (st == IC_OK) {
        ic_plot_scene scene;
        ic_plot_scene_of_problem(&scene, p, r);
        st = ic_plot_write(argv[2], &scene, NULL, &err);
    }
    if (st == IC_OK)
        printf("%d points traced in %.1f s (max_step %.3g), page written in %.1f s\n",
               total_points(r), t1 - t0, opt.max_step, seconds_now() - t1);
    else
        fprintf(stderr, "bench_page_trace: %s\n", err.message);
    ic_trace_result_free(r);
    ic_pair_free(pair);
    ic_problem_free(p);
    return st == IC_OK ? 0 : 1;
}
