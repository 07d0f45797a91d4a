/* An ellipse of an exact path written out as a traced curve, with its exact
 * apparatus (exact_ellipse.c; docs/tracing.md, "Exact paths"). */
#ifndef IC_TRACE_EXACT_ELLIPSE_H
#define IC_TRACE_EXACT_ELLIPSE_H

#include "trace/core/result.h"

#include <math.h>

/* p(theta) = c + a cos(theta) u + b sin(theta) v, u and v orthonormal, a
 * and b positive in either order, traced from theta = 0 towards v. Each
 * surface's gradient along it is affine in the cosine and sine (both
 * surfaces are planes or quadrics): grad[s][0] + cos(theta) grad[s][1] +
 * sin(theta) grad[s][2]. branch_ends: the points at theta = 0 and pi are
 * branch points, where the normals are parallel (their angle written 0).
 * symmetric: the angle between the normals is the same at theta, -theta
 * and pi - theta (the pair is symmetric under reflections mapping the
 * ellipse to itself so): it is computed on the first quadrant only. */
typedef struct {
    double c[3], u[3], v[3];
    double a, b;
    double grad[2][3][3];
    int branch_ends, symmetric;
} ic_exact_ellipse;

/* How an ellipse is written (exact_ellipse_plan.c): n arcs (a multiple of
 * 8) of equal angle phi, tan(theta) = r tan(phi); the arc length of each
 * by Gauss-Legendre on `split` equal parts. */
typedef struct {
    int n, split;
    double r;
} ic_ellipse_plan;

/* The cosine and sine of theta from those of phi. */
static inline void ic_ellipse_theta(const ic_ellipse_plan *plan, double cphi, double sphi,
                                    double *ctheta, double *stheta)
{
    const double rs = plan->r * sphi, inv = 1 / sqrt(cphi * cphi + rs * rs);
    *ctheta = cphi * inv, *stheta = rs * inv;
}

/* The half-extent of the ellipse along each coordinate axis:
 * sqrt((a u_k)^2 + (b v_k)^2). */
void ic_exact_ellipse_extent(const ic_exact_ellipse *e, double extent[3]);

/* Its plan under the options (absolute lengths): 0, or -1 when it needs
 * more than max_points points (the general path reports the budget) or
 * its arc length cannot be bounded to rounding. */
int ic_exact_ellipse_plan(const ic_trace_options *opt, const ic_exact_ellipse *e,
                          ic_ellipse_plan *plan);

/* The arc length S[j] from phi = 0 to phi_j = 2 pi j / n, j = 0..n/4, from
 * the cosines and sines phi[j] of those angles; summed with Kahan's
 * compensation. */
void ic_exact_quarter_lengths(const ic_exact_ellipse *e, const ic_ellipse_plan *plan,
                              const double (*phi)[2], double *S);

/* The arc length from phi0 to phi1 (phi1 - phi0 at most one arc, 2 pi /
 * n): the plan's quadrature on `split` parts of that stretch, whose error
 * bound (exact_ellipse_plan.c) only falls on a shorter stretch. */
double ic_exact_ellipse_arc(const ic_exact_ellipse *e, const ic_ellipse_plan *plan, double phi0,
                            double phi1);

/* The point at the angle theta of cosine cs and sine sn with its exact
 * apparatus (b = binormal, u x v), the angle between the normals when
 * `angle` is set; not s. The point must be zeroed first. */
void ic_exact_ellipse_point(ic_trace_point *p, const ic_exact_ellipse *e, const double *binormal,
                            double cs, double sn, int angle);

/* The plan's n + 1 points (the last the first again) with their apparatus
 * and arc length, in *pts (calloc'ed): 0, or -1 out of memory. */
int ic_exact_ellipse_points(const ic_exact_ellipse *e, const ic_ellipse_plan *plan,
                            ic_trace_point **pts);

/* Adds the np points (taken: the result frees them from now on, even on an
 * error) to r as a closed transversal curve, its shape that of the shape
 * test. */
ic_status ic_exact_add_ellipse_points(ic_trace_result *r, const ic_exact_ellipse *e,
                                      ic_trace_point *pts, int np, const ic_trace_options *opt,
                                      ic_error *err);

/* Adds it to r as a closed transversal curve, its shape that of the shape
 * test. IC_ERR_NOMEM out of memory. */
ic_status ic_exact_add_ellipse(ic_trace_result *r, const ic_exact_ellipse *e,
                               const ic_ellipse_plan *plan, const ic_trace_options *opt,
                               ic_error *err);

#endif
