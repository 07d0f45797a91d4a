/*
 * Composition of a Taylor polynomial with jets, and series reversion.
 *
 * Composition evaluates P(delta_1, ..., delta_p), delta_i = g_i - g_i(0), by
 * nested Horner schemes over the first p - 1 variables; the innermost
 * variable uses its precomputed powers, so the innermost polynomials are mere
 * linear combinations. Every delta has no constant term, so degrees above K
 * vanish and the schemes stop there.
 *
 * The reversions find the series degree by degree, so they compose one
 * degree at a time (jet_chain.h) instead of recomposing at every degree.
 */
#include "common/args.h"
#include "jet_chain.h"
#include "jet_internal.h"

#include <math.h>

typedef struct {
    const double *P;
    const ic_jet_space *sp_p;
    const ic_jet_space *sp;
    int Kc;                 /* min(K_p, K, D) */
    int D;                  /* the highest output degree wanted */
    const double *delta[IC_JET_MAX_VARS];
    const double *powers;   /* powers of the last delta, [Kc + 1][n] */
    double *work;           /* 2 buffers per nesting level */
} compose_ctx;

/* out = sum over the remaining exponents of P[alpha] * delta^alpha, where
 * alpha[0..level-1] are fixed and sum to `used`. */
static void compose_level(const compose_ctx *cx, double *out, int level, int *alpha, int used)
{
    const ic_jet_space *sp = cx->sp;
    const int p = cx->sp_p->m;
    const int budget = cx->Kc - used;
    /* p <= IC_JET_MAX_VARS holds for every space; the second test states it
     * here, so no level can index delta[] or alpha[] past their ends */
    if (level == p - 1 || level == IC_JET_MAX_VARS - 1) {
        ic_jet_zero(out, sp);
        for (int a = 0; a <= budget; a++) {
            alpha[level] = a;
            const double coef = cx->P[ic_jet_index(cx->sp_p, alpha)];
            if (coef == 0.0)
                continue;
            const double *pw = cx->powers + (size_t)a * (size_t)sp->n;
            /* delta^a has no terms below degree a */
            for (int i = sp->deg_start[a]; i < sp->deg_start[cx->D + 1]; i++)
                out[i] += coef * pw[i];
        }
        return;
    }
    double *tmp = cx->work + (size_t)(2 * level) * (size_t)sp->n;
    double *sub = tmp + sp->n;
    /* Horner in delta_level, from the highest exponent down. */
    alpha[level] = budget;
    compose_level(cx, out, level + 1, alpha, used + budget);
    for (int a = budget - 1; a >= 0; a--) {
        ic_jet_mul_upto(tmp, out, cx->delta[level], sp, cx->D);
        alpha[level] = a;
        compose_level(cx, sub, level + 1, alpha, used + a);
        ic_jet_add(out, tmp, sub, sp);
    }
}

/* The composition on the output degrees <= D (the rest zero): every delta
 * has no constant term, so the terms of P above degree D do not matter. */
static void compose_upto(double *out, const double *P, const ic_jet_space *sp_p,
                         const double *const *g, const ic_jet_space *sp, double *scratch, int D)
{
    const int n = sp->n, p = sp_p->m;
    compose_ctx cx = {.P = P, .sp_p = sp_p, .sp = sp, .D = D};
    cx.Kc = sp_p->K < sp->K ? sp_p->K : sp->K;
    if (cx.Kc > D)
        cx.Kc = D;
    double *buf = scratch;
    for (int i = 0; i < p; i++) {
        ic_jet_copy(buf, g[i], sp);
        buf[0] = 0.0;
        cx.delta[i] = buf;
        buf += n;
    }
    double *powers = buf;
    ic_jet_set_const(powers, 1.0, sp);
    for (int a = 1; a <= cx.Kc; a++)
        ic_jet_mul_upto(powers + (size_t)a * n, powers + (size_t)(a - 1) * n, cx.delta[p - 1], sp,
                        D);
    cx.powers = powers;
    cx.work = powers + (size_t)(cx.Kc + 1) * n;
    int alpha[IC_JET_MAX_VARS] = {0};
    compose_level(&cx, out, 0, alpha, 0);
}

