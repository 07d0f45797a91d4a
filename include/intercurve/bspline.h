/**
 * @file bspline.h
 * B-spline curves: the fitted form of a traced intersection curve in space
 * and its curves in the surfaces' parameter planes (docs/bspline.md).
 */
#ifndef INTERCURVE_BSPLINE_H
#define INTERCURVE_BSPLINE_H

#include "intercurve/common.h"

#ifdef __cplusplus
extern "C" {
#endif

/**
 * A B-spline curve c(t) = sum_i N_i,p(t) P_i over the knot vector `knots`
 * (ncontrol + degree + 1 values; the curve's parameter runs from
 * knots[degree] to knots[ncontrol]). A traced curve's B-spline is
 * parametrised by arc length s, as its points are.
 *
 * An open curve is clamped (its first and last knots repeated degree + 1
 * times). A periodic one (a closed curve, smooth where it closes) has an
 * unclamped knot vector continued by the period on both sides, and its
 * first `degree` control points repeated at the end; the same sum gives it
 * over its parameter range (docs/bspline.md, "Closed curves").
 */
typedef struct {
    int dim;         /**< 3 in space, 2 in a parameter plane (u, v) */
    int degree;      /**< 1..IC_BSPLINE_MAX_DEGREE */
    int ncontrol;    /**< control points, at least degree + 1 */
    double *knots;   /**< ncontrol + degree + 1 nondecreasing values */
    double *control; /**< point i at control[dim * i] */
    int periodic;    /**< 1: closed and periodic, as above */
} ic_bspline;

#define IC_BSPLINE_MAX_DEGREE 9

/**
 * The point and derivatives of c at t: out[k * dim + j] is the k-th
 * derivative of coordinate j, k = 0..nderiv (nderiv <= degree; higher
 * derivatives are 0 and not asked). t outside the parameter range takes
 * the end piece, or, on a periodic curve, is taken modulo the period. A
 * parameter on an interior knot takes the piece above it.
 * IC_ERR_INVALID on a malformed curve or nderiv out of range.
 */
IC_API IC_NODISCARD ic_status ic_bspline_eval(const ic_bspline *c, double t, int nderiv,
                                              double *out, ic_error *err);

#ifdef __cplusplus
}
#endif
#endif
