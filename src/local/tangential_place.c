/* How well the place of a located tangential point is known
 * (ic_local_tangential_place): the residuals probed outwards along each
 * unknown until they grow steadily. */
#include "common/args.h"
#include "tangential_residuals.h"
#include "common/vec3.h"

#include <math.h>
#include <string.h>

/* The place radius probes each unknown's direction at distances
 * 10^-15 .. 10^-4 of its unit (L for a coordinate, 1 + |p| for a parameter);
 * from the rung where the residual starts to grow by at least this factor
 * per decade (half an order: a simple root grows tenfold, a root of
 * multiplicity k by 10^k) out, the point is told apart from its
 * neighbours. Each is pinned both ways by tests/test_constants.c: a simple
 * point's radius is at most 16 ulps of L, and no radius is below an eighth
 * of the true distance unless it is the top rung ("not known"). */
#define PLACE_FIRST_RUNG 1e-15
#define PLACE_RUNGS 12
#define PLACE_GROWTH 3.0

/* The xyz distance from pt to the point of unknowns z. */
static double xyz_distance(const ic_tres *c, const double *z, const ic_local_point *pt)
{
    ic_local_point q;
    if (ic_tres_position(c, z, q.xyz, NULL) != IC_OK)
        return INFINITY;
    double d[3];
    ic_axpy3(d, q.xyz, -1.0, pt->xyz);
    return ic_norm3(d);
}

/* The radius along unknown j, direction sgn: the distance of the innermost
 * rung from which the residual grows steadily out. */
static double place_along(const ic_tres *c, const double *z, int m, int j, int sgn,
                          const ic_local_point *pt)
{
    double r[PLACE_RUNGS], zs[PLACE_RUNGS][4], F[6];
    double rho = PLACE_FIRST_RUNG * (c->params ? 1.0 + fabs(z[j]) : c->L);
    for (int k = 0; k < PLACE_RUNGS; k++, rho *= 10) {
        memcpy(zs[k], z, sizeof zs[k]);
        zs[k][j] += sgn * rho;
        r[k] = ic_tres_worst(c, zs[k], m, F);
    }
    int k0 = PLACE_RUNGS - 1;
    while (k0 > 0 && r[k0] < INFINITY && r[k0] >= PLACE_GROWTH * r[k0 - 1])
        k0--;
    return xyz_distance(c, zs[k0], pt);
}

ic_status ic_local_tangential_place(ic_pair *pair, const ic_local_point *pt,
                                    const ic_local_options *opt, double *radius, ic_error *err)
{
    IC_ARG_NOT_NULL(pair, "pair");
    IC_ARG_NOT_NULL(pt, "pt");
    IC_ARG_NOT_NULL(radius, "radius");
    ic_tres c;
    double z[4] = {0}, F[6];
    ic_tres_setup(&c, pair, pt, opt, z);
    if (c.two_sheets && opt) { /* along (u, v), B following */
        ic_tres r;
        ic_tres_reduce(&c, z, &r);
        c = r;
    }
    const int m = ic_tres_residuals(&c, z, F);
    *radius = INFINITY;
    if (m < 0)
        return ic_error_set(err, IC_ERR_UNABLE, 0, "a surface is singular at the point");
    double worst = 0;
    for (int j = 0; j < c.n; j++)
        for (int sgn = -1; sgn <= 1; sgn += 2)
            worst = fmax(worst, place_along(&c, z, m, j, sgn, pt));
    *radius = worst;
    return IC_OK;
}
