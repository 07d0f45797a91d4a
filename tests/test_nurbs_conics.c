/* The conic path on NURBS nets recognised as cylinders and planes
 * (docs/tracing.md, "Plane sections of quadrics"; the nets of
 * tests/nurbs_nets.h): Steinmetz's pair of equal cylinder nets whose axes
 * meet at a random angle and place (two ellipses through two branch
 * points), and a plane net oblique to a cylinder net (one ellipse), plain,
 * degree-elevated and knot-inserted. Against the closed forms derived here
 * (every point on the ellipse and on both exact surfaces, the lengths
 * 4 a E(m), the branch points exact); every point's parameters putting
 * each net on the point; a point exactly on every knot line crossed, as
 * many as the closed form says; the pcurves fitted; and against the general
 * path (exact_paths = 0): the same curves, closed, the same branch points,
 * the same lengths to its accuracy. A cylinder net too short for its
 * ellipse is left to the general path: exactly what it gives. */
#include <string.h>

#include "same_trace.h"
#include "elliptic_e.h"
#include "harness.h"
#include "nurbs_nets.h"

static const char NETS[] = "closed form: NURBS nets recognised as plane sections of quadrics";

/* relative to the problem's size L: the exact points against the ellipses
 * and surfaces derived here, and the lengths against 4 a E(m): a few
 * roundings of O(L) coordinates (the nets' axes are read to rounding) */
#define EXACT_REL 1e-14
/* relative to L: every point's parameters on a net put it back on the
 * point, |S(u, v) - x| (the path refuses beyond this: IC_EXACT_ON_NET) */
#define ON_NET_REL 1e-12
/* relative to L: a step's arc length s against its chord, chord <= ds <=
 * chord + kappa_max^2 ds^3 / 24 (a plane arc of curvature at most
 * kappa_max), beyond a few roundings of the O(L) values of s */
#define ARC_ROUNDING 1e-14
/* relative to a parameter's domain: a step's parameters move by less than
 * this (the steps are short; a wrap not run on jumps by a whole period) */
#define STEP_PARAM 0.25
/* relative: the closed form derived here, 4 sqrt(2) E(1/2) by the AGM,
 * against mpmath's (as test_exact_conics' EXACT_LENGTH) */
#define AGM_LENGTH (16 * DBL_EPSILON)
/* relative: the general path's lengths against the exact ones (its
 * truncation error per step is 1e-11 L at most, of either sign along a
 * closed curve; test_exact_conics holds the primitives to the same) */
#define GENERAL_LENGTH 1e-11
/* relative to L: the general path's points and branch points from the
 * derived ellipses and points (it locates them to about 1e-12 L) */
#define GENERAL_ON_EXACT 1e-9

enum { MAX_ELLIPSES = 2 };

/* A sheet: a cylinder (axis through o along a, radius r), a cone (apex o,
 * axis a, rho = z tan_half at the height z along a) or a plane (through o,
 * normal a), written as a net; a revolved net's profile runs from height
 * z0 to z1. */
typedef struct {
    net_patch net;
    int plane, cone;
    double o[3], a[3], r, tan_half, z0, z1;
} sheet;

/* x(t) = c + A cos t + B sin t, A and B orthogonal. */
typedef struct {
    double c[3], A[3], B[3];
} ellipse;

typedef struct {
    char name[128];
    sheet s[2];
    int nell, nbranch;
    ellipse ell[MAX_ELLIPSES];
    double branch[2][3];
} conic_case;

typedef struct {
    ic_surface *S[2];
    ic_pair *pair;
    ic_trace_result *res[2]; /* [0] the general path, [1] the exact one */
    double L;
} traced;

static double dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static double norm3(const double *a) { return sqrt(dot3(a, a)); }

