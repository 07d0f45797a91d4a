/*
 * Interval arithmetic with outward rounding.
 *
 * Every bound computed in floating point is pushed outward: by one ulp after
 * a correctly rounded operation (+ - * / sqrt), by four ulps after a libm
 * function (glibc documents errors of at most a few ulps for exp, log, sin,
 * pow, ...). An interval is empty when !(lo <= hi); a function applied to an
 * interval encloses its values on the part of the interval where it is
 * defined (sqrt([-1, 4]) = [0, 2]), and is empty if that part is empty.
 */
#include "expr_internal.h"
#include "common/mathconst.h"

#include <float.h>
#include <math.h>

#define LIBM_ULPS 4.0

static const ic_interval EMPTY = {NAN, NAN};
static const ic_interval ENTIRE = {-INFINITY, INFINITY};

int ic_interval_is_empty(ic_interval a) { return !(a.lo <= a.hi); }

/* Moves x down (up) by at least k ulps. A lower bound that overflowed to
 * +inf stands for a finite value above DBL_MAX, so it becomes DBL_MAX (and
 * an upper bound of -inf becomes -DBL_MAX): [inf, inf] would enclose no real
 * number, and an interval built on it could exclude zero wrongly. */
static double down(double x, double k)
{
    if (isinf(x))
        return x > 0 ? DBL_MAX : x;
    return x - k * fabs(x) * DBL_EPSILON - DBL_TRUE_MIN;
}

static double up(double x, double k)
{
    if (isinf(x))
        return x < 0 ? -DBL_MAX : x;
    return x + k * fabs(x) * DBL_EPSILON + DBL_TRUE_MIN;
}

/* [lo, hi] widened outward. A NaN bound (inf - inf, after an overflow)
 * means that bound is unknown: it becomes infinite, never empty, since an
 * empty interval proves that no value exists. */
static ic_interval make(double lo, double hi, double k)
{
    ic_interval r = {isnan(lo) ? -INFINITY : down(lo, k), isnan(hi) ? INFINITY : up(hi, k)};
    return r;
}

static ic_interval clamp(ic_interval a, double lo, double hi)
{
    if (a.lo < lo)
        a.lo = lo;
    if (a.hi > hi)
        a.hi = hi;
    return a;
}

ic_interval ic_interval_add(ic_interval a, ic_interval b)
{
    if (ic_interval_is_empty(a) || ic_interval_is_empty(b))
        return EMPTY;
    return make(a.lo + b.lo, a.hi + b.hi, 1.0);
}

ic_interval ic_interval_neg(ic_interval a)
{
    ic_interval r = {-a.hi, -a.lo};
    return ic_interval_is_empty(a) ? EMPTY : r;
}

ic_interval ic_interval_sub(ic_interval a, ic_interval b)
{
    return ic_interval_add(a, ic_interval_neg(b));
}

/* x * y where 0 * inf counts as 0 (an infinite bound is not a value). */
static double mul0(double x, double y)
{
    double p = x * y;
    return isnan(p) ? 0.0 : p;
}

ic_interval ic_interval_mul(ic_interval a, ic_interval b)
{
    if (ic_interval_is_empty(a) || ic_interval_is_empty(b))
        return EMPTY;
    double p[4] = {mul0(a.lo, b.lo), mul0(a.lo, b.hi), mul0(a.hi, b.lo), mul0(a.hi, b.hi)};
    double lo = p[0], hi = p[0];
    for (int i = 1; i < 4; i++) {
        lo = fmin(lo, p[i]);
        hi = fmax(hi, p[i]);
    }
    return make(lo, hi, 1.0);
}

ic_interval ic_interval_div(ic_interval a, ic_interval b)
{
    if (ic_interval_is_empty(a) || ic_interval_is_empty(b))
        return EMPTY;
    if (b.lo == 0.0 && b.hi == 0.0)
        return EMPTY; /* division by zero everywhere: undefined */
    if (b.lo < 0.0 && b.hi > 0.0)
        return ENTIRE;
    /* b in [0, h] or [l, 0] or away from 0: reciprocal, infinite at 0. */
    ic_interval rb;
    rb.lo = b.hi == 0.0 ? -INFINITY : down(1.0 / b.hi, 1.0);
    rb.hi = b.lo == 0.0 ? INFINITY : up(1.0 / b.lo, 1.0);
    return ic_interval_mul(a, rb);
}

