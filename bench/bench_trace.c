/* Benchmark of the marching core (make bench): time and points per curve at
 * tolerances 1e-6, 1e-10, 1e-12, with the largest distance of an output
 * point to either surface: first single curves from a given start point,
 * then the whole intersection of the bundled examples, then the exact paths
 * of three coaxial pairs of primitives and two conic ones against the
 * search (usage: bench_trace [EXAMPLES_DIR]). */
#include <math.h>
#include <stdio.h>

#include "bench_timer.h"
#include "intercurve.h"

typedef struct {
    ic_pair *pair;
    ic_local_point start;
    ic_trace_options opt;
    int points;
    double length;
} job;

static int run(void *ctx)
{
    job *j = ctx;
    ic_tracer *tr = NULL;
    ic_trace_event ev;
    if (ic_tracer_new(&tr, j->pair, &j->opt, NULL) || ic_tracer_start(tr, &j->start, 1, NULL) ||
        ic_tracer_run(tr, &ev, NULL)) {
        ic_tracer_free(tr);
        return 1;
    }
    j->points = ic_tracer_num_points(tr);
    j->length = ic_tracer_point(tr, j->points - 1)->s;
    ic_tracer_free(tr);
    return 0;
}

/* Largest distance of a traced point to either surface: |f|/|grad f| for an
 * implicit surface, |R(params) - xyz| for a parametric one. */
static double worst_distance(const ic_trace_result *r, ic_pair *pair)
{
    double worst = 0;
    for (int i = 0; i < ic_trace_result_num_curves(r); i++) {
        const ic_trace_curve *c = ic_trace_result_curve(r, i);
        for (int k = 0; k < c->npoints; k++)
            for (int s = 0; s < 2; s++) {
                ic_surface *S = ic_pair_surface(pair, s);
                const ic_trace_point *p = &c->points[k];
                double d = INFINITY;
                if (ic_surface_get_kind(S) == IC_PARAMETRIC) {
                    double x[3];
                    if (ic_surface_eval(S, x, p->params[s], NULL) == IC_OK)
                        d = hypot(hypot(x[0] - p->xyz[0], x[1] - p->xyz[1]), x[2] - p->xyz[2]);
                } else {
                    ic_surface_geometry g;
                    if (ic_surface_geometry_at(S, &g, p->xyz, NULL) == IC_OK)
                        d = fabs(g.value) / g.normal_length;
                }
                worst = fmax(worst, d);
            }
    }
    return worst;
}

/* Traces one bundled example at one tolerance and prints its row. */
static int whole_example(const char *dir, const char *file, double tol)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s", dir, file);
    ic_problem *p = NULL;
    ic_pair *pair = NULL;
    ic_trace_result *r = NULL;
    ic_error err;
    ic_trace_options opt;
    ic_trace_defaults(&opt);
    opt.tol = tol;
    opt.threads = 1; /* the threads have their own bench (bench_threads) */
    int rc = 1;
    if (ic_problem_load(&p, path, &err) != IC_OK) {
        fprintf(stderr, "%s: %s\n", path, err.message);
        return 1;
    }
    opt.has_box = ic_problem_box(p, opt.box);
    const int self = ic_problem_is_self(p);
    if (ic_pair_new(&pair, ic_problem_surface(p, 0), self ? NULL : ic_problem_surface(p, 1),
                    &err) == IC_OK) {
        const double t0 = bench_now();
        if (ic_trace(&r, pair, &opt, &err) == IC_OK) {
            const double ms = (bench_now() - t0) * 1e3;
            int points = 0;
            for (int i = 0; i < ic_trace_result_num_curves(r); i++)
                points += ic_trace_result_curve(r, i)->npoints;
            /* the certificate's share of the trace (docs/performance.md) */
            const ic_trace_certificate *c = &ic_trace_result_report(r)->certificate;
            printf("%-26s %6.0e %6d %6d %6d %10.1f %10.1e %9.1f %s\n", file, tol,
                   ic_trace_result_num_curves(r), points, ic_trace_result_num_specials(r), ms,
                   worst_distance(r, pair), c->seconds * 1e3,
                   c->accepted ? "proven" : c->checked ? "refused" : "-");
            rc = 0;
        }
    }
    if (rc)
        fprintf(stderr, "%s: %s\n", path, err.message);
    ic_trace_result_free(r);
    ic_pair_free(pair);
    ic_problem_free(p);
    return rc;
}

/* ---- the exact paths (docs/tracing.md, "Exact paths") ---- */

typedef struct {
    ic_pair *pair;
    ic_trace_options opt;
    int curves, specials;
} whole_job;

static int trace_whole(void *ctx)
{
    whole_job *j = ctx;
    ic_trace_result *r = NULL;
    if (ic_trace(&r, j->pair, &j->opt, NULL) != IC_OK)
        return 1;
    j->curves = ic_trace_result_num_curves(r);
    j->specials = ic_trace_result_num_specials(r);
    ic_trace_result_free(r);
    return 0;
}

/* The best of three single traces, in ns (the search takes up to seconds). */
static double best_of_three(whole_job *j)
{
    double best = INFINITY;
    for (int k = 0; k < 3; k++) {
        const double t0 = bench_now();
        if (trace_whole(j) != 0)
            return NAN;
        best = fmin(best, (bench_now() - t0) * 1e9);
    }
    return best;
}

/* The three coaxial pairs of implicit primitives and two conic
 * ones (Steinmetz's cylinders, a cylinder cut at 60 degrees to its axis),
 * traced whole with the exact path and with the search (exact_paths = 0). */
