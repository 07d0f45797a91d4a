/* Timing for the benchmarks: the best of 5 batches of at least 20 ms, each
 * batch's repetition count grown until it lasts that long. */
#ifndef IC_BENCH_TIMER_H
#define IC_BENCH_TIMER_H

#include <math.h>
#include <time.h>

static double bench_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

/* ns per call of fn(ctx), which returns 0 on success; NaN if it failed. */
static double bench_ns_per_call(int (*fn)(void *ctx), void *ctx)
{
    double best = 1e30;
    long reps = 16;
    for (int batch = 0; batch < 5; batch++) {
        double t0, t1;
        for (;;) {
            t0 = bench_now();
            for (long r = 0; r < reps; r++)
                if (fn(ctx) != 0)
                    return NAN;
            t1 = bench_now();
            if (t1 - t0 > 0.02)
                break;
            reps *= 4;
        }
        const double ns = (t1 - t0) * 1e9 / reps;
        if (ns < best)
            best = ns;
    }
    return best;
}

#endif