static double dist3(const double *a, const double *b)
{
    const double d[3] = {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    return norm3(d);
}

static void axpy(double *y, const double *x, double s, const double *z)
{
    for (int k = 0; k < 3; k++)
        y[k] = x[k] + s * z[k];
}

/* ---- the nets ---- */

/* variants: 0 plain, 1 degree-elevated, 2 a knot put in each direction */
static void vary(net_curve *c, int variant, double t)
{
    if (variant == 1)
        curve_elevate(c);
    if (variant == 2)
        curve_insert(c, t);
}

/* A place with e3 = a through o, e1 any normal to it (turned by spin). */
static net_place place_along(const double *o, const double *a, double spin)
{
    net_place p;
    memcpy(p.o, o, sizeof p.o);
    p.s = 1;
    memcpy(p.e[2], a, sizeof p.e[2]);
    const double x[3] = {cos(spin), sin(spin), 0.3};
    net_cross(p.e[1], a, x);
    net_unit(p.e[1]);
    net_cross(p.e[0], p.e[1], a);
    return p;
}

/* The cylinder about the place's e3 through its origin (unit scale). */
static void cylinder_at(sheet *s, const net_place *pl, double r, double half, int variant)
{
    net_curve circle, profile;
    circle9(&circle);
    segment(&profile, r, -half, r, half);
    vary(&circle, variant, 0.4);
    vary(&profile, variant, 0.3);
    revolve(&s->net, &circle, &profile, pl, 0, 0);
    s->plane = s->cone = 0, s->r = r, s->z0 = -half, s->z1 = half;
    memcpy(s->o, pl->o, sizeof s->o), memcpy(s->a, pl->e[2], sizeof s->a);
}

static void cylinder_sheet(sheet *s, const double *o, const double *a, double r, double half,
                           double spin, int variant)
{
    const net_place pl = place_along(o, a, spin);
    cylinder_at(s, &pl, r, half, variant);
}

/* The plane through o normal to n as a grid [-w, w]^2 sheared by the
 * angle 1.2 between its edges, about o. */
static void plane_sheet(sheet *s, const double *o, const double *n, double w, int variant)
{
    net_curve fu, fv;
    const double angle = 1.2;
    segment(&fu, -w - w * cos(angle), 0, w - w * cos(angle), 0);
    segment(&fv, -w, 0, w, 0);
    vary(&fu, variant, 0.45);
    vary(&fv, variant, 0.6);
    const net_place pl = place_along(o, n, 0.7);
    plane_grid(&s->net, &fu, &fv, angle, &pl);
    s->plane = 1, s->cone = 0, s->r = 0;
    memcpy(s->o, o, sizeof s->o), memcpy(s->a, n, sizeof s->a);
}

static void random_unit(harness_rng *g, double *e)
{
    for (int k = 0; k < 3; k++)
        e[k] = harness_uniform(g, -1, 1);
    net_unit(e);
}

/* Steinmetz's pair: radius r, axes a and b (unit) meeting at o. The
 * ellipses lie in the planes through o normal to a - b and a + b: one
 * semi-axis r along w = a x b (its ends the branch points o +- r w, on
 * both cylinders where their normals are parallel), the other along the
 * plane's direction d normal to w, reaching the cylinder about a where
 * t |d x a| = r. */
static void steinmetz(conic_case *c, const double *o, const double *a, const double *b, double r,
                      double half, int variant, harness_rng *g)
{
    memset(c, 0, sizeof *c);
    cylinder_sheet(&c->s[0], o, a, r, half, harness_uniform(g, 0, 6), variant);
    cylinder_sheet(&c->s[1], o, b, r, half, harness_uniform(g, 0, 6), variant);
    double w[3];
    net_cross(w, a, b);
    net_unit(w);
    c->nell = c->nbranch = 2;
    for (int i = 0; i < 2; i++) {
        double d[3], x[3];
        axpy(d, a, i ? 1.0 : -1.0, b);
        net_unit(d);
        net_cross(x, d, a);
        ellipse *e = &c->ell[i];
        memcpy(e->c, o, sizeof e->c);
        for (int k = 0; k < 3; k++)
            e->A[k] = r * w[k], e->B[k] = r / norm3(x) * d[k];
        axpy(c->branch[i], o, i ? -r : r, w);
    }
}

/* A plane through q normal to n and a cylinder about the axis through o
 * along a, radius r: the ellipse about the axis' point in the plane,
 * semi-axes r along w = a x n and r / |a . n| along n x w. */
static void plane_cylinder(conic_case *c, const double *q, const double *n, const double *o,
                           const double *a, double r, int variant)
{
    memset(c, 0, sizeof *c);
    double w[3], d[3], oq[3];
    net_cross(w, a, n);
    net_unit(w);
    net_cross(d, n, w);
    axpy(oq, q, -1.0, o);
    ellipse *e = &c->ell[0];
    axpy(e->c, o, dot3(oq, n) / dot3(a, n), a);
    for (int k = 0; k < 3; k++)
        e->A[k] = r * w[k], e->B[k] = r / fabs(dot3(a, n)) * d[k];
    c->nell = 1;
    plane_sheet(&c->s[0], e->c, n, 6 * r, variant);
    cylinder_sheet(&c->s[1], o, a, r, 6 * r, 1.1, variant);
}

/* The cone rho = t z (z > 0) and the plane z = h + m x in local
 * coordinates, placed: in the plane y = 0 the section runs from x1 = h t
 * / (1 - m t) to x2 = -h t / (1 + m t); the ellipse is centred at xc = (x1
 * + x2) / 2 (z = h + m xc), its semi-axes (x1 - x2) / 2 (1, 0, m) and,
 * along y, sqrt(((h + m xc) t)^2 - xc^2) (m t < 1: an ellipse). The cone's
 * net covers the heights [z0, z1] of one nappe. */
static void plane_cone(conic_case *c, const net_place *pl, double t, double h, double m, double z0,
                       double z1, int variant)
{
    memset(c, 0, sizeof *c);
    const double x1 = h * t / (1 - m * t), x2 = -h * t / (1 + m * t), xc = 0.5 * (x1 + x2);
    const double zc = h + m * xc, b = sqrt(zc * t * zc * t - xc * xc), half = 0.5 * (x1 - x2);
    ellipse *e = &c->ell[0];
    double at[3];
    net_to_space(pl, xc, 0, zc, e->c);
    net_to_space(pl, 0, 0, 0, at);
    double A[3], B[3], n[3];
    net_to_space(pl, half, 0, half * m, A);
    net_to_space(pl, 0, b, 0, B);
    net_to_space(pl, -m, 0, 1, n);
    for (int k = 0; k < 3; k++)
        e->A[k] = A[k] - at[k], e->B[k] = B[k] - at[k], n[k] -= at[k];
    net_unit(n);
    c->nell = 1;
    plane_sheet(&c->s[0], e->c, n, 4 * half, variant);
    net_curve circle, profile;
    circle9(&circle);
    segment(&profile, z0 * t, z0, z1 * t, z1);
    vary(&circle, variant, 0.4);
    vary(&profile, variant, 0.3);
    sheet *s = &c->s[1];
    revolve(&s->net, &circle, &profile, pl, 0, 0);
    s->plane = 0, s->cone = 1, s->tan_half = t, s->z0 = z0, s->z1 = z1;
    memcpy(s->o, pl->o, sizeof s->o), memcpy(s->a, pl->e[2], sizeof s->a);
}

/* ---- tracing ---- */

static void release(traced *t)
{
    for (int i = 0; i < 2; i++) {
        ic_trace_result_free(t->res[i]);
        ic_surface_free(t->S[i]);
    }
    ic_pair_free(t->pair);
}

/* The diagonal of the nets' control points' box. */
static double nets_size(const conic_case *c)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int s = 0; s < 2; s++)
        for (int i = 0; i < c->s[s].net.count[0] * c->s[s].net.count[1]; i++)
            for (int k = 0; k < 3; k++)
                lo[k] = fmin(lo[k], c->s[s].net.points[3 * i + k]),
                hi[k] = fmax(hi[k], c->s[s].net.points[3 * i + k]);
    const double d[3] = {hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
    return norm3(d);
}

