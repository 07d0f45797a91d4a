/* Exact paths (docs/tracing.md, "Exact paths"): coaxial surfaces of
 * revolution traced in closed form, checked against closed forms written
 * here family by family (radius, height, kappa, tau, length) and against the
 * general path (exact_paths = 0), the reference: the same curves and points
 * found, of the same types and shapes, the same lengths. Random placements
 * (a fixed seed) and the three exact cases of the issue; then the cases left
 * to the general path (nearly coaxial, nearly tangent, coincident, a cone's
 * apex on the other surface, a circle the box cuts) must give exactly what
 * the general path gives. */
#include <math.h>
#include <string.h>

#include "exact_pair.h"
#include "harness.h"
#include "intercurve.h"

#define PI 3.14159265358979323846

/* relative: the closed-form path's radius, height and (relative to the
 * problem's size L) point positions against the closed forms here: a few
 * roundings of O(L) coordinates (the brief's 1e-14) */
#define EXACT_REL 1e-14
/* relative: its points on both surfaces, |f| / |grad f| over L: the torus'
 * quartic cancels about L^4 eps into a distance of L^3 eps / |grad f| */
#define EXACT_ON_SURFACE 1e-13
/* relative: the general path's lengths against the closed form's (the
 * brief's 1e-12: its truncation error per step is 1e-11 L at most, and of
 * alternating sign on a circle) */
#define GENERAL_LENGTH 1e-12
/* relative to L: the general path's points and contact points from the
 * exact circles and points (it locates them to about 1e-12 L) */
#define GENERAL_ON_EXACT 1e-9

static const char CLOSED_FORM[] = "closed form: coaxial surfaces of revolution";

/* The common axis: through o along the unit e, u normal to it. */
typedef struct {
    double o[3], e[3], u[3];
} axis;

static void random_axis(harness_rng *g, axis *ax)
{
    double n = 0;
    for (int k = 0; k < 3; k++) {
        ax->o[k] = harness_uniform(g, -0.3, 0.3);
        ax->e[k] = harness_uniform(g, -1, 1);
        n += ax->e[k] * ax->e[k];
    }
    n = sqrt(n);
    for (int k = 0; k < 3; k++)
        ax->e[k] /= n;
    /* u: e x (the coordinate axis least aligned with e) */
    int m = 0;
    for (int k = 1; k < 3; k++)
        if (fabs(ax->e[k]) < fabs(ax->e[m]))
            m = k;
    double x[3] = {0, 0, 0};
    x[m] = 1;
    ax->u[0] = ax->e[1] * x[2] - ax->e[2] * x[1];
    ax->u[1] = ax->e[2] * x[0] - ax->e[0] * x[2];
    ax->u[2] = ax->e[0] * x[1] - ax->e[1] * x[0];
}

static const axis Z_AXIS = {{0, 0, 0}, {0, 0, 1}, {1, 0, 0}};

/* A primitive of the kind about the axis, its centre (a cone's apex) at
 * height z. */
static ic_primitive about(ic_primitive_kind kind, const axis *ax, double z)
{
    ic_primitive p;
    memset(&p, 0, sizeof p);
    p.kind = kind;
    for (int k = 0; k < 3; k++) {
        p.center[k] = ax->o[k] + z * ax->e[k];
        p.ref_direction[k] = ax->u[k];
        if (kind == IC_PRIM_PLANE)
            p.normal[k] = ax->e[k];
        else
            p.axis[k] = ax->e[k];
    }
    return p;
}

#define MAX_PIECES 4

/* A case: two primitives, the box [-half, half]^3, and what the closed
 * forms say: circles (rho, z; tangential or not) and contact points (z). */
typedef struct {
    char name[64];
    axis ax;
    ic_primitive prim[2];
    double half;
    int ncircles, ncontacts;
    double rho[MAX_PIECES], z[MAX_PIECES];
    int tangential[MAX_PIECES];
    double contact_z[MAX_PIECES];
} exact_case;

static void add_circle(exact_case *c, double rho, double z, int tangential)
{
    c->rho[c->ncircles] = rho, c->z[c->ncircles] = z;
    c->tangential[c->ncircles++] = tangential;
}

/* ---- traces (exact_pair.h) ---- */

