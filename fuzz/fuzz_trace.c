/* libFuzzer target: a problem file from memory, traced whole.
 * The input is loaded with ic_problem_parse from a buffer of exactly its
 * size; a problem that loads is made into a pair as the command line does
 * (src/cli/traced.c: the box, one surface for a self-intersection) and
 * traced with the defaults at a shallow search (depth at most 3), a small
 * point budget and a time limit of 1 s. The trace may fail, but with a
 * message; a result must hold curves of at least one point with finite
 * coordinates and arc length non-decreasing from a finite start, finite
 * non-negative lengths, non-negative report counts, and complete = 1 only
 * without failures. Everything is freed (LeakSanitizer runs). */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "intercurve/local.h"
#include "intercurve/problem.h"
#include "intercurve/trace.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void check_curve(const ic_trace_curve *c)
{
    if (!c || c->npoints < 1 || !c->points)
        abort();
    if (!isfinite(c->length) || c->length < 0)
        abort();
    double prev = -INFINITY;
    for (int j = 0; j < c->npoints; j++) {
        const ic_trace_point *q = &c->points[j];
        for (int k = 0; k < 3; k++)
            if (!isfinite(q->xyz[k]))
                abort();
        if (!isfinite(q->s) || q->s < prev)
            abort(); /* arc length runs forward along the curve */
        prev = q->s;
    }
}

static void check_report(const ic_trace_report *r)
{
    if (!r)
        abort();
    if (r->complete != 0 && r->complete != 1)
        abort();
    if (r->complete && r->nfailures != 0)
        abort(); /* complete means nothing was left undecided */
    const int counts[] = {
        r->cells,           r->cells_excluded,       r->cells_excluded_centred, r->candidates,
        r->uncovered_cells, r->unproven_cells,       r->loop_free_cells,        r->loop_cells,
        r->refined_cells,   r->undecided_loop_cells, r->coincident_cells,       r->nfailures};
    for (size_t i = 0; i < sizeof counts / sizeof counts[0]; i++)
        if (counts[i] < 0)
            abort();
    if (r->nfailures > IC_TRACE_MAX_FAILURES)
        abort();
}

static void check_result(const ic_trace_result *res)
{
    if (!res)
        abort();
    const int n = ic_trace_result_num_curves(res);
    if (n < 0)
        abort();
    for (int i = 0; i < n; i++)
        check_curve(ic_trace_result_curve(res, i));
    const int ns = ic_trace_result_num_specials(res);
    if (ns < 0)
        abort();
    for (int i = 0; i < ns; i++)
        if (!ic_trace_result_special(res, i))
            abort();
    check_report(ic_trace_result_report(res));
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size > IC_PROBLEM_MAX_FILE)
        return 0;
    char *text = malloc(size ? size : 1);
    if (!text)
        return 0;
    memcpy(text, data, size);
    ic_problem *p = NULL;
    ic_error err;
    ic_error_clear(&err);
    if (ic_problem_parse(&p, text, size, &err) != IC_OK) {
        if (p || err.message[0] == '\0')
            abort();
        free(text);
        return 0;
    }
    if (!p)
        abort();

    ic_trace_options opt;
    ic_trace_defaults(&opt);
    if (opt.depth > 3)
        opt.depth = 3;
    opt.time_limit = 1.0;
    opt.max_points = 2000;
    opt.has_box = ic_problem_box(p, opt.box);

    const int self = ic_problem_is_self(p);
    ic_pair *pair = NULL;
    ic_error_clear(&err);
    if (ic_pair_new(&pair, ic_problem_surface(p, 0), self ? NULL : ic_problem_surface(p, 1),
                    &err) != IC_OK) {
        if (pair || err.message[0] == '\0')
            abort();
    } else {
        if (!pair)
            abort();
        ic_trace_result *res = NULL;
        ic_error_clear(&err);
        const ic_status st = ic_trace(&res, pair, &opt, &err);
        if (st == IC_OK)
            check_result(res);
        else if (err.message[0] == '\0')
            abort(); /* a failure must say what went wrong */
        ic_trace_result_free(res);
    }
    ic_pair_free(pair);
    ic_problem_free(p);
    free(text);
    return 0;
}