static int trace_case(traced *t, const conic_case *c)
{
    ic_error err;
    memset(t, 0, sizeof *t);
    t->L = nets_size(c);
    for (int s = 0; s < 2; s++)
        if (!REQUIRE(net_surface(&t->S[s], &c->s[s].net, &err) == IC_OK, "%s: net %d: %s", c->name,
                     s, err.message))
            return 0;
    if (!REQUIRE(ic_pair_new(&t->pair, t->S[0], t->S[1], &err) == IC_OK, "%s: %s", c->name,
                 err.message))
        return 0;
    for (int exact = 0; exact <= 1; exact++) {
        ic_trace_options opt;
        ic_trace_defaults(&opt);
        opt.exact_paths = exact;
        opt.certify = 0; /* the paths compared, not the proof: tracer_complete */
        if (!REQUIRE(ic_trace(&t->res[exact], t->pair, &opt, &err) == IC_OK, "%s: traced: %s",
                     c->name, err.message))
            return 0;
    }
    return 1;
}

/* ---- against the closed forms ---- */

/* The point's distance from the ellipse, read at the angle its offsets
 * along A and B give. */
static double off_ellipse(const ellipse *e, const double *x)
{
    double w[3], y[3];
    axpy(w, x, -1.0, e->c);
    const double t = atan2(dot3(w, e->B) / dot3(e->B, e->B), dot3(w, e->A) / dot3(e->A, e->A));
    axpy(y, e->c, cos(t), e->A);
    axpy(y, y, sin(t), e->B);
    return dist3(x, y);
}