static int trace_both(traced_pair *t, const exact_case *c)
{
    return trace_pair_both(t, &c->prim[0], &c->prim[1], c->half, c->name);
}

/* ---- geometry about the axis ---- */

static double dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* rho and z of x about the axis, and the unit radial direction. */
static void cylindrical(const axis *ax, const double *x, double *rho, double *z, double *radial)
{
    double w[3];
    for (int k = 0; k < 3; k++)
        w[k] = x[k] - ax->o[k];
    *z = dot3(w, ax->e);
    for (int k = 0; k < 3; k++)
        radial[k] = w[k] - *z * ax->e[k];
    *rho = sqrt(dot3(radial, radial));
    for (int k = 0; k < 3; k++)
        radial[k] /= *rho > 0 ? *rho : 1;
}

/* The largest |f| / |grad f| of the curve's points on either surface. */
static double off_surfaces(traced_pair *t, const ic_trace_curve *c)
{
    double worst = 0;
    for (int k = 0; k < c->npoints; k++)
        for (int s = 0; s < 2; s++) {
            ic_surface_geometry g;
            if (ic_surface_geometry_at(t->S[s], &g, c->points[k].xyz, NULL) != IC_OK)
                return INFINITY;
            worst = fmax(worst, fabs(g.value) / g.normal_length);
        }
    return worst;
}

/* The expected circle the curve is (nearest in rho and z), or -1. */
static int which_circle(const exact_case *c, const ic_trace_curve *cv, double L)
{
    double rho, z, radial[3];
    cylindrical(&c->ax, cv->points[0].xyz, &rho, &z, radial);
    for (int i = 0; i < c->ncircles; i++)
        if (fabs(rho - c->rho[i]) <= GENERAL_ON_EXACT * L && fabs(z - c->z[i]) <= GENERAL_ON_EXACT * L)
            return i;
    return -1;
}

/* Every point of an exact circle: its place, its apparatus. */
static int exact_points_ok(const exact_case *c, const ic_trace_curve *cv, int i, double L)
{
    const double rho = c->rho[i];
    for (int k = 0; k < cv->npoints; k++) {
        const ic_trace_point *p = &cv->points[k];
        double r, z, radial[3];
        cylindrical(&c->ax, p->xyz, &r, &z, radial);
        int ok = fabs(r - rho) <= EXACT_REL * L && fabs(z - c->z[i]) <= EXACT_REL * L &&
                 fabs(p->kappa * rho - 1) <= EXACT_REL && p->tau == 0 && p->frame_defined &&
                 (c->tangential[i] ? p->angle == 0 : p->angle > 0);
        /* n towards the axis, b along it, t about it */
        for (int m = 0; m < 3; m++)
            ok = ok && fabs(p->n[m] + radial[m]) <= EXACT_REL &&
                 fabs(fabs(dot3(p->b, c->ax.e)) - 1) <= EXACT_REL &&
                 fabs(dot3(p->t, radial)) <= EXACT_REL && fabs(dot3(p->t, c->ax.e)) <= EXACT_REL;
        /* in order along t: the chord from the last point is the arc's by s */
        if (k > 0) {
            const ic_trace_point *q = &cv->points[k - 1];
            const double d[3] = {p->xyz[0] - q->xyz[0], p->xyz[1] - q->xyz[1], p->xyz[2] - q->xyz[2]};
            const double ds = p->s - q->s;
            ok = ok && ds > 0 && dot3(d, p->t) > 0 &&
                 fabs(sqrt(dot3(d, d)) - 2 * rho * sin(ds / (2 * rho))) <= EXACT_REL * L;
        }
        if (!ok)
            return 0;
    }
    return 1;
}

