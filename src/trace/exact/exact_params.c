/* The parameters of any curve's points on recognised patches
 * (exact_source.h): each point's by inverting its patch's structure
 * (net_shape.c), a wrapping parameter continued from the point before, every
 * point checked on the patch. */
#include "exact_source.h"
#include "common/vec3.h"
#include "surface/surface_access.h"

#include <math.h>

/* Sheet s's parameters of the points, continued across a wrapping seam. */
static int sheet_params(const ic_exact_source *src, int s, ic_trace_point *pts, int n, double L)
{
    double dom[2][2];
    int periodic[2];
    ic_surface_get_domain(src->surface, dom, periodic);
    for (int i = 0; i < n; i++) {
        double *uv = pts[i].params[s], S[3], d[3];
        if (ic_net_params(src->net, pts[i].xyz, uv) != 0)
            return 1;
        for (int k = 0; i > 0 && k < 2; k++)
            if (periodic[k]) {
                const double period = dom[k][1] - dom[k][0];
                uv[k] += period * round((pts[i - 1].params[s][k] - uv[k]) / period);
            }
        ic_surface_nurbs_point(src->surface, uv, S);
        ic_axpy3(d, S, -1.0, pts[i].xyz);
        if (!(ic_norm3(d) <= IC_EXACT_ON_NET * L))
            return 1;
    }
    return 0;
}

int ic_exact_curve_params(const ic_exact_source src[2], ic_trace_point *pts, int n, double L)
{
    for (int s = 0; s < 2; s++)
        if (src[s].net && sheet_params(&src[s], s, pts, n, L) != 0)
            return 1;
    return 0;
}
