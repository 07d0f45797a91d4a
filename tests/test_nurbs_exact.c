/* The exact path on NURBS nets recognised as coaxial surfaces of
 * revolution (docs/tracing.md, "Exact paths"; the nets of
 * tests/nurbs_nets.h at random places): the circles and contact points
 * against the closed forms written here (radius, centre, length, type);
 * every point's parameters on every net against the net (S(u, v) = x), a
 * point on every knot line and seam crossed, exactly on it; the fitted
 * pcurves kept and within the fit tolerance; and against the general path
 * (exact_paths = 0), the reference: the same curves, closed, tangential,
 * of the same shape and length, the same points of the same types. Then
 * the cases left to the general path (a circle at the edge of a patch, a
 * patch too small for its circle, a sphere's net about another axis, a
 * closed patch that does not wrap crossed off its seam) must give exactly
 * what it gives; a circle off a patch is left out. */
#include <string.h>

#include "same_trace.h"
#include "harness.h"
#include "nurbs_nets.h"
#include "trace/exact/exact_source.h"

/* relative to the problem's size L: the exact path's points, centres,
 * contact points and lengths against the closed forms here: a few roundings
 * of O(L) coordinates, the nets' axes read to rounding (measured worst
 * printed at the end) */
#define EXACT_REL 1e-14
/* relative to L: every point's parameters on a net put it back on the
 * point, |S(u, v) - x|: the point's and the patch's roundings and the
 * inversion's four ulps (the exact path itself refuses beyond 1e-12 L) */
#define ON_NET_REL 1e-14
/* relative: the general path's lengths against the exact path's (its
 * truncation error per step is 1e-11 L at most, of alternating sign on a
 * circle: test_exact_paths and test_nurbs_traces hold it to the same) */
#define GENERAL_LENGTH 1e-12
/* relative to L: the general path's points and contact points from the
 * exact circles and points (it locates them to about 1e-12 L) */
#define GENERAL_ON_EXACT 1e-9
/* relative to L: an approximate point of the general path from the exact
 * one: at a net's pole it is the search's start candidate (docs/tracing.md,
 * "The whole intersection", step 4), Newton's on a double root, which stops
 * about sqrt(eps) L = 1.5e-8 L away (measured 1.45e-8 L) */
#define GENERAL_APPROX 1e-7
/* relative to the period: the parameters of one point before and after a
 * full turn, a whole period apart but for the inversion's ulps */
#define TURN_REL 1e-12

static const char NETS[] = "closed form: NURBS nets recognised as coaxial surfaces of revolution";
static double worst_exact, worst_on_net;

enum { MAX_PIECES = 4 };

/* A sheet: a net, or an implicit primitive. */
typedef struct {
    int is_net;
    net_patch net;
    ic_primitive prim;
} sheet;

typedef struct {
    char name[128];
    sheet s[2];
    double axis[3];
    int ncircles, ncontacts;
    double centre[MAX_PIECES][3], rho[MAX_PIECES];
    int tangential[MAX_PIECES];
    double contact[MAX_PIECES][3];
    int general; /* compared with the general path */
} net_case;

/* ---- cases ---- */

static double dist3(const double *a, const double *b)
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                (a[2] - b[2]) * (a[2] - b[2]));
}

static double dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* An implicit primitive about the place's axis, its centre at height z. */
static ic_primitive about(ic_primitive_kind kind, const net_place *pl, double z)
{
    ic_primitive p;
    memset(&p, 0, sizeof p);
    p.kind = kind;
    net_to_space(pl, 0, 0, z, p.center);
    for (int k = 0; k < 3; k++) {
        p.ref_direction[k] = pl->e[0][k];
        if (kind == IC_PRIM_PLANE)
            p.normal[k] = pl->e[2][k];
        else
            p.axis[k] = pl->e[2][k];
    }
    return p;
}

static void add_circle(net_case *c, const net_place *pl, double rho, double z, int tangential)
{
    net_to_space(pl, 0, 0, z, c->centre[c->ncircles]);
    c->rho[c->ncircles] = pl->s * rho;
    c->tangential[c->ncircles++] = tangential;
}

/* circle_variant: 0 the 9-point circle, 1 elevated, 2 a knot inserted at
 * 0.1, 3 the 7-point circle. */
static void sphere_sheet(sheet *s, const net_place *pl, double r, double zc, int circle_variant)
{
    net_curve circle, profile;
    circle9(&circle);
    if (circle_variant == 1)
        curve_elevate(&circle);
    else if (circle_variant == 2)
        curve_insert(&circle, 0.1);
    if (circle_variant == 3)
        circle7(&circle);
    half_circle(&profile, r, zc);
    s->is_net = 1;
    revolve(&s->net, &circle, &profile, pl, 0, 0);
}

