/* Two surfaces, their pair and its trace, owned together and released
 * together (test_trace_robust, test_trust). */
#ifndef IC_TEST_TRACED_PAIR_H
#define IC_TEST_TRACED_PAIR_H

#include <string.h>

#include "intercurve.h"

typedef struct {
    ic_surface *A, *B;
    ic_pair *pair;
    ic_trace_result *res;
} traced;

static inline void release(traced *t)
{
    ic_trace_result_free(t->res);
    ic_pair_free(t->pair);
    ic_surface_free(t->A);
    ic_surface_free(t->B);
    memset(t, 0, sizeof *t);
}

#endif
