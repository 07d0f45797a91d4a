/* Every public function refuses NULL and nonsense arguments without a crash
 * (docs/conventions.md, "Argument checking"): a function returning ic_status
 * gives IC_ERR_INVALID and an error message "<function>: <argument> ...";
 * a getter gives its documented neutral value (0, -1, NULL); a void
 * function does nothing. Each pointer argument is NULL in turn, the others
 * valid. test_api_args_cover.sh checks that every IC_API function of the
 * headers appears below. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "harness.h"
#include "intercurve.h"

static ic_error err;

/* The call gave IC_ERR_INVALID and err's message begins with "fn: arg ". */
static void expect_invalid(ic_status st, const char *fn, const char *arg, int line)
{
    char want[160];
    snprintf(want, sizeof want, "%s: %s ", fn, arg);
    CHECK(st == IC_ERR_INVALID && err.code == IC_ERR_INVALID &&
              strncmp(err.message, want, strlen(want)) == 0,
          "line %d: wanted IC_ERR_INVALID and '%s...', got status %d '%s'", line, want, (int)st,
          err.message);
}

#define BAD(fn, arg, call) (ic_error_clear(&err), expect_invalid((call), #fn, arg, __LINE__))

/* The objects the calls need, valid. */
typedef struct {
    ic_jet_space *sp;
    ic_surface *A, *B, *par;
    ic_pair *pair;
    ic_trace_options topt;
    ic_local_options lopt;
    ic_trace_result *res;
    ic_problem *problem;
    ic_local_point pt;
    ic_local_result lres;
    ic_expr *expr;
} fixture;

static const char PROBLEM[] =
    "{\"title\": \"sphere and plane\", \"surfaces\": ["
    "{\"name\": \"A\", \"type\": \"implicit\", \"f\": \"x^2 + y^2 + z^2 - 4\"},"
    "{\"name\": \"B\", \"type\": \"implicit\", \"f\": \"z - 1\"}],"
    "\"box\": [[-3, 3], [-3, 3], [-3, 3]]}";

static int setup(fixture *fx)
{
    memset(fx, 0, sizeof *fx);
    const char *xyz[3] = {"u", "v", "u*v"};
    const char *f = "x + y";
    const char *vars[2] = {"x", "y"};
    const double at[3] = {1.7320508075688772, 0.0, 1.0}; /* sqrt 3: on both */
    ic_trace_defaults(&fx->topt);
    fx->topt.has_box = 1;
    for (int k = 0; k < 3; k++)
        fx->topt.box[k][0] = -3, fx->topt.box[k][1] = 3;
    ic_local_defaults(&fx->lopt);
    return REQUIRE(ic_jet_space_new(&fx->sp, 2, 3, &err) == IC_OK, "space: %s", err.message) &&
           REQUIRE(ic_surface_new_implicit(&fx->A, "x^2 + y^2 + z^2 - 4", NULL, 0, &err) ==
                       IC_OK, "A: %s", err.message) &&
           REQUIRE(ic_surface_new_implicit(&fx->B, "z - 1", NULL, 0, &err) == IC_OK, "B: %s",
                   err.message) &&
           REQUIRE(ic_surface_new_parametric(&fx->par, xyz, NULL, NULL, 0, NULL, &err) == IC_OK,
                   "parametric: %s", err.message) &&
           REQUIRE(ic_pair_new(&fx->pair, fx->A, fx->B, &err) == IC_OK, "pair: %s",
                   err.message) &&
           REQUIRE(ic_trace(&fx->res, fx->pair, &fx->topt, &err) == IC_OK, "trace: %s",
                   err.message) &&
           REQUIRE(ic_trace_fit(fx->res, fx->pair, 1e-6, &err) == IC_OK, "fit: %s", err.message) &&
           REQUIRE(ic_problem_parse(&fx->problem, PROBLEM, sizeof PROBLEM - 1, &err) == IC_OK,
                   "problem: %s", err.message) &&
           REQUIRE(ic_local_locate(fx->pair, &fx->pt, at, &fx->lopt, &err) == IC_OK,
                   "locate: %s", err.message) &&
           REQUIRE(ic_local_apparatus(fx->pair, &fx->lres, &fx->pt, 3, IC_METHOD_AUTO, &fx->lopt,
                                      &err) == IC_OK, "apparatus: %s", err.message) &&
           REQUIRE(ic_expr_compile(&fx->expr, &f, 1, vars, 2, NULL, 0, NULL, &err) == IC_OK,
                   "expr: %s", err.message);
}

static void teardown(fixture *fx)
{
    ic_expr_free(fx->expr);
    ic_problem_free(fx->problem);
    ic_trace_result_free(fx->res);
    ic_pair_free(fx->pair);
    ic_surface_free(fx->A);
    ic_surface_free(fx->B);
    ic_surface_free(fx->par);
    ic_jet_space_free(fx->sp);
}

static void common_args(void)
{
    CHECK(ic_status_name(IC_OK) != NULL && ic_status_name((ic_status)99) != NULL, "status name");
    ic_error_clear(NULL);
    CHECK(ic_error_set(NULL, IC_ERR_INVALID, 0, "x") == IC_ERR_INVALID, "error_set NULL");
    ic_error_set_path(NULL, "x");
    ic_free(NULL);
    /* a name that is no default, and NULL: NaN, never a crash */
    CHECK(isnan(ic_default_value(NULL)) && isnan(ic_default_value("no-such-default")),
          "default_value of no name");
    CHECK(ic_default_value("tol") == IC_TRACE_TOL_DEFAULT &&
              ic_default_value("mesh") == IC_PLOT_MESH_DEFAULT,
          "default_value by name");
}

