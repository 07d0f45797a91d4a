/* The CAD reader (src/cad/cad.h) on files OpenCASCADE wrote
 * (tests/data/cad/bspline.*, primitives.*; tests/cad/gen_cad_files.cpp) and
 * on hand-written ones (small.step, small.igs): the surfaces listed, and
 * their geometry against the generator's definitions, restated here on
 * their own; bad files give errors naming the entity.
 * usage: test_cad SOURCE_DIR */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "common/mathconst.h"
#include "harness.h"
#include "intercurve/problem.h"
#include "cad/cad.h"

/* The writers' digits: OpenCASCADE writes STEP reals to 12 significant
 * digits and IGES reals to 10, so each number read is within 5e-13 (5e-10)
 * of the exact one, relative. A point of a patch mixes some tens of them
 * (weights and coordinates, degree 2 x 2: 9 terms of 4 numbers each): so
 * a distance is checked to 100 times the rounding, relative to the
 * surface's size. */
#define STEP_DIGITS (100 * 5e-13)
#define IGES_DIGITS (100 * 5e-10)

static char source_dir[512];

static void path_of(char *out, size_t size, const char *name)
{
    snprintf(out, size, "%s/tests/data/cad/%s", source_dir, name);
}

/* ---- the generator's definitions (gen_cad_files.cpp), stated again ---- */

static double bicubic_z(int i, int j) { return 2.0 * ((3 * i + 5 * j) % 4) - 3.0 + 0.25 * i * j; }
static const double BICUBIC_U[9] = {0, 0, 0, 0, 0.4, 1, 1, 1, 1};
static const double BICUBIC_V[8] = {0, 0, 0, 0, 2, 2, 2, 2};

typedef struct {
    double center[3], axis[3], ref[3];
} frame;