ic_interval ic_interval_sqrt(ic_interval a)
{
    if (ic_interval_is_empty(a) || a.hi < 0.0)
        return EMPTY;
    double lo = a.lo > 0.0 ? down(sqrt(a.lo), 1.0) : 0.0;
    return (ic_interval){lo < 0.0 ? 0.0 : lo, up(sqrt(a.hi), 1.0)};
}

ic_interval ic_interval_exp(ic_interval a)
{
    if (ic_interval_is_empty(a))
        return EMPTY;
    ic_interval r = make(exp(a.lo), exp(a.hi), LIBM_ULPS);
    if (r.lo < 0.0)
        r.lo = 0.0;
    return r;
}

ic_interval ic_interval_log(ic_interval a)
{
    if (ic_interval_is_empty(a) || a.hi <= 0.0)
        return EMPTY;
    double lo = a.lo > 0.0 ? down(log(a.lo), LIBM_ULPS) : -INFINITY;
    return (ic_interval){lo, up(log(a.hi), LIBM_ULPS)};
}

ic_interval ic_interval_pow_int(ic_interval a, long n)
{
    if (ic_interval_is_empty(a))
        return EMPTY;
    if (n == 0)
        return (ic_interval){1.0, 1.0};
    if (n < 0)
        return ic_interval_div((ic_interval){1.0, 1.0}, ic_interval_pow_int(a, -n));
    if (n == 1)
        return a;
    /* small powers by products (each correctly rounded: n - 1 ulps), the
     * others by pow (LIBM_ULPS) */
    double pl, ph, ulps;
    if (n <= 4) {
        pl = a.lo, ph = a.hi;
        for (long k = 1; k < n; k++)
            pl *= a.lo, ph *= a.hi;
        ulps = (double)(n - 1);
    } else {
        pl = pow(a.lo, (double)n), ph = pow(a.hi, (double)n);
        ulps = LIBM_ULPS;
    }
    /* in the subnormal range each product may err by half a subnormal */
    const double tiny = 2.0 * (double)n * DBL_TRUE_MIN;
    if (n % 2 == 1 || a.lo >= 0.0)
        return make(pl - tiny, ph + tiny, ulps);
    if (a.hi <= 0.0)
        return make(ph - tiny, pl + tiny, ulps);
    return (ic_interval){0.0, up(fmax(pl, ph) + tiny, ulps)};
}

ic_interval ic_interval_pow_real(ic_interval a, double p)
{
    if (ic_interval_is_empty(a) || a.hi < 0.0)
        return EMPTY;
    const double lo = a.lo < 0.0 ? 0.0 : a.lo;
    ic_interval r = p > 0.0 ? make(pow(lo, p), pow(a.hi, p), LIBM_ULPS)
                            : make(pow(a.hi, p), pow(lo, p), LIBM_ULPS);
    if (r.lo < 0.0)
        r.lo = 0.0;
    return r;
}

ic_interval ic_interval_pow(ic_interval a, ic_interval b)
{
    /* a^b = exp(b log a), defined for a > 0 */
    return ic_interval_exp(ic_interval_mul(b, ic_interval_log(a)));
}

/* 1 if [lo, hi] may contain a point offset + k * period for an integer k.
 * Conservative: answers 1 when rounding makes the question undecidable. */
static int may_contain(double lo, double hi, double offset, double period)
{
    const double a = (lo - offset) / period, b = (hi - offset) / period;
    const double slack = 1e-9 + 4.0 * DBL_EPSILON * fmax(fabs(a), fabs(b));
    return floor(b + slack) >= ceil(a - slack);
}

/* Range of a function with maxima at max_at + 2 pi k and minima at
 * max_at + pi + 2 pi k (sin: pi/2, cos: 0). */
