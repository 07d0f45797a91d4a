/* Jet identities, composition, reversion and domain errors. */
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "intercurve/jet.h"
#include "jet/jet_chain.h"

static double max_abs_diff(const double *a, const double *b, int n)
{
    double m = 0.0;
    for (int i = 0; i < n; i++)
        m = fmax(m, fabs(a[i] - b[i]));
    return m;
}

static double mag(const double *a, int n)
{
    double m = 1.0;
    for (int i = 0; i < n; i++)
        m = fmax(m, fabs(a[i]));
    return m;
}

/* A jet with "high-entropy" coefficients of degree <= 3 about a0. */
static void sample_jet(double *a, double a0, const ic_jet_space *sp, harness_rng *rng)
{
    ic_jet_zero(a, sp);
    a[0] = a0;
    for (int i = 1; i < ic_jet_degree_start(sp, 4); i++)
        a[i] = harness_uniform(rng, -0.4, 0.4);
}

static void test_space_layout(void)
{
    ic_jet_space *sp = NULL;
    if (!REQUIRE(ic_jet_space_new(&sp, 3, 6, NULL) == IC_OK, "space 3 vars order 6"))
        return;
    CHECK(ic_jet_space_len(sp) == 84, "C(9,3) = 84 coefficients, got %d", ic_jet_space_len(sp));
    for (int i = 0; i < ic_jet_space_len(sp); i++) {
        int alpha[3];
        ic_jet_exponents(sp, i, alpha);
        CHECK(ic_jet_index(sp, alpha) == i, "index/exponents round trip at %d", i);
    }
    int x2y[3] = {2, 1, 0}, too_high[3] = {4, 3, 0}, negative[3] = {-1, 0, 0};
    CHECK(ic_jet_index(sp, too_high) == -1, "degree above K has no index");
    CHECK(ic_jet_index(sp, negative) == -1, "negative exponent has no index");
    CHECK(ic_jet_factorial(sp, ic_jet_index(sp, x2y)) == 2.0, "2! 1! 0! = 2");
    /* order: 1, x, y, z, x^2, xy, xz, y^2, ... */
    int xy[3] = {1, 1, 0};
    CHECK(ic_jet_index(sp, xy) == 5, "xy is the 6th monomial");
    ic_jet_space_free(sp);

    ic_error err;
    CHECK(ic_jet_space_new(&sp, 0, 4, &err) == IC_ERR_INVALID && sp == NULL, "0 variables");
    CHECK(ic_jet_space_new(&sp, 5, 4, &err) == IC_ERR_INVALID, "5 variables");
    CHECK(ic_jet_space_new(&sp, 2, -1, &err) == IC_ERR_INVALID, "negative order");
    CHECK(ic_jet_space_new(&sp, 2, IC_JET_MAX_ORDER + 1, &err) == IC_ERR_INVALID, "order > max");
    CHECK(strstr(err.message, "order") != NULL, "message names the order: %s", err.message);
    CHECK(ic_jet_space_new(&sp, 4, 16, NULL) == IC_OK, "4 variables, order 16");
    CHECK(ic_jet_space_len(sp) == 4845, "C(20,4) = 4845");
    ic_jet_space_free(sp);
    ic_jet_space_free(NULL);
}

