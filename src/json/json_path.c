/* Reading JSON values with errors that name their path (json_path.h). */
#include "json_path.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
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

/* A constant formula's error. The formula layer refuses a literal or a
 * folded value that is not finite ("1e400", "1e308*10") with its column;
 * the problem's rule names it the way it names such a JSON number. */
static ic_status constant_error(ic_error *err, const char *path, const char *formula)
{
    if (err && (strstr(err->message, "not finite") || strstr(err->message, "non-finite"))) {
        char msg[IC_ERROR_MESSAGE_LEN];
        snprintf(msg, sizeof msg, "not a finite number: %s", err->message);
        snprintf(err->message, sizeof err->message, "%s", msg);
    }
    return ic_json_formula_error(err, path, formula);
}

ic_status ic_json_number(double *out, const cJSON *item, const char *path,
                         const ic_constant *consts, int nconsts, ic_error *err)
{
    if (cJSON_IsNumber(item) || cJSON_IsString(item)) {
        if (cJSON_IsNumber(item))
            *out = item->valuedouble;
        else if (ic_expr_eval_constant(out, item->valuestring, consts, nconsts, err) != IC_OK)
            return constant_error(err, path, item->valuestring);
        if (isfinite(*out))
            return IC_OK;
        ic_error_set_path(err, "%s", path); /* 1e400 reads as inf */
        return ic_error_set(err, IC_ERR_INVALID, 0, "not a finite number");
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
    for (size_t i = 0; i < pos; i++) { /* a NUL byte is a column too */
        if (text[i] == '\n') {
            (*line)++;
            *col = 1;
        } else {
            (*col)++;
        }
    }
}

/* ---- Strictness of the whole document ---------------------------------- */

/* A JSON path built in place: components are appended on the way down and
 * cut off on the way back, so the walk needs one buffer, not one per level.
 * A path longer than the buffer is cut (the message still names its start). */
typedef struct {
    char text[IC_ERROR_PATH_LEN];
    size_t len;
} json_path;

static size_t path_key(json_path *p, const char *key)
{
    const size_t old = p->len;
    snprintf(p->text + old, sizeof p->text - old, old ? ".%s" : "%s", key ? key : "");
    p->len = strlen(p->text);
    return old;
}

/* An array's element; "(root)[i]" when the document itself is the array. */
static size_t path_index(json_path *p, int i)
{
    const size_t old = p->len;
    snprintf(p->text + old, sizeof p->text - old, "%s[%d]", old ? "" : "(root)", i);
    p->len = strlen(p->text);
    return old;
}

static void path_cut(json_path *p, size_t len)
{
    p->len = len;
    p->text[len] = '\0';
}

/* The child's component of the path: its key in an object, else its index. */
static size_t path_child(json_path *p, const cJSON *parent, const cJSON *child, int index)
{
    return cJSON_IsObject(parent) ? path_key(p, child->string) : path_index(p, index);
}

static ic_status path_error(ic_error *err, const json_path *p, const char *msg)
{
    ic_error_set_path(err, "%s", p->len ? p->text : "(root)");
    return ic_error_set(err, IC_ERR_INVALID, 0, "%s", msg);
}

/* Where the text breaks the NUL rule: the index (in document order) of the
 * first string holding a NUL, or the offset of a raw NUL outside strings.
 * The text is valid JSON (cJSON parsed it), so a quote outside a string
 * always opens one and a backslash inside one always starts an escape. */
typedef struct {
    long string;  /* -1: none */
    size_t where; /* offset of the NUL (raw or the escape's backslash) */
    int raw;      /* 1 for a raw NUL byte */
} nul_place;

static int is_nul_escape(const char *s, size_t i, size_t len)
{
    return i + 5 < len && s[i + 1] == 'u' && memcmp(s + i + 2, "0000", 4) == 0;
}

static int find_nul(const char *text, size_t len, nul_place *out)
{
    long strings = 0;
    int inside = 0;
    for (size_t i = 0; i < len; i++) {
        const char c = text[i];
        if (c == '\0' || (inside && c == '\\' && is_nul_escape(text, i, len))) {
            out->string = inside ? strings - 1 : -1;
            out->where = i;
            out->raw = c == '\0';
            return 1;
        }
        if (inside && c == '\\')
            i++; /* the escaped character cannot close the string */
        else if (c == '"') {
            inside = !inside;
            strings += inside;
        }
    }
    return 0;
}

/* The path of the n-th string of the document (keys count, before their
 * values); *is_key tells which. 1 when found. */
static int nth_string(const cJSON *item, long *n, json_path *p, int *is_key)
{
    if (cJSON_IsString(item) && (*n)-- == 0) {
        *is_key = 0;
        return 1;
    }
    int i = 0;
    for (const cJSON *c = item->child; c; c = c->next, i++) {
        const size_t old = path_child(p, item, c, i);
        if (cJSON_IsObject(item) && (*n)-- == 0) {
            *is_key = 1;
            return 1;
        }
        if (nth_string(c, n, p, is_key))
            return 1;
        path_cut(p, old);
    }
    return 0;
}

static ic_status check_nul(const cJSON *root, const char *text, size_t len, ic_error *err)
{
    nul_place at;
    if (!find_nul(text, len, &at))
        return IC_OK;
    json_path p = {"", 0};
    int is_key = 0;
    long n = at.string;
    char msg[120];
    snprintf(msg, sizeof msg, "%s: it would cut the text short there",
             at.raw ? "a NUL byte inside a string" : "a NUL character (\\u0000) inside a string");
    if (at.string >= 0 && nth_string(root, &n, &p, &is_key)) {
        if (is_key)
            snprintf(msg, sizeof msg, "%s inside a key: it would cut the key short there",
                     at.raw ? "a NUL byte" : "a NUL character (\\u0000)");
        return path_error(err, &p, msg);
    }
    /* outside strings (or, never expected, a string the tree lacks): where */
    int line, col;
    ic_json_line_col(text, at.where, &line, &col);
    ic_error_set_path(err, "(line %d, column %d)", line, col);
    return ic_error_set(err, IC_ERR_INVALID, 0, "%s",
                        at.string < 0 ? "a NUL byte outside any string: a problem file is text"
                                      : msg);
}

static int compare_keys(const void *a, const void *b)
{
    return strcmp(*(const char *const *)a, *(const char *const *)b);
}

/* The first duplicate key of an object (in sorted order), or NULL; sorting
 * keeps a 16 MB object of single keys from taking quadratic time. */
static ic_status duplicate_key(const cJSON *obj, const char **dup, ic_error *err)
{
    *dup = NULL;
    size_t n = 0;
    for (const cJSON *c = obj->child; c; c = c->next)
        n++;
    if (n < 2)
        return IC_OK;
    const char **keys = malloc(n * sizeof *keys);
    if (!keys)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory checking a problem's keys");
    size_t k = 0;
    for (const cJSON *c = obj->child; c; c = c->next)
        keys[k++] = c->string ? c->string : "";
    qsort(keys, n, sizeof *keys, compare_keys);
    for (k = 1; k < n && !*dup; k++)
        if (strcmp(keys[k - 1], keys[k]) == 0)
            *dup = keys[k];
    free(keys);
    return IC_OK;
}

/* Duplicate keys and non-finite numbers, depth first in document order. */
static ic_status check_values(const cJSON *item, json_path *p, ic_error *err)
{
    if (cJSON_IsNumber(item) && !isfinite(item->valuedouble))
        return path_error(err, p, "not a finite number (beyond the largest double, about 1.8e308)");
    if (cJSON_IsObject(item)) {
        const char *dup;
        ic_status st = duplicate_key(item, &dup, err);
        if (st != IC_OK)
            return st;
        if (dup) {
            char msg[IC_ERROR_MESSAGE_LEN];
            snprintf(msg, sizeof msg, "duplicate key \"%s\": a key may appear once in an object",
                     dup);
            path_key(p, dup);
            return path_error(err, p, msg);
        }
    }
    int i = 0;
    for (const cJSON *c = item->child; c; c = c->next, i++) {
        const size_t old = path_child(p, item, c, i);
        ic_status st = check_values(c, p, err);
        if (st != IC_OK)
            return st;
        path_cut(p, old);
    }
    return IC_OK;
}

ic_status ic_json_check_document(const cJSON *root, const char *text, size_t len, ic_error *err)
{
    ic_status st = check_nul(root, text, len, err);
    if (st != IC_OK)
        return st;
    json_path p = {"", 0};
    return check_values(root, &p, err);
}
