/* Whether two traces are the same, point for point and bit for bit, and
 * both the search (the exact-path tests: a case an exact path leaves to
 * the general path gives exactly what the general path gives). */
#ifndef IC_TEST_SAME_TRACE_H
#define IC_TEST_SAME_TRACE_H

#include <string.h>

#include "intercurve.h"

/* Field by field, bit for bit (NaN parameters included): a memcmp of the
 * whole struct would read its padding, which nothing sets. */
#define SAME_FIELD(a, b, f) (memcmp(&(a)->f, &(b)->f, sizeof(a)->f) == 0)

static inline int same_point(const ic_trace_point *a, const ic_trace_point *b)
{
    return SAME_FIELD(a, b, s) && SAME_FIELD(a, b, xyz) && SAME_FIELD(a, b, params) &&
           SAME_FIELD(a, b, t) && SAME_FIELD(a, b, n) && SAME_FIELD(a, b, b) &&
           SAME_FIELD(a, b, kappa) && SAME_FIELD(a, b, tau) && SAME_FIELD(a, b, angle) &&
           SAME_FIELD(a, b, frame_defined) && SAME_FIELD(a, b, knot_line) &&
           SAME_FIELD(a, b, knot_side);
}

static inline int same_special(const ic_trace_special *a, const ic_trace_special *b)
{
    return SAME_FIELD(a, b, xyz) && SAME_FIELD(a, b, type) && SAME_FIELD(a, b, nbranches) &&
           SAME_FIELD(a, b, approximate);
}

/* Both traces the same, point for point, and both the search. */
static inline int same_results(const ic_trace_result *a, const ic_trace_result *b)
{
    const ic_trace_report *ra = ic_trace_result_report(a), *rb = ic_trace_result_report(b);
    if (strcmp(ra->method, "search") != 0 || strcmp(rb->method, "search") != 0 ||
        ra->complete != rb->complete || ra->cells != rb->cells || ra->nfailures != rb->nfailures ||
        ic_trace_result_num_curves(a) != ic_trace_result_num_curves(b) ||
        ic_trace_result_num_specials(a) != ic_trace_result_num_specials(b))
        return 0;
    for (int k = 0; k < ic_trace_result_num_curves(a); k++) {
        const ic_trace_curve *ca = ic_trace_result_curve(a, k), *cb = ic_trace_result_curve(b, k);
        if (ca->npoints != cb->npoints || ca->length != cb->length ||
            ca->tangential != cb->tangential)
            return 0;
        for (int i = 0; i < ca->npoints; i++)
            if (!same_point(&ca->points[i], &cb->points[i]))
                return 0;
    }
    for (int k = 0; k < ic_trace_result_num_specials(a); k++)
        if (!same_special(ic_trace_result_special(a, k), ic_trace_result_special(b, k)))
            return 0;
    return 1;
}

#endif
