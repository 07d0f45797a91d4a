/* A circle of an exact path as traced points (exact_circle.c,
 * exact_knots.c; docs/tracing.md, "Exact paths"): equal arcs with the
 * circle's exact apparatus, a point on every knot line of a recognised
 * patch it crosses, and every point's parameters on the patches. */
#ifndef IC_TRACE_EXACT_CIRCLE_H
#define IC_TRACE_EXACT_CIRCLE_H

#include "exact_source.h"

/* The circle of radius rho about the line through centre along the unit e,
 * u a unit vector normal to e (v = e x u): its points at angle phi are
 * centre + rho (cos phi u + sin phi v), counterclockwise about e. angle:
 * between the surfaces' normals; tangent: the surfaces touch along it. */
typedef struct {
    double centre[3], u[3], v[3], e[3];
    double rho, angle;
    int tangent;
} ic_exact_circle;

/* A point of the circle on a knot line (or a periodic seam) of sheet s's
 * patch: at angle phi, on the line param[dir] = value (a seam: value is
 * the domain's start, the point takes the end its neighbours lead to). */
typedef struct {
    double phi;
    int sheet, dir, seam;
    double value;
} ic_exact_knot;

/* A growing list of knot points (exact_knots.c), zeroed to start. */
typedef struct {
    ic_exact_knot *m;
    int n, cap;
} ic_exact_marks;

/* Appends the point at angle phi taken modulo 2 pi into [0, 2 pi): 0, or -1
 * out of memory (the list kept). */
int ic_exact_mark_add(ic_exact_marks *k, double phi, int sheet, int dir, int seam, double value);

/* On crossing k: the parameter *t of its patch (src) set exactly on its
 * line, by whole periods where the direction is periodic (a seam: the end
 * of the domain the computed value is nearest, one period on). */
void ic_exact_knot_snap(const ic_exact_source *src, const ic_exact_knot *k, double *t);

/* The circle's crossings of the knot lines of both sources' patches, in
 * *marks (malloc'ed, *n of them, any order): 0, 1 where they cannot be
 * told (a knot line nearly touching the circle, or a revolved patch the
 * circle is not a parameter line of), -1 out of memory (exact_knots.c).
 * theta0[s]: the angle of the circle's start about sheet s's revolved
 * patch; way[s] = +1 (-1) when its angle grows (falls) along the circle;
 * L the problem's size. */
int ic_exact_circle_knots(const ic_exact_circle *c, const ic_exact_source src[2],
                          const double theta0[2], const int way[2], ic_exact_knot **marks, int *n,
                          double L);

/* The circle's points: n equal arcs (a multiple of 8), the crossings of
 * knot lines put in, the first point again at the end (at s = 2 pi rho).
 * Parameters on each recognised patch by inverting its structure, each
 * point checked against the patch (IC_EXACT_ON_NET L). The circle starts
 * at the seam of the first patch about its axis, if any (then c->u is
 * moved there). *pts malloc'ed, *npts points: 0, 1 when the general path
 * must trace the pair, -1 out of memory. */
int ic_exact_circle_points(ic_exact_circle *c, int n, const ic_exact_source src[2], double L,
                           ic_trace_point **pts, int *npts);

/* A transversal circle's points turned, when they run against it, to run
 * along N_A x N_B at its start (a net's normal R_u x R_v, an implicit
 * surface's gradient), as the general path's curves run. */
void ic_exact_circle_orient(ic_pair *pair, ic_trace_point *pts, int n);

/* The same for any closed curve's points, read at point `at` (where the
 * normals are not parallel). */
void ic_exact_orient_at(ic_pair *pair, ic_trace_point *pts, int n, int at);

#endif
