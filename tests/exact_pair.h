/* Two implicit primitives traced by the exact paths and by the general
 * path (exact_paths = 0, the reference) in the box [-half, half]^3, owned
 * together; and whether two traces are the same point for point
 * (test_exact_paths, test_exact_conics). */
#ifndef IC_TEST_EXACT_PAIR_H
#define IC_TEST_EXACT_PAIR_H

#include <math.h>
#include <string.h>

#include "harness.h"
#include "intercurve.h"
#include "same_trace.h"

typedef struct {
    ic_surface *S[2];
    ic_pair *pair;
    ic_trace_result *res[2]; /* general path, exact path */
    double L;                /* the problem's size: the box's diagonal */
} traced_pair;

static inline ic_status trace_pair_with(traced_pair *t, double half, int exact, ic_error *err)
{
    ic_trace_options opt;
    ic_trace_defaults(&opt);
    opt.exact_paths = exact;
    opt.certify = 0; /* the paths compared, not the proof: tracer_complete */
    opt.has_box = 1;
    for (int k = 0; k < 3; k++)
        opt.box[k][0] = -half, opt.box[k][1] = half;
    t->L = 2 * half * sqrt(3.0);
    return ic_trace(&t->res[exact], t->pair, &opt, err);
}

/* Both traces of the implicit primitives A and B; 0 (a failed check) when
 * one could not be made. */
static inline int trace_pair_both(traced_pair *t, const ic_primitive *A, const ic_primitive *B,
                                  double half, const char *name)
{
    ic_error err;
    memset(t, 0, sizeof *t);
    return REQUIRE(ic_surface_new_primitive(&t->S[0], A, IC_IMPLICIT, &err) == IC_OK &&
                       ic_surface_new_primitive(&t->S[1], B, IC_IMPLICIT, &err) == IC_OK &&
                       ic_pair_new(&t->pair, t->S[0], t->S[1], &err) == IC_OK &&
                       trace_pair_with(t, half, 1, &err) == IC_OK &&
                       trace_pair_with(t, half, 0, &err) == IC_OK,
                   "%s: traced: %s", name, err.message);
}

static inline void release_pair(traced_pair *t)
{
    for (int i = 0; i < 2; i++) {
        ic_trace_result_free(t->res[i]);
        ic_surface_free(t->S[i]);
    }
    ic_pair_free(t->pair);
}

/* A pair the exact paths must leave to the general path: both traces give
 * exactly what the general path gives. */
static inline void check_fall_back(const char *name, const ic_primitive *A, const ic_primitive *B,
                                   double half)
{
    traced_pair t;
    if (trace_pair_both(&t, A, B, half, name))
        CHECK(same_results(t.res[0], t.res[1]),
              "%s: left to the general path, exactly what it gives", name);
    release_pair(&t);
}

#endif
