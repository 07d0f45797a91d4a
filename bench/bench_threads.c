/* Benchmark of a trace's threads (make bench; docs/tracing.md, "Threads"):
 * whole traces where the search is most of the work (and one where the
 * marching of many curves is), in 1 thread, 2 and all
 * the machine's online cores: the best of three wall times, the CPU time of
 * the process (all its threads) in that run, and the speed-up of the wall
 * time over 1 thread; "same" says the trace document equals the 1-thread one.
 * On a machine shared with other work the wall times say what the other
 * work left: the CPU times say what the threads cost (usage: bench_threads
 * [SOURCE_DIR]). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include <math.h>
#include <pthread.h>

#include "intercurve.h"

#define RUNS 3 /* the best of these, by wall time */

typedef struct {
    const char *file;
    int depth, exact;
} bench_case;

/* Seconds on a clock: CLOCK_MONOTONIC (wall) or CLOCK_PROCESS_CPUTIME_ID. */
static double seconds(clockid_t clock)
{
    struct timespec ts;
    clock_gettime(clock, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

typedef struct {
    double wall, cpu; /* seconds, of the fastest run */
    char *doc;        /* its trace document */
} timed;

/* The best of RUNS traces of the pair in `threads` threads; -1 on failure. */
static int time_trace(ic_pair *pair, ic_trace_options opt, int threads, timed *t)
{
    opt.threads = threads;
    t->wall = INFINITY;
    t->doc = NULL;
    for (int k = 0; k < RUNS; k++) {
        ic_trace_result *r = NULL;
        ic_error err;
        const double w0 = seconds(CLOCK_MONOTONIC), c0 = seconds(CLOCK_PROCESS_CPUTIME_ID);
        if (ic_trace(&r, pair, &opt, &err) != IC_OK) {
            fprintf(stderr, "trace: %s\n", err.message);
            return -1;
        }
        const double wall = seconds(CLOCK_MONOTONIC) - w0;
        const double cpu = seconds(CLOCK_PROCESS_CPUTIME_ID) - c0;
        if (wall < t->wall) {
            t->wall = wall, t->cpu = cpu;
            free(t->doc);
            t->doc = NULL;
            if (ic_trace_json_alloc(&t->doc, NULL, r, pair, &err) != IC_OK)
                t->doc = NULL;
        }
        ic_trace_result_free(r);
    }
    return 0;
}

/* Additions of the calibration: about 0.2 s of one core. */
#define SPIN_STEPS 60000000L

static void *spin(void *arg)
{
    volatile double x = 0;
    for (long i = 0; i < SPIN_STEPS; i++)
        x += 1e-9;
    return x > 0 ? arg : NULL; /* x read: the sum is used (clang's -Wunused-but-set-variable) */
}

/* How many cores the machine gives this process now: the time of one
 * thread of plain arithmetic over that of n such threads at once, times n
 * (n on an idle machine of n cores, less on a shared one). */
static double cores_given(int n)
{
    const double t0 = seconds(CLOCK_MONOTONIC);
    spin(NULL);
    const double one = seconds(CLOCK_MONOTONIC) - t0;
    pthread_t th[64];
    int started = 0;
    const double t1 = seconds(CLOCK_MONOTONIC);
    while (started < n - 1 && started < 64 && pthread_create(&th[started], NULL, spin, NULL) == 0)
        started++;
    spin(NULL);
    for (int k = 0; k < started; k++)
        pthread_join(th[k], NULL);
    return (started + 1) * one / (seconds(CLOCK_MONOTONIC) - t1);
}

/* One problem's row per thread count. */
static int bench_one(const char *src, const bench_case *c, const int *counts, int ncounts)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", src, c->file);
    ic_problem *p = NULL;
    ic_pair *pair = NULL;
    ic_error err;
    if (ic_problem_load(&p, path, &err) != IC_OK ||
        ic_pair_new(&pair, ic_problem_surface(p, 0),
                    ic_problem_is_self(p) ? NULL : ic_problem_surface(p, 1), &err) != IC_OK) {
        fprintf(stderr, "%s: %s\n", path, err.message);
        ic_problem_free(p);
        return 1;
    }
    ic_trace_options opt;
    ic_trace_defaults(&opt);
    opt.depth = c->depth;
    opt.exact_paths = c->exact;
    opt.has_box = ic_problem_box(p, opt.box);
    timed one = {0};
    int rc = 0;
    for (int k = 0; k < ncounts && rc == 0; k++) {
        timed t;
        if ((rc = time_trace(pair, opt, counts[k], &t)) != 0)
            break;
        if (k == 0)
            one = t;
        const char *name = strrchr(c->file, '/') ? strrchr(c->file, '/') + 1 : c->file;
        printf("%-38s %5d %5s %7d %10.1f %10.1f %8.2f %5s\n", name, c->depth,
               c->exact ? "yes" : "no", counts[k], t.wall * 1e3, t.cpu * 1e3, one.wall / t.wall,
               one.doc && t.doc && strcmp(one.doc, t.doc) == 0 ? "same" : "DIFF");
        if (k > 0)
            free(t.doc);
    }
    free(one.doc);
    ic_pair_free(pair);
    ic_problem_free(p);
    return rc;
}

int main(int argc, char **argv)
{
    const char *src = argc > 1 ? argv[1] : ".";
    static const bench_case CASES[] = {
        {"examples/torus-sphere.json", 7, 0},
        {"examples/enneper-self.json", 7, 1},
        {"examples/torus-plane-tangential.json", 7, 1},
        {"tests/data/nurbs/problem-torus-sphere-tangential.json", 7, 1},
        {"tests/data/nurbs/problem-freeform-bicubic.json", 8, 1},
        /* 98 closed curves: the marching of start candidates is most of it */
        {"tests/torture/eggcrate-k10.json", 6, 1},
    };
    const long cores = sysconf(_SC_NPROCESSORS_ONLN);
    int counts[3] = {1, 2, (int)(cores > 0 ? cores : 1)}, ncounts = counts[2] > 2 ? 3 : 2;
    printf("\n%-38s %5s %5s %7s %10s %10s %8s %5s\n", "threads (best of 3 by wall time)", "depth",
           "exact", "threads", "wall (ms)", "cpu (ms)", "speed-up", "doc");
    for (size_t c = 0; c < sizeof CASES / sizeof *CASES; c++)
        if (bench_one(src, &CASES[c], counts, ncounts) != 0)
            return 1;
    printf("(%ld online cores; cpu: all the process's threads; on a shared machine the wall\n"
           " times depend on the other work, the cpu times on the threads' own: two threads\n"
           " of plain arithmetic ran at %.2f times one's speed just now, 2.00 on 2 free cores)\n",
           cores, cores_given(2));
    return 0;
}
