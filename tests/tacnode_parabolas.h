/* The parabolas of examples/tacnode.json (and its B-spline form,
 * tests/data/nurbs/problem-tacnode-nurbs.json): y = a X^2 in the tilted
 * plane c z = s x, X = c x + s z, c = cos 0.3, s = sin 0.3; a = 3/2 and
 * -1/2, tangent at the tacnode at the origin. */
#ifndef IC_TEST_TACNODE_PARABOLAS_H
#define IC_TEST_TACNODE_PARABOLAS_H

#include <math.h>

#include "intercurve.h"

/* relative: curvature at the traced points of the tacnode's parabolas.
 * Within reach of the branch series at the tacnode the points take its
 * apparatus (exact to 1e-12); just beyond, the jet method's frame matrix is
 * still nearly singular and loses digits as eps / angle^2: 3e-8 measured on
 * the B-spline form, 1.2e-9 on the formulas. (A sign slip in the series'
 * truncation test once gave 3.5e-2.) */
#define TACNODE_KAPPA_REL 1e-7

/* The largest relative curvature error over the traced points of the
 * parabola y = a X^2: kappa = 2|a| / (1 + 4 a^2 X^2)^(3/2). */
static inline double tacnode_kappa_error(const ic_trace_curve *c, double a)
{
    double worst = 0;
    for (int j = 0; j < c->npoints; j++) {
        const double *x = c->points[j].xyz, X = cos(0.3) * x[0] + sin(0.3) * x[2];
        const double kappa = 2 * fabs(a) / pow(1 + 4 * a * a * X * X, 1.5);
        worst = fmax(worst, fabs(c->points[j].kappa - kappa) / kappa);
    }
    return worst;
}

/* Which parabola c is: the a (3/2 or -1/2) whose y = a X^2 its middle point
 * is nearer to. */
static inline double tacnode_parabola_of(const ic_trace_curve *c)
{
    const double *x = c->points[c->npoints / 4].xyz, X = cos(0.3) * x[0] + sin(0.3) * x[2];
    return fabs(x[1] - 1.5 * X * X) < fabs(x[1] + 0.5 * X * X) ? 1.5 : -0.5;
}

#endif