static void surface_args(fixture *fx)
{
    ic_surface *s = (ic_surface *)1;
    const char *xyz[3] = {"u", "v", "0"};
    ic_primitive prim = {.kind = IC_PRIM_SPHERE, .radius = 1};
    double frame[3][3], out[64], at[3] = {0.1, 0.2, 0.3}, dom[2][2] = {{0, 1}, {0, 1}};
    BAD(ic_primitive_frame, "prim", ic_primitive_frame(NULL, frame, &err));
    BAD(ic_primitive_frame, "frame", ic_primitive_frame(&prim, NULL, &err));
    BAD(ic_surface_new_parametric, "s", ic_surface_new_parametric(NULL, xyz, NULL, NULL, 0, NULL, &err));
    BAD(ic_surface_new_parametric, "xyz", ic_surface_new_parametric(&s, NULL, NULL, NULL, 0, NULL, &err));
    CHECK(s == NULL, "*s is NULL on failure");
    BAD(ic_surface_new_parametric, "nconsts", ic_surface_new_parametric(&s, xyz, NULL, NULL, -1, NULL, &err));
    BAD(ic_surface_new_parametric, "consts", ic_surface_new_parametric(&s, xyz, NULL, NULL, 2, NULL, &err));
    BAD(ic_surface_new_implicit, "s", ic_surface_new_implicit(NULL, "x", NULL, 0, &err));
    BAD(ic_surface_new_implicit, "f", ic_surface_new_implicit(&s, NULL, NULL, 0, &err));
    BAD(ic_surface_new_implicit, "nconsts", ic_surface_new_implicit(&s, "x", NULL, -1, &err));
    BAD(ic_surface_new_implicit, "consts", ic_surface_new_implicit(&s, "x", NULL, 1, &err));
    BAD(ic_surface_new_callback, "s", ic_surface_new_callback(NULL, IC_IMPLICIT, NULL, NULL, &err));
    BAD(ic_surface_new_callback, "fn", ic_surface_new_callback(&s, IC_IMPLICIT, NULL, NULL, &err));
    BAD(ic_surface_new_primitive, "s", ic_surface_new_primitive(NULL, &prim, IC_IMPLICIT, &err));
    BAD(ic_surface_new_primitive, "prim", ic_surface_new_primitive(&s, NULL, IC_IMPLICIT, &err));
    BAD(ic_surface_new_nurbs, "s", ic_surface_new_nurbs(NULL, NULL, &err));
    BAD(ic_surface_new_nurbs, "nurbs", ic_surface_new_nurbs(&s, NULL, &err));
    ic_surface_free(NULL);
    double knot = 0;
    CHECK(ic_surface_knot_crossed(NULL, 0, 0, 1, &knot) == 0, "knot_crossed NULL");
    CHECK(ic_surface_knot_seam(NULL, 0) == 0, "knot_seam NULL");
    ic_surface_set_knot_side(NULL, NULL);
    CHECK(ic_surface_get_kind(NULL) == IC_SURFACE_NONE, "get_kind NULL");
    CHECK(ic_surface_num_vars(NULL) == 0 && ic_surface_num_outputs(NULL) == 0, "num NULL");
    BAD(ic_surface_set_domain, "s", ic_surface_set_domain(NULL, dom, NULL, &err));
    BAD(ic_surface_set_domain, "domain", ic_surface_set_domain(fx->par, NULL, NULL, &err));
    ic_surface_get_domain(NULL, dom, NULL);
    CHECK(dom[0][1] == 1, "get_domain NULL leaves domain");
    ic_jet_space *sp1 = NULL;
    REQUIRE(ic_jet_space_new(&sp1, 3, 2, &err) == IC_OK, "space: %s", err.message);
    BAD(ic_surface_taylor, "s", ic_surface_taylor(NULL, out, at, sp1, &err));
    BAD(ic_surface_taylor, "out", ic_surface_taylor(fx->A, NULL, at, sp1, &err));
    BAD(ic_surface_taylor, "at", ic_surface_taylor(fx->A, out, NULL, sp1, &err));
    BAD(ic_surface_taylor, "sp", ic_surface_taylor(fx->A, out, at, NULL, &err));
    const double *in[3] = {out, out, out};
    BAD(ic_surface_compose, "s", ic_surface_compose(NULL, out, in, sp1, &err));
    BAD(ic_surface_compose, "out", ic_surface_compose(fx->A, NULL, in, sp1, &err));
    BAD(ic_surface_compose, "in", ic_surface_compose(fx->A, out, NULL, sp1, &err));
    BAD(ic_surface_compose, "sp", ic_surface_compose(fx->A, out, in, NULL, &err));
    ic_jet_space_free(sp1);
    BAD(ic_surface_eval, "s", ic_surface_eval(NULL, out, at, &err));
    BAD(ic_surface_eval, "out", ic_surface_eval(fx->A, NULL, at, &err));
    BAD(ic_surface_eval, "at", ic_surface_eval(fx->A, out, NULL, &err));
    ic_interval box[3] = {{0, 1}, {0, 1}, {0, 1}}, iv[3];
    ic_interval_grad ig[3];
    BAD(ic_surface_eval_interval, "s", ic_surface_eval_interval(NULL, iv, box, &err));
    BAD(ic_surface_eval_interval, "out", ic_surface_eval_interval(fx->A, NULL, box, &err));
    BAD(ic_surface_eval_interval, "in", ic_surface_eval_interval(fx->A, iv, NULL, &err));
    BAD(ic_surface_eval_interval_grad, "s", ic_surface_eval_interval_grad(NULL, ig, box, &err));
    BAD(ic_surface_eval_interval_grad, "out", ic_surface_eval_interval_grad(fx->A, NULL, box, &err));
    BAD(ic_surface_eval_interval_grad, "in", ic_surface_eval_interval_grad(fx->A, ig, NULL, &err));
    ic_interval_hess ih[3];
    BAD(ic_surface_eval_interval_hess, "s", ic_surface_eval_interval_hess(NULL, ih, box, &err));
    BAD(ic_surface_eval_interval_hess, "out", ic_surface_eval_interval_hess(fx->A, NULL, box, &err));
    BAD(ic_surface_eval_interval_hess, "in", ic_surface_eval_interval_hess(fx->A, ih, NULL, &err));
    ic_surface_geometry g;
    BAD(ic_surface_geometry_at, "s", ic_surface_geometry_at(NULL, &g, at, &err));
    BAD(ic_surface_geometry_at, "g", ic_surface_geometry_at(fx->A, NULL, at, &err));
    BAD(ic_surface_geometry_at, "at", ic_surface_geometry_at(fx->A, &g, NULL, &err));
    BAD(ic_surface_normal_at, "s", ic_surface_normal_at(NULL, &g, at, &err));
    BAD(ic_surface_normal_at, "g", ic_surface_normal_at(fx->A, NULL, at, &err));
    BAD(ic_surface_normal_at, "at", ic_surface_normal_at(fx->A, &g, NULL, &err));
    /* err itself may be NULL */
    CHECK(ic_surface_eval(NULL, out, at, NULL) == IC_ERR_INVALID, "err NULL");
}

