/* The residuals of a tangential point over the unknowns of each pairing
 * (tangential_residuals.h). */
#include "tangential_residuals.h"
#include "common/vec3.h"

#include <math.h>
#include <string.h>

/* Builds the point from the unknowns: the pairing's parameters and
 * position (a reduced context: A's parameters; B's stay the base's). */
void ic_tres_unpack(const ic_tres *c, const double *z, ic_local_point *pt)
{
    const ic_pairing *pg = ic_pair_pairing(c->pair);
    *pt = c->base;
    if (c->reduced) {
        pt->params[0][0] = z[0], pt->params[0][1] = z[1];
        return;
    }
    pg->kind->unflatten(pg, z, pt->params);
    double X[3];
    if (pg->kind->position(pg, z, X, NULL) == IC_OK)
        memcpy(pt->xyz, X, sizeof X);
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
    if (c->reduced) {
        ic_local_point pt;
        ic_tres_unpack(c, z, &pt);
        return ic_tres_reduced_at(c, &pt, F);
    }
    const ic_pairing *pg = ic_pair_pairing(c->pair);
    return pg->kind->contact_residuals(pg, z, c->L, F);
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
    const ic_pairing *pg = ic_pair_pairing(pair);
    c->n = pg->kind->dim;
    c->params = pg->kind->nparams > 0;
    c->two_sheets = pg->kind->nparams == 4;
    pg->kind->flatten(pg, near->xyz, near->params, z);
}

/* The reduced context of two parametric sheets at the unknowns z. */
void ic_tres_reduce(const ic_tres *c, const double *z, ic_tres *r)
{
    *r = *c;
    ic_tres_unpack(c, z, &r->base);
    r->reduced = 1;
    r->n = 2;
}


ic_status ic_tres_position(const ic_tres *c, const double *z, double xyz[3], ic_error *err)
{
    if (c->reduced) /* R_A(u, v) */
        return ic_surface_eval(ic_pair_surface(c->pair, 0), xyz, z, err);
    const ic_pairing *pg = ic_pair_pairing(c->pair);
    return pg->kind->position(pg, z, xyz, err);
}
