/* Exact paths for quadric pairs that meet in conics (docs/tracing.md,
 * "Exact paths"): a plane's ellipse on a cylinder, an ellipsoid or a cone,
 * and the two ellipses of two cylinders of equal radius whose axes meet.
 * Each case's ellipses are derived here by another route than the code's
 * (no eigenproblem): the cylinder's and the two cylinders' in closed form,
 * the ellipsoid's as the image of a circle of the unit sphere, the cone's
 * from its centre M^-1 n and conjugate semi-diameters. Every point is
 * checked against them (place, t, n, b, kappa, tau 0, the angle from the
 * surfaces' own normals, the arc length of each step by Simpson's rule),
 * the length against 4 a E(1 - b^2/a^2) by the arithmetic-geometric mean
 * (itself checked against mpmath, tests/truth/gen_ellipe.py), and the
 * whole against the general path (exact_paths = 0). The cases the exact
 * paths leave to the general path must give exactly what it gives. */
#include <math.h>
#include <string.h>

#include "exact_pair.h"
#include "elliptic_e.h"
#include "harness.h"
#include "intercurve.h"

#define PI 3.14159265358979323846

static const char CLOSED_FORM[] = "closed form: plane sections of quadrics";

/* relative to the problem's size L: the exact points' distance from both
 * surfaces (|f| / |grad f|) and from the ellipses derived here; a few
 * roundings of O(L) coordinates (the brief's 1e-14) */
#define EXACT_PLACE 1e-14
/* relative: kappa, t, n and b of every point against the derived ellipse's:
 * a few roundings of quotients of O(1) quantities (the ellipses here are at
 * most 3 times longer than wide) */
#define EXACT_FRAME 1e-13
/* radians: the angle between the normals against the one of the
 * surfaces' own unit normals at the point (each to a few ulps; measured
 * 8.9e-16) */
#define EXACT_ANGLE 1e-14
/* relative: an arc's length against Simpson's rule on it, between the
 * points' parameters found here (each to a few ulps: 1e-14 of a step of
 * 0.01 rad); the difference of the two s carries besides a few roundings
 * of the whole length (EXACT_S_ROUNDING of it). The whole length against
 * the elliptic integral: a compensated sum of arcs each within a few
 * roundings. */
#define EXACT_ARC 1e-13
#define EXACT_S_ROUNDING (4 * DBL_EPSILON)
#define EXACT_LENGTH (16 * DBL_EPSILON)
/* relative: how far a step may exceed the marching's rules at its start
 * point: the spacing keeps them at every point's own radius of curvature,
 * which changes along the step (measured 9.4e-4) */
#define SPACING_SLACK 1e-2
/* ratio: the most arcs an ellipse may take for the fewest the rules allow
 * (spacing equal in one angle cannot follow them everywhere): up to an
 * aspect of 4, and beyond (exact_ellipse_plan.c: 1.1 at 4, 4.6 at 100;
 * measured 5.8 on the needle of aspect 120; equal spacing in theta takes
 * 2.9 at 4, 48 at 100) */
#define SPACING_EXCESS_LOW 1.25
#define SPACING_EXCESS_HIGH 8
/* relative: the general path's lengths against the exact ones (its
 * truncation error per step is 1e-11 L at most, of either sign along a
 * closed curve: measured 3.5e-13 at worst on these cases; the exact
 * lengths agree with 4 a E(m) to 2 ulps) */
#define GENERAL_LENGTH 1e-11
/* relative to L: the general path's points and branch points from the
 * derived ellipses and points (it locates them to about 1e-12 L) */
#define GENERAL_ON_EXACT 1e-9

/* ---- small vector algebra ---- */

