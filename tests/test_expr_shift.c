/*
 * A formula moved to a new origin (expr/shift.c, ic_expr_shifted): g(y) =
 * f(a + y) - b in real arithmetic, and far from the origin g keeps the
 * digits f loses. Each case's truth is its formula written out here in
 * long double at the moved point, independent of the tape (the points are
 * chosen so that a + y is exact in long double, and the formulas'
 * constants are the doubles the tape holds).
 *
 * Tolerance: TIER_MOVED relative to max(1, |truth|): g runs on values of
 * size at most 1e3 here (constants too large for one double carried in
 * two), a few roundings of 1.1e-16 each, against a truth with 11 more bits; the saddle evaluated where it lies (f itself) is off
 * by about 1e-10 at 1e6 (the last place of 1e6), which the test also shows.
 */
#include <math.h>
#include <string.h>

#include "expr/expr_access.h"
#include "harness.h"
#include "intercurve.h"

#define TIER_MOVED 1e-14

/* the formulas' 0.05: the double nearest it, as the tape has it */
#define COEF ((long double)0.05)

typedef long double (*truth_fn)(const long double *x, int out);

typedef struct {
    const char *name;
    const char *formulas[3];
    int nout, nvars;
    double a[3], b[3];
    truth_fn truth; /* f - b at the user's point x = a + y */
    double tol;     /* relative to max(1, |truth|) */
} shift_case;

static long double saddle(const long double *x, int out)
{
    (void)out;
    const long double o = 1e6L;
    return x[2] - o - COEF * ((x[0] - o) * (x[0] - o) - (x[1] - o) * (x[1] - o));
}

static long double mixed(const long double *x, int out)
{
    (void)out;
    return sinl(x[0] - 1000.25L) * 3 / 4 + sqrtl(x[1] * x[1] + 1) - 2 * (x[2] + 7);
}

/* 0.1 and 1e6 + 0.5 - 0.1 are not doubles: those constants cannot combine
 * exactly, and g keeps the sum as f has it. */
static long double inexact(const long double *x, int out)
{
    (void)out;
    const long double tenth = 0.1; /* the double nearest 0.1, as the formula has it */
    return (x[0] - tenth) * (x[0] - tenth) / 1e6L + x[0] / 3 - 1e6L;
}

/* less b = (1e6, 0, 1e6), by hand: (1e6 + u) - 1e6 = u and so on */
/* x - 0.1 - 1e6 at x = 1e6 + 0.5 + y: (0.5 + y) - 0.1, by hand */
static long double uncombined(const long double *x, int out)
{
    (void)out;
    return (x[0] - 1e6L) - (long double)0.1;
}

/* x - 0.1 - 0.2 - 0.3 - 1e6 at x = 1e6 + 0.5 + y, by hand */
static long double tails(const long double *x, int out)
{
    (void)out;
    return (x[0] - 1e6L) - (long double)0.1 - (long double)0.2 - (long double)0.3;
}

static long double sheet(const long double *x, int out)
{
    if (out == 0)
        return x[0];
    return out == 1 ? x[1] - 2 : COEF * x[0] * x[1];
}

static long double negated(const long double *x, int out)
{
    (void)out;
    return -(x[0] - 1e6L) / 8 + (1e6L - x[1]) * 2 + 1e6L * x[2];
}

/* O + 0.37 u - 0.21 v + 0.05 less O, by hand (O + 0.05 is no double: its
 * two doubles carry it) */
static long double tail(const long double *x, int out)
{
    (void)out;
    return (long double)0.37 * x[0] - (long double)0.21 * x[1] + (long double)0.05;
}

static const shift_case CASES[] = {
    {"saddle at 1e6", {"z - 1e6 - 0.05*((x - 1e6)^2 - (y - 1e6)^2)"}, 1, 3, {1e6, 1e6, 1e6},
     {0}, saddle, TIER_MOVED},
    {"sin, sqrt, a quotient", {"sin(x - 1000.25)*3/4 + sqrt(y*y + 1) - 2*(z + 7)"}, 1, 3,
     {1000.25, 0, -7}, {0}, mixed, TIER_MOVED},
    {"constants that cannot combine", {"(x - 0.1)^2/1e6 + x/3 - 1e6"}, 1, 3,
     {1e6 + 0.5, 0, 0}, {0}, inexact, TIER_MOVED},
    /* 1e6 + 0.5 - 0.1 is no double, but it is two (its tail exact): less
     * 1e6 it is 0.4 and the tail, and g keeps every digit; its enclosure
     * holds the truth only if no constant was rounded */
    {"a constant that is no double", {"x - 0.1 - 1e6"}, 1, 3, {1e6 + 0.5, 0, 0}, {0},
     uncombined, TIER_MOVED},
    /* three such constants: their tails need not sum into one double, and
     * where they do not, g forms the sum at 1e6 as f does (2 ulps of 1e6,
     * 2.4e-10); its enclosure holds the truth only if no tail was rounded */
    {"tails that may not combine", {"x - 0.1 - 0.2 - 0.3 - 1e6"}, 1, 3, {1e6 + 0.5, 0, 0},
     {0}, tails, 2.4e-10},
    {"a parametric sheet", {"1e6 + u", "v - 2", "1e6 + 0.05*u*v"}, 3, 2, {3, 4}, {1e6, 0, 1e6},
     sheet, TIER_MOVED},
    {"a small constant after a large one", {"1e6 + 0.37*u - 0.21*v + 0.05"}, 1, 2, {0, 0},
     {1e6}, tail, TIER_MOVED},
    {"negations, products by constants", {"-(x - 1e6)/8 + (1e6 - y)*2 + 1e6*z"}, 1, 3,
     {1e6, 1e6, 0}, {0}, negated, TIER_MOVED},
};
#define NCASES (int)(sizeof CASES / sizeof CASES[0])

