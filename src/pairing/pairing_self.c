/* A self-intersection R(u, v) = R(p, q) with (u, v) != (p, q): two
 * parametric sheets of one surface (pairing_params.c), with one sheet pair
 * per curve ((u, v) before (p, q)) and the trivial diagonal (u, v) = (p, q),
 * a whole surface of solutions, kept away from. */
#include "pairing.h"

#include <math.h>

/* dimensionless: two preimages closer than this fraction of the diagonal
 * band are one (Newton leaves trivial solutions apart by rounding, 1e-15 of
 * the domain; the band is about 1/16 of it) */
#define SELF_DISTINCT_OF_BAND 1e-6

/* 1 when R is proven one-to-one over the (u, v) box [lo, hi]: for a and b
 * in the box, R(a) - R(b) = M (a - b) with row i of M the gradient of R_i at
 * a point between them (mean value theorem, row by row), so M lies in the
 * interval matrix of R's gradients over the box; where a 2 x 2 minor of it
 * excludes 0, every such M has rank 2 and R(a) = R(b) forces a = b. */
static int injective(const ic_pairing *p, const double lo[2], const double hi[2])
{
    const ic_interval box[2] = {{lo[0], hi[0]}, {lo[1], hi[1]}};
    ic_interval_grad R[3];
    if (ic_surface_eval_interval_grad(p->S[0], R, box, NULL) != IC_OK)
        return 0;
    for (int i = 0; i < 3; i++) {
        const int j = (i + 1) % 3;
        const ic_interval minor = ic_interval_sub(ic_interval_mul(R[i].d[0], R[j].d[1]),
                                                  ic_interval_mul(R[i].d[1], R[j].d[0]));
        if (ic_pairing_excludes_zero(minor))
            return 1;
    }
    return 0;
}

/* The period of the sheet's parameter k, 0 where it is not periodic. */
static double period(const ic_pairing *p, int k)
{
    double dom[2][2];
    int periodic[2];
    ic_surface_get_domain(p->S[0], dom, periodic);
    return periodic[k] ? dom[k][1] - dom[k][0] : 0.0;
}

/* The shift of the (p, q) box by whole periods that brings coordinate k
 * within `band` of the (u, v) box, in *shift; 0 when none does. On a
 * periodic parameter the diagonal also runs where u lies by one edge of
 * the domain and p by the other: the same point of the surface. */
static int near_shift(const ic_pairing *p, const double *lo, const double *hi, int k,
                      double band, double *shift)
{
    const double T = period(p, k);
    for (int s = -1; s <= 1; s++) {
        if (s != 0 && T == 0.0)
            continue;
        if (hi[k] >= lo[k + 2] + s * T - band && lo[k] <= hi[k + 2] + s * T + band) {
            *shift = s * T;
            return 1;
        }
    }
    return 0;
}

/* A leaf by the diagonal (lo, hi: (u, v, p, q)) proven to hold no pair
 * of distinct preimages: R one-to-one over the hull of its two boxes. */
static int trivial_leaf(const ic_pairing *p, const double *lo, const double *hi,
                        const double band[2])
{
    double shift[2];
    if (!near_shift(p, lo, hi, 0, band[0], &shift[0]) ||
        !near_shift(p, lo, hi, 1, band[1], &shift[1]))
        return 0;
    const double hlo[2] = {fmin(lo[0], lo[2] + shift[0]), fmin(lo[1], lo[3] + shift[1])};
    const double hhi[2] = {fmax(hi[0], hi[2] + shift[0]), fmax(hi[1], hi[3] + shift[1])};
    return injective(p, hlo, hhi);
}

/* The box [lo, hi] of one preimage carried back across the glued edges. */
static void glue_back_box(const ic_pairing *p, const double lo[2], const double hi[2],
                          double out_lo[2], double out_hi[2])
{
    double a[2], b[2];
    ic_pairing_glue_back(p, lo, a);
    ic_pairing_glue_back(p, hi, b);
    for (int k = 0; k < 2; k++)
        out_lo[k] = fmin(a[k], b[k]), out_hi[k] = fmax(a[k], b[k]);
}

/* The same with either box carried back across the glued edges
 * (pairing_glue.c): by the glue the points of both boxes are then of one
 * sheet beside the edge. */
static int trivial_glued_leaf(const ic_pairing *p, const double *lo, const double *hi,
                              const double band[2])
{
    if (p->glue.axis < 0)
        return 0;
    double glo[4] = {lo[0], lo[1], lo[2], lo[3]}, ghi[4] = {hi[0], hi[1], hi[2], hi[3]};
    glue_back_box(p, lo + 2, hi + 2, glo + 2, ghi + 2);
    if (trivial_leaf(p, glo, ghi, band))
        return 1;
    double alo[4] = {lo[0], lo[1], lo[2], lo[3]}, ahi[4] = {hi[0], hi[1], hi[2], hi[3]};
    glue_back_box(p, lo, hi, alo, ahi);
    return trivial_leaf(p, alo, ahi, band);
}

/* One sheet pair per curve ((u, v) before (p, q): a cell wholly after is
 * the mirror of one before); a leaf within `band` of the diagonal (two leaf
 * widths of the first search), modulo the periods, is skipped only where R
 * is proven one-to-one over the hull of its two parameter boxes, which then
 * holds no pair of distinct preimages. Elsewhere it is searched like any
 * cell (before: every such leaf was skipped, and at depth 3 the band held
 * the whole domain of Enneper's surface: no curve, "complete"). */
static int skip(const ic_pairing *p, const double *lo, const double *hi, int leaf,
                const double band[2])
{
    if (lo[0] > hi[2])
        return 1;
    return leaf && (trivial_leaf(p, lo, hi, band) || trivial_glued_leaf(p, lo, hi, band));
}

/* Preimages apart by more than a millionth of the band, modulo the
 * periods: Newton from a cell by the diagonal that lands on the diagonal
 * itself (a trivial solution, apart by rounding, or by a whole period on a
 * periodic parameter) gives no start point; a true pair of preimages close
 * together does. */
static double gap_mod_periods(const ic_pairing *p, const double a[2], const double b[2])
{
    double gap = 0.0;
    for (int k = 0; k < 2; k++) {
        const double T = period(p, k);
        const double d = a[k] - b[k];
        gap += fabs(T > 0.0 ? remainder(d, T) : d);
    }
    return gap;
}

double ic_pairing_self_gap(const ic_pairing *p, const double *z)
{
    double gap = gap_mod_periods(p, z, z + 2);
    if (p->glue.axis >= 0) { /* either preimage may be on the far edge's side */
        double back[2];
        ic_pairing_glue_back(p, z + 2, back);
        gap = fmin(gap, gap_mod_periods(p, z, back));
        ic_pairing_glue_back(p, z, back);
        gap = fmin(gap, gap_mod_periods(p, back, z + 2));
    }
    return gap;
}

static int distinct(const ic_pairing *p, const double *z, const double band[2])
{
    return ic_pairing_self_gap(p, z) > SELF_DISTINCT_OF_BAND * (band[0] + band[1]);
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
    IC_PAIRING_OPERATIONS,
    .skip = skip,
    .distinct = distinct,
};
