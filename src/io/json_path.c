/* Reading JSON values with errors that name their path (json_path.h). */
#include "json_path.h"

#include <stdio.h>
#include <string.h>

#include "intercurve/expr.h"

ic_status ic_json_check_keys(const cJSON *obj, const char *path, const char *const *allowed,
                             ic_error *err)
{
    for (const cJSON *it = obj->child; it; it = it->next) {
        int ok = 0;
        for (int i = 0; allowed[i]; i++)
            if (it->string && strcmp(it->string, allowed[i]) == 0)
                ok = 1;
        if (!ok) {
            char list[200] = "";
            for (int i = 0; allowed[i]; i++) {
                strncat(list, i ? ", " : "", sizeof list - strlen(list) - 1);
                strncat(list, allowed[i], sizeof list - strlen(list) - 1);
            }
            ic_error_set_path(err, "%s", path);
            return ic_error_set(err, IC_ERR_INVALID, 0, "unknown key \"%s\" (allowed: %s)",
                                it->string ? it->string : "", list);
        }
    }
    return IC_OK;
}

ic_status ic_json_formula_error(ic_error *err, const char *path, const char *formula)
{
    if (!err)
        return IC_ERR_PARSE;
    ic_error_set_path(err, "%s", path);
    if (err->column > 0) {
        char caret[200];
        ic_expr_caret(caret, sizeof caret, formula, err->column);
        const size_t used = strlen(err->message);
        snprintf(err->message + used, sizeof err->message - used, "\n%s", caret);
    }
    return err->code;
}

ic_status ic_json_number(double *out, const cJSON *item, const char *path,
                         const ic_constant *consts, int nconsts, ic_error *err)
{
    if (cJSON_IsNumber(item)) {
        *out = item->valuedouble;
        return IC_OK;
    }
    if (cJSON_IsString(item)) {
        ic_status st = ic_expr_eval_constant(out, item->valuestring, consts, nconsts, err);
        if (st != IC_OK)
            return ic_json_formula_error(err, path, item->valuestring);
        return IC_OK;
    }
    ic_error_set_path(err, "%s", path);
    return ic_error_set(err, IC_ERR_INVALID, 0, "expected a number or a formula string");
}

ic_status ic_json_numbers(double *out, int n, const cJSON *item, const char *path,
                          const ic_constant *consts, int nconsts, ic_error *err)
{
    if (!cJSON_IsArray(item) || cJSON_GetArraySize(item) != n) {
        ic_error_set_path(err, "%s", path);
        return ic_error_set(err, IC_ERR_INVALID, 0, "expected an array of %d numbers", n);
    }
    for (int i = 0; i < n; i++) {
        char sub[IC_ERROR_PATH_LEN];
        snprintf(sub, sizeof sub, "%s[%d]", path, i);
        ic_status st = ic_json_number(&out[i], cJSON_GetArrayItem(item, i), sub, consts, nconsts,
                                      err);
        if (st != IC_OK)
            return st;
    }
    return IC_OK;
}

void ic_json_line_col(const char *text, size_t pos, int *line, int *col)
{
    *line = 1;
    *col = 1;
    for (size_t i = 0; i < pos && text[i]; i++) {
        if (text[i] == '\n') {
            (*line)++;
            *col = 1;
        } else {
            (*col)++;
        }
    }
}
