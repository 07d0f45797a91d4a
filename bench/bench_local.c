/* Benchmarks of the local apparatus at a transversal point (make bench):
 * ns per point for each pairing at K = 4, 8 and 16: the whole apparatus by
 * the jet method, the jet method alone (the derivatives c^(2..K), the
 * sheets' geometry given), and the two surfaces' own order-K derivative
 * tensors at the same point, with the ratio of the last two (the jet
 * method's overhead over evaluating the surfaces; docs/performance.md);
 * the closed forms at K = 3 beside. The point is located once beforehand.
 *
 * bench_local --instructions, run under callgrind, counts instructions
 * instead (a shared machine's timings wander): for each pairing and K, the
 * jet method and the surfaces each called 10 times after a warm-up call,
 * between CALLGRIND_ZERO_STATS and CALLGRIND_DUMP_STATS_AT("jet|surfaces
 * <pairing> K=<K>"); each dump's totals divided by 10 are the instructions
 * per call (docs/performance.md, "Jets"). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "bench_timer.h"
#include "intercurve.h"
#include "local/local_internal.h"

#if defined(__has_include)
#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#define BENCH_CALLGRIND 1
#endif
#endif

typedef struct {
    ic_pair *pair;
    ic_local_point pt;
    int order;
    ic_method method;
    ic_local_options opt;
    ic_jet_space *sp[2];
    ic_sheet sh[2]; /* the jet method alone starts from these */
} job;

static int run_jet_method(void *ctx)
{
    job *j = ctx;
    ic_branch br;
    return ic_jet_method(j->pair, &br, j->sh, j->order, NULL);
}

static int run_apparatus(void *ctx)
{
    job *j = ctx;
    ic_local_result res;
    return ic_local_apparatus(j->pair, &res, &j->pt, j->order, j->method, &j->opt, NULL);
}

static int run_surfaces(void *ctx)
{
    job *j = ctx;
    double out[3 * 969]; /* 3 jets of 3 variables, order 16 */
    for (int s = 0; s < 2; s++) {
        ic_surface *srf = ic_pair_surface(j->pair, s);
        const int par = ic_surface_get_kind(srf) == IC_PARAMETRIC;
        if (ic_surface_taylor(srf, out, par ? j->pt.params[s] : j->pt.xyz, j->sp[!par], NULL))
            return 1;
    }
    return 0;
}

/* --instructions: fn's calls counted apart (10 after a warm-up, labelled);
 * 0 on success. */
static int count_instructions(int (*fn)(void *ctx), void *ctx, const char *what, const char *name,
                              int K)
{
#ifdef BENCH_CALLGRIND
    char label[96];
    snprintf(label, sizeof label, "%s %s K=%d", what, name, K);
    int bad = fn(ctx); /* the warm-up */
    CALLGRIND_ZERO_STATS;
    for (int r = 0; r < 10; r++)
        bad |= fn(ctx);
    CALLGRIND_DUMP_STATS_AT(label);
    printf("%s\n", label);
    return bad;
#else
    (void)fn, (void)ctx, (void)what, (void)name, (void)K;
    fprintf(stderr, "bench_local: built without valgrind/callgrind.h, no --instructions\n");
    return 1;
#endif
}

typedef struct {
    const char *name;
    ic_surface *A, *B; /* B NULL: self-intersection */
    double at[3];
} bench_case;

/* The surfaces made, freed together at the end. */
typedef struct {
    ic_surface *s[24];
    int n;
} surface_pool;

/* A primitive added to the pool, or NULL. A function, not a macro: two calls
 * in one initializer list are then each done whole, in either order. */
static ic_surface *prim(surface_pool *pool, const ic_primitive *p, ic_surface_kind form)
{
    ic_surface *srf = NULL;
    if (pool->n == (int)(sizeof pool->s / sizeof pool->s[0]) ||
        ic_surface_new_primitive(&srf, p, form, NULL) != IC_OK)
        return NULL;
    pool->s[pool->n++] = srf;
    return srf;
}

