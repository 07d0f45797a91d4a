/*
 * A formula as a sum of terms (expr_access.h): the additive structure of
 * its tape above the first operation that is not a sum, a difference, a
 * negation or a product or quotient by a constant. Two formulas written
 * alike share their terms, and a combination of them cancels those exactly
 * where interval arithmetic would not (the dependency problem):
 * f_B - f_A for two tori 1e-9 apart in level is -1e-9 itself, not an
 * interval as wide as the terms (surface_combined.c).
 */
#include "expr_internal.h"

#include <string.h>

/* Instructions that structural equality may visit per call: tapes share
 * registers, so without a budget a comparison could revisit a subtree
 * exponentially often; running out only misses a match. */
#define SAME_BUDGET 4096

static int add_term(ic_expr_term *terms, int *n, int max, int reg, ic_interval coef)
{
    for (int i = 0; i < *n; i++)
        if (terms[i].reg == reg) {
            terms[i].coef = ic_interval_add(terms[i].coef, coef);
            return 0;
        }
    if (*n >= max)
        return -1;
    terms[(*n)++] = (ic_expr_term){reg, coef};
    return 0;
}

static int split(const ic_expr *e, int reg, ic_interval coef, ic_expr_term *terms, int *n, int max,
                 ic_interval *K)
{
    const ic_instr *in = &e->code[reg];
    const int a_const = in->a >= 0 && e->code[in->a].op == OP_CONST;
    const int b_const = in->b >= 0 && e->code[in->b].op == OP_CONST;
    switch (in->op) {
    case OP_CONST:
        *K = ic_interval_add(*K, ic_interval_mul(coef, (ic_interval){in->c, in->c}));
        return 0;
    case OP_ADD:
        return split(e, in->a, coef, terms, n, max, K) || split(e, in->b, coef, terms, n, max, K)
                   ? -1
                   : 0;
    case OP_SUB:
        return split(e, in->a, coef, terms, n, max, K) ||
                       split(e, in->b, ic_interval_neg(coef), terms, n, max, K)
                   ? -1
                   : 0;
    case OP_NEG:
        return split(e, in->a, ic_interval_neg(coef), terms, n, max, K);
    case OP_MUL:
        if (a_const || b_const) {
            const double c = e->code[a_const ? in->a : in->b].c;
            return split(e, a_const ? in->b : in->a, ic_interval_mul(coef, (ic_interval){c, c}),
                         terms, n, max, K);
        }
        break;
    case OP_DIV:
        if (b_const) {
            const double c = e->code[in->b].c;
            return split(e, in->a, ic_interval_div(coef, (ic_interval){c, c}), terms, n, max, K);
        }
        break;
    default:
        break;
    }
    return add_term(terms, n, max, reg, coef);
}

int ic_expr_linear_terms(const ic_expr *e, int output, ic_expr_term *terms, int max, ic_interval *K)
{
    if (!e || !terms || !K || output < 0 || output >= e->noutputs)
        return -1;
    int n = 0;
    *K = (ic_interval){0.0, 0.0};
    return split(e, e->outputs[output], (ic_interval){1.0, 1.0}, terms, &n, max, K) ? -1 : n;
}

static int same(const ic_expr *a, int ra, const ic_expr *b, int rb, int *budget)
{
    if (--*budget < 0)
        return 0;
    const ic_instr *x = &a->code[ra], *y = &b->code[rb];
    if (x->op != y->op || x->n != y->n || memcmp(&x->c, &y->c, sizeof x->c) != 0)
        return 0;
    if ((x->a < 0) != (y->a < 0) || (x->b < 0) != (y->b < 0))
        return 0;
    return (x->a < 0 || same(a, x->a, b, y->a, budget)) &&
           (x->b < 0 || same(a, x->b, b, y->b, budget));
}

int ic_expr_same_register(const ic_expr *a, int ra, const ic_expr *b, int rb)
{
    if (!a || !b || ra < 0 || rb < 0 || ra >= a->len || rb >= b->len || a->nvars != b->nvars)
        return 0;
    int budget = SAME_BUDGET;
    return same(a, ra, b, rb, &budget);
}
