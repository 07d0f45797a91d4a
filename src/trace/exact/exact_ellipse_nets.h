/* An ellipse of the conic paths on NURBS patches recognised as its
 * surfaces (exact_ellipse_cover.c, exact_ellipse_knots.c,
 * exact_ellipse_nets.c; docs/tracing.md, "Exact paths"): what each patch
 * covers of it, proven from its closed form; the knot lines it crosses,
 * solved in closed form; its points with their parameters. */
#ifndef IC_TRACE_EXACT_ELLIPSE_NETS_H
#define IC_TRACE_EXACT_ELLIPSE_NETS_H

#include "exact_circle.h"
#include "exact_ellipse.h"
#include "exact_source.h"

/* Whether the conic paths take the source: an implicit primitive, a
 * planar net, or a revolved net of a cylinder or a cone (a segment
 * profile) whose turning direction wraps (periodic: an ellipse on it
 * winds once about its axis, crossing the seam). */
int ic_exact_conic_source_ok(const ic_exact_source *src);

/* Where the ellipse lies against what the source's patch covers: 1 inside
 * by more than the margin (a length), 0 outside by more, -1 otherwise (the
 * general path decides); 1 for an implicit primitive. Exact: along a
 * direction k the ellipse's offsets are c.k + a cos u.k + b sin v.k, their
 * range c.k +- sqrt((a u.k)^2 + (b v.k)^2). */
int ic_exact_ellipse_covered(const ic_exact_source *src, const ic_exact_ellipse *e, double margin);

/* Where the ellipse crosses the knot lines (and wrapping seams) of the
 * sources' patches, each as an ic_exact_knot whose phi is the angle theta
 * of the ellipse there in [0, 2 pi), in *marks (malloc'ed, *n of them, any
 * order; NULL when none): 0, 1 where a line nearly touches the ellipse or
 * the crossings are not as the closed form says, -1 out of memory
 * (exact_ellipse_knots.c). */
int ic_exact_ellipse_knots(const ic_exact_ellipse *e, const ic_exact_source src[2], double L,
                           ic_exact_knot **marks, int *n);

/* The ellipse's points on the recognised patches: the plan's, the
 * crossings of knot lines put in (a crossing within EXACT_SAME_ANGLE of a
 * plan point is that point: the branch points stay the plan's), every
 * point's parameters by ic_exact_curve_params, exactly on the lines it
 * crosses, and the points turned to run as the general path's do. *pts
 * malloc'ed, *np points: 0, 1 where the general path must trace, -1 out
 * of memory. */
int ic_exact_ellipse_net_points(ic_pair *pair, const ic_exact_source src[2],
                                const ic_exact_ellipse *e, const ic_ellipse_plan *plan, double L,
                                ic_trace_point **pts, int *np);

#endif