static void test_identities(int m, int K, harness_rng *rng)
{
    ic_jet_space *sp = NULL;
    if (!REQUIRE(ic_jet_space_new(&sp, m, K, NULL) == IC_OK, "jet space of %d variables, order %d",
                 m, K))
        return;
    const int n = ic_jet_space_len(sp);
    double *a = calloc((size_t)n, sizeof *a), *s = calloc((size_t)n, sizeof *s);
    double *c = calloc((size_t)n, sizeof *c), *t = calloc((size_t)n, sizeof *t);
    double *u = calloc((size_t)n, sizeof *u), *one = calloc((size_t)n, sizeof *one);
    double *scratch = malloc(ic_jet_scratch_len(sp) * sizeof *scratch);
    if (!REQUIRE(a && s && c && t && u && one && scratch, "no memory for jets of %d coefficients",
                 n)) {
        free(a), free(s), free(c), free(t), free(u), free(one), free(scratch);
        ic_jet_space_free(sp);
        return;
    }
    ic_jet_set_const(one, 1.0, sp);
    for (int trial = 0; trial < 5 * harness_multiplier(); trial++) {
        sample_jet(a, harness_uniform(rng, 0.2, 1.4), sp, rng);
        ic_jet_sin_cos(s, c, a, sp); /* sin^2 + cos^2 = 1 */
        ic_jet_mul(t, s, s, sp);
        ic_jet_mul(u, c, c, sp);
        ic_jet_add(t, t, u, sp);
        CHECK(max_abs_diff(t, one, n) <= TIER_IDENTITY, "sin^2+cos^2 = 1 (%d vars, order %d): %g",
              m, K, max_abs_diff(t, one, n));
        CHECK(ic_jet_log(t, a, sp, NULL) == IC_OK, "log"); /* exp(log a) = a */
        ic_jet_exp(u, t, sp);
        /* relative to the largest coefficient of the intermediate log a */
        CHECK(max_abs_diff(u, a, n) <= TIER_IDENTITY * mag(t, n), "exp(log a) = a: %g",
              max_abs_diff(u, a, n) / mag(t, n));
        ic_jet_sinh_cosh(s, c, a, sp); /* cosh^2 - sinh^2 = 1 */
        ic_jet_mul(t, c, c, sp);
        ic_jet_mul(u, s, s, sp);
        ic_jet_sub(t, t, u, sp);
        CHECK(max_abs_diff(t, one, n) <= 8 * TIER_IDENTITY, "cosh^2-sinh^2 = 1: %g",
              max_abs_diff(t, one, n)); /* cosh^2 ~ 4.6: 8x the O(1) tier */
        CHECK(ic_jet_sqrt(t, a, sp, NULL) == IC_OK, "sqrt"); /* sqrt(a)^2 = a */
        ic_jet_mul(u, t, t, sp);
        CHECK(max_abs_diff(u, a, n) <= TIER_IDENTITY * mag(t, n), "sqrt(a)^2 = a: %g",
              max_abs_diff(u, a, n) / mag(t, n));
        ic_jet_scale(t, a, 0.5, sp); /* tan(atan(a/2)) = a/2; asin(sin(a/2)) */
        ic_jet_atan(u, t, sp, scratch);
        CHECK(ic_jet_tan(s, u, sp, scratch, NULL) == IC_OK, "tan");
        CHECK(max_abs_diff(s, t, n) <= TIER_IDENTITY, "tan(atan x) = x: %g", max_abs_diff(s, t, n));
        ic_jet_sin(u, t, sp, scratch);
        CHECK(ic_jet_asin(s, u, sp, scratch, NULL) == IC_OK, "asin");
        CHECK(max_abs_diff(s, t, n) <= TIER_IDENTITY, "asin(sin x) = x: %g", max_abs_diff(s, t, n));
        /* a^2.5 / a^1.5 = a on a base with a(0) in [0.9, 2.1]: the pow
         * recurrence divides by a(0) at every degree, so a base near 0 would
         * measure conditioning, not correctness */
        double *base = c;
        ic_jet_add_const(base, a, 0.7, sp);
        CHECK(ic_jet_pow_real(u, base, 2.5, sp, scratch, NULL) == IC_OK, "pow 2.5");
        CHECK(ic_jet_pow_real(s, base, 1.5, sp, scratch, NULL) == IC_OK, "pow 1.5");
        CHECK(ic_jet_div(t, u, s, sp, NULL) == IC_OK, "div");
        const double big = fmax(mag(u, n), mag(s, n));
        CHECK(max_abs_diff(t, base, n) <= 4 * TIER_IDENTITY * big, "a^2.5/a^1.5 = a: %g",
              max_abs_diff(t, base, n) / big); /* three recurrences in a row */
    }
    free(a), free(s), free(c), free(t), free(u), free(one), free(scratch);
    ic_jet_space_free(sp);
}

/* Composition is the chain rule: the Taylor polynomial of F at g(0)
 * composed with g equals F evaluated directly on g. */