/* The plane z = h of the place as a square net of half width w, turned by
 * a about the axis and moved by (dx, dy) in it; `knotted` 1: an interior
 * knot at 0.3 along both parameters (inserted: the map stays linear); 2: a
 * kink at 0.5, the coordinates -w, -w/5, w (the map only C^0 there). */
static void plane_sheet(sheet *s, const net_place *pl, double h, double w, double a, double dx,
                        double dy, int knotted)
{
    net_place q = *pl;
    for (int k = 0; k < 3; k++) {
        q.e[0][k] = cos(a) * pl->e[0][k] + sin(a) * pl->e[1][k];
        q.e[1][k] = -sin(a) * pl->e[0][k] + cos(a) * pl->e[1][k];
    }
    net_to_space(pl, dx, dy, h, q.o);
    net_curve fu, fv;
    segment(&fu, -w, 0, w, 0);
    segment(&fv, -w, 0, w, 0);
    if (knotted == 1)
        curve_insert(&fu, 0.3), curve_insert(&fv, 0.3);
    if (knotted == 2) {
        static const double k[] = {0, 0, 0.5, 1, 1};
        const double x[] = {-w, -w / 5, w}, y[] = {0, 0, 0};
        curve_set(&fu, 1, 3, k, x, y, NULL);
        fv = fu;
    }
    s->is_net = 1;
    plane_grid(&s->net, &fu, &fv, NET_PI / 2, &q);
}

static void torus_sheet(sheet *s, const net_place *pl, double R, double r, double zc)
{
    net_curve circle, tube;
    circle9(&circle);
    circle9(&tube);
    curve_place(&tube, r, R, zc);
    s->is_net = 1;
    revolve(&s->net, &circle, &tube, pl, 0, 1);
}

static void cylinder_sheet(sheet *s, const net_place *pl, double r, double z0, double z1)
{
    net_curve circle, profile;
    circle9(&circle);
    segment(&profile, r, z0, r, z1);
    s->is_net = 1;
    revolve(&s->net, &circle, &profile, pl, 0, 0);
}

enum {
    SPHERE_PLANE,
    SPHERE_PLANE_NET,
    SPHERE_ELEVATED_PLANE,
    SPHERE_INSERTED_PLANE_KNOTTED,
    SPHERE7_PLANE,
    SPHERE_PLANE_KINKED,
    CYLINDER_SPHERE,
    CONE_PLANE_NET,
    TORUS_PLANE,
    TORUS_SPHERE_NETS,
    SPHERE_TOUCH_POLE,
    SPHERE_TOUCH_TURNED,
    DISC_SPHERE,
    NFAMILIES
};
static const char *const FAMILY[NFAMILIES] = {"sphere net, plane",
                                              "sphere net, plane net",
                                              "elevated sphere net, plane",
                                              "knot-inserted sphere net, knotted plane net",
                                              "sphere net of the 7-point circle, plane",
                                              "sphere net, plane net with a kink",
                                              "cylinder net, sphere",
                                              "cone net, plane net",
                                              "torus net, plane",
                                              "torus net, sphere net touching",
                                              "sphere net on a plane net at its pole",
                                              "sphere net turned on a plane net",
                                              "disc net, sphere"};