/* The closed-form path against the closed forms of the case. */
static void check_exact(traced_pair *t, const exact_case *c)
{
    const ic_trace_result *r = t->res[1];
    const ic_trace_report *rep = ic_trace_result_report(r);
    CHECK(rep->tracer_complete && rep->method && strcmp(rep->method, CLOSED_FORM) == 0,
          "%s: complete %d, in closed form (%s)", c->name, rep->tracer_complete,
          rep->method ? rep->method : "null");
    const int nc = ic_trace_result_num_curves(r);
    CHECK(nc == c->ncircles && ic_trace_result_num_specials(r) == c->ncontacts,
          "%s: %d circles, %d points; the closed forms: %d, %d", c->name, nc,
          ic_trace_result_num_specials(r), c->ncircles, c->ncontacts);
    int seen = 0;
    for (int k = 0; k < nc; k++) {
        const ic_trace_curve *cv = ic_trace_result_curve(r, k);
        const int i = which_circle(c, cv, t->L);
        if (!REQUIRE(i >= 0 && !(seen & (1 << i)), "%s: curve %d is one circle of the closed forms",
                     c->name, k))
            continue;
        seen |= 1 << i;
        CHECK(cv->closed && cv->ends[0] == IC_TRACE_CLOSED && cv->ends[1] == IC_TRACE_CLOSED &&
                  cv->tangential == c->tangential[i] && cv->shape == IC_SHAPE_CIRCLE,
              "%s: circle %d closed, tangential %d (want %d), a circle (%s)", c->name, i,
              cv->tangential, c->tangential[i], ic_shape_name(cv->shape));
        CHECK(fabs(cv->length - 2 * PI * c->rho[i]) <= EXACT_REL * 2 * PI * c->rho[i],
              "%s: circle %d length %.17g, 2 pi rho = %.17g", c->name, i, cv->length,
              2 * PI * c->rho[i]);
        CHECK(exact_points_ok(c, cv, i, t->L), "%s: circle %d: rho %.17g, z %.17g, kappa 1/rho, in order, "
              "tau 0, n to the axis, b along it at every point", c->name, i, c->rho[i], c->z[i]);
        const double off = off_surfaces(t, cv);
        CHECK(off <= EXACT_ON_SURFACE * t->L, "%s: circle %d on both surfaces: %.3g", c->name, i,
              off);
    }
    for (int k = 0; k < ic_trace_result_num_specials(r) && k < c->ncontacts; k++) {
        const ic_trace_special *sp = ic_trace_result_special(r, k);
        double rho, z, radial[3];
        cylindrical(&c->ax, sp->xyz, &rho, &z, radial);
        CHECK(sp->type == IC_POINT_ISOLATED_CONTACT && !sp->approximate && rho <= EXACT_REL * t->L &&
                  fabs(z - c->contact_z[k]) <= EXACT_REL * t->L,
              "%s: an isolated contact on the axis at z = %.17g: %s at rho %.3g, z %.17g", c->name,
              c->contact_z[k], ic_point_type_name(sp->type), rho, z);
    }
}

/* The general path (the reference) finds the same: complete, the same
 * circles (its points on them), types and shapes, lengths within
 * GENERAL_LENGTH, the same contact points. */
static void check_against_general(traced_pair *t, const exact_case *c)
{
    const ic_trace_result *g = t->res[0], *x = t->res[1];
    const ic_trace_report *rep = ic_trace_result_report(g);
    CHECK(rep->tracer_complete && strcmp(rep->method, "search") == 0,
          "%s: the general path is complete (%d) and searched", c->name, rep->tracer_complete);
    const int n = ic_trace_result_num_curves(g);
    CHECK(n == ic_trace_result_num_curves(x) && ic_trace_result_num_specials(g) ==
                                                    ic_trace_result_num_specials(x),
          "%s: the general path's %d curves and %d points, the exact path's %d and %d", c->name, n,
          ic_trace_result_num_specials(g), ic_trace_result_num_curves(x),
          ic_trace_result_num_specials(x));
    for (int k = 0; k < n; k++) {
        const ic_trace_curve *gc = ic_trace_result_curve(g, k);
        const int i = which_circle(c, gc, t->L);
        const ic_trace_curve *xc = NULL;
        for (int m = 0; m < ic_trace_result_num_curves(x) && i >= 0; m++)
            if (which_circle(c, ic_trace_result_curve(x, m), t->L) == i)
                xc = ic_trace_result_curve(x, m);
        if (!REQUIRE(xc, "%s: the general path's curve %d is an exact circle", c->name, k))
            continue;
        int on = 1;
        for (int p = 0; p < gc->npoints; p++) {
            double rho, z, radial[3];
            cylindrical(&c->ax, gc->points[p].xyz, &rho, &z, radial);
            on = on && fabs(rho - c->rho[i]) <= GENERAL_ON_EXACT * t->L &&
                 fabs(z - c->z[i]) <= GENERAL_ON_EXACT * t->L;
        }
        CHECK(on && gc->closed == xc->closed && gc->tangential == xc->tangential &&
                  gc->shape == xc->shape,
              "%s: circle %d: the general path's points on it, closed %d/%d, tangential %d/%d, "
              "shape %s/%s", c->name, i, gc->closed, xc->closed, gc->tangential, xc->tangential,
              ic_shape_name(gc->shape), ic_shape_name(xc->shape));
        CHECK(fabs(gc->length - xc->length) <= GENERAL_LENGTH * xc->length,
              "%s: circle %d: lengths %.17g (general), %.17g (exact)", c->name, i, gc->length,
              xc->length);
    }
    for (int k = 0; k < ic_trace_result_num_specials(g) && k < ic_trace_result_num_specials(x);
         k++) {
        const ic_trace_special *a = ic_trace_result_special(g, k), *b = ic_trace_result_special(x, k);
        double d2 = 0;
        for (int m = 0; m < 3; m++)
            d2 += (a->xyz[m] - b->xyz[m]) * (a->xyz[m] - b->xyz[m]);
        CHECK(a->type == b->type && a->nbranches == b->nbranches &&
                  a->approximate == b->approximate && sqrt(d2) <= GENERAL_ON_EXACT * t->L,
              "%s: point %d: %s (general), %s (exact), %.3g apart", c->name, k,
              ic_point_type_name(a->type), ic_point_type_name(b->type), sqrt(d2));
    }
}

