/*
 * Exclusion of a search cell by centred forms (docs/tracing.md): for a
 * function h with interval gradient G over the cell X and centre c,
 *   h(X) is inside h(c) + sum_k G_k (X_k - c_k)      (mean value theorem),
 * whose width shrinks like the cell squared where the gradient varies
 * little, while the plain enclosure shrinks only like the cell. Near a
 * tangency the two surfaces are closer than a cell's plain enclosure can
 * tell apart; there the combination h = f_B - mu f_A (mu making grad h
 * small at c) separates them: any common zero is a zero of h, for any mu.
 *  - implicit pair over a box: f_A, f_B and f_B - mu f_A;
 *  - parametric R against implicit f over (u, v): F = f(R(u, v));
 *  - two parametric surfaces over (u, v, p, q): the components of
 *    R_A - R_B and N . (R_A - R_B), N the normal of A at the centre.
 * Every value at c is an interval (outward rounded), so exclusion is proven.
 */
#include "trace_internal.h"

#include <math.h>

static int excludes_zero(ic_interval a) { return ic_interval_is_empty(a) || a.lo > 0 || a.hi < 0; }

static ic_interval point(double x) { return (ic_interval){x, x}; }

/* h(c) + sum_k G[k] (X_k - c_k) excludes 0? */
static int centred_excludes(ic_interval hc, const ic_interval *G, const double *lo,
                            const double *hi, int n)
{
    ic_interval sum = hc;
    for (int k = 0; k < n; k++) {
        const double c = 0.5 * (lo[k] + hi[k]);
        const ic_interval dx = ic_interval_sub((ic_interval){lo[k], hi[k]}, point(c));
        sum = ic_interval_add(sum, ic_interval_mul(G[k], dx));
    }
    return excludes_zero(sum);
}

static ic_interval mid(ic_interval a) { return point(0.5 * (a.lo + a.hi)); }

static int implicit_pair(ic_surface *const S[2], const double *lo, const double *hi)
{
    ic_interval box[3], cbox[3];
    for (int k = 0; k < 3; k++) {
        box[k] = (ic_interval){lo[k], hi[k]};
        cbox[k] = point(0.5 * (lo[k] + hi[k]));
    }
    ic_interval_grad f[2], fc[2];
    for (int s = 0; s < 2; s++)
        if (ic_surface_eval_interval_grad(S[s], &f[s], box, NULL) != IC_OK ||
            ic_surface_eval_interval_grad(S[s], &fc[s], cbox, NULL) != IC_OK)
            return 0;
    for (int s = 0; s < 2; s++)
        if (centred_excludes(fc[s].v, f[s].d, lo, hi, 3))
            return 1;
    /* mu = grad f_B . grad f_A / |grad f_A|^2 at the centre */
    double ab = 0, aa = 0;
    for (int k = 0; k < 3; k++) {
        const double ga = mid(fc[0].d[k]).lo, gb = mid(fc[1].d[k]).lo;
        ab += ga * gb, aa += ga * ga;
    }
    if (!(aa > 0) || !isfinite(ab / aa))
        return 0;
    const ic_interval mu = point(ab / aa);
    ic_interval G[3];
    for (int k = 0; k < 3; k++)
        G[k] = ic_interval_sub(f[1].d[k], ic_interval_mul(mu, f[0].d[k]));
    const ic_interval hc = ic_interval_sub(fc[1].v, ic_interval_mul(mu, fc[0].v));
    return centred_excludes(hc, G, lo, hi, 3);
}