static double dot(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross(double *c, const double *a, const double *b)
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

static double norm(const double *a) { return sqrt(dot(a, a)); }

static void unit(double *a)
{
    const double n = norm(a);
    for (int k = 0; k < 3; k++)
        a[k] /= n;
}

/* a random unit vector, and a unit vector normal to e */
static void random_unit(harness_rng *g, double *e)
{
    do
        for (int k = 0; k < 3; k++)
            e[k] = harness_uniform(g, -1, 1);
    while (norm(e) < 0.2);
    unit(e);
}

static void normal_to(harness_rng *g, const double *e, double *w)
{
    double x[3];
    do
        random_unit(g, x), cross(w, e, x);
    while (norm(w) < 0.2);
    unit(w);
}

/* ---- E(m) (elliptic_e.h) against mpmath ---- */

static void agm_against_mpmath(void)
{
    /* tests/truth/gen_ellipe.py */
    const double m[3] = {0.5, 0.9, 0.999};
    const double E[3] = {1.35064388104767550252, 1.10477473270407332609, 1.00217079083444516587};
    for (int i = 0; i < 3; i++)
        CHECK_CLOSE(ellipe(m[i]), E[i], 4 * DBL_EPSILON, "E(m) by the AGM against mpmath");
}

/* ---- an ellipse C + cos(t) P + sin(t) Q (P, Q conjugate semi-diameters) */

typedef struct {
    double C[3], P[3], Q[3];
} ellipse;

/* Its semi-axes a >= b: the square roots of the eigenvalues of the Gram
 * matrix of P and Q (the product is |P x Q|, the area's). */
static void semi_axes(const ellipse *e, double *a, double *b)
{
    double x[3];
    cross(x, e->P, e->Q);
    const double pp = dot(e->P, e->P), qq = dot(e->Q, e->Q), pq = dot(e->P, e->Q);
    const double hi = 0.5 * (pp + qq + hypot(pp - qq, 2 * pq));
    *a = sqrt(hi), *b = norm(x) / *a;
}

static double ellipse_length(const ellipse *e)
{
    double a, b;
    semi_axes(e, &a, &b);
    return 4 * a * ellipe(1 - (b / a) * (b / a));
}

/* The parameter of x on the ellipse (least squares on P, Q) and the
 * distance from x to the ellipse's point there. */
static double param_of(const ellipse *e, const double *x, double *t)
{
    double z[3], r[3];
    for (int k = 0; k < 3; k++)
        z[k] = x[k] - e->C[k];
    const double pp = dot(e->P, e->P), qq = dot(e->Q, e->Q), pq = dot(e->P, e->Q);
    const double zp = dot(z, e->P), zq = dot(z, e->Q), det = pp * qq - pq * pq;
    const double c = (qq * zp - pq * zq) / det, s = (pp * zq - pq * zp) / det;
    *t = atan2(s, c);
    for (int k = 0; k < 3; k++)
        r[k] = z[k] - cos(*t) * e->P[k] - sin(*t) * e->Q[k];
    return norm(r);
}

static double speed(const ellipse *e, double t)
{
    double d[3];
    for (int k = 0; k < 3; k++)
        d[k] = -sin(t) * e->P[k] + cos(t) * e->Q[k];
    return norm(d);
}

/* The arc length from t0 to t1 (t1 > t0) by Simpson's rule on panels of
 * at most 1e-4 rad: an error about 1e-16 of it here. */
static double simpson_arc(const ellipse *e, double t0, double t1)
{
    const int n = 2 * (int)ceil((t1 - t0) / 2e-4);
    const double h = (t1 - t0) / n;
    double sum = speed(e, t0) + speed(e, t1);
    for (int i = 1; i < n; i++)
        sum += (i % 2 ? 4 : 2) * speed(e, t0 + i * h);
    return sum * h / 3;
}

/* ---- a case: two implicit primitives in the box [-half, half]^3 and the
 * ellipses and branch points derived for them ---- */

typedef struct {
    char name[80];
    ic_primitive prim[2];
    double half;
    int nellipses, nbranch;
    ellipse ell[2];
    double branch[2][3];
} conic_case;

static ic_primitive primitive(ic_primitive_kind kind, const double *centre, const double *axis)
{
    ic_primitive p;
    memset(&p, 0, sizeof p);
    p.kind = kind;
    memcpy(p.center, centre, sizeof p.center);
    memcpy(kind == IC_PRIM_PLANE ? p.normal : p.axis, axis, sizeof p.axis);
    return p;
}

/* Plane through c0 + h a at angle beta to the cylinder's axis a: the
 * ellipse about the axis' point, r along m = a x w (w the tilt), r / cos
 * beta along n x m. */
static void plane_cylinder(harness_rng *g, conic_case *c)
{
    double a[3], w[3], n[3], m[3], d[3], c0[3], C[3];
    random_unit(g, a), normal_to(g, a, w);
    const double beta = harness_uniform(g, 0.2, 1.2), r = harness_uniform(g, 0.4, 1.0);
    const double h = harness_uniform(g, -0.5, 0.5);
    for (int k = 0; k < 3; k++) {
        c0[k] = harness_uniform(g, -0.3, 0.3);
        n[k] = cos(beta) * a[k] + sin(beta) * w[k];
        C[k] = c0[k] + h * a[k];
    }
    cross(m, a, w), cross(d, n, m);
    c->prim[0] = primitive(IC_PRIM_CYLINDER, c0, a), c->prim[0].radius = r;
    c->prim[1] = primitive(IC_PRIM_PLANE, C, n);
    c->nellipses = 1;
    for (int k = 0; k < 3; k++) {
        c->ell[0].C[k] = C[k];
        c->ell[0].P[k] = r * m[k];
        c->ell[0].Q[k] = r / cos(beta) * d[k];
    }
}

/* The ellipsoid c0 + R^T S z, |z| = 1 (R the rows e1, e2, e3 of its frame,
 * S its semi-axes): the plane n.x = h meets the unit sphere in the circle
 * about z0 = h' N / |N|^2 of radius sqrt(1 - h'^2 / |N|^2), N = S R n, h' =
 * h - n.c0; its image is the ellipse, conjugate semi-diameters the images
 * of two orthogonal radii. */
static void ellipsoid_section(conic_case *c, const double *c0, const double (*e)[3],
                              const double *S, const double *n, double frac, const double *x)
{
    double N[3], f0[3], f1[3];
    for (int i = 0; i < 3; i++)
        N[i] = S[i] * dot(e[i], n);
    const double lenN = norm(N), hp = frac * lenN, rho = sqrt(1 - frac * frac);
    cross(f0, N, x), unit(f0), cross(f1, N, f0), unit(f1);
    ellipse *el = &c->ell[0];
    for (int k = 0; k < 3; k++) {
        el->C[k] = c0[k], el->P[k] = el->Q[k] = 0;
        for (int i = 0; i < 3; i++) {
            el->C[k] += e[i][k] * S[i] * hp * N[i] / (lenN * lenN);
            el->P[k] += e[i][k] * S[i] * rho * f0[i];
            el->Q[k] += e[i][k] * S[i] * rho * f1[i];
        }
    }
    c->prim[0] = primitive(IC_PRIM_ELLIPSOID, c0, e[2]);
    memcpy(c->prim[0].ref_direction, e[0], sizeof e[0]);
    memcpy(c->prim[0].axes, S, sizeof c->prim[0].axes);
    c->prim[1] = primitive(IC_PRIM_PLANE, el->C, n);
    c->nellipses = 1;
}

static void plane_ellipsoid(harness_rng *g, conic_case *c)
{
    double e[3][3], n[3], x[3], c0[3], S[3];
    random_unit(g, e[2]), normal_to(g, e[2], e[0]), cross(e[1], e[2], e[0]);
    random_unit(g, n), random_unit(g, x);
    for (int k = 0; k < 3; k++)
        c0[k] = harness_uniform(g, -0.3, 0.3), S[k] = harness_uniform(g, 0.5, 1.5);
    ellipsoid_section(c, c0, (const double(*)[3])e, S, n, harness_uniform(g, -0.7, 0.7), x);
}

/* y^T M y for M = I - (1 + t^2) a a^T, the cone's form about its apex. */
static double cone_form(const double *a, double t, const double *x, const double *y)
{
    return dot(x, y) - (1 + t * t) * dot(x, a) * dot(y, a);
}

/* The cone about a with apex c0 and the plane n.(x - c0) = d, n at beta
 * < pi/2 - alpha from the axis: the centre c0 + mu M^-1 n, mu = d / (n^T
 * M^-1 n) (where grad f is along n), M^-1 = I - (1 + t^2) / t^2 a a^T; the
 * plane's directions z have z^T M z = -mu d on the ellipse, P along any and
 * Q along the M-conjugate one. */
static void plane_cone(harness_rng *g, int below, conic_case *c)
{
    double a[3], w[3], n[3], c0[3], y[3], e0[3], e1[3], q[3];
    random_unit(g, a), normal_to(g, a, w);
    const double alpha = harness_uniform(g, 0.3, 0.7), t = tan(alpha);
    const double beta = harness_uniform(g, 0, 0.8) * (0.5 * PI - alpha);
    const double d = harness_uniform(g, 0.3, 0.6) * (below ? -1 : 1);
    for (int k = 0; k < 3; k++) {
        c0[k] = harness_uniform(g, -0.2, 0.2);
        n[k] = cos(beta) * a[k] + sin(beta) * w[k];
    }
    const double ninv = 1 - (1 + t * t) / (t * t) * dot(n, a) * dot(n, a), mu = d / ninv;
    ellipse *el = &c->ell[0];
    for (int k = 0; k < 3; k++) {
        y[k] = mu * (n[k] - (1 + t * t) / (t * t) * dot(n, a) * a[k]);
        el->C[k] = c0[k] + y[k];
    }
    normal_to(g, n, e0), cross(e1, n, e0);
    const double rhs = -mu * d, m00 = cone_form(a, t, e0, e0), m01 = cone_form(a, t, e0, e1);
    for (int k = 0; k < 3; k++)
        q[k] = e1[k] - m01 / m00 * e0[k];
    const double mqq = cone_form(a, t, q, q);
    for (int k = 0; k < 3; k++)
        el->P[k] = sqrt(rhs / m00) * e0[k], el->Q[k] = sqrt(rhs / mqq) * q[k];
    c->prim[0] = primitive(IC_PRIM_CONE, c0, a), c->prim[0].half_angle = alpha;
    c->prim[1] = primitive(IC_PRIM_PLANE, el->C, n);
    c->nellipses = 1;
}

/* Cylinders of radius r about a and b through c0 (b at phi from a): the
 * ellipses c0 + r cos m + 2r/|a - b| sin (a + b)/|a + b| and c0 + r cos m +
 * 2r/|a + b| sin (b - a)/|b - a| (exact_cylinders.c derives them), the
 * branch points c0 +- r m, m = a x b / |a x b|. */
static void equal_cylinders(conic_case *c, const double *c0, const double *a, const double *b,
                            double r)
{
    double m[3], s[3], dd[3];
    cross(m, a, b), unit(m);
    for (int k = 0; k < 3; k++)
        s[k] = a[k] + b[k], dd[k] = b[k] - a[k];
    const double ls = norm(s), ld = norm(dd);
    c->prim[0] = primitive(IC_PRIM_CYLINDER, c0, a), c->prim[0].radius = r;
    c->prim[1] = primitive(IC_PRIM_CYLINDER, c0, b), c->prim[1].radius = r;
    c->nellipses = 2, c->nbranch = 2;
    for (int k = 0; k < 3; k++) {
        c->ell[0].C[k] = c->ell[1].C[k] = c0[k];
        c->ell[0].P[k] = c->ell[1].P[k] = r * m[k];
        c->ell[0].Q[k] = 2 * r / ld * s[k] / ls;
        c->ell[1].Q[k] = 2 * r / ls * dd[k] / ld;
        c->branch[0][k] = c0[k] + r * m[k], c->branch[1][k] = c0[k] - r * m[k];
    }
}

static void random_equal_cylinders(harness_rng *g, conic_case *c)
{
    double a[3], w[3], b[3], c0[3];
    random_unit(g, a), normal_to(g, a, w);
    const double phi = harness_uniform(g, 0.5, PI - 0.5);
    for (int k = 0; k < 3; k++) {
        b[k] = cos(phi) * a[k] + sin(phi) * w[k];
        c0[k] = harness_uniform(g, -0.3, 0.3);
    }
    equal_cylinders(c, c0, a, b, harness_uniform(g, 0.3, 0.8));
}

/* ---- checks ---- */

/* The derived ellipse the curve lies on (every point within tol), or -1:
 * the first point alone would not tell the two ellipses of two cylinders
 * apart, both passing through their branch points. */
static int which_ellipse(const conic_case *c, const ic_trace_curve *cv, double tol)
{
    for (int i = 0; i < c->nellipses; i++) {
        double worst = 0, t;
        for (int k = 0; k < cv->npoints && worst <= tol; k++)
            worst = fmax(worst, param_of(&c->ell[i], cv->points[k].xyz, &t));
        if (worst <= tol)
            return i;
    }
    return -1;
}

/* The largest |f| / |grad f| of the points on either surface, and the
 * largest difference of their angles from the surfaces' normals'. */
static void against_surfaces(ic_surface *const S[2], const ic_trace_curve *cv, double *off,
                             double *angle_err)
{
    *off = *angle_err = 0;
    for (int k = 0; k < cv->npoints; k++) {
        ic_surface_geometry g[2];
        for (int s = 0; s < 2; s++) {
            if (ic_surface_normal_at(S[s], &g[s], cv->points[k].xyz, NULL) != IC_OK) {
                *off = INFINITY;
                return;
            }
            *off = fmax(*off, fabs(g[s].value) / g[s].normal_length);
        }
        double x[3];
        cross(x, g[0].normal, g[1].normal);
        const double angle = atan2(norm(x), fabs(dot(g[0].normal, g[1].normal)));
        *angle_err = fmax(*angle_err, fabs(angle - cv->points[k].angle));
    }
}

/* Point k's apparatus against the ellipse at its parameter t: 1 when all
 * agree. `orient` (+1 or -1) is the direction of travel in t. */
static int frame_ok(const ellipse *e, const ic_trace_point *p, double t, double orient)
{
    double d[3], z[3], x[3], tt[3], nn[3];
    for (int k = 0; k < 3; k++) {
        d[k] = orient * (-sin(t) * e->P[k] + cos(t) * e->Q[k]);
        z[k] = cos(t) * e->P[k] + sin(t) * e->Q[k]; /* -c'' */
    }
    cross(x, e->P, e->Q);
    const double v = norm(d), kappa = norm(x) / (v * v * v);
    for (int k = 0; k < 3; k++)
        tt[k] = d[k] / v;
    for (int k = 0; k < 3; k++)
        nn[k] = -(z[k] - dot(z, tt) * tt[k]);
    unit(nn);
    double b[3];
    cross(b, tt, nn);
    int ok = fabs(p->kappa - kappa) <= EXACT_FRAME * kappa && p->tau == 0 && p->frame_defined;
    for (int k = 0; k < 3; k++)
        ok = ok && fabs(p->t[k] - tt[k]) <= EXACT_FRAME && fabs(p->n[k] - nn[k]) <= EXACT_FRAME &&
             fabs(p->b[k] - b[k]) <= EXACT_FRAME;
    return ok;
}

/* Every point of an exact curve on the derived ellipse i, in order, with
 * its apparatus and arc length. */
static void check_points(const conic_case *c, const traced_pair *t, const ic_trace_curve *cv, int i)
{
    const ellipse *e = &c->ell[i];
    double worst_place = 0, worst_arc = 0, t0, t1;
    int frames = 1, forward = 1;
    param_of(e, cv->points[0].xyz, &t0);
    param_of(e, cv->points[1].xyz, &t1);
    const double orient = remainder(t1 - t0, 2 * PI) > 0 ? 1 : -1;
    double prev = t0;
    for (int k = 0; k < cv->npoints; k++) {
        const ic_trace_point *p = &cv->points[k];
        double tk;
        worst_place = fmax(worst_place, param_of(e, p->xyz, &tk));
        frames = frames && frame_ok(e, p, tk, orient);
        if (k == 0)
            continue;
        /* the step in t the way the curve goes, then its arc by Simpson */
        const double step = orient * remainder(tk - prev, 2 * PI);
        forward = forward && step > 0 && p->s > cv->points[k - 1].s;
        const double arc =
            orient > 0 ? simpson_arc(e, prev, prev + step) : simpson_arc(e, prev - step, prev);
        const double ds = p->s - cv->points[k - 1].s;
        worst_arc =
            fmax(worst_arc, fabs(ds - arc) / (EXACT_ARC * arc + EXACT_S_ROUNDING * cv->length));
        prev = tk;
    }
    CHECK(worst_place <= EXACT_PLACE * t->L, "%s: ellipse %d: points on it to %.3g L", c->name, i,
          worst_place / t->L);
    CHECK(frames, "%s: ellipse %d: t, n, b, kappa, tau 0 at every point", c->name, i);
    CHECK(forward && worst_arc <= 1,
          "%s: ellipse %d: in order, arcs (Simpson) to %.3g of their tolerance", c->name, i,
          worst_arc);
    double off, angle_err;
    against_surfaces(t->S, cv, &off, &angle_err);
    CHECK(off <= EXACT_PLACE * t->L && angle_err <= EXACT_ANGLE,
          "%s: ellipse %d: on both surfaces to %.3g L, angles to %.3g rad", c->name, i, off / t->L,
          angle_err);
}

/* The marching's step rules on a circle of radius rho (docs/tracing.md, "A
 * step"; "Exact paths"), lengths absolute at the size F: the truncation
 * terms of orders K-1 and K with |c^(k)| = rho^(1-k), the chord height
 * h^2 / (8 rho), the longest step. */
static double rule_step(const ic_trace_options *o, double F, double rho)
{
    double h = o->max_step * F, fact = 1;
    for (int k = 1; k <= o->order; k++) {
        fact *= k;
        if (k >= o->order - 1)
            h = fmin(h, pow(o->tol * F * fact * pow(rho, k - 1), 1.0 / k));
    }
    return fmin(h, sqrt(8 * o->chord * F * rho));
}

/* The size the exact path takes for its lengths, as the search would: the
 * diagonal of the box around the ellipses (C +- sqrt(P_k^2 + Q_k^2) along
 * each axis) when between 1e-3 L and L (docs/tracing.md, "Scale"). */
static double found_size(const conic_case *c, double L)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY},
           d2 = 0;
    for (int i = 0; i < c->nellipses; i++)
        for (int k = 0; k < 3; k++) {
            const ellipse *e = &c->ell[i];
            const double ext = hypot(e->P[k], e->Q[k]);
            lo[k] = fmin(lo[k], e->C[k] - ext), hi[k] = fmax(hi[k], e->C[k] + ext);
        }
    for (int k = 0; k < 3; k++)
        d2 += (hi[k] - lo[k]) * (hi[k] - lo[k]);
    return sqrt(d2) > 1e-3 * L && sqrt(d2) < L ? sqrt(d2) : L;
}

