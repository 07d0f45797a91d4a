/* Benchmark of the marching core (make bench): time and points per curve at
 * tolerances 1e-6, 1e-10, 1e-12, with the largest distance of an output
 * point to either surface. Start points are given (start-point search comes
 * with the tracing issue). */
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

int main(void)
{
    struct {
        const char *name, *f, *g;
        double at[3];
    } cases[] = {
        {"sphere/plane circle (closed)", "x^2 + y^2 + z^2 - 4", "z - 1", {1.7320508075688772, 0, 1}},
        {"ellipsoids Ex 5.1 half-ellipse", "x^2/0.36 + y^2/0.64 + z^2 - 1",
         "x^2/0.2025 + y^2/0.64 + z^2/1.5625 - 1", {0.16875, 0.69282032302755092, 0.41339864718575637}},
        {"Viviani lobe to the branch point", "(x - 1)^2 + y^2 - 1", "x^2 + y^2 + z^2 - 4",
         {1.5, 0.8660254037844386, 1}},
    };
    const double tols[3] = {1e-6, 1e-10, 1e-12};
    printf("%-34s %8s %8s %12s %10s\n", "curve (implicit/implicit)", "tol", "points", "us per curve",
           "length");
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
    /* the whole intersection: start-point search, every curve, the report */
    printf("\n%-40s %8s %8s %14s\n", "whole intersection (box search, depth 6)", "tol", "curves",
           "ms per trace");
    struct {
        const char *name, *f, *g;
        double box;
    } whole[] = {
        {"Viviani (implicit/implicit)", "(x - 1)^2 + y^2 - 1", "x^2 + y^2 + z^2 - 4", 2.5},
        {"ellipsoids Ex 5.1", "x^2/0.36 + y^2/0.64 + z^2 - 1",
         "x^2/0.2025 + y^2/0.64 + z^2/1.5625 - 1", 1.5},
        {"sphere/plane circle", "x^2 + y^2 + z^2 - 4", "z - 1", 3},
    };
    for (size_t c = 0; c < sizeof whole / sizeof whole[0]; c++) {
        ic_surface *A = NULL, *B = NULL;
        ic_pair *pair = NULL;
        if (ic_surface_new_implicit(&A, whole[c].f, NULL, 0, NULL) ||
            ic_surface_new_implicit(&B, whole[c].g, NULL, 0, NULL) || ic_pair_new(&pair, A, B, NULL))
            return 1;
        for (int k = 0; k < 3; k++) {
            ic_trace_options opt;
            ic_trace_defaults(&opt);
            opt.tol = tols[k];
            opt.has_box = 1;
            for (int i = 0; i < 3; i++)
                opt.box[i][0] = -whole[c].box, opt.box[i][1] = whole[c].box;
            const double t0 = bench_now();
            ic_trace_result *r = NULL;
            if (ic_trace(&r, pair, &opt, NULL) != IC_OK)
                return 1;
            const double ms = (bench_now() - t0) * 1e3;
            printf("%-40s %8.0e %8d %14.1f\n", whole[c].name, tols[k], ic_trace_result_num_curves(r), ms);
            ic_trace_result_free(r);
        }
        ic_pair_free(pair);
        ic_surface_free(A);
        ic_surface_free(B);
    }
    return 0;
}
