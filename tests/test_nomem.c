/* Out of memory, everywhere (issue 11, item 8): every allocation a library
 * entry point makes is failed in turn, and the call must then neither crash
 * nor leak, and must either return IC_ERR_NOMEM with an error record that
 * says so, or succeed with the very result it gives with all the memory it
 * asks for (the allocation was optional: a cache, a speed-up). A trace may
 * also succeed with a report that is not complete and lists the shortage
 * (its list of undecided regions: the regions go, their cells are still
 * counted): an honest answer.
 *
 * Each scenario below is a whole use of one entry point: the objects it
 * needs are made inside it, so the allocations of their making fail too,
 * and everything is freed before it returns. It runs once counting its
 * allocations, N (asserted > 0: the wrappers of nomem_wrap.h see the
 * library's allocations), then once for each k, with the k-th failing. A
 * scenario of more than SAMPLE_ALL allocations (the traces) is sampled: every
 * k up to SAMPLE_ALL, then SAMPLE_STRIDED more spread evenly up to N, the
 * last included. Leaks are LeakSanitizer's to find: `make sanitize` runs this
 * test with it, and checks for leaks after each scenario, naming it.
 *
 * A failed check names the scenario and k, and lists the calls that made the
 * failed allocation as offsets into their files: `addr2line -f -i -e
 * test_nomem OFFSET` names the lines.
 *
 * usage: test_nomem SOURCE_DIR TEMP_DIR [WORD] (WORD: only the scenarios
 * whose name holds it) */
#define _GNU_SOURCE /* dladdr */
#include <dirent.h>
#include <dlfcn.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "harness.h"
#include "intercurve.h"
#include "nomem_wrap.h"

/* AddressSanitizer, as gcc and clang say it */
#if defined(__SANITIZE_ADDRESS__)
#define NOMEM_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define NOMEM_ASAN 1
#endif
#endif
#ifdef NOMEM_ASAN
#include <sanitizer/lsan_interface.h>
#define NOMEM_LEAK_CHECK() __lsan_do_recoverable_leak_check()
#else
#define NOMEM_LEAK_CHECK() 0
#endif

/* every allocation up to this one is failed; beyond it a sample */
#define SAMPLE_ALL 200
#define SAMPLE_STRIDED 100

enum { SUMMARY_LEN = 512 };

/* A use of the library. Returns the status of its first failing call and
 * fills err; on success, writes into summary what it computed (the numbers
 * to 17 digits), to be compared between runs. */
typedef ic_status (*scenario_fn)(ic_error *err, char *summary);

/* The source directory (for the example files) and a directory to write in. */
static const char *source_dir = ".", *temp_dir = ".";

/* ---- what the scenarios share ---- */

/* Appends printf-formatted text to the summary. */
static void say(char *summary, const char *fmt, ...) IC_PRINTF(2, 3);
static void say(char *summary, const char *fmt, ...)
{
    const size_t n = strlen(summary);
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(summary + n, SUMMARY_LEN - n, fmt, ap);
    va_end(ap);
}

/* A surface: a parametric triple, or (xyz[1] NULL) the implicit formula
 * xyz[0]; dom and periodic: the parametric domain (none when dom is empty). */
typedef struct {
    const char *xyz[3];
    double dom[2][2];
    int periodic[2];
} surface_def;

static ic_status make_surface(ic_surface **s, const surface_def *d, ic_error *err)
{
    if (!d->xyz[1])
        return ic_surface_new_implicit(s, d->xyz[0], NULL, 0, err);
    ic_status st = ic_surface_new_parametric(s, d->xyz, NULL, NULL, 0, NULL, err);
    if (st == IC_OK && d->dom[0][1] > d->dom[0][0])
        st = ic_surface_set_domain(*s, d->dom, d->periodic, err);
    return st;
}

typedef struct {
    ic_surface *A, *B;
    ic_pair *pair;
} made_pair;

static ic_status make_pair(made_pair *m, const surface_def *a, const surface_def *b,
                           ic_error *err)
{
    memset(m, 0, sizeof *m);
    ic_status st = make_surface(&m->A, a, err);
    if (st == IC_OK && b)
        st = make_surface(&m->B, b, err);
    if (st == IC_OK)
        st = ic_pair_new(&m->pair, m->A, m->B, err);
    return st;
}

static void free_pair(made_pair *m)
{
    ic_pair_free(m->pair);
    ic_surface_free(m->A);
    ic_surface_free(m->B);
}

#define PI 3.141592653589793
static const surface_def CYLINDER_I = {{"(x - 1)^2 + y^2 - 1"}, {{0}}, {0}};
static const surface_def SPHERE_I = {{"x^2 + y^2 + z^2 - 4"}, {{0}}, {0}};
static const surface_def SPHERE_P = {{"2*cos(u)*cos(v)", "2*sin(u)*cos(v)", "2*sin(v)"},
                                     {{-PI, PI}, {-PI / 2, PI / 2}},
                                     {1, 0}};
