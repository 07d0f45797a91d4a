/* Jet spaces: the monomial order and the product tables (jet.h). */
#include "common/args.h"
#include "jet_chain.h"
#include "jet_internal.h"

#include <stdlib.h>

static long binomial(int n, int k)
{
    long r = 1;
    for (int i = 1; i <= k; i++)
        r = r * (n - k + i) / i;
    return r;
}

/* Monomials of total degree `rest` in variables v..m-1, exponent of variable
 * v decreasing, then v+1, ...: appended at exps[*count * m] onwards. */
static void enumerate_degree(int *exps, int *count, int m, int v, int rest, int *alpha)
{
    if (v == m - 1) {
        alpha[v] = rest;
        for (int i = 0; i < m; i++)
            exps[*count * m + i] = alpha[i];
        (*count)++;
        return;
    }
    for (int a = rest; a >= 0; a--) {
        alpha[v] = a;
        enumerate_degree(exps, count, m, v + 1, rest - a, alpha);
    }
}

static int code_of(const ic_jet_space *sp, const int *alpha)
{
    int code = 0;
    for (int i = sp->m - 1; i >= 0; i--)
        code = code * (sp->K + 1) + alpha[i];
    return code;
}

/* lower_var and lower of monomial i (after the lookup table); -1 for 1. */
static void lower_monomial(ic_jet_space *sp, int i)
{
    int alpha[IC_JET_MAX_VARS];
    ic_jet_exponents(sp, i, alpha);
    int v = 0;
    while (v < sp->m && alpha[v] == 0)
        v++;
    if (v == sp->m) {
        sp->lower_var[i] = sp->lower[i] = -1;
        return;
    }
    alpha[v]--;
    sp->lower_var[i] = v;
    sp->lower[i] = sp->lookup[code_of(sp, alpha)];
}

ic_status ic_jet_space_new(ic_jet_space **out, int nvars, int order, ic_error *err)
{
    IC_ARG_NOT_NULL(out, "sp");
    *out = NULL;
    if (nvars < 1 || nvars > IC_JET_MAX_VARS)
        return ic_error_set(err, IC_ERR_INVALID, 0, "jet space: %d variables (allowed 1..%d)",
                            nvars, IC_JET_MAX_VARS);
    if (order < 0 || order > IC_JET_MAX_ORDER)
        return ic_error_set(err, IC_ERR_INVALID, 0, "jet space: order %d (allowed 0..%d)", order,
                            IC_JET_MAX_ORDER);
    ic_jet_space *sp = calloc(1, sizeof *sp);
    if (!sp)
        goto nomem;
    sp->m = nvars;
    sp->K = order;
    sp->n = (int)binomial(nvars + order, nvars);
    const int m = nvars, K = order, n = sp->n;
    long codes = 1;
    for (int i = 0; i < m; i++)
        codes *= K + 1;
    sp->deg_start = malloc((size_t)(K + 2) * sizeof *sp->deg_start);
    sp->exps = malloc((size_t)n * (size_t)m * sizeof *sp->exps);
    sp->fact = malloc((size_t)n * sizeof *sp->fact);
    sp->lookup = malloc((size_t)codes * sizeof *sp->lookup);
    sp->block_off = malloc((size_t)(K + 1) * (size_t)(K + 1) * sizeof *sp->block_off);
    sp->lower_var = malloc((size_t)n * sizeof *sp->lower_var);
    sp->lower = malloc((size_t)n * sizeof *sp->lower);
    if (!sp->deg_start || !sp->exps || !sp->fact || !sp->lookup || !sp->block_off ||
        !sp->lower_var || !sp->lower)
        goto nomem;

    int count = 0;
    for (int d = 0; d <= K; d++) {
        int alpha[IC_JET_MAX_VARS];
        sp->deg_start[d] = count;
        enumerate_degree(sp->exps, &count, m, 0, d, alpha);
    }
    sp->deg_start[K + 1] = count;
    for (long c = 0; c < codes; c++)
        sp->lookup[c] = -1;
    for (int i = 0; i < n; i++) {
        double f = 1.0;
        for (int v = 0; v < m; v++)
            for (int k = 2; k <= sp->exps[i * m + v]; k++)
                f *= k;
        sp->fact[i] = f;
        sp->lookup[code_of(sp, sp->exps + i * m)] = i;
    }
    for (int i = 0; i < n; i++)
        lower_monomial(sp, i);

    size_t total = 0;
    for (int j = 0; j <= K; j++)
        for (int k = 0; k <= K; k++) {
            sp->block_off[j * (K + 1) + k] = total;
            if (j + k <= K)
                total += (size_t)(sp->deg_start[j + 1] - sp->deg_start[j]) *
                         (size_t)(sp->deg_start[k + 1] - sp->deg_start[k]);
        }
    sp->pair_idx = malloc((total ? total : 1) * sizeof *sp->pair_idx);
    if (!sp->pair_idx)
        goto nomem;
    for (int j = 0; j <= K; j++)
        for (int k = 0; j + k <= K; k++) {
            int *idx = sp->pair_idx + sp->block_off[j * (K + 1) + k];
            for (int p = sp->deg_start[j]; p < sp->deg_start[j + 1]; p++)
                for (int q = sp->deg_start[k]; q < sp->deg_start[k + 1]; q++) {
                    int sum[IC_JET_MAX_VARS];
                    for (int v = 0; v < m; v++)
                        sum[v] = sp->exps[p * m + v] + sp->exps[q * m + v];
                    *idx++ = sp->lookup[code_of(sp, sum)];
                }
        }
    *out = sp;
    return IC_OK;
nomem:
    ic_jet_space_free(sp);
    return ic_error_set(err, IC_ERR_NOMEM, 0, "jet space: out of memory (%d variables, order %d)",
                        nvars, order);
}