/* Every step of an exact curve within the marching's rules at the radius
 * of curvature where it starts (as the marching takes them), but for
 * SPACING_SLACK; and no more points than SPACING_EXCESS times the fewest
 * those rules allow (the sum of ds / h). */
static void check_spacing(const conic_case *c, const traced_pair *t, const ic_trace_curve *cv,
                          int i)
{
    ic_trace_options o;
    ic_trace_defaults(&o);
    const double F = found_size(c, t->L);
    double worst = 0, fewest = 0, a, b;
    for (int k = 0; k + 1 < cv->npoints; k++) {
        const double ds = cv->points[k + 1].s - cv->points[k].s;
        const double h = rule_step(&o, F, 1 / cv->points[k].kappa);
        worst = fmax(worst, ds / h), fewest += ds / h;
    }
    semi_axes(&c->ell[i], &a, &b);
    const double excess = a <= 4 * b ? SPACING_EXCESS_LOW : SPACING_EXCESS_HIGH;
    CHECK(worst <= 1 + SPACING_SLACK && cv->npoints - 1 <= excess * fewest,
          "%s: ellipse %d: steps within %.4f of the rules' at their start, %d arcs where the "
          "rules allow %.0f",
          c->name, i, worst, cv->npoints - 1, fewest);
}

/* The exact path's result against the derived ellipses and points. */
static void check_exact(const conic_case *c, const traced_pair *t)
{
    const ic_trace_result *r = t->res[1];
    const ic_trace_report *rep = ic_trace_result_report(r);
    CHECK(rep->tracer_complete && rep->proven && strcmp(rep->method, CLOSED_FORM) == 0 && rep->cells == 0,
          "%s: complete, in closed form (%s)", c->name, rep->method);
    const int nc = ic_trace_result_num_curves(r), ns = ic_trace_result_num_specials(r);
    if (!REQUIRE(nc == c->nellipses && ns == c->nbranch, "%s: %d curves, %d points; want %d, %d",
                 c->name, nc, ns, c->nellipses, c->nbranch))
        return;
    int seen = 0;
    for (int k = 0; k < nc; k++) {
        const ic_trace_curve *cv = ic_trace_result_curve(r, k);
        const int i = which_ellipse(c, cv, EXACT_PLACE * t->L);
        if (!REQUIRE(i >= 0 && !(seen & (1 << i)), "%s: curve %d is a derived ellipse", c->name, k))
            continue;
        seen |= 1 << i;
        const double length = ellipse_length(&c->ell[i]);
        CHECK(cv->closed && cv->ends[0] == IC_TRACE_CLOSED && cv->ends[1] == IC_TRACE_CLOSED &&
                  !cv->tangential && cv->shape == IC_SHAPE_PLANAR,
              "%s: ellipse %d closed, transversal, planar (%s)", c->name, i,
              ic_shape_name(cv->shape));
        CHECK(fabs(cv->length - length) <= EXACT_LENGTH * length,
              "%s: ellipse %d: length %.17g, 4 a E(m) = %.17g", c->name, i, cv->length, length);
        check_points(c, t, cv, i);
        check_spacing(c, t, cv, i);
    }
    for (int k = 0; k < ns; k++) {
        const ic_trace_special *sp = ic_trace_result_special(r, k);
        double d = INFINITY;
        for (int j = 0; j < c->nbranch; j++) {
            double x[3];
            for (int m = 0; m < 3; m++)
                x[m] = sp->xyz[m] - c->branch[j][m];
            d = fmin(d, norm(x));
        }
        CHECK(sp->type == IC_POINT_BRANCH && sp->nbranches == 2 && !sp->approximate &&
                  d <= EXACT_PLACE * t->L,
              "%s: point %d a branch point of 2 branches, exact, %.3g L from the derived one",
              c->name, k, d / t->L);
    }
}