/* The point's distance from the sheet's exact surface. */
static double off_sheet(const sheet *s, const double *x)
{
    double w[3];
    axpy(w, x, -1.0, s->o);
    const double z = dot3(w, s->a), rho = sqrt(fmax(0, dot3(w, w) - z * z));
    if (s->cone) /* from the nappe z > 0: its normal (cos, -sin) of the half-angle */
        return fabs(rho - z * s->tan_half) / sqrt(1 + s->tan_half * s->tan_half);
    return s->plane ? fabs(z) : fabs(rho - s->r);
}

static int which_ellipse(const conic_case *c, const ic_trace_curve *cv, double tol)
{
    for (int i = 0; i < c->nell; i++) {
        double worst = 0;
        for (int p = 0; p < cv->npoints; p++)
            worst = fmax(worst, off_ellipse(&c->ell[i], cv->points[p].xyz));
        if (worst <= tol)
            return i;
    }
    return -1;
}

static double ellipse_length(const ellipse *e)
{
    const double a = fmax(norm3(e->A), norm3(e->B)), b = fmin(norm3(e->A), norm3(e->B));
    return 4 * a * ellipe(1 - (b / a) * (b / a));
}

/* The range of the ellipse's offsets (x - o) . k. */
static void ellipse_range(const ellipse *e, const double *o, const double *k, double *lo,
                          double *hi)
{
    double w[3];
    axpy(w, e->c, -1.0, o);
    const double half = hypot(dot3(e->A, k), dot3(e->B, k));
    *lo = dot3(w, k) - half, *hi = dot3(w, k) + half;
}

/* How many knot lines of sheet s the ellipse crosses: a cylinder net's
 * turning knots (the distinct interior ones) and its seam once each (the
 * ellipse winds once about the axis), its profile's knots (parallels at
 * heights affine in the knot: the segment from -half to half) twice when
 * within the ellipse's heights; a plane net's lines twice when they cut
 * the ellipse. */
static int crossings(const conic_case *c, int s, const ellipse *e)
{
    const net_patch *n = &c->s[s].net;
    int count = 0;
    for (int d = 0; d < 2; d++) {
        const double *k = n->knots[d], k0 = k[n->degree[d]], k1 = k[n->count[d]];
        for (int i = n->degree[d] + 1; i < n->count[d]; i++) {
            if (k[i] == k[i - 1] || k[i] <= k0 || k[i] >= k1)
                continue;
            if (!c->s[s].plane && d == 0) {
                count++;
                continue;
            }
            /* the line's points at the knot on two edges of the patch */
            double P[3], Q[3], lo, hi;
            const double f = (k[i] - k0) / (k1 - k0);
            /* the grids' and profiles' segments are affine in their
             * parameter on [0, 1] (elevation and insertion keep the
             * curve): the line is the corners' blend */
            double c00[3], c10[3], c01[3];
            const int n0 = n->count[0], n1 = n->count[1];
            memcpy(c00, n->points, sizeof c00);
            memcpy(c10, n->points + 3 * (n0 - 1) * n1, sizeof c10);
            memcpy(c01, n->points + 3 * (n1 - 1), sizeof c01);
            if (c->s[s].plane) {
                const double *far = d == 0 ? c10 : c01, *side = d == 0 ? c01 : c10;
                for (int j = 0; j < 3; j++)
                    P[j] = c00[j] + f * (far[j] - c00[j]), Q[j] = P[j] + side[j] - c00[j];
                double along[3], nrm[3];
                axpy(along, Q, -1.0, P);
                net_cross(nrm, c->s[s].a, along);
                net_unit(nrm);
                ellipse_range(e, P, nrm, &lo, &hi);
                count += 2 * (lo < 0 && hi > 0);
            } else { /* a parallel of the cylinder at its height */
                ellipse_range(e, c->s[s].o, c->s[s].a, &lo, &hi);
                const double h = c->s[s].z0 + f * (c->s[s].z1 - c->s[s].z0);
                count += 2 * (lo < h && hi > h);
            }
        }
    }
    return count + !c->s[s].plane; /* the seam */
}

/* Whether x is one of the net's interior knots along d, or (periodic) the
 * domain's ends, plus whole periods (the sum as computed: 0.4 + 1 is not
 * 1.4 - 1). */