static void test_compose(harness_rng *rng)
{
    ic_jet_space *s1 = NULL, *s2 = NULL, *s3 = NULL, *p2 = NULL, *p3 = NULL;
    enum { K = 12 };
    if (!REQUIRE(ic_jet_space_new(&s1, 1, K, NULL) == IC_OK &&
                     ic_jet_space_new(&s2, 2, K, NULL) == IC_OK &&
                     ic_jet_space_new(&s3, 3, 7, NULL) == IC_OK &&
                     ic_jet_space_new(&p2, 2, K, NULL) == IC_OK &&
                     ic_jet_space_new(&p3, 3, K, NULL) == IC_OK,
                 "the jet spaces of the composition test")) {
        ic_jet_space_free(s1), ic_jet_space_free(s2), ic_jet_space_free(s3);
        ic_jet_space_free(p2), ic_jet_space_free(p3);
        return;
    }
    double scratch[(K + 20) * 455];
    double g[3][455], P[455], x[3][455], t1[455], t2[455], direct[455], composed[455];
    for (int out = 0; out < 3; out++) {
        const ic_jet_space *sp = out == 0 ? s1 : out == 1 ? s2 : s3;
        const int n = ic_jet_space_len(sp);
        /* F(x, y) = exp(x) cos(y) - x y^3 over two variables */
        for (int i = 0; i < 2; i++)
            sample_jet(g[i], harness_uniform(rng, -0.8, 0.8), sp, rng);
        for (int i = 0; i < 2; i++)
            ic_jet_set_var(x[i], g[i][0], i, p2);
        ic_jet_exp(t1, x[0], p2);
        ic_jet_cos(t2, x[1], p2, scratch);
        ic_jet_mul(P, t1, t2, p2);
        ic_jet_mul(t1, x[1], x[1], p2);
        ic_jet_mul(t2, t1, x[1], p2);
        ic_jet_mul(t1, t2, x[0], p2);
        ic_jet_sub(P, P, t1, p2);
        const double *gs[3] = {g[0], g[1], g[2]};
        ic_jet_compose(composed, P, p2, gs, sp, scratch);
        ic_jet_exp(t1, g[0], sp);
        ic_jet_cos(t2, g[1], sp, scratch);
        ic_jet_mul(direct, t1, t2, sp);
        ic_jet_mul(t1, g[1], g[1], sp);
        ic_jet_mul(t2, t1, g[1], sp);
        ic_jet_mul(t1, t2, g[0], sp);
        ic_jet_sub(direct, direct, t1, sp);
        CHECK(max_abs_diff(direct, composed, n) <= TIER_IDENTITY,
              "compose 2-var polynomial into %d vars: %g", out + 1,
              max_abs_diff(direct, composed, n));
        /* F(x, y, z) = sin(x + 2y) / (2 + z^2) over three variables */
        sample_jet(g[2], harness_uniform(rng, -0.8, 0.8), sp, rng);
        for (int i = 0; i < 3; i++)
            ic_jet_set_var(x[i], g[i][0], i, p3);
        ic_jet_scale(t1, x[1], 2.0, p3);
        ic_jet_add(t1, t1, x[0], p3);
        ic_jet_sin(t2, t1, p3, scratch);
        ic_jet_mul(t1, x[2], x[2], p3);
        t1[0] += 2.0;
        CHECK(ic_jet_div(P, t2, t1, p3, NULL) == IC_OK, "div");
        ic_jet_compose(composed, P, p3, gs, sp, scratch);
        ic_jet_scale(t1, g[1], 2.0, sp);
        ic_jet_add(t1, t1, g[0], sp);
        ic_jet_sin(t2, t1, sp, scratch);
        ic_jet_mul(t1, g[2], g[2], sp);
        t1[0] += 2.0;
        CHECK(ic_jet_div(direct, t2, t1, sp, NULL) == IC_OK, "div");
        CHECK(max_abs_diff(direct, composed, n) <= TIER_IDENTITY,
              "compose 3-var function into %d vars: %g", out + 1,
              max_abs_diff(direct, composed, n));
    }
    ic_jet_space_free(s1), ic_jet_space_free(s2), ic_jet_space_free(s3);
    ic_jet_space_free(p2), ic_jet_space_free(p3);
}