static const surface_def CYLINDER_P = {{"1 + sin(v)", "cos(v)", "u"}, {{-2.5, 2.5}, {0, 2 * PI}},
                                       {0, 1}};
static const surface_def PLANE_I = {{"z - 1"}, {{0}}, {0}};
static const surface_def ENNEPER = {{"u - u^3/3 + u*v^2", "-v - u^2*v + v^3/3", "u^2 - v^2"},
                                    {{-2.5, 2.5}, {-2.5, 2.5}},
                                    {0, 0}};

/* ---- the scenarios ---- */

static ic_status formula(ic_error *err, char *summary)
{
    const char *f[3] = {"R*cos(u)*cos(v) + sqrt(1 + u^2)", "R*sin(u)*cos(v) - atan2(v, 2)",
                        "R*sin(v) + exp(u*v)/(2 + v^2)"};
    const char *vars[2] = {"u", "v"};
    const ic_constant consts[1] = {{"R", 2.5}};
    ic_expr *e = NULL;
    ic_status st = ic_expr_compile(&e, f, 3, vars, 2, consts, 1, NULL, err);
    double c = 0;
    if (st == IC_OK)
        st = ic_expr_eval_constant(&c, "2*pi*R - sin(R)", consts, 1, err);
    if (st == IC_OK) {
        double out[3], work[256];
        const double at[2] = {0.3, -0.4};
        st = ic_expr_eval(e, out, at, work, err);
        say(summary, "tape %d, %.17g %.17g %.17g, %.17g", ic_expr_tape_len(e), out[0], out[1],
            out[2], c);
    }
    ic_expr_free(e);
    return st;
}

static ic_status jet_space(ic_error *err, char *summary)
{
    ic_jet_space *sp = NULL;
    const ic_status st = ic_jet_space_new(&sp, 3, 8, err);
    if (st == IC_OK)
        say(summary, "%d coefficients", ic_jet_space_len(sp));
    ic_jet_space_free(sp);
    return st;
}

/* The geometry, a jet of order 6 and an interval gradient of a surface at
 * `at` (its workspaces grow on first use), freed after. */
static ic_status use_surface(ic_surface *s, const double *at, ic_error *err, char *summary)
{
    ic_surface_geometry g;
    ic_status st = ic_surface_geometry_at(s, &g, at, err);
    ic_jet_space *sp = NULL;
    if (st == IC_OK)
        st = ic_jet_space_new(&sp, ic_surface_num_vars(s), 6, err);
    double t[3 * 84];
    if (st == IC_OK)
        st = ic_surface_taylor(s, t, at, sp, err);
    if (st == IC_OK) {
        say(summary, "k %.17g %.17g, c %.17g; ", g.principal_curvatures[0],
            g.principal_curvatures[1], t[ic_jet_space_len(sp) - 1]);
        ic_interval_grad out[3];
        ic_interval box[3];
        for (int i = 0; i < 3; i++)
            box[i] = (ic_interval){at[i] - 0.01, at[i] + 0.01};
        /* callbacks and parametric primitives have none: IC_ERR_UNABLE */
        const ic_status si = ic_surface_eval_interval_grad(s, out, box, err);
        if (si == IC_OK)
            say(summary, "[%.17g, %.17g]; ", out[0].d[0].lo, out[0].d[0].hi);
        else if (si != IC_ERR_UNABLE)
            st = si;
    }
    ic_jet_space_free(sp);
    ic_surface_free(s);
    return st;
}

static ic_status parametric_surface(ic_error *err, char *summary)
{
    ic_surface *s = NULL;
    const ic_status st = make_surface(&s, &SPHERE_P, err);
    const double at[3] = {0.3, 0.4, 0};
    return st == IC_OK ? use_surface(s, at, err, summary) : st;
}

static ic_status implicit_surface(ic_error *err, char *summary)
{
    ic_surface *s = NULL;
    const ic_status st = make_surface(&s, &SPHERE_I, err);
    const double at[3] = {1.2, 1.6, 0};
    return st == IC_OK ? use_surface(s, at, err, summary) : st;
}

/* the paraboloid z = u^2 + v^2, derivatives to order 2 by hand */
static int paraboloid(void *user, double *d, const double *at, const ic_jet_space *sp)
{
    (void)user;
    const int n = ic_jet_space_len(sp);
    memset(d, 0, 3 * (size_t)n * sizeof *d);
    d[0] = at[0], d[n] = at[1], d[2 * n] = at[0] * at[0] + at[1] * at[1];
    if (ic_jet_space_order(sp) >= 1)
        d[1] = 1, d[n + 2] = 1, d[2 * n + 1] = 2 * at[0], d[2 * n + 2] = 2 * at[1];
    if (ic_jet_space_order(sp) >= 2)
        d[2 * n + 3] = 2, d[2 * n + 5] = 2;
    return 0;
}