static int on_knot(const net_patch *n, int d, double x)
{
    const double *k = n->knots[d], d0 = k[n->degree[d]], d1 = k[n->count[d]];
    const double period = n->periodic[d] ? d1 - d0 : 0;
    for (int i = n->degree[d]; i <= n->count[d]; i++) {
        const int interior = i > n->degree[d] && i < n->count[d];
        if (!interior && !period)
            continue;
        const double r = period ? round((x - k[i]) / period) : 0;
        if (x == k[i] + r * period)
            return 1;
    }
    return 0;
}

/* Every step's arc length against its chord (the knot-line points' s
 * come from their own quadrature): the worst excess over the bounds. */
static double arc_excess(const ellipse *e, const ic_trace_curve *cv)
{
    const double a = fmax(norm3(e->A), norm3(e->B)), b = fmin(norm3(e->A), norm3(e->B));
    const double kmax = a / (b * b);
    double worst = 0;
    for (int p = 0; p + 1 < cv->npoints; p++) {
        const double ds = cv->points[p + 1].s - cv->points[p].s;
        const double chord = dist3(cv->points[p + 1].xyz, cv->points[p].xyz);
        worst = fmax(worst, fmax(chord - ds, ds - chord - kmax * kmax * ds * ds * ds / 24));
    }
    return worst;
}

/* The points of curve cv (ellipse i) against the closed forms: on the
 * ellipse, on both exact surfaces, each net at the point's parameters; a
 * point on every knot line crossed, exactly on it; the arc lengths. */
static void check_points(traced *t, const conic_case *c, const ic_trace_curve *cv, int i)
{
    double off = 0, on = 0;
    int flagged[2] = {0, 0}, exact_on[2] = {1, 1}, continued = 1;
    for (int p = 0; p < cv->npoints; p++) {
        const ic_trace_point *pt = &cv->points[p];
        off = fmax(off, off_ellipse(&c->ell[i], pt->xyz));
        for (int s = 0; s < 2; s++) {
            double x[3];
            ic_error err;
            off = fmax(off, off_sheet(&c->s[s], pt->xyz));
            on = ic_surface_eval(t->S[s], x, pt->params[s], &err) == IC_OK
                     ? fmax(on, dist3(x, pt->xyz))
                     : INFINITY;
            for (int d = 0; p > 0 && d < 2; d++) { /* no jump of a period between points */
                const net_patch *n = &c->s[s].net;
                const double width = n->knots[d][n->count[d]] - n->knots[d][n->degree[d]];
                continued &= fabs(pt->params[s][d] - pt[-1].params[s][d]) < STEP_PARAM * width;
            }
            if (p + 1 == cv->npoints && pt->knot_line != cv->points[0].knot_line)
                exact_on[s] = 0; /* the last point is the first again */
            if (p + 1 == cv->npoints && (pt->knot_line & (1 << s)))
                exact_on[s] &= on_knot(&c->s[s].net, 0, pt->params[s][0]) ||
                               on_knot(&c->s[s].net, 1, pt->params[s][1]);
            if (p + 1 < cv->npoints && (pt->knot_line & (1 << s))) { /* the last: the first */
                flagged[s]++;
                exact_on[s] &= on_knot(&c->s[s].net, 0, pt->params[s][0]) ||
                               on_knot(&c->s[s].net, 1, pt->params[s][1]);
            }
        }
    }
    CHECK(off <= EXACT_REL * t->L, "%s: ellipse %d: the points %.3g L off it or a surface", c->name,
          i, off / t->L);
    CHECK(continued, "%s: ellipse %d: the parameters run on from point to point", c->name, i);
    const double excess = arc_excess(&c->ell[i], cv);
    CHECK(excess <= ARC_ROUNDING * t->L,
          "%s: ellipse %d: a step's s %.3g L beyond its chord's bounds", c->name, i, excess / t->L);
    CHECK(on <= ON_NET_REL * t->L, "%s: ellipse %d: the nets at the points' parameters %.3g L off",
          c->name, i, on / t->L);
    for (int s = 0; s < 2; s++) {
        const int want = crossings(c, s, &c->ell[i]);
        CHECK(flagged[s] == want && exact_on[s],
              "%s: ellipse %d: %d points on net %d's knot lines (want %d), exactly on: %d", c->name,
              i, flagged[s], s, want, exact_on[s]);
    }
}