/* The general path finds the same: complete, as many curves, closed and
 * planar, on the derived ellipses, lengths within GENERAL_LENGTH, the same
 * branch points. */
static void check_against_general(const conic_case *c, const traced_pair *t)
{
    const ic_trace_result *g = t->res[0], *x = t->res[1];
    CHECK(ic_trace_result_report(g)->tracer_complete, "%s: the general path is complete", c->name);
    const int n = ic_trace_result_num_curves(g);
    if (!REQUIRE(n == ic_trace_result_num_curves(x) &&
                     ic_trace_result_num_specials(g) == ic_trace_result_num_specials(x),
                 "%s: the general path's %d curves and %d points, the exact path's %d, %d", c->name,
                 n, ic_trace_result_num_specials(g), ic_trace_result_num_curves(x),
                 ic_trace_result_num_specials(x)))
        return;
    for (int k = 0; k < n; k++) {
        const ic_trace_curve *gc = ic_trace_result_curve(g, k), *xc = NULL;
        const int i = which_ellipse(c, gc, GENERAL_ON_EXACT * t->L);
        for (int m = 0; m < n && i >= 0; m++)
            if (which_ellipse(c, ic_trace_result_curve(x, m), EXACT_PLACE * t->L) == i)
                xc = ic_trace_result_curve(x, m);
        if (!REQUIRE(xc, "%s: the general path's curve %d is a derived ellipse", c->name, k))
            continue;
        double worst = 0, tp;
        for (int p = 0; p < gc->npoints; p++)
            worst = fmax(worst, param_of(&c->ell[i], gc->points[p].xyz, &tp));
        CHECK(worst <= GENERAL_ON_EXACT * t->L && gc->closed == xc->closed &&
                  gc->tangential == xc->tangential && gc->shape == xc->shape,
              "%s: ellipse %d: the general path's points on it (%.3g L), closed %d/%d, shape "
              "%s/%s",
              c->name, i, worst / t->L, gc->closed, xc->closed, ic_shape_name(gc->shape),
              ic_shape_name(xc->shape));
        CHECK(fabs(gc->length - xc->length) <= GENERAL_LENGTH * xc->length,
              "%s: ellipse %d: lengths %.17g (general), %.17g (exact)", c->name, i, gc->length,
              xc->length);
    }
    for (int k = 0; k < ic_trace_result_num_specials(g); k++) {
        const ic_trace_special *a = ic_trace_result_special(g, k);
        int matched = 0;
        for (int m = 0; m < ic_trace_result_num_specials(x); m++) {
            const ic_trace_special *b = ic_trace_result_special(x, m);
            double d[3];
            for (int j = 0; j < 3; j++)
                d[j] = a->xyz[j] - b->xyz[j];
            matched = matched || (norm(d) <= GENERAL_ON_EXACT * t->L && a->type == b->type &&
                                  a->nbranches == b->nbranches && a->approximate == b->approximate);
        }
        CHECK(matched, "%s: the general path's point %d (%s, %d branches) is an exact one", c->name,
              k, ic_point_type_name(a->type), a->nbranches);
    }
}