static ic_interval periodic_range(ic_interval a, double (*f)(double), double max_at)
{
    if (ic_interval_is_empty(a))
        return EMPTY;
    if (!(a.hi - a.lo < 2.0 * IC_PI) || fabs(a.lo) > 1e15 || fabs(a.hi) > 1e15)
        return (ic_interval){-1.0, 1.0};
    const double fl = f(a.lo), fh = f(a.hi);
    ic_interval r = make(fmin(fl, fh), fmax(fl, fh), LIBM_ULPS);
    if (may_contain(a.lo, a.hi, max_at, 2.0 * IC_PI))
        r.hi = 1.0;
    if (may_contain(a.lo, a.hi, max_at + IC_PI, 2.0 * IC_PI))
        r.lo = -1.0;
    return clamp(r, -1.0, 1.0);
}

ic_interval ic_interval_sin(ic_interval a) { return periodic_range(a, sin, 0.5 * IC_PI); }
ic_interval ic_interval_cos(ic_interval a) { return periodic_range(a, cos, 0.0); }

ic_interval ic_interval_tan(ic_interval a)
{
    if (ic_interval_is_empty(a))
        return EMPTY;
    if (!(a.hi - a.lo < IC_PI) || fabs(a.lo) > 1e15 || fabs(a.hi) > 1e15 ||
        may_contain(a.lo, a.hi, 0.5 * IC_PI, IC_PI))
        return ENTIRE;
    return make(tan(a.lo), tan(a.hi), LIBM_ULPS);
}

ic_interval ic_interval_asin(ic_interval a)
{
    if (ic_interval_is_empty(a) || a.hi < -1.0 || a.lo > 1.0)
        return EMPTY;
    a = clamp(a, -1.0, 1.0);
    return clamp(make(asin(a.lo), asin(a.hi), LIBM_ULPS), -up(0.5 * IC_PI, 1.0),
                 up(0.5 * IC_PI, 1.0));
}

ic_interval ic_interval_acos(ic_interval a)
{
    if (ic_interval_is_empty(a) || a.hi < -1.0 || a.lo > 1.0)
        return EMPTY;
    a = clamp(a, -1.0, 1.0);
    return clamp(make(acos(a.hi), acos(a.lo), LIBM_ULPS), 0.0, up(IC_PI, 1.0));
}

ic_interval ic_interval_atan(ic_interval a)
{
    if (ic_interval_is_empty(a))
        return EMPTY;
    return make(atan(a.lo), atan(a.hi), LIBM_ULPS);
}

/* atan2 over a box: where the box holds the origin or meets the branch cut
 * (x <= 0, y = 0) the whole range; elsewhere the angle is monotone along
 * every edge, so its extremes are at the corners. */
ic_interval ic_interval_atan2(ic_interval y, ic_interval x)
{
    if (ic_interval_is_empty(y) || ic_interval_is_empty(x))
        return EMPTY;
    const double pi_up = up(IC_PI, 1.0);
    if (y.lo <= 0.0 && y.hi >= 0.0 && x.lo <= 0.0)
        return (ic_interval){-pi_up, pi_up};
    const double c[4] = {atan2(y.lo, x.lo), atan2(y.lo, x.hi), atan2(y.hi, x.lo),
                         atan2(y.hi, x.hi)};
    double lo = c[0], hi = c[0];
    for (int i = 1; i < 4; i++) {
        lo = fmin(lo, c[i]);
        hi = fmax(hi, c[i]);
    }
    return clamp(make(lo, hi, LIBM_ULPS), -pi_up, pi_up);
}

ic_interval ic_interval_sinh(ic_interval a)
{
    if (ic_interval_is_empty(a))
        return EMPTY;
    return make(sinh(a.lo), sinh(a.hi), LIBM_ULPS);
}

ic_interval ic_interval_cosh(ic_interval a)
{
    if (ic_interval_is_empty(a))
        return EMPTY;
    const double cl = cosh(a.lo), ch = cosh(a.hi);
    if (a.lo <= 0.0 && a.hi >= 0.0)
        return (ic_interval){1.0, up(fmax(cl, ch), LIBM_ULPS)};
    ic_interval r = make(fmin(cl, ch), fmax(cl, ch), LIBM_ULPS);
    if (r.lo < 1.0)
        r.lo = 1.0;
    return r;
}