/* A rational biquadratic-by-linear NURBS patch (weights 0.8 in the middle
 * row), added to the pool, or NULL. */
static ic_surface *rational_patch(surface_pool *pool)
{
    static const double ku[] = {0, 0, 0, 0.5, 1, 1, 1}, kv[] = {0, 0, 1, 1};
    double pts[4][2][3], w[4][2];
    const double x[4] = {-1.5, -0.4, 0.6, 1.5}, z[4] = {0.2, 0.9, 0.1, 0.6};
    for (int i = 0; i < 4; i++)
        for (int k = 0; k < 2; k++) {
            pts[i][k][0] = x[i];
            pts[i][k][1] = k ? 2.5 : -2.5;
            pts[i][k][2] = z[i];
            w[i][k] = i == 1 || i == 2 ? 0.8 : 1.0;
        }
    const ic_nurbs nb = {.degree = {2, 1}, .count = {4, 2}, .knots = {ku, kv},
                         .points = &pts[0][0][0], .weights = &w[0][0]};
    ic_surface *srf = NULL;
    if (pool->n == (int)(sizeof pool->s / sizeof pool->s[0]) ||
        ic_surface_new_nurbs(&srf, &nb, NULL) != IC_OK)
        return NULL;
    pool->s[pool->n++] = srf;
    return srf;
}