void ic_jet_space_free(ic_jet_space *sp)
{
    if (!sp)
        return;
    free(sp->deg_start);
    free(sp->exps);
    free(sp->fact);
    free(sp->lookup);
    free(sp->pair_idx);
    free(sp->block_off);
    free(sp->lower_var);
    free(sp->lower);
    free(sp);
}

int ic_jet_space_num_vars(const ic_jet_space *sp) { return sp ? sp->m : 0; }
int ic_jet_space_order(const ic_jet_space *sp) { return sp ? sp->K : 0; }
int ic_jet_space_len(const ic_jet_space *sp) { return sp ? sp->n : 0; }

size_t ic_jet_scratch_len(const ic_jet_space *sp)
{
    if (!sp)
        return 0;
    /* composition: K + 1 powers, 3 per nesting level (<= 4 levels); reversion
     * and the functions with auxiliary series: 4 more (docs/jets.md). */
    const size_t len = (size_t)(sp->K + 1 + 3 * IC_JET_MAX_VARS + 4) * (size_t)sp->n;
    if (sp->m > 2)
        return len;
    /* the reversions: their one-degree-at-a-time composition (jet_chain.h)
     * keeps every power product of the series, after m results */
    const size_t revert = (size_t)sp->m * (size_t)sp->n + ic_jet_chain_len(sp, sp->K, sp);
    return revert > len ? revert : len;
}

int ic_jet_degree_start(const ic_jet_space *sp, int d)
{
    if (!sp || d < 0)
        return 0;
    if (d > sp->K + 1)
        d = sp->K + 1;
    return sp->deg_start[d];
}

int ic_jet_index(const ic_jet_space *sp, const int *alpha)
{
    if (!sp || !alpha)
        return -1;
    int deg = 0;
    for (int v = 0; v < sp->m; v++) {
        if (alpha[v] < 0)
            return -1;
        deg += alpha[v];
    }
    if (deg > sp->K)
        return -1;
    return sp->lookup[code_of(sp, alpha)];
}

void ic_jet_exponents(const ic_jet_space *sp, int index, int *alpha)
{
    if (!sp || !alpha || index < 0 || index >= sp->n)
        return;
    for (int v = 0; v < sp->m; v++)
        alpha[v] = sp->exps[index * sp->m + v];
}

double ic_jet_factorial(const ic_jet_space *sp, int index)
{
    return sp && index >= 0 && index < sp->n ? sp->fact[index] : 0.0;
}
