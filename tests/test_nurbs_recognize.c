/* NURBS nets recognised as the standard surfaces they are (docs/nurbs.md,
 * "Recognised nets"), against the closed forms the nets were written from
 * (tests/nurbs_nets.h): spheres, cylinders, cones, tori, discs and annuli
 * revolved from the 9-point and the 7-point circles, degree-elevated,
 * with a knot inserted, their knots scaled and shifted, turning along u or
 * v, at random places, sizes and turns; planes as affine grids, skewed,
 * elevated, with knots inserted. For each: the kind, axis, centre and radii
 * of the primitive, what of it the patch covers, and the parameters of its
 * points found again. Then what must not be recognised: nets moved off by
 * 1e-9 of their size (a point, a weight, a row's weight), partial
 * revolutions and profiles, a profile that overshoots its end or crosses
 * the axis, free-form and non-affine patches, a patch cut to part of its
 * domain. */
#include "harness.h"
#include "nurbs_nets.h"
#include "surface/surface_internal.h"

/* relative to the net's size: the primitive's centre, axis, radii and the
 * covered range against the numbers the net was written from. They are
 * read from three points of a row, least squares over the net and a
 * circumcentre: a few hundred roundings of O(1) coordinates at most
 * (measured worst printed at the end) */
#define SHAPE_REL 1e-13
/* relative to the domain's width: the parameters found from a point of the
 * patch against those it was evaluated at. The point carries roundings of
 * O(1) coordinates (1e-16), which move its angle by that over its radius
 * (0.2 at least here) and its profile place likewise; the inversion stops
 * within 4 ulps */
#define PARAM_REL 1e-12
/* relative to the size: the patch at the parameters found against the
 * point they were found from (a few roundings of the evaluation) */
#define POINT_REL 1e-14
/* the perturbation that must not be recognised, relative (1000 times the
 * recognition's tolerance, IC_NET_REL = 1e-12) */
#define PERTURB 1e-9

static double worst_shape, worst_param;

/* The surface's recognised shape, or NULL (none, or out of memory: no test
 * here runs short of it). */
static const ic_net_shape *net_shape(ic_surface *S)
{
    const ic_net_shape *sh = NULL;
    return ic_surface_net_shape(S, &sh) == 0 ? sh : NULL;
}

typedef enum { SPHERE, CYLINDER, CONE, TORUS, DISC, ANNULUS, NFAMILIES } family;
static const char *const FAMILY[NFAMILIES] = {"sphere", "cylinder", "cone",
                                              "torus",  "disc",     "annulus"};

/* What a family's net is, in the place's local coordinates (scale 1). */
typedef struct {
    ic_primitive_kind kind;
    double zc; /* the centre's (apex's, plane's) height on the axis */
    double radius, major, half_angle;
    double lo, hi; /* the covered heights (cylinder, cone) or radii (disc, annulus) */
    int periodic_profile;
} expected;

static expected profile_of(family f, net_curve *pr)
{
    expected e;
    memset(&e, 0, sizeof e);
    switch (f) {
    case SPHERE:
        half_circle(pr, 1.0, 0.3);
        e.kind = IC_PRIM_SPHERE, e.zc = 0.3, e.radius = 1.0;
        break;
    case CYLINDER:
        segment(pr, 0.7, -0.5, 0.7, 0.8);
        e.kind = IC_PRIM_CYLINDER, e.radius = 0.7, e.lo = -0.5, e.hi = 0.8;
        break;
    case CONE: /* the line x = z / 2 through the apex at the origin */
        segment(pr, 0.2, 0.4, 1.0, 2.0);
        e.kind = IC_PRIM_CONE, e.half_angle = atan(0.5), e.lo = 0.4, e.hi = 2.0;
        break;
    case TORUS:
        circle9(pr);
        curve_place(pr, 0.4, 1.2, 0.1);
        e.kind = IC_PRIM_TORUS, e.zc = 0.1, e.radius = 0.4, e.major = 1.2;
        e.periodic_profile = 1;
        break;
    case DISC:
        segment(pr, 0.0, 0.25, 1.5, 0.25);
        e.kind = IC_PRIM_PLANE, e.zc = 0.25, e.lo = 0.0, e.hi = 1.5;
        break;
    case ANNULUS: /* written from the outside in */
        segment(pr, 1.5, -0.2, 0.5, -0.2);
        e.kind = IC_PRIM_PLANE, e.zc = -0.2, e.lo = 0.5, e.hi = 1.5;
        break;
    default:
        break;
    }
    return e;
}