static void jet_args(fixture *fx)
{
    ic_jet_space *sp = fx->sp;
    const int n = ic_jet_space_len(sp);
    double a[64], b[64], c[64], scratch[4096];
    int alpha[2] = {1, 1};
    REQUIRE(n <= 64 && ic_jet_scratch_len(sp) <= 4096, "buffers too small");
    ic_jet_set_var(a, 0.5, 0, sp);
    ic_jet_set_var(b, 0.25, 1, sp);
    BAD(ic_jet_space_new, "sp", ic_jet_space_new(NULL, 2, 3, &err));
    ic_jet_space_free(NULL);
    CHECK(ic_jet_space_num_vars(NULL) == 0 && ic_jet_space_order(NULL) == 0 &&
              ic_jet_space_len(NULL) == 0 && ic_jet_scratch_len(NULL) == 0,
          "space getters NULL");
    CHECK(ic_jet_degree_start(NULL, 1) == 0, "degree_start NULL");
    CHECK(ic_jet_index(NULL, alpha) == -1 && ic_jet_index(sp, NULL) == -1, "index NULL");
    alpha[0] = 7;
    ic_jet_exponents(NULL, 0, alpha);
    ic_jet_exponents(sp, n, alpha);
    ic_jet_exponents(sp, -1, alpha);
    ic_jet_exponents(sp, 0, NULL);
    CHECK(alpha[0] == 7, "exponents out of range leaves alpha");
    CHECK(ic_jet_factorial(NULL, 0) == 0 && ic_jet_factorial(sp, n) == 0 &&
              ic_jet_factorial(sp, -1) == 0, "factorial out of range");
    /* void operations: a NULL anywhere does nothing (c stays as it was) */
    c[0] = 42;
    ic_jet_zero(NULL, sp), ic_jet_zero(c, NULL);
    ic_jet_set_const(NULL, 1, sp), ic_jet_set_const(c, 1, NULL);
    ic_jet_set_var(NULL, 1, 0, sp), ic_jet_set_var(c, 1, 0, NULL);
    ic_jet_copy(NULL, a, sp), ic_jet_copy(c, NULL, sp), ic_jet_copy(c, a, NULL);
    ic_jet_add(NULL, a, b, sp), ic_jet_add(c, NULL, b, sp), ic_jet_add(c, a, NULL, sp);
    ic_jet_add(c, a, b, NULL);
    ic_jet_sub(NULL, a, b, sp), ic_jet_sub(c, NULL, b, sp), ic_jet_sub(c, a, NULL, sp);
    ic_jet_sub(c, a, b, NULL);
    ic_jet_neg(NULL, a, sp), ic_jet_neg(c, NULL, sp), ic_jet_neg(c, a, NULL);
    ic_jet_scale(NULL, a, 2, sp), ic_jet_scale(c, NULL, 2, sp), ic_jet_scale(c, a, 2, NULL);
    ic_jet_add_const(NULL, a, 2, sp), ic_jet_add_const(c, NULL, 2, sp);
    ic_jet_add_const(c, a, 2, NULL);
    ic_jet_mul(NULL, a, b, sp), ic_jet_mul(c, NULL, b, sp), ic_jet_mul(c, a, NULL, sp);
    ic_jet_mul(c, a, b, NULL);
    ic_jet_exp(NULL, a, sp), ic_jet_exp(c, NULL, sp), ic_jet_exp(c, a, NULL);
    ic_jet_sin_cos(NULL, b, a, sp), ic_jet_sin_cos(c, NULL, a, sp);
    ic_jet_sin_cos(c, b, NULL, sp), ic_jet_sin_cos(c, b, a, NULL);
    ic_jet_sinh_cosh(NULL, b, a, sp), ic_jet_sinh_cosh(c, NULL, a, sp);
    ic_jet_sinh_cosh(c, b, NULL, sp), ic_jet_sinh_cosh(c, b, a, NULL);
    void (*const unary[])(double *, const double *, const ic_jet_space *, double *) = {
        ic_jet_sin, ic_jet_cos, ic_jet_atan, ic_jet_sinh, ic_jet_cosh, ic_jet_tanh};
    for (size_t k = 0; k < sizeof unary / sizeof *unary; k++) {
        unary[k](NULL, a, sp, scratch), unary[k](c, NULL, sp, scratch);
        unary[k](c, a, NULL, scratch), unary[k](c, a, sp, NULL);
    }
    const double *g[2] = {a, b};
    ic_jet_compose(NULL, a, sp, g, sp, scratch), ic_jet_compose(c, NULL, sp, g, sp, scratch);
    ic_jet_compose(c, a, NULL, g, sp, scratch), ic_jet_compose(c, a, sp, NULL, sp, scratch);
    ic_jet_compose(c, a, sp, g, NULL, scratch), ic_jet_compose(c, a, sp, g, sp, NULL);
    CHECK(c[0] == 42, "a void jet operation with a NULL argument wrote its output");
    /* the fallible ones name the argument */
    BAD(ic_jet_div, "q", ic_jet_div(NULL, a, b, sp, &err));
    BAD(ic_jet_div, "a", ic_jet_div(c, NULL, b, sp, &err));
    BAD(ic_jet_div, "b", ic_jet_div(c, a, NULL, sp, &err));
    BAD(ic_jet_div, "sp", ic_jet_div(c, a, b, NULL, &err));
    ic_status (*const plain[])(double *, const double *, const ic_jet_space *, ic_error *) = {
        ic_jet_sqrt, ic_jet_log, ic_jet_abs};
    const char *const plain_names[] = {"ic_jet_sqrt", "ic_jet_log", "ic_jet_abs"};
    for (int k = 0; k < 3; k++) {
        ic_error_clear(&err), expect_invalid(plain[k](NULL, a, sp, &err), plain_names[k], "b", __LINE__);
        ic_error_clear(&err), expect_invalid(plain[k](c, NULL, sp, &err), plain_names[k], "a", __LINE__);
        ic_error_clear(&err), expect_invalid(plain[k](c, a, NULL, &err), plain_names[k], "sp", __LINE__);
    }
    ic_status (*const withscr[])(double *, const double *, const ic_jet_space *, double *,
                                 ic_error *) = {ic_jet_tan, ic_jet_asin, ic_jet_acos};
    const char *const withscr_names[] = {"ic_jet_tan", "ic_jet_asin", "ic_jet_acos"};
    const char *const out_names[] = {"t", "b", "b"};
    for (int k = 0; k < 3; k++) {
        ic_error_clear(&err), expect_invalid(withscr[k](NULL, a, sp, scratch, &err), withscr_names[k], out_names[k], __LINE__);
        ic_error_clear(&err), expect_invalid(withscr[k](c, NULL, sp, scratch, &err), withscr_names[k], "a", __LINE__);
        ic_error_clear(&err), expect_invalid(withscr[k](c, a, NULL, scratch, &err), withscr_names[k], "sp", __LINE__);
        ic_error_clear(&err), expect_invalid(withscr[k](c, a, sp, NULL, &err), withscr_names[k], "scratch", __LINE__);
    }
    BAD(ic_jet_pow_int, "b", ic_jet_pow_int(NULL, a, 2, sp, scratch, &err));
    BAD(ic_jet_pow_int, "a", ic_jet_pow_int(c, NULL, 2, sp, scratch, &err));
    BAD(ic_jet_pow_int, "sp", ic_jet_pow_int(c, a, 2, NULL, scratch, &err));
    BAD(ic_jet_pow_int, "scratch", ic_jet_pow_int(c, a, 2, sp, NULL, &err));
    BAD(ic_jet_pow_real, "b", ic_jet_pow_real(NULL, a, 2, sp, scratch, &err));
    BAD(ic_jet_pow_real, "a", ic_jet_pow_real(c, NULL, 2, sp, scratch, &err));
    BAD(ic_jet_pow_real, "sp", ic_jet_pow_real(c, a, 2, NULL, scratch, &err));
    BAD(ic_jet_pow_real, "scratch", ic_jet_pow_real(c, a, 2, sp, NULL, &err));
    BAD(ic_jet_atan2, "b", ic_jet_atan2(NULL, a, b, sp, scratch, &err));
    BAD(ic_jet_atan2, "y", ic_jet_atan2(c, NULL, b, sp, scratch, &err));
    BAD(ic_jet_atan2, "x", ic_jet_atan2(c, a, NULL, sp, scratch, &err));
    BAD(ic_jet_atan2, "sp", ic_jet_atan2(c, a, b, NULL, scratch, &err));
    BAD(ic_jet_atan2, "scratch", ic_jet_atan2(c, a, b, sp, NULL, &err));
    BAD(ic_jet_revert, "g", ic_jet_revert(NULL, a, sp, scratch, &err));
    BAD(ic_jet_revert, "f", ic_jet_revert(c, NULL, sp, scratch, &err));
    BAD(ic_jet_revert, "sp", ic_jet_revert(c, a, NULL, scratch, &err));
    BAD(ic_jet_revert, "scratch", ic_jet_revert(c, a, sp, NULL, &err));
    double *const gg[2] = {c, b};
    const double *const ff[2] = {a, b};
    BAD(ic_jet_revert2, "g", ic_jet_revert2(NULL, ff, sp, scratch, &err));
    BAD(ic_jet_revert2, "f", ic_jet_revert2(gg, NULL, sp, scratch, &err));
    BAD(ic_jet_revert2, "sp", ic_jet_revert2(gg, ff, NULL, scratch, &err));
    BAD(ic_jet_revert2, "scratch", ic_jet_revert2(gg, ff, sp, NULL, &err));
}