static void run_case(const exact_case *c)
{
    traced_pair t;
    if (trace_both(&t, c)) {
        check_exact(&t, c);
        check_against_general(&t, c);
    }
    release_pair(&t);
}

/* ---- the three exact cases of the issue ---- */

static void exact_cases(void)
{
    exact_case c;
    memset(&c, 0, sizeof c);
    snprintf(c.name, sizeof c.name, "sphere r = 1, plane z = 1/2");
    c.ax = Z_AXIS, c.half = 2;
    c.prim[0] = about(IC_PRIM_SPHERE, &c.ax, 0), c.prim[0].radius = 1;
    c.prim[1] = about(IC_PRIM_PLANE, &c.ax, 0.5);
    add_circle(&c, sqrt(3.0) / 2, 0.5, 0);
    run_case(&c);

    memset(&c, 0, sizeof c);
    snprintf(c.name, sizeof c.name, "torus R = 2, r = 1/2, sphere r = 5/2");
    c.ax = Z_AXIS, c.half = 3;
    c.prim[0] = about(IC_PRIM_TORUS, &c.ax, 0), c.prim[0].major_radius = 2,
    c.prim[0].radius = 0.5;
    c.prim[1] = about(IC_PRIM_SPHERE, &c.ax, 0), c.prim[1].radius = 2.5;
    add_circle(&c, 2.5, 0, 1);
    run_case(&c);

    memset(&c, 0, sizeof c);
    snprintf(c.name, sizeof c.name, "sphere r = 1 at (0, 0, 1), plane z = 0");
    c.ax = Z_AXIS, c.half = 2;
    c.prim[0] = about(IC_PRIM_SPHERE, &c.ax, 1), c.prim[0].radius = 1;
    c.prim[1] = about(IC_PRIM_PLANE, &c.ax, 0);
    c.contact_z[c.ncontacts++] = 0;
    run_case(&c);
}

/* ---- random coaxial pairs, family by family ---- */

enum {
    SPHERE_PLANE,
    SPHERE_CYLINDER,
    CYLINDER_PLANE,
    CONE_PLANE,
    TORUS_PLANE,
    TORUS_CYLINDER,
    SPHERE_SPHERE,
    TORUS_SPHERE_TOUCHING,
    NFAMILIES
};

static const char *const FAMILY[NFAMILIES] = {
    "sphere/plane", "sphere/cylinder", "cylinder/plane", "cone/plane",
    "torus/plane", "torus/cylinder", "sphere/sphere", "torus/sphere touching"};