static ic_status callback_surface(ic_error *err, char *summary)
{
    ic_surface *s = NULL;
    ic_status st = ic_surface_new_callback(&s, IC_PARAMETRIC, paraboloid, NULL, err);
    ic_surface_geometry g;
    const double at[2] = {0.3, -0.2};
    if (st == IC_OK)
        st = ic_surface_geometry_at(s, &g, at, err);
    if (st == IC_OK)
        say(summary, "k %.17g %.17g", g.principal_curvatures[0], g.principal_curvatures[1]);
    ic_surface_free(s);
    return st;
}

static ic_status primitives(ic_error *err, char *summary)
{
    ic_primitive p;
    memset(&p, 0, sizeof p);
    p.normal[2] = 1, p.radius = 0.5, p.major_radius = 2, p.half_angle = 0.4;
    p.axes[0] = 1.5, p.axes[1] = 0.8, p.axes[2] = 1.1;
    const double uv[2] = {0.3, 0.4};
    ic_status st = IC_OK;
    for (int kind = IC_PRIM_PLANE; st == IC_OK && kind <= IC_PRIM_ELLIPSOID; kind++)
        for (int form = 0; st == IC_OK && form < 2; form++) {
            p.kind = (ic_primitive_kind)kind;
            ic_surface *s = NULL;
            st = ic_surface_new_primitive(&s, &p, form ? IC_IMPLICIT : IC_PARAMETRIC, err);
            if (st == IC_OK) {
                double at[3] = {uv[0], uv[1], 0}, X[3];
                /* implicit: the point of the parametric form at uv */
                if (form) {
                    ic_surface *q = NULL;
                    st = ic_surface_new_primitive(&q, &p, IC_PARAMETRIC, err);
                    if (st == IC_OK)
                        st = ic_surface_eval(q, X, uv, err);
                    ic_surface_free(q);
                    memcpy(at, X, sizeof at);
                }
                if (st == IC_OK)
                    st = use_surface(s, at, err, summary);
                else
                    ic_surface_free(s);
            }
        }
    return st;
}

static ic_status pairs(ic_error *err, char *summary)
{
    const surface_def *defs[4][2] = {{&CYLINDER_I, &SPHERE_I},
                                     {&SPHERE_P, &PLANE_I},
                                     {&CYLINDER_P, &SPHERE_P},
                                     {&ENNEPER, NULL}};
    ic_status st = IC_OK;
    for (int i = 0; st == IC_OK && i < 4; i++) {
        made_pair m;
        st = make_pair(&m, defs[i][0], defs[i][1], err);
        if (st == IC_OK)
            say(summary, "%d ", ic_pair_is_self(m.pair));
        free_pair(&m);
    }
    return st;
}

/* Viviani's curve (implicit cylinder, parametric sphere) at `at`: located,
 * then the apparatus by each method given. */
static ic_status apparatus_at(const double at[3], const ic_method *methods, int nmethods,
                              ic_error *err, char *summary)
{
    made_pair m;
    ic_status st = make_pair(&m, &CYLINDER_I, &SPHERE_P, err);
    ic_local_options opt;
    ic_local_defaults(&opt);
    ic_local_point pt;
    if (st == IC_OK)
        st = ic_local_locate(m.pair, &pt, at, &opt, err);
    for (int i = 0; st == IC_OK && i < nmethods; i++) {
        ic_local_result res;
        const int order = methods[i] == IC_METHOD_CLOSED_FORM   ? 3
                          : methods[i] == IC_METHOD_PERTURBATION ? 2
                                                                  : 8;
        st = ic_local_apparatus(m.pair, &res, &pt, order, methods[i], &opt, err);
        if (st == IC_OK) {
            say(summary, "%s, %d branches:", ic_point_type_name(res.type), res.nbranches);
            for (int b = 0; b < res.nbranches; b++)
                say(summary, " %.17g", res.branches[b].kappa);
            say(summary, "; ");
        }
    }
    free_pair(&m);
    return st;
}

static ic_status apparatus_transversal(ic_error *err, char *summary)
{
    const double at[3] = {1.5, 0.8660254037844386, 1};
    const ic_method methods[2] = {IC_METHOD_JET, IC_METHOD_CLOSED_FORM};
    return apparatus_at(at, methods, 2, err, summary);
}

/* the branch point (2, 0, 0) of Viviani's curve */
static ic_status apparatus_tangential(ic_error *err, char *summary)
{
    const double at[3] = {2, 0, 0};
    const ic_method methods[2] = {IC_METHOD_HEIGHT_DIFFERENCE, IC_METHOD_PERTURBATION};
    return apparatus_at(at, methods, 2, err, summary);
}