static void expr_args(fixture *fx)
{
    const char *f = "x + y";
    const char *vars[2] = {"x", "y"};
    ic_expr *e = NULL;
    double out[4], x[2] = {1, 2}, work[64], value;
    BAD(ic_expr_compile, "out", ic_expr_compile(NULL, &f, 1, vars, 2, NULL, 0, NULL, &err));
    BAD(ic_expr_compile, "formulas", ic_expr_compile(&e, NULL, 1, vars, 2, NULL, 0, NULL, &err));
    BAD(ic_expr_compile, "nformulas", ic_expr_compile(&e, &f, 0, vars, 2, NULL, 0, NULL, &err));
    BAD(ic_expr_compile, "nvars", ic_expr_compile(&e, &f, 1, vars, -1, NULL, 0, NULL, &err));
    BAD(ic_expr_compile, "vars", ic_expr_compile(&e, &f, 1, NULL, 2, NULL, 0, NULL, &err));
    ic_expr_free(NULL);
    CHECK(ic_expr_num_outputs(NULL) == 0 && ic_expr_num_vars(NULL) == 0 &&
              ic_expr_tape_len(NULL) == 0, "expr getters NULL");
    BAD(ic_expr_eval_constant, "value", ic_expr_eval_constant(NULL, "1", NULL, 0, &err));
    BAD(ic_expr_eval_constant, "formula", ic_expr_eval_constant(&value, NULL, NULL, 0, &err));
    CHECK(ic_expr_work_len(NULL) == 0 && ic_expr_interval_work_len(NULL) == 0 &&
              ic_expr_interval_grad_work_len(NULL) == 0 &&
              ic_expr_jet_work_len(NULL, fx->sp) == 0 && ic_expr_jet_work_len(fx->expr, NULL) == 0,
          "work lengths NULL");
    BAD(ic_expr_eval, "e", ic_expr_eval(NULL, out, x, work, &err));
    BAD(ic_expr_eval, "out", ic_expr_eval(fx->expr, NULL, x, work, &err));
    BAD(ic_expr_eval, "x", ic_expr_eval(fx->expr, out, NULL, work, &err));
    BAD(ic_expr_eval, "work", ic_expr_eval(fx->expr, out, x, NULL, &err));
    ic_interval ix[2] = {{0, 1}, {0, 1}}, iout = {5, 5}, iwork[64];
    ic_expr_eval_interval(NULL, &iout, ix, iwork);
    ic_expr_eval_interval(fx->expr, NULL, ix, iwork);
    ic_expr_eval_interval(fx->expr, &iout, NULL, iwork);
    ic_expr_eval_interval(fx->expr, &iout, ix, NULL);
    CHECK(iout.lo == 5, "eval_interval with a NULL argument wrote out");
    ic_interval_grad gx[2] = {{{0, 1}, {{1, 1}, {0, 0}, {0, 0}}}, {{0, 1}, {{0, 0}, {1, 1}, {0, 0}}}};
    ic_interval_grad gout, gwork[64];
    CHECK(ic_expr_eval_interval_grad(NULL, &gout, gx, 2, gwork) == 0 &&
              ic_expr_eval_interval_grad(fx->expr, NULL, gx, 2, gwork) == 0 &&
              ic_expr_eval_interval_grad(fx->expr, &gout, NULL, 2, gwork) == 0 &&
              ic_expr_eval_interval_grad(fx->expr, &gout, gx, 2, NULL) == 0,
          "eval_interval_grad NULL gives 0");
    ic_interval_hess hx[2] = {{.v = {0, 1}, .d = {{1, 1}}}, {.v = {0, 1}, .d = {{0, 0}, {1, 1}}}};
    ic_interval_hess hout, hwork[64];
    CHECK(ic_expr_interval_hess_work_len(NULL) == 0 &&
              ic_expr_eval_interval_hess(NULL, &hout, hx, 2, hwork) == 0 &&
              ic_expr_eval_interval_hess(fx->expr, NULL, hx, 2, hwork) == 0 &&
              ic_expr_eval_interval_hess(fx->expr, &hout, NULL, 2, hwork) == 0 &&
              ic_expr_eval_interval_hess(fx->expr, &hout, hx, 2, NULL) == 0 &&
              ic_expr_eval_interval_hess(fx->expr, &hout, hx, 4, hwork) == 0,
          "eval_interval_hess NULL or too many directions gives 0");
    CHECK(ic_interval_hess_index(0, 0) == 0 && ic_interval_hess_index(2, 1) == 4 &&
              ic_interval_hess_index(1, 2) == 4 && ic_interval_hess_index(2, 2) == 5,
          "Hessian entries in the order (0,0) (0,1) (0,2) (1,1) (1,2) (2,2)");
    double ja[64], jb[64], jout[64], jwork[4096];
    const double *jx[2] = {ja, jb};
    REQUIRE(ic_expr_jet_work_len(fx->expr, fx->sp) <= 4096, "jet work too small");
    BAD(ic_expr_eval_jet, "e", ic_expr_eval_jet(NULL, jout, jx, fx->sp, jwork, &err));
    BAD(ic_expr_eval_jet, "out", ic_expr_eval_jet(fx->expr, NULL, jx, fx->sp, jwork, &err));
    BAD(ic_expr_eval_jet, "x", ic_expr_eval_jet(fx->expr, jout, NULL, fx->sp, jwork, &err));
    BAD(ic_expr_eval_jet, "sp", ic_expr_eval_jet(fx->expr, jout, jx, NULL, jwork, &err));
    BAD(ic_expr_eval_jet, "work", ic_expr_eval_jet(fx->expr, jout, jx, fx->sp, NULL, &err));
    char buf[200] = "x";
    CHECK(ic_expr_caret(NULL, 10, "x", 1) == NULL, "caret NULL buf");
    CHECK(ic_expr_caret(buf, sizeof buf, NULL, 1) == buf && buf[0] == '\0', "caret NULL formula");
}