/* A random case of the family, with its closed forms. */
static void random_case(harness_rng *g, int family, int index, exact_case *c)
{
    memset(c, 0, sizeof *c);
    snprintf(c->name, sizeof c->name, "%s %d", FAMILY[family], index);
    random_axis(g, &c->ax);
    c->half = 4;
    const axis *ax = &c->ax;
    const double t = harness_uniform(g, -0.5, 0.5);
    switch (family) {
    case SPHERE_PLANE: { /* z = h, rho^2 + (h - t)^2 = R^2 */
        const double R = harness_uniform(g, 0.6, 1.5), h = t + R * harness_uniform(g, -0.8, 0.8);
        c->prim[0] = about(IC_PRIM_SPHERE, ax, t), c->prim[0].radius = R;
        c->prim[1] = about(IC_PRIM_PLANE, ax, h);
        add_circle(c, sqrt(R * R - (h - t) * (h - t)), h, 0);
        break;
    }
    case SPHERE_CYLINDER: { /* rho = r, z = t +- sqrt(R^2 - r^2) */
        const double R = harness_uniform(g, 0.6, 1.5), r = R * harness_uniform(g, 0.2, 0.9);
        c->prim[0] = about(IC_PRIM_SPHERE, ax, t), c->prim[0].radius = R;
        c->prim[1] = about(IC_PRIM_CYLINDER, ax, harness_uniform(g, -1, 1)), c->prim[1].radius = r;
        add_circle(c, r, t - sqrt(R * R - r * r), 0);
        add_circle(c, r, t + sqrt(R * R - r * r), 0);
        break;
    }
    case CYLINDER_PLANE: {
        const double r = harness_uniform(g, 0.3, 2), h = harness_uniform(g, -1.5, 1.5);
        c->prim[0] = about(IC_PRIM_CYLINDER, ax, t), c->prim[0].radius = r;
        c->prim[1] = about(IC_PRIM_PLANE, ax, h);
        add_circle(c, r, h, 0);
        break;
    }
    case CONE_PLANE: { /* rho = |h - a| tan(alpha) */
        const double alpha = harness_uniform(g, 0.3, 1.0), d = harness_uniform(g, 0.3, 1.2);
        const double h = t + (index % 2 ? d : -d);
        c->prim[0] = about(IC_PRIM_CONE, ax, t), c->prim[0].half_angle = alpha;
        c->prim[1] = about(IC_PRIM_PLANE, ax, h);
        add_circle(c, d * tan(alpha), h, 0);
        break;
    }
    case TORUS_PLANE: { /* z = h, (rho - R)^2 + (h - t)^2 = r^2 */
        const double R = harness_uniform(g, 1, 1.5), r = harness_uniform(g, 0.2, 0.5), h = t + r * harness_uniform(g, -0.8, 0.8);
        const double w = sqrt(r * r - (h - t) * (h - t));
        c->prim[0] = about(IC_PRIM_TORUS, ax, t), c->prim[0].major_radius = R,
        c->prim[0].radius = r;
        c->prim[1] = about(IC_PRIM_PLANE, ax, h);
        add_circle(c, R - w, h, 0);
        add_circle(c, R + w, h, 0);
        break;
    }
    case TORUS_CYLINDER: { /* rho = rc, (rc - R)^2 + (z - t)^2 = r^2 */
        const double R = harness_uniform(g, 1, 1.5), r = harness_uniform(g, 0.2, 0.5), rc = R + r * harness_uniform(g, -0.8, 0.8);
        const double w = sqrt(r * r - (rc - R) * (rc - R));
        c->prim[0] = about(IC_PRIM_TORUS, ax, t), c->prim[0].major_radius = R,
        c->prim[0].radius = r;
        c->prim[1] = about(IC_PRIM_CYLINDER, ax, harness_uniform(g, -1, 1)), c->prim[1].radius = rc;
        add_circle(c, rc, t - w, 0);
        add_circle(c, rc, t + w, 0);
        break;
    }
    case SPHERE_SPHERE: { /* the radical plane z - t = (d^2 + R1^2 - R2^2) / (2 d) */
        const double R1 = harness_uniform(g, 0.6, 1.5), R2 = harness_uniform(g, 0.6, 1.5);
        const double lo = fabs(R1 - R2), hi = R1 + R2, d = lo + (hi - lo) * harness_uniform(g, 0.15, 0.85);
        const double a = (d * d + R1 * R1 - R2 * R2) / (2 * d);
        c->prim[0] = about(IC_PRIM_SPHERE, ax, t), c->prim[0].radius = R1;
        c->prim[1] = about(IC_PRIM_SPHERE, ax, t + d), c->prim[1].radius = R2;
        add_circle(c, sqrt(R1 * R1 - a * a), t + a, 0);
        break;
    }
    case TORUS_SPHERE_TOUCHING: { /* the sphere R + r about the torus' centre: its equator */
        const double R = harness_uniform(g, 1, 1.5), r = harness_uniform(g, 0.2, 0.5);
        c->prim[0] = about(IC_PRIM_TORUS, ax, t), c->prim[0].major_radius = R,
        c->prim[0].radius = r;
        c->prim[1] = about(IC_PRIM_SPHERE, ax, t), c->prim[1].radius = R + r;
        add_circle(c, R + r, t, 1);
        break;
    }
    }
}

