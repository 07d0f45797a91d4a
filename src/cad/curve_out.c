/* Numbers, text and checks shared by the STEP and IGES curve writers. */
#include "cad/curve_out.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

void ic_curve_real(char out[IC_CURVE_REAL_SIZE], double x)
{
    char digits[IC_CURVE_REAL_SIZE];
    snprintf(digits, sizeof digits, "%.17g", x == 0 ? 0.0 : x); /* -0 as 0 */
    const size_t mantissa = strcspn(digits, "eE");
    const int has_point = memchr(digits, '.', mantissa) != NULL;
    snprintf(out, IC_CURVE_REAL_SIZE, "%.*s%s", (int)mantissa, digits, has_point ? "" : ".");
    if (digits[mantissa]) { /* the exponent, as E */
        const size_t used = strlen(out);
        snprintf(out + used, IC_CURVE_REAL_SIZE - used, "E%s", digits + mantissa + 1);
    }
}

void ic_curve_ascii(char *out, size_t size, const char *s)
{
    size_t n = 0;
    for (; s && s[n] && n + 1 < size; n++)
        out[n] = s[n] >= 32 && s[n] < 127 ? s[n] : '?';
    if (size)
        out[n] = '\0';
}

int ic_curve_knot_run(const ic_bspline *b, int i)
{
    const int nknots = b->ncontrol + b->degree + 1;
    int k = i + 1;
    while (k < nknots && b->knots[k] == b->knots[i])
        k++;
    return k - i;
}

static int all_finite(const double *x, int n)
{
    for (int k = 0; k < n; k++)
        if (!isfinite(x[k]))
            return 0;
    return 1;
}

ic_status ic_curve_check_fits(const ic_trace_result *res, const char *format, ic_error *err)
{
    int fitted = 0;
    for (int i = 0; i < ic_trace_result_num_curves(res); i++) {
        const ic_curve_fit *fit = ic_trace_result_fit(res, i);
        if (!fit)
            continue;
        const ic_bspline *b = &fit->curve;
        if (b->dim != 3 || b->degree < 1 || b->ncontrol < b->degree + 1 ||
            !all_finite(b->knots, b->ncontrol + b->degree + 1) ||
            !all_finite(b->control, 3 * b->ncontrol))
            return ic_error_set(err, IC_ERR_INVALID, 0,
                                "%s output: curve %d's B-spline is malformed or not finite", format,
                                i);
        fitted++;
    }
    if (fitted == 0)
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            "%s output: no curve has a B-spline; fit the curves first "
                            "(ic_trace_fit)",
                            format);
    return IC_OK;
}

void ic_curve_time_stamp(char *out, size_t size, const char *format)
{
    const time_t now = time(NULL);
    struct tm utc;
    if (!gmtime_r(&now, &utc) || strftime(out, size, format, &utc) == 0)
        ic_curve_ascii(out, size, "");
}