/* The interval functions take values, no pointers: nothing can be NULL;
 * an empty or reversed interval is still answered. */
static void interval_args(void)
{
    const ic_interval a = {1, 2}, b = {-1, 3}, r = {2, 1};
    ic_interval (*const one[])(ic_interval) = {
        ic_interval_neg,  ic_interval_sqrt, ic_interval_exp,  ic_interval_log,  ic_interval_sin,
        ic_interval_cos,  ic_interval_tan,  ic_interval_asin, ic_interval_acos, ic_interval_atan,
        ic_interval_sinh, ic_interval_cosh, ic_interval_tanh, ic_interval_abs};
    ic_interval (*const two[])(ic_interval, ic_interval) = {
        ic_interval_add, ic_interval_sub, ic_interval_mul, ic_interval_div, ic_interval_pow,
        ic_interval_atan2};
    for (size_t k = 0; k < sizeof one / sizeof *one; k++)
        (void)one[k](r);
    for (size_t k = 0; k < sizeof two / sizeof *two; k++)
        (void)two[k](a, b), (void)two[k](r, a);
    (void)ic_interval_pow_int(r, -3);
    (void)ic_interval_pow_real(r, 0.5);
    CHECK(!ic_interval_is_empty(a), "a non-empty interval");
}

static void local_args(fixture *fx)
{
    ic_pair *p = (ic_pair *)1;
    ic_local_point pt;
    ic_local_result res;
    const double xyz[3] = {1.5, 0, 1}, params[2][2] = {{0, 0}, {0, 0}}, values[2] = {0, 0};
    double radius;
    CHECK(ic_point_type_name((ic_point_type)99) != NULL, "point type name");
    CHECK(ic_method_name((ic_method)99) != NULL, "method name");
    CHECK(ic_method_from_name(NULL) == -1, "method_from_name NULL");
    ic_local_defaults(NULL);
    BAD(ic_pair_new, "pair", ic_pair_new(NULL, fx->A, fx->B, &err));
    BAD(ic_pair_new, "A", ic_pair_new(&p, NULL, fx->B, &err));
    CHECK(p == NULL, "*pair is NULL on failure");
    ic_pair_free(NULL);
    CHECK(ic_pair_is_self(NULL) == 0, "is_self NULL");
    CHECK(ic_pair_surface(NULL, 0) == NULL && ic_pair_surface(fx->pair, 2) == NULL &&
              ic_pair_surface(fx->pair, -1) == NULL && ic_pair_surface(fx->pair, 1) == fx->B,
          "pair_surface");
    ic_local_options *o = &fx->lopt;
    BAD(ic_local_locate, "pair", ic_local_locate(NULL, &pt, xyz, o, &err));
    BAD(ic_local_locate, "pt", ic_local_locate(fx->pair, NULL, xyz, o, &err));
    BAD(ic_local_locate, "xyz", ic_local_locate(fx->pair, &pt, NULL, o, &err));
    BAD(ic_local_locate, "opt", ic_local_locate(fx->pair, &pt, xyz, NULL, &err));
    BAD(ic_local_locate_params, "pair", ic_local_locate_params(NULL, &pt, values, 2, o, &err));
    BAD(ic_local_locate_params, "pt", ic_local_locate_params(fx->pair, NULL, values, 2, o, &err));
    BAD(ic_local_locate_params, "params", ic_local_locate_params(fx->pair, &pt, NULL, 2, o, &err));
    BAD(ic_local_locate_params, "opt", ic_local_locate_params(fx->pair, &pt, values, 2, NULL, &err));
    BAD(ic_local_locate_guess, "pair", ic_local_locate_guess(NULL, &pt, xyz, params, o, &err));
    BAD(ic_local_locate_guess, "pt", ic_local_locate_guess(fx->pair, NULL, xyz, params, o, &err));
    BAD(ic_local_locate_guess, "xyz", ic_local_locate_guess(fx->pair, &pt, NULL, params, o, &err));
    BAD(ic_local_locate_guess, "params", ic_local_locate_guess(fx->pair, &pt, xyz, NULL, o, &err));
    BAD(ic_local_locate_guess, "opt", ic_local_locate_guess(fx->pair, &pt, xyz, params, NULL, &err));
    BAD(ic_local_locate_tangential, "pair", ic_local_locate_tangential(NULL, &pt, &fx->pt, 1, o, &err));
    BAD(ic_local_locate_tangential, "pt", ic_local_locate_tangential(fx->pair, NULL, &fx->pt, 1, o, &err));
    BAD(ic_local_locate_tangential, "near", ic_local_locate_tangential(fx->pair, &pt, NULL, 1, o, &err));
    BAD(ic_local_tangential_place, "pair", ic_local_tangential_place(NULL, &fx->pt, o, &radius, &err));
    BAD(ic_local_tangential_place, "pt", ic_local_tangential_place(fx->pair, NULL, o, &radius, &err));
    BAD(ic_local_tangential_place, "radius", ic_local_tangential_place(fx->pair, &fx->pt, o, NULL, &err));
    BAD(ic_local_locate_degenerate, "pair", ic_local_locate_degenerate(NULL, &pt, &fx->pt, 1, o, &err));
    BAD(ic_local_locate_degenerate, "pt", ic_local_locate_degenerate(fx->pair, NULL, &fx->pt, 1, o, &err));
    BAD(ic_local_locate_degenerate, "near", ic_local_locate_degenerate(fx->pair, &pt, NULL, 1, o, &err));
    /* opt may be NULL for these three (the defaults): a status, no crash */
    ic_status st[3] = {ic_local_locate_tangential(fx->pair, &pt, &fx->pt, 1, NULL, &err),
                       ic_local_tangential_place(fx->pair, &fx->pt, NULL, &radius, &err),
                       ic_local_locate_degenerate(fx->pair, &pt, &fx->pt, 1, NULL, &err)};
    for (int k = 0; k < 3; k++)
        CHECK(st[k] >= IC_OK && st[k] <= IC_ERR_IO, "opt NULL: status %d", (int)st[k]);
    BAD(ic_local_find, "pair", ic_local_find(NULL, &pt, xyz, 3, 0, o, &err));
    BAD(ic_local_find, "pt", ic_local_find(fx->pair, NULL, xyz, 3, 0, o, &err));
    BAD(ic_local_find, "values", ic_local_find(fx->pair, &pt, NULL, 3, 0, o, &err));
    BAD(ic_local_find, "opt", ic_local_find(fx->pair, &pt, xyz, 3, 0, NULL, &err));
    ic_branch_reverse(NULL);
    CHECK(ic_branch_is_line(NULL, 1) == 0 && ic_branch_is_planar(NULL, 1) == 0, "branch NULL");
    BAD(ic_local_apparatus, "pair", ic_local_apparatus(NULL, &res, &fx->pt, 3, IC_METHOD_AUTO, o, &err));
    BAD(ic_local_apparatus, "res", ic_local_apparatus(fx->pair, NULL, &fx->pt, 3, IC_METHOD_AUTO, o, &err));
    BAD(ic_local_apparatus, "pt", ic_local_apparatus(fx->pair, &res, NULL, 3, IC_METHOD_AUTO, o, &err));
    BAD(ic_local_apparatus, "opt", ic_local_apparatus(fx->pair, &res, &fx->pt, 3, IC_METHOD_AUTO, NULL, &err));
}

