/* The bend across a tangential curve (pair_access.h; docs/tracing.md,
 * "Crossings of a tangential curve"). */
#include "local_internal.h"
#include "common/vec3.h"

#include <math.h>

/*
 * Along a tangential curve with tangent T the height difference g of B over
 * A (heights along A's normal N) has the quadratic part (bend / 2) w^2 in
 * the direction W = N x T across the curve: g's second derivatives along T
 * and across (T, W) vanish there, the curve being one of contact. So the
 * trace of II_B - II_A (B's normal turned to A's side) over the tangent
 * plane is the bend, and needs no T: twice the difference of the mean
 * curvatures. It vanishes where the whole quadratic part does.
 */
static double trace_second_form(const ic_sheet *sh, const double e1[3], const double e2[3])
{
    return ic_sheet_second_form(sh, e1, e1) + ic_sheet_second_form(sh, e2, e2);
}

ic_status ic_local_tangential_bend(ic_pair *pair, const ic_local_point *pt, double *bend,
                                   ic_error *err)
{
    ic_sheet sh[2];
    for (int s = 0; s < 2; s++) {
        const ic_status st = ic_sheet_at(pair, &sh[s], s, pt, err);
        if (st != IC_OK)
            return ic_sheet_singular(err, st, s);
    }
    const double *N = sh[0].geo.normal;
    double e1[3], e2[3];
    ic_plane_basis3(N, e1, e2);
    const double side = ic_dot3(N, sh[1].geo.normal) < 0 ? -1.0 : 1.0;
    *bend = side * trace_second_form(&sh[1], e1, e2) - trace_second_form(&sh[0], e1, e2);
    return isfinite(*bend) ? IC_OK : ic_error_set(err, IC_ERR_UNABLE, 0, "the bend is not finite");
}