static int mixed_pair(ic_surface *P, ic_surface *I, const double *lo, const double *hi)
{
    const ic_interval box[2] = {{lo[0], hi[0]}, {lo[1], hi[1]}};
    const ic_interval cbox[2] = {point(0.5 * (lo[0] + hi[0])), point(0.5 * (lo[1] + hi[1]))};
    ic_interval_grad R[3], Rc[3], f, fc;
    if (ic_surface_eval_interval_grad(P, R, box, NULL) != IC_OK ||
        ic_surface_eval_interval_grad(P, Rc, cbox, NULL) != IC_OK)
        return 0;
    const ic_interval X[3] = {R[0].v, R[1].v, R[2].v}, Xc[3] = {Rc[0].v, Rc[1].v, Rc[2].v};
    if (ic_surface_eval_interval_grad(I, &f, X, NULL) != IC_OK ||
        ic_surface_eval_interval_grad(I, &fc, Xc, NULL) != IC_OK)
        return 0;
    ic_interval G[2];
    for (int j = 0; j < 2; j++) { /* F_j = grad f(R(X)) . R_j(X) */
        G[j] = point(0.0);
        for (int i = 0; i < 3; i++)
            G[j] = ic_interval_add(G[j], ic_interval_mul(f.d[i], R[i].d[j]));
    }
    return centred_excludes(fc.v, G, lo, hi, 2);
}

static int parametric_pair(ic_surface *const S[2], const double *lo, const double *hi)
{
    ic_interval_grad R[2][3], Rc[2][3];
    for (int s = 0; s < 2; s++) {
        const double *l = lo + 2 * s, *h = hi + 2 * s;
        const ic_interval box[2] = {{l[0], h[0]}, {l[1], h[1]}};
        const ic_interval cbox[2] = {point(0.5 * (l[0] + h[0])), point(0.5 * (l[1] + h[1]))};
        if (ic_surface_eval_interval_grad(S[s], R[s], box, NULL) != IC_OK ||
            ic_surface_eval_interval_grad(S[s], Rc[s], cbox, NULL) != IC_OK)
            return 0;
    }
    /* D = R_A(u, v) - R_B(p, q): gradient (R_A,u, R_A,v, -R_B,p, -R_B,q) */
    ic_interval G[3][4], Dc[3];
    for (int i = 0; i < 3; i++) {
        Dc[i] = ic_interval_sub(Rc[0][i].v, Rc[1][i].v);
        G[i][0] = R[0][i].d[0], G[i][1] = R[0][i].d[1];
        G[i][2] = ic_interval_neg(R[1][i].d[0]), G[i][3] = ic_interval_neg(R[1][i].d[1]);
        if (centred_excludes(Dc[i], G[i], lo, hi, 4))
            return 1;
    }
    /* N . D with N = R_u x R_v of A at the centre (midpoints) */
    double Ru[3], Rv[3], N[3];
    for (int i = 0; i < 3; i++)
        Ru[i] = mid(Rc[0][i].d[0]).lo, Rv[i] = mid(Rc[0][i].d[1]).lo;
    N[0] = Ru[1] * Rv[2] - Ru[2] * Rv[1];
    N[1] = Ru[2] * Rv[0] - Ru[0] * Rv[2];
    N[2] = Ru[0] * Rv[1] - Ru[1] * Rv[0];
    if (!isfinite(N[0] + N[1] + N[2]))
        return 0;
    ic_interval hc = point(0.0), H[4] = {point(0), point(0), point(0), point(0)};
    for (int i = 0; i < 3; i++) {
        hc = ic_interval_add(hc, ic_interval_mul(point(N[i]), Dc[i]));
        for (int k = 0; k < 4; k++)
            H[k] = ic_interval_add(H[k], ic_interval_mul(point(N[i]), G[i][k]));
    }
    return centred_excludes(hc, H, lo, hi, 4);
}

int ic_trace_cell_excluded_centred(ic_surface *const S[2], int par0, int par1, const double *lo,
                                   const double *hi)
{
    if (par0 && par1)
        return parametric_pair(S, lo, hi);
    if (par0 || par1)
        return mixed_pair(S[par0 ? 0 : 1], S[par0 ? 1 : 0], lo, hi);
    return implicit_pair(S, lo, hi);
}