static void trace_args(fixture *fx)
{
    ic_tracer *tr = (ic_tracer *)1;
    ic_trace_event ev;
    ic_trace_result *res = (ic_trace_result *)1;
    ic_curve_fit *fit = (ic_curve_fit *)1;
    ic_trace_defaults(NULL);
    CHECK(ic_trace_event_name((ic_trace_event)99) != NULL, "event name");
    CHECK(ic_shape_name((ic_shape)99) != NULL, "shape name");
    ic_trace_points_reverse(NULL, 3);
    BAD(ic_tracer_new, "tr", ic_tracer_new(NULL, fx->pair, &fx->topt, &err));
    BAD(ic_tracer_new, "pair", ic_tracer_new(&tr, NULL, &fx->topt, &err));
    CHECK(tr == NULL, "*tr is NULL on failure");
    BAD(ic_tracer_new, "opt", ic_tracer_new(&tr, fx->pair, NULL, &err));
    ic_tracer_free(NULL);
    if (REQUIRE(ic_tracer_new(&tr, fx->pair, &fx->topt, &err) == IC_OK, "tracer: %s", err.message)) {
        BAD(ic_tracer_start, "tr", ic_tracer_start(NULL, &fx->pt, 1, &err));
        BAD(ic_tracer_start, "start", ic_tracer_start(tr, NULL, 1, &err));
        BAD(ic_tracer_step, "tr", ic_tracer_step(NULL, &ev, &err));
        BAD(ic_tracer_run, "tr", ic_tracer_run(NULL, &ev, &err));
        if (REQUIRE(ic_tracer_start(tr, &fx->pt, 1, &err) == IC_OK, "start: %s", err.message)) {
            BAD(ic_tracer_step, "event", ic_tracer_step(tr, NULL, &err));
            BAD(ic_tracer_run, "event", ic_tracer_run(tr, NULL, &err));
            const int n = ic_tracer_num_points(tr);
            CHECK(n >= 1 && ic_tracer_point(tr, n) == NULL && ic_tracer_point(tr, -1) == NULL,
                  "tracer point out of range");
        }
        ic_tracer_free(tr);
    }
    CHECK(ic_tracer_num_points(NULL) == 0 && ic_tracer_point(NULL, 0) == NULL, "tracer NULL");
    BAD(ic_trace, "res", ic_trace(NULL, fx->pair, &fx->topt, &err));
    BAD(ic_trace, "pair", ic_trace(&res, NULL, &fx->topt, &err));
    BAD(ic_trace, "opt", ic_trace(&res, fx->pair, NULL, &err));
    CHECK(ic_trace(NULL, fx->pair, &fx->topt, NULL) == IC_ERR_INVALID, "err NULL");
    ic_trace_result_free(NULL);
    const int nc = ic_trace_result_num_curves(fx->res), ns = ic_trace_result_num_specials(fx->res);
    CHECK(nc == 1, "the sphere and the plane meet in one circle, got %d curves", nc);
    CHECK(ic_trace_result_num_curves(NULL) == 0 && ic_trace_result_num_specials(NULL) == 0 &&
              ic_trace_result_curve(NULL, 0) == NULL && ic_trace_result_special(NULL, 0) == NULL &&
              ic_trace_result_report(NULL) == NULL && ic_trace_result_fit(NULL, 0) == NULL,
          "result getters NULL");
    CHECK(ic_trace_result_curve(fx->res, nc) == NULL && ic_trace_result_curve(fx->res, -1) == NULL &&
              ic_trace_result_special(fx->res, ns) == NULL &&
              ic_trace_result_special(fx->res, -1) == NULL &&
              ic_trace_result_fit(fx->res, nc) == NULL && ic_trace_result_fit(fx->res, -1) == NULL,
          "result getters out of range");
    BAD(ic_trace_fit, "res", ic_trace_fit(NULL, fx->pair, 1e-6, &err));
    BAD(ic_trace_fit, "pair", ic_trace_fit(fx->res, NULL, 1e-6, &err));
    const ic_trace_curve *c = ic_trace_result_curve(fx->res, 0);
    BAD(ic_curve_fit_new, "fit", ic_curve_fit_new(NULL, fx->pair, c, 1e-6, &err));
    BAD(ic_curve_fit_new, "pair", ic_curve_fit_new(&fit, NULL, c, 1e-6, &err));
    CHECK(fit == NULL, "*fit is NULL on failure");
    BAD(ic_curve_fit_new, "c", ic_curve_fit_new(&fit, fx->pair, NULL, 1e-6, &err));
    ic_curve_fit_free(NULL);
    const ic_curve_fit *cf = ic_trace_result_fit(fx->res, 0);
    double out[3];
    if (REQUIRE(cf != NULL, "curve 0 fitted")) {
        BAD(ic_bspline_eval, "c", ic_bspline_eval(NULL, 0, 0, out, &err));
        BAD(ic_bspline_eval, "out", ic_bspline_eval(&cf->curve, 0, 0, NULL, &err));
    }
}

