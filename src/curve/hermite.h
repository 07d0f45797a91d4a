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
    double tau;            /* the torsion there (3D nodes; NAN where undefined) */
} ic_hermite_node;

/* Whether the n nodes close smoothly: the last is the first again (same
 * point, the last's derivatives before it equal to the first's after it),
 * so the curve can be one periodic B-spline. */
int ic_hermite_closes(const ic_hermite_node *nodes, int n, int dim);

/* The quintic from node a to node z (a's derivatives after it, z's before
 * it) at s: out[k][j] is the k-th derivative of coordinate j, k = 0..3. */
void ic_hermite_eval(const ic_hermite_node *a, const ic_hermite_node *z, int dim, double s,
                     double out[4][3]);

/* Which nodes a coarser fit keeps (Hermite pieces over longer stretches):
 * from each kept node, the stretch grows over the next nodes while its
 * quintic passes within pos_tol of each node it skips (at the node's s),
 * with the node's first derivative within deriv_tol, its second within
 * deriv_tol * max(|x''|, 1 / length) and (in space, where the node has
 * one) its torsion within tau_tol * max(|x''|, 1 / length). Pinned nodes, the first and the last
 * are always kept, and a stretch spans at most IC_HERMITE_MAX_MERGE nodes
 * (the cost of the test grows with the square of the span). keep[]
 * receives the kept nodes' indices; returns how many. */
enum { IC_HERMITE_MAX_MERGE = 32 };
int ic_hermite_merge(const ic_hermite_node *nodes, const int *pinned, int n, int dim,
                     double pos_tol, double deriv_tol, double tau_tol, int *keep);

/* The piecewise quintic through the nodes (n >= 2) as one B-spline of
 * degree 5 in s: clamped, or periodic when `periodic` (the nodes must
 * close, ic_hermite_closes). c is overwritten; its arrays are malloc'ed. */
ic_status ic_hermite_bspline(ic_bspline *c, const ic_hermite_node *nodes, int n, int dim,
                             int periodic, ic_error *err);

#endif