static void test_reversion(harness_rng *rng)
{
    enum { K = 16 };
    ic_jet_space *s1 = NULL, *s2 = NULL;
    if (!REQUIRE(ic_jet_space_new(&s1, 1, K, NULL) == IC_OK &&
                     ic_jet_space_new(&s2, 2, 10, NULL) == IC_OK,
                 "the jet spaces of the reversion test")) {
        ic_jet_space_free(s1);
        ic_jet_space_free(s2);
        return;
    }
    double scratch[(K + 20) * 153];
    double f[17], g[17], h[17], y[17];
    /* f(x) = sin(x) + x^2/3: revert twice gives f back; f(g(y)) = y */
    ic_jet_set_var(y, 0.0, 0, s1);
    ic_jet_sin(f, y, s1, scratch);
    f[2] += 1.0 / 3.0;
    CHECK(ic_jet_revert(g, f, s1, scratch, NULL) == IC_OK, "revert");
    CHECK(ic_jet_revert(h, g, s1, scratch, NULL) == IC_OK, "revert back");
    CHECK(max_abs_diff(h, f, 17) <= 1e-12, "revert(revert(f)) = f: %g", max_abs_diff(h, f, 17));
    /* 1e-12: coefficients of the reversion grow like 2^k here (about 1e4
     * at k = 16), and the error is relative to them */
    const double *gs[1] = {g};
    ic_jet_compose(h, f, s1, gs, s1, scratch);
    h[0] = 0.0;
    CHECK(max_abs_diff(h, y, 17) <= 1e-12, "f(g(y)) = y: %g", max_abs_diff(h, y, 17));
    /* asin is the reversion of sin: compare with the direct series */
    ic_jet_sin(f, y, s1, scratch);
    CHECK(ic_jet_revert(g, f, s1, scratch, NULL) == IC_OK, "revert sin");
    CHECK(ic_jet_asin(h, y, s1, scratch, NULL) == IC_OK, "asin");
    CHECK(max_abs_diff(h, g, 17) <= TIER_IDENTITY, "revert(sin) = asin: %g",
          max_abs_diff(h, g, 17));
    double zero[17] = {0};
    ic_error err;
    CHECK(ic_jet_revert(g, zero, s1, scratch, &err) == IC_ERR_UNABLE, "f'(0) = 0 is refused");

    /* bivariate: F(x, y) = (x + 0.3 y + sin(x y) , -0.2 x + y + x^2 - y^3 / 2) */
    const int n = ic_jet_space_len(s2);
    double X[66], Y[66], F0[66], F1[66], G0[66], G1[66], H0[66], H1[66], t[66];
    ic_jet_set_var(X, 0.0, 0, s2);
    ic_jet_set_var(Y, 0.0, 1, s2);
    ic_jet_mul(t, X, Y, s2);
    ic_jet_sin(F0, t, s2, scratch);
    for (int i = 0; i < n; i++)
        F0[i] += X[i] + 0.3 * Y[i];
    ic_jet_mul(F1, X, X, s2);
    ic_jet_mul(t, Y, Y, s2);
    ic_jet_mul(H0, t, Y, s2);
    for (int i = 0; i < n; i++)
        F1[i] += -0.2 * X[i] + Y[i] - 0.5 * H0[i];
    double *G[2] = {G0, G1}, *H[2] = {H0, H1};
    const double *F[2] = {F0, F1}, *Gc[2] = {G0, G1};
    CHECK(ic_jet_revert2(G, F, s2, scratch, NULL) == IC_OK, "revert2");
    CHECK(ic_jet_revert2(H, Gc, s2, scratch, NULL) == IC_OK, "revert2 back");
    /* relative to the coefficients of the inverse map G (up to ~1e3 at degree 10) */
    const double gbig = fmax(mag(G0, n), mag(G1, n));
    CHECK(max_abs_diff(H0, F0, n) <= TIER_IDENTITY * gbig &&
              max_abs_diff(H1, F1, n) <= TIER_IDENTITY * gbig,
          "revert2(revert2(F)) = F: %g %g (scale %g)", max_abs_diff(H0, F0, n),
          max_abs_diff(H1, F1, n), gbig);
    ic_jet_compose(H0, F0, s2, Gc, s2, scratch);
    ic_jet_compose(H1, F1, s2, Gc, s2, scratch);
    CHECK(max_abs_diff(H0, X, n) <= TIER_IDENTITY * gbig &&
              max_abs_diff(H1, Y, n) <= TIER_IDENTITY * gbig,
          "F(G(y)) = y: %g %g (scale %g)", max_abs_diff(H0, X, n), max_abs_diff(H1, Y, n), gbig);
    /* a singular linear part is refused */
    ic_jet_mul(F1, X, X, s2);
    for (int i = 0; i < n; i++)
        F1[i] += 2.0 * X[i] + 0.6 * Y[i]; /* rows (1, 0.3) and (2, 0.6) */
    CHECK(ic_jet_revert2(G, F, s2, scratch, &err) == IC_ERR_UNABLE, "singular Jacobian refused");
    CHECK(strstr(err.message, "singular") != NULL, "message: %s", err.message);
    (void)rng;
    ic_jet_space_free(s1);
    ic_jet_space_free(s2);
}

