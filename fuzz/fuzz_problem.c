/* libFuzzer target: the problem loader (ic_problem_parse) on arbitrary bytes.
 * The input is handed over in a buffer of exactly its size, so a read past
 * the end is caught. Any input must load or fail with a status, a message
 * and (for the caller's mistakes) a JSON path; a loaded problem must keep
 * the rules of docs/problem-files.md (one or two named surfaces, a box and
 * domains of ordered bounds within the limits) and its surfaces must
 * evaluate without crashing. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "intercurve/problem.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* The error of a rejected input: status, message, and where. */
static void check_error(ic_status st, const ic_error *err)
{
    if (err->code != st || err->message[0] == '\0')
        abort(); /* a failure must say what went wrong */
    if ((st == IC_ERR_INVALID || st == IC_ERR_PARSE) && err->path[0] == '\0')
        abort(); /* and, being the file's fault, where */
}

/* A loaded interval: ordered, no NaN, and a finite bound within the
 * loader's limit of 1e150 (docs/problem-files.md, "Strictness"). */
static void check_interval(const double iv[2], int may_be_infinite)
{
    if (!(iv[0] < iv[1]))
        abort();
    for (int k = 0; k < 2; k++)
        if (isfinite(iv[k]) ? fabs(iv[k]) > 1e150 : !may_be_infinite)
            abort();
}

/* The invariants of a loaded problem; its surfaces evaluated once. */
static void check_problem(const ic_problem *p)
{
    const int n = ic_problem_num_surfaces(p);
    if (n != (ic_problem_is_self(p) ? 1 : 2))
        abort();
    for (int i = 0; i < n; i++) {
        ic_surface *s = ic_problem_surface(p, i);
        const char *name = ic_problem_surface_name(p, i);
        if (!s || !name || !name[0] || ic_problem_find_surface(p, name) != i)
            abort();
        if (ic_surface_get_kind(s) == IC_PARAMETRIC) {
            double domain[2][2];
            int periodic[2];
            ic_surface_get_domain(s, domain, periodic);
            for (int k = 0; k < 2; k++)
                check_interval(domain[k], !periodic[k]); /* unbounded unless periodic */
        }
        const double at[3] = {0.25, -0.5, 0.75};
        double out[3];
        (void)ic_surface_eval(s, out, at, NULL); /* domain errors are fine */
    }
    double box[3][2];
    if (ic_problem_box(p, box))
        for (int k = 0; k < 3; k++)
            check_interval(box[k], 0);
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
    ic_status st = ic_problem_parse(&p, text, size, &err);
    if (st == IC_OK) {
        if (!p)
            abort();
        check_problem(p);
    } else {
        if (p)
            abort();
        check_error(st, &err);
    }
    ic_problem_free(p);
    free(text);
    return 0;
}