ic_interval ic_interval_tanh(ic_interval a)
{
    if (ic_interval_is_empty(a))
        return EMPTY;
    return clamp(make(tanh(a.lo), tanh(a.hi), LIBM_ULPS), -1.0, 1.0);
}

ic_interval ic_interval_abs(ic_interval a)
{
    if (ic_interval_is_empty(a))
        return EMPTY;
    if (a.lo >= 0.0)
        return a;
    if (a.hi <= 0.0)
        return ic_interval_neg(a);
    return (ic_interval){0.0, fmax(-a.lo, a.hi)};
}

size_t ic_expr_interval_work_len(const ic_expr *e) { return e ? (size_t)e->len : 0; }

ic_interval ic_interval_op(const ic_instr *in, ic_interval a, ic_interval b)
{
    switch (in->op) {
    case OP_CONST:
        return (ic_interval){in->c, in->c};
    case OP_VAR:
        return a;
    case OP_ADD:
        return ic_interval_add(a, b);
    case OP_SUB:
        return ic_interval_sub(a, b);
    case OP_MUL:
        return ic_interval_mul(a, b);
    case OP_DIV:
        return ic_interval_div(a, b);
    case OP_NEG:
        return ic_interval_neg(a);
    case OP_POWI:
        return ic_interval_pow_int(a, in->n);
    case OP_POWR:
        return ic_interval_pow_real(a, in->c);
    case OP_POW:
        return ic_interval_pow(a, b);
    case OP_SQRT:
        return ic_interval_sqrt(a);
    case OP_EXP:
        return ic_interval_exp(a);
    case OP_LOG:
        return ic_interval_log(a);
    case OP_SIN:
        return ic_interval_sin(a);
    case OP_COS:
        return ic_interval_cos(a);
    case OP_TAN:
        return ic_interval_tan(a);
    case OP_ASIN:
        return ic_interval_asin(a);
    case OP_ACOS:
        return ic_interval_acos(a);
    case OP_ATAN:
        return ic_interval_atan(a);
    case OP_ATAN2:
        return ic_interval_atan2(a, b);
    case OP_SINH:
        return ic_interval_sinh(a);
    case OP_COSH:
        return ic_interval_cosh(a);
    case OP_TANH:
        return ic_interval_tanh(a);
    case OP_ABS:
        return ic_interval_abs(a);
    case OP_COUNT:
        break;
    }
    return ENTIRE;
}

int ic_interval_op_defined(const ic_instr *in, ic_interval a, ic_interval b)
{
    const int holds0 = a.lo <= 0.0 && a.hi >= 0.0;
    switch (in->op) {
    case OP_DIV:
        return !(b.lo <= 0.0 && b.hi >= 0.0);
    case OP_POWI:
        return in->n >= 0 || !holds0;
    case OP_POWR:
        return in->c > 0.0 ? a.lo >= 0.0 : a.lo > 0.0;
    case OP_POW:
    case OP_LOG:
        return a.lo > 0.0;
    case OP_SQRT:
        return a.lo >= 0.0;
    case OP_ASIN:
    case OP_ACOS:
        return a.lo >= -1.0 && a.hi <= 1.0;
    case OP_TAN:
        return !(a.hi - a.lo < IC_PI) || fabs(a.lo) > 1e15 || fabs(a.hi) > 1e15
                   ? 0
                   : !may_contain(a.lo, a.hi, 0.5 * IC_PI, IC_PI);
    case OP_ATAN2: /* a = y, b = x: undefined at the origin */
        return !(holds0 && b.lo <= 0.0 && b.hi >= 0.0);
    default:
        return 1;
    }
}

void ic_expr_eval_interval(const ic_expr *e, ic_interval *out, const ic_interval *x,
                           ic_interval *work)
{
    if (!e || !out || !x || !work)
        return;
    for (int i = 0; i < e->len; i++) {
        const ic_instr *in = &e->code[i];
        const ic_interval a = in->op == OP_VAR ? x[in->n] : in->a >= 0 ? work[in->a] : ENTIRE;
        const ic_interval b = in->b >= 0 ? work[in->b] : ENTIRE;
        work[i] = ic_interval_op(in, a, b);
    }
    for (int k = 0; k < e->noutputs; k++)
        out[k] = work[e->outputs[k]];
}
