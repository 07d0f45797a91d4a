/* Command-line argument helpers. */
#include "cli.h"

#include <stdlib.h>
#include <string.h>

int ic_cli_parse_list(double *out, int max, const char *text, const char *option)
{
    int count = 0, depth = 0;
    const char *start = text;
    for (const char *c = text;; c++) {
        if (*c == '(')
            depth++;
        else if (*c == ')')
            depth--;
        if ((*c == ',' && depth == 0) || *c == '\0') {
            if (count == max) {
                fprintf(stderr, "intercurve: %s takes at most %d values, got more in '%s'\n",
                        option, max, text);
                return -1;
            }
            char item[256];
            size_t len = (size_t)(c - start);
            if (len >= sizeof item) {
                fprintf(stderr, "intercurve: %s: value too long\n", option);
                return -1;
            }
            memcpy(item, start, len);
            item[len] = '\0';
            ic_error err;
            ic_error_clear(&err);
            if (ic_expr_eval_constant(&out[count], item, NULL, 0, &err) != IC_OK) {
                char caret[200];
                fprintf(stderr, "intercurve: %s, value %d ('%s'), column %d: %s\n%s", option,
                        count + 1, item, err.column, err.message,
                        ic_expr_caret(caret, sizeof caret, item, err.column));
                return -1;
            }
            count++;
            if (*c == '\0')
                break;
            start = c + 1;
        }
    }
    return count;
}

int ic_cli_parse_int(int *out, const char *text, int lo, int hi, const char *option)
{
    char *end = NULL;
    long v = strtol(text, &end, 10);
    if (!text[0] || *end != '\0' || v < lo || v > hi) {
        fprintf(stderr, "intercurve: %s expects a whole number from %d to %d, got '%s'\n", option,
                lo, hi, text);
        return -1;
    }
    *out = (int)v;
    return 0;
}

void ic_cli_print_error(const char *file, const ic_error *err)
{
    fprintf(stderr, "intercurve: ");
    if (file)
        fprintf(stderr, "%s: ", file);
    if (err->path[0])
        fprintf(stderr, "%s: ", err->path);
    if (err->column > 0)
        fprintf(stderr, "column %d: ", err->column);
    fprintf(stderr, "%s", err->message);
    const size_t len = strlen(err->message);
    if (len == 0 || err->message[len - 1] != '\n')
        fputc('\n', stderr);
}
