/* libFuzzer target: the formula parser and all three evaluators.
 * Any input must compile or fail with a column inside the formula; a
 * compiled formula must evaluate on doubles, intervals and jets without
 * crashing (domain errors are fine). */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "intercurve/expr.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const char *const vars[3] = {"x", "y", "z"};
    static const ic_constant consts[2] = {{"R", 2.0}, {"r", 0.5}};
    char *text = malloc(size + 1);
    if (!text)
        return 0;
    memcpy(text, data, size);
    text[size] = '\0';
    const char *formula = text;
    ic_expr *e = NULL;
    ic_error err;
    if (ic_expr_compile(&e, &formula, 1, vars, 3, consts, 2, NULL, &err) != IC_OK) {
        const int len = (int)strlen(text);
        if (err.column < 1 || err.column > len + 1)
            abort(); /* the column must point into the formula */
        char caret[256];
        ic_expr_caret(caret, sizeof caret, text, err.column);
        free(text);
        return 0;
    }
    double out, work[4096];
    const double at[3] = {0.3, -0.7, 1.1};
    if (ic_expr_work_len(e) <= 4096)
        (void)ic_expr_eval(e, &out, at, work, &err);
    ic_interval box[3] = {{-1, 1}, {0.5, 2}, {-3, -2}}, iout, iwork[4096];
    if (ic_expr_interval_work_len(e) <= 4096)
        ic_expr_eval_interval(e, &iout, box, iwork);
    ic_jet_space *sp = NULL;
    if (ic_jet_space_new(&sp, 3, 3, NULL) == IC_OK) {
        const int n = ic_jet_space_len(sp);
        double *jw = malloc(ic_expr_jet_work_len(e, sp) * sizeof *jw);
        double *x = malloc(4 * (size_t)n * sizeof *x);
        if (jw && x) {
            for (int i = 0; i < 3; i++)
                ic_jet_set_var(x + i * n, at[i], i, sp);
            const double *in[3] = {x, x + n, x + 2 * n};
            (void)ic_expr_eval_jet(e, x + 3 * n, in, sp, jw, &err);
        }
        free(jw);
        free(x);
        ic_jet_space_free(sp);
    }
    ic_expr_free(e);
    free(text);
    return 0;
}
