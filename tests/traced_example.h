/* A bundled example traced whole, for the tests that read examples/
 * (test_writers, test_trace_examples): load, pair, trace, release. */
#ifndef IC_TEST_TRACED_EXAMPLE_H
#define IC_TEST_TRACED_EXAMPLE_H

#include <stdio.h>
#include <string.h>

#include "harness.h"
#include "intercurve.h"

typedef struct {
    ic_problem *problem;
    ic_pair *pair;
    ic_trace_result *res;
} traced;

/* Any problem file, traced with the options given (and its box). */
static inline int trace_file_with(traced *t, const char *path, ic_trace_options opt)
{
    ic_error err;
    memset(t, 0, sizeof *t);
    ic_status st = ic_problem_load(&t->problem, path, &err);
    if (st == IC_OK) {
        opt.has_box = ic_problem_box(t->problem, opt.box);
        const int self = ic_problem_is_self(t->problem);
        st = ic_pair_new(&t->pair, ic_problem_surface(t->problem, 0),
                         self ? NULL : ic_problem_surface(t->problem, 1), &err);
    }
    if (st == IC_OK)
        st = ic_trace(&t->res, t->pair, &opt, &err);
    CHECK(st == IC_OK, "%s: %s", path, err.message);
    return st == IC_OK ? 0 : -1;
}

/* The options of a coarse trace (chord heights of 1e-2 of the size, steps
 * up to 0.2 of it, truncation 1e-6): stretches that turn 0.1 to 0.25 rad,
 * for the tests of what is drawn or fitted between the traced points. */
static inline ic_trace_options coarse_trace_options(void)
{
    ic_trace_options opt;
    ic_trace_defaults(&opt);
    opt.chord = 1e-2, opt.max_step = 0.2, opt.tol = 1e-6;
    return opt;
}

/* Any problem file, traced with the default options (and its box). */
static inline int trace_file(traced *t, const char *path)
{
    ic_trace_options opt;
    ic_trace_defaults(&opt);
    return trace_file_with(t, path, opt);
}

static inline int trace_example(traced *t, const char *dir, const char *name)
{
    char path[512];
    snprintf(path, sizeof path, "%s/examples/%s", dir, name);
    return trace_file(t, path);
}

static inline void release(traced *t)
{
    ic_trace_result_free(t->res);
    ic_pair_free(t->pair);
    ic_problem_free(t->problem);
}

#endif