/* The variants of a curve: as written, elevated, a knot inserted, its knots
 * scaled and shifted. */
enum { AS_IS, ELEVATED, INSERTED, RESCALED, NVARIANTS };
static const char *const VARIANT[NVARIANTS] = {"as is", "elevated", "knot inserted", "rescaled"};

static void vary(net_curve *c, int v)
{
    if (v == ELEVATED)
        curve_elevate(c);
    else if (v == INSERTED)
        curve_insert(c, c->knots[c->degree] + 0.37 * (c->knots[c->count] - c->knots[c->degree]));
    else if (v == RESCALED)
        curve_rescale(c, 3.0, 5.0);
}

static double dist3(const double *a, const double *b)
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                (a[2] - b[2]) * (a[2] - b[2]));
}

/* The distance from x to the line through o along the unit e. */
static double off_line(const double *x, const double *o, const double *e)
{
    double w[3], c[3];
    for (int k = 0; k < 3; k++)
        w[k] = x[k] - o[k];
    net_cross(c, w, e);
    return sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
}

/* The local coordinates of x at the place. */
static void to_local(const net_place *pl, const double *x, double L[3])
{
    for (int k = 0; k < 3; k++)
        L[k] = ((x[0] - pl->o[0]) * pl->e[k][0] + (x[1] - pl->o[1]) * pl->e[k][1] +
                (x[2] - pl->o[2]) * pl->e[k][2]) /
               pl->s;
}

/* The recognised primitive against the expected one at the place. */
static int shape_matches(const ic_net_shape *sh, const expected *e, const net_place *pl,
                         double *err)
{
    double axis[3], centre[3];
    net_cross(axis, sh->frame[2], pl->e[2]);
    net_to_space(pl, 0, 0, e->zc, centre);
    const double s = pl->s, size = sh->size;
    double off = sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]) * size;
    off = fmax(off, e->kind == IC_PRIM_CYLINDER ? off_line(sh->prim.center, pl->o, pl->e[2])
                                                : dist3(sh->prim.center, centre));
    off = fmax(off, fabs(sh->prim.radius - s * e->radius));
    off = fmax(off, fabs(sh->prim.major_radius - s * e->major));
    off = fmax(off, fabs(sh->prim.half_angle - e->half_angle) * size);
    if (e->kind == IC_PRIM_CYLINDER || e->kind == IC_PRIM_CONE || e->kind == IC_PRIM_PLANE) {
        /* the covered range: the heights (a plane's radii) of the ends of
         * the segment the patch covers */
        const ic_net_profile *pr = &sh->profile;
        double lo = INFINITY, hi = -INFINITY;
        for (int end = 0; end < 2; end++) {
            const double tau = end ? pr->hi : pr->lo;
            const double x = pr->c[0] + tau * pr->d[0], z = pr->c[1] + tau * pr->d[1];
            double P[3], L[3];
            for (int m = 0; m < 3; m++)
                P[m] = sh->origin[m] + z * sh->frame[2][m] + x * sh->frame[0][m];
            to_local(pl, P, L);
            const double h = e->kind == IC_PRIM_PLANE ? hypot(L[0], L[1]) : L[2];
            lo = fmin(lo, h), hi = fmax(hi, h);
        }
        off = fmax(off, s * fmax(fabs(lo - e->lo), fabs(hi - e->hi)));
    }
    *err = off / size;
    return sh->kind == IC_NET_REVOLVED && sh->prim.kind == e->kind && *err <= SHAPE_REL;
}

