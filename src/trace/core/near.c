/* Whether something the trace has found (a traced curve, a recorded special
 * point) passes near a point: the question the search's candidates, the
 * open cells and the deferred candidates all ask. */
#include "common/vec3.h"
#include "curve_index.h"
#include "near.h"
#include "polyline.h"

int ic_trace_curves_near(const ic_trace_result *r, const double *x, double bound)
{
    const int hit = r->index ? ic_curve_index_near(r->index, r, x, bound) : -1;
    if (hit >= 0)
        return hit;
    for (int c = 0; c < r->ncurves; c++)
        if (ic_trace_polyline_distance(r->curves[c].points, r->curves[c].npoints, x, bound) <=
            bound)
            return 1;
    return 0;
}

int ic_trace_point_near_found(const ic_trace_result *r, const double *x, double bound)
{
    for (int k = 0; k < r->nspecials; k++) {
        double d[3];
        ic_axpy3(d, r->specials[k].xyz, -1.0, x);
        if (ic_norm3(d) <= bound)
            return 1;
    }
    return ic_trace_curves_near(r, x, bound);
}
