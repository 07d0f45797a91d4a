/* The surfaces of a pair as the exact paths take them (exact_source.c,
 * exact_cover.c; docs/tracing.md, "Exact paths"): an implicit primitive,
 * or a NURBS patch recognised as a standard surface (net_shape.h), with
 * the part of that surface the patch covers. An exact path takes the two
 * primitives from ic_exact_sources, finds its curves on them, keeps those
 * ic_exact_covers says the patches hold, and gives their points the
 * patches' parameters (exact_circle.c for circles). */
#ifndef IC_TRACE_EXACT_SOURCE_H
#define IC_TRACE_EXACT_SOURCE_H

#include "intercurve/trace.h"
#include "surface/net_shape.h"

/* relative length: the same margin as the box's (IC_EXACT_BOX_MARGIN): a
 * circle or point this near the edge of what a patch covers (inside or
 * out) is left to the general path, which decides what the edge cuts */
#define IC_EXACT_COVER_MARGIN 1e-6
/* relative length: every point an exact path gives a recognised patch
 * parameters at must lie this near the patch there, |S(u, v) - x| <=
 * IC_EXACT_ON_NET L, or the general path traces the pair (a thousand
 * roundings of L; an exact net is met to a few) */
#define IC_EXACT_ON_NET 1e-12

/* One surface of the pair: the implicit primitive and its frame (rows e1,
 * e2, e3; e3 the axis or the plane's normal); net NULL for an implicit
 * primitive (everything covered, no parameters), else the patch's shape. */
typedef struct {
    ic_primitive prim;
    double frame[3][3];
    const ic_net_shape *net;
    ic_surface *surface;
} ic_exact_source;

/* Both surfaces of the pair as sources: 1, 0 when either is neither an
 * implicit primitive nor a NURBS patch recognised whole (or the pair is a
 * self-intersection), -1 out of memory (recognising a patch). */
int ic_exact_sources(ic_pair *pair, ic_exact_source src[2]);

/* Where the circle of radius rho about the line through centre along the
 * unit e (a point when rho = 0), on the source's surface, lies against
 * what the patch covers of it: 1 inside by more than the margin (a length),
 * 0 outside by more, -1 within it of the edge (the general path decides).
 * Always 1 for an implicit primitive. */
int ic_exact_covers(const ic_exact_source *src, const double centre[3], const double e[3],
                    double rho, double margin);

/* The same for a point x of the source's surface (any curve's point): 1
 * inside what the patch covers by more than the margin, 0 outside by
 * more, -1 near its edge; 1 for an implicit primitive. */
int ic_exact_covers_point(const ic_exact_source *src, const double x[3], double margin);

/* The parameters of any curve's points on the recognised patches of the
 * pair (a circle's are best made by ic_exact_circle_points, which adds the
 * knot lines' points): each point's by inverting its patch's structure, a
 * wrapping parameter continued from the point before by whole periods,
 * every point checked on its patch (IC_EXACT_ON_NET L). 0, or 1 where the
 * general path must trace (a point with no parameters, on an axis; a point
 * off its patch). Knot-line points are the caller's to add (exact_circle.c
 * shows how). */
int ic_exact_curve_params(const ic_exact_source src[2], ic_trace_point *pts, int n, double L);

/* Whether a recognised revolved net's axis is the line through o along e
 * (within IC_EXACT_COAXIAL, lengths relative to L): its circles about that
 * line are then its parameter lines. */
int ic_exact_net_coaxial(const ic_exact_source *src, const double o[3], const double e[3],
                         double L);

#endif
