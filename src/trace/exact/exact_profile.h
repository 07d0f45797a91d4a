/* Meridian profiles of surfaces of revolution about one axis, and where two
 * of them meet (exact_profile.c; docs/tracing.md, "Exact paths"). In the
 * meridian half-plane a point is (rho, z): rho its distance from the axis,
 * z its coordinate along it. */
#ifndef IC_TRACE_EXACT_PROFILE_H
#define IC_TRACE_EXACT_PROFILE_H

/* The thresholds of the exact paths. Lengths are fractions of the problem's
 * size L, angles radians. A case within the band between a "same" threshold
 * and its "near" one is not decided here: the general path traces it. */

/* relative length, and radians: two axes this close (the offset of a
 * centre from the axis, the angle between directions) are one axis. About
 * a thousand rounding errors of L: placed primitives given the same axis
 * agree to a few. */
#define IC_EXACT_COAXIAL 1e-13
/* relative length: profiles whose gap is within this touch (a tangency);
 * the same margin as IC_EXACT_COAXIAL, the gap being computed from it */
#define IC_EXACT_TANGENT 1e-13
/* relative length: a gap between profiles, or a meeting's distance from
 * the axis, within this (and beyond IC_EXACT_TANGENT) is nearly a tangency,
 * nearly on the axis: the general path decides. A gap g opens two crossings
 * at about sqrt(2 g / r) radians, 1.4e-3 at g = 1e-6 L, r = L. */
#define IC_EXACT_NEAR 1e-6
/* radians: a crossing at a smaller angle between the normals falls back
 * (the general path calls points below the tangential angle, 1e-5 by
 * default, tangential; this leaves a hundredfold margin) */
#define IC_EXACT_MIN_ANGLE 1e-3

/* One piece of a profile: the circle of centre c and radius r, or the line
 * through c along the unit vector d. */
typedef struct {
    int circle;
    double c[2], d[2], r;
} ic_profile_piece;

/* A surface's profile: one piece, or two (a cone's nappes). flat_on_axis: the
 * surface is smooth where it meets the axis and normal to it there (a plane,
 * a sphere); elsewhere (a cone's apex) a meeting on the axis is singular. */
typedef struct {
    int n;
    ic_profile_piece piece[2];
    int flat_on_axis;
} ic_profile;

/* Where two profiles meet: the point, 1 where they touch there, and the
 * angle between them (0 where they touch). */
typedef struct {
    double rho, z;
    int tangent;
    double angle;
} ic_profile_meeting;

#define IC_PROFILE_MAX_MEETINGS 8

/* Every meeting of a and b in the whole meridian plane (rho of either sign:
 * the mirror images are the caller's to drop), L the problem's size. 0, or
 * -1 where the general path must decide: pieces that coincide or nearly do,
 * a gap within the near band. */
int ic_profile_meet(const ic_profile *a, const ic_profile *b, double L,
                    ic_profile_meeting out[IC_PROFILE_MAX_MEETINGS], int *n);

#endif
