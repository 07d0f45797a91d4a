/* What the exact paths share (docs/tracing.md, "Exact paths"): the box
 * test with its margin, the marching's step rule on a circle, the scale of
 * what was found and the report of a closed form (exact_common.c). Their
 * thresholds: exact_profile.h. */
#ifndef IC_TRACE_EXACT_COMMON_H
#define IC_TRACE_EXACT_COMMON_H

#include "intercurve/trace.h"

/* relative length: a curve or point this near a face of the box (inside or
 * out) falls back: the general path decides what the box cuts */
#define IC_EXACT_BOX_MARGIN 1e-6
/* count: the fewest arcs a closed curve is traced in (the shape test and
 * the B-spline fit want a few points whatever the step rules allow) */
#define IC_EXACT_MIN_ARCS 8

/* Where a closed curve lies against the box widened and narrowed by the
 * margin, from its centre and its half-extent along each coordinate axis
 * (0 for a point): 1 inside, 0 outside, -1 across a face or near one. */
int ic_exact_box_side(const ic_trace_options *opt, const double centre[3], const double extent[3],
                      double L);

/* The step of the general tracer's rules (options absolute) on a circle of
 * radius rho: the truncation terms of orders K-1 and K with |c^(k)| =
 * rho^(1-k), the chord height h^2 / (8 rho), the longest step. */
double ic_exact_circle_step(const ic_trace_options *opt, double rho);

/* The box lo..hi grown to hold the centre plus and minus the extent. */
void ic_exact_extent_add(double lo[3], double hi[3], const double centre[3],
                         const double extent[3]);

/* The size of what was found, as the search takes it for the marching's
 * lengths and the fit (ic_trace_found_scale): the diagonal of the box lo..hi
 * (started at +inf..-inf) when between 1e-3 L and L; else L. */
double ic_exact_found_scale(double L, const double lo[3], const double hi[3]);

/* The report of a closed form: nothing searched, nothing left open. */
void ic_exact_report(ic_trace_report *rep, const char *method);

#endif
