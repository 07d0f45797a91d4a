/* Exact paths for quadric pairs that meet in conics (docs/tracing.md,
 * "Exact paths"): a plane and a quadric primitive (exact_quadric.c), two
 * cylinders of equal radius whose axes meet (exact_cylinders.c), both
 * written out by exact_conic.c. The shared thresholds are in
 * exact_profile.h (IC_EXACT_COAXIAL, IC_EXACT_NEAR, IC_EXACT_MIN_ANGLE). */
#ifndef IC_TRACE_EXACT_CONIC_H
#define IC_TRACE_EXACT_CONIC_H

#include "exact_ellipse.h"
#include "intercurve/surface.h"

/* ratio: an ellipse longer than this times its width falls back. It is then
 * nearly a parabola or a pair of lines: a cone's section loses about
 * log10(ratio^2) digits to cancellation in the conic's determinant, and the
 * box cuts it at any ordinary size. */
#define IC_EXACT_MAX_ASPECT 1e3
/* relative length: a cone's apex this near the plane falls back. The
 * general path drops the points within IC_TRACE_SINGULAR_CLEARANCE = 1.5e-4
 * L of a singular point of a surface; an ellipse 1e-3 L off the apex keeps
 * six times that from it. */
#define IC_EXACT_APEX_CLEARANCE 1e-3
/* relative: two cylinders' radii this close are equal (the same margin as
 * IC_EXACT_COAXIAL: radii given equal agree to rounding; radii 1e-9 apart
 * make two curves that nearly touch, no branch point, for the general path) */
#define IC_EXACT_SAME_RADIUS 1e-13

/* A quadric primitive (sphere, cylinder, cone, ellipsoid) as
 * f(p) = (p - c)^T M (p - c) - k0 with M = sum_i d_i e_i e_i^T, (e1, e2, e3)
 * its frame (ic_primitive_frame): the implicit form of surface.h, so grad f
 * = 2 M (p - c) is the surface's gradient. */
typedef struct {
    const ic_primitive *p;
    double c[3], e[3][3], d[3], k0;
} ic_quadric;

/* What a conic path found: up to two ellipses and two branch points. */
typedef struct {
    int nellipses, nbranch;
    ic_exact_ellipse ellipse[2];
    double branch[2][3];
} ic_conic_found;

/* The quadric of a primitive: 0, or -1 when it is none (a plane, a torus)
 * or its frame is invalid. */
int ic_quadric_of(const ic_primitive *p, ic_quadric *q);

/* grad f along the ellipse p(theta) = c + a cos u + b sin v:
 * g[0] + cos(theta) g[1] + sin(theta) g[2] (grad f is affine in p). */
void ic_quadric_gradient_along(const ic_quadric *q, const ic_exact_ellipse *e, double g[3][3]);

/* The plane's section of the quadric (L the problem's size): 1 with the
 * ellipse in *out (its grad[0] the plane's, grad[1] the quadric's), 0 when
 * they do not meet, -1 when the general path must decide. */
int ic_exact_plane_section(const ic_primitive *plane, const ic_quadric *q, double L,
                           ic_exact_ellipse *out);

/* Two cylinders of equal radius whose axes meet: 0 with the two ellipses
 * and the two branch points in *out, -1 when the general path must decide. */
int ic_exact_equal_cylinders(const ic_quadric *A, const ic_quadric *B, double L,
                             ic_conic_found *out);

/* Whether an ellipse is one the conic paths write: neither nearly a point
 * (its smaller semi-axis above IC_EXACT_NEAR L) nor nearly a parabola
 * (IC_EXACT_MAX_ASPECT). */
int ic_exact_ellipse_fair(const ic_exact_ellipse *e, double L);

#endif
