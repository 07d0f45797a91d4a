/*
 * Enclosures of values, gradients and Hessians together (second-order
 * forward mode on intervals): each register holds the interval of its value
 * over the box, of its partials along up to IC_INTERVAL_GRAD_MAX directions
 * and of its second partials. The rules are the calculus ones in interval
 * arithmetic:
 *   a * b:   h = ha b + a hb + da db^T + db da^T,
 *   a / b:   h = (ha - r hb - dr db^T - db dr^T) / b   (from a = r b),
 *   op(a):   h = f'(a) ha + f''(a) da da^T,
 * and a^b as exp(b log a). So each entry encloses the second derivative at
 * every point of the box where the formula is twice differentiable.
 * Operations with no second derivative somewhere on the box (|x| across
 * 0) or none written here (atan2) leave the evaluation not whole: the
 * second-order forms of the exclusion tests (docs/tracing.md) then decide
 * nothing.
 */
#include "expr_internal.h"

#include <math.h>

static const ic_interval ZERO = {0.0, 0.0};

static ic_interval scalar(double c) { return (ic_interval){c, c}; }
static ic_interval sq(ic_interval a) { return ic_interval_pow_int(a, 2); }
static ic_interval mul(ic_interval a, ic_interval b) { return ic_interval_mul(a, b); }
static ic_interval add(ic_interval a, ic_interval b) { return ic_interval_add(a, b); }
static ic_interval sub(ic_interval a, ic_interval b) { return ic_interval_sub(a, b); }

size_t ic_expr_interval_hess_work_len(const ic_expr *e) { return e ? (size_t)e->len : 0; }

int ic_interval_hess_index(int j, int k)
{
    if (j > k) {
        const int t = j;
        j = k, k = t;
    }
    return j * (5 - j) / 2 + k;
}

/* f''(a) of a one-argument operation over the enclosure a, given v = op(a)
 * and f = f'(a); *defined = 0 where it has none written here. */
static ic_interval unary_second(const ic_instr *in, ic_interval a, ic_interval v, ic_interval f,
                                int *defined)
{
    switch (in->op) {
    case OP_NEG:
        return ZERO;
    case OP_POWI:
        return in->n == 0 || in->n == 1 ? ZERO
                                        : mul(scalar((double)in->n * (double)(in->n - 1)),
                                              ic_interval_pow_int(a, in->n - 2));
    case OP_POWR:
        return mul(scalar(in->c * (in->c - 1.0)), ic_interval_pow_real(a, in->c - 2.0));
    case OP_SQRT: /* -1 / (4 v^3) = -f' / (2 v^2) */
        return ic_interval_neg(ic_interval_div(f, mul(scalar(2.0), sq(v))));
    case OP_EXP:
        return v;
    case OP_LOG:
        return ic_interval_neg(sq(f));
    case OP_SIN:
        return ic_interval_neg(v);
    case OP_COS:
        return ic_interval_neg(v);
    case OP_TAN: /* 2 v (1 + v^2) */
        return mul(scalar(2.0), mul(v, f));
    case OP_ASIN: /* a (1 - a^2)^(-3/2) = a f'^3 */
        return mul(a, ic_interval_pow_int(f, 3));
    case OP_ACOS: /* -a (1 - a^2)^(-3/2) = a f'^3 (f' < 0) */
        return mul(a, ic_interval_pow_int(f, 3));
    case OP_ATAN: /* -2 a / (1 + a^2)^2 = -2 a f'^2 */
        return mul(scalar(-2.0), mul(a, sq(f)));
    case OP_SINH:
        return v;
    case OP_COSH:
        return v;
    case OP_TANH: /* -2 v (1 - v^2) */
        return mul(scalar(-2.0), mul(v, f));
    case OP_ABS:
        *defined = a.lo > 0.0 || a.hi < 0.0; /* a kink where a holds 0 */
        return ZERO;
    default:
        *defined = 0;
        return (ic_interval){-INFINITY, INFINITY};
    }
}

/* r = op(a) given its value r->v, f' and f'' over a. */
static void chain(ic_interval_hess *r, const ic_interval_hess *A, ic_interval f1, ic_interval f2,
                  int n)
{
    for (int j = 0; j < n; j++)
        r->d[j] = mul(f1, A->d[j]);
    for (int j = 0; j < n; j++)
        for (int k = j; k < n; k++) {
            const int i = ic_interval_hess_index(j, k);
            r->h[i] = add(mul(f1, A->h[i]), mul(f2, mul(A->d[j], A->d[k])));
        }
}

static void product(ic_interval_hess *r, const ic_interval_hess *A, const ic_interval_hess *B,
                    int n)
{
    r->v = mul(A->v, B->v);
    for (int j = 0; j < n; j++)
        r->d[j] = add(mul(A->d[j], B->v), mul(A->v, B->d[j]));
    for (int j = 0; j < n; j++)
        for (int k = j; k < n; k++) {
            const int i = ic_interval_hess_index(j, k);
            const ic_interval cross = add(mul(A->d[j], B->d[k]), mul(B->d[j], A->d[k]));
            r->h[i] = add(add(mul(A->h[i], B->v), mul(A->v, B->h[i])), cross);
        }
}