/* dyadic, of few bits: a + y is exact in double and in long double */
static const double POINTS[][3] = {{0x5p-14, 0x3p-13, 0x1p-28},
                                   {-0.75, 0.5, 0.125},
                                   {0x1p-23, -0x3p-23, 0},
                                   {0.3125, 0.6875, -0.1875}};
#define NPOINTS (int)(sizeof POINTS / sizeof POINTS[0])

/* g's interval enclosure at each point holds the truth: no constant of
 * g was rounded (a rounded one moves g off f by up to its rounding,
 * outside the outward-rounded enclosure). */
static void check_enclosure(const shift_case *k, const ic_expr *g)
{
    ic_interval *work = malloc((ic_expr_interval_work_len(g) + 1) * sizeof *work);
    for (int p = 0; work && p < NPOINTS; p++) {
        ic_interval y[3], out[3];
        long double x[3];
        for (int i = 0; i < k->nvars; i++) {
            y[i] = (ic_interval){POINTS[p][i], POINTS[p][i]};
            x[i] = (long double)k->a[i] + POINTS[p][i];
        }
        ic_expr_eval_interval(g, out, y, work);
        for (int o = 0; o < k->nout; o++) {
            const long double want = k->truth(x, o);
            CHECK(out[o].lo <= want && want <= out[o].hi,
                  "%s, point %d, output %d: [%.17g, %.17g] misses the truth %.17Lg", k->name, p,
                  o, out[o].lo, out[o].hi, want);
        }
    }
    free(work);
}

static void check_case(const shift_case *k)
{
    static const char *const XYZ[] = {"x", "y", "z"}, *const UV[] = {"u", "v"};
    ic_expr *f = NULL, *g = NULL;
    ic_error err;
    if (!REQUIRE(ic_expr_compile(&f, k->formulas, k->nout, k->nvars == 3 ? XYZ : UV, k->nvars,
                                 NULL, 0, NULL, &err) == IC_OK,
                 "%s: %s", k->name, err.message))
        return;
    if (REQUIRE(ic_expr_shifted(&g, f, k->a, k->b, &err) == IC_OK, "%s: %s", k->name,
                err.message)) {
        double *work = malloc(ic_expr_work_len(g) * sizeof *work);
        for (int p = 0; work && p < NPOINTS; p++) {
            double got[3];
            long double x[3];
            for (int i = 0; i < k->nvars; i++)
                x[i] = (long double)k->a[i] + POINTS[p][i];
            if (!REQUIRE(ic_expr_eval(g, got, POINTS[p], work, &err) == IC_OK, "%s: eval: %s",
                         k->name, err.message))
                continue;
            for (int o = 0; o < k->nout; o++) {
                const long double want = k->truth(x, o);
                CHECK(fabsl(got[o] - want) <= k->tol * fmaxl(1, fabsl(want)),
                      "%s, point %d, output %d: %.17g, truth %.17Lg", k->name, p, o, got[o],
                      want);
            }
        }
        free(work);
        check_enclosure(k, g);
    }
    ic_expr_free(g);
    ic_expr_free(f);
}

/* The reason for the move: the sheet's z = 1e6 + 0.05 u v where it lies
 * rounds to the last place of 1e6 (1.2e-10), which g keeps. */
static void sheet_where_it_lies(void)
{
    const shift_case *k = &CASES[5]; /* the parametric sheet */
    static const char *const UV[] = {"u", "v"};
    ic_expr *f = NULL;
    ic_error err;
    if (!REQUIRE(ic_expr_compile(&f, k->formulas, 3, UV, 2, NULL, 0, NULL, &err) == IC_OK, "%s",
                 err.message))
        return;
    double *work = malloc(ic_expr_work_len(f) * sizeof *work);
    double worst = 0;
    for (int p = 0; work && p < NPOINTS; p++) {
        const double at[2] = {k->a[0] + POINTS[p][0], k->a[1] + POINTS[p][1]};
        const long double x[2] = {at[0], at[1]};
        double got[3];
        if (REQUIRE(ic_expr_eval(f, got, at, work, &err) == IC_OK, "%s", err.message))
            worst = fmax(worst, (double)fabsl((got[2] - k->b[2]) - sheet(x, 2)));
    }
    CHECK(worst > 1e-12,
          "unmoved sheet at 1e6 unexpectedly exact (worst %.3g): the test no longer shows why "
          "the move is needed",
          worst);
    free(work);
    ic_expr_free(f);
}

int main(void)
{
    for (int i = 0; i < NCASES; i++)
        check_case(&CASES[i]);
    sheet_where_it_lies();
    return harness_finish("expr_shift");
}
