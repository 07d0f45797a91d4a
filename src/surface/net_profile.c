/* The meridian profile of a revolved net (net_shape.h; docs/nurbs.md,
 * "Recognised nets"), (X, Z) in its half plane X >= 0, classified:
 *  - a segment (every control point on one line, so the curve is on it):
 *    parallel to the axis a cylinder, normal to it a plane (a disc or an
 *    annulus), else a cone (the line meets the axis at its apex). Its
 *    coordinate along the line strictly monotone (net_pieces.c), the curve
 *    covers exactly the segment between its ends (continuity, and no
 *    overshoot where the coordinate is monotone);
 *  - an arc of a circle (its identity on every span, net_curve.c), the
 *    angle about the centre strictly monotone: a sphere when the centre is
 *    on the axis and the arc runs from pole to pole (within X >= 0, so it
 *    is the whole half circle), a torus when the arc closes on itself
 *    after one turn about a centre farther from the axis than the radius.
 * Anything else (a partial sphere or torus, a profile that turns back) is
 * not recognised. */
#include "net_shape.h"
#include "common/mathconst.h"
#include "common/vec3.h"

#include <math.h>
#include <string.h>

/* sine: three points of the profile closer than this to a line fix no
 * circle */
#define NET_MIN_TRIANGLE 1e-6
/* radians: a monotone arc's turn within this of pi (of 2 pi) is the half
 * circle between its poles (the closed circle) */
#define NET_TURN_SLACK 0.5

static void control(const ic_net_curve *c, int j, double P[2])
{
    P[0] = c->hom[j][0] / c->hom[j][2], P[1] = c->hom[j][1] / c->hom[j][2];
}

/* The line through the two control points farthest apart (one pass from
 * the first to the farthest, one back): 0 when all are one point. */
static int spanning_line(const ic_net_curve *c, double tol, double c0[2], double d[2])
{
    double A[2], B[2], P[2];
    int far = 0;
    control(c, 0, A);
    for (int pass = 0; pass < 2; pass++) {
        double best = -1;
        for (int j = 0; j < c->n; j++) {
            control(c, j, P);
            const double dist = hypot(P[0] - A[0], P[1] - A[1]);
            if (dist > best)
                best = dist, far = j;
        }
        if (pass == 0)
            control(c, far, A);
    }
    control(c, far, B);
    const double len = hypot(B[0] - A[0], B[1] - A[1]);
    if (!(len > tol))
        return 0;
    c0[0] = A[0], c0[1] = A[1];
    d[0] = (B[0] - A[0]) / len, d[1] = (B[1] - A[1]) / len;
    return 1;
}

/* The spread of a coordinate (0: x, 1: z) over the control points. */
static double spread(const ic_net_curve *c, int k)
{
    double lo = INFINITY, hi = -INFINITY, P[2];
    for (int j = 0; j < c->n; j++) {
        control(c, j, P);
        lo = fmin(lo, P[k]), hi = fmax(hi, P[k]);
    }
    return hi - lo;
}

/* The point of the axis at height z. */
static void on_axis(const ic_net_shape *sh, double z, double out[3])
{
    ic_axpy3(out, sh->origin, z, sh->frame[2]);
}

static void set_axis(ic_net_shape *sh, ic_primitive_kind kind, double z)
{
    ic_primitive *p = &sh->prim;
    memset(p, 0, sizeof *p);
    p->kind = kind;
    on_axis(sh, z, p->center);
    memcpy(kind == IC_PRIM_PLANE ? p->normal : p->axis, sh->frame[2], sizeof p->axis);
    memcpy(p->ref_direction, sh->frame[0], sizeof p->ref_direction);
}

