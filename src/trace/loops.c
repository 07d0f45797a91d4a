/*
 * The loop test of a search cell (normal cones, docs/tracing.md): a proof
 * that no closed intersection curve lies wholly inside the cell.
 *  - Two surfaces in space (implicit/implicit over a box, parametric pairs
 *    over (u, v) x (p, q)): the curve's tangent is parallel to
 *    T = N_A x N_B. If T . v keeps one sign over the cell for a fixed v, then
 *    x . v is strictly monotone along every intersection curve in the cell
 *    (oriented by T), so none closes there.
 *  - Parametric/implicit over a (u, v) cell: the curve is the zero set of
 *    F = f(R(u, v)); a closed one bounds a disc in the (convex) cell on whose
 *    interior F has an extremum, where grad F = 0. If F_u or F_v keeps one
 *    sign over the cell, there is none.
 * Enclosures come from interval gradients (ic_surface_eval_interval_grad),
 * so a "loop-free" answer is a proof up to outward rounding.
 */
#include "trace_internal.h"

#include <math.h>

static int excludes_zero(ic_interval a) { return ic_interval_is_empty(a) || a.lo > 0 || a.hi < 0; }

static ic_interval mul(ic_interval a, ic_interval b) { return ic_interval_mul(a, b); }

static void cross(ic_interval *c, const ic_interval *a, const ic_interval *b)
{
    for (int i = 0; i < 3; i++) {
        const int j = (i + 1) % 3, k = (i + 2) % 3;
        c[i] = ic_interval_sub(mul(a[j], b[k]), mul(a[k], b[j]));
    }
}

/* Does T . v keep one sign for v = the midpoint direction of T, or for a
 * coordinate axis? */
static int one_sided(const ic_interval *T)
{
    double v[3], len = 0;
    for (int i = 0; i < 3; i++) {
        if (excludes_zero(T[i]))
            return 1;
        v[i] = 0.5 * (T[i].lo + T[i].hi);
        len += v[i] * v[i];
    }
    if (!(len > 0) || !isfinite(len))
        return 0;
    ic_interval dot = {0, 0};
    for (int i = 0; i < 3; i++)
        dot = ic_interval_add(dot, mul(T[i], (ic_interval){v[i], v[i]}));
    return excludes_zero(dot);
}

/* The normal R_u x R_v of a parametric surface over a parameter box. */
static int param_normal(ic_surface *s, const double *lo, const double *hi, ic_interval *N,
                        ic_interval *xyz)
{
    const ic_interval box[2] = {{lo[0], hi[0]}, {lo[1], hi[1]}};
    ic_interval_grad R[3];
    if (ic_surface_eval_interval_grad(s, R, box, NULL) != IC_OK)
        return 0;
    ic_interval Ru[3], Rv[3];
    for (int i = 0; i < 3; i++) {
        Ru[i] = R[i].d[0], Rv[i] = R[i].d[1];
        if (xyz)
            xyz[i] = R[i].v;
    }
    cross(N, Ru, Rv);
    return 1;
}

int ic_trace_cell_loop_free(ic_surface *const S[2], int par0, int par1, const double *lo,
                            const double *hi)
{
    ic_interval T[3];
    if (par0 && par1) { /* (u, v, p, q) */
        ic_interval NA[3], NB[3];
        if (!param_normal(S[0], lo, hi, NA, NULL) || !param_normal(S[1], lo + 2, hi + 2, NB, NULL))
            return 0;
        cross(T, NA, NB);
        return one_sided(T);
    }
    if (par0 || par1) { /* (u, v) of the parametric one */
        const int P = par0 ? 0 : 1;
        const ic_interval box[2] = {{lo[0], hi[0]}, {lo[1], hi[1]}};
        ic_interval_grad R[3], f;
        if (ic_surface_eval_interval_grad(S[P], R, box, NULL) != IC_OK)
            return 0;
        const ic_interval X[3] = {R[0].v, R[1].v, R[2].v};
        if (ic_surface_eval_interval_grad(S[1 - P], &f, X, NULL) != IC_OK)
            return 0;
        for (int j = 0; j < 2; j++) { /* F_j = grad f . R_j */
            ic_interval Fj = {0, 0};
            for (int i = 0; i < 3; i++)
                Fj = ic_interval_add(Fj, mul(f.d[i], R[i].d[j]));
            if (excludes_zero(Fj))
                return 1;
        }
        return 0;
    }
    const ic_interval box[3] = {{lo[0], hi[0]}, {lo[1], hi[1]}, {lo[2], hi[2]}};
    ic_interval_grad fa, fb;
    if (ic_surface_eval_interval_grad(S[0], &fa, box, NULL) != IC_OK ||
        ic_surface_eval_interval_grad(S[1], &fb, box, NULL) != IC_OK)
        return 0;
    cross(T, fa.d, fb.d);
    return one_sided(T);
}

/* 1 when R_u x R_v of a parametric sheet may vanish over the cell: a pole
 * or another degenerate point of the parametrization, where the loop test
 * cannot succeed (R_u x R_v is its normal). */
int ic_trace_cell_may_degenerate(ic_surface *const S[2], int par0, int par1, const double *lo,
                                 const double *hi)
{
    const int par[2] = {par0, par1};
    int off = 0;
    for (int s = 0; s < 2; s++) {
        if (!par[s])
            continue;
        ic_interval N[3];
        if (!param_normal(S[s], lo + off, hi + off, N, NULL))
            return 1;
        if (!excludes_zero(N[0]) && !excludes_zero(N[1]) && !excludes_zero(N[2]))
            return 1;
        off += 2;
    }
    return 0;
}

int ic_trace_point_may_degenerate(ic_pair *pair, const ic_local_point *pt, double rel)
{
    ic_surface *S[2] = {ic_pair_surface(pair, 0), ic_pair_surface(pair, 1)};
    int par[2];
    double lo[4], hi[4];
    int off = 0;
    for (int s = 0; s < 2; s++) {
        par[s] = ic_surface_get_kind(S[s]) == IC_PARAMETRIC;
        if (!par[s])
            continue;
        double dom[2][2];
        int periodic[2];
        ic_surface_get_domain(S[s], dom, periodic);
        for (int k = 0; k < 2; k++) {
            const double half = rel * (dom[k][1] - dom[k][0]);
            lo[off + k] = pt->params[s][k] - half;
            hi[off + k] = pt->params[s][k] + half;
        }
        off += 2;
    }
    return off > 0 && ic_trace_cell_may_degenerate(S, par[0], par[1], lo, hi);
}
