/* Whole traces with placed primitives (problem files with "axis" and
 * "ref_direction") against closed-form lengths, and against the same
 * problems with the placed surfaces written as formulas (their twins, in
 * the frames derived by hand in tests/placed_frames.h): the same curves, the
 * same lengths, and a search as complete and proven as for primitives in
 * standard position. */
#include <stdio.h>
#include <string.h>

#include "curve_lengths.h"
#include "harness.h"
#include "intercurve.h"
#include "placed_frames.h"
#include "traced_example.h"

#define PI_L 3.14159265358979323846264338327950288L
#define PI 3.14159265358979323846

/* Center of the tilted cases and the half-width of their box. */
static const double C[3] = {0.2, -0.1, 0.3};
#define HALF_BOX 2.5

/* The loop y = 0.7 cos t, z = 0.7 sin t, x = sqrt(1 - y^2) of the
 * cylinders x^2 + y^2 = 1 and y^2 + z^2 = 0.49. */
static long double loop_speed(long double t)
{
    const long double c = cosl(t), s = sinl(t), dx = 0.49L * c * s / sqrtl(1 - 0.49L * c * c);
    return sqrtl(0.49L + dx * dx);
}

/* The ellipse x = z = cos t, y = sin t in the plane x = z, one of the two
 * curves of x^2 + y^2 = 1 and y^2 + z^2 = 1 (semi-axes sqrt 2 and 1). */
static long double ellipse_speed(long double t)
{
    const long double s = sinl(t), c = cosl(t);
    return sqrtl(2 * s * s + c * c);
}

/* A problem given as text, traced whole with the defaults and its box. */
static int trace_text(traced *t, const char *name, const char *json)
{
    ic_error err;
    ic_trace_options opt;
    ic_trace_defaults(&opt);
    memset(t, 0, sizeof *t);
    ic_status st = ic_problem_parse(&t->problem, json, strlen(json), &err);
    if (st == IC_OK) {
        opt.has_box = ic_problem_box(t->problem, opt.box);
        st = ic_pair_new(&t->pair, ic_problem_surface(t->problem, 0),
                         ic_problem_surface(t->problem, 1), &err);
    }
    if (st == IC_OK)
        st = ic_trace(&t->res, t->pair, &opt, &err);
    CHECK(st == IC_OK, "%s: %s", name, err.message);
    return st == IC_OK ? 0 : -1;
}

/* What a trace must show: n closed curves of length L each (TIER_LENGTH),
 * of the shape, `branches` branch points, the search complete and proven. */
typedef struct {
    int n;
    double L;
    ic_shape shape;
    int branches;
} expected;

/* Checks t against want; fills lengths[] (n of them, in trace order). */
static void check_traced(const traced *t, const char *name, const expected *want, double *lengths)
{
    const ic_trace_report *rep = ic_trace_result_report(t->res);
    const int n = ic_trace_result_num_curves(t->res);
    CHECK(n == want->n, "%s: %d curves, not %d", name, n, want->n);
    CHECK(rep->tracer_complete && rep->proven, "%s: the search is complete %d, proven %d", name,
          rep->tracer_complete, rep->proven);
    int branches = 0;
    for (int i = 0; i < ic_trace_result_num_specials(t->res); i++)
        branches += ic_trace_result_special(t->res, i)->type == IC_POINT_BRANCH;
    CHECK(ic_trace_result_num_specials(t->res) == want->branches && branches == want->branches,
          "%s: %d points met, not %d branch points", name, ic_trace_result_num_specials(t->res),
          want->branches);
    double worst = 0;
    for (int i = 0; i < n && i < want->n; i++) {
        const ic_trace_curve *c = ic_trace_result_curve(t->res, i);
        lengths[i] = c->length;
        worst = fmax(worst, fabs(c->length - want->L) / want->L);
        CHECK(c->closed && c->shape == want->shape &&
                  fabs(c->length - want->L) <= TIER_LENGTH * want->L,
              "%s curve %d: closed %d, %s, length %.17g of %.17g", name, i, c->closed,
              ic_shape_name(c->shape), c->length, want->L);
    }
    printf("%-34s %d closed %s curves, length error %.2g\n", name, n, ic_shape_name(want->shape),
           worst);
}

/* The placed problem and its formula twin traced: each as expected, and
 * their lengths the same in order of size (both within TIER_LENGTH of L). */
static void check_pair(const char *name, const traced *placed, const traced *twin,
                       const expected *want)
{
    double a[8] = {0}, b[8] = {0};
    char twin_name[96];
    snprintf(twin_name, sizeof twin_name, "%s (formulas)", name);
    check_traced(placed, name, want, a);
    check_traced(twin, twin_name, want, b);
    for (int i = 0; i < want->n && i < 8; i++)
        CHECK(fabs(a[i] - b[i]) <= TIER_LENGTH * want->L,
              "%s: curve %d is %.17g long, its twin's %.17g", name, i, a[i], b[i]);
}