/* Points of the patch at random parameters (the profile's ends left out:
 * a sphere's poles have no angle) found again from their place. */
static void params_round_trip(ic_surface *S, const ic_net_shape *sh, harness_rng *g,
                              const char *name)
{
    double dom[2][2], worst = 0, worst_point = 0;
    int per[2], failed = 0;
    ic_surface_get_domain(S, dom, per);
    for (int k = 0; k < 10; k++) {
        double uv[2], x[3], back[2], y[3];
        for (int d = 0; d < 2; d++)
            uv[d] = dom[d][0] + (dom[d][1] - dom[d][0]) * harness_uniform(g, 0.03, 0.97);
        ic_error err;
        if (ic_surface_eval(S, x, uv, &err) != IC_OK || ic_net_params(sh, x, back) != 0 ||
            ic_surface_eval(S, y, back, &err) != IC_OK) {
            failed++;
            continue;
        }
        for (int d = 0; d < 2; d++)
            worst = fmax(worst, fabs(back[d] - uv[d]) / (dom[d][1] - dom[d][0]));
        worst_point = fmax(worst_point, dist3(x, y) / sh->size);
    }
    worst_param = fmax(worst_param, worst);
    CHECK(!failed && worst <= PARAM_REL && worst_point <= POINT_REL,
          "%s: parameters found again: %d failed, worst %.3g of the domain, %.3g of the size off",
          name, failed, worst, worst_point);
}

static void revolved_case(family f, int circle_variant, int profile_variant, int around,
                          harness_rng *g)
{
    net_curve circle, profile;
    if (circle_variant == NVARIANTS)
        circle7(&circle);
    else {
        circle9(&circle);
        vary(&circle, circle_variant);
    }
    const expected e = profile_of(f, &profile);
    vary(&profile, profile_variant);
    const net_place pl = net_random_place(g);
    static net_patch n;
    revolve(&n, &circle, &profile, &pl, around, e.periodic_profile);
    char name[160];
    snprintf(name, sizeof name, "%s, circle %s, profile %s, turning along %c", FAMILY[f],
             circle_variant == NVARIANTS ? "of 7 points" : VARIANT[circle_variant],
             VARIANT[profile_variant], around ? 'v' : 'u');
    ic_surface *S = NULL;
    ic_error err;
    if (!REQUIRE(net_surface(&S, &n, &err) == IC_OK, "%s: %s", name, err.message))
        return;
    const ic_net_shape *sh = net_shape(S);
    double off = INFINITY;
    if (REQUIRE(sh && sh->around == around && shape_matches(sh, &e, &pl, &off),
                "%s: recognised (%s), kind %d (want %d), off by %.3g of its size", name,
                sh ? "yes" : "no", sh ? (int)sh->prim.kind : -1, (int)e.kind, off)) {
        worst_shape = fmax(worst_shape, off);
        params_round_trip(S, sh, g, name);
    }
    ic_surface_free(S);
}

static void revolved_nets(void)
{
    harness_rng g = {0x2545F4914F6CDD1DULL};
    for (int f = 0; f < NFAMILIES; f++)
        for (int cv = 0; cv <= NVARIANTS; cv++) /* NVARIANTS: the 7-point circle */
            for (int pv = 0; pv < NVARIANTS; pv++)
                revolved_case(f, cv, pv, (cv + pv) % 2, &g);
}

/* ---- planar nets ---- */

