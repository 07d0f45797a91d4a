/* The fit's check (fit_check.c): the fitted curve and its pcurves against
 * both surfaces at the middle of every stretch between the nodes (docs/bspline.md). */
#ifndef IC_CURVE_FIT_CHECK_H
#define IC_CURVE_FIT_CHECK_H

#include "curve/hermite.h"
#include "intercurve/bspline.h"
#include "intercurve/trace.h"
#include "intercurve/jet.h"
#include "intercurve/local.h"

/* The jet spaces the fit evaluates in, made once for all its rounds: a
 * sheet's derivatives (two variables to order 2), and the check's distances
 * to a sheet and to an implicit surface (two and three variables to order
 * 1, check_at). */
typedef struct {
    ic_jet_space *sheet, *sheet1, *point1;
} fit_spaces;

void ic_fit_spaces_free(fit_spaces *sp);
ic_status ic_fit_spaces_new(fit_spaces *sp, ic_error *err);

/* The nearest representative of x modulo the period (periodic directions)
 * to predicted; x itself where period is not positive. */
double ic_fit_unwrap(double x, double predicted, double period);

/* The pcurves checked, then the fit, at the middles of the stretches
 * between the n nodes (source[k]: node k's traced point): f's fit_error
 * and checks set, the middles where the error passes tol in bad[0..*nbad). */
ic_status ic_fit_check_all(ic_pair *pair, ic_curve_fit *f, const ic_trace_curve *c,
                           const ic_hermite_node *nodes, const int *source, int n, double tol,
                           const fit_spaces *sp, double *bad, int *nbad, ic_error *err);

#endif