static void run_case(conic_case *c)
{
    traced_pair t;
    if (trace_pair_both(&t, &c->prim[0], &c->prim[1], c->half, c->name)) {
        check_exact(c, &t);
        check_against_general(c, &t);
    }
    release_pair(&t);
}

/* ---- the cases ---- */

/* Steinmetz's pair (the peers benchmark's "steinmetz", and
 * examples/cylinders-equal.json as primitives): the ellipses' length 4
 * sqrt(2) E(1/2) from mpmath, the branch points (+-1, 0, 0) exactly, and
 * the curves' points there typed as the general path's are (equal to the
 * special point). */
static void steinmetz(void)
{
    conic_case c;
    memset(&c, 0, sizeof c);
    snprintf(c.name, sizeof c.name, "Steinmetz: cylinders about z and y, r = 1");
    const double o[3] = {0, 0, 0}, z[3] = {0, 0, 1}, y[3] = {0, 1, 0};
    equal_cylinders(&c, o, z, y, 1);
    c.half = 1.5;
    run_case(&c);
    traced_pair t;
    if (!trace_pair_both(&t, &c.prim[0], &c.prim[1], c.half, c.name))
        return release_pair(&t);
    const ic_trace_result *r = t.res[1];
    for (int k = 0; k < ic_trace_result_num_curves(r); k++) {
        const ic_trace_curve *cv = ic_trace_result_curve(r, k);
        CHECK_CLOSE(cv->length, 7.64039557805542403581, EXACT_LENGTH,
                    "Steinmetz: 4 sqrt(2) E(1/2)");
        int at_branch = 0;
        for (int p = 0; p < cv->npoints; p++)
            for (int j = 0; j < ic_trace_result_num_specials(r); j++)
                at_branch += memcmp(cv->points[p].xyz, ic_trace_result_special(r, j)->xyz,
                                    sizeof cv->points[p].xyz) == 0 &&
                             cv->points[p].angle == 0;
        /* both branch points, the first point also the last */
        CHECK(at_branch == 3, "Steinmetz: curve %d passes both branch points exactly (%d)", k,
              at_branch);
    }
    for (int j = 0; j < ic_trace_result_num_specials(r); j++) {
        const double *x = ic_trace_result_special(r, j)->xyz;
        CHECK(fabs(x[0]) == 1 && x[1] == 0 && x[2] == 0, "Steinmetz: branch point (%g, %g, %g)",
              x[0], x[1], x[2]);
    }
    release_pair(&t);
}

