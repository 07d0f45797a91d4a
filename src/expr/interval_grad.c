/*
 * Enclosures of values and gradients together (forward mode on intervals):
 * each register holds the interval of its value over the box and the
 * intervals of its partial derivatives along up to IC_INTERVAL_GRAD_MAX
 * directions of differentiation. The derivative rules are the calculus ones evaluated in
 * interval arithmetic, so each partial encloses the derivative at every
 * point of the box where the formula is differentiable (|x| contributes
 * [-1, 1] times its argument's derivative where the argument holds 0). The
 * loop test of the tracer (normal cones) needs these.
 */
#include "expr_internal.h"

#include <math.h>
#include <string.h>

static const ic_interval ZERO = {0.0, 0.0};
static const ic_interval ONE = {1.0, 1.0};

static ic_interval scalar(double c) { return (ic_interval){c, c}; }
static ic_interval sq(ic_interval a) { return ic_interval_pow_int(a, 2); }

size_t ic_expr_interval_grad_work_len(const ic_expr *e) { return e ? (size_t)e->len : 0; }

ic_interval ic_interval_unary_factor(const ic_instr *in, ic_interval a, ic_interval v)
{
    switch (in->op) {
    case OP_NEG:
        return scalar(-1.0);
    case OP_POWI:
        return in->n == 0
                   ? ZERO
                   : ic_interval_mul(scalar((double)in->n), ic_interval_pow_int(a, in->n - 1));
    case OP_POWR:
        return ic_interval_mul(scalar(in->c), ic_interval_pow_real(a, in->c - 1.0));
    case OP_SQRT:
        return ic_interval_div(scalar(0.5), v);
    case OP_EXP:
        return v;
    case OP_LOG:
        return ic_interval_div(ONE, a);
    case OP_SIN:
        return ic_interval_cos(a);
    case OP_COS:
        return ic_interval_neg(ic_interval_sin(a));
    case OP_TAN:
        return ic_interval_add(ONE, sq(v));
    case OP_ASIN:
        return ic_interval_div(ONE, ic_interval_sqrt(ic_interval_sub(ONE, sq(a))));
    case OP_ACOS:
        return ic_interval_neg(ic_interval_div(ONE, ic_interval_sqrt(ic_interval_sub(ONE, sq(a)))));
    case OP_ATAN:
        return ic_interval_div(ONE, ic_interval_add(ONE, sq(a)));
    case OP_SINH:
        return ic_interval_cosh(a);
    case OP_COSH:
        return ic_interval_sinh(a);
    case OP_TANH:
        return ic_interval_sub(ONE, sq(v));
    case OP_ABS:
        return a.lo > 0.0 ? ONE : a.hi < 0.0 ? scalar(-1.0) : (ic_interval){-1.0, 1.0};
    default:
        return (ic_interval){-INFINITY, INFINITY};
    }
}

static void grad_op(const ic_instr *in, ic_interval_grad *r, const ic_interval_grad *A,
                    const ic_interval_grad *B, int ngrad)
{
    const ic_interval a = A ? A->v : ZERO, b = B ? B->v : ZERO;
    r->v = ic_interval_op(in, a, b);
    for (int k = 0; k < ngrad; k++) {
        const ic_interval da = A ? A->d[k] : ZERO, db = B ? B->d[k] : ZERO;
        ic_interval d;
        switch (in->op) {
        case OP_CONST:
            d = ZERO;
            break;
        case OP_ADD:
            d = ic_interval_add(da, db);
            break;
        case OP_SUB:
            d = ic_interval_sub(da, db);
            break;
        case OP_MUL:
            d = ic_interval_add(ic_interval_mul(da, b), ic_interval_mul(a, db));
            break;
        case OP_DIV: /* (da - v db) / b */
            d = ic_interval_div(ic_interval_sub(da, ic_interval_mul(r->v, db)), b);
            break;
        case OP_POW: /* v (db log a + b da / a) */
            d = ic_interval_mul(r->v, ic_interval_add(ic_interval_mul(db, ic_interval_log(a)),
                                                      ic_interval_div(ic_interval_mul(b, da), a)));
            break;
        case OP_ATAN2: /* atan2(y = a, x = b): (b da - a db) / (a^2 + b^2) */
            d = ic_interval_div(ic_interval_sub(ic_interval_mul(b, da), ic_interval_mul(a, db)),
                                ic_interval_add(sq(a), sq(b)));
            break;
        default:
            d = ic_interval_mul(ic_interval_unary_factor(in, a, r->v), da);
            break;
        }
        r->d[k] = d;
    }
}

/* 1 when no enclosure of r is empty. */
static int all_nonempty(const ic_interval_grad *r, int ngrad)
{
    int ok = !ic_interval_is_empty(r->v);
    for (int k = 0; k < ngrad; k++)
        ok = ok && !ic_interval_is_empty(r->d[k]);
    return ok;
}

int ic_expr_eval_interval_grad(const ic_expr *e, ic_interval_grad *out, const ic_interval_grad *x,
                               int ngrad, ic_interval_grad *work)
{
    if (!e || !out || !x || !work)
        return 0;
    int whole = 1;
    for (int i = 0; i < e->len; i++) {
        const ic_instr *in = &e->code[i];
        if (in->op == OP_VAR) {
            work[i] = x[in->n];
            continue;
        }
        const ic_interval_grad *A = in->a >= 0 ? &work[in->a] : NULL;
        const ic_interval_grad *B = in->b >= 0 ? &work[in->b] : NULL;
        whole = whole && ic_interval_op_defined(in, A ? A->v : (ic_interval){0, 0},
                                                B ? B->v : (ic_interval){0, 0});
        grad_op(in, &work[i], A, B, ngrad);
        whole = whole && all_nonempty(&work[i], ngrad);
    }
    for (int k = 0; k < e->noutputs; k++)
        out[k] = work[e->outputs[k]];
    return whole;
}
