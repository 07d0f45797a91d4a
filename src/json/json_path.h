/* Helpers for reading JSON values with errors that name their path. */
#ifndef IC_JSON_PATH_H
#define IC_JSON_PATH_H

#include <cjson/cJSON.h>

#include "intercurve/common.h"

/* Fails with "<path>: <what>" if `item` has a key outside allowed[]
 * (NULL-terminated). */
ic_status ic_json_check_keys(const cJSON *obj, const char *path, const char *const *allowed,
                             ic_error *err);

/* A number, or a string holding a formula of constants ("2*pi"); a value
 * that is not finite is an error ("not a finite number"). */
ic_status ic_json_number(double *out, const cJSON *item, const char *path,
                         const ic_constant *consts, int nconsts, ic_error *err);

/* An array of exactly n numbers-or-formulas. */
ic_status ic_json_numbers(double *out, int n, const cJSON *item, const char *path,
                          const ic_constant *consts, int nconsts, ic_error *err);

/* Sets err's path and message for a formula error: the message gets the
 * caret picture of `formula` appended. Returns err's code. */
ic_status ic_json_formula_error(ic_error *err, const char *path, const char *formula);

/* The rules of the whole document (docs/problem-files.md), checked before
 * any key is read: no NUL in any string (a "\u0000" escape or a raw byte;
 * cJSON would cut the string there) nor anywhere in text[0, len), no key
 * twice in one object (cJSON keeps both, lookups take the first), no number
 * that is not finite (cJSON reads 1e400 as inf). text is what cJSON parsed
 * into root. Errors name the JSON path, or the line and column of a raw
 * NUL outside strings. */
ic_status ic_json_check_document(const cJSON *root, const char *text, size_t len, ic_error *err);

/* Line and column (1-based) of byte offset `pos` in text. */
void ic_json_line_col(const char *text, size_t pos, int *line, int *col);

#endif