/* Eccentric ellipses. A needle: the ellipsoid of semi-axes 1.2, 0.01, 0.01
 * cut through its centre by a plane along its long axis, an ellipse 120
 * times longer than wide. */
static void eccentric(void)
{
    conic_case c;
    memset(&c, 0, sizeof c);
    snprintf(c.name, sizeof c.name, "a needle ellipsoid's ellipse of aspect 120");
    const double o[3] = {0, 0, 0}, e[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const double S[3] = {1.2, 0.01, 0.01}, n[3] = {0, 1, 0.2}, x[3] = {0, 0, 1};
    ellipsoid_section(&c, o, e, S, n, 0, x);
    c.half = 1.5;
    run_case(&c);
    /* two cylinders of radius 0.01 crossing at 0.02 rad: one ellipse 100
     * times longer than wide, its minor axis first (theta = 0 at a branch
     * point): the longest step binds at the flat ends, and the spacing's
     * tightest place is inside a quadrant */
    memset(&c, 0, sizeof c);
    snprintf(c.name, sizeof c.name, "thin cylinders crossing at 0.02 rad");
    const double z[3] = {0, 0, 1}, tilted[3] = {0, sin(0.02), cos(0.02)};
    equal_cylinders(&c, o, z, tilted, 0.01);
    c.half = 1.5;
    run_case(&c);
}

/* Coarse options (8 arcs for the whole ellipse, the fewest): the
 * quadrature of each arc must be split for its bound, and the length still
 * be 4 a E(m). A cylinder cut at acos(1/8) to its axis: an ellipse 8 times
 * longer than wide. */
static void coarse_steps(void)
{
    const double o[3] = {0, 0, 0}, z[3] = {0, 0, 1};
    const double n[3] = {sqrt(63) / 8, 0, 1.0 / 8}, y[3] = {0, 1, 0},
                 d[3] = {1.0 / 8, 0, -sqrt(63) / 8};
    conic_case c;
    memset(&c, 0, sizeof c);
    c.prim[0] = primitive(IC_PRIM_CYLINDER, o, z), c.prim[0].radius = 0.1;
    c.prim[1] = primitive(IC_PRIM_PLANE, o, n);
    for (int k = 0; k < 3; k++)
        c.ell[0].P[k] = 0.1 * y[k], c.ell[0].Q[k] = 0.8 * d[k];
    ic_trace_options opt;
    ic_trace_defaults(&opt);
    opt.tol = 1e-2, opt.chord = 0.5, opt.max_step = 1, opt.has_box = 1;
    for (int k = 0; k < 3; k++)
        opt.box[k][0] = -1, opt.box[k][1] = 1;
    ic_surface *S[2] = {NULL, NULL};
    ic_pair *pair = NULL;
    ic_trace_result *r = NULL;
    ic_error err;
    if (REQUIRE(ic_surface_new_primitive(&S[0], &c.prim[0], IC_IMPLICIT, &err) == IC_OK &&
                    ic_surface_new_primitive(&S[1], &c.prim[1], IC_IMPLICIT, &err) == IC_OK &&
                    ic_pair_new(&pair, S[0], S[1], &err) == IC_OK &&
                    ic_trace(&r, pair, &opt, &err) == IC_OK,
                "coarse steps: traced: %s", err.message) &&
        REQUIRE(ic_trace_result_num_curves(r) == 1, "coarse steps: one ellipse")) {
        const ic_trace_curve *cv = ic_trace_result_curve(r, 0);
        const double length = ellipse_length(&c.ell[0]);
        CHECK(cv->npoints == 9 && fabs(cv->length - length) <= EXACT_LENGTH * length,
              "coarse steps: %d points, length %.17g, 4 a E(m) = %.17g", cv->npoints, cv->length,
              length);
    }
    ic_trace_result_free(r);
    ic_pair_free(pair);
    ic_surface_free(S[0]);
    ic_surface_free(S[1]);
}

enum { PLANE_CYLINDER, PLANE_ELLIPSOID, PLANE_CONE, EQUAL_CYLINDERS, NFAMILIES };
static const char *const FAMILY[NFAMILIES] = {"plane/cylinder", "plane/ellipsoid", "plane/cone",
                                              "equal cylinders"};

static void random_cases(int per_family)
{
    harness_rng g = {0x2545F4914F6CDD1DULL};
    for (int f = 0; f < NFAMILIES; f++)
        for (int i = 0; i < per_family; i++) {
            conic_case c;
            memset(&c, 0, sizeof c);
            snprintf(c.name, sizeof c.name, "%s %d", FAMILY[f], i);
            c.half = 3;
            if (f == PLANE_CYLINDER)
                plane_cylinder(&g, &c);
            else if (f == PLANE_ELLIPSOID)
                plane_ellipsoid(&g, &c);
            else if (f == PLANE_CONE)
                plane_cone(&g, i % 2, &c); /* either side of the apex */
            else
                random_equal_cylinders(&g, &c);
            if (i % 2) { /* either surface first */
                const ic_primitive first = c.prim[0];
                c.prim[0] = c.prim[1], c.prim[1] = first;
            }
            run_case(&c);
        }
}

/* A plane that misses the ellipsoid: nothing, in closed form. */
static void plane_misses(void)
{
    const double o[3] = {0, 0, 0}, z[3] = {0, 0, 1}, n[3] = {1, 1, 1};
    const double far[3] = {2, 0, 0};
    ic_primitive E = primitive(IC_PRIM_ELLIPSOID, o, z), P = primitive(IC_PRIM_PLANE, far, n);
    E.axes[0] = 1, E.axes[1] = 0.7, E.axes[2] = 0.5;
    traced_pair t;
    if (trace_pair_both(&t, &E, &P, 3, "plane missing an ellipsoid")) {
        const ic_trace_result *x = t.res[1], *g = t.res[0];
        CHECK(strcmp(ic_trace_result_report(x)->method, CLOSED_FORM) == 0 &&
                  ic_trace_result_report(x)->tracer_complete && ic_trace_result_num_curves(x) == 0 &&
                  ic_trace_result_num_specials(x) == 0 && ic_trace_result_num_curves(g) == 0 &&
                  ic_trace_result_num_specials(g) == 0 && ic_trace_result_report(g)->tracer_complete,
              "plane missing an ellipsoid: nothing, complete, in closed form and by the search");
    }
    release_pair(&t);
}

/* A plane normal to a cylinder's axis is coaxial: the revolution path's. */
static void coaxial_stays(void)
{
    const double o[3] = {0, 0, 0}, z[3] = {0, 0, 1}, up[3] = {0, 0, 0.5};
    ic_primitive C = primitive(IC_PRIM_CYLINDER, o, z), P = primitive(IC_PRIM_PLANE, up, z);
    C.radius = 1;
    traced_pair t;
    if (trace_pair_both(&t, &C, &P, 2, "coaxial cylinder and plane"))
        CHECK(strcmp(ic_trace_result_report(t.res[1])->method,
                     "closed form: coaxial surfaces of revolution") == 0,
              "a cylinder and a plane normal to its axis: the revolution path (%s)",
              ic_trace_result_report(t.res[1])->method);
    release_pair(&t);
}

/* The cases left to the general path: exactly what it gives. */
static void fall_back_cases(void)
{
    const double o[3] = {0, 0, 0}, x[3] = {1, 0, 0}, y[3] = {0, 1, 0}, z[3] = {0, 0, 1};
    ic_primitive cyl = primitive(IC_PRIM_CYLINDER, o, z), other;
    cyl.radius = 1;
    /* the ellipse of semi-axes 1 and 2 (the plane at 60 degrees to the
     * axis) cut by the box's faces z = +-1.5 */
    const double tilt[3] = {sqrt(3) / 2, 0, 0.5};
    check_fall_back("plane and cylinder, the ellipse cut by the box", &cyl,
                    (ic_primitive[]){primitive(IC_PRIM_PLANE, o, tilt)}, 1.5);
    /* a plane along the axis: two lines */
    check_fall_back("plane along a cylinder's axis", &cyl,
                    (ic_primitive[]){primitive(IC_PRIM_PLANE, o, x)}, 1.5);
    /* a cone of half-angle pi/4 and a plane parallel to a generator: a
     * parabola; steeper: a hyperbola; through the apex: a point */
    ic_primitive cone = primitive(IC_PRIM_CONE, o, z);
    cone.half_angle = PI / 4;
    const double along[3] = {1, 0, 1}, steep[3] = {1, 0, 0.3}, mild[3] = {0.3, 0, 1};
    const double below[3] = {0, 0, -0.5};
    check_fall_back("cone and a plane parallel to a generator", &cone,
                    (ic_primitive[]){primitive(IC_PRIM_PLANE, below, along)}, 1.5);
    check_fall_back("cone and a steep plane", &cone,
                    (ic_primitive[]){primitive(IC_PRIM_PLANE, below, steep)}, 1.5);
    check_fall_back("cone and a plane through its apex", &cone,
                    (ic_primitive[]){primitive(IC_PRIM_PLANE, o, mild)}, 1.5);
    /* the apex 1e-4 L from a plane that cuts an ellipse */
    const double near_apex[3] = {0, 0, 3e-4};
    check_fall_back("cone and a plane by its apex", &cone,
                    (ic_primitive[]){primitive(IC_PRIM_PLANE, near_apex, mild)}, 1.5);
    /* an ellipsoid nearly touched: planes 5e-7 L (within IC_EXACT_NEAR, the
     * normals 1.8e-3 rad apart) and 1e-7 L (8e-4 rad) below its top */
    ic_primitive ell = primitive(IC_PRIM_ELLIPSOID, o, z);
    ell.axes[0] = 1, ell.axes[1] = 0.8, ell.axes[2] = 0.6;
    for (int i = 0; i < 2; i++) {
        const double top[3] = {0, 0, 0.6 - (i ? 1e-7 : 5e-7) * 3 * sqrt(3)};
        check_fall_back(i ? "ellipsoid nearly touched by a plane, 8e-4 rad"
                          : "ellipsoid nearly touched by a plane, 5e-7 L",
                        &ell, (ic_primitive[]){primitive(IC_PRIM_PLANE, top, z)}, 1.5);
    }
    /* a flat ellipsoid (radius of curvature 30 at its top) cut 1e-5 below
     * its top: the gap 2e-6 L is clear of IC_EXACT_NEAR, the normals only
     * 8e-4 rad apart */
    ell.axes[0] = ell.axes[1] = 3, ell.axes[2] = 0.3;
    const double flat_top[3] = {0, 0, 0.3 - 1e-5};
    check_fall_back("flat ellipsoid cut by a plane at 8e-4 rad", &ell,
                    (ic_primitive[]){primitive(IC_PRIM_PLANE, flat_top, z)}, 1.5);
    /* a sphere crossed 1e-6 below its pole: the revolution path leaves it
     * to the general path (a nearly tangent profile), and so must this one */
    ic_primitive sphere = primitive(IC_PRIM_SPHERE, o, z);
    sphere.radius = 1;
    const double pole[3] = {0, 0, 1 - 1e-6};
    check_fall_back("sphere and a plane 1e-6 below its pole", &sphere,
                    (ic_primitive[]){primitive(IC_PRIM_PLANE, pole, z)}, 2);
    /* two cylinders of radius 1 about z and y: radii 1e-9 apart, axes that
     * miss by 1e-9; about z and 1e-2 rad from it, nearly parallel (an
     * ellipse 200 times longer than wide; the general path takes 150 s
     * where the axes are 1e-4 rad apart, 1.5 s here) */
    other = primitive(IC_PRIM_CYLINDER, o, y), other.radius = 1 + 1e-9;
    check_fall_back("cylinders of radii 1e-9 apart", &cyl, &other, 1.5);
    const double off[3] = {1e-9, 0, 0};
    other = primitive(IC_PRIM_CYLINDER, off, y), other.radius = 1;
    check_fall_back("cylinders whose axes miss by 1e-9", &cyl, &other, 1.5);
    const double nearly_z[3] = {1e-2, 0, 1};
    other = primitive(IC_PRIM_CYLINDER, o, nearly_z), other.radius = 1;
    check_fall_back("cylinders 1e-2 rad from parallel", &cyl, &other, 1.5);
    /* unequal crossing cylinders (examples/cylinders.json as primitives) */
    other = primitive(IC_PRIM_CYLINDER, o, x), other.radius = 0.5;
    check_fall_back("cylinders of radii 1 and 1/2 crossing", &cyl, &other, 1.5);
}

int main(void)
{
    agm_against_mpmath();
    steinmetz();
    random_cases(3 * harness_multiplier());
    eccentric();
    coarse_steps();
    plane_misses();
    coaxial_stays();
    fall_back_cases();
    return harness_finish("test_exact_conics");
}
