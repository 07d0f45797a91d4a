/*
 * A formula moved to a new origin (expr_access.h, ic_expr_shifted): the
 * tape of g(y) = f(a + y) - b for offsets a of the variables and b of the
 * outputs, equal to f's in real arithmetic, with the large constants of
 * both combined before any rounding can see them.
 *
 * Why: a saddle z - o - 0.05((x - o)^2 - (y - o)^2) at o = 1e6 evaluated at
 * x near o keeps only the digits of o's last place, 1.2e-10, beside a
 * feature of size 1; written about the origin (o, o, o) the same formula is
 * z' - 0.05(x'^2 - y'^2) and keeps all its digits (docs/tracing.md,
 * "Far from the origin").
 *
 * How: each register r of f becomes a pair K + s, K a double and s a
 * register of g (or nothing), carried through sums, negations and products
 * and quotients by constants while every combination of the Ks is exact
 * (an error-free transformation says so); any other operation first forms
 * K + s in g. No constant is ever rounded, so g is f moved, not an
 * approximation of it.
 */
#include "common/frame.h"
#include "expr_internal.h"

#include <math.h>
#include <stdlib.h>

/* A register of f as K + L + s: K + L a constant held exactly in two
 * doubles (L the tail two-sums leave, 0 mostly), s a register of g, or -1
 * for none (f's register is the constant K). Two doubles keep o + 0.05 at
 * o = 1e6 exact, so o + 0.37 u + 0.05 - o is 0.05 + 0.37 u' exactly. */
typedef struct {
    double K, L;
    int s;
} shifted_reg;

/* 1 when a + b is a double exactly. */
static int sum_exact(double a, double b) { return !isnan(ic_exact_difference(a, -b)); }

/* 1 when a * b is a double exactly (the product's fma residue is zero). */
static int product_exact(double a, double b)
{
    const double p = a * b;
    return isfinite(p) && fma(a, b, -p) == 0.0;
}

/* Knuth's two-sum: a + b = *sum + *err exactly (finite a + b). */
static void two_sum(double a, double b, double *sum, double *err)
{
    *sum = a + b;
    const double bv = *sum - a;
    *err = (a - (*sum - bv)) + (b - bv);
}

/* (K1 + L1) + (K2 + L2) as K + L exactly: 1 so, 0 where the tails do not
 * combine into one double. */
static int dd_add(double K1, double L1, double K2, double L2, double *K, double *L)
{
    double S, E;
    two_sum(K1, K2, &S, &E);
    if (!isfinite(S) || !sum_exact(L1, L2) || !sum_exact(L1 + L2, E))
        return 0;
    two_sum(S, L1 + L2 + E, K, L);
    return 1;
}

/* c (K + L) as K' + L' exactly: 1 so. */
static int dd_scale(double c, double K, double L, double *Ko, double *Lo)
{
    const double p = c * K, e = fma(c, K, -p);
    if (!isfinite(p) || !product_exact(c, L) || !sum_exact(c * L, e))
        return 0;
    two_sum(p, c * L + e, Ko, Lo);
    return 1;
}

/* 1 when a / b is a double exactly. */
static int quotient_exact(double a, double b)
{
    const double q = a / b;
    return b != 0.0 && isfinite(q) && fma(q, b, -a) == 0.0;
}

/* K + s formed as one register of g (-1 out of memory). */
static int form1(ic_expr *g, double K, int s, int column, ic_error *err)
{
    if (s < 0)
        return ic_tape_emit(g, OP_CONST, -1, -1, 0, K, column, err);
    if (K == 0.0)
        return s;
    const int k = ic_tape_emit(g, OP_CONST, -1, -1, 0, K, column, err);
    return k < 0 ? -1 : ic_tape_emit(g, OP_ADD, k, s, 0, 0.0, column, err);
}

/* K + (L + s) formed (a register of f's constants has L = 0: f folded
 * them into one double). */
static int form(ic_expr *g, shifted_reg r, int column, ic_error *err)
{
    if (r.L == 0.0 || r.s < 0)
        return form1(g, r.K, r.s, column, err);
    const int t = form1(g, r.L, r.s, column, err);
    return t < 0 ? -1 : form1(g, r.K, t, column, err);
}

/* s1 op s2 in g for op ADD or SUB, either side possibly none. */
static int combine(ic_expr *g, ic_opcode op, int s1, int s2, int column, ic_error *err)
{
    if (s2 < 0)
        return s1;
    if (s1 < 0)
        return op == OP_ADD ? s2 : ic_tape_emit(g, OP_NEG, s2, -1, 0, 0.0, column, err);
    return ic_tape_emit(g, op, s1, s2, 0, 0.0, column, err);
}

/* A sum or a difference: the constants combined where that is exact. */
static int add_sub(ic_expr *g, const ic_instr *in, shifted_reg a, shifted_reg b, shifted_reg *out,
                   ic_error *err)
{
    const double sign = in->op == OP_ADD ? 1.0 : -1.0;
    if (dd_add(a.K, a.L, sign * b.K, sign * b.L, &out->K, &out->L)) {
        out->s = combine(g, in->op, a.s, b.s, in->column, err);
        return (a.s >= 0 || b.s >= 0) && out->s < 0 ? -1 : 0;
    }
    const int fa = form(g, a, in->column, err), fb = form(g, b, in->column, err);
    out->K = out->L = 0.0;
    out->s = fa < 0 || fb < 0 ? -1 : ic_tape_emit(g, in->op, fa, fb, 0, 0.0, in->column, err);
    return out->s < 0 ? -1 : 0;
}

