/* A minimal test harness: CHECK counts, failures print file:line and a
 * message, finish() prints "<name>: N passed, M failed" and the exit code
 * (non-zero on any failure, and when no check ran at all).
 * The tolerance tiers shared by the tests are below, each with its unit and
 * its reason (docs/testing.md, "Tolerance tiers"). */
#ifndef IC_TEST_HARNESS_H
#define IC_TEST_HARNESS_H

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static int harness_run, harness_failed;

static inline int harness_fail_at(const char *file, int line)
{
    harness_failed++;
    fprintf(stderr, "%s:%d: FAIL: ", file, line);
    return 0;
}

/* A check as an expression: counts it, prints the message when cond is
 * false, and yields whether it held. cond is evaluated once, before the
 * message's arguments. A setup step that must succeed is a REQUIRE, so that
 * a test can never vanish by returning early without a failure:
 *   if (!REQUIRE(ic_pair_new(&pair, A, B, &err) == IC_OK, "pair: %s", err.message))
 *       return; */
#define REQUIRE(cond, ...)                                                                      \
    (harness_run++, (cond) ? 1                                                                  \
                           : (harness_fail_at(__FILE__, __LINE__), fprintf(stderr, __VA_ARGS__), \
                              fputc('\n', stderr), 0))

#define CHECK(cond, ...) ((void)REQUIRE(cond, __VA_ARGS__))

/* |got - want| <= tol * max(1, |want|) when `relative`, else <= tol; NaN fails. */
static inline int harness_close(double got, double want, double tol, int relative)
{
    if (isnan(got) || isnan(want))
        return 0;
    const double scale = relative ? fmax(1.0, fabs(want)) : 1.0;
    return fabs(got - want) <= tol * scale;
}

#define CHECK_CLOSE(got, want, tol, what)                                                       \
    CHECK(harness_close((got), (want), (tol), 1), "%s: got %.17g, want %.17g (tol %g)", (what), \
          (double)(got), (double)(want), (double)(tol))

#define CHECK_ABS(got, want, tol, what)                                                         \
    CHECK(harness_close((got), (want), (tol), 0), "%s: got %.17g, want %.17g (abs tol %g)",     \
          (what), (double)(got), (double)(want), (double)(tol))

/* The exit code of a test program: 1 on any failed check, and when no
 * check ran (a test that ran nothing has shown nothing). */
static inline int harness_finish(const char *name)
{
    printf("%s: %d passed, %d failed\n", name, harness_run - harness_failed, harness_failed);
    if (harness_run == 0)
        fprintf(stderr, "%s: FAIL: no check ran\n", name);
    return harness_failed || harness_run == 0 ? 1 : 0;
}

/* Deterministic generator (xorshift64*), seeded per test; the number of
 * random trials is multiplied by $IC_TEST_MULTIPLIER (default 1). */
typedef struct {
    unsigned long long s;
} harness_rng;

static inline double harness_uniform(harness_rng *r, double lo, double hi)
{
    r->s ^= r->s >> 12;
    r->s ^= r->s << 25;
    r->s ^= r->s >> 27;
    const unsigned long long x = r->s * 2685821657736338717ull;
    return lo + (hi - lo) * (double)(x >> 11) * (1.0 / 9007199254740992.0);
}

static inline int harness_multiplier(void)
{
    const char *m = getenv("IC_TEST_MULTIPLIER");
    int k = m ? atoi(m) : 1;
    return k > 0 ? k : 1;
}

#endif