int main(int argc, char **argv)
{
    const int instructions = argc > 1 && strcmp(argv[1], "--instructions") == 0;
    int failed = 0; /* --instructions: a count that could not be made */
    ic_primitive cyl = {.kind = IC_PRIM_CYLINDER, .center = {1, 0, 0}, .radius = 1};
    ic_primitive sph = {.kind = IC_PRIM_SPHERE, .radius = 2};
    ic_primitive torus = {.kind = IC_PRIM_TORUS, .major_radius = 2, .radius = 0.5};
    ic_primitive ell1 = {.kind = IC_PRIM_ELLIPSOID, .axes = {0.6, 0.8, 1}};
    ic_primitive ell2 = {.kind = IC_PRIM_ELLIPSOID, .axes = {0.45, 0.8, 1.25}};
    ic_primitive plane = {.kind = IC_PRIM_PLANE, .center = {0, 0, 0.3}, .normal = {0.2, 0, 1}};
    const char *enneper[3] = {"u - u^3/3 + u*v^2", "-v - u^2*v + v^3/3", "u^2 - v^2"};
    const double th = 0.7;
    bench_case cases[9];
    int n = 0;
    surface_pool pool = {.n = 0};
#define PRIM(p, form) prim(&pool, &(p), (form))
    cases[n++] = (bench_case){"Viviani param/param (primitives)", PRIM(cyl, IC_PARAMETRIC),
                              PRIM(sph, IC_PARAMETRIC),
                              {1 + cos(th), sin(th), 2 * sin(th / 2)}};
    cases[n++] = (bench_case){"Viviani param/implicit", PRIM(cyl, IC_PARAMETRIC),
                              PRIM(sph, IC_IMPLICIT), {1 + cos(th), sin(th), 2 * sin(th / 2)}};
    cases[n++] = (bench_case){"Viviani implicit/implicit", PRIM(cyl, IC_IMPLICIT),
                              PRIM(sph, IC_IMPLICIT), {1 + cos(th), sin(th), 2 * sin(th / 2)}};
    cases[n++] = (bench_case){"ellipsoids implicit/implicit", PRIM(ell1, IC_IMPLICIT),
                              PRIM(ell2, IC_IMPLICIT),
                              {27.0 / 160, 2 * sqrt(3.0) / 5, 5 * sqrt(7.0) / 32}};
    /* torus and plane z = 0.3 - 0.2 x: a point on both */
    cases[n++] = (bench_case){"torus/plane param/implicit", PRIM(torus, IC_PARAMETRIC),
                              PRIM(plane, IC_IMPLICIT), {0, 0, 0}};
    ic_surface *enn = NULL;
    if (ic_surface_new_parametric(&enn, enneper, NULL, NULL, 0, NULL, NULL) == IC_OK)
        pool.s[pool.n++] = enn;
    const double dom[2][2] = {{-5, 5}, {-5, 5}};
    if (!enn || ic_surface_set_domain(enn, dom, NULL, NULL) != IC_OK)
        return 1;
    cases[n++] = (bench_case){"Enneper self-intersection", enn, NULL,
                              {28 * sqrt(2.0) / 3, 0, -7}};
    /* the torus/plane point: on the torus' circle v = 0.5, where the plane
     * cuts it (solve 0.2 x + z = 0.3 along u by bisection) */
    {
        double lo = 0.0, hi = 3.14159;
        for (int it = 0; it < 200; it++) {
            const double u = 0.5 * (lo + hi), w = 2 + 0.5 * cos(0.5);
            const double g = 0.2 * w * cos(u) + 0.5 * sin(0.5) - 0.3;
            if (g > 0)
                lo = u;
            else
                hi = u;
        }
        const double u = 0.5 * (lo + hi), w = 2 + 0.5 * cos(0.5);
        cases[4].at[0] = w * cos(u), cases[4].at[1] = w * sin(u), cases[4].at[2] = 0.5 * sin(0.5);
    }
    ic_surface *nurbs = rational_patch(&pool);
    if (!nurbs)
        return 1;
    /* x and z of the patch do not change along v: at u = 0.4, y puts the
     * point on the sphere of radius 2 */
    double Ru[3];
    if (ic_surface_eval(nurbs, Ru, (const double[2]){0.4, 0.5}, NULL) != IC_OK)
        return 1;
    cases[n++] = (bench_case){"rational NURBS/implicit sphere", nurbs, PRIM(sph, IC_IMPLICIT),
                              {Ru[0], sqrt(4 - Ru[0] * Ru[0] - Ru[2] * Ru[2]), Ru[2]}};
    if (!instructions)
        printf("%-36s %3s %10s %10s %10s %8s %10s\n", "pairing (ns per point)", "K", "apparatus",
               "jet method", "surfaces", "jet/surf", "closed K=3");
    for (int i = 0; i < n; i++) {
        job j;
        memset(&j, 0, sizeof j);
        ic_local_defaults(&j.opt);
        ic_error err;
        if (ic_pair_new(&j.pair, cases[i].A, cases[i].B, &err) != IC_OK ||
            ic_local_locate(j.pair, &j.pt, cases[i].at, &j.opt, &err) != IC_OK) {
            fprintf(stderr, "%s: %s\n", cases[i].name, err.message);
            return 1;
        }
        for (int s = 0; s < 2; s++)
            if (ic_sheet_at(j.pair, &j.sh[s], s, &j.pt, &err) != IC_OK) {
                fprintf(stderr, "%s: %s\n", cases[i].name, err.message);
                return 1;
            }
        const int orders[3] = {4, 8, 16};
        for (int k = 0; k < 3; k++) {
            const int K = orders[k];
            if (ic_jet_space_new(&j.sp[0], 2, K, NULL) || ic_jet_space_new(&j.sp[1], 3, K, NULL))
                return 1;
            double r[4];
            j.order = K;
            j.method = IC_METHOD_JET;
            if (instructions) {
                failed |= count_instructions(run_jet_method, &j, "jet", cases[i].name, K) ||
                          count_instructions(run_surfaces, &j, "surfaces", cases[i].name, K);
                ic_jet_space_free(j.sp[0]);
                ic_jet_space_free(j.sp[1]);
                continue;
            }
            r[0] = bench_ns_per_call(run_apparatus, &j);
            r[1] = bench_ns_per_call(run_jet_method, &j);
            r[2] = bench_ns_per_call(run_surfaces, &j);
            r[3] = NAN;
            if (k == 0) {
                j.order = 3;
                j.method = IC_METHOD_CLOSED_FORM;
                r[3] = bench_ns_per_call(run_apparatus, &j);
            }
            printf("%-36s %3d %10.0f %10.0f %10.0f %8.1f %10.0f\n", k ? "" : cases[i].name, K,
                   r[0], r[1], r[2], r[1] / r[2], r[3]);
            ic_jet_space_free(j.sp[0]);
            ic_jet_space_free(j.sp[1]);
        }
        ic_pair_free(j.pair);
    }
    if (instructions) {
        for (int i = 0; i < pool.n; i++)
            ic_surface_free(pool.s[i]);
        return failed;
    }
    /* tangential points: classification (order 1), the full apparatus by the
     * height-difference method at K = 3 and 8, and the perturbation method */
    ic_primitive tor = {.kind = IC_PRIM_TORUS, .major_radius = 2, .radius = 1};
    ic_primitive unit = {.kind = IC_PRIM_SPHERE, .radius = 1};
    ic_primitive touch = {.kind = IC_PRIM_PLANE, .center = {0, 1, 0}, .normal = {0, 1, 0}};
    bench_case tang[4];
    int nt = 0;
    tang[nt++] = (bench_case){"Viviani branch point impl/impl", PRIM(cyl, IC_IMPLICIT),
                              PRIM(sph, IC_IMPLICIT), {2, 0, 0}};
    tang[nt++] = (bench_case){"Viviani branch point param/param", PRIM(cyl, IC_PARAMETRIC),
                              PRIM(sph, IC_PARAMETRIC), {2, 0, 0}};
    tang[nt++] = (bench_case){"torus/sphere tangential circle", PRIM(tor, IC_IMPLICIT),
                              PRIM(unit, IC_IMPLICIT), {0.6, 0.8, 0}};
    tang[nt++] = (bench_case){"sphere/plane isolated contact", PRIM(unit, IC_IMPLICIT),
                              PRIM(touch, IC_IMPLICIT), {0, 1, 0}};
    printf("\n%-36s %10s %10s %10s %12s %12s\n", "tangential point (ns per point)", "classify",
           "height K=3", "height K=8", "perturbation", "closed-form");
    for (int i = 0; i < nt; i++) {
        job j;
        memset(&j, 0, sizeof j);
        ic_local_defaults(&j.opt);
        ic_error err;
        if (!tang[i].A || !tang[i].B || ic_pair_new(&j.pair, tang[i].A, tang[i].B, &err) != IC_OK ||
            ic_local_locate(j.pair, &j.pt, tang[i].at, &j.opt, &err) != IC_OK) {
            fprintf(stderr, "%s: %s\n", tang[i].name, err.message);
            return 1;
        }
        double r[4];
        const int orders[3] = {1, 3, 8};
        j.method = IC_METHOD_HEIGHT_DIFFERENCE;
        for (int k = 0; k < 3; k++) {
            j.order = orders[k];
            r[k] = bench_ns_per_call(run_apparatus, &j);
        }
        j.method = IC_METHOD_PERTURBATION;
        j.order = 2;
        r[3] = bench_ns_per_call(run_apparatus, &j);
        j.method = IC_METHOD_CLOSED_FORM; /* branch points only (NaN elsewhere) */
        j.order = 3;
        double r4 = i < 2 ? bench_ns_per_call(run_apparatus, &j) : NAN;
        printf("%-36s %10.0f %10.0f %10.0f %12.0f %12.0f\n", tang[i].name, r[0], r[1], r[2], r[3],
               r4);
        ic_pair_free(j.pair);
    }
    for (int i = 0; i < pool.n; i++)
        ic_surface_free(pool.s[i]);
    return 0;
}