static void make_case(net_case *c, int family, const net_place *pl, harness_rng *g)
{
    memset(c, 0, sizeof *c);
    snprintf(c->name, sizeof c->name, "%s", FAMILY[family]);
    memcpy(c->axis, pl->e[2], sizeof c->axis);
    const double h = harness_uniform(g, -0.6, 0.6), a = harness_uniform(g, 0, 2 * NET_PI);
    switch (family) {
    case SPHERE_PLANE: /* sphere R = 1 about height 0.3, the plane z = 0.3 + h */
    case SPHERE_PLANE_NET:
    case SPHERE_ELEVATED_PLANE:
    case SPHERE_INSERTED_PLANE_KNOTTED:
    case SPHERE7_PLANE:
    case SPHERE_PLANE_KINKED:
        sphere_sheet(&c->s[0], pl, 1.0, 0.3,
                     family == SPHERE_ELEVATED_PLANE           ? 1
                     : family == SPHERE_INSERTED_PLANE_KNOTTED ? 2
                     : family == SPHERE7_PLANE                 ? 3
                                                               : 0);
        if (family == SPHERE_PLANE || family == SPHERE_ELEVATED_PLANE || family == SPHERE7_PLANE)
            c->s[1].prim = about(IC_PRIM_PLANE, pl, 0.3 + h);
        else
            plane_sheet(
                &c->s[1], pl, 0.3 + h, 1.5, a, 0.1, -0.1,
                family == SPHERE_INSERTED_PLANE_KNOTTED ? 1 : 2 * (family == SPHERE_PLANE_KINKED));
        add_circle(c, pl, sqrt(1 - h * h), 0.3 + h, 0);
        break;
    case CYLINDER_SPHERE: /* r = 0.7 over [-0.5, 0.8]; the sphere R = 1 at height 0.3 + h/20:
                           * circles at 0.3 + h/20 +- 0.714, the upper one off the patch */
        cylinder_sheet(&c->s[0], pl, 0.7, -0.5, 0.8);
        c->s[1].prim = about(IC_PRIM_SPHERE, pl, 0.3 + h / 20), c->s[1].prim.radius = pl->s;
        add_circle(c, pl, 0.7, 0.3 + h / 20 - sqrt(1 - 0.49), 0);
        break;
    case CONE_PLANE_NET: { /* apex at the origin, x = z / 2 over z in [0.4, 2] */
        net_curve circle, profile;
        circle9(&circle);
        segment(&profile, 0.2, 0.4, 1.0, 2.0);
        c->s[0].is_net = 1;
        revolve(&c->s[0].net, &circle, &profile, pl, 0, 0);
        plane_sheet(&c->s[1], pl, 1.2 + h, 1.5, a, 0, 0, 0);
        add_circle(c, pl, (1.2 + h) / 2, 1.2 + h, 0);
        break;
    }
    case TORUS_PLANE: /* R = 1.2, r = 0.4 about height 0.1, the plane z = 0.1 + h/3 */
        torus_sheet(&c->s[0], pl, 1.2, 0.4, 0.1);
        c->s[1].prim = about(IC_PRIM_PLANE, pl, 0.1 + h / 3);
        for (int sg = -1; sg <= 1; sg += 2)
            add_circle(c, pl, 1.2 + sg * sqrt(0.16 - h * h / 9), 0.1 + h / 3, 0);
        break;
    case TORUS_SPHERE_NETS: /* the peer benchmark's case: the sphere R + r about the torus' centre
                             */
        torus_sheet(&c->s[0], pl, 2, 0.5, 0);
        sphere_sheet(&c->s[1], pl, 2.5, 0, 0);
        add_circle(c, pl, 2.5, 0, 1);
        break;
    case SPHERE_TOUCH_POLE: /* the unit sphere at height 1 on the plane z = 0 */
        sphere_sheet(&c->s[0], pl, 1.0, 1.0, 0);
        plane_sheet(&c->s[1], pl, 0, 2, a, 0.2, 0.3, 0);
        net_to_space(pl, 0, 0, 0, c->contact[c->ncontacts++]);
        break;
    case SPHERE_TOUCH_TURNED: { /* the same sphere's net about the place's e1 */
        net_place turned = *pl;
        memcpy(turned.e[2], pl->e[0], sizeof turned.e[2]);
        memcpy(turned.e[0], pl->e[1], sizeof turned.e[0]);
        memcpy(turned.e[1], pl->e[2], sizeof turned.e[1]);
        net_to_space(pl, 0, 0, 1, turned.o);
        sphere_sheet(&c->s[0], &turned, 1.0, 0, 0);
        plane_sheet(&c->s[1], pl, 0, 2, a, -0.2, 0.1, 0);
        net_to_space(pl, 0, 0, 0, c->contact[c->ncontacts++]);
        break;
    }
    case DISC_SPHERE: { /* a disc of radius 1.5 at height 0.25, the unit sphere at 0 */
        net_curve circle, profile;
        circle9(&circle);
        segment(&profile, 0, 0.25, 1.5, 0.25);
        c->s[0].is_net = 1;
        revolve(&c->s[0].net, &circle, &profile, pl, 0, 0);
        c->s[1].prim = about(IC_PRIM_SPHERE, pl, 0), c->s[1].prim.radius = pl->s;
        add_circle(c, pl, sqrt(1 - 0.0625), 0.25, 0);
        break;
    }
    }
    c->general = family != SPHERE_ELEVATED_PLANE && family != TORUS_PLANE;
}

/* ---- traces ---- */

typedef struct {
    ic_surface *S[2];
    ic_pair *pair;
    ic_trace_result *res[2]; /* general path, exact path */
    double L;                /* a length of the problem's size: the nets' boxes */
} traced;