static void planar_case(int variant_u, int variant_v, double skew, harness_rng *g)
{
    net_curve fu, fv;
    segment(&fu, -1.3, 0, 0.9, 0);
    segment(&fv, -0.4, 0, 1.1, 0);
    vary(&fu, variant_u);
    vary(&fv, variant_v);
    if (variant_v == ELEVATED)
        curve_elevate(&fv); /* degree 3 */
    const net_place pl = net_random_place(g);
    static net_patch n;
    plane_grid(&n, &fu, &fv, skew, &pl);
    char name[160];
    snprintf(name, sizeof name, "plane, u %s, v %s, edges %.2f rad apart", VARIANT[variant_u],
             VARIANT[variant_v], skew);
    ic_surface *S = NULL;
    ic_error err;
    if (!REQUIRE(net_surface(&S, &n, &err) == IC_OK, "%s: %s", name, err.message))
        return;
    const ic_net_shape *sh = net_shape(S);
    if (REQUIRE(sh && sh->kind == IC_NET_PLANAR && sh->prim.kind == IC_PRIM_PLANE,
                "%s: recognised as a parallelogram", name)) {
        double corner[3], e0[3], e1[3], c[3], normal[3];
        net_to_space(&pl, -1.3 - 0.4 * cos(skew), -0.4 * sin(skew), 0, corner);
        for (int k = 0; k < 3; k++) {
            e0[k] = pl.s * 2.2 * pl.e[0][k];
            e1[k] = pl.s * 1.5 * (cos(skew) * pl.e[0][k] + sin(skew) * pl.e[1][k]);
        }
        net_cross(normal, sh->frame[2], pl.e[2]);
        net_cross(c, sh->edge[0], e0);
        double off =
            fmax(dist3(sh->corner, corner), fmax(dist3(sh->edge[0], e0), dist3(sh->edge[1], e1)));
        off =
            fmax(off, sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]) *
                          sh->size) /
            sh->size;
        worst_shape = fmax(worst_shape, off);
        CHECK(off <= SHAPE_REL, "%s: the parallelogram off by %.3g of its size", name, off);
        params_round_trip(S, sh, g, name);
    }
    ic_surface_free(S);
}

static void planar_nets(void)
{
    harness_rng g = {0x9E3779B97F4A7C15ULL};
    for (int vu = 0; vu < NVARIANTS; vu++)
        for (int vv = 0; vv < NVARIANTS; vv++)
            planar_case(vu, vv, vu == vv ? NET_PI / 2 : 0.6 + 0.2 * vv, &g);
}

/* ---- what must not be recognised ---- */

static void refused(const char *name, const net_patch *n)
{
    ic_surface *S = NULL;
    ic_error err;
    if (!REQUIRE(net_surface(&S, n, &err) == IC_OK, "%s: %s", name, err.message))
        return;
    CHECK(net_shape(S) == NULL, "%s: not recognised", name);
    ic_surface_free(S);
}

/* The unit sphere's net, its circle and profile given. */
static void sphere_net(net_patch *n, const net_curve *circle, const net_curve *profile)
{
    revolve(n, circle, profile, &NET_STANDARD, 0, 0);
}

/* Nets 1e-9 of their size off the structure. */
static void perturbed_nets(void)
{
    static net_patch n;
    net_curve circle, profile;
    circle9(&circle);
    half_circle(&profile, 1.0, 0.0);
    sphere_net(&n, &circle, &profile);
    ic_surface *S = NULL;
    ic_error err;
    /* the control: the same net untouched is a sphere */
    if (REQUIRE(net_surface(&S, &n, &err) == IC_OK, "the sphere: %s", err.message))
        CHECK(net_shape(S) && net_shape(S)->prim.kind == IC_PRIM_SPHERE,
              "the sphere's net, untouched, is recognised");
    ic_surface_free(S);
    const int at = 3 * 5 + 2; /* control point (3, 2), on the equator */
    /* its size is 2 sqrt(3): a point moved by 1e-9 of it along (1, 1, 1) */
    for (int k = 0; k < 3; k++)
        n.points[3 * at + k] += PERTURB * 2;
    refused("the sphere with a control point moved by 1e-9 of its size", &n);
    /* the point (3, 2) is r (-1, 1, 0): moved along (1, 1, 0), normal to it,
     * it leaves the least-squares profile and the rows' circle as they were */
    sphere_net(&n, &circle, &profile);
    n.points[3 * at] += PERTURB * 2, n.points[3 * at + 1] += PERTURB * 2;
    refused("the sphere with a control point moved by 1e-9 of its size along its row", &n);
    sphere_net(&n, &circle, &profile);
    n.weights[at] *= 1 + PERTURB;
    refused("the sphere with a weight changed by 1e-9", &n);
    net_curve c2 = circle;
    c2.w[1] *= 1 + PERTURB; /* weights still separable, rows no longer circles */
    sphere_net(&n, &c2, &profile);
    refused("the sphere with its circle's weight changed by 1e-9", &n);
    net_curve p2 = profile;
    p2.x[2] += PERTURB; /* the profile no longer a circle */
    sphere_net(&n, &circle, &p2);
    refused("the sphere with its profile moved by 1e-9", &n);
    /* a torus' tube, whose centre nothing else fixes, 1e-9 off a circle */
    circle9(&p2);
    curve_place(&p2, 0.4, 1.2, 0);
    p2.x[3] += PERTURB;
    revolve(&n, &circle, &p2, &NET_STANDARD, 0, 1);
    refused("a torus with its tube's profile moved by 1e-9", &n);
}

