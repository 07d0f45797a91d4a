/* The caret picture of an error position in a formula. */
#include "intercurve/expr.h"

#include <stdio.h>
#include <string.h>

char *ic_expr_caret(char *buf, size_t size, const char *formula, int column)
{
    if (!buf || size == 0)
        return buf;
    if (!formula) {
        buf[0] = '\0';
        return buf;
    }
    const int len = (int)strlen(formula);
    const int width = 70; /* characters of the formula shown at most */
    int from = 0;
    if (column < 1)
        column = 1;
    if (column > len + 1)
        column = len + 1;
    if (len > width && column > width / 2)
        from = column - width / 2;
    int shown = len - from < width ? len - from : width;
    const char *pre = from > 0 ? "..." : "";
    const char *post = from + shown < len ? "..." : "";
    int pad = (int)strlen(pre) + column - 1 - from;
    snprintf(buf, size, "  %s%.*s%s\n  %*s^\n", pre, shown, formula + from, post, pad, "");
    return buf;
}