static void check_exact(traced *t, const conic_case *c)
{
    const ic_trace_result *r = t->res[1];
    const ic_trace_report *rep = ic_trace_result_report(r);
    CHECK(rep->tracer_complete && strcmp(rep->method, NETS) == 0, "%s: complete %d, %s", c->name,
          rep->tracer_complete, rep->method);
    const int nc = ic_trace_result_num_curves(r), ns = ic_trace_result_num_specials(r);
    if (!REQUIRE(nc == c->nell && ns == c->nbranch, "%s: %d curves, %d points; want %d, %d",
                 c->name, nc, ns, c->nell, c->nbranch))
        return;
    int seen = 0;
    for (int k = 0; k < nc; k++) {
        const ic_trace_curve *cv = ic_trace_result_curve(r, k);
        const int i = which_ellipse(c, cv, EXACT_REL * t->L);
        if (!REQUIRE(i >= 0, "%s: curve %d on an ellipse of the closed forms", c->name, k))
            continue;
        seen |= 1 << i;
        check_points(t, c, cv, i);
        CHECK(cv->closed && fabs(cv->length - ellipse_length(&c->ell[i])) <= EXACT_REL * t->L,
              "%s: ellipse %d: closed %d, length %.17g, 4 a E(m) %.17g", c->name, i, cv->closed,
              cv->length, ellipse_length(&c->ell[i]));
    }
    CHECK(seen == (1 << c->nell) - 1, "%s: every ellipse traced (%d)", c->name, seen);
    for (int j = 0; j < ns; j++) {
        const ic_trace_special *sp = ic_trace_result_special(r, j);
        double best = INFINITY;
        for (int b = 0; b < c->nbranch; b++)
            best = fmin(best, dist3(sp->xyz, c->branch[b]));
        int passed = 0; /* the curves' points at it: the point itself */
        for (int k = 0; k < nc; k++) {
            const ic_trace_curve *cv = ic_trace_result_curve(r, k);
            for (int p = 0; p + 1 < cv->npoints; p++)
                passed += memcmp(cv->points[p].xyz, sp->xyz, sizeof sp->xyz) == 0;
        }
        CHECK(sp->type == IC_POINT_BRANCH && sp->nbranches == 2 && !sp->approximate &&
                  best <= EXACT_REL * t->L && passed == 2,
              "%s: branch point %d: %s, %d branches, %.3g L off, on %d curves' points", c->name, j,
              ic_point_type_name(sp->type), sp->nbranches, best / t->L, passed);
    }
}

/* The B-spline fits within the tolerance, every net's pcurve kept, on
 * each net on as many curves as the general path's fit keeps (on one of
 * the cone nets here both drop it: the fit's check between nodes, not
 * this path's points) */
static void check_fit(traced *t, const conic_case *c)
{
    ic_error err;
    if (!REQUIRE(ic_trace_fit(t->res[1], t->pair, IC_TRACE_FIT_TOL_DEFAULT, &err) == IC_OK &&
                     ic_trace_fit(t->res[0], t->pair, IC_TRACE_FIT_TOL_DEFAULT, &err) == IC_OK,
                 "%s: fitted: %s", c->name, err.message))
        return;
    const ic_trace_report *rep = ic_trace_result_report(t->res[1]);
    int dropped[2][2] = {{0, 0}, {0, 0}}; /* [general, exact][net] */
    for (int x = 0; x < 2; x++)
        for (int k = 0; k < ic_trace_result_num_curves(t->res[x]); k++) {
            const ic_curve_fit *f = ic_trace_result_fit(t->res[x], k);
            if (!REQUIRE(f, "%s: curve %d fitted", c->name, k))
                continue;
            for (int s = 0; s < 2; s++)
                dropped[x][s] += f->pcurves[s].ncontrol == 0 || f->pcurve_dropped[s];
            if (x == 1)
                CHECK(f->fit_error <= rep->fit_tol, "%s: curve %d: fit error %.3g, tolerance %.3g",
                      c->name, k, f->fit_error, rep->fit_tol);
        }
    for (int s = 0; s < 2; s++)
        CHECK(dropped[1][s] <= dropped[0][s],
              "%s: net %d's pcurve dropped on %d curves, by the general path's fit on %d", c->name,
              s, dropped[1][s], dropped[0][s]);
}

/* The general path finds the same: complete, the same curves on the
 * derived ellipses, closed, the same lengths to its accuracy, the same
 * branch points. */