/* A curve of the first count points of c over the knots given. */
static void part_of(net_curve *out, const net_curve *c, int count, const double *knots)
{
    curve_set(out, c->degree, count, knots, c->x, c->y, c->w);
}

/* Partial surfaces, and curves going round twice or back. */
static void partial_nets(void)
{
    static net_patch n;
    static const double half[] = {0, 0, 0, 0.5, 0.5, 1, 1, 1};
    static const double three[] = {0, 0, 0, 1.0 / 3, 1.0 / 3, 2.0 / 3, 2.0 / 3, 1, 1, 1};
    net_curve circle, profile, part;
    circle9(&circle);
    half_circle(&profile, 1.0, 0.0);
    part_of(&part, &circle, 5, half); /* the rows half circles */
    revolve(&n, &part, &profile, &NET_STANDARD, 0, 0);
    n.periodic[0] = 0;
    refused("half a sphere (half a revolution)", &n);
    part_of(&part, &profile, 3, (const double[]){0, 0, 0, 1, 1, 1}); /* south pole to equator */
    revolve(&n, &circle, &part, &NET_STANDARD, 0, 0);
    refused("the southern half of a sphere (a quarter profile)", &n);
    /* from the south pole to 80 degrees north: the last arc's middle point
     * where the tangents meet, r (1, tan 40 deg), weight cos 40 deg */
    const double a = 40 * NET_PI / 180;
    curve_set(&part, 2, 5, half, (const double[]){0, 1, 1, 1, cos(2 * a)},
              (const double[]){-1, -1, 0, tan(a), sin(2 * a)},
              (const double[]){1, sqrt(0.5), 1, cos(a), 1});
    revolve(&n, &circle, &part, &NET_STANDARD, 0, 0);
    refused("a sphere short of its north pole by 10 degrees", &n);
    net_curve tube;
    circle9(&tube);
    curve_place(&tube, 0.4, 1.2, 0);
    part_of(&part, &tube, 7, three); /* three quarters of the tube */
    revolve(&n, &circle, &part, &NET_STANDARD, 0, 0);
    refused("three quarters of a torus' tube", &n);
    /* circles going round twice and four times: the 9 points, then 8 more
     * again and again (four turns put the rows' points at a third and two
     * thirds of the domain counterclockwise from the start, as one does) */
    for (int turns = 2; turns <= 4; turns += 2) {
        net_curve many;
        double k[NET_MAX_KNOTS], x[NET_MAX_CTRL], y[NET_MAX_CTRL], w[NET_MAX_CTRL];
        const int count = 8 * turns + 1;
        for (int i = 0; i < count; i++)
            x[i] = circle.x[i % 8], y[i] = circle.y[i % 8], w[i] = circle.w[i % 8];
        for (int i = 0; i < count + 3; i++)
            k[i] = i < 3 ? 0 : i >= count ? 1 : (double)((i - 1) / 2) / (4 * turns);
        curve_set(&many, 2, count, k, x, y, w);
        revolve(&n, &many, &profile, &NET_STANDARD, 0, 0);
        refused(turns == 2 ? "a sphere whose rows go round twice"
                           : "a sphere whose rows go round four times",
                &n);
    }
}