static void test_domain_errors(void)
{
    ic_jet_space *sp = NULL;
    if (!REQUIRE(ic_jet_space_new(&sp, 2, 3, NULL) == IC_OK, "jet space of 2 variables, order 3"))
        return;
    double a[10], b[10], r[10], scratch[40 * 10];
    ic_error err;
#define EXPECT_DOMAIN(call, what)                                                               \
    do {                                                                                        \
        ic_error_clear(&err);                                                                   \
        CHECK((call) == IC_ERR_DOMAIN && err.code == IC_ERR_DOMAIN && err.message[0],           \
              "%s is a domain error", what);                                                    \
    } while (0)
    ic_jet_set_var(a, 0.0, 0, sp);
    EXPECT_DOMAIN(ic_jet_log(r, a, sp, &err), "log at 0");
    EXPECT_DOMAIN(ic_jet_sqrt(r, a, sp, &err), "sqrt at 0");
    EXPECT_DOMAIN(ic_jet_div(r, b, a, sp, &err), "division by a jet with value 0");
    EXPECT_DOMAIN(ic_jet_pow_int(r, a, -2, sp, scratch, &err), "0^-2");
    EXPECT_DOMAIN(ic_jet_pow_real(r, a, 0.5, sp, scratch, &err), "0^0.5");
    EXPECT_DOMAIN(ic_jet_abs(r, a, sp, &err), "abs at 0");
    ic_jet_set_var(b, 0.0, 1, sp);
    EXPECT_DOMAIN(ic_jet_atan2(r, a, b, sp, scratch, &err), "atan2(0, 0)");
    ic_jet_set_var(a, -1.5, 0, sp);
    EXPECT_DOMAIN(ic_jet_log(r, a, sp, &err), "log of -1.5");
    EXPECT_DOMAIN(ic_jet_sqrt(r, a, sp, &err), "sqrt of -1.5");
    EXPECT_DOMAIN(ic_jet_pow_real(r, a, 1.5, sp, scratch, &err), "(-1.5)^1.5");
    EXPECT_DOMAIN(ic_jet_asin(r, a, sp, scratch, &err), "asin(-1.5)");
    ic_jet_set_var(a, 1.0, 0, sp);
    EXPECT_DOMAIN(ic_jet_acos(r, a, sp, scratch, &err), "acos at 1 (infinite derivative)");
    /* allowed: integer powers of 0, negative base to an integer power */
    ic_jet_set_var(a, 0.0, 0, sp);
    CHECK(ic_jet_pow_int(r, a, 3, sp, scratch, NULL) == IC_OK && r[ic_jet_degree_start(sp, 3)] == 1.0,
          "x^3 at 0 is the monomial x^3");
    ic_jet_set_var(a, -2.0, 0, sp);
    CHECK(ic_jet_pow_real(r, a, 3.0, sp, scratch, NULL) == IC_OK && r[0] == -8.0 && r[1] == 12.0,
          "(-2 + x)^3: -8 + 12x + ...");
    ic_jet_space_free(sp);
}

/* The composition one degree at a time (jet/jet_chain.h) against
 * ic_jet_compose: P in p variables (dense, or with its terms of degree 2
 * and 5 only, so the chain keeps some power products just to build
 * others), deltas in m variables. Revealed: the deltas' degree-k parts are
 * set only after step k, as the series solvers do; the step's part then
 * lacks exactly P's linear terms on them. Linear: the deltas of degree 1
 * only, declared so (ic_jet_chain_set_delta_degree), as a rotation is. */
