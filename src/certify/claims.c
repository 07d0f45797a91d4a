/*
 * The claim's points held against the surfaces (match.h): every point of a
 * traced curve must lie on the intersection, to first order within
 * IC_CERTIFY_POINT_REACH of the region's width (the walk through the cells,
 * match.c, checks chords and crossings, not each point: a point moved off
 * the curve inside one cell went unseen), except inside a singular box,
 * where a surface's own singular point may leave no gradient to measure by.
 * And the cells in a tube are not examined (tube.c), so a tube stands only
 * where the surfaces do touch. Each point of a curve the result calls tangential
 * must lie on both surfaces with their normals parallel, to
 * IC_CERTIFY_TANGENTIAL_RESIDUAL. A sampled test, not an enclosure: it
 * refutes a tube about a transversal curve or about nothing (a tube claimed
 * in empty space, or about a curve that crosses at a visible angle), not a
 * transversal curve whose surfaces meet at an angle below the tolerance.
 */
#include "match.h"

#include <math.h>

/* The point of curve k at j, refused when it is no tangential point. */
static int tangential_point(ic_certificate *c, int k, int j, const double *z)
{
    double w[4], F[8];
    ic_certificate_wrap(c, z, w);
    const double L = c->singular_half / IC_CERTIFY_SINGULAR_HALF;
    const int n = c->pg->kind->contact_residuals(c->pg, w, L, F);
    double worst = 0.0;
    for (int i = 0; i < n; i++)
        worst = fmax(worst, fabs(F[i]));
    if (n < 0 || worst <= IC_CERTIFY_TANGENTIAL_RESIDUAL)
        return 1; /* a singular normal: a surface's own point, not tested */
    ic_certificate_refuse(c,
                          "curve %d is called tangential but its point %d is not a point where "
                          "the surfaces touch (residual %.3g of the region's size and in the "
                          "normals' angle, more than %g)",
                          k, j, worst, IC_CERTIFY_TANGENTIAL_RESIDUAL);
    return 0;
}

int ic_certify_tubes_real(ic_certificate *c, const ic_certify_curve *curves, int ncurves)
{
    for (int k = 0; k < ncurves; k++) {
        if (!curves[k].tangential)
            continue;
        for (int j = 0; j < curves[k].npoints; j++)
            if (!tangential_point(c, k, j, curves[k].z + (size_t)j * (size_t)c->dim))
                return 0;
    }
    return 1;
}

/* The point z (search coordinates) lies within a singular box, in space. */
static int in_a_box(const ic_certificate *c, const double *z)
{
    double xyz[3];
    if (c->pg->kind->position(c->pg, z, xyz, NULL) != IC_OK)
        return 0;
    for (int s = 0; s < c->nsingular; s++) {
        const double h = c->singular_half * c->singular_scale[s];
        const double *p = c->singular[s];
        if (fabs(xyz[0] - p[0]) <= h && fabs(xyz[1] - p[1]) <= h && fabs(xyz[2] - p[2]) <= h)
            return 1;
    }
    return 0;
}

/* Search coordinates' rounding where the user's points are stored: a
 * trace of a problem moved near the origin (trace/frame.h) is saved at its
 * place, to half a unit in the last place of the origin there, and verify
 * moves the points back (exactly, but rounded already); 4 units of the
 * largest origin's magnitude, 0 when nothing moved. */
static double stored_rounding(const ic_certificate *c)
{
    double far = 0.0;
    for (int k = 0; k < c->dim; k++)
        far = fmax(far, fabs(ic_certificate_origin(c, k)));
    return far > 0 ? 4 * (nextafter(far, INFINITY) - far) : 0.0;
}

int ic_certify_points_on(ic_certificate *c, const ic_certify_curve *curves, int ncurves)
{
    double width = 0.0;
    for (int k = 0; k < c->dim; k++)
        width = fmax(width, c->hi[k] - c->lo[k]);
    /* a point is on the curve to its reach in the region or to its storage */
    const double reach = fmax(IC_CERTIFY_POINT_REACH * width, stored_rounding(c));
    for (int k = 0; k < ncurves; k++) {
        if (curves[k].tangential)
            continue; /* its own test: ic_certify_tubes_real */
        for (int j = 0; j < curves[k].npoints; j++) {
            const double *z = curves[k].z + (size_t)j * (size_t)c->dim;
            double w[4];
            ic_certificate_wrap(c, z, w);
            if (ic_certify_near_curve(c, w, reach) || in_a_box(c, w))
                continue;
            ic_certificate_refuse(c,
                                  "point %d of curve %d is not on the intersection (farther "
                                  "than %g of the region's width, to first order)",
                                  j, k, IC_CERTIFY_POINT_REACH);
            return 0;
        }
    }
    return 1;
}