static void quotient(ic_interval_hess *r, const ic_interval_hess *A, const ic_interval_hess *B,
                     int n)
{
    r->v = ic_interval_div(A->v, B->v);
    for (int j = 0; j < n; j++) /* (da - r db) / b */
        r->d[j] = ic_interval_div(sub(A->d[j], mul(r->v, B->d[j])), B->v);
    for (int j = 0; j < n; j++)
        for (int k = j; k < n; k++) {
            const int i = ic_interval_hess_index(j, k);
            const ic_interval cross = add(mul(r->d[j], B->d[k]), mul(B->d[j], r->d[k]));
            r->h[i] = ic_interval_div(sub(sub(A->h[i], mul(r->v, B->h[i])), cross), B->v);
        }
}

static void sum(ic_interval_hess *r, const ic_interval_hess *A, const ic_interval_hess *B,
                double sign, int n)
{
    const ic_interval s = scalar(sign);
    r->v = add(A->v, mul(s, B->v));
    for (int j = 0; j < n; j++)
        r->d[j] = add(A->d[j], mul(s, B->d[j]));
    for (int i = 0; i < IC_INTERVAL_HESS_LEN; i++)
        r->h[i] = add(A->h[i], mul(s, B->h[i]));
}

/* One-argument operation; 0 where its second derivative is not written. */
static int unary(const ic_instr *in, ic_interval_hess *r, const ic_interval_hess *A, int n)
{
    r->v = ic_interval_op(in, A->v, ZERO);
    const ic_interval f1 = ic_interval_unary_factor(in, A->v, r->v);
    int defined = 1;
    const ic_interval f2 = unary_second(in, A->v, r->v, f1, &defined);
    chain(r, A, f1, f2, n);
    return defined;
}

/* a^b = exp(b log a), a > 0. */
static int power(ic_interval_hess *r, const ic_interval_hess *A, const ic_interval_hess *B, int n)
{
    const ic_instr log_in = {.op = OP_LOG, .a = -1, .b = -1},
                   exp_in = {.op = OP_EXP, .a = -1, .b = -1};
    ic_interval_hess L, P;
    const int ok = unary(&log_in, &L, A, n);
    product(&P, B, &L, n);
    return unary(&exp_in, r, &P, n) && ok;
}

static void constant(ic_interval_hess *r, double c) { *r = (ic_interval_hess){.v = scalar(c)}; }

/* One instruction; 0 where it has no second derivative written here. */
static int hess_op(const ic_instr *in, ic_interval_hess *r, const ic_interval_hess *A,
                   const ic_interval_hess *B, int n)
{
    switch (in->op) {
    case OP_CONST:
        constant(r, in->c);
        return 1;
    case OP_ADD:
        sum(r, A, B, 1.0, n);
        return 1;
    case OP_SUB:
        sum(r, A, B, -1.0, n);
        return 1;
    case OP_MUL:
        product(r, A, B, n);
        return 1;
    case OP_DIV:
        quotient(r, A, B, n);
        return 1;
    case OP_POW:
        return power(r, A, B, n);
    case OP_ATAN2:
        constant(r, 0.0);
        return 0;
    default:
        return unary(in, r, A, n);
    }
}

static int all_nonempty(const ic_interval_hess *r, int n)
{
    int ok = !ic_interval_is_empty(r->v);
    for (int j = 0; j < n; j++)
        ok = ok && !ic_interval_is_empty(r->d[j]);
    for (int j = 0; j < n; j++)
        for (int k = j; k < n; k++)
            ok = ok && !ic_interval_is_empty(r->h[ic_interval_hess_index(j, k)]);
    return ok;
}

int ic_expr_eval_interval_hess(const ic_expr *e, ic_interval_hess *out, const ic_interval_hess *x,
                               int ngrad, ic_interval_hess *work)
{
    if (!e || !out || !x || !work || ngrad < 0 || ngrad > IC_INTERVAL_GRAD_MAX)
        return 0;
    int whole = 1;
    for (int i = 0; i < e->len; i++) {
        const ic_instr *in = &e->code[i];
        if (in->op == OP_VAR) {
            work[i] = x[in->n];
            continue;
        }
        const ic_interval_hess *A = in->a >= 0 ? &work[in->a] : NULL;
        const ic_interval_hess *B = in->b >= 0 ? &work[in->b] : NULL;
        const ic_interval_hess zero = {.v = ZERO};
        whole = whole && ic_interval_op_defined(in, A ? A->v : ZERO, B ? B->v : ZERO);
        whole = hess_op(in, &work[i], A ? A : &zero, B ? B : &zero, ngrad) && whole;
        whole = whole && all_nonempty(&work[i], ngrad);
    }
    for (int k = 0; k < e->noutputs; k++)
        out[k] = work[e->outputs[k]];
    return whole;
}