static void unit3(double v[3])
{
    const double n = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int k = 0; k < 3; k++)
        v[k] /= n;
}

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static double dist3(const double a[3], const double b[3])
{
    const double d[3] = {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    return sqrt(dot3(d, d));
}

/* The distance of x from the axis through c along unit a, and its height. */
static void axial(const double x[3], const double c[3], const double a[3], double *radial,
                  double *height)
{
    const double d[3] = {x[0] - c[0], x[1] - c[1], x[2] - c[2]};
    *height = dot3(d, a);
    const double r[3] = {d[0] - *height * a[0], d[1] - *height * a[1], d[2] - *height * a[2]};
    *radial = sqrt(dot3(r, r));
}

/* ---- B-spline evaluation, written for the test ---- */

/* The basis function N_{i,p}(t) by its recursive definition (0/0 = 0), the
 * right end of the knots counted in the last span. */
static double basis_rec(const double *T, int nknots, int i, int p, double t)
{
    if (p == 0) {
        const double last = T[nknots - 1];
        if (t == last)
            return T[i] < t && T[i + 1] == last ? 1 : 0;
        return T[i] <= t && t < T[i + 1] ? 1 : 0;
    }
    double v = 0;
    if (T[i + p] > T[i])
        v += (t - T[i]) / (T[i + p] - T[i]) * basis_rec(T, nknots, i, p - 1, t);
    if (T[i + p + 1] > T[i + 1])
        v += (T[i + p + 1] - t) / (T[i + p + 1] - T[i + 1]) * basis_rec(T, nknots, i + 1, p - 1, t);
    return v;
}

/* A patch's point at (u, v) as sum N_i N_j w P / sum N_i N_j w. */
static void eval_patch(const ic_nurbs *n, double u, double v, double out[3])
{
    double s[4] = {0, 0, 0, 0};
    const int nu = n->count[0] + n->degree[0] + 1, nv = n->count[1] + n->degree[1] + 1;
    for (int i = 0; i < n->count[0]; i++) {
        const double bu = basis_rec(n->knots[0], nu, i, n->degree[0], u);
        for (int j = 0; bu != 0 && j < n->count[1]; j++) {
            const size_t k = (size_t)i * n->count[1] + j;
            const double b = bu * basis_rec(n->knots[1], nv, j, n->degree[1], v) *
                             (n->weights ? n->weights[k] : 1);
            for (int c = 0; c < 3; c++)
                s[c] += b * n->points[3 * k + c];
            s[3] += b;
        }
    }
    for (int c = 0; c < 3; c++)
        out[c] = s[c] / s[3];
}

/* The bicubic at (u, v) by de Boor's algorithm on the definition's points:
 * a curve along v for each of the five u rows, then one along u. */
static double de_boor(const double *T, int p, const double *P, int count, double t)
{
    int s = p;
    while (s < count - 1 && T[s + 1] <= t)
        s++;
    double d[4];
    for (int k = 0; k <= p; k++)
        d[k] = P[s - p + k];
    for (int r = 1; r <= p; r++)
        for (int k = p; k >= r; k--) {
            const int i = s - p + k;
            const double a = (t - T[i]) / (T[i + p + 1 - r] - T[i]);
            d[k] = (1 - a) * d[k - 1] + a * d[k];
        }
    return d[p];
}

static void bicubic_point(double u, double v, double out[3])
{
    for (int c = 0; c < 3; c++) {
        double rows[5];
        for (int i = 0; i < 5; i++) {
            double col[4];
            for (int j = 0; j < 4; j++)
                col[j] = c == 0 ? 10.0 * i : c == 1 ? 8.0 * j : bicubic_z(i, j);
            rows[i] = de_boor(BICUBIC_V, 3, col, 4, v);
        }
        out[c] = de_boor(BICUBIC_U, 3, rows, 5, u);
    }
}

/* ---- the checks ---- */

static void check_bicubic(const ic_cad_surface *s, const char *file)
{
    const ic_nurbs *n = &s->nurbs;
    if (!REQUIRE(s->is_nurbs && n->degree[0] == 3 && n->degree[1] == 3 && n->count[0] == 5 &&
                     n->count[1] == 4 && !n->weights,
                 "%s: the bicubic is a 3 x 3 patch of 5 x 4 points without weights", file))
        return;
    for (int k = 0; k < 9; k++)
        CHECK(n->knots[0][k] == BICUBIC_U[k], "%s: u knot %d: %g", file, k, n->knots[0][k]);
    for (int k = 0; k < 8; k++)
        CHECK(n->knots[1][k] == BICUBIC_V[k], "%s: v knot %d: %g", file, k, n->knots[1][k]);
    for (int i = 0; i < 5; i++)
        for (int j = 0; j < 4; j++) {
            const double *p = n->points + 3 * (i * 4 + j);
            CHECK(p[0] == 10.0 * i && p[1] == 8.0 * j && p[2] == bicubic_z(i, j),
                  "%s: control point (%d, %d) is (%g, %g, %g)", file, i, j, p[0], p[1], p[2]);
        }
    CHECK(s->domain[0][0] == 0 && s->domain[0][1] == 1 && s->domain[1][0] == 0 &&
              s->domain[1][1] == 2 && !s->periodic[0] && !s->periodic[1],
          "%s: the bicubic's domain [0, 1] x [0, 2], not periodic", file);
    double worst = 0;
    for (int a = 0; a <= 10; a++)
        for (int b = 0; b <= 10; b++) {
            double got[3], want[3];
            eval_patch(n, a / 10.0, b / 5.0, got);
            bicubic_point(a / 10.0, b / 5.0, want);
            worst = fmax(worst, dist3(got, want));
        }
    CHECK(worst <= TIER_ROUNDING * 40, "%s: the bicubic's points are off by %g mm", file, worst);
}

/* Points of a patch on a grid of its domain, each tested by `off` (its
 * distance from the surface), the largest distance returned. */
static double worst_off(const ic_nurbs *n, const double domain[2][2],
                        double (*off)(const double x[3], const void *), const void *what)
{
    double worst = 0;
    for (int a = 0; a <= 12; a++)
        for (int b = 0; b <= 12; b++) {
            double x[3];
            eval_patch(n, domain[0][0] + a * (domain[0][1] - domain[0][0]) / 12,
                       domain[1][0] + b * (domain[1][1] - domain[1][0]) / 12, x);
            worst = fmax(worst, off(x, what));
        }
    return worst;
}

typedef struct {
    ic_primitive_kind kind;
    frame f;
    double r, R, angle;
    double vrange[2]; /* the cylinder's heights */
} shape;

static double off_shape(const double x[3], const void *what)
{
    const shape *s = what;
    double radial, h;
    axial(x, s->f.center, s->f.axis, &radial, &h);
    switch (s->kind) {
    case IC_PRIM_PLANE:
        return fabs(h);
    case IC_PRIM_SPHERE:
        return fabs(dist3(x, s->f.center) - s->r);
    case IC_PRIM_CYLINDER:
        return fabs(radial - s->r) + fmax(0, fmax(s->vrange[0] - h, h - s->vrange[1]));
    case IC_PRIM_CONE: /* the generator's radius 2.5 at the placement */
        return fabs(radial - (2.5 + h * tan(s->angle))) * cos(s->angle);
    default: /* torus */
        return fabs(hypot(radial - s->R, h) - s->r);
    }
}

static shape nurbs_sphere(void)
{
    shape s = {.kind = IC_PRIM_SPHERE, .f = {{5, -3, 12}, {1, 1, 1}, {1, -1, 0}}, .r = 7.5};
    unit3(s.f.axis);
    return s;
}

static shape nurbs_cylinder(void)
{
    shape s = {.kind = IC_PRIM_CYLINDER, .f = {{-2, 4, 1}, {0, 0.6, 0.8}, {1, 0, 0}}, .r = 3,
               .vrange = {-5, 15}};
    return s;
}

/* The primitives of primitives.*, in the generator's order. */
static void placed_shapes(shape out[5])
{
    out[0] = (shape){.kind = IC_PRIM_PLANE, .f = {{1, 2, 3}, {0, 1, 1}, {1, 0, 0}}};
    out[1] = (shape){.kind = IC_PRIM_CYLINDER, .f = {{10, -4, 2}, {0.6, 0, 0.8}, {0, 1, 0}},
                     .r = 4, .vrange = {-2, 6}};
    out[2] = (shape){.kind = IC_PRIM_CONE, .f = {{-3, 5, 1}, {0, -0.6, 0.8}, {1, 0, 0}},
                     .angle = 0.4};
    out[3] = (shape){.kind = IC_PRIM_SPHERE, .f = {{2, 2, -7}, {1, 0, 0}, {0, 0, 1}}, .r = 3.25};
    out[4] = (shape){.kind = IC_PRIM_TORUS, .f = {{0, -6, 4}, {0, 0.8, 0.6}, {1, 0, 0}}, .R = 9,
                     .r = 2};
    for (int k = 0; k < 5; k++)
        unit3(out[k].f.axis);
}

static ic_cad_surface *list_file(const char *name, int *n, ic_cad_info *info)
{
    char path[600];
    path_of(path, sizeof path, name);
    ic_cad_surface *list = NULL;
    ic_error err;
    *n = 0;
    if (!REQUIRE(ic_cad_list(path, IC_CAD_ANY, &list, n, info, &err) == IC_OK, "%s: %s", name,
                 err.message))
        return NULL;
    return list;
}

static int count_type(const ic_cad_surface *list, int n, const char *type)
{
    int c = 0;
    for (int k = 0; k < n; k++)
        c += strcmp(list[k].type, type) == 0;
    return c;
}

/* How many readable NURBS of the list lie on `s` (within tol, relative to size). */
static int count_on(const ic_cad_surface *list, int n, const shape *s, double tol, double size)
{
    int c = 0;
    for (int k = 0; k < n; k++)
        if (list[k].supported && list[k].is_nurbs &&
            worst_off(&list[k].nurbs, list[k].domain, off_shape, s) <= tol * size)
            c++;
    return c;
}

static void test_bspline_step(void)
{
    int n;
    ic_cad_info info;
    ic_cad_surface *list = list_file("bspline.step", &n, &info);
    if (!list)
        return;
    CHECK(n == 3 && count_type(list, n, "B_SPLINE_SURFACE_WITH_KNOTS") == 1 &&
              count_type(list, n, "RATIONAL_B_SPLINE_SURFACE") == 2,
          "bspline.step: one B_SPLINE_SURFACE_WITH_KNOTS and two rational ones, got %d", n);
    CHECK(info.format == IC_CAD_STEP && strcmp(info.unit, "mm") == 0 && info.unit_metres == 1e-3,
          "bspline.step: unit mm, got '%s' (%g m)", info.unit, info.unit_metres);
    for (int k = 0; k < n; k++)
        if (strcmp(list[k].type, "B_SPLINE_SURFACE_WITH_KNOTS") == 0)
            check_bicubic(&list[k], "bspline.step");
    const shape sphere = nurbs_sphere(), cyl = nurbs_cylinder();
    CHECK(count_on(list, n, &sphere, STEP_DIGITS, 7.5) == 1,
          "bspline.step: one patch on the sphere");
    CHECK(count_on(list, n, &cyl, STEP_DIGITS, 15) == 1, "bspline.step: one patch on the cylinder");
    for (int k = 0; k < n; k++)
        if (list[k].nurbs.weights) /* both close along u (the full turn) and not along v */
            CHECK(list[k].periodic[0] && !list[k].periodic[1],
                  "bspline.step: #%d: periodic along u only, got %d %d", list[k].entity,
                  list[k].periodic[0], list[k].periodic[1]);
    ic_cad_list_free(list, n);
}

static void test_bspline_iges(void)
{
    int n;
    ic_cad_info info;
    ic_cad_surface *list = list_file("bspline.igs", &n, &info);
    if (!list)
        return;
    CHECK(n == 5 && count_type(list, n, "128") == 3 && count_type(list, n, "144") == 2,
          "bspline.igs: three 128 and two 144, got %d surfaces", n);
    CHECK(info.format == IC_CAD_IGES && strcmp(info.unit, "mm") == 0 && info.unit_metres == 1e-3,
          "bspline.igs: unit mm, got '%s'", info.unit);
    int bicubics = 0;
    for (int k = 0; k < n; k++)
        if (list[k].supported && !list[k].nurbs.weights) {
            check_bicubic(&list[k], "bspline.igs");
            bicubics++;
        }
    CHECK(bicubics == 1, "bspline.igs: one polynomial patch, got %d", bicubics);
    const shape sphere = nurbs_sphere(), cyl = nurbs_cylinder();
    /* each on two entries: the 128 and the 144 whose base it is */
    CHECK(count_on(list, n, &sphere, IGES_DIGITS, 7.5) == 2, "bspline.igs: the sphere twice");
    CHECK(count_on(list, n, &cyl, IGES_DIGITS, 15) == 2, "bspline.igs: the cylinder twice");
    ic_cad_list_free(list, n);
}

static void check_frame(const ic_cad_surface *s, const frame *f, const char *what)
{
    double ref[3] = {f->ref[0], f->ref[1], f->ref[2]};
    unit3(ref);
    CHECK(dist3(s->prim.axis, f->axis) <= TIER_ROUNDING && dist3(s->prim.ref_direction, ref) <=
                                                                TIER_ROUNDING,
          "%s: axis (%g, %g, %g), ref_direction (%g, %g, %g)", what, s->prim.axis[0],
          s->prim.axis[1], s->prim.axis[2], s->prim.ref_direction[0], s->prim.ref_direction[1],
          s->prim.ref_direction[2]);
}

static void check_primitive(const ic_cad_surface *s, const shape *want)
{
    char what[80];
    snprintf(what, sizeof what, "primitives.step #%d (%s)", s->entity, s->type);
    if (!REQUIRE(s->supported && !s->is_nurbs && s->prim.kind == want->kind, "%s: kind %d", what,
                 (int)s->prim.kind))
        return;
    check_frame(s, &want->f, what);
    double center[3];
    memcpy(center, want->f.center, sizeof center);
    if (want->kind == IC_PRIM_CONE) /* apex below the radius-2.5 circle at the placement */
        for (int k = 0; k < 3; k++)
            center[k] -= 2.5 / tan(want->angle) * want->f.axis[k];
    CHECK(dist3(s->prim.center, center) <= TIER_ROUNDING * 20, "%s: center (%g, %g, %g)", what,
          s->prim.center[0], s->prim.center[1], s->prim.center[2]);
    if (want->kind == IC_PRIM_PLANE)
        CHECK(dist3(s->prim.normal, want->f.axis) <= TIER_ROUNDING, "%s: normal", what);
    if (want->kind == IC_PRIM_CONE)
        CHECK(fabs(s->prim.half_angle - want->angle) <= TIER_ROUNDING, "%s: half-angle %.17g",
              what, s->prim.half_angle);
    if (want->kind == IC_PRIM_TORUS)
        CHECK(s->prim.major_radius == want->R, "%s: major radius %g", what, s->prim.major_radius);
    if (want->kind != IC_PRIM_PLANE && want->kind != IC_PRIM_CONE)
        CHECK(s->prim.radius == want->r, "%s: radius %g", what, s->prim.radius);
}

static void test_primitives_step(void)
{
    static const char *const types[5] = {"PLANE", "CYLINDRICAL_SURFACE", "CONICAL_SURFACE",
                                         "SPHERICAL_SURFACE", "TOROIDAL_SURFACE"};
    int n;
    ic_cad_info info;
    ic_cad_surface *list = list_file("primitives.step", &n, &info);
    if (!list)
        return;
    shape want[5];
    placed_shapes(want);
    CHECK(n == 6, "primitives.step: six surfaces, got %d", n);
    for (int t = 0; t < 5; t++) {
        CHECK(count_type(list, n, types[t]) == 1, "primitives.step: one %s", types[t]);
        for (int k = 0; k < n; k++)
            if (strcmp(list[k].type, types[t]) == 0)
                check_primitive(&list[k], &want[t]);
    }
    for (int k = 0; k < n; k++) {
        if (strcmp(list[k].type, "SURFACE_OF_REVOLUTION") != 0)
            continue;
        char who[64];
        snprintf(who, sizeof who, "#%d (SURFACE_OF_REVOLUTION)", list[k].entity);
        CHECK(!list[k].supported && strstr(list[k].problem, who) &&
                  strstr(list[k].problem, "not supported"),
              "primitives.step: the surface of revolution is not read, saying so: '%s'",
              list[k].problem);
    }
    ic_cad_list_free(list, n);
}

static void test_primitives_iges(void)
{
    int n;
    ic_cad_info info;
    ic_cad_surface *list = list_file("primitives.igs", &n, &info);
    if (!list)
        return;
    CHECK(n == 10 && count_type(list, n, "128") == 5 && count_type(list, n, "144") == 5,
          "primitives.igs: five 144 on five 128, got %d surfaces", n);
    shape want[5];
    placed_shapes(want);
    static const double size[5] = {5, 10, 10, 3.25, 11};
    for (int t = 0; t < 5; t++)
        CHECK(count_on(list, n, &want[t], IGES_DIGITS, size[t]) == 2,
              "primitives.igs: primitive %d lies under one 128 and its 144", t);
    ic_cad_list_free(list, n);
}

static ic_status read_one(const char *name, int entity, ic_cad_surface *s, ic_error *err)
{
    char path[600];
    path_of(path, sizeof path, name);
    return ic_cad_read(path, IC_CAD_ANY, entity, s, err);
}

/* Reading `entity` fails with `code` and a message holding each of the
 * `words` (up to three, NULL-ended). */
static void check_refused(const char *name, int entity, ic_status code, const char *w1,
                          const char *w2)
{
    ic_cad_surface s;
    ic_error err;
    const ic_status st = read_one(name, entity, &s, &err);
    CHECK(st == code && strstr(err.message, name) && strstr(err.message, w1) &&
              (!w2 || strstr(err.message, w2)),
          "%s, entity %d: status %d, message '%s' (wanted '%s', '%s')", name, entity, (int)st,
          err.message, w1, w2 ? w2 : "");
    ic_cad_surface_clear(&s);
}

static void test_small_step_shapes(void)
{
    ic_cad_surface s;
    ic_error err;
    if (REQUIRE(read_one("small.step", 10, &s, &err) == IC_OK, "small.step #10: %s", err.message)) {
        CHECK(strcmp(s.name, "it's a cylinder") == 0, "#10: name '%s' ('' undone)", s.name);
        const double ref[3] = {sqrt(0.5), sqrt(0.5), 0}, z[3] = {0, 0, 1};
        CHECK(dist3(s.prim.ref_direction, ref) <= TIER_ROUNDING && dist3(s.prim.axis, z) == 0,
              "#10: the placement's directions made unit");
        CHECK(strcmp(s.unit, "inch") == 0 && s.unit_metres == 0.0254,
              "small.step: the unit of its GLOBAL_UNIT_ASSIGNED_CONTEXT, inch: '%s' %g", s.unit,
              s.unit_metres);
    }
    ic_cad_surface_clear(&s);
    if (REQUIRE(read_one("small.step", 11, &s, &err) == IC_OK, "small.step #11: %s", err.message)) {
        const double apex_z = 3.5 - 1 / tan(IC_PI / 6); /* radius 1, 30 degrees */
        CHECK(fabs(s.prim.half_angle - IC_PI / 6) <= TIER_ROUNDING &&
                  fabs(s.prim.center[2] - apex_z) <= TIER_ROUNDING * 4,
              "#11: semi_angle 30 in degrees, apex below: %.17g, %.17g", s.prim.half_angle,
              s.prim.center[2]);
    }
    ic_cad_surface_clear(&s);
    if (REQUIRE(read_one("small.step", 12, &s, &err) == IC_OK, "small.step #12: %s", err.message))
        CHECK(s.prim.kind == IC_PRIM_PLANE && s.prim.normal[2] == 1 && s.prim.ref_direction[0] == 1 &&
                  isinf(s.domain[0][0]) && isinf(s.domain[1][1]),
              "#12: a plane with the default axes ($), unbounded");
    ic_cad_surface_clear(&s);
    if (REQUIRE(read_one("small.step", 40, &s, &err) == IC_OK, "small.step #40: %s", err.message))
        CHECK(s.entity == 10 && s.prim.kind == IC_PRIM_CYLINDER && s.prim.radius == 2.5,
              "#40: the face leads to its cylinder #10, got #%d", s.entity);
    ic_cad_surface_clear(&s);
}

static void test_small_step_splines(void)
{
    ic_cad_surface s;
    ic_error err;
    static const double knots_u[5] = {0, 0, 0.5, 1, 1};
    if (REQUIRE(read_one("small.step", 30, &s, &err) == IC_OK, "small.step #30: %s", err.message)) {
        int same = s.nurbs.count[0] == 3 && s.nurbs.count[1] == 2 && !s.nurbs.weights;
        for (int k = 0; same && k < 5; k++)
            same = s.nurbs.knots[0][k] == knots_u[k];
        CHECK(same, "#30: 3 x 2 points, multiplicities (2, 1, 2) expanded");
        /* control_points_list[i][j]: (i, j) = (1, 1) is #23 = (1, 1, 1) */
        CHECK(same && s.nurbs.points[3 * 3 + 2] == 1 && s.nurbs.points[3 * 1 + 1] == 1,
              "#30: the points in the order [u][v]");
        CHECK(strcmp(s.name, "bilinear") == 0, "#30: name '%s'", s.name);
    }
    ic_cad_surface_clear(&s);
    if (REQUIRE(read_one("small.step", 31, &s, &err) == IC_OK, "small.step #31: %s", err.message)) {
        const double w[6] = {1, 2, 1, 1, 0.5, 1};
        int same = s.nurbs.weights != NULL && strcmp(s.type, "RATIONAL_B_SPLINE_SURFACE") == 0;
        for (int k = 0; same && k < 6; k++)
            same = s.nurbs.weights[k] == w[k];
        CHECK(same, "#31: the complex instance's weights [u][v]");
        CHECK(strcmp(s.name, "rational") == 0, "#31: the name from REPRESENTATION_ITEM: '%s'",
              s.name);
    }
    ic_cad_surface_clear(&s);
}

static void test_small_step_errors(void)
{
    check_refused("small.step", 32, IC_ERR_INVALID, "#32 (B_SPLINE_SURFACE_WITH_KNOTS)",
                  "multiplicities add up to 4");
    check_refused("small.step", 33, IC_ERR_INVALID, "#33 (OFFSET_SURFACE)", "not supported");
    check_refused("small.step", 41, IC_ERR_INVALID, "#41", "not a surface");
    check_refused("small.step", 1, IC_ERR_INVALID, "#1 is a CARTESIAN_POINT", "not a surface");
    check_refused("small.step", 999, IC_ERR_INVALID, "#999", "no such instance");
    ic_cad_surface s;
    ic_error err;
    if (REQUIRE(read_one("small.step", 34, &s, &err) == IC_OK, "small.step #34: %s", err.message))
        CHECK(!s.periodic[0] && !s.periodic[1], "#34: u_closed .T. on an open patch: not periodic");
    ic_cad_surface_clear(&s);
}

static void test_small_iges(void)
{
    ic_cad_surface s;
    ic_error err;
    /* control points (0,0,0) (1,0,0) (0,1,0) (1,1,1), u fastest, moved by DE 1:
     * (x, y, z) -> (10 - y, x, z); the 144 DE 5 then by its DE 13, z + 5, and
     * that by DE 15, x + 100 */
    static const double want[4][3] = {{10, 0, 0}, {9, 0, 0}, {10, 1, 0}, {9, 1, 1}};
    for (int e = 3; e <= 5; e += 2) {
        if (!REQUIRE(read_one("small.igs", e, &s, &err) == IC_OK, "small.igs DE %d: %s", e,
                     err.message))
            continue;
        int same = s.nurbs.count[0] == 2 && s.nurbs.count[1] == 2;
        for (int k = 0; same && k < 4; k++) {
            const double moved[3] = {want[k][0] + (e == 5 ? 100 : 0), want[k][1],
                                     want[k][2] + (e == 5 ? 5 : 0)};
            same = dist3(s.nurbs.points + 3 * k, moved) == 0;
        }
        CHECK(same, "small.igs DE %d: the points reordered [u][v] and moved by the 124s", e);
        CHECK(s.domain[1][1] == 2 && strcmp(s.unit, "inch") == 0 && s.unit_metres == 0.0254,
              "small.igs DE %d: v to 2, unit inch ('%s')", e, s.unit);
        CHECK(strcmp(s.name, e == 3 ? "PATCH" : "TRIM") == 0, "DE %d: name '%s'", e, s.name);
        ic_cad_surface_clear(&s);
    }
    check_refused("small.igs", 7, IC_ERR_INVALID, "DE 7 (entity 108)", "not read");
    check_refused("small.igs", 9, IC_ERR_INVALID, "DE 9 (entity 144)", "base surface DE 7");
    check_refused("small.igs", 11, IC_ERR_INVALID, "DE 11 (entity 110)", "not a surface");
    check_refused("small.igs", 4, IC_ERR_INVALID, "DE 4", "no such directory entry");
    check_refused("small.igs", 17, IC_ERR_INVALID, "DE 17", "no such directory entry");
}

static char *slurp(const char *name, size_t *len)
{
    char path[600];
    path_of(path, sizeof path, name);
    FILE *f = fopen(path, "rb");
    char *data = f ? malloc(1 << 16) : NULL;
    *len = data ? fread(data, 1, 1 << 16, f) : 0;
    if (f)
        fclose(f);
    return data;
}

/* Every prefix of a file read as a whole file: a result or an error with a
 * message, never a crash (AddressSanitizer watches the reads); the cut
 * inside a record is a parse error with a line. */
static void test_truncated(const char *name, int step)
{
    size_t len;
    char *data = slurp(name, &len);
    if (!REQUIRE(data && len > 100, "%s read", name))
        return;
    int silent = 0;
    for (size_t cut = 0; cut < len; cut++) {
        char *copy = malloc(cut ? cut : 1);
        memcpy(copy, data, cut);
        ic_cad_surface *list = NULL;
        int n = 0;
        ic_error err;
        if (ic_cad_list_buffer(copy, cut, IC_CAD_ANY, &list, &n, NULL, &err) != IC_OK)
            silent += err.message[0] == '\0';
        ic_cad_list_free(list, n);
        free(copy);
    }
    CHECK(silent == 0, "%s: %d prefixes failed without a message", name, silent);
    ic_cad_surface s;
    ic_error err;
    const ic_status st = ic_cad_read_buffer(data, len / 2, IC_CAD_ANY, 10, &s, &err);
    CHECK(st != IC_OK && (!step || (st == IC_ERR_PARSE && strstr(err.message, "line"))),
          "%s cut in half: %s: '%s'", name, step ? "a parse error with its line" : "an error",
          err.message);
    free(data);
}

/* small.igs with "\r\n" line ends, and as fixed 80-byte records without
 * line ends: the same surfaces. */
static void test_iges_layouts(void)
{
    size_t len;
    char *text = slurp("small.igs", &len);
    if (!REQUIRE(text && len > 0, "small.igs read"))
        return;
    char *crlf = malloc(2 * len), *fixed = malloc(2 * len);
    size_t ncrlf = 0, nfixed = 0, column = 0;
    for (size_t k = 0; k < len; k++) {
        if (text[k] == '\n') {
            crlf[ncrlf++] = '\r';
            for (; column < 80; column++)
                fixed[nfixed++] = ' ';
            column = 0;
        } else {
            fixed[nfixed++] = text[k];
            column++;
        }
        crlf[ncrlf++] = text[k];
    }
    const char *variants[2] = {crlf, fixed};
    const size_t lengths[2] = {ncrlf, nfixed};
    for (int v = 0; v < 2; v++) {
        ic_cad_surface *list = NULL;
        int n = 0;
        ic_error err;
        const ic_status st = ic_cad_list_buffer(variants[v], lengths[v], IC_CAD_IGES, &list, &n,
                                                NULL, &err);
        CHECK(st == IC_OK && n == 4 && list[0].supported && list[0].entity == 3 &&
                  list[0].nurbs.points[3 * 3 + 2] == 1,
              "small.igs %s: status %d, %d surfaces (%s)", v ? "in 80-byte records" : "with CRLF",
              (int)st, n, st == IC_OK ? "" : err.message);
        ic_cad_list_free(list, n);
    }
    free(crlf);
    free(fixed);
    free(text);
}

static void test_bad_files(void)
{
    ic_cad_surface s;
    ic_error err;
    static const char garbage[] = "\x7f" "ELF\x01\x02 not a CAD file \xff\xfe";
    CHECK(ic_cad_read_buffer(garbage, sizeof garbage - 1, IC_CAD_ANY, 1, &s, &err) == IC_ERR_PARSE &&
              strstr(err.message, "neither a STEP file"),
          "garbage: '%s'", err.message);
    size_t len;
    char *step = slurp("small.step", &len);
    CHECK(step && ic_cad_read_buffer(step, len, IC_CAD_IGES, 10, &s, &err) == IC_ERR_INVALID &&
              strstr(err.message, "not an IGES file: it is a STEP file"),
          "a STEP file read as IGES: '%s'", err.message);
    free(step);
    char *iges = slurp("small.igs", &len);
    if (iges && len > 400) { /* an IGES whose directory lost its last record */
        char *d = strstr(iges, "D0000016");
        if (REQUIRE(d != NULL, "small.igs has D0000016"))
            memset(d - 72, ' ', 80); /* the record blanked: passed over */
        CHECK(ic_cad_read_buffer(iges, len, IC_CAD_ANY, 3, &s, &err) == IC_ERR_PARSE &&
                  strstr(err.message, "odd number"),
              "IGES directory cut: '%s'", err.message);
    }
    free(iges);
    CHECK(read_one("no-such-file.step", 1, &s, &err) == IC_ERR_IO &&
              strstr(err.message, "no-such-file.step"),
          "a missing file: '%s'", err.message);
}

/* ---- problem files naming CAD surfaces ---- */

/* A problem of one surface `entry` (JSON) loaded from text; files are named
 * by absolute paths under the source directory. */
static ic_status load_one(ic_problem **p, const char *entry, ic_error *err)
{
    char json[2048];
    snprintf(json, sizeof json, "{\"surfaces\": [%s, {\"type\": \"sphere\", \"radius\": 1}]}",
             entry);
    return ic_problem_parse(p, json, strlen(json), err);
}

static void test_problem_file(void)
{
    char path[600];
    snprintf(path, sizeof path, "%s/tests/data/cad/problem-step-iges.json", source_dir);
    ic_problem *p = NULL;
    ic_error err;
    if (!REQUIRE(ic_problem_load(&p, path, &err) == IC_OK, "problem-step-iges.json: %s: %s",
                 err.path, err.message))
        return;
    double worst = 0, x[3], want[3];
    for (int a = 0; a <= 4; a++) {
        const double at[2] = {a / 4.0, 2 - a / 3.0};
        if (ic_surface_eval(ic_problem_surface(p, 0), x, at, &err) == IC_OK) {
            bicubic_point(at[0], at[1], want);
            worst = fmax(worst, dist3(x, want));
        } else {
            worst = INFINITY;
        }
    }
    CHECK(worst <= TIER_ROUNDING * 40, "the problem's STEP patch is the bicubic: off by %g", worst);
    double domain[2][2];
    int periodic[2];
    ic_surface_get_domain(ic_problem_surface(p, 1), domain, periodic);
    const shape sphere = nurbs_sphere();
    worst = 0;
    for (int a = 0; a <= 6; a++) {
        const double at[2] = {a, -1.5 + a / 2.0};
        worst = ic_surface_eval(ic_problem_surface(p, 1), x, at, &err) == IC_OK
                    ? fmax(worst, off_shape(x, &sphere))
                    : INFINITY;
    }
    CHECK(worst <= IGES_DIGITS * 7.5 && periodic[0] &&
              fabs(domain[0][1] - 2 * IC_PI) <= IGES_DIGITS * 2 * IC_PI,
          "the problem's IGES sphere: off by %g, periodic along u", worst);
    ic_problem_free(p);
}

static void test_problem_primitives(void)
{
    char entry[1024];
    ic_problem *p = NULL;
    ic_error err;
    snprintf(entry, sizeof entry,
             "{\"type\": \"step\", \"file\": \"%s/tests/data/cad/small.step\", \"entity\": 15}",
             source_dir);
    if (REQUIRE(load_one(&p, entry, &err) == IC_OK, "small.step #15: %s", err.message)) {
        double x[3];
        const double at[2] = {1.0, 0.75}; /* location (1, -2, 3.5), radius 1.5, standard axes */
        const double want[3] = {1 + 1.5 * cos(1.0), -2 + 1.5 * sin(1.0), 3.5 + 0.75};
        CHECK(ic_surface_eval(ic_problem_surface(p, 0), x, at, &err) == IC_OK &&
                  dist3(x, want) <= TIER_ROUNDING * 8,
              "small.step #15: the cylinder's point (%g, %g, %g)", x[0], x[1], x[2]);
    }
    ic_problem_free(p);
    p = NULL;
    /* rotated: the primitive follows the file's placement */
    snprintf(entry, sizeof entry,
             "{\"type\": \"step\", \"file\": \"%s/tests/data/cad/small.step\", \"entity\": 10}",
             source_dir);
    if (REQUIRE(load_one(&p, entry, &err) == IC_OK, "small.step #10: %s", err.message)) {
        double x[3];
        const double at[2] = {0, 0.5}, r = 2.5 / sqrt(2.0);
        const double want[3] = {1 + r, -2 + r, 4};
        CHECK(ic_surface_eval(ic_problem_surface(p, 0), x, at, &err) == IC_OK &&
                  dist3(x, want) <= TIER_ROUNDING * 8,
              "small.step #10: the seam along ref_direction (1, 1, 0)");
    }
    ic_problem_free(p);
}

/* A problem naming a CAD surface wrongly: the JSON path and a message
 * naming the file and the entity. */
static void check_problem_refused(const char *type, const char *file, int entity,
                                  const char *where, const char *w1, const char *w2)
{
    char entry[1024];
    snprintf(entry, sizeof entry,
             "{\"type\": \"%s\", \"file\": \"%s/tests/data/cad/%s\", \"entity\": %d}", type,
             source_dir, file, entity);
    ic_problem *p = NULL;
    ic_error err;
    const ic_status st = load_one(&p, entry, &err);
    const int names_file = entity > 0; /* a bad entity number is the problem file's alone */
    CHECK(st != IC_OK && !p && strcmp(err.path, where) == 0 &&
              (!names_file || strstr(err.message, file)) &&
              strstr(err.message, w1) && (!w2 || strstr(err.message, w2)),
          "%s %s %d: %s: %s", type, file, entity, err.path, err.message);
    ic_problem_free(p);
}

static void test_problem_errors(void)
{
    check_problem_refused("step", "small.step", 9999, "surfaces[0].entity", "#9999",
                          "no such instance");
    check_problem_refused("step", "small.step", 33, "surfaces[0].entity", "#33 (OFFSET_SURFACE)",
                          "not supported");
    check_problem_refused("iges", "small.igs", 7, "surfaces[0].entity", "DE 7 (entity 108)",
                          "not read");
    check_problem_refused("iges", "small.step", 10, "surfaces[0].file", "not an IGES file",
                          NULL);
    check_problem_refused("step", "missing.step", 10, "surfaces[0].file", "cannot read", NULL);
    check_problem_refused("step", "small.step", 0, "surfaces[0].entity", "expected the entity",
                          NULL);
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: test_cad SOURCE_DIR\n");
        return 2;
    }
    snprintf(source_dir, sizeof source_dir, "%s", argv[1]);
    test_bspline_step();
    test_bspline_iges();
    test_primitives_step();
    test_primitives_iges();
    test_small_step_shapes();
    test_small_step_splines();
    test_small_step_errors();
    test_small_iges();
    test_truncated("small.step", 1);
    test_truncated("small.igs", 0);
    test_iges_layouts();
    test_bad_files();
    test_problem_file();
    test_problem_primitives();
    test_problem_errors();
    return harness_finish("test_cad");
}