static void format_box(char *out, size_t size)
{
    snprintf(out, size, "[[%.17g, %.17g], [%.17g, %.17g], [%.17g, %.17g]]", C[0] - HALF_BOX,
             C[0] + HALF_BOX, C[1] - HALF_BOX, C[1] + HALF_BOX, C[2] - HALF_BOX, C[2] + HALF_BOX);
}

/* examples/placed-cylinders.json (radius 1 along z, 0.7 along x): two loops. */
static void test_example(const char *dir)
{
    static const char *twin_json =
        "{\"surfaces\": [{\"name\": \"upright\", \"type\": \"implicit\", \"f\": \"x^2 + y^2 - 1\"},"
        " {\"name\": \"lying\", \"type\": \"implicit\", \"f\": \"y^2 + z^2 - 0.49\"}],"
        " \"box\": [[-1.5, 1.5], [-1.5, 1.5], [-1.5, 1.5]]}";
    const expected want = {2, simpson_length(loop_speed, 0, 2 * PI_L), IC_SHAPE_GENERAL, 0};
    traced p = {0}, q = {0};
    if (trace_example(&p, dir, "placed-cylinders.json") == 0 &&
        trace_text(&q, "placed-cylinders twin", twin_json) == 0)
        check_pair("placed-cylinders.json", &p, &q, &want);
    release(&p);
    release(&q);
}

/* Steinmetz: radius 1 along x (placed) and along z: two ellipses through
 * the branch points (0, +-1, 0). */
static void test_steinmetz(void)
{
    static const char *placed_json =
        "{\"surfaces\": [{\"type\": \"cylinder\", \"radius\": 1},"
        " {\"type\": \"cylinder\", \"radius\": 1, \"axis\": [2, 0, 0]}],"
        " \"box\": [[-1.5, 1.5], [-1.5, 1.5], [-1.5, 1.5]]}";
    static const char *twin_json =
        "{\"surfaces\": [{\"type\": \"implicit\", \"f\": \"x^2 + y^2 - 1\"},"
        " {\"type\": \"implicit\", \"f\": \"y^2 + z^2 - 1\"}],"
        " \"box\": [[-1.5, 1.5], [-1.5, 1.5], [-1.5, 1.5]]}";
    const expected want = {2, simpson_length(ellipse_speed, 0, 2 * PI_L), IC_SHAPE_PLANAR, 2};
    traced p = {0}, q = {0};
    if (trace_text(&p, "Steinmetz", placed_json) == 0 &&
        trace_text(&q, "Steinmetz twin", twin_json) == 0) {
        check_pair("Steinmetz, one cylinder along x", &p, &q, &want);
        int at = 0;
        for (int i = 0; i < ic_trace_result_num_specials(p.res); i++) {
            const double *x = ic_trace_result_special(p.res, i)->xyz;
            at += hypot(hypot(x[0], fabs(x[1]) - 1), x[2]) <= TIER_LOCATED;
        }
        CHECK(at == 2, "Steinmetz: the branch points at (0, +-1, 0)");
    }
    release(&p);
    release(&q);
}

/* A sphere of radius 1.5 and a parametric cylinder of radius 1 along
 * (1, 2, 2), both about C: the circles of radius 1 at +-sqrt(1.25) along
 * the axis, 2 pi long each. */
static void test_tilted_cylinder(void)
{
    char box[200], sphere[200], placed_json[1024], twin_json[4096], xyz[3][512];
    format_box(box, sizeof box);
    snprintf(sphere, sizeof sphere,
             "{\"type\": \"implicit\", \"f\": \"(x - (%.17g))^2 + (y - (%.17g))^2 + "
             "(z - (%.17g))^2 - 2.25\"}",
             C[0], C[1], C[2]);
    snprintf(placed_json, sizeof placed_json,
             "{\"surfaces\": [%s, {\"type\": \"cylinder\", \"form\": \"parametric\", "
             "\"radius\": 1, \"center\": [%.17g, %.17g, %.17g], \"axis\": [1, 2, 2], "
             "\"ref_direction\": [1, 0, 0], \"domain\": [[0, \"2*pi\"], [-10, 10]]}], \"box\": %s}",
             sphere, C[0], C[1], C[2], box);
    placed_frame f;
    tilted_frame(&f, C);
    static const char *const local[3] = {"cos(u)", "sin(u)", "v"};
    twin_parametric(xyz, &f, local);
    snprintf(twin_json, sizeof twin_json,
             "{\"surfaces\": [%s, {\"type\": \"parametric\", \"xyz\": [\"%s\", \"%s\", \"%s\"], "
             "\"domain\": [[0, \"2*pi\"], [-10, 10]], \"periodic\": [true, false]}], \"box\": %s}",
             sphere, xyz[0], xyz[1], xyz[2], box);
    const expected want = {2, 2 * PI, IC_SHAPE_CIRCLE, 0};
    traced p = {0}, q = {0};
    if (trace_text(&p, "tilted cylinder", placed_json) == 0 &&
        trace_text(&q, "tilted cylinder twin", twin_json) == 0)
        check_pair("sphere and tilted cylinder", &p, &q, &want);
    release(&p);
    release(&q);
}

