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

/* ---- Tolerance tiers (docs/testing.md, "Tolerance tiers") ----
 * The bounds the tests share, each with its unit and why it is enough. A
 * test whose comparison is of another kind keeps its own, named beside it
 * with its reason. Rounding tiers count DBL_EPSILON (GSL's TEST_TOL idea). */

/* Jets against 60-digit truth: units of (d + 1) DBL_EPSILON times the
 * largest truth coefficient up to degree d. The degree-d coefficient is a
 * sum of O(d) rounded products of lower ones (measured worst 2.29: x^5
 * after the three roundings of binary powering). */
#define TIER_JET_TRUTH 4.0

/* A few roundings of O(1) values, relative to their O(1) scale: the same
 * operations in another order, a formula against libm, the principal
 * curvatures (1/length) of closed-form surfaces. */
#define TIER_ROUNDING (8 * DBL_EPSILON)

/* Surface derivatives against sympy, and primitives against the same
 * surface written as formulas: relative to the largest derivative (or
 * coefficient) of the order; sums of O(2^d) rounded products to order 6
 * (measured worst 8.8 ulps). */
#define TIER_DERIVATIVE (32 * DBL_EPSILON)

/* Jet identities (sin^2 + cos^2 = 1, exp(log a) = a, a composition, a
 * reversion): relative to the largest coefficient of the intermediate. A
 * handful of recurrence passes, each within a few ulps per coefficient
 * (test_jet_truth measures 1.3 (d + 1) ulps); about 45 ulps, enough for
 * order 16 and a composition. */
#define TIER_IDENTITY 1e-14

/* The local apparatus against truth, relative to max(1, |c^(k)|), for
 * orders 1..4 and 5..8: the order-k system's conditioning grows like
 * 1/sin(angle)^k (measured 7.5e-14 and 1.5e-10). */
#define TIER_APPARATUS_LOW 1e-11
#define TIER_APPARATUS_HIGH 1e-8

/* Two exact methods (the papers' closed forms, the jet method) at well
 * transversal points (normals 0.3 rad or more apart) of O(1) surfaces,
 * relative (measured 2e-13). */
#define TIER_METHODS_AGREE 1e-12

/* Traced lengths, relative: the docs' promise for arc length
 * (docs/tracing.md; measured worst 9.8e-10, Viviani with the cylinder's
 * height u^3 + u and both domains shifted, at tol 1e-10). */
#define TIER_LENGTH 1e-9

/* Traced points against the closed form of their curve: equation residuals
 * or distances, relative to the curve's size. The corrector puts each point
 * on both surfaces to about 1e-14 (measured 1.3e-14); what is compared
 * along a curve also carries the arc length's error (z(s) on a helix) and
 * the scale of the curve (the Enneper double curves reach x ~ 60). */
#define TIER_ON_CURVE 1e-9

/* Located singular and contact points: a distance, in units of the
 * problem's size (about 1 in these tests). The locator's residual, 1e-12,
 * linear in the offset (measured 6.1e-17). */
#define TIER_LOCATED 1e-12

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
