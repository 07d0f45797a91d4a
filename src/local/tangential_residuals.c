/* The residuals of a tangential point over the unknowns of each pairing
 * (tangential_residuals.h). */
#include "tangential_residuals.h"
#include "common/vec3.h"

#include <math.h>
#include <string.h>

/* Builds the point from the unknowns. */
void ic_tres_unpack(const ic_tres *c, const double *z, ic_local_point *pt)
{
    *pt = c->base;
    int k = 0;
    if (!c->par[0] && !c->par[1]) {
        memcpy(pt->xyz, z, 3 * sizeof *z);
        return;
    }
    for (int s = 0; s < 2; s++)
        if (c->par[s] && !(c->reduced && s == 1)) {
            pt->params[s][0] = z[k++];
            pt->params[s][1] = z[k++];
        }
}

/* The reduced residuals: R_A(u, v) - R_B(projection) over L, N_A x N_B;
 * pt->params[1] receives the projection. */
int ic_tres_reduced_at(const ic_tres *c, ic_local_point *pt, double *F)
{
    ic_surface_geometry g[2];
    double dist;
    if (ic_surface_normal_at(ic_pair_surface(c->pair, 0), &g[0], pt->params[0], NULL) != IC_OK ||
        ic_local_project(c->pair, 1, pt->params[1], g[0].point, c->opt, &dist) != IC_OK ||
        ic_surface_normal_at(ic_pair_surface(c->pair, 1), &g[1], pt->params[1], NULL) != IC_OK)
        return -1;
    for (int k = 0; k < 3; k++)
        F[k] = (g[0].point[k] - g[1].point[k]) / c->L;
    ic_cross3(F + 3, g[0].normal, g[1].normal);
    return 6;
}

/* Residuals: returns their number, or -1 where a surface is singular. */
int ic_tres_residuals(const ic_tres *c, const double *z, double *F)
{
    ic_local_point pt;
    ic_tres_unpack(c, z, &pt);
    if (c->reduced)
        return ic_tres_reduced_at(c, &pt, F);
    ic_surface_geometry g[2];
    double X[2][3];
    for (int s = 0; s < 2; s++) {
        ic_surface *srf = ic_pair_surface(c->pair, s);
        if (c->par[s]) {
            if (ic_surface_normal_at(srf, &g[s], pt.params[s], NULL) != IC_OK)
                return -1;
            memcpy(X[s], g[s].point, sizeof X[s]);
        }
    }
    int m = 0;
    if (c->par[0] && c->par[1]) {
        for (int k = 0; k < 3; k++)
            F[m++] = (X[0][k] - X[1][k]) / c->L;
    } else {
        const double *P = c->par[0] ? X[0] : c->par[1] ? X[1] : pt.xyz;
        for (int s = 0; s < 2; s++)
            if (!c->par[s]) {
                if (ic_surface_normal_at(ic_pair_surface(c->pair, s), &g[s], P, NULL) != IC_OK)
                    return -1;
                F[m++] = g[s].value / g[s].normal_length / c->L;
            }
    }
    double cr[3];
    ic_cross3(cr, g[0].normal, g[1].normal);
    for (int k = 0; k < 3; k++)
        F[m++] = cr[k];
    return m;
}

/* The largest residual at z (infinite where a surface is singular or the
 * count differs from m). */
double ic_tres_worst(const ic_tres *c, const double *z, int m, double *F)
{
    if (ic_tres_residuals(c, z, F) != m)
        return INFINITY;
    double w = 0;
    for (int i = 0; i < m; i++)
        w = fmax(w, fabs(F[i]));
    return isnan(w) ? INFINITY : w;
}

/* Sets up the unknowns from `near`. */
void ic_tres_setup(ic_tres *c, ic_pair *pair, const ic_local_point *near, const ic_local_options *opt,
                  double *z)
{
    memset(c, 0, sizeof *c);
    c->pair = pair;
    c->opt = opt;
    c->base = *near;
    c->L = opt && opt->scale > 0 && isfinite(opt->scale) ? opt->scale : 1.0;
    for (int s = 0; s < 2; s++) {
        c->par[s] = ic_surface_get_kind(ic_pair_surface(pair, s)) == IC_PARAMETRIC;
        if (c->par[s]) {
            z[c->n++] = near->params[s][0];
            z[c->n++] = near->params[s][1];
        }
    }
    if (c->n == 0) {
        memcpy(z, near->xyz, sizeof near->xyz);
        c->n = 3;
    }
}

/* The reduced context of two parametric sheets at the unknowns z. */
void ic_tres_reduce(const ic_tres *c, const double *z, ic_tres *r)
{
    *r = *c;
    ic_tres_unpack(c, z, &r->base);
    r->reduced = 1;
    r->n = 2;
}

