/*
 * Heights over the common tangent plane at a tangential point P
 * (docs/tangential.md): each sheet as a graph P + x e1 + y e2 + psi(x, y) N, with
 * psi a bivariate jet.
 *  - implicit f: f(P + x e1 + y e2 + psi N) = 0 solved degree by degree:
 *    psi_d = -[f(X with psi_<d)]_d / (grad f . N), after a Newton solve for
 *    the constant psi_0 (the sheet's offset from P along N); step d composes
 *    f in a space of order d only (the jets' higher degrees do not enter
 *    their degree-d part), which costs a third of composing at order H
 *    every time at H = 12;
 *  - parametric R: the map (u, v) -> (x, y) = ((R - P).e1, (R - P).e2) is
 *    reverted as a bivariate series G, and psi = ((R - P).N) o G.
 */
#include "tangential.h"
#include "common/vec3.h"
#include "surface/surface_jets.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static ic_status implicit_height(ic_surface *s, double *psi, const ic_heights *h,
                                 const ic_jet_space *sp, double *work, ic_error *err)
{
    const int n = ic_jet_space_len(sp);
    /* psi_0 and the normal derivative by Newton along N */
    double psi0 = 0.0, t1[4], fN = 0.0;
    const ic_jet_space *s1 = ic_surface_space(s, 1, err); /* cached there */
    if (!s1)
        return err ? err->code : IC_ERR_NOMEM;
    ic_status st = IC_OK;
    for (int it = 0; it < 50; it++) {
        double X[3];
        ic_axpy3(X, h->P, psi0, h->N);
        st = ic_surface_taylor(s, t1, X, s1, err);
        if (st != IC_OK)
            break;
        fN = t1[1] * h->N[0] + t1[2] * h->N[1] + t1[3] * h->N[2];
        if (fN == 0.0) {
            st = ic_error_set(err, IC_ERR_DOMAIN, 0, "grad f is tangent to the other surface");
            break;
        }
        const double step = t1[0] / fN;
        psi0 -= step;
        if (fabs(step) <= 1e-16 * (1 + fabs(psi0)))
            break;
    }
    if (st != IC_OK)
        return st;
    double *X[3] = {work, work + n, work + 2 * n}, *F = work + 3 * n;
    ic_jet_zero(psi, sp);
    psi[0] = psi0;
    const int H = ic_jet_space_order(sp);
    for (int d = 1; d <= H; d++) {
        /* the jets of order d are the first coefficients of those of order H */
        const ic_jet_space *spd = d < H ? ic_surface_plane_space(s, d, err) : sp;
        if (!spd)
            return err ? err->code : IC_ERR_NOMEM;
        const int nd = ic_jet_space_len(spd);
        for (int i = 0; i < 3; i++) {
            for (int k = 0; k < nd; k++)
                X[i][k] = psi[k] * h->N[i];
            X[i][0] += h->P[i];
            X[i][1] += h->e1[i];
            X[i][2] += h->e2[i];
        }
        const double *in[3] = {X[0], X[1], X[2]};
        st = ic_surface_compose(s, F, in, spd, err);
        if (st != IC_OK)
            return st;
        for (int k = ic_jet_degree_start(sp, d); k < ic_jet_degree_start(sp, d + 1); k++)
            psi[k] = -F[k] / fN;
    }
    return IC_OK;
}

static ic_status parametric_height(ic_surface *s, const double *uv, double *psi,
                                   const ic_heights *h, const ic_jet_space *sp, double *work,
                                   ic_error *err)
{
    const int n = ic_jet_space_len(sp);
    double *T = work, *X = work + 3 * n, *Y = work + 4 * n, *Hh = work + 5 * n;
    double *G0 = work + 6 * n, *G1 = work + 7 * n, *scratch = work + 8 * n;
    ic_status st = ic_surface_taylor(s, T, uv, sp, err);
    if (st != IC_OK)
        return st;
    for (int k = 0; k < n; k++) {
        double v[3] = {T[k], T[n + k], T[2 * n + k]};
        if (k == 0)
            ic_axpy3(v, v, -1.0, h->P);
        X[k] = ic_dot3(v, h->e1);
        Y[k] = ic_dot3(v, h->e2);
        Hh[k] = ic_dot3(v, h->N);
    }
    /* (x, y) offsets of this sheet's point from P are at the level of the
     * point's residual; the reversion expands about the sheet's own point */
    double *G[2] = {G0, G1};
    const double *F[2] = {X, Y};
    st = ic_jet_revert2(G, F, sp, scratch, err);
    if (st != IC_OK)
        return ic_error_set(err, IC_ERR_DOMAIN, 0,
                            "the surface is not a graph over the tangent plane here");
    const double *Gc[2] = {G0, G1};
    ic_jet_compose(psi, Hh, sp, Gc, sp, scratch);
    psi[0] = Hh[0];
    return IC_OK;
}

ic_status ic_heights_compute(ic_heights *h, const ic_sheet sh[2], const ic_jet_space *sp,
                             ic_error *err)
{
    memset(h, 0, sizeof *h);
    h->sp = sp;
    const ic_sheet *a = &sh[0];
    memcpy(h->N, a->geo.normal, sizeof h->N);
    memcpy(h->P, a->parametric ? a->geo.point : a->at, sizeof h->P);
    /* e1 along the first tangent basis vector, e2 = N x e1 */
    memcpy(h->e1, a->geo.basis[0], sizeof h->e1);
    ic_axpy3(h->e1, h->e1, -ic_dot3(h->e1, h->N), h->N);
    ic_normalize3(h->e1);
    ic_cross3(h->e2, h->N, h->e1);
    const int n = ic_jet_space_len(sp);
    h->psi[0] = calloc((size_t)n, sizeof(double));
    h->psi[1] = calloc((size_t)n, sizeof(double));
    h->g = calloc((size_t)n, sizeof(double));
    double *work = malloc((8 * (size_t)n + ic_jet_scratch_len(sp)) * sizeof(double));
    ic_status st = IC_OK;
    if (!h->psi[0] || !h->psi[1] || !h->g || !work)
        st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory at a tangential point");
    for (int s = 0; s < 2 && st == IC_OK; s++)
        st = sh[s].parametric
                 ? parametric_height(sh[s].s, sh[s].at, h->psi[s], h, sp, work, err)
                 : implicit_height(sh[s].s, h->psi[s], h, sp, work, err);
    free(work);
    if (st != IC_OK) {
        ic_heights_free(h);
        return ic_sheet_singular(err, st, 0);
    }
    for (int k = 0; k < n; k++)
        h->g[k] = h->psi[0][k] - h->psi[1][k];
    return IC_OK;
}

void ic_heights_free(ic_heights *h)
{
    free(h->psi[0]);
    free(h->psi[1]);
    free(h->g);
    h->psi[0] = h->psi[1] = h->g = NULL;
}
