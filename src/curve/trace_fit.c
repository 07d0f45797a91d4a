/* The B-spline fits of a whole trace (ic_trace_fit, include/intercurve/trace.h):
 * each traced curve fitted by ic_curve_fit_new, kept with the result, which
 * frees them through free_fits when it is freed. */
#include "common/args.h"
#include "intercurve/bspline.h"
#include "intercurve/trace.h"
#include "trace/core/result.h"

#include <math.h>
#include <stdlib.h>

/* Frees the fits of a result's n curves and their array. */
static void free_fits(ic_curve_fit **fits, int n)
{
    for (int i = 0; i < n; i++)
        ic_curve_fit_free(fits[i]);
    free(fits);
}

ic_status ic_trace_fit(ic_trace_result *r, ic_pair *pair, double fit_tol, ic_error *err)
{
    IC_ARG_NOT_NULL(r, "res");
    IC_ARG_NOT_NULL(pair, "pair");
    if (!(fit_tol > 0) || !isfinite(fit_tol))
        return ic_error_set(err, IC_ERR_INVALID, 0, "ic_trace_fit: a result, its pair and a "
                                                    "positive tolerance");
    const double tol = fit_tol * r->scale;
    if (!r->fits && r->ncurves > 0 && !(r->fits = calloc((size_t)r->ncurves, sizeof *r->fits)))
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory fitting curves");
    r->free_fits = free_fits;
    r->report.fit_tol = tol;
    r->report.fit_error = 0;
    for (int i = 0; i < r->ncurves; i++) {
        ic_curve_fit_free(r->fits[i]);
        r->fits[i] = NULL;
        ic_error e2;
        const ic_status st = ic_curve_fit_new(&r->fits[i], pair, &r->curves[i], tol, &e2);
        if (st == IC_ERR_NOMEM)
            return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory fitting curves");
        if (st == IC_OK)
            r->report.fit_error = fmax(r->report.fit_error, r->fits[i]->fit_error);
    }
    return IC_OK;
}
