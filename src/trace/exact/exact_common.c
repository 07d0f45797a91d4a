/* The exact paths' shared pieces (exact_common.h). */
#include "exact_common.h"

#include <math.h>

int ic_exact_box_side(const ic_trace_options *opt, const double centre[3], const double extent[3],
                      double L)
{
    const double m = IC_EXACT_BOX_MARGIN * L;
    int inside = 1;
    for (int k = 0; k < 3; k++) {
        const double x = centre[k], ext = extent[k];
        if (x + ext < opt->box[k][0] - m || x - ext > opt->box[k][1] + m)
            return 0;
        if (x - ext < opt->box[k][0] + m || x + ext > opt->box[k][1] - m)
            inside = -1;
    }
    return inside;
}

double ic_exact_circle_step(const ic_trace_options *opt, double rho)
{
    double h = opt->max_step, fact = 1.0;
    for (int k = 1; k <= opt->order; k++) {
        fact *= k;
        if (k >= opt->order - 1)
            h = fmin(h, pow(opt->tol * fact * pow(rho, k - 1), 1.0 / k));
    }
    return fmin(h, sqrt(8 * opt->chord * rho));
}

void ic_exact_extent_add(double lo[3], double hi[3], const double centre[3], const double extent[3])
{
    for (int k = 0; k < 3; k++) {
        lo[k] = fmin(lo[k], centre[k] - extent[k]);
        hi[k] = fmax(hi[k], centre[k] + extent[k]);
    }
}

double ic_exact_found_scale(double L, const double lo[3], const double hi[3])
{
    double d2 = 0;
    for (int k = 0; k < 3; k++)
        d2 += hi[k] > lo[k] ? (hi[k] - lo[k]) * (hi[k] - lo[k]) : 0.0;
    const double F = sqrt(d2);
    return isfinite(F) && F > 1e-3 * L && F < L ? F : L;
}

void ic_exact_report(ic_trace_report *rep, const char *method)
{
    rep->complete = 1;
    rep->proven = 1;
    rep->method = method;
}