void ic_jet_compose(double *out, const double *P, const ic_jet_space *sp_p,
                    const double *const *g, const ic_jet_space *sp, double *scratch)
{
    if (!out || !P || !sp_p || !g || !sp || !scratch)
        return;
    compose_upto(out, P, sp_p, g, sp, scratch, sp->K);
}

/* g_1 = y / f_1; then for k = 2..K the degree-k coefficient of f(g) - f(0)
 * must vanish, and it depends on g_k only through f_1 g_k: with g_k = 0
 * still, g_k = -[f(g)]_k / f_1, the powers of g extended one degree per
 * step (jet_chain.h). */
ic_status ic_jet_revert(double *g, const double *f, const ic_jet_space *sp, double *scratch,
                        ic_error *err)
{
    IC_ARG_NOT_NULL(g, "g");
    IC_ARG_NOT_NULL(f, "f");
    IC_ARG_NOT_NULL(sp, "sp");
    IC_ARG_NOT_NULL(scratch, "scratch");
    if (sp->m != 1)
        return ic_error_set(err, IC_ERR_INVALID, 0, "ic_jet_revert needs a one-variable space");
    if (sp->K >= 1 && f[1] == 0.0)
        return ic_error_set(err, IC_ERR_UNABLE, 0, "series reversion: f'(0) = 0");
    ic_jet_zero(g, sp);
    if (sp->K == 0)
        return IC_OK;
    g[1] = 1.0 / f[1];
    double *h = scratch;
    const double *gs[1] = {g};
    ic_jet_chain ch;
    const double *fs[1] = {f};
    ic_jet_chain_init(&ch, sp, fs, 1, gs, sp, scratch + sp->n);
    for (int k = 2; k <= sp->K; k++) {
        ic_jet_chain_extend(&ch, k);
        ic_jet_chain_part(&ch, h, f, k);
        g[k] = -h[k] / f[1];
    }
    return IC_OK;
}

ic_status ic_jet_revert2(double *const g[2], const double *const f[2], const ic_jet_space *sp,
                         double *scratch, ic_error *err)
{
    IC_ARG_NOT_NULL(g, "g");
    IC_ARG_NOT_NULL(f, "f");
    IC_ARG_NOT_NULL(sp, "sp");
    IC_ARG_NOT_NULL(scratch, "scratch");
    if (sp->m != 2)
        return ic_error_set(err, IC_ERR_INVALID, 0, "ic_jet_revert2 needs a two-variable space");
    ic_jet_zero(g[0], sp);
    ic_jet_zero(g[1], sp);
    if (sp->K == 0)
        return IC_OK;
    /* Jacobian L = [[f0_x, f0_y], [f1_x, f1_y]] (degree-1 monomials x, y). */
    const double a = f[0][1], b = f[0][2], c = f[1][1], d = f[1][2];
    const double det = a * d - b * c;
    const double scale = fmax(fabs(a), fabs(b)) * fmax(fabs(c), fabs(d));
    if (!(fabs(det) > 1e-14 * scale) || !isfinite(det))
        return ic_error_set(err, IC_ERR_UNABLE, 0,
                            "bivariate reversion: singular Jacobian (det = %g)", det);
    const double i00 = d / det, i01 = -b / det, i10 = -c / det, i11 = a / det;
    /* G_1 = L^{-1} y: x-coefficient is column 0, y-coefficient column 1. */
    g[0][1] = i00;
    g[0][2] = i01;
    g[1][1] = i10;
    g[1][2] = i11;
    double *h0 = scratch, *h1 = scratch + sp->n;
    const double *gs[2] = {g[0], g[1]};
    ic_jet_chain ch;
    ic_jet_chain_init(&ch, sp, f, 2, gs, sp, scratch + 2 * sp->n);
    for (int k = 2; k <= sp->K; k++) {
        /* [F(G)]_k with G_k = 0 still; G_k -= L^{-1} [F(G)]_k */
        ic_jet_chain_extend(&ch, k);
        ic_jet_chain_part(&ch, h0, f[0], k);
        ic_jet_chain_part(&ch, h1, f[1], k);
        for (int i = sp->deg_start[k]; i < sp->deg_start[k + 1]; i++) {
            g[0][i] -= i00 * h0[i] + i01 * h1[i];
            g[1][i] -= i10 * h0[i] + i11 * h1[i];
        }
    }
    return IC_OK;
}
