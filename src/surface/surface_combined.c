/* Combinations of two implicit formula surfaces with their common terms
 * cancelled (surface_access.h; expr_access.h, ic_expr_linear_terms). */
#include "expr/expr_access.h"
#include "surface_access.h"
#include "surface_internal.h"

#include <stdlib.h>

/* Terms a formula may have for the combination; more, and it is not formed. */
#define MAX_TERMS 32
/* Registers on the stack; longer formulas allocate. */
#define STACK_REGISTERS 128

static int formula_implicit(const ic_surface *s)
{
    return s && s->backend == BACKEND_FORMULA && s->kind == IC_IMPLICIT && s->expr &&
           ic_expr_num_outputs(s->expr) == 1;
}

/* Every register of s's formula over X (work, len registers): 1 when the
 * formula is defined over the whole box. */
static int registers(const ic_surface *s, const ic_interval *X, ic_interval_grad *work)
{
    ic_interval_grad x[3], out;
    for (int i = 0; i < 3; i++)
        x[i].v = X[i];
    return ic_expr_eval_interval_grad(s->expr, &out, x, 0, work);
}

/* sum_i w c_i T_i over the terms not marked used, marking them. */
static ic_interval add_terms(ic_interval sum, ic_interval w, const ic_expr_term *t, int n,
                             const int *used, const ic_interval_grad *work)
{
    for (int i = 0; i < n; i++)
        if (!used[i])
            sum = ic_interval_add(sum,
                                  ic_interval_mul(ic_interval_mul(w, t[i].coef), work[t[i].reg].v));
    return sum;
}

static int combine(const ic_surface *A, ic_interval wA, const ic_surface *B, ic_interval wB,
                   const ic_interval_grad *workA, const ic_interval_grad *workB, ic_interval *out)
{
    ic_expr_term ta[MAX_TERMS], tb[MAX_TERMS];
    ic_interval KA, KB;
    const int na = ic_expr_linear_terms(A->expr, 0, ta, MAX_TERMS, &KA);
    const int nb = ic_expr_linear_terms(B->expr, 0, tb, MAX_TERMS, &KB);
    if (na < 0 || nb < 0)
        return 0;
    int used_a[MAX_TERMS] = {0}, used_b[MAX_TERMS] = {0}, matched = 0;
    ic_interval sum = ic_interval_add(ic_interval_mul(wA, KA), ic_interval_mul(wB, KB));
    for (int j = 0; j < nb; j++)
        for (int i = 0; i < na && !used_b[j]; i++) {
            if (used_a[i] || !ic_expr_same_register(A->expr, ta[i].reg, B->expr, tb[j].reg))
                continue;
            /* one function: (wA cA + wB cB) T, T enclosed once */
            const ic_interval c =
                ic_interval_add(ic_interval_mul(wA, ta[i].coef), ic_interval_mul(wB, tb[j].coef));
            sum = ic_interval_add(sum, ic_interval_mul(c, workA[ta[i].reg].v));
            used_a[i] = used_b[j] = 1;
            matched++;
        }
    sum = add_terms(sum, wA, ta, na, used_a, workA);
    *out = add_terms(sum, wB, tb, nb, used_b, workB);
    return matched > 0 && !ic_interval_is_empty(*out);
}

int ic_surface_combined_interval(ic_surface *A, ic_interval wA, ic_surface *B, ic_interval wB,
                                 const ic_interval *X, ic_interval *out)
{
    if (!formula_implicit(A) || !formula_implicit(B) || !X || !out)
        return 0;
    const size_t la = ic_expr_interval_grad_work_len(A->expr);
    const size_t lb = ic_expr_interval_grad_work_len(B->expr);
    ic_interval_grad stack[2][STACK_REGISTERS];
    ic_interval_grad *wa = la > STACK_REGISTERS ? malloc(la * sizeof *wa) : stack[0];
    ic_interval_grad *wb = lb > STACK_REGISTERS ? malloc(lb * sizeof *wb) : stack[1];
    int ok = wa && wb && registers(A, X, wa) && registers(B, X, wb) &&
             combine(A, wA, B, wB, wa, wb, out);
    if (wa != stack[0])
        free(wa);
    if (wb != stack[1])
        free(wb);
    return ok;
}