static void check_against_general(traced *t, const conic_case *c)
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
            if (which_ellipse(c, ic_trace_result_curve(x, m), EXACT_REL * t->L) == i)
                xc = ic_trace_result_curve(x, m);
        if (!REQUIRE(xc, "%s: the general path's curve %d is a derived ellipse", c->name, k))
            continue;
        CHECK(gc->closed == xc->closed && gc->shape == xc->shape &&
                  fabs(gc->length - xc->length) <= GENERAL_LENGTH * xc->length,
              "%s: ellipse %d: closed %d/%d, shape %s/%s, lengths %.17g (general), %.17g (exact)",
              c->name, i, gc->closed, xc->closed, ic_shape_name(gc->shape),
              ic_shape_name(xc->shape), gc->length, xc->length);
    }
    for (int k = 0; k < ic_trace_result_num_specials(g); k++) {
        const ic_trace_special *a = ic_trace_result_special(g, k);
        int matched = 0;
        for (int m = 0; m < ic_trace_result_num_specials(x); m++) {
            const ic_trace_special *b = ic_trace_result_special(x, m);
            matched |= dist3(a->xyz, b->xyz) <= GENERAL_ON_EXACT * t->L && a->type == b->type &&
                       a->nbranches == b->nbranches && a->approximate == b->approximate;
        }
        CHECK(matched, "%s: the general path's point %d (%s, %d branches) is an exact one", c->name,
              k, ic_point_type_name(a->type), a->nbranches);
    }
}

static void run_case(const conic_case *c)
{
    traced t;
    if (trace_case(&t, c)) {
        check_exact(&t, c);
        check_against_general(&t, c);
        check_fit(&t, c);
    }
    release(&t);
}

/* ---- the cases ---- */

static const char *const VARIANT[3] = {"plain", "elevated", "knots inserted"};

/* Steinmetz's pair at random places and crossing angles (between 0.5 and
 * pi/2), its cylinders long enough for the ellipses. */
static void steinmetz_cases(harness_rng *g)
{
    for (int v = 0; v < 3; v++) {
        conic_case c;
        double o[3], a[3], b[3], x[3];
        for (int k = 0; k < 3; k++)
            o[k] = harness_uniform(g, -1, 1);
        random_unit(g, a);
        random_unit(g, x);
        net_cross(b, a, x); /* normal to a, then turned towards it */
        net_unit(b);
        const double gamma = harness_uniform(g, 0.5, 0.5 * NET_PI), r = harness_uniform(g, 0.5, 2);
        for (int k = 0; k < 3; k++)
            b[k] = sin(gamma) * b[k] + cos(gamma) * a[k];
        /* the ellipses reach r / tan(gamma / 2) along each axis at most */
        steinmetz(&c, o, a, b, r, 1.5 * r / tan(0.5 * gamma), v, g);
        snprintf(c.name, sizeof c.name, "Steinmetz nets (%s), crossing at %.3f", VARIANT[v], gamma);
        run_case(&c);
    }
}

/* A plane net oblique to a cylinder net, at random places and tilts. */
static void plane_cylinder_cases(harness_rng *g)
{
    for (int v = 0; v < 3; v++) {
        conic_case c;
        double o[3], a[3], n[3], q[3];
        for (int k = 0; k < 3; k++)
            o[k] = harness_uniform(g, -1, 1);
        random_unit(g, a);
        do
            random_unit(g, n);
        while (fabs(dot3(a, n)) < 0.5 || fabs(dot3(a, n)) > 0.95);
        const double r = harness_uniform(g, 0.5, 2);
        axpy(q, o, harness_uniform(g, -r, r), a);
        plane_cylinder(&c, q, n, o, a, r, v);
        snprintf(c.name, sizeof c.name, "plane net on a cylinder net (%s), cos %.3f", VARIANT[v],
                 dot3(a, n));
        run_case(&c);
    }
}

/* A plane net oblique to a cone net, at random places. */
static void plane_cone_cases(harness_rng *g)
{
    for (int v = 0; v < 3; v++) {
        conic_case c;
        net_place pl = net_random_place(g);
        pl.s = 1;
        const double t = harness_uniform(g, 0.3, 1), m = harness_uniform(g, -0.6, 0.6) / t;
        plane_cone(&c, &pl, t, 1.5, m, 0.3, 6, v);
        snprintf(c.name, sizeof c.name, "plane net on a cone net (%s), m t %.3f", VARIANT[v],
                 m * t);
        run_case(&c);
    }
}

