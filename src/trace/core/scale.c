/*
 * The problem's length scale L (docs/tracing.md, "Scale"): the diagonal of
 * the region where the intersection is sought: the box for two implicit
 * surfaces; otherwise the bounding box of the parametric surfaces sampled
 * over their domains (cut to the box when there is one). Tolerances of the
 * tracer that are lengths are fractions of L, so a problem scaled by any
 * factor gives the same answer.
 */
#include "common/vec3.h"
#include "local/pair_access.h"
#include "options.h"
#include "surface/surface_access.h"

#include <math.h>

enum { SCALE_GRID = 17 };

/* Grows the box [lo, hi] by the samples of a parametric surface; sp: two
 * variables, order 2 (the point is each jet's constant term; a NURBS patch
 * gives the same bits without jets, several times faster). */
static void sample_bounds(ic_surface *s, const ic_jet_space *sp, double *lo, double *hi)
{
    double dom[2][2];
    int per[2];
    ic_surface_get_domain(s, dom, per);
    if (!isfinite(dom[0][1] - dom[0][0]) || !isfinite(dom[1][1] - dom[1][0]))
        return;
    for (int i = 0; i < SCALE_GRID; i++)
        for (int j = 0; j < SCALE_GRID; j++) {
            const double uv[2] = {dom[0][0] + (dom[0][1] - dom[0][0]) * i / (SCALE_GRID - 1),
                                  dom[1][0] + (dom[1][1] - dom[1][0]) * j / (SCALE_GRID - 1)};
            double t[18], x[3];
            if (ic_surface_nurbs_point(s, uv, x) != 0) {
                if (ic_surface_taylor(s, t, uv, sp, NULL) != IC_OK)
                    continue;
                x[0] = t[0], x[1] = t[6], x[2] = t[12];
            }
            if (!isfinite(x[0] + x[1] + x[2]))
                continue;
            for (int k = 0; k < 3; k++)
                lo[k] = fmin(lo[k], x[k]), hi[k] = fmax(hi[k], x[k]);
        }
}

void ic_trace_problem_bounds(ic_pair *pair, const ic_trace_options *opt, double lo[3],
                             double hi[3])
{
    for (int k = 0; k < 3; k++)
        lo[k] = INFINITY, hi[k] = -INFINITY;
    /* the pair's space (the surface's workspace for it is made with the
     * surface): a space made here could fail, and a smaller L would follow
     * (tests/test_nomem.c, "trace, mixed") */
    for (int s = 0; s < 2; s++) {
        ic_surface *S = ic_pair_surface(pair, s);
        if (ic_surface_get_kind(S) == IC_PARAMETRIC)
            sample_bounds(S, ic_pair_near_space(pair, 2), lo, hi);
    }
    for (int k = 0; opt->has_box && k < 3; k++) {
        /* the samples cut to the box; no samples there: the box itself */
        const double a = fmax(lo[k], opt->box[k][0]), b = fmin(hi[k], opt->box[k][1]);
        lo[k] = a <= b ? a : opt->box[k][0];
        hi[k] = a <= b ? b : opt->box[k][1];
    }
}

double ic_trace_problem_scale(ic_pair *pair, const ic_trace_options *opt)
{
    double lo[3], hi[3];
    ic_trace_problem_bounds(pair, opt, lo, hi);
    double d2 = 0;
    for (int k = 0; k < 3; k++)
        d2 += hi[k] > lo[k] ? (hi[k] - lo[k]) * (hi[k] - lo[k]) : 0.0;
    const double L = sqrt(d2);
    return isfinite(L) && L > 0 ? L : 1.0;
}
