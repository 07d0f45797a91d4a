// The public headers from C++: every header included, at least one function
// of each called and linked against the shared library (extern "C" guards,
// IC_API exports). A sphere of radius 2 cut by the plane z = 1 is the circle
// of radius sqrt(3) in that plane, which every check below derives from.
#include "intercurve.h"
#include "intercurve/common.h"
#include "intercurve/expr.h"
#include "intercurve/jet.h"
#include "intercurve/local.h"
#include "intercurve/plot.h"
#include "intercurve/problem.h"
#include "intercurve/surface.h"
#include "intercurve/trace.h"
#include "intercurve/writers.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "harness.h"

static const double PI = 3.14159265358979323846;

// common.h and intercurve.h
static void check_common(void)
{
    CHECK(std::strcmp(ic_status_name(IC_ERR_DOMAIN), "domain error") == 0, "ic_status_name: %s",
          ic_status_name(IC_ERR_DOMAIN));
    ic_error err;
    std::memset(&err, 'x', sizeof err);
    ic_error_clear(&err);
    CHECK(err.code == IC_OK && err.message[0] == '\0', "ic_error_clear left code %d",
          (int)err.code);
    CHECK(std::string(IC_VERSION) == IC_EXPECTED_VERSION, "IC_VERSION %s, the project says %s",
          IC_VERSION, IC_EXPECTED_VERSION);
}

// jet.h: exp(x) about 0 is 1 + x + x^2/2 + x^3/6
static void check_jet(void)
{
    ic_jet_space *sp = NULL;
    ic_error err;
    CHECK(ic_jet_space_new(&sp, 1, 3, &err) == IC_OK, "ic_jet_space_new: %s", err.message);
    if (!sp)
        return;
    CHECK(ic_jet_space_num_vars(sp) == 1 && ic_jet_space_len(sp) == 4, "space of %d vars, %d",
          ic_jet_space_num_vars(sp), ic_jet_space_len(sp));
    double x[4], e[4];
    ic_jet_set_var(x, 0.0, 0, sp);
    ic_jet_exp(e, x, sp);
    const double want[4] = {1.0, 1.0, 0.5, 1.0 / 6.0};
    for (int i = 0; i < 4; i++)
        CHECK_CLOSE(e[i], want[i], 4 * DBL_EPSILON, "exp coefficient");
    ic_jet_space_free(sp);
}

// expr.h: x^2 + 1 at 2
static void check_expr(void)
{
    const char *f[1] = {"x^2 + 1"};
    const char *vars[1] = {"x"};
    ic_expr *e = NULL;
    ic_error err;
    CHECK(ic_expr_compile(&e, f, 1, vars, 1, NULL, 0, NULL, &err) == IC_OK, "compile: %s",
          err.message);
    if (!e)
        return;
    double work[64], out = 0.0;
    const double at = 2.0;
    CHECK(ic_expr_work_len(e) <= 64, "work of %zu doubles", ic_expr_work_len(e));
    CHECK(ic_expr_eval(e, &out, &at, work, &err) == IC_OK && out == 5.0, "x^2 + 1 at 2 = %g",
          out);
    ic_expr_free(e);
}

// surface.h: an implicit sphere of radius 2 has principal curvatures -1/2
// with its outward normal (docs/conventions.md)
static void check_surface(ic_surface *sphere)
{
    ic_surface_geometry g;
    ic_error err;
    const double top[3] = {0, 0, 2};
    CHECK(ic_surface_num_vars(sphere) == 3, "an implicit surface has %d variables",
          ic_surface_num_vars(sphere));
    CHECK(ic_surface_geometry_at(sphere, &g, top, &err) == IC_OK, "geometry: %s", err.message);
    CHECK_CLOSE(g.principal_curvatures[0], -0.5, 16 * DBL_EPSILON, "k1");
    CHECK_CLOSE(g.principal_curvatures[1], -0.5, 16 * DBL_EPSILON, "k2");
}

// local.h: the circle through (sqrt 3, 0, 1) has curvature 1/sqrt(3)
static void check_local(ic_pair *pair)
{
    ic_local_options opt;
    ic_local_defaults(&opt);
    ic_local_point pt;
    ic_local_result res;
    ic_error err;
    const double at[3] = {std::sqrt(3.0), 0, 1};
    CHECK(ic_local_locate(pair, &pt, at, &opt, &err) == IC_OK, "locate: %s", err.message);
    CHECK(ic_local_apparatus(pair, &res, &pt, 2, IC_METHOD_JET, &opt, &err) == IC_OK,
          "apparatus: %s", err.message);
    CHECK(res.type == IC_POINT_TRANSVERSAL, "point type %s", ic_point_type_name(res.type));
    CHECK_CLOSE(res.branches[0].kappa, 1.0 / std::sqrt(3.0), 1e-12, "kappa");
}