static void fall_back(const conic_case *c)
{
    traced t;
    if (trace_case(&t, c))
        CHECK(same_results(t.res[0], t.res[1]),
              "%s: left to the general path, exactly what it gives (%d curves; method %s)", c->name,
              ic_trace_result_num_curves(t.res[1]), ic_trace_result_report(t.res[1])->method);
    release(&t);
}

/* Patches whose edges cut the ellipses: Steinmetz's cylinders at right
 * angles, half-length 0.8 (the ellipses reach 1 along each axis); a plane
 * net of half-width 0.4 about the centre of an ellipse of semi-axes 1 and
 * more. */
static void edges_cut(void)
{
    conic_case c;
    harness_rng g = {7};
    const double o[3] = {0, 0, 0}, x[3] = {1, 0, 0}, y[3] = {0, 1, 0};
    steinmetz(&c, o, x, y, 1, 0.8, 0, &g);
    snprintf(c.name, sizeof c.name, "Steinmetz nets cut by their edges");
    fall_back(&c);
    const double a[3] = {0, 0, 1};
    double n[3] = {0.3, -0.4, 1};
    net_unit(n);
    plane_cylinder(&c, o, n, o, a, 1, 0);
    plane_sheet(&c.s[0], c.ell[0].c, n, 0.4, 0);
    snprintf(c.name, sizeof c.name, "a plane net cut by the cylinder net's ellipse");
    fall_back(&c);
}

/* The peers benchmark's case: unit cylinders about x and y, half-length
 * 1.5; the ellipses 4 sqrt(2) E(1/2) long (mpmath, as in
 * test_exact_conics), the branch points (0, 0, +-1). */
static void bench_case(void)
{
    conic_case c;
    harness_rng g = {11};
    const double o[3] = {0, 0, 0}, x[3] = {1, 0, 0}, y[3] = {0, 1, 0};
    steinmetz(&c, o, x, y, 1, 1.5, 0, &g);
    /* the seams along z, as the benchmark's: the branch point (0, 0, 1),
     * where the ellipses start, on both seams, (0, 0, -1) on the meridians
     * at pi */
    const net_place px = {{0, 0, 0}, 1, {{0, 0, 1}, {0, -1, 0}, {1, 0, 0}}};
    const net_place py = {{0, 0, 0}, 1, {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}}};
    cylinder_at(&c.s[0], &px, 1, 1.5, 0);
    cylinder_at(&c.s[1], &py, 1, 1.5, 0);
    snprintf(c.name, sizeof c.name, "Steinmetz nets of the peers benchmark");
    run_case(&c);
    CHECK_CLOSE(ellipse_length(&c.ell[0]), 7.64039557805542403581, AGM_LENGTH,
                "4 sqrt(2) E(1/2): the closed form derived here");
}

/* A plane net beside a cylinder net's ellipse (its plane cuts the
 * cylinder, the patch lies 20 radii away along it): nothing, found by the
 * conic path (the ellipse proven off the patch), as by the general path. */
static void off_patch(void)
{
    conic_case c;
    const double o[3] = {0.1, -0.2, 0.3}, a[3] = {0, 0, 1};
    double n[3] = {0.3, -0.4, 1}, q[3];
    net_unit(n);
    plane_cylinder(&c, o, n, o, a, 1, 0);
    axpy(q, c.ell[0].c, 20, c.ell[0].A);
    plane_sheet(&c.s[0], q, n, 6, 0);
    snprintf(c.name, sizeof c.name, "plane net beside a cylinder net's ellipse");
    traced t;
    if (trace_case(&t, &c)) {
        const ic_trace_report *rep = ic_trace_result_report(t.res[1]);
        CHECK(rep->tracer_complete && strcmp(rep->method, NETS) == 0 &&
                  ic_trace_result_num_curves(t.res[1]) == 0 &&
                  ic_trace_result_num_specials(t.res[1]) == 0 &&
                  ic_trace_result_num_curves(t.res[0]) == 0 &&
                  ic_trace_result_num_specials(t.res[0]) == 0,
              "%s: %s, %d curves (the general path %d)", c.name, rep->method,
              ic_trace_result_num_curves(t.res[1]), ic_trace_result_num_curves(t.res[0]));
    }
    release(&t);
}

int main(void)
{
    harness_rng g = {20261130};
    bench_case();
    steinmetz_cases(&g);
    plane_cylinder_cases(&g);
    plane_cone_cases(&g);
    edges_cut();
    off_patch();
    return harness_finish("test_nurbs_conics");
}