static int segment(ic_net_shape *sh, const double c0[2], const double d[2], double tol)
{
    ic_net_profile *pr = &sh->profile;
    const ic_net_curve *c = &sh->curve[1];
    const int st = ic_net_pieces_make(&sh->pieces[1], c, IC_NET_ALONG, c0, d);
    if (st != 0)
        return st;
    const ic_net_pieces *pc = &sh->pieces[1];
    pr->circle = 0;
    memcpy(pr->c, c0, sizeof pr->c);
    memcpy(pr->d, d, sizeof pr->d);
    pr->lo = fmin(pc->pos[0], pc->pos[pc->n]), pr->hi = fmax(pc->pos[0], pc->pos[pc->n]);
    for (int e = 0; e < 2; e++) /* an end on the axis */
        pr->pole[e] = fabs(c0[0] + pc->pos[e ? pc->n : 0] * d[0]) <= tol;
    if (spread(c, 0) <= tol) { /* parallel to the axis */
        if (!(c0[0] > tol))
            return 1;
        set_axis(sh, IC_PRIM_CYLINDER, 0);
        sh->prim.radius = c0[0];
    } else if (spread(c, 1) <= tol) { /* normal to it */
        set_axis(sh, IC_PRIM_PLANE, c0[1]);
    } else { /* meeting it at the apex */
        set_axis(sh, IC_PRIM_CONE, c0[1] - c0[0] * d[1] / d[0]);
        sh->prim.half_angle = atan(fabs(d[0] / d[1]));
    }
    return 0;
}

/* The circle through the profile's points at 0, 1/3 and 2/3 of its domain. */
static int three_point_circle(const ic_net_curve *c, double centre[2], double *r)
{
    const double t0 = c->knots[c->p], T = c->knots[c->n] - t0;
    double p[3][2];
    for (int k = 0; k < 3; k++)
        ic_net_curve_point(c, t0 + T * k / 3.0, p[k]);
    const double a[2] = {p[0][0] - p[2][0], p[0][1] - p[2][1]};
    const double b[2] = {p[1][0] - p[2][0], p[1][1] - p[2][1]};
    const double cr = a[0] * b[1] - a[1] * b[0], aa = a[0] * a[0] + a[1] * a[1];
    const double bb = b[0] * b[0] + b[1] * b[1];
    if (!(fabs(cr) > NET_MIN_TRIANGLE * sqrt(aa * bb)))
        return 0;
    /* the circumcentre from p2: (|a|^2 b - |b|^2 a) rotated by -90 degrees / (2 cr) */
    const double w[2] = {aa * b[0] - bb * a[0], aa * b[1] - bb * a[1]};
    centre[0] = p[2][0] + w[1] / (2 * cr);
    centre[1] = p[2][1] - w[0] / (2 * cr);
    *r = hypot(p[0][0] - centre[0], p[0][1] - centre[1]);
    return 1;
}

static int arc(ic_net_shape *sh, double tol)
{
    ic_net_profile *pr = &sh->profile;
    const ic_net_curve *c = &sh->curve[1];
    double centre[2], r, first[2], last[2];
    if (!three_point_circle(c, centre, &r) || !(ic_net_curve_circle_gap(c, centre, r) <= tol))
        return 1;
    const int st = ic_net_pieces_make(&sh->pieces[1], c, IC_NET_ANGLE, centre, NULL);
    if (st != 0)
        return st;
    const ic_net_pieces *pc = &sh->pieces[1];
    const double turn = fabs(pc->pos[pc->n] - pc->pos[0]);
    ic_net_curve_point(c, c->knots[c->p], first);
    ic_net_curve_point(c, c->knots[c->n], last);
    pr->circle = 1;
    memcpy(pr->c, centre, sizeof pr->c);
    pr->r = r;
    const int poles = fabs(first[0]) <= tol && fabs(last[0]) <= tol;
    if (fabs(centre[0]) <= tol && poles && fabs(turn - IC_PI) < NET_TURN_SLACK) {
        pr->pole[0] = pr->pole[1] = 1;
        set_axis(sh, IC_PRIM_SPHERE, centre[1]);
        sh->prim.radius = r;
        return 0;
    }
    if (centre[0] - r > tol && hypot(last[0] - first[0], last[1] - first[1]) <= tol &&
        fabs(turn - 2 * IC_PI) < NET_TURN_SLACK) {
        set_axis(sh, IC_PRIM_TORUS, centre[1]);
        sh->prim.major_radius = centre[0], sh->prim.radius = r;
        return 0;
    }
    return 1; /* a partial sphere or torus, or no standard one */
}

int ic_net_classify_profile(ic_net_shape *sh)
{
    const double tol = IC_NET_REL * sh->size;
    const ic_net_curve *c = &sh->curve[1];
    double c0[2], d[2];
    if (!spanning_line(c, tol, c0, d))
        return 1;
    if (ic_net_curve_line_gap(c, c0, d) <= tol)
        return segment(sh, c0, d, tol);
    return arc(sh, tol);
}