/* A parametric torus (R = 2, r = 0.5) along (2, 4, 4) with its seam along
 * y, and a sphere of radius 2 about its center: on both, |d|^2 = 4 and
 * (|d|^2 + R^2 - r^2)^2 = 4 R^2 rho^2, so two circles of radius rho =
 * (4 + 4 - 0.25)/4 = 1.9375 about the axis. */
static void test_tilted_torus(void)
{
    char box[200], json[1024];
    format_box(box, sizeof box);
    snprintf(json, sizeof json,
             "{\"surfaces\": [{\"type\": \"torus\", \"form\": \"parametric\", "
             "\"major_radius\": 2, \"minor_radius\": 0.5, \"center\": [%.17g, %.17g, %.17g], "
             "\"axis\": [2, 4, 4], \"ref_direction\": [0, 1, 0]}, {\"type\": \"sphere\", "
             "\"radius\": 2, \"center\": [%.17g, %.17g, %.17g]}], \"box\": %s}",
             C[0], C[1], C[2], C[0], C[1], C[2], box);
    const expected want = {2, 2 * PI * 1.9375, IC_SHAPE_CIRCLE, 0};
    traced t = {0};
    double lengths[2];
    if (trace_text(&t, "tilted torus", json) == 0)
        check_traced(&t, "sphere and tilted torus", &want, lengths);
    release(&t);
}

/* A cone of half-angle 0.4, apex C, axis (1, 2, 2), cut by the parametric
 * plane normal to the axis at distance 1 from the apex (with a
 * ref_direction): one circle of radius tan 0.4. */
static void test_tilted_cone(void)
{
    char box[200], json[1024];
    format_box(box, sizeof box);
    const double at[3] = {C[0] + 1.0 / 3, C[1] + 2.0 / 3, C[2] + 2.0 / 3};
    snprintf(json, sizeof json,
             "{\"surfaces\": [{\"type\": \"cone\", \"half_angle\": 0.4, "
             "\"center\": [%.17g, %.17g, %.17g], \"axis\": [1, 2, 2]}, {\"type\": \"plane\", "
             "\"form\": \"parametric\", \"normal\": [1, 2, 2], \"ref_direction\": [0, 0, 1], "
             "\"center\": [%.17g, %.17g, %.17g], \"domain\": [[-2, 2], [-2, 2]]}], "
             "\"box\": %s}",
             C[0], C[1], C[2], at[0], at[1], at[2], box);
    const expected want = {1, 2 * PI * tan(0.4), IC_SHAPE_CIRCLE, 0};
    traced t = {0};
    double lengths[1];
    if (trace_text(&t, "tilted cone", json) == 0)
        check_traced(&t, "tilted cone and plane", &want, lengths);
    release(&t);
}

/* The cylinder #163 of the OpenCASCADE-written tests/data/cad/primitives.step
 * (radius 4 mm, axis (0.6, 0, 0.8) through (10, -4, 2): the generator's
 * definition, tests/cad/gen_cad_files.cpp) cut by the plane through that
 * point normal to its axis: one circle of length 8 pi. */
static void test_step_cylinder(const char *dir)
{
    char json[1024];
    snprintf(json, sizeof json,
             "{\"surfaces\": [{\"type\": \"step\", \"file\": "
             "\"%s/tests/data/cad/primitives.step\", \"entity\": 163, \"form\": "
             "\"parametric\", \"domain\": [[0, 6.283185307179586], [-5, 5]], \"periodic\": "
             "[true, false]}, {\"type\": \"plane\", \"center\": [10, -4, 2], \"normal\": "
             "[0.6, 0, 0.8]}]}",
             dir);
    const expected want = {1, 8 * PI, IC_SHAPE_CIRCLE, 0};
    traced t = {0};
    double lengths[1];
    if (trace_text(&t, "STEP cylinder", json) == 0)
        check_traced(&t, "the STEP file's tilted cylinder and a plane", &want, lengths);
    release(&t);
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : ".";
    test_step_cylinder(dir);
    test_example(dir);
    test_steinmetz();
    test_tilted_cylinder();
    test_tilted_torus();
    test_tilted_cone();
    return harness_finish("test_placed_trace");
}