/* Profiles that are not a standard part: crossing the axis, overshooting
 * their end; free-form and non-affine patches. */
static void other_nets(void)
{
    static net_patch n;
    net_curve circle, profile;
    circle9(&circle);
    segment(&profile, -0.5, -1, 0.5, 1);
    revolve(&n, &circle, &profile, &NET_STANDARD, 0, 0);
    refused("a cone's profile crossing the axis (both nappes)", &n);
    curve_set(&profile, 2, 3, (const double[]){0, 0, 0, 1, 1, 1}, (const double[]){0, 2, 1},
              (const double[]){0.25, 0.25, 0.25}, NULL);
    revolve(&n, &circle, &profile, &NET_STANDARD, 0, 0);
    refused("a disc whose profile overshoots its end (x = 4t - 3t^2 reaches 4/3)", &n);
    /* a free-form bicubic: heights from a fixed generator */
    harness_rng g = {0xD1B54A32D192ED03ULL};
    net_curve fu, fv;
    curve_set(&fu, 3, 5, (const double[]){0, 0, 0, 0, 0.5, 1, 1, 1, 1},
              (const double[]){0, 0.25, 0.5, 0.75, 1}, (const double[]){0, 0, 0, 0, 0}, NULL);
    fv = fu;
    plane_grid(&n, &fu, &fv, NET_PI / 2, &NET_STANDARD);
    for (int i = 0; i < 25; i++)
        n.points[3 * i + 2] = harness_uniform(&g, -0.3, 0.3);
    refused("a free-form bicubic patch", &n);
    plane_grid(&n, &fu, &fv, NET_PI / 2, &NET_STANDARD);
    n.points[3 * (2 * 5 + 2)] += 0.1; /* an inner point moved within the plane */
    refused("a plane whose grid is not affine", &n);
    curve_set(&fu, 2, 3, (const double[]){0, 0, 0, 1, 1, 1}, (const double[]){0, 2, 1},
              (const double[]){0, 0, 0}, NULL);
    plane_grid(&n, &fu, &fv, NET_PI / 2, &NET_STANDARD);
    refused("a plane whose u coordinate turns back", &n);
    segment(&fu, 0, 0, 1, 0);
    plane_grid(&n, &fu, &fv, NET_PI / 2, &NET_STANDARD);
    n.weights[0] = 2;
    refused("a rational plane (not affine: a projective map)", &n);
}

/* A recognised net cut to part of its domain is a part. */
static void restricted_domain(void)
{
    static net_patch n;
    net_curve circle, profile;
    circle9(&circle);
    half_circle(&profile, 1.0, 0.0);
    revolve(&n, &circle, &profile, &NET_STANDARD, 0, 0);
    n.periodic[0] = 0;
    ic_surface *S = NULL;
    ic_error err;
    if (!REQUIRE(net_surface(&S, &n, &err) == IC_OK, "the sphere: %s", err.message))
        return;
    const double part[2][2] = {{0, 0.5}, {0, 1}}, whole[2][2] = {{0, 1}, {0, 1}};
    const int periodic[2] = {0, 0};
    CHECK(ic_surface_set_domain(S, part, periodic, &err) == IC_OK && net_shape(S) == NULL,
          "a sphere's net over half its u domain is not recognised");
    CHECK(ic_surface_set_domain(S, whole, periodic, &err) == IC_OK && net_shape(S),
          "and over all of it again it is");
    ic_surface_free(S);
}

int main(void)
{
    revolved_nets();
    planar_nets();
    perturbed_nets();
    partial_nets();
    other_nets();
    restricted_domain();
    printf("worst shape %.3g of the size, worst parameter %.3g of the domain\n", worst_shape,
           worst_param);
    return harness_finish("nurbs_recognize");
}
