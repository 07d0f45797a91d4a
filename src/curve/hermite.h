/* Piecewise quintic Hermite curves as B-splines (docs/bspline.md): the
 * assembly used by the curve fit (fit.c) for a curve in space and for its
 * curves in the parameter planes. */
#ifndef IC_CURVE_HERMITE_H
#define IC_CURVE_HERMITE_H

#include "intercurve/bspline.h"

/* the data of one curve point: position and its first two derivatives with
 * respect to arc length, in dim coordinates */
typedef struct {
    double s;
    double x[3];
    double d1[3], d2[3];   /* of the stretch after the node (larger s) */
    double d1b[3], d2b[3]; /* of the stretch before it: different on a knot line */
} ic_hermite_node;

/* Whether the n nodes close smoothly: the last is the first again (same
 * point, the last's derivatives before it equal to the first's after it),
 * so the curve can be one periodic B-spline. */
int ic_hermite_closes(const ic_hermite_node *nodes, int n, int dim);

/* The piecewise quintic through the nodes (n >= 2) as one B-spline of
 * degree 5 in s: clamped, or periodic when `periodic` (the nodes must
 * close, ic_hermite_closes). c is overwritten; its arrays are malloc'ed. */
ic_status ic_hermite_bspline(ic_bspline *c, const ic_hermite_node *nodes, int n, int dim,
                             int periodic, ic_error *err);

#endif
