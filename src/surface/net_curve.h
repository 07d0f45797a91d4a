/* Plane rational B-spline curves taken from a NURBS net (a row of a
 * revolved net, its meridian profile, an edge of a planar net) and what the
 * recognition of nets proves about them (net_curve.c, net_pieces.c;
 * docs/nurbs.md, "Recognised nets"). */
#ifndef IC_SURFACE_NET_CURVE_H
#define IC_SURFACE_NET_CURVE_H

/* n control points of degree p over the knots (n + p + 1 values, not
 * owned), homogeneous: hom[i] = (w x, w y, w), w > 0. The curve's domain
 * is [knots[p], knots[n]]. */
typedef struct {
    int p, n;
    const double *knots;
    double (*hom)[3]; /* owned */
} ic_net_curve;

/* hom allocated for n points: 0, or -1 out of memory. */
int ic_net_curve_alloc(ic_net_curve *c, int p, int n, const double *knots);
void ic_net_curve_free(ic_net_curve *c);

/* The point at t (the end pieces extended outside the domain). */
void ic_net_curve_point(const ic_net_curve *c, double t, double out[2]);

/* The largest distance of a control point from the line through c0 along
 * the unit d: the curve lies within it of the line (a rational curve with
 * positive weights is a convex combination of its control points). */
double ic_net_curve_line_gap(const ic_net_curve *c, const double c0[2], const double d[2]);

/* A bound on | |C(t) - centre| - r | over the domain: on each span the
 * Bernstein coefficients of |X - centre W|^2 - r^2 W^2 (X the homogeneous
 * point, W the weight; degree 2p), which bound that polynomial, divided by
 * min W^2 r. INFINITY where a weight's coefficient is not provably
 * positive. */
double ic_net_curve_circle_gap(const ic_net_curve *c, const double centre[2], double r);

/* How a position is read along a curve: the angle of C - centre about the
 * centre, counted on from the curve's start; or the coordinate
 * (C - point) . d along a line. */
typedef enum { IC_NET_ANGLE, IC_NET_ALONG } ic_net_reading;

/* The curve's domain cut into pieces on each of which its position is
 * strictly monotone (the same way on all) and, reading angles, the curve
 * turns by less than pi about the centre: piece k is [t[k], t[k+1]] on
 * span[k], its ends at positions pos[k], pos[k+1]. */
typedef struct {
    ic_net_reading reading;
    double c[2], d[2]; /* the centre, or the line's point and unit direction */
    int n, p;
    double *t, *pos; /* n + 1 each; owned */
    int *span;       /* n; owned */
    double *net;     /* n Bezier nets of the homogeneous curve, (p + 1) x 3 each; owned */
    int sign;        /* +1: the position increases with t; -1: it decreases */
} ic_net_pieces;

/* The pieces of c read as said: 0, 1 where monotony cannot be proven (the
 * curve turns back, or stands still, within the subdivisions allowed), or
 * -1 out of memory. c0 is the centre or the line's point, d (ALONG only)
 * the line's unit direction. */
int ic_net_pieces_make(ic_net_pieces *pc, const ic_net_curve *c, ic_net_reading reading,
                       const double c0[2], const double d[2]);
void ic_net_pieces_free(ic_net_pieces *pc);

/* The parameter where the position is pos (pos between pos[0] and pos[n]):
 * the piece that holds it, then Newton's method on its Bezier net kept
 * inside the piece's bracket by bisection. 0, or -1 when pos lies outside
 * the range. */
int ic_net_pieces_invert(const ic_net_pieces *pc, const ic_net_curve *c, double pos, double *t);

#endif