static void random_cases(int per_family)
{
    harness_rng g = {0x9E3779B97F4A7C15ULL};
    for (int f = 0; f < NFAMILIES; f++)
        for (int i = 0; i < per_family; i++) {
            exact_case c;
            random_case(&g, f, i, &c);
            if (i % 2) { /* either surface first (the first with an axis line sets the axis) */
                const ic_primitive first = c.prim[0];
                c.prim[0] = c.prim[1], c.prim[1] = first;
            }
            run_case(&c);
        }
}

/* ---- the cases left to the general path ---- */

static void fall_back(const char *name, ic_primitive A, ic_primitive B, double half)
{
    check_fall_back(name, &A, &B, half);
}

static void fall_back_cases(void)
{
    const axis *z = &Z_AXIS;
    ic_primitive torus = about(IC_PRIM_TORUS, z, 0), other;
    torus.major_radius = 1, torus.radius = 0.5;
    /* nearly coaxial: the cylinder's axis 1e-9 rad off the torus' */
    other = about(IC_PRIM_CYLINDER, z, 0), other.radius = 0.5, other.axis[0] = 1e-9;
    fall_back("torus and a cylinder nearly coaxial", torus, other, 2);
    /* nearly tangent: the plane 1e-6 above the sphere's pole (1.4e-7 L) */
    ic_primitive sphere = about(IC_PRIM_SPHERE, z, 0);
    sphere.radius = 1;
    fall_back("sphere and a plane nearly touching", sphere, about(IC_PRIM_PLANE, z, 1 + 1e-6), 2);
    /* ... and 1e-6 below it: a circle of radius 1.4e-3 crossed at 1.4e-3 rad */
    fall_back("sphere and a plane nearly touching, crossing", sphere,
              about(IC_PRIM_PLANE, z, 1 - 1e-6), 2);
    /* coincident: the same sphere twice */
    fall_back("the same sphere twice", sphere, sphere, 2);
    /* a cone's apex on the sphere */
    other = about(IC_PRIM_CONE, z, 1), other.half_angle = 0.5;
    fall_back("a cone's apex on the sphere", other, sphere, 2);
    /* the circle of radius sqrt(3)/2 at z = 1/2 cut by the box's faces x, y = +-0.8 */
    fall_back("sphere and plane, the circle cut by the box", sphere, about(IC_PRIM_PLANE, z, 0.5),
              0.8);
}

/* exact_paths = 0: the search, and the report says so. */
static void option_off(void)
{
    exact_case c;
    memset(&c, 0, sizeof c);
    snprintf(c.name, sizeof c.name, "sphere and plane, exact_paths 0");
    c.ax = Z_AXIS, c.half = 2;
    c.prim[0] = about(IC_PRIM_SPHERE, &c.ax, 0), c.prim[0].radius = 1;
    c.prim[1] = about(IC_PRIM_PLANE, &c.ax, 0.5);
    traced_pair t;
    if (trace_both(&t, &c)) {
        const ic_trace_report *rep = ic_trace_result_report(t.res[0]);
        CHECK(strcmp(rep->method, "search") == 0 && rep->cells > 0,
              "exact_paths 0: the search (%s, %d cells)", rep->method, rep->cells);
    }
    release_pair(&t);
}

int main(void)
{
    exact_cases();
    random_cases(3);
    fall_back_cases();
    option_off();
    return harness_finish("test_exact_paths");
}
