/* NURBS patches recognised as the standard surfaces they are (docs/nurbs.md,
 * "Recognised nets"): a complete surface of revolution written as a
 * revolved net (net_revolved.c, net_profile.c), or a parallelogram of a
 * plane written as an affine net (net_planar.c); the parameters of their
 * points by inverting that structure (net_shape.c). */
#ifndef IC_SURFACE_NET_SHAPE_H
#define IC_SURFACE_NET_SHAPE_H

#include "intercurve/surface.h"
#include "net_curve.h"
#include "nurbs.h"

/* relative to the patch's size D (the diagonal of its control points'
 * box): control points within IC_NET_REL D of the structure, weights
 * within IC_NET_REL of it relatively, and row and profile curves within
 * IC_NET_REL D of their circle or line (the Bernstein bound) are taken as
 * exact. Then every point of the patch lies within 4 IC_NET_REL D of the
 * recognised surface (docs/nurbs.md gives the bound): about 1e4 roundings
 * of D, and a net perturbed by 1e-9 D is refused. */
#define IC_NET_REL 1e-12

typedef enum { IC_NET_NONE, IC_NET_REVOLVED, IC_NET_PLANAR } ic_net_kind;

/* A revolved net's meridian profile, in its half plane: x the distance from
 * the axis, z the height along e3 from the origin. */
typedef struct {
    int circle;        /* 1: an arc of the circle (c, r); 0: a segment of the line */
    double c[2], d[2]; /* the circle's centre, or a point of the line and its unit direction */
    double r;
    double lo, hi; /* a segment: the line coordinates (x - c) . d it covers, lo < hi */
    int pole[2];   /* the profile's start (end) is on the axis: the patch degenerates there */
} ic_net_profile;

typedef struct ic_net_shape {
    ic_net_kind kind;
    /* the implicit primitive the patch lies on and its frame (rows e1, e2,
     * e3): e3 the axis (a plane's normal); e1 a revolved net's seam
     * direction (where its circles start), a planar net's first edge */
    ic_primitive prim;
    double frame[3][3];
    double size; /* D */
    /* revolved: the point of the axis at height 0, the parameter that turns
     * about the axis (0: u, 1: v), the profile; curve[0] the unit circle in
     * (e1, e2) the rows turn along (its angle increasing from 0 at the seam
     * to 2 pi), curve[1] the profile (x, z). Planar: curve[0] and curve[1]
     * the coordinates f(u), g(v) along edge directions E1 = e1 and E2 (as
     * (f, 0) with weight 1, read along x). */
    double origin[3];
    int around;
    ic_net_profile profile;
    ic_net_curve curve[2];
    ic_net_pieces pieces[2];
    /* planar: the unit edge directions, and the parallelogram covered:
     * corner + s edge[0] + t edge[1], s, t in [0, 1] */
    double E[2][3];
    double corner[3], edge[2][3];
} ic_net_shape;

/* The shape of a patch: 0 with *out (NULL when not recognised), or -1 out
 * of memory. */
int ic_net_recognize(const ic_nurbs_patch *patch, ic_net_shape **out);
void ic_net_shape_free(ic_net_shape *sh);

/* The recognition steps (net_revolved.c, net_planar.c) on a zeroed shape:
 * 0 recognised, 1 not, -1 out of memory (the shape's arrays are freed by
 * ic_net_shape_free either way). */
int ic_net_recognize_revolved(const ic_nurbs_patch *patch, int around, ic_net_shape *sh);
int ic_net_recognize_planar(const ic_nurbs_patch *patch, ic_net_shape *sh);
/* The profile's kind, coverage and primitive (net_profile.c): 0 or 1 (not
 * a complete standard profile), -1 out of memory. */
int ic_net_classify_profile(ic_net_shape *sh);

/* Parameters of points (net_shape.c). The angle of a point about a
 * revolved net's axis, from e1 towards e2 in [0, 2 pi); and the parameter
 * along the turning direction at a cumulative angle in [0, 2 pi] (0 and
 * 2 pi: the two ends of the domain). */
double ic_net_angle_of(const ic_net_shape *sh, const double xyz[3]);
int ic_net_around_param(const ic_net_shape *sh, double angle, double *t);
/* The profile's parameter at the point (x, z) of its half plane (within
 * IC_NET_REL D of the profile's covered part): 0, or -1. */
int ic_net_profile_param(const ic_net_shape *sh, double x, double z, double *t);
/* (u, v) of a point of the recognised surface (a revolved net's angle taken
 * in [0, 2 pi)): 0, or -1 where it has none (on the axis) or lies beyond
 * the patch. */
int ic_net_params(const ic_net_shape *sh, const double xyz[3], double uv[2]);

#endif