static ic_status write_nothing(FILE *f, void *user, ic_error *e)
{
    (void)f, (void)user, (void)e;
    return IC_OK;
}

static void writer_args(fixture *fx, FILE *f)
{
    const ic_trace_curve *c = ic_trace_result_curve(fx->res, 0);
    const double at[3] = {1, 1, 1};
    CHECK(ic_trace_point_type(NULL, c, NULL) == IC_POINT_TRANSVERSAL &&
              ic_trace_point_type(fx->res, NULL, NULL) == IC_POINT_TRANSVERSAL,
          "point type NULL");
    BAD(ic_trace_write_csv, "f", ic_trace_write_csv(NULL, fx->res, fx->pair, &err));
    BAD(ic_trace_write_csv, "res", ic_trace_write_csv(f, NULL, fx->pair, &err));
    BAD(ic_trace_write_csv, "pair", ic_trace_write_csv(f, fx->res, NULL, &err));
    BAD(ic_trace_write_vtk, "f", ic_trace_write_vtk(NULL, fx->res, &err));
    BAD(ic_trace_write_vtk, "res", ic_trace_write_vtk(f, NULL, &err));
    BAD(ic_trace_write_obj, "f", ic_trace_write_obj(NULL, fx->res, &err));
    BAD(ic_trace_write_obj, "res", ic_trace_write_obj(f, NULL, &err));
    BAD(ic_local_write_json, "f", ic_local_write_json(NULL, &fx->lres, fx->pair, 3, &err));
    BAD(ic_local_write_json, "res", ic_local_write_json(f, NULL, fx->pair, 3, &err));
    BAD(ic_local_write_json, "pair", ic_local_write_json(f, &fx->lres, NULL, 3, &err));
    BAD(ic_local_write_text, "f", ic_local_write_text(NULL, &fx->lres, &err));
    BAD(ic_local_write_text, "res", ic_local_write_text(f, NULL, &err));
    BAD(ic_trace_write_json, "f", ic_trace_write_json(NULL, fx->res, fx->pair, &err));
    BAD(ic_trace_write_json, "res", ic_trace_write_json(f, NULL, fx->pair, &err));
    BAD(ic_trace_write_json, "pair", ic_trace_write_json(f, fx->res, NULL, &err));
    BAD(ic_trace_write_text, "f", ic_trace_write_text(NULL, fx->res, NULL, &err));
    BAD(ic_trace_write_text, "res", ic_trace_write_text(f, NULL, NULL, &err));
    BAD(ic_surface_write_json, "f", ic_surface_write_json(NULL, fx->A, "A", at, 2, &err));
    BAD(ic_surface_write_json, "s", ic_surface_write_json(f, NULL, "A", at, 2, &err));
    BAD(ic_surface_write_json, "name", ic_surface_write_json(f, fx->A, NULL, at, 2, &err));
    BAD(ic_surface_write_json, "at", ic_surface_write_json(f, fx->A, "A", NULL, 2, &err));
    BAD(ic_trace_write_step, "f", ic_trace_write_step(NULL, fx->res, NULL, &err));
    BAD(ic_trace_write_step, "res", ic_trace_write_step(f, NULL, NULL, &err));
    BAD(ic_trace_write_iges, "f", ic_trace_write_iges(NULL, fx->res, NULL, &err));
    BAD(ic_trace_write_iges, "res", ic_trace_write_iges(f, NULL, NULL, &err));
    BAD(ic_write_file_atomic, "path", ic_write_file_atomic(NULL, write_nothing, NULL, &err));
    BAD(ic_write_file_atomic, "writer", ic_write_file_atomic("unused", NULL, NULL, &err));
}

static void problem_args(fixture *fx, FILE *f)
{
    ic_problem *p = (ic_problem *)1;
    double box[3][2];
    BAD(ic_problem_load, "p", ic_problem_load(NULL, "x.json", &err));
    BAD(ic_problem_load, "filename", ic_problem_load(&p, NULL, &err));
    CHECK(p == NULL, "*p is NULL on failure");
    BAD(ic_problem_parse, "p", ic_problem_parse(NULL, PROBLEM, sizeof PROBLEM - 1, &err));
    BAD(ic_problem_parse, "json", ic_problem_parse(&p, NULL, 10, &err));
    BAD(ic_problem_read, "p", ic_problem_read(NULL, f, "f", 0, &err));
    BAD(ic_problem_read, "f", ic_problem_read(&p, NULL, "f", 0, &err));
    BAD(ic_problem_read, "name", ic_problem_read(&p, f, NULL, 0, &err));
    ic_problem_free(NULL);
    CHECK(ic_problem_title(NULL) == NULL && ic_problem_num_surfaces(NULL) == 0 &&
              ic_problem_surface(NULL, 0) == NULL && ic_problem_surface_name(NULL, 0) == NULL &&
              ic_problem_find_surface(NULL, "A") == -1 && ic_problem_is_self(NULL) == 0 &&
              ic_problem_box(NULL, box) == 0,
          "problem getters NULL");
    CHECK(ic_problem_surface(fx->problem, 2) == NULL && ic_problem_surface(fx->problem, -1) == NULL &&
              ic_problem_surface_name(fx->problem, 2) == NULL &&
              ic_problem_surface_name(fx->problem, -1) == NULL &&
              ic_problem_find_surface(fx->problem, NULL) == -1,
          "problem getters out of range");
}

