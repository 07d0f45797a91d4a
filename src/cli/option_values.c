/* One option's value, read and checked against its table entry
 * (options.h). Every message names the command and the option. */
#include "cli/options.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "intercurve.h"

void ic_cli_format_bound(char *out, size_t size, double x)
{
    char buf[32];
    snprintf(buf, sizeof buf, "%g", x);
    char *e = strchr(buf, 'e');
    if (e) { /* "1e+06" -> "1e6", "1e-06" -> "1e-6" */
        char *digits = e + 1;
        const int negative = *digits == '-';
        if (*digits == '+' || *digits == '-')
            digits++;
        while (digits[0] == '0' && digits[1])
            digits++;
        snprintf(out, size, "%.*s%s%s", (int)(e - buf + 1), buf, negative ? "-" : "", digits);
    } else {
        snprintf(out, size, "%s", buf);
    }
}

/* One number of a list, a formula of constants ("pi/2"). */
static int read_number(double *out, const char *cmd, const char *option, const char *item,
                       int index)
{
    ic_error err;
    ic_error_clear(&err);
    if (ic_expr_eval_constant(out, item, NULL, 0, &err) == IC_OK)
        return 0;
    char caret[200];
    fprintf(stderr, "intercurve %s: %s, value %d ('%s'), column %d: %s\n%s", cmd, option, index + 1,
            item, err.column, err.message, ic_expr_caret(caret, sizeof caret, item, err.column));
    return -1;
}

/* "a,b[,c]" into out[max], split at the commas outside parentheses;
 * the count, or -1 after a message. */
static int read_list(double *out, int max, const char *cmd, const char *option, const char *text)
{
    int count = 0, depth = 0;
    const char *start = text;
    for (const char *c = text;; c++) {
        depth += (*c == '(') - (*c == ')');
        if ((*c != ',' || depth != 0) && *c != '\0')
            continue;
        if (count == max) {
            fprintf(stderr, "intercurve %s: %s takes at most %d values, got more in '%s'\n", cmd,
                    option, max, text);
            return -1;
        }
        char item[256];
        const size_t len = (size_t)(c - start);
        if (len >= sizeof item) {
            fprintf(stderr, "intercurve %s: %s: value %d too long\n", cmd, option, count + 1);
            return -1;
        }
        memcpy(item, start, len);
        item[len] = '\0';
        if (read_number(&out[count], cmd, option, item, count) < 0)
            return -1;
        count++;
        if (*c == '\0')
            return count;
        start = c + 1;
    }
}

static int read_int(const char *cmd, const ic_cli_option *opt, const char *text, ic_cli_value *v)
{
    char *end = NULL;
    const long x = strtol(text, &end, 10);
    if (!text[0] || *end != '\0' || x < opt->lo || x > opt->hi) {
        fprintf(stderr, "intercurve %s: %s expects a whole number from %.0f to %.0f, got '%s'\n",
                cmd, opt->name, opt->lo, opt->hi, text);
        return -1;
    }
    v->integer = x;
    return 0;
}

static int read_real(const char *cmd, const ic_cli_option *opt, const char *text, ic_cli_value *v)
{
    double x;
    if (read_list(&x, 1, cmd, opt->name, text) != 1)
        return -1;
    if (!(x > opt->lo && x <= opt->hi)) {
        char lo[32], hi[32];
        ic_cli_format_bound(lo, sizeof lo, opt->lo);
        ic_cli_format_bound(hi, sizeof hi, opt->hi);
        if (isinf(opt->hi))
            fprintf(stderr, "intercurve %s: %s expects %s > %s, got '%s'\n", cmd, opt->name,
                    opt->metavar, lo, text);
        else
            fprintf(stderr, "intercurve %s: %s expects %s in (%s, %s], got '%s'\n", cmd, opt->name,
                    opt->metavar, lo, hi, text);
        return -1;
    }
    v->real = x;
    return 0;
}

void ic_cli_choices_text(char *out, size_t size, const char *choices)
{
    size_t k = 0;
    for (const char *c = choices; *c && k + 3 < size; c++) {
        if (*c == '|') {
            out[k++] = ',';
            out[k++] = ' ';
        } else {
            out[k++] = *c;
        }
    }
    out[k] = '\0';
}

static int read_choice(const char *cmd, const ic_cli_option *opt, const char *text, ic_cli_value *v)
{
    const size_t n = strlen(text);
    int index = 0;
    for (const char *c = opt->choices; *c; index++) {
        const size_t len = strcspn(c, "|");
        if (len == n && strncmp(c, text, n) == 0) {
            v->choice = index;
            return 0;
        }
        c += len + (c[len] == '|');
    }
    char list[256];
    ic_cli_choices_text(list, sizeof list, opt->choices);
    fprintf(stderr,
            "intercurve %s: %s %s is not one of %s\n"
            "intercurve %s: %s expects one of these values\n",
            cmd, opt->name, text, list, cmd, opt->name);
    return -1;
}

static int read_list_option(const char *cmd, const ic_cli_option *opt, const char *text,
                            ic_cli_value *v)
{
    const int count = read_list(v->list, (int)opt->hi, cmd, opt->name, text);
    if (count < 0)
        return -1;
    if (count < opt->lo) {
        fprintf(stderr, "intercurve %s: %s expects %s, got %d value%s\n", cmd, opt->name,
                opt->metavar, count, count == 1 ? "" : "s");
        return -1;
    }
    v->count = count;
    return 0;
}

static int read_size(const char *cmd, const ic_cli_option *opt, const char *text, ic_cli_value *v)
{
    int w, h;
    char tail;
    if (sscanf(text, "%dx%d%c", &w, &h, &tail) != 2 || w < opt->lo || w > opt->hi || h < opt->lo2 ||
        h > opt->hi) {
        fprintf(stderr,
                "intercurve %s: %s expects WxH, W in %.0f..%.0f and H in %.0f..%.0f (got '%s')\n",
                cmd, opt->name, opt->lo, opt->hi, opt->lo2, opt->hi, text);
        return -1;
    }
    v->width = w, v->height = h;
    return 0;
}

int ic_cli_read_value(const char *cmd, const ic_cli_option *opt, const char *text, ic_cli_value *v)
{
    v->text = text;
    switch (opt->kind) {
    case IC_OPT_FLAG:
        v->integer = 1;
        return 0;
    case IC_OPT_TEXT:
        return 0;
    case IC_OPT_CHOICE:
        return read_choice(cmd, opt, text, v);
    case IC_OPT_INT:
        return read_int(cmd, opt, text, v);
    case IC_OPT_REAL:
        return read_real(cmd, opt, text, v);
    case IC_OPT_LIST:
        return read_list_option(cmd, opt, text, v);
    case IC_OPT_SIZE:
        return read_size(cmd, opt, text, v);
    }
    return -1;
}