static void release(traced *t)
{
    for (int i = 0; i < 2; i++) {
        ic_trace_result_free(t->res[i]);
        ic_surface_free(t->S[i]);
    }
    ic_pair_free(t->pair);
}

/* The diagonal of the nets' control points' box. */
static double nets_size(const net_case *c)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int s = 0; s < 2; s++)
        for (int i = 0; c->s[s].is_net && i < c->s[s].net.count[0] * c->s[s].net.count[1]; i++)
            for (int k = 0; k < 3; k++)
                lo[k] = fmin(lo[k], c->s[s].net.points[3 * i + k]),
                hi[k] = fmax(hi[k], c->s[s].net.points[3 * i + k]);
    return sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

static int trace_case(traced *t, const net_case *c, int general)
{
    ic_error err;
    memset(t, 0, sizeof *t);
    t->L = nets_size(c);
    for (int s = 0; s < 2; s++) {
        const ic_status st =
            c->s[s].is_net ? net_surface(&t->S[s], &c->s[s].net, &err)
                           : ic_surface_new_primitive(&t->S[s], &c->s[s].prim, IC_IMPLICIT, &err);
        if (!REQUIRE(st == IC_OK, "%s: surface %d: %s", c->name, s, err.message))
            return 0;
    }
    if (!REQUIRE(ic_pair_new(&t->pair, t->S[0], t->S[1], &err) == IC_OK, "%s: %s", c->name,
                 err.message))
        return 0;
    for (int exact = general ? 0 : 1; exact <= 1; exact++) {
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

/* ---- the exact path against the closed forms ---- */

/* The circle of the case the curve's first point is on, or -1. */
static int which_circle(const net_case *c, const ic_trace_curve *cv, double tol)
{
    for (int i = 0; i < c->ncircles; i++) {
        double w[3];
        for (int k = 0; k < 3; k++)
            w[k] = cv->points[0].xyz[k] - c->centre[i][k];
        const double z = dot3(w, c->axis);
        const double r = sqrt(fmax(0, dot3(w, w) - z * z));
        if (fabs(z) <= tol && fabs(r - c->rho[i]) <= tol)
            return i;
    }
    return -1;
}

/* The largest distance of the curve's points from circle i. */
static double off_circle(const net_case *c, const ic_trace_curve *cv, int i)
{
    double worst = 0;
    for (int p = 0; p < cv->npoints; p++) {
        double w[3];
        for (int k = 0; k < 3; k++)
            w[k] = cv->points[p].xyz[k] - c->centre[i][k];
        const double z = dot3(w, c->axis);
        worst = fmax(worst, fmax(fabs(z), fabs(sqrt(fmax(0, dot3(w, w) - z * z)) - c->rho[i])));
    }
    return worst;
}

/* Every point's parameters on the nets: the net there is the point. */
static double off_nets(traced *t, const net_case *c, const ic_trace_curve *cv)
{
    double worst = 0;
    for (int s = 0; s < 2; s++)
        for (int p = 0; c->s[s].is_net && p < cv->npoints; p++) {
            double x[3];
            ic_error err;
            if (ic_surface_eval(t->S[s], x, cv->points[p].params[s], &err) != IC_OK)
                return INFINITY;
            worst = fmax(worst, dist3(x, cv->points[p].xyz));
        }
    return worst;
}

/* How many knot lines of a net the circle crosses, and at how many
 * points: a revolved net's turning parameter's interior knots and its seam
 * once each (meridians); a planar net's lines twice each where they pass
 * nearer the centre than the radius. */
static int knot_crossings(traced *t, const net_case *c, int s, int circle)
{
    const net_patch *n = &c->s[s].net;
    int count = n->periodic[0];
    for (int d = 0; d < (n->periodic[0] ? 1 : 2); d++)
        for (int i = n->degree[d] + 1; i < n->count[d]; i++) {
            if (n->knots[d][i] == n->knots[d][i - 1])
                continue;
            if (n->periodic[0]) {
                count++;
                continue;
            }
            /* the line from the patch's points at the knot on the two edges */
            double a[2] = {n->knots[d][i], n->knots[1 - d][n->degree[1 - d]]}, b[2], P[3], Q[3];
            b[0] = a[0], b[1] = n->knots[1 - d][n->count[1 - d]];
            double uva[2] = {a[d], a[1 - d]}, uvb[2] = {b[d], b[1 - d]};
            if (d == 1)
                uva[0] = a[1], uva[1] = a[0], uvb[0] = b[1], uvb[1] = b[0];
            ic_error err;
            if (ic_surface_eval(t->S[s], P, uva, &err) != IC_OK ||
                ic_surface_eval(t->S[s], Q, uvb, &err) != IC_OK)
                return -1;
            double e[3], w[3], cr[3];
            for (int k = 0; k < 3; k++)
                e[k] = Q[k] - P[k], w[k] = c->centre[circle][k] - P[k];
            net_cross(cr, w, e);
            count += 2 * (sqrt(dot3(cr, cr) / dot3(e, e)) < c->rho[circle]);
        }
    return count;
}

/* Whether x is one of the net's interior knots along d, or (`wraps`) the
 * domain's ends, by whole periods. */
static int on_knot(const net_patch *n, int d, double x)
{
    const double *k = n->knots[d], d0 = k[n->degree[d]], d1 = k[n->count[d]];
    if (n->periodic[d])
        x -= (d1 - d0) * floor((x - d0) / (d1 - d0));
    for (int i = n->degree[d] + 1; i < n->count[d]; i++)
        if (x == k[i])
            return 1;
    return n->periodic[d] && (x == d0 || x == d1);
}

/* The points flagged on a knot line of net s: every one exactly on one of
 * its knot values (or its seam), as many as the lines crossed. */
static void check_knot_points(traced *t, const net_case *c, const ic_trace_curve *cv, int s,
                              int circle)
{
    const net_patch *n = &c->s[s].net;
    int on = 1, flagged = 0;
    for (int p = 0; p + 1 < cv->npoints; p++) { /* the last point is the first again */
        const ic_trace_point *pt = &cv->points[p];
        if (!(pt->knot_line & (1 << s)))
            continue;
        flagged++;
        on &= on_knot(n, 0, pt->params[s][0]) || on_knot(n, 1, pt->params[s][1]);
    }
    const int want = knot_crossings(t, c, s, circle);
    CHECK(on && flagged == want,
          "%s: %d points on the knot lines of net %d (want %d), every one exactly on its line: %d",
          c->name, flagged, s, want, on);
}

static void check_exact(traced *t, const net_case *c)
{
    const ic_trace_result *r = t->res[1];
    const ic_trace_report *rep = ic_trace_result_report(r);
    CHECK(rep->tracer_complete && strcmp(rep->method, NETS) == 0, "%s: complete %d, %s", c->name,
          rep->tracer_complete, rep->method);
    const int nc = ic_trace_result_num_curves(r), np = ic_trace_result_num_specials(r);
    CHECK(nc == c->ncircles && np == c->ncontacts, "%s: %d circles and %d points, want %d, %d",
          c->name, nc, np, c->ncircles, c->ncontacts);
    for (int k = 0; k < nc; k++) {
        const ic_trace_curve *cv = ic_trace_result_curve(r, k);
        const int i = which_circle(c, cv, 1e-9 * t->L);
        if (!REQUIRE(i >= 0, "%s: curve %d is a circle of the closed forms", c->name, k))
            continue;
        const double off = off_circle(c, cv, i) / t->L, on = off_nets(t, c, cv) / t->L;
        const double len = fabs(cv->length - 2 * NET_PI * c->rho[i]) / t->L;
        worst_exact = fmax(worst_exact, fmax(off, len));
        worst_on_net = fmax(worst_on_net, on);
        CHECK(off <= EXACT_REL && len <= EXACT_REL && cv->closed && cv->shape == IC_SHAPE_CIRCLE &&
                  cv->tangential == c->tangential[i],
              "%s: circle %d: %.3g L off, length %.3g L off, closed %d, %s, tangential %d", c->name,
              i, off, len, cv->closed, ic_shape_name(cv->shape), cv->tangential);
        CHECK(on <= ON_NET_REL, "%s: circle %d: the nets at the points' parameters %.3g L off",
              c->name, i, on);
        for (int s = 0; s < 2; s++)
            if (c->s[s].is_net)
                check_knot_points(t, c, cv, s, i);
    }
    for (int k = 0; k < np && k < c->ncontacts; k++) {
        const ic_trace_special *sp = ic_trace_result_special(r, k);
        const double off = dist3(sp->xyz, c->contact[k]) / t->L;
        worst_exact = fmax(worst_exact, off);
        CHECK(sp->type == IC_POINT_ISOLATED_CONTACT && !sp->approximate && off <= EXACT_REL,
              "%s: an exact isolated contact: %s, approximate %d, %.3g L off", c->name,
              ic_point_type_name(sp->type), sp->approximate, off);
    }
}

/* The B-spline fits: every net's pcurve kept, within the tolerance. */
static void check_fit(traced *t, const net_case *c)
{
    ic_error err;
    if (!REQUIRE(ic_trace_fit(t->res[1], t->pair, IC_TRACE_FIT_TOL_DEFAULT, &err) == IC_OK,
                 "%s: fitted: %s", c->name, err.message))
        return;
    const ic_trace_report *rep = ic_trace_result_report(t->res[1]);
    for (int k = 0; k < ic_trace_result_num_curves(t->res[1]); k++) {
        const ic_curve_fit *f = ic_trace_result_fit(t->res[1], k);
        if (!REQUIRE(f, "%s: curve %d fitted", c->name, k))
            continue;
        for (int s = 0; s < 2; s++)
            CHECK(!c->s[s].is_net || (f->pcurves[s].ncontrol > 0 && !f->pcurve_dropped[s]),
                  "%s: curve %d: net %d's pcurve kept (dropped %d)", c->name, k, s,
                  f->pcurve_dropped[s]);
        CHECK(f->fit_error <= rep->fit_tol, "%s: curve %d: fit error %.3g, tolerance %.3g", c->name,
              k, f->fit_error, rep->fit_tol);
    }
}

/* ---- against the general path ---- */

/* The way the curve runs about the case's axis at its first point: +1
 * counterclockwise, -1 clockwise. */
static int turning(const net_case *c, const ic_trace_curve *cv, int i)
{
    double r[3], m[3];
    for (int k = 0; k < 3; k++)
        r[k] = cv->points[0].xyz[k] - c->centre[i][k];
    net_cross(m, r, cv->points[0].t);
    return dot3(m, c->axis) > 0 ? 1 : -1;
}

static void check_against_general(traced *t, const net_case *c)
{
    const ic_trace_result *g = t->res[0], *x = t->res[1];
    const ic_trace_report *rep = ic_trace_result_report(g);
    CHECK(rep->tracer_complete && strcmp(rep->method, "search") == 0,
          "%s: the general path is complete (%d) and searched", c->name, rep->tracer_complete);
    const int n = ic_trace_result_num_curves(g);
    CHECK(n == ic_trace_result_num_curves(x) &&
              ic_trace_result_num_specials(g) == ic_trace_result_num_specials(x),
          "%s: the general path's %d curves and %d points, the exact path's %d and %d", c->name, n,
          ic_trace_result_num_specials(g), ic_trace_result_num_curves(x),
          ic_trace_result_num_specials(x));
    for (int k = 0; k < n; k++) {
        const ic_trace_curve *gc = ic_trace_result_curve(g, k), *xc = NULL;
        const int i = which_circle(c, gc, GENERAL_ON_EXACT * t->L);
        for (int m = 0; m < ic_trace_result_num_curves(x) && i >= 0; m++)
            if (which_circle(c, ic_trace_result_curve(x, m), GENERAL_ON_EXACT * t->L) == i)
                xc = ic_trace_result_curve(x, m);
        if (!REQUIRE(xc, "%s: the general path's curve %d is an exact circle", c->name, k))
            continue;
        CHECK(off_circle(c, gc, i) <= GENERAL_ON_EXACT * t->L && gc->closed == xc->closed &&
                  gc->tangential == xc->tangential && gc->shape == xc->shape,
              "%s: circle %d: the general path's points on it, closed %d/%d, tangential %d/%d, "
              "shape %s/%s",
              c->name, i, gc->closed, xc->closed, gc->tangential, xc->tangential,
              ic_shape_name(gc->shape), ic_shape_name(xc->shape));
        CHECK(gc->tangential || turning(c, gc, i) == turning(c, xc, i),
              "%s: circle %d runs the general path's way about the axis (%+d, exact %+d)", c->name,
              i, turning(c, gc, i), turning(c, xc, i));
        CHECK(fabs(gc->length - xc->length) <= GENERAL_LENGTH * xc->length,
              "%s: circle %d: lengths %.17g (general), %.17g (exact)", c->name, i, gc->length,
              xc->length);
    }
    /* the same points, of the same types (at a pole of a net the general
     * path's point is approximate: its analysis is made beside the pole) */
    for (int k = 0; k < ic_trace_result_num_specials(g) && k < ic_trace_result_num_specials(x);
         k++) {
        const ic_trace_special *a = ic_trace_result_special(g, k),
                               *b = ic_trace_result_special(x, k);
        const double tol = (a->approximate ? GENERAL_APPROX : GENERAL_ON_EXACT) * t->L;
        CHECK(a->type == b->type && a->nbranches == b->nbranches && dist3(a->xyz, b->xyz) <= tol,
              "%s: point %d: %s (general), %s (exact), %.3g apart", c->name, k,
              ic_point_type_name(a->type), ic_point_type_name(b->type), dist3(a->xyz, b->xyz));
    }
}

static void run_case(const net_case *c)
{
    traced t;
    if (trace_case(&t, c, c->general)) {
        check_exact(&t, c);
        check_fit(&t, c);
        if (c->general)
            check_against_general(&t, c);
    }
    release(&t);
}

static void families(void)
{
    harness_rng g = {0x5851F42D4C957F2DULL};
    for (int f = 0; f < NFAMILIES; f++) {
        net_case c;
        const net_place pl = f == TORUS_SPHERE_NETS ? NET_STANDARD : net_random_place(&g);
        make_case(&c, f, &pl, &g);
        run_case(&c);
    }
}

/* ---- cases left to the general path, and circles off the patches ---- */

static void fall_back(const net_case *c)
{
    traced t;
    if (trace_case(&t, c, 1))
        CHECK(same_results(t.res[0], t.res[1]),
              "%s: left to the general path, exactly what it "
              "gives (%d curves; method %s)",
              c->name, ic_trace_result_num_curves(t.res[1]),
              ic_trace_result_report(t.res[1])->method);
    release(&t);
}

/* The unit sphere's net at the place and another sheet. */
static void sphere_and(net_case *c, const char *name, const net_place *pl)
{
    memset(c, 0, sizeof *c);
    snprintf(c->name, sizeof c->name, "%s", name);
    memcpy(c->axis, pl->e[2], sizeof c->axis);
    sphere_sheet(&c->s[0], pl, 1.0, 0, 0);
}

static void fall_back_cases(void)
{
    harness_rng g = {0x853C49E6748FEA9BULL};
    const net_place pl = net_random_place(&g);
    net_case c;
    /* the cylinder's lower circle 3e-7 above its edge (IC_EXACT_COVER_MARGIN: 1e-6 L) */
    memset(&c, 0, sizeof c);
    snprintf(c.name, sizeof c.name, "a circle at the edge of a cylinder's net");
    cylinder_sheet(&c.s[0], &pl, 0.7, -0.5, 0.8);
    c.s[1].prim = about(IC_PRIM_SPHERE, &pl, -0.5 + 3e-7 + sqrt(0.51)), c.s[1].prim.radius = pl.s;
    fall_back(&c);
    /* the square of half width 0.9 at the equator cuts the unit circle */
    sphere_and(&c, "a plane's net that cuts the circle", &pl);
    plane_sheet(&c.s[1], &pl, 0, 0.9, 0.3, 0, 0, 0);
    fall_back(&c);
    /* the sphere's net about an axis 0.3 rad from the plane's normal: its
     * circle is no parameter line of the net */
    net_place tilted = pl;
    for (int k = 0; k < 3; k++) {
        tilted.e[2][k] = cos(0.3) * pl.e[2][k] + sin(0.3) * pl.e[0][k];
        tilted.e[0][k] = cos(0.3) * pl.e[0][k] - sin(0.3) * pl.e[2][k];
    }
    sphere_and(&c, "a sphere's net about another axis than the plane's normal", &tilted);
    c.s[1].prim = about(IC_PRIM_PLANE, &pl, 0.2);
    fall_back(&c);
    /* a cylinder's net that does not wrap, its seam a radian from the
     * sphere's: the circles cross it between their ends */
    net_place turned = pl;
    for (int k = 0; k < 3; k++) {
        turned.e[0][k] = cos(1.0) * pl.e[0][k] + sin(1.0) * pl.e[1][k];
        turned.e[1][k] = -sin(1.0) * pl.e[0][k] + cos(1.0) * pl.e[1][k];
    }
    sphere_and(&c, "a cylinder's net that does not wrap, crossed off its seam", &pl);
    cylinder_sheet(&c.s[1], &turned, 0.6, -1.5, 1.5);
    c.s[1].net.periodic[0] = 0;
    fall_back(&c);
}

/* A circle wholly off a patch is no part of the intersection: the unit
 * sphere and a square of half width 0.5 inside its circle. */
static void circle_off_patch(void)
{
    harness_rng g = {0xDA942042E4DD58B5ULL};
    const net_place pl = net_random_place(&g);
    net_case c;
    sphere_and(&c, "a plane's net inside the circle", &pl);
    plane_sheet(&c.s[1], &pl, 0, 0.5, 0.3, 0, 0, 0);
    traced t;
    if (trace_case(&t, &c, 1)) {
        const ic_trace_report *rep = ic_trace_result_report(t.res[1]);
        CHECK(strcmp(rep->method, NETS) == 0 && rep->tracer_complete &&
                  ic_trace_result_num_curves(t.res[1]) == 0 &&
                  ic_trace_result_num_specials(t.res[1]) == 0,
              "%s: nothing, in closed form (%s, %d curves)", c.name, rep->method,
              ic_trace_result_num_curves(t.res[1]));
        CHECK(ic_trace_result_report(t.res[0])->tracer_complete &&
                  ic_trace_result_num_curves(t.res[0]) == 0 &&
                  ic_trace_result_num_specials(t.res[0]) == 0,
              "%s: and nothing by the general path", c.name);
    }
    release(&t);
}

/* ---- the steps another exact path would take (exact_source.h) ---- */

/* What a cylinder's net (r = 0.7 over heights [-0.5, 0.8]) and a square
 * plane's net (half width 1 at height 0) cover, point by point, and the
 * parameters of the points of an ellipse, a plane's oblique section of the
 * cylinder, on its net: back on the net at each, continued across the seam
 * (one period in all). */
static void generic_steps(void)
{
    net_case c;
    memset(&c, 0, sizeof c);
    cylinder_sheet(&c.s[0], &NET_STANDARD, 0.7, -0.5, 0.8);
    plane_sheet(&c.s[1], &NET_STANDARD, 0, 1, 0, 0, 0, 0);
    traced t;
    ic_error err;
    memset(&t, 0, sizeof t);
    t.L = nets_size(&c);
    ic_exact_source src[2];
    if (!REQUIRE(net_surface(&t.S[0], &c.s[0].net, &err) == IC_OK &&
                     net_surface(&t.S[1], &c.s[1].net, &err) == IC_OK &&
                     ic_pair_new(&t.pair, t.S[0], t.S[1], &err) == IC_OK &&
                     ic_exact_sources(t.pair, src) == 1,
                 "the cylinder's and the plane's nets as sources")) {
        release(&t);
        return;
    }
    const double m = IC_EXACT_COVER_MARGIN * t.L;
    const double at[6][3] = {{0.7, 0, 0},   {0, 0.7, 0.8 + 10 * m}, {0, -0.7, 0.8 - m / 10},
                             {0.2, 0.3, 0}, {1 + 10 * m, 0, 0},     {0, 1 - m / 10, 0}};
    const int want[6] = {1, 0, -1, 1, 0, -1};
    for (int k = 0; k < 6; k++)
        CHECK(ic_exact_covers_point(&src[k / 3], at[k], m) == want[k],
              "point %d on %s: covered %d, want %d", k, k < 3 ? "the cylinder" : "the plane",
              ic_exact_covers_point(&src[k / 3], at[k], m), want[k]);
    enum { N = 65 };
    static ic_trace_point pts[N];
    for (int k = 0; k < N; k++) {
        const double a = 2 * NET_PI * k / (N - 1) + 0.1;
        memset(&pts[k], 0, sizeof pts[k]);
        pts[k].xyz[0] = 0.7 * cos(a), pts[k].xyz[1] = 0.7 * sin(a), pts[k].xyz[2] = 0.21 * cos(a);
    }
    const ic_exact_source cyl[2] = {src[0], {.net = NULL}};
    if (REQUIRE(ic_exact_curve_params(cyl, pts, N, t.L) == 0, "the ellipse's parameters")) {
        double off = 0;
        int up = 1;
        for (int k = 0; k < N; k++) {
            double x[3];
            off = fmax(off, ic_surface_eval(t.S[0], x, pts[k].params[0], &err) == IC_OK
                                ? dist3(x, pts[k].xyz) / t.L
                                : INFINITY);
            up &= k == 0 || pts[k].params[0][0] > pts[k - 1].params[0][0];
        }
        CHECK(off <= ON_NET_REL && up &&
                  fabs(pts[N - 1].params[0][0] - pts[0].params[0][0] - 1) <= TURN_REL,
              "the ellipse on the net: %.3g L off, increasing %d, %.17g periods", off, up,
              pts[N - 1].params[0][0] - pts[0].params[0][0]);
    }
    release(&t);
}

int main(void)
{
    families();
    generic_steps();
    fall_back_cases();
    circle_off_patch();
    printf("worst: %.3g L from the closed forms, %.3g L from the nets\n", worst_exact,
           worst_on_net);
    return harness_finish("nurbs_exact");
}