static void binding_and_plot_args(fixture *fx)
{
    ic_trace_result *res = (ic_trace_result *)1;
    ic_pair *pair = (ic_pair *)1;
    char *json;
    size_t len;
    const double values[3] = {1.5, 0, 1};
    const ic_problem *pb = fx->problem;
    BAD(ic_problem_trace, "res", ic_problem_trace(NULL, &pair, pb, 1e-9, 4, 0, 0, 0, &err));
    BAD(ic_problem_trace, "pair", ic_problem_trace(&res, NULL, pb, 1e-9, 4, 0, 0, 0, &err));
    BAD(ic_problem_trace, "problem", ic_problem_trace(&res, &pair, NULL, 1e-9, 4, 0, 0, 0, &err));
    CHECK(res == NULL && pair == NULL, "problem_trace outputs NULL on failure");
    res = (ic_trace_result *)1, pair = (ic_pair *)1;
    BAD(ic_problem_trace_keep_certificate, "res", ic_problem_trace_keep_certificate(NULL, &pair, pb, 1e-9, 4, 0, 0, 0, &err));
    BAD(ic_problem_trace_keep_certificate, "pair", ic_problem_trace_keep_certificate(&res, NULL, pb, 1e-9, 4, 0, 0, 0, &err));
    BAD(ic_problem_trace_keep_certificate, "problem", ic_problem_trace_keep_certificate(&res, &pair, NULL, 1e-9, 4, 0, 0, 0, &err));
    CHECK(res == NULL && pair == NULL, "problem_trace_keep_certificate outputs NULL on failure");
    CHECK(ic_trace_result_certificate(NULL) == NULL, "a NULL result has no certificate");
    CHECK(ic_trace_result_certificate(fx->res) == NULL, "a result not kept has no certificate");
    BAD(ic_trace_json_alloc, "json", ic_trace_json_alloc(NULL, &len, fx->res, fx->pair, &err));
    BAD(ic_trace_json_alloc, "res", ic_trace_json_alloc(&json, &len, NULL, fx->pair, &err));
    BAD(ic_trace_json_alloc, "pair", ic_trace_json_alloc(&json, &len, fx->res, NULL, &err));
    ic_trace_certificate cert;
    BAD(ic_problem_verify, "problem", ic_problem_verify(NULL, "{}", &cert, &err));
    BAD(ic_problem_verify, "trace_json", ic_problem_verify(pb, NULL, &cert, &err));
    BAD(ic_problem_verify, "out", ic_problem_verify(pb, "{}", NULL, &err));
    BAD(ic_problem_verify_json, "json", ic_problem_verify_json(NULL, &len, pb, "{}", &err));
    BAD(ic_problem_verify_json, "problem", ic_problem_verify_json(&json, &len, NULL, "{}", &err));
    BAD(ic_problem_verify_certificate, "problem", ic_problem_verify_certificate(NULL, "{}", "{}", &cert, &err));
    BAD(ic_problem_verify_certificate, "trace_json", ic_problem_verify_certificate(pb, NULL, "{}", &cert, &err));
    BAD(ic_problem_verify_certificate, "certificate_json", ic_problem_verify_certificate(pb, "{}", NULL, &cert, &err));
    BAD(ic_problem_verify_certificate, "out", ic_problem_verify_certificate(pb, "{}", "{}", NULL, &err));
    BAD(ic_problem_verify_certificate_json, "json", ic_problem_verify_certificate_json(NULL, &len, pb, "{}", "{}", &err));
    BAD(ic_problem_verify_certificate_json, "problem", ic_problem_verify_certificate_json(&json, &len, NULL, "{}", "{}", &err));
    BAD(ic_certificate_write_json, "f", ic_certificate_write_json(NULL, &cert, &err));
    BAD(ic_certificate_write_json, "c", ic_certificate_write_json(stdout, NULL, &err));
    BAD(ic_problem_point_json, "json", ic_problem_point_json(NULL, &len, pb, values, 3, 0, 2, "auto", 1e-6, &err));
    BAD(ic_problem_point_json, "problem", ic_problem_point_json(&json, &len, NULL, values, 3, 0, 2, "auto", 1e-6, &err));
    BAD(ic_problem_point_json, "values", ic_problem_point_json(&json, &len, pb, NULL, 3, 0, 2, "auto", 1e-6, &err));
    BAD(ic_problem_point_json, "method", ic_problem_point_json(&json, &len, pb, values, 3, 0, 2, NULL, 1e-6, &err));
    BAD(ic_problem_plot, "path", ic_problem_plot(NULL, pb, NULL, 100, 100, 0, 0, 0, 0, 8, &err));
    BAD(ic_problem_plot, "problem", ic_problem_plot("unused.png", NULL, NULL, 100, 100, 0, 0, 0, 0, 8, &err));
    ic_plot_defaults(NULL);
    ic_plot_scene_of_problem(NULL, pb, NULL);
    ic_plot_scene scene;
    ic_plot_scene_of_problem(&scene, NULL, NULL);
    CHECK(scene.surfaces[0] == NULL && scene.title == NULL, "scene of a NULL problem is empty");
    BAD(ic_plot_write, "path", ic_plot_write(NULL, &scene, NULL, &err));
    BAD(ic_plot_write, "scene", ic_plot_write("unused.png", NULL, NULL, &err));
}

int main(void)
{
    fixture fx;
    if (setup(&fx)) {
        FILE *f = tmpfile();
        if (REQUIRE(f != NULL, "tmpfile")) {
            common_args();
            surface_args(&fx);
            jet_args(&fx);
            expr_args(&fx);
            interval_args();
            local_args(&fx);
            trace_args(&fx);
            writer_args(&fx, f);
            problem_args(&fx, f);
            binding_and_plot_args(&fx);
            fclose(f);
        }
    }
    teardown(&fx);
    return harness_finish("api_args");
}
