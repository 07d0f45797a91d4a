/* The pairing's equations over a cell (system.h). */
#include "system.h"

#include <math.h>
#include <string.h>

int ic_certify_equations(const ic_pairing *pg) { return pg->kind->dim - 1; }

static int finite(ic_interval a) { return isfinite(a.lo) && isfinite(a.hi) && a.lo <= a.hi; }

static int enclose_implicit(const ic_pairing *pg, const ic_interval *X, ic_certify_eval *out)
{
    for (int s = 0; s < 2; s++) {
        ic_interval_grad g;
        if (ic_surface_eval_interval_grad(pg->S[s], &g, X, NULL) != IC_OK)
            return 0;
        out->F[s] = g.v;
        for (int j = 0; j < 3; j++)
            out->J[s][j] = g.d[j];
    }
    return 1;
}

static int enclose_mixed(const ic_pairing *pg, const ic_interval *X, ic_certify_eval *out)
{
    ic_interval_grad R[3], g;
    if (ic_surface_eval_interval_grad(pg->S[pg->P], R, X, NULL) != IC_OK)
        return 0;
    const ic_interval Rv[3] = {R[0].v, R[1].v, R[2].v};
    if (ic_surface_eval_interval_grad(pg->S[pg->I], &g, Rv, NULL) != IC_OK)
        return 0;
    out->F[0] = g.v;
    for (int j = 0; j < 2; j++) { /* dF/du_j = grad f(R) . dR/du_j */
        ic_interval s = {0.0, 0.0};
        for (int i = 0; i < 3; i++)
            s = ic_interval_add(s, ic_interval_mul(g.d[i], R[i].d[j]));
        out->J[0][j] = s;
    }
    return 1;
}

static int enclose_params(const ic_pairing *pg, const ic_interval *X, ic_certify_eval *out)
{
    ic_interval_grad A[3], B[3];
    if (ic_surface_eval_interval_grad(pg->S[0], A, X, NULL) != IC_OK ||
        ic_surface_eval_interval_grad(pg->S[1], B, X + 2, NULL) != IC_OK)
        return 0;
    for (int i = 0; i < 3; i++) {
        out->F[i] = ic_interval_sub(A[i].v, B[i].v);
        out->J[i][0] = A[i].d[0], out->J[i][1] = A[i].d[1];
        out->J[i][2] = ic_interval_neg(B[i].d[0]), out->J[i][3] = ic_interval_neg(B[i].d[1]);
    }
    return 1;
}

int ic_certify_enclose(const ic_pairing *pg, const ic_interval *X, ic_certify_eval *out)
{
    const int dim = pg->kind->dim;
    int ok = dim == 3 ? enclose_implicit(pg, X, out)
             : dim == 2 ? enclose_mixed(pg, X, out)
                        : enclose_params(pg, X, out);
    for (int i = 0; ok && i < dim - 1; i++) {
        ok = finite(out->F[i]);
        for (int j = 0; ok && j < dim; j++)
            ok = finite(out->J[i][j]);
    }
    return ok;
}

int ic_certify_at(const ic_pairing *pg, const double *z, double F[3], double J[3][4])
{
    ic_interval X[4];
    const int dim = pg->kind->dim;
    for (int j = 0; j < dim; j++)
        X[j] = (ic_interval){z[j], z[j]};
    ic_certify_eval e;
    if (!ic_certify_enclose(pg, X, &e))
        return 0;
    for (int i = 0; i < dim - 1; i++) {
        F[i] = 0.5 * e.F[i].lo + 0.5 * e.F[i].hi;
        for (int j = 0; j < dim; j++)
            J[i][j] = 0.5 * e.J[i][j].lo + 0.5 * e.J[i][j].hi;
    }
    return 1;
}

int ic_certify_excludes(const ic_certify_eval *e, int m)
{
    for (int i = 0; i < m; i++)
        if (e->F[i].lo > 0.0 || e->F[i].hi < 0.0)
            return 1;
    return 0;
}

int ic_certify_image(const ic_pairing *pg, const ic_interval *X, ic_interval xyz[3])
{
    const int dim = pg->kind->dim;
    if (dim == 3) {
        memcpy(xyz, X, 3 * sizeof *xyz);
        return 1;
    }
    const int s = dim == 2 ? pg->P : 0;
    if (ic_surface_eval_interval(pg->S[s], xyz, X, NULL) != IC_OK)
        return 0;
    return finite(xyz[0]) && finite(xyz[1]) && finite(xyz[2]);
}

int ic_certify_image_grad(const ic_pairing *pg, const ic_interval *X, int k, ic_interval *v,
                          ic_interval g[4])
{
    const int dim = pg->kind->dim;
    if (dim == 3) {
        *v = X[k];
        for (int j = 0; j < 3; j++)
            g[j] = (ic_interval){j == k, j == k};
        return 1;
    }
    ic_interval_grad R[3];
    if (ic_surface_eval_interval_grad(pg->S[dim == 2 ? pg->P : 0], R, X, NULL) != IC_OK)
        return 0;
    *v = R[k].v;
    for (int j = 0; j < dim; j++)
        g[j] = j < 2 ? R[k].d[j] : (ic_interval){0.0, 0.0};
    return finite(*v) && finite(g[0]) && finite(g[1]);
}

/* 1 when the interval [lo, hi] is finite and excludes 0. */
static int finite_excludes(ic_interval a) { return finite(a) && (a.lo > 0.0 || a.hi < 0.0); }

int ic_certify_values_exclude(const ic_pairing *pg, const ic_interval *X)
{
    ic_interval v[3], w[3];
    const int dim = pg->kind->dim;
    if (dim == 3) {
        for (int s = 0; s < 2; s++)
            if (ic_surface_eval_interval(pg->S[s], v, X, NULL) == IC_OK && finite_excludes(v[0]))
                return 1;
        return 0;
    }
    if (dim == 2)
        return ic_surface_eval_interval(pg->S[pg->P], v, X, NULL) == IC_OK &&
               ic_surface_eval_interval(pg->S[pg->I], w, v, NULL) == IC_OK &&
               finite_excludes(w[0]);
    if (ic_surface_eval_interval(pg->S[0], v, X, NULL) != IC_OK ||
        ic_surface_eval_interval(pg->S[1], w, X + 2, NULL) != IC_OK)
        return 0;
    for (int i = 0; i < 3; i++)
        if (finite_excludes(ic_interval_sub(v[i], w[i])))
            return 1;
    return 0;
}