// trace.h and writers.h: one closed curve of length 2 pi sqrt(3); its OBJ
// file has one vertex per point and one polyline
static void check_trace(ic_pair *pair)
{
    ic_trace_options opt;
    ic_trace_defaults(&opt);
    opt.has_box = 1;
    for (int k = 0; k < 3; k++)
        opt.box[k][0] = -3, opt.box[k][1] = 3;
    ic_trace_result *res = NULL;
    ic_error err;
    CHECK(ic_trace(&res, pair, &opt, &err) == IC_OK, "trace: %s", err.message);
    if (!res)
        return;
    CHECK(ic_trace_result_num_curves(res) == 1, "%d curves", ic_trace_result_num_curves(res));
    const ic_trace_curve *c = ic_trace_result_curve(res, 0);
    if (c) {
        CHECK(c->closed, "the circle is not closed");
        // the default truncation error, 1e-11 of the size per step, over a
        // few hundred steps
        CHECK_CLOSE(c->length, 2 * PI * std::sqrt(3.0), 1e-8, "circle length");
    }
    std::FILE *f = std::tmpfile();
    CHECK(f != NULL, "no temporary file");
    if (f && c) {
        CHECK(ic_trace_write_obj(f, res, &err) == IC_OK, "ic_trace_write_obj: %s", err.message);
        std::rewind(f);
        char line[256];
        int vertices = 0, polylines = 0;
        while (std::fgets(line, sizeof line, f)) {
            vertices += std::strncmp(line, "v ", 2) == 0;
            polylines += std::strncmp(line, "l ", 2) == 0;
        }
        CHECK(vertices >= c->npoints && polylines == 1, "OBJ: %d vertices for %d points, %d "
              "polylines", vertices, c->npoints, polylines);
    }
    if (f)
        std::fclose(f);
    ic_trace_result_free(res);
}

// problem.h and plot.h
static void check_problem(void)
{
    const char *json = "{\"title\": \"circle\", \"surfaces\": ["
                       "{\"name\": \"ball\", \"type\": \"implicit\", \"f\": \"x^2+y^2+z^2-4\"},"
                       "{\"name\": \"lid\", \"type\": \"implicit\", \"f\": \"z - 1\"}],"
                       "\"box\": [[-3, 3], [-3, 3], [-3, 3]]}";
    ic_problem *p = NULL;
    ic_error err;
    CHECK(ic_problem_parse(&p, json, std::strlen(json), &err) == IC_OK, "parse: %s",
          err.message);
    if (!p)
        return;
    CHECK(ic_problem_num_surfaces(p) == 2 && ic_problem_find_surface(p, "lid") == 1,
          "%d surfaces, lid at %d", ic_problem_num_surfaces(p), ic_problem_find_surface(p, "lid"));
    ic_plot_options opt;
    ic_plot_defaults(&opt);
    CHECK(opt.width == 1400 && opt.height == 800, "plot size %d x %d", opt.width, opt.height);
    ic_plot_scene scene;
    ic_plot_scene_of_problem(&scene, p, NULL);
    CHECK(scene.nsurfaces == 2 && scene.has_box && std::strcmp(scene.names[0], "ball") == 0,
          "scene of %d surfaces", scene.nsurfaces);
    ic_problem_free(p);
}

int main(void)
{
    check_common();
    check_jet();
    check_expr();
    check_problem();
    ic_primitive ball, lid;
    std::memset(&ball, 0, sizeof ball);
    std::memset(&lid, 0, sizeof lid);
    ball.kind = IC_PRIM_SPHERE;
    ball.radius = 2;
    lid.kind = IC_PRIM_PLANE;
    lid.center[2] = 1;
    lid.normal[2] = 1;
    ic_surface *A = NULL, *B = NULL;
    ic_pair *pair = NULL;
    ic_error err;
    CHECK(ic_surface_new_primitive(&A, &ball, IC_IMPLICIT, &err) == IC_OK &&
              ic_surface_new_primitive(&B, &lid, IC_IMPLICIT, &err) == IC_OK &&
              ic_pair_new(&pair, A, B, &err) == IC_OK,
          "surfaces: %s", err.message);
    if (pair) {
        check_surface(A);
        check_local(pair);
        check_trace(pair);
    }
    ic_pair_free(pair);
    ic_surface_free(A);
    ic_surface_free(B);
    return harness_finish("cxx");
}
