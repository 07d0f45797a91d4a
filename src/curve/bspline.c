/* B-spline curves: evaluation of points and derivatives (bspline.h). */
#include "common/args.h"
#include "intercurve/bspline.h"

#include <math.h>
#include <string.h>

#include "surface/nurbs.h"

static ic_status malformed(ic_error *err, const char *what)
{
    return ic_error_set(err, IC_ERR_INVALID, 0, "B-spline curve: %s", what);
}

ic_status ic_bspline_eval(const ic_bspline *c, double t, int nderiv, double *out, ic_error *err)
{
    IC_ARG_NOT_NULL(c, "c");
    IC_ARG_NOT_NULL(out, "out");
    if (!c || !c->knots || !c->control || (c->dim != 2 && c->dim != 3))
        return malformed(err, "no curve, or a dimension other than 2 or 3");
    const int p = c->degree, n = c->ncontrol;
    if (p < 1 || p > IC_BSPLINE_MAX_DEGREE || n < p + 1)
        return malformed(err, "degree out of 1..9 or too few control points");
    if (nderiv < 0 || nderiv > p)
        return malformed(err, "derivative order out of 0..degree");
    if (!isfinite(t) || !(c->knots[p] < c->knots[n]))
        return malformed(err, "parameter not finite, or an empty parameter range");
    if (c->periodic) { /* into [lo, hi) */
        const double lo = c->knots[p], period = c->knots[n] - lo;
        t -= period * floor((t - lo) / period);
        if (!(t < c->knots[n]))
            t = lo;
    }
    const int s = ic_knot_span(c->knots, p, n, t, IC_NURBS_RIGHT);
    double b[IC_NURBS_MAX_DEGREE + 1][IC_NURBS_MAX_DEGREE + 1];
    ic_basis_taylor(b, c->knots, s, p, t, nderiv);
    double fact = 1;
    for (int k = 0; k <= nderiv; k++) {
        if (k > 0)
            fact *= k;
        for (int j = 0; j < c->dim; j++) {
            double v = 0;
            for (int i = 0; i <= p; i++)
                v += b[k][i] * c->control[c->dim * (s - p + i) + j];
            out[k * c->dim + j] = v * fact;
        }
    }
    return IC_OK;
}