/* Marks a summary whose report says it is incomplete for lack of memory. */
#define HONEST " [incomplete: out of memory listed]"

/* What a trace found: curves, points, completeness, lengths. */
static void say_trace(char *summary, const ic_trace_result *res)
{
    const ic_trace_report *rep = ic_trace_result_report(res);
    for (int i = 0; i < rep->nfailures; i++)
        if (!rep->complete && strstr(rep->failures[i], "out of memory")) {
            say(summary, HONEST);
            break;
        }
    say(summary, "%d curves, %d points, complete %d, %d failures:",
        ic_trace_result_num_curves(res), ic_trace_result_num_specials(res), rep->complete,
        rep->nfailures);
    for (int i = 0; i < ic_trace_result_num_curves(res) && i < 8; i++)
        say(summary, " %d %.15g", ic_trace_result_curve(res, i)->npoints,
            ic_trace_result_curve(res, i)->length);
}

/* A trace at search depth `depth` (the box [-2.5, 2.5]^3 for two implicit
 * surfaces) in `threads` threads (1: the allocations come in the same order
 * in every run, so the k-th is the same one). */
static ic_status trace_in(const surface_def *a, const surface_def *b, int depth, int threads,
                          ic_error *err, char *summary)
{
    made_pair m;
    ic_status st = make_pair(&m, a, b, err);
    ic_trace_options opt;
    ic_trace_defaults(&opt);
    opt.depth = depth;
    opt.threads = threads;
    opt.has_box = !a->xyz[1] && b && !b->xyz[1];
    for (int k = 0; k < 3; k++)
        opt.box[k][0] = -2.5, opt.box[k][1] = 2.5;
    ic_trace_result *res = NULL;
    if (st == IC_OK)
        st = ic_trace(&res, m.pair, &opt, err);
    if (st == IC_OK)
        say_trace(summary, res);
    ic_trace_result_free(res);
    free_pair(&m);
    return st;
}

static ic_status trace(const surface_def *a, const surface_def *b, int depth, ic_error *err,
                       char *summary)
{
    return trace_in(a, b, depth, 1, err, summary);
}

/* two implicit surfaces: Viviani's figure-eight and its branch point */
static ic_status trace_implicit(ic_error *err, char *summary)
{
    return trace(&CYLINDER_I, &SPHERE_I, 3, err, summary);
}

/* a parametric sphere and an implicit plane: a circle */
static ic_status trace_mixed(ic_error *err, char *summary)
{
    return trace(&SPHERE_P, &PLANE_I, 3, err, summary);
}

/* two parametric surfaces: Viviani again, through the sphere's poles */
static ic_status trace_parametric(ic_error *err, char *summary)
{
    return trace(&CYLINDER_P, &SPHERE_P, 5, err, summary);
}

/* the same at depth 3: cells left undecided, listed by region in the report */
static ic_status trace_incomplete(ic_error *err, char *summary)
{
    return trace(&CYLINDER_P, &SPHERE_P, 3, err, summary);
}

/* the same in three threads (docs/tracing.md, "Threads"): an allocation
 * that fails in a thread costs only the part of the search done ahead
 * there, which the trace then does itself, with the same result; the k-th
 * allocation is any thread's */
static ic_status trace_threads(ic_error *err, char *summary)
{
    return trace_in(&CYLINDER_P, &SPHERE_P, 3, 3, err, summary);
}

/* a self-intersection: the double curves of Enneper's surface (at depth 5:
 * below 4 the search of [-2.5, 2.5]^2 finds none, and says it is complete) */
static ic_status trace_self(ic_error *err, char *summary)
{
    return trace(&ENNEPER, NULL, 5, err, summary);
}

/* primitives in closed form (docs/tracing.md, "Exact paths"): a torus cut
 * by a plane in two circles, a sphere on a plane at a point, and two equal
 * cylinders (two ellipses, two branch points) */
static ic_status trace_exact(ic_error *err, char *summary)
{
    const ic_primitive prims[3][2] = {
        {{.kind = IC_PRIM_TORUS, .major_radius = 1.5, .radius = 0.5},
         {.kind = IC_PRIM_PLANE, .center = {0, 0, 0.2}, .normal = {0, 0, 1}}},
        {{.kind = IC_PRIM_SPHERE, .center = {0, 0, 1}, .radius = 1},
         {.kind = IC_PRIM_PLANE, .normal = {0, 0, 1}}},
        {{.kind = IC_PRIM_CYLINDER, .radius = 1},
         {.kind = IC_PRIM_CYLINDER, .radius = 1, .axis = {0, 1, 0}}}};
    ic_status st = IC_OK;
    for (int c = 0; c < 3 && st == IC_OK; c++) {
        made_pair m;
        memset(&m, 0, sizeof m);
        st = ic_surface_new_primitive(&m.A, &prims[c][0], IC_IMPLICIT, err);
        if (st == IC_OK)
            st = ic_surface_new_primitive(&m.B, &prims[c][1], IC_IMPLICIT, err);
        if (st == IC_OK)
            st = ic_pair_new(&m.pair, m.A, m.B, err);
        ic_trace_options opt;
        ic_trace_defaults(&opt);
        opt.threads = 1;
        opt.has_box = 1;
        for (int k = 0; k < 3; k++)
            opt.box[k][0] = -2.5, opt.box[k][1] = 2.5;
        ic_trace_result *res = NULL;
        if (st == IC_OK)
            st = ic_trace(&res, m.pair, &opt, err);
        if (st == IC_OK)
            say_trace(summary, res);
        ic_trace_result_free(res);
        free_pair(&m);
    }
    return st;
}

