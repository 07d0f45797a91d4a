/* A self-intersection R(u, v) = R(p, q) with (u, v) != (p, q): two
 * parametric sheets of one surface (pairing_params.c), with one sheet pair
 * per curve ((u, v) before (p, q)) and the trivial diagonal (u, v) = (p, q),
 * a whole surface of solutions, kept away from. */
#include "pairing.h"

#include <math.h>

/* One sheet pair per curve, and away from the diagonal by `band` (two leaf
 * widths of the first search: the band does not shrink with refinement). */
static int skip(const ic_pairing *p, const double *lo, const double *hi, int leaf,
                const double band[2])
{
    (void)p;
    return lo[0] > hi[2] ||
           (leaf && hi[0] >= lo[2] - band[0] && lo[0] <= hi[2] + band[0] &&
            hi[1] >= lo[3] - band[1] && lo[1] <= hi[3] + band[1]);
}

static int distinct(const ic_pairing *p, const double *z, const double band[2])
{
    (void)p;
    return fabs(z[0] - z[2]) + fabs(z[1] - z[3]) > 2 * (band[0] + band[1]);
}

static ic_status region(const ic_pairing *p, const double box[3][2], int has_box, double *lo,
                        double *hi, int *periodic, ic_error *err)
{
    return ic_pairing_params.region(p, box, has_box, lo, hi, periodic, err);
}

static int enclosable(const ic_pairing *p, const double *lo, const double *hi)
{
    return ic_pairing_params.enclosable(p, lo, hi);
}

static int excluded(const ic_pairing *p, const double *lo, const double *hi)
{
    return ic_pairing_params.excluded(p, lo, hi);
}

static int overflows(const ic_pairing *p, const double *lo, const double *hi)
{
    return ic_pairing_params.overflows(p, lo, hi);
}

static int newton(const ic_pairing *p, double accept_rel, double L, double *z, double *xyz)
{
    return ic_pairing_params.newton(p, accept_rel, L, z, xyz);
}

static void unflatten(const ic_pairing *p, const double *z, double params[2][2])
{
    ic_pairing_params.unflatten(p, z, params);
}

static void flatten(const ic_pairing *p, const double xyz[3], const double params[2][2],
                    double *z)
{
    ic_pairing_params.flatten(p, xyz, params, z);
}

static ic_status section(const ic_pairing *p, const double *z, const double t[3],
                         const double X0[3], double F[4], double J[4][4], double X[3],
                         ic_error *err)
{
    return ic_pairing_params.section(p, z, t, X0, F, J, X, err);
}

static void step(const ic_pairing *p, double *z, const double *dz)
{
    ic_pairing_params.step(p, z, dz);
}

static ic_status position(const ic_pairing *p, const double *z, double xyz[3], ic_error *err)
{
    return ic_pairing_params.position(p, z, xyz, err);
}

static int contact_residuals(const ic_pairing *p, const double *z, double L, double *F)
{
    return ic_pairing_params.contact_residuals(p, z, L, F);
}

static void place(const ic_pairing *p, const double *lo, const double *hi, double xyz[3],
                  double params[2][2], double *radius)
{
    ic_pairing_params.place(p, lo, hi, xyz, params, radius);
}

static int loop_free(const ic_pairing *p, const double *lo, const double *hi)
{
    return ic_pairing_params.loop_free(p, lo, hi);
}

static int excluded_centred(const ic_pairing *p, const double *lo, const double *hi)
{
    return ic_pairing_params.excluded_centred(p, lo, hi);
}

static int may_degenerate(const ic_pairing *p, const double *lo, const double *hi)
{
    return ic_pairing_params.may_degenerate(p, lo, hi);
}

const ic_pairing_kind ic_pairing_self = {
    .name = "self-intersection",
    .dim = 4,
    .nparams = 4,
    .region = region,
    .enclosable = enclosable,
    .excluded = excluded,
    .overflows = overflows,
    .newton = newton,
    .unflatten = unflatten,
    .flatten = flatten,
    .place = place,
    .contact_residuals = contact_residuals,
    .section = section,
    .step = step,
    .position = position,
    .loop_free = loop_free,
    .excluded_centred = excluded_centred,
    .may_degenerate = may_degenerate,
    .skip = skip,
    .distinct = distinct,
};