static int exact_cases(void)
{
    const ic_primitive Z = {.kind = IC_PRIM_SPHERE};
    struct {
        const char *name;
        ic_primitive A, B;
        double half;
    } cases[5] = {{"sphere r 1, plane z = 1/2", Z, Z, 2},
                  {"torus 2, 1/2 on sphere r 5/2", Z, Z, 3},
                  {"sphere on plane z = 0 (point)", Z, Z, 2},
                  {"cylinders z, y r 1 (Steinmetz)", Z, Z, 1.5},
                  {"cylinder r 1, plane at 60 deg", Z, Z, 2.5}};
    cases[0].A.radius = 1;
    cases[0].B = (ic_primitive){.kind = IC_PRIM_PLANE, .center = {0, 0, 0.5}, .normal = {0, 0, 1}};
    cases[1].A = (ic_primitive){.kind = IC_PRIM_TORUS, .major_radius = 2, .radius = 0.5};
    cases[1].B.radius = 2.5;
    cases[2].A = (ic_primitive){.kind = IC_PRIM_SPHERE, .center = {0, 0, 1}, .radius = 1};
    cases[2].B = (ic_primitive){.kind = IC_PRIM_PLANE, .normal = {0, 0, 1}};
    cases[3].A = (ic_primitive){.kind = IC_PRIM_CYLINDER, .radius = 1};
    cases[3].B = (ic_primitive){.kind = IC_PRIM_CYLINDER, .radius = 1, .axis = {0, 1, 0}};
    cases[4].A = cases[3].A;
    cases[4].B = (ic_primitive){.kind = IC_PRIM_PLANE, .normal = {0.8660254037844386, 0, 0.5}};
    printf("\n%-30s %6s %6s %14s %14s\n", "exact primitives (box)", "curves", "special",
           "exact (us)", "search (ms)");
    for (int c = 0; c < 5; c++) {
        ic_surface *A = NULL, *B = NULL;
        whole_job j = {0};
        if (ic_surface_new_primitive(&A, &cases[c].A, IC_IMPLICIT, NULL) ||
            ic_surface_new_primitive(&B, &cases[c].B, IC_IMPLICIT, NULL) ||
            ic_pair_new(&j.pair, A, B, NULL))
            return 1;
        ic_trace_defaults(&j.opt);
        j.opt.threads = 1;
        j.opt.has_box = 1;
        for (int k = 0; k < 3; k++)
            j.opt.box[k][0] = -cases[c].half, j.opt.box[k][1] = cases[c].half;
        const double exact = bench_ns_per_call(trace_whole, &j);
        j.opt.exact_paths = 0;
        const double search = best_of_three(&j);
        printf("%-30s %6d %6d %14.2f %14.1f\n", cases[c].name, j.curves, j.specials, exact / 1e3,
               search / 1e6);
        ic_pair_free(j.pair);
        ic_surface_free(A);
        ic_surface_free(B);
    }
    return 0;
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : "examples";
    struct {
        const char *name, *f, *g;
        double at[3];
    } cases[] = {
        {"sphere/plane circle (closed)",
         "x^2 + y^2 + z^2 - 4",
         "z - 1",
         {1.7320508075688772, 0, 1}},
        {"ellipsoids Ex 5.1 half-ellipse",
         "x^2/0.36 + y^2/0.64 + z^2 - 1",
         "x^2/0.2025 + y^2/0.64 + z^2/1.5625 - 1",
         {0.16875, 0.69282032302755092, 0.41339864718575637}},
        {"Viviani lobe to the branch point",
         "(x - 1)^2 + y^2 - 1",
         "x^2 + y^2 + z^2 - 4",
         {1.5, 0.8660254037844386, 1}},
    };
    const double tols[3] = {1e-6, 1e-10, 1e-12};
    printf("%-34s %8s %8s %12s %10s\n", "curve (implicit/implicit)", "tol", "points",
           "us per curve", "length");
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        ic_surface *A = NULL, *B = NULL;
        job j = {0};
        if (ic_surface_new_implicit(&A, cases[c].f, NULL, 0, NULL) ||
            ic_surface_new_implicit(&B, cases[c].g, NULL, 0, NULL) ||
            ic_pair_new(&j.pair, A, B, NULL))
            return 1;
        for (int k = 0; k < 3; k++) {
            ic_trace_defaults(&j.opt);
            j.opt.tol = tols[k];
            if (ic_local_locate(j.pair, &j.start, cases[c].at, &j.opt.local, NULL))
                return 1;
            const double ns = bench_ns_per_call(run, &j);
            printf("%-34s %8.0e %8d %12.1f %10.6f\n", cases[c].name, tols[k], j.points, ns / 1e3,
                   j.length);
        }
        ic_pair_free(j.pair);
        ic_surface_free(A);
        ic_surface_free(B);
    }
    /* the whole intersection of the bundled examples (every pairing):
     * start-point search, every curve, the report */
    printf("\n%-26s %6s %6s %6s %6s %10s %10s %9s %s\n", "whole intersection (depth 6)", "tol",
           "curves", "points", "special", "ms", "max dist", "cert ms", "certificate");
    const char *files[] = {"viviani-implicit.json",       "viviani.json",
                           "ellipsoids.json",             "enneper-self.json",
                           "sphere-cylinder-branch.json", "sphere-plane-contact.json",
                           "torus-sphere.json",           "torus-plane-tangential.json",
                           "cylinders.json",              "cylinders-equal.json",
                           "small-loop.json",             "tacnode.json",
                           "nurbs-patch-sphere.json",     "placed-cylinders.json",
                           "paraboloid-cubic.json"};
    for (size_t c = 0; c < sizeof files / sizeof files[0]; c++)
        for (int k = 0; k < 3; k++)
            if (whole_example(dir, files[c], tols[k]) != 0)
                return 1;
    return exact_cases();
}