static void check_chain(int p, int m, int K, int sparse, int revealed, int linear,
                        harness_rng *rng)
{
    ic_jet_space *sp_p = NULL, *sp = NULL;
    if (!REQUIRE(ic_jet_space_new(&sp_p, p, K, NULL) == IC_OK &&
                     ic_jet_space_new(&sp, m, K, NULL) == IC_OK,
                 "chain spaces"))
        goto done;
    const int np = ic_jet_space_len(sp_p), n = ic_jet_space_len(sp);
    double *P = malloc((size_t)np * sizeof *P), *want = malloc((size_t)n * sizeof *want);
    double *got = calloc((size_t)n, sizeof *got), *full = malloc(4 * (size_t)n * sizeof *full);
    double *live = calloc(4 * (size_t)n, sizeof *live);
    double *work = malloc(ic_jet_chain_len(sp_p, K, sp) * sizeof *work);
    double *scratch = malloc(ic_jet_scratch_len(sp) * sizeof *scratch);
    if (!REQUIRE(P && want && got && full && live && work && scratch, "chain memory"))
        goto free_all;
    for (int i = 0; i < np; i++) {
        int alpha[IC_JET_MAX_VARS], d = 0;
        ic_jet_exponents(sp_p, i, alpha);
        for (int v = 0; v < p; v++)
            d += alpha[v];
        P[i] = sparse && d != 2 && d != 5 ? 0.0 : harness_uniform(rng, -1, 1);
    }
    const double *g[IC_JET_MAX_VARS], *lv[IC_JET_MAX_VARS];
    for (int v = 0; v < p; v++) {
        double *f = full + (size_t)v * n;
        for (int i = 0; i < n; i++)
            f[i] = linear && i >= ic_jet_degree_start(sp, 2) ? 0.0 : harness_uniform(rng, -0.7, 0.7);
        g[v] = f;
        lv[v] = live + (size_t)v * n;
        if (!revealed)
            memcpy(live + (size_t)v * n, f, (size_t)n * sizeof *f);
    }
    ic_jet_compose(want, P, sp_p, g, sp, scratch);
    const double *Ps[1] = {P};
    ic_jet_chain ch;
    ic_jet_chain_init(&ch, sp_p, Ps, 1, lv, sp, work);
    if (linear)
        ic_jet_chain_set_delta_degree(&ch, 1);
    got[0] = P[0];
    for (int k = 1; k <= K; k++) {
        ic_jet_chain_extend(&ch, k);
        ic_jet_chain_part(&ch, got, P, k);
        for (int i = ic_jet_degree_start(sp, k); revealed && i < ic_jet_degree_start(sp, k + 1); i++)
            for (int v = 0; v < p; v++) {
                live[(size_t)v * n + i] = g[v][i];
                got[i] += P[1 + v] * g[v][i];
            }
    }
    CHECK(max_abs_diff(got, want, n) <= 1e-13 * mag(want, n),
          "chain = compose (p %d, m %d, K %d, sparse %d, revealed %d, linear %d): %g", p, m, K,
          sparse, revealed, linear, max_abs_diff(got, want, n));
free_all:
    free(P), free(want), free(got), free(full), free(live), free(work), free(scratch);
done:
    ic_jet_space_free(sp_p);
    ic_jet_space_free(sp);
}

static void test_chain(harness_rng *rng)
{
    const int pm[5][2] = {{1, 1}, {2, 1}, {3, 1}, {2, 2}, {3, 2}};
    for (int c = 0; c < 5; c++)
        for (int sparse = 0; sparse < 2; sparse++)
            for (int revealed = 0; revealed < 2; revealed++)
                check_chain(pm[c][0], pm[c][1], pm[c][1] == 1 ? 12 : 7, sparse, revealed, 0, rng);
    check_chain(2, 2, 9, 0, 0, 1, rng);
    check_chain(3, 2, 7, 1, 0, 1, rng);
}

int main(void)
{
    harness_rng rng = {0x9e3779b97f4a7c15ull};
    test_space_layout();
    test_identities(1, 16, &rng);
    test_identities(2, 16, &rng);
    test_identities(3, 10, &rng);
    test_identities(4, 6, &rng);
    test_compose(&rng);
    test_reversion(&rng);
    test_chain(&rng);
    test_domain_errors();
    return harness_finish("test_jet");
}
