/* A parametric sheet R(u, v) and an implicit surface f: f(R(u, v)) = 0,
 * searched over the sheet's (u, v) domain. */
#include "pairing.h"
#include "common/vec3.h"

#include <math.h>
#include <string.h>

static ic_status region(const ic_pairing *p, const double box[3][2], int has_box, double *lo,
                        double *hi, int *periodic, ic_error *err)
{
    (void)box, (void)has_box;
    return ic_pairing_domain_box(p, p->P, lo, hi, periodic, err);
}

/* f's enclosure over the sheet's image of the cell; 0 where either fails. */
static int enclose(const ic_pairing *p, const double *lo, const double *hi, ic_interval xyz[3],
                   ic_interval *f)
{
    const ic_interval box[2] = {{lo[0], hi[0]}, {lo[1], hi[1]}};
    return ic_pairing_enclose_sheet(p, p->P, box, xyz) &&
           ic_pairing_enclose_sheet(p, p->I, xyz, f);
}

static int enclosable(const ic_pairing *p, const double *lo, const double *hi)
{
    ic_interval xyz[3], f;
    return enclose(p, lo, hi, xyz, &f);
}

static int excluded(const ic_pairing *p, const double *lo, const double *hi)
{
    ic_interval xyz[3], f;
    return enclose(p, lo, hi, xyz, &f) && ic_pairing_excludes_zero(f);
}

static int overflows(const ic_pairing *p, const double *lo, const double *hi)
{
    ic_interval xyz[3], f;
    if (!enclose(p, lo, hi, xyz, &f))
        return 1;
    for (int k = 0; k < 3; k++)
        if (ic_pairing_unbounded(xyz[k]))
            return 1;
    return ic_pairing_unbounded(f);
}

/* Min-norm Newton onto f(R(u, v)) = 0 from z = (u, v). */
static int newton(const ic_pairing *p, double accept_rel, double L, double *z, double *xyz)
{
    for (int it = 0; it < 40; it++) {
        double t[9], f, g[3];
        if (ic_surface_taylor(p->S[p->P], t, z, p->sp2, NULL))
            return -1;
        const double X[3] = {t[0], t[3], t[6]};
        const double Ru[3] = {t[1], t[4], t[7]}, Rv[3] = {t[2], t[5], t[8]};
        if (ic_pairing_value_grad(p->S[p->I], p->sp3, X, &f, g))
            return -1;
        const double du = ic_dot3(g, Ru), dv = ic_dot3(g, Rv), nn = du * du + dv * dv;
        if (!(nn > 0))
            return -1;
        z[0] -= f * du / nn;
        z[1] -= f * dv / nn;
        memcpy(xyz, X, sizeof X);
        if (fabs(f) * sqrt(1 / nn) <= 1e-15 * (1 + fabs(z[0]) + fabs(z[1])))
            return fabs(f) / ic_norm3(g) < accept_rel * (L + ic_norm3(xyz)) ? 0 : -1;
    }
    return -1;
}

static void unflatten(const ic_pairing *p, const double *z, double params[2][2])
{
    params[p->P][0] = z[0], params[p->P][1] = z[1];
}

static void place(const ic_pairing *p, const double *lo, const double *hi, double xyz[3],
                  double params[2][2], double *radius)
{
    const double c[2] = {0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])};
    unflatten(p, c, params);
    ic_pairing_place_sheet(p, p->P, lo, hi, xyz, radius);
}

const ic_pairing_kind ic_pairing_mixed = {
    "parametric/implicit", 2, region, enclosable, excluded, overflows, newton, unflatten, place,
    NULL, NULL};