/* c (K + s) or (K + s) / c, a constant c: c K exact keeps the pair. */
static int scale(ic_expr *g, const ic_instr *in, double c, shifted_reg x, int divide,
                 shifted_reg *out, ic_error *err)
{
    double K = 0.0, L = 0.0;
    const int exact =
        divide ? quotient_exact(x.K, c) && quotient_exact(x.L, c) &&
                     (two_sum(x.K / c, x.L / c, &K, &L), 1)
               : dd_scale(c, x.K, x.L, &K, &L);
    const int k = ic_tape_emit(g, OP_CONST, -1, -1, 0, c, in->column, err);
    if (k < 0)
        return -1;
    const int sx = exact ? x.s : form(g, x, in->column, err);
    if (sx < 0)
        return -1;
    out->K = exact ? K : 0.0;
    out->L = exact ? L : 0.0;
    out->s = divide ? ic_tape_emit(g, OP_DIV, sx, k, 0, 0.0, in->column, err)
                    : ic_tape_emit(g, OP_MUL, k, sx, 0, 0.0, in->column, err);
    return out->s < 0 ? -1 : 0;
}

/* Any other operation: its arguments formed, then the operation itself. */
static int apply(ic_expr *g, const ic_instr *in, const shifted_reg *m, shifted_reg *out,
                 ic_error *err)
{
    const int fa = in->a >= 0 ? form(g, m[in->a], in->column, err) : -1;
    const int fb = in->b >= 0 ? form(g, m[in->b], in->column, err) : -1;
    if ((in->a >= 0 && fa < 0) || (in->b >= 0 && fb < 0))
        return -1;
    out->K = out->L = 0.0;
    out->s = ic_tape_emit(g, in->op, fa, fb, in->n, in->c, in->column, err);
    return out->s < 0 ? -1 : 0;
}

/* Instruction i of f in g. */
static int shift_instr(ic_expr *g, const ic_instr *in, const shifted_reg *m, const double *var_at,
                       shifted_reg *out, ic_error *err)
{
    const shifted_reg none = {0.0, 0.0, -1};
    const shifted_reg a = in->a >= 0 ? m[in->a] : none, b = in->b >= 0 ? m[in->b] : none;
    switch (in->op) {
    case OP_CONST:
        *out = (shifted_reg){in->c, 0.0, -1};
        return 0;
    case OP_VAR:
        out->K = var_at[in->n], out->L = 0.0;
        out->s = ic_tape_emit(g, OP_VAR, -1, -1, in->n, 0.0, in->column, err);
        return out->s < 0 ? -1 : 0;
    case OP_ADD:
    case OP_SUB:
        return add_sub(g, in, a, b, out, err);
    case OP_NEG:
        out->K = -a.K, out->L = -a.L;
        out->s = combine(g, OP_SUB, -1, a.s, in->column, err);
        return a.s >= 0 && out->s < 0 ? -1 : 0;
    case OP_MUL:
        if (a.s < 0)
            return scale(g, in, a.K, b, 0, out, err);
        if (b.s < 0)
            return scale(g, in, b.K, a, 0, out, err);
        return apply(g, in, m, out, err);
    case OP_DIV:
        if (b.s < 0 && b.K != 0.0)
            return scale(g, in, b.K, a, 1, out, err);
        return apply(g, in, m, out, err);
    default:
        return apply(g, in, m, out, err);
    }
}

/* Output k of g: f's output less its offset, formed; -1 with *unable set
 * for a constant output whose move is no double (the tape would fold the
 * difference, rounded). */
static int shift_output(ic_expr *g, shifted_reg r, double off, int column, int *unable,
                        ic_error *err)
{
    shifted_reg moved = {0.0, 0.0, r.s};
    if (dd_add(r.K, r.L, -off, 0.0, &moved.K, &moved.L) && (r.s >= 0 || moved.L == 0.0))
        return form(g, moved, column, err);
    if (r.s < 0)
        return *unable = 1, -1;
    const int f = form(g, r, column, err);
    const int k = f < 0 ? -1 : ic_tape_emit(g, OP_CONST, -1, -1, 0, off, column, err);
    return k < 0 ? -1 : ic_tape_emit(g, OP_SUB, f, k, 0, 0.0, column, err);
}

ic_status ic_expr_shifted(ic_expr **out, const ic_expr *f, const double *var_at,
                          const double *out_at, ic_error *err)
{
    *out = NULL;
    ic_expr *g = calloc(1, sizeof *g);
    shifted_reg *m = malloc(((size_t)f->len + 1) * sizeof *m);
    if (g)
        g->outputs = malloc((size_t)f->noutputs * sizeof *g->outputs);
    int ok = g && m && g->outputs;
    if (ok) {
        g->nvars = f->nvars;
        g->noutputs = f->noutputs;
    }
    for (int i = 0; ok && i < f->len; i++)
        ok = shift_instr(g, &f->code[i], m, var_at, &m[i], err) == 0;
    int unable = 0;
    for (int k = 0; ok && k < f->noutputs; k++)
        ok = (g->outputs[k] = shift_output(g, m[f->outputs[k]], out_at ? out_at[k] : 0.0, 0,
                                            &unable, err)) >= 0;
    free(m);
    if (ok)
        ok = ic_expr_finish(g) == 0;
    if (!ok && unable) {
        ic_expr_free(g);
        return ic_error_set(err, IC_ERR_UNABLE, 0, "a constant output does not move exactly");
    }
    if (!ok) {
        ic_expr_free(g);
        /* the tape folds no constant here (every operation has a register
         * argument), so only memory can fail */
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory moving a formula");
    }
    *out = g;
    return IC_OK;
}