/* The unit sphere's exact NURBS net (the 9-point circle revolved with a
 * half circle) and a square plane's bilinear net at height h: recognised
 * as a sphere and a plane, traced in closed form. */
static ic_status nurbs_sphere_plane(made_pair *m, double h, ic_error *err)
{
    static const double cx[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, cy[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
    static const double px[5] = {0, 1, 1, 1, 0}, pz[5] = {-1, -1, 0, 1, 1};
    static const double ku[12] = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
    static const double kv[8] = {0, 0, 0, 0.5, 0.5, 1, 1, 1}, k1[4] = {0, 0, 1, 1};
    double P[3 * 45], w[45], Q[12];
    for (int i = 0; i < 9; i++)
        for (int j = 0; j < 5; j++) {
            const int at = 5 * i + j;
            P[3 * at] = px[j] * cx[i], P[3 * at + 1] = px[j] * cy[i], P[3 * at + 2] = pz[j];
            w[at] = (i % 2 ? sqrt(0.5) : 1) * (j % 2 ? sqrt(0.5) : 1);
        }
    for (int i = 0; i < 4; i++)
        Q[3 * i] = i < 2 ? -2 : 2, Q[3 * i + 1] = i % 2 ? 2 : -2, Q[3 * i + 2] = h;
    const ic_nurbs sphere = {{2, 2}, {9, 5}, {ku, kv}, P, w, {1, 0}};
    const ic_nurbs plane = {{1, 1}, {2, 2}, {k1, k1}, Q, NULL, {0, 0}};
    memset(m, 0, sizeof *m);
    ic_status st = ic_surface_new_nurbs(&m->A, &sphere, err);
    if (st == IC_OK)
        st = ic_surface_new_nurbs(&m->B, &plane, err);
    if (st == IC_OK)
        st = ic_pair_new(&m->pair, m->A, m->B, err);
    return st;
}

/* The unit cylinder's net about z (the 9-point circle revolved with the
 * segment from height -2 to 2) and the plane z = 0.3 x's bilinear net over
 * [-3, 3]^2: recognised as a cylinder and a plane, their ellipse traced in
 * closed form with its knot lines' points. */
static ic_status nurbs_cylinder_plane(made_pair *m, ic_error *err)
{
    static const double cx[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, cy[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
    static const double ku[12] = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
    static const double k1[4] = {0, 0, 1, 1};
    double P[3 * 18], w[18], Q[12];
    for (int i = 0; i < 9; i++)
        for (int j = 0; j < 2; j++) {
            const int at = 2 * i + j;
            P[3 * at] = cx[i], P[3 * at + 1] = cy[i], P[3 * at + 2] = j ? 2 : -2;
            w[at] = i % 2 ? sqrt(0.5) : 1;
        }
    for (int i = 0; i < 4; i++)
        Q[3 * i] = i < 2 ? -3 : 3, Q[3 * i + 1] = i % 2 ? 3 : -3, Q[3 * i + 2] = 0.3 * Q[3 * i];
    const ic_nurbs cylinder = {{2, 1}, {9, 2}, {ku, k1}, P, w, {1, 0}};
    const ic_nurbs plane = {{1, 1}, {2, 2}, {k1, k1}, Q, NULL, {0, 0}};
    memset(m, 0, sizeof *m);
    ic_status st = ic_surface_new_nurbs(&m->A, &cylinder, err);
    if (st == IC_OK)
        st = ic_surface_new_nurbs(&m->B, &plane, err);
    if (st == IC_OK)
        st = ic_pair_new(&m->pair, m->A, m->B, err);
    return st;
}

/* the exact path on recognised nets: a circle with its parameters, and a
 * contact point at a pole */
static ic_status trace_exact_nets(ic_error *err, char *summary)
{
    ic_status st = IC_OK;
    for (int c = 0; c < 2 && st == IC_OK; c++) {
        made_pair m;
        st = nurbs_sphere_plane(&m, c ? -1 : 0.5, err);
        ic_trace_options opt;
        ic_trace_defaults(&opt);
        ic_trace_result *res = NULL;
        if (st == IC_OK)
            st = ic_trace(&res, m.pair, &opt, err);
        if (st == IC_OK) {
            say(summary, "%s; ", ic_trace_result_report(res)->method);
            say_trace(summary, res);
        }
        ic_trace_result_free(res);
        free_pair(&m);
    }
    return st;
}

/* the conic path on recognised nets: an ellipse with its parameters and
 * its knot lines' points */
static ic_status trace_conic_nets(ic_error *err, char *summary)
{
    made_pair m;
    ic_status st = nurbs_cylinder_plane(&m, err);
    ic_trace_options opt;
    ic_trace_defaults(&opt);
    ic_trace_result *res = NULL;
    if (st == IC_OK)
        st = ic_trace(&res, m.pair, &opt, err);
    if (st == IC_OK) {
        say(summary, "%s; ", ic_trace_result_report(res)->method);
        say_trace(summary, res);
    }
    ic_trace_result_free(res);
    free_pair(&m);
    return st;
}

/* a tangential curve: the unit cylinder touches the plane x = 1 along a line */
static ic_status trace_tangential(ic_error *err, char *summary)
{
    const surface_def cylinder = {{"x^2 + y^2 - 1"}, {{0}}, {0}};
    const surface_def plane = {{"x - 1"}, {{0}}, {0}};
    return trace(&cylinder, &plane, 3, err, summary);
}

/* The marching core alone: Viviani's curve from (1.5, sqrt(3)/2, 1) into its
 * branch point (2, 0, 0) both ways (the march shortens its step before it),
 * or (tangential) the line where the unit cylinder touches the plane x = 1,
 * classified at every step, to the box. */
static ic_status march(int tangential, ic_error *err, char *summary)
{
    const surface_def cylinder = {{"x^2 + y^2 - 1"}, {{0}}, {0}};
    const surface_def plane = {{"x - 1"}, {{0}}, {0}};
    made_pair m;
    ic_status st = tangential ? make_pair(&m, &cylinder, &plane, err)
                              : make_pair(&m, &CYLINDER_I, &SPHERE_I, err);
    ic_trace_options opt;
    ic_trace_defaults(&opt);
    opt.has_box = 1;
    for (int k = 0; k < 3; k++)
        opt.box[k][0] = -2.5, opt.box[k][1] = 2.5;
    ic_tracer *tr = NULL;
    ic_local_point pt;
    const double X0[3] = {tangential ? 1 : 1.5, tangential ? 0 : 0.8660254037844386,
                          tangential ? 0.3 : 1};
    ic_trace_event ev = IC_TRACE_FAILED;
    if (st == IC_OK)
        st = ic_tracer_new(&tr, m.pair, &opt, err);
    if (st == IC_OK)
        st = ic_local_locate(m.pair, &pt, X0, &opt.local, err);
    for (int dir = -1; st == IC_OK && dir <= 1; dir += 2) {
        st = ic_tracer_start(tr, &pt, dir, err);
        if (st == IC_OK)
            st = ic_tracer_run(tr, &ev, err);
        const int n = ic_tracer_num_points(tr);
        if (st == IC_OK)
            say(summary, "%s after %d points at %.17g; ", ic_trace_event_name(ev), n,
                ic_tracer_point(tr, n - 1)->xyz[0]);
    }
    ic_tracer_free(tr);
    free_pair(&m);
    return st;
}

static ic_status tracer(ic_error *err, char *summary) { return march(0, err, summary); }

static ic_status tracer_tangential(ic_error *err, char *summary)
{
    return march(1, err, summary);
}

static ic_status problem_file(ic_error *err, char *summary)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/examples/viviani.json", source_dir);
    ic_problem *p = NULL;
    ic_status st = ic_problem_load(&p, path, err);
    if (st == IC_OK)
        say(summary, "%s: %d surfaces; ", ic_problem_title(p), ic_problem_num_surfaces(p));
    ic_problem_free(p);
    p = NULL;
    const char *json = "{\"constants\": {\"R\": 2}, \"surfaces\": ["
                       "{\"name\": \"ball\", \"type\": \"implicit\", \"f\": \"x^2+y^2+z^2-R^2\"},"
                       "{\"name\": \"tube\", \"type\": \"parametric\", \"params\": [\"s\", \"t\"],"
                       " \"xyz\": [\"1 + cos(t)\", \"sin(t)\", \"s\"],"
                       " \"domain\": [[-3, 3], [0, \"2*pi\"]], \"periodic\": [false, true]}],"
                       " \"box\": [[-3, 3], [-3, 3], [-3, 3]]}";
    if (st == IC_OK)
        st = ic_problem_parse(&p, json, strlen(json), err);
    if (st == IC_OK)
        say(summary, "%d surfaces, tube at %d", ic_problem_num_surfaces(p),
            ic_problem_find_surface(p, "tube"));
    ic_problem_free(p);
    return st;
}

/* The bytes and a checksum of what a writer wrote into f. */
static void say_file(char *summary, FILE *f)
{
    rewind(f);
    uint64_t h = 1469598103934665603u;
    long n = 0;
    for (int c; (c = fgetc(f)) != EOF; n++)
        h = (h ^ (unsigned char)c) * 1099511628211u;
    say(summary, "%ld bytes %016llx; ", n, (unsigned long long)h);
}

/* Viviani traced, then written as CSV, VTK, OBJ and drawn to SVG. The three
 * file writers allocate nothing of their own; the picture's meshes do. */
static ic_status writers(ic_error *err, char *summary)
{
    made_pair m;
    ic_status st = make_pair(&m, &CYLINDER_I, &SPHERE_I, err);
    ic_trace_options opt;
    ic_trace_defaults(&opt);
    opt.depth = 3;
    opt.threads = 1;
    opt.has_box = 1;
    for (int k = 0; k < 3; k++)
        opt.box[k][0] = -2.5, opt.box[k][1] = 2.5;
    ic_trace_result *res = NULL;
    if (st == IC_OK)
        st = ic_trace(&res, m.pair, &opt, err);
    for (int w = 0; st == IC_OK && w < 3; w++) {
        FILE *f = tmpfile();
        if (!f) {
            st = ic_error_set(err, IC_ERR_IO, 0, "no temporary file");
            break;
        }
        st = w == 0   ? ic_trace_write_csv(f, res, m.pair, err)
             : w == 1 ? ic_trace_write_vtk(f, res, err)
                      : ic_trace_write_obj(f, res, err);
        if (st == IC_OK)
            say_file(summary, f);
        fclose(f);
    }
    if (st == IC_OK) {
        ic_plot_scene scene;
        memset(&scene, 0, sizeof scene);
        scene.nsurfaces = 2;
        scene.surfaces[0] = m.A, scene.surfaces[1] = m.B;
        scene.names[0] = "cylinder", scene.names[1] = "sphere";
        scene.has_box = 1;
        memcpy(scene.box, opt.box, sizeof scene.box);
        scene.trace = res;
        ic_plot_options po;
        ic_plot_defaults(&po);
        po.width = 400, po.height = 300, po.mesh = 8;
        char path[1024];
        snprintf(path, sizeof path, "%s/nomem.svg", temp_dir);
        st = ic_plot_write(path, &scene, &po, err);
        FILE *f = st == IC_OK ? fopen(path, "rb") : NULL;
        if (f) {
            say_file(summary, f);
            fclose(f);
        }
    }
    ic_trace_result_free(res);
    free_pair(&m);
    return st;
}

/* The entry points for other languages (bindings.h): a problem parsed,
 * traced and its curves fitted, its document in memory (its length tells
 * a different fit), a point's document. */
static ic_status bindings(ic_error *err, char *summary)
{
    const char *json = "{\"surfaces\": [{\"type\": \"implicit\", \"f\": \"x^2+y^2+z^2-4\"},"
                       " {\"type\": \"implicit\", \"f\": \"z - 1\"}],"
                       " \"box\": [[-3, 3], [-3, 3], [-3, 3]]}";
    ic_problem *p = NULL;
    ic_trace_result *res = NULL;
    ic_pair *pair = NULL;
    char *doc = NULL;
    size_t len = 0;
    ic_status st = ic_problem_parse(&p, json, strlen(json), err);
    if (st == IC_OK)
        st = ic_problem_trace(&res, &pair, p, 1e-11, 3, 0, 1, 1e-9, err);
    if (st == IC_OK)
        st = ic_trace_json_alloc(&doc, &len, res, pair, err);
    if (st == IC_OK)
        say(summary, "trace %zu bytes %.40s; ", len, doc);
    ic_free(doc);
    doc = NULL;
    const double at[3] = {sqrt(3.0), 0, 1};
    if (st == IC_OK)
        st = ic_problem_point_json(&doc, &len, p, at, 3, 0, 4, "auto", 1e-6, err);
    if (st == IC_OK)
        say(summary, "point %zu bytes", len);
    ic_free(doc);
    ic_trace_result_free(res);
    ic_pair_free(pair);
    ic_problem_free(p);
    return st;
}

/* ---- the driver ---- */

typedef struct {
    const char *name;
    scenario_fn run;
} scenario;

/* The calls that made the failed allocation, innermost first, as offsets
 * into the files that hold them. */
static void print_stack(void)
{
    for (int i = 1; i < nomem.depth; i++) {
        Dl_info info;
        if (dladdr(nomem.stack[i], &info) && info.dli_fname)
            fprintf(stderr, "    %s +%#lx\n", info.dli_fname,
                    (unsigned long)((char *)nomem.stack[i] - (char *)info.dli_fbase));
    }
}

/* One run with the k-th allocation failing (0: none); the allocations made. */
static long run_once(scenario_fn fn, long k, ic_status *st, ic_error *err, char *summary)
{
    ic_error_clear(err);
    summary[0] = '\0';
    nomem_arm(k);
    *st = fn(err, summary);
    nomem_disarm();
    return nomem.count;
}

/* The next k to fail after k, of N: all up to SAMPLE_ALL, then a stride. */
static long next_k(long k, long N)
{
    if (k < SAMPLE_ALL || N <= SAMPLE_ALL + SAMPLE_STRIDED || k >= N)
        return k + 1;
    const long stride = (N - SAMPLE_ALL) / SAMPLE_STRIDED;
    return k + stride < N ? k + stride : N;
}

static double seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void run_scenario(const scenario *sc)
{
    static char want[SUMMARY_LEN], got[SUMMARY_LEN];
    ic_error err;
    ic_status st;
    const double t0 = seconds();
    const long N = run_once(sc->run, 0, &st, &err, want);
    if (!REQUIRE(st == IC_OK, "%s: fails with all the memory it asks for: %s", sc->name,
                 err.message) ||
        !REQUIRE(N > 0, "%s: no allocation seen (are the wrappers linked?)", sc->name))
        return;
    long runs = 0, optional = 0, honest = 0;
    for (long k = 1; k <= N; k = next_k(k, N), runs++) {
        run_once(sc->run, k, &st, &err, got);
        if (!REQUIRE(nomem.failed == 1, "%s: allocation %ld of %ld never made (the runs differ)",
                     sc->name, k, N))
            continue;
        if (st == IC_OK && strcmp(got, want) == 0) {
            optional++;
        } else if (st == IC_OK && strstr(got, HONEST)) {
            honest++;
        } else if (st == IC_OK) {
            CHECK(0, "%s: allocation %ld of %ld failed, yet success with another result:\n  %s\nnot\n  %s",
                  sc->name, k, N, got, want);
            print_stack();
        } else if (!REQUIRE(st == IC_ERR_NOMEM && err.code == IC_ERR_NOMEM && err.message[0],
                            "%s: allocation %ld of %ld failed: status %s (%d), error '%s'",
                            sc->name, k, N, ic_status_name(st), (int)st, err.message)) {
            print_stack();
        }
    }
    CHECK(NOMEM_LEAK_CHECK() == 0, "%s: leaks (LeakSanitizer's report above)", sc->name);
    printf("%-24s %6ld allocations, %4ld failed in turn (%ld optional, %ld said in the report), "
           "%.2f s\n  %.120s\n",
           sc->name, N, runs, optional, honest, seconds() - t0, want);
    fflush(stdout); /* LeakSanitizer ends the program without flushing it */
}

/* No temporary of the picture is left behind in temp_dir. */
static void check_no_temporaries(void)
{
    DIR *d = opendir(temp_dir);
    if (!REQUIRE(d != NULL, "cannot list %s", temp_dir))
        return;
    int stray = 0;
    for (struct dirent *e; (e = readdir(d)) != NULL;)
        if (strncmp(e->d_name, ".nomem.svg.", 11) == 0) {
            stray++;
            fprintf(stderr, "left behind: %s/%s\n", temp_dir, e->d_name);
        }
    closedir(d);
    CHECK(stray == 0, "%d temporaries of the picture left in %s", stray, temp_dir);
}

int main(int argc, char **argv)
{
    if (argc > 1)
        source_dir = argv[1];
    if (argc > 2)
        temp_dir = argv[2];
    const char *only = argc > 3 ? argv[3] : "";
    static const scenario SCENARIOS[] = {
        {"formula", formula},
        {"jet space", jet_space},
        {"parametric surface", parametric_surface},
        {"implicit surface", implicit_surface},
        {"callback surface", callback_surface},
        {"primitives", primitives},
        {"pairs", pairs},
        {"apparatus, transversal", apparatus_transversal},
        {"apparatus, tangential", apparatus_tangential},
        {"tracer", tracer},
        {"tracer, tangential", tracer_tangential},
        {"trace, implicit", trace_implicit},
        {"trace, mixed", trace_mixed},
        {"trace, parametric", trace_parametric},
        {"trace, incomplete", trace_incomplete},
        {"trace, threads", trace_threads},
        {"trace, self", trace_self},
        {"trace, tangential", trace_tangential},
        {"trace, exact", trace_exact},
        {"trace, exact nets", trace_exact_nets},
        {"trace, conic nets", trace_conic_nets},
        {"problem file", problem_file},
        {"writers", writers},
        {"bindings", bindings},
    };
    for (size_t i = 0; i < sizeof SCENARIOS / sizeof SCENARIOS[0]; i++)
        if (strstr(SCENARIOS[i].name, only))
            run_scenario(&SCENARIOS[i]);
    check_no_temporaries();
    return harness_finish("nomem");
}
