/* Traced and fitted curves for the tests of the STEP and IGES curve
 * writers (test_curve_step, test_curve_iges): Viviani's curve, a circle and
 * the two loops of two cylinders, each pair of surfaces with its exact
 * distance functions written here, and the check that a curve read back
 * from a file lies on both surfaces. */
#ifndef IC_TEST_FITTED_CASES_H
#define IC_TEST_FITTED_CASES_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "intercurve.h"

/* Places on a read-back curve checked against the surfaces. */
enum { CASE_CHECKS = 200 };

typedef double (*surface_distance)(const double x[3]);

typedef struct {
    const char *name;
    const char *example; /* a bundled example (examples/), or NULL: */
    const char *problem; /* the problem file's text */
    int ncurves;         /* how many curves the trace finds */
    surface_distance distance[2];
} fitted_case;

typedef struct {
    ic_problem *problem;
    ic_pair *pair;
    ic_trace_result *res;
} fitted;

static inline double norm3(const double x[3])
{
    return sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
}
/* Viviani (examples/viviani-implicit.json): the cylinder (x - 1)^2 + y^2 = 1 and the sphere of
 * radius 2. */
static inline double viviani_cylinder(const double x[3]) { return fabs(hypot(x[0] - 1, x[1]) - 1); }
static inline double sphere2(const double x[3]) { return fabs(norm3(x) - 2); }
/* The circle: the same sphere and the plane z = 1. */
static inline double plane_z1(const double x[3]) { return fabs(x[2] - 1); }
/* Two cylinders (examples/cylinders.json): x^2 + y^2 = 1 and x^2 + z^2 = 0.49. */
static inline double upright(const double x[3]) { return fabs(hypot(x[0], x[1]) - 1); }
static inline double lying(const double x[3]) { return fabs(hypot(x[0], x[2]) - 0.7); }

static const fitted_case FITTED_CASES[] = {
    {"Viviani", "viviani-implicit.json", NULL, 1, {viviani_cylinder, sphere2}},
    {"circle",
     NULL,
     "{\"title\": \"A circle: sphere and plane\", \"surfaces\": [{\"type\": \"implicit\", "
     "\"f\": \"x^2 + y^2 + z^2 - 4\"}, {\"type\": \"implicit\", \"f\": \"z - 1\"}],"
     " \"box\": [[-3, 3], [-3, 3], [-3, 3]]}",
     1,
     {sphere2, plane_z1}},
    {"two cylinders", "cylinders.json", NULL, 2, {upright, lying}},
};
#define NFITTED_CASES ((int)(sizeof FITTED_CASES / sizeof FITTED_CASES[0]))

/* The case's problem loaded: the example under dir, or its text. */
static inline ic_status fitted_load(ic_problem **p, const fitted_case *c, const char *dir,
                                    ic_error *err)
{
    if (c->example) {
        char path[512];
        snprintf(path, sizeof path, "%s/examples/%s", dir, c->example);
        return ic_problem_load(p, path, err);
    }
    FILE *f = fmemopen((void *)c->problem, strlen(c->problem), "r");
    if (!f)
        return ic_error_set(err, IC_ERR_IO, 0, "fmemopen failed");
    const ic_status st = ic_problem_read(p, f, c->name, 0, err);
    fclose(f);
    return st;
}

/* The case's problem traced (default options, its box) and fitted with the
 * command line's default fit tolerance; 0 on success. */
static inline int fitted_trace(fitted *t, const fitted_case *c, const char *dir)
{
    ic_error err;
    ic_error_clear(&err);
    memset(t, 0, sizeof *t);
    ic_status st = fitted_load(&t->problem, c, dir, &err);
    ic_trace_options opt;
    ic_trace_defaults(&opt);
    if (st == IC_OK) {
        opt.has_box = ic_problem_box(t->problem, opt.box);
        st = ic_pair_new(&t->pair, ic_problem_surface(t->problem, 0),
                         ic_problem_surface(t->problem, 1), &err);
    }
    if (st == IC_OK)
        st = ic_trace(&t->res, t->pair, &opt, &err);
    if (st == IC_OK)
        st = ic_trace_fit(t->res, t->pair, 1e-9, &err);
    if (!REQUIRE(st == IC_OK, "%s: traced and fitted: %s", c->name, err.message))
        return -1;
    return REQUIRE(ic_trace_result_num_curves(t->res) == c->ncurves, "%s: %d curves", c->name,
                   ic_trace_result_num_curves(t->res))
               ? 0
               : -1;
}

static inline void fitted_release(fitted *t)
{
    ic_trace_result_free(t->res);
    ic_pair_free(t->pair);
    ic_problem_free(t->problem);
}

/* A curve read back from a file, evaluated at CASE_CHECKS places over its
 * parameter range, lies on both surfaces within tol (a length): the
 * largest distance found, or INFINITY when it cannot be evaluated. */
static inline double fitted_largest_distance(const fitted_case *c, const ic_bspline *b)
{
    double worst = 0;
    const double t0 = b->knots[b->degree], t1 = b->knots[b->ncontrol];
    for (int k = 0; k < CASE_CHECKS; k++) {
        double x[3];
        ic_error err;
        if (ic_bspline_eval(b, t0 + (t1 - t0) * (k + 0.5) / CASE_CHECKS, 0, x, &err) != IC_OK)
            return INFINITY;
        for (int s = 0; s < 2; s++)
            worst = fmax(worst, c->distance[s](x));
    }
    return worst;
}

/* A writer of a fitted trace (ic_trace_write_step, ic_trace_write_iges). */
typedef ic_status (*fitted_writer)(FILE *f, const ic_trace_result *res, const char *title,
                                   ic_error *err);

/* The file a writer makes of t, in memory (free it); NULL when it fails. */
static inline char *fitted_write(fitted_writer w, const fitted *t, const char *title,
                                 ic_status *st, ic_error *err)
{
    char *buf = NULL;
    size_t size = 0;
    FILE *f = open_memstream(&buf, &size);
    if (!f)
        return NULL;
    *st = w(f, t->res, title, err);
    fclose(f);
    if (*st != IC_OK) {
        free(buf);
        return NULL;
    }
    return buf;
}

/* n doubles equal bit for bit. */
static inline int same_doubles(const double *a, const double *b, int n)
{
    return n == 0 || memcmp(a, b, (size_t)n * sizeof *a) == 0;
}

#endif
