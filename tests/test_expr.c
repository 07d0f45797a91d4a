/* The formula language: parse errors with columns, evaluation on doubles,
 * jets and intervals, constant folding and sharing. */
#include <string.h>

#include "harness.h"
#include "intercurve/expr.h"

static const char *const XYZ[3] = {"x", "y", "z"};

typedef struct {
    const char *formula;
    int column;          /* expected column of the error */
    const char *message; /* expected part of the message */
} bad_formula;

static const bad_formula BAD[] = {
    {"", 1, "empty formula"},
    {"   ", 1, "empty formula"},
    {"foo + x", 1, "unknown identifier 'foo'"},
    {"x + foo(y)", 5, "unknown function 'foo'"},
    {"sin(x, y)", 1, "takes 1 argument, got 2"},
    {"atan2(x)", 1, "takes 2 arguments, got 1"},
    {"sin()", 1, "takes 1 argument, got 0"},
    {"(x + 1", 1, "never closed"},
    {"2 * sin(x", 8, "never closed"},
    {"x + 1)", 6, "')' without a matching '('"},
    {"x y", 3, "expected an operator"},
    {"1e", 1, "exponent has no digits"},
    {"2*1e+", 3, "exponent has no digits"},
    {"1.2.3", 1, "malformed number"},
    {"1e999", 1, "not finite"},
    {"x +", 4, "unexpected end of formula"},
    {"* x", 1, "unexpected '*'"},
    {"x $ y", 3, "unexpected character '$'"},
    {"sin + x", 1, "needs its arguments in parentheses"},
    {"x(1)", 1, "unknown function 'x'"},
    {"log(0)", 1, "non-finite constant"},
    {"1/0", 2, "non-finite constant"},
    {"2^^3", 3, "unexpected '^'"},
    {"x,y", 2, "expected an operator"},
    {".", 1, "'.' without digits"},
    {"sqrt(-1) + x", 1, "non-finite constant"},
    {"x + (y * )", 10, "unexpected ')'"},
    {"2x", 1, "malformed number"},
    {"exp(1000)", 1, "non-finite constant"},
};

static void test_parse_errors(void)
{
    const int nbad = (int)(sizeof BAD / sizeof BAD[0]);
    CHECK(nbad >= 20, "at least 20 malformed inputs");
    for (int i = 0; i < nbad; i++) {
        ic_expr *e = NULL;
        ic_error err;
        ic_error_clear(&err);
        int which = 7;
        ic_status st = ic_expr_compile(&e, &BAD[i].formula, 1, XYZ, 3, NULL, 0, &which, &err);
        CHECK(st == IC_ERR_PARSE && e == NULL, "'%s' is a parse error (status %d)", BAD[i].formula,
              st);
        CHECK(which == 0, "'%s': formula index reported", BAD[i].formula);
        CHECK(err.column == BAD[i].column, "'%s': column %d, want %d (%s)", BAD[i].formula,
              err.column, BAD[i].column, err.message);
        CHECK(strstr(err.message, BAD[i].message) != NULL, "'%s': message '%s' lacks '%s'",
              BAD[i].formula, err.message, BAD[i].message);
    }
    /* nesting deeper than the limit is an error, not a stack overflow */
    char deep[2 * IC_EXPR_MAX_DEPTH + 64];
    int k = 0;
    for (int i = 0; i < IC_EXPR_MAX_DEPTH + 5; i++)
        deep[k++] = '(';
    deep[k++] = 'x';
    for (int i = 0; i < IC_EXPR_MAX_DEPTH + 5; i++)
        deep[k++] = ')';
    deep[k] = '\0';
    const char *dp = deep;
    ic_expr *e = NULL;
    ic_error err;
    CHECK(ic_expr_compile(&e, &dp, 1, XYZ, 3, NULL, 0, NULL, &err) == IC_ERR_PARSE &&
              strstr(err.message, "nested too deeply"),
          "deep nesting: %s", err.message);
    /* the second of three formulas is at fault */
    const char *three[3] = {"x", "y +* z", "z"};
    int which = -1;
    CHECK(ic_expr_compile(&e, three, 3, XYZ, 3, NULL, 0, &which, &err) == IC_ERR_PARSE &&
              which == 1 && err.column == 4,
          "which = %d, column %d", which, err.column);
    /* bad names of variables and constants */
    const ic_constant bad_const[1] = {{"sin", 1.0}};
    const char *f = "x";
    CHECK(ic_expr_compile(&e, &f, 1, XYZ, 3, bad_const, 1, NULL, &err) == IC_ERR_INVALID,
          "constant named like a function");
    const ic_constant dup[1] = {{"x", 1.0}};
    CHECK(ic_expr_compile(&e, &f, 1, XYZ, 3, dup, 1, NULL, &err) == IC_ERR_INVALID &&
              strstr(err.message, "twice"),
          "constant named like a variable: %s", err.message);
    /* the caret picture */
    char caret[200];
    ic_expr_caret(caret, sizeof caret, "x + foo(y)", 5);
    CHECK(strcmp(caret, "  x + foo(y)\n      ^\n") == 0, "caret:\n%s", caret);
}

static void test_numbers_and_constants(void)
{
    const struct {
        const char *text;
        double value;
    } cases[] = {{"1", 1.0},
                 {"2.5", 2.5},
                 {".5", 0.5},
                 {"1e-3", 1e-3},
                 {"1.5E+2", 150.0},
                 {"0.1", 0.1},
                 {"-2^2", -4.0},
                 {"2^3^2", 512.0},
                 {"2^-1", 0.5},
                 {"pi", 3.141592653589793},
                 {"e", 2.718281828459045},
                 {"2*pi", 6.283185307179586},
                 {"atan2(1, 1)", 0.7853981633974483},
                 {"pow(2, 10)", 1024.0},
                 {"abs(-3)", 3.0},
                 {"123456789012345678901234567890", 1.2345678901234568e29},
                 {"0.000000000000000000001", 1e-21},
                 {"8 - 3 - 2", 3.0},
                 {"8 / 4 / 2", 1.0}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        double v = NAN;
        ic_error err;
        ic_status st = ic_expr_eval_constant(&v, cases[i].text, NULL, 0, &err);
        CHECK(st == IC_OK && v == cases[i].value, "'%s' = %.17g, want %.17g", cases[i].text, v,
              cases[i].value);
    }
    const ic_constant consts[2] = {{"R", 2.0}, {"r_1", 0.5}};
    double v;
    CHECK(ic_expr_eval_constant(&v, "R^2 - r_1", consts, 2, NULL) == IC_OK && v == 3.5,
          "constants: %g", v);
    ic_error err;
    CHECK(ic_expr_eval_constant(&v, "x + 1", NULL, 0, &err) == IC_ERR_PARSE && err.column == 1,
          "a variable in a constant formula");
}

/* Folding and sharing: the tape of a torus parametrisation. */
static void test_tape(void)
{
    const char *torus[3] = {"(2 + 0.5*cos(v))*cos(u)", "(2 + 0.5*cos(v))*sin(u)", "0.5*sin(v)"};
    const char *uv[2] = {"u", "v"};
    ic_expr *e = NULL;
    if (!REQUIRE(ic_expr_compile(&e, torus, 3, uv, 2, NULL, 0, NULL, NULL) == IC_OK,
                 "torus compiles"))
        return;
    /* u, v, 2, 0.5, cos v, 0.5 cos v, 2 + ., cos u, *, sin u, *, sin v, 0.5 sin v = 13 */
    CHECK(ic_expr_tape_len(e) == 13, "shared subexpressions: tape of %d", ic_expr_tape_len(e));
    double out[3], work[64];
    const double at[2] = {0.3, 1.1};
    CHECK(ic_expr_eval(e, out, at, work, NULL) == IC_OK, "eval");
    CHECK_CLOSE(out[0], (2 + 0.5 * cos(1.1)) * cos(0.3), 2 * DBL_EPSILON, "torus x");
    CHECK_CLOSE(out[2], 0.5 * sin(1.1), 2 * DBL_EPSILON, "torus z");
    ic_expr_free(e);
    const char *folded = "x * (2*pi - sqrt(4)*pi) + sin(pi/2)";
    if (!REQUIRE(ic_expr_compile(&e, &folded, 1, XYZ, 3, NULL, 0, NULL, NULL) == IC_OK,
                 "folded formula compiles"))
        return;
    /* constants fold: x, 0 (2pi - 2pi), x*0, 1, + */
    CHECK(ic_expr_tape_len(e) <= 5, "folded tape of %d", ic_expr_tape_len(e));
    ic_expr_free(e);
}

static void test_eval_domain(void)
{
    const char *f = "log(x) + sqrt(y)";
    ic_expr *e = NULL;
    if (!REQUIRE(ic_expr_compile(&e, &f, 1, XYZ, 3, NULL, 0, NULL, NULL) == IC_OK, "compiles"))
        return;
    double out, work[16];
    ic_error err;
    const double bad[3] = {-1.0, 1.0, 0.0};
    CHECK(ic_expr_eval(e, &out, bad, work, &err) == IC_ERR_DOMAIN && err.column == 1,
          "log(-1): column %d, %s", err.column, err.message);
    const double bad2[3] = {1.0, -1.0, 0.0};
    CHECK(ic_expr_eval(e, &out, bad2, work, &err) == IC_ERR_DOMAIN && err.column == 10,
          "sqrt(-1): column %d", err.column);
    ic_expr_free(e);
}

/* Jet evaluation of a formula against the same function built from jet
 * operations, and the double evaluation against libm. */
static void test_eval_jet(void)
{
    const char *f = "exp(x)*cos(y) - x*y^3 + atan2(z, x + 2) + tanh(x*z)/(1 + y^2) + pow(x+3, 0.5)";
    ic_expr *e = NULL;
    ic_jet_space *sp = NULL;
    if (!REQUIRE(ic_expr_compile(&e, &f, 1, XYZ, 3, NULL, 0, NULL, NULL) == IC_OK, "compiles") ||
        !REQUIRE(ic_jet_space_new(&sp, 3, 6, NULL) == IC_OK, "jet space of 3 variables, order 6")) {
        ic_expr_free(e);
        return;
    }
    const int n = ic_jet_space_len(sp);
    const double p[3] = {0.31, -0.72, 0.45};
    double x[3][84], out[84], work[4096], a[84], b[84], c[84], r[84], scratch[40 * 84];
    const double *xs[3] = {x[0], x[1], x[2]};
    for (int i = 0; i < 3; i++)
        ic_jet_set_var(x[i], p[i], i, sp);
    CHECK(ic_expr_jet_work_len(e, sp) <= sizeof work / sizeof work[0], "work size");
    CHECK(ic_expr_eval_jet(e, out, xs, sp, work, NULL) == IC_OK, "jet eval");
    /* the same with jet calls */
    ic_jet_exp(a, x[0], sp);
    ic_jet_cos(b, x[1], sp, scratch);
    ic_jet_mul(r, a, b, sp);
    ic_jet_mul(a, x[1], x[1], sp);
    ic_jet_mul(b, a, x[1], sp);
    ic_jet_mul(a, x[0], b, sp);
    ic_jet_sub(r, r, a, sp);
    ic_jet_add_const(a, x[0], 2.0, sp);
    CHECK(ic_jet_atan2(b, x[2], a, sp, scratch, NULL) == IC_OK, "atan2");
    ic_jet_add(r, r, b, sp);
    ic_jet_mul(a, x[0], x[2], sp);
    ic_jet_tanh(b, a, sp, scratch);
    ic_jet_mul(a, x[1], x[1], sp);
    a[0] += 1.0;
    CHECK(ic_jet_div(c, b, a, sp, NULL) == IC_OK, "div");
    ic_jet_add(r, r, c, sp);
    ic_jet_add_const(a, x[0], 3.0, sp);
    CHECK(ic_jet_pow_real(b, a, 0.5, sp, scratch, NULL) == IC_OK, "pow");
    ic_jet_add(r, r, b, sp);
    double worst = 0.0;
    for (int i = 0; i < n; i++)
        worst = fmax(worst, fabs(out[i] - r[i]));
    /* same operations in the same order: equal up to a few roundings */
    CHECK(worst <= TIER_ROUNDING, "formula jet = jet calls: %g", worst);
    double v, w[64];
    CHECK(ic_expr_eval(e, &v, p, w, NULL) == IC_OK, "double eval");
    const double want = exp(p[0]) * cos(p[1]) - p[0] * pow(p[1], 3) + atan2(p[2], p[0] + 2) +
                        tanh(p[0] * p[2]) / (1 + p[1] * p[1]) + sqrt(p[0] + 3);
    CHECK_CLOSE(v, want, TIER_ROUNDING, "double eval against libm");
    CHECK_CLOSE(out[0], want, TIER_ROUNDING, "jet constant term");
    ic_jet_space_free(sp);
    ic_expr_free(e);
}

/* Formulas for the interval tests: every function, domains that end
 * inside the boxes, poles, real and variable powers. */
static const char *const INTERVAL_FORMULAS[] = {
    "sin(3*x) * cos(y) + z^2",
    "tan(x) - atan(y*z)",
    "x / (y - 0.1)",
    "sqrt(x + 1) * log(y + 2) - exp(z)",
    "asin(x/2) + acos(y/3) * sinh(z)",
    "atan2(y, x) + cosh(z) - tanh(x*y)",
    "abs(x - y)^3 - pow(z + 3, 1.7)",
    "(x + y)^-2 + x^2*y^2 - z^5",
    "pow(x + 2, y)",
};
enum { NUM_INTERVAL_FORMULAS = 9 };

/* Interval evaluation encloses every sampled value of the formula on the
 * box; special cases for periodic functions and division by 0. */
static void test_intervals(harness_rng *rng)
{
    const char *const *formulas = INTERVAL_FORMULAS;
    const int nf = NUM_INTERVAL_FORMULAS;
    ic_expr *e = NULL;
    if (!REQUIRE(ic_expr_compile(&e, formulas, nf, XYZ, 3, NULL, 0, NULL, NULL) == IC_OK,
                 "compile the interval formulas"))
        return;
    ic_interval box[3], out[NUM_INTERVAL_FORMULAS], iwork[256];
    double pt[3], val[NUM_INTERVAL_FORMULAS], work[256];
    int checked = 0;
    for (int trial = 0; trial < 300 * harness_multiplier(); trial++) {
        for (int i = 0; i < 3; i++) {
            const double c = harness_uniform(rng, -1.5, 1.5);
            const double h = harness_uniform(rng, 0.0, 0.8);
            box[i] = (ic_interval){c - h, c + h};
        }
        ic_expr_eval_interval(e, out, box, iwork);
        for (int s = 0; s < 20; s++) {
            for (int i = 0; i < 3; i++)
                pt[i] = harness_uniform(rng, box[i].lo, box[i].hi);
            if (ic_expr_eval(e, val, pt, work, NULL) != IC_OK)
                continue; /* some formula is undefined there */
            for (int k = 0; k < nf; k++) {
                checked++;
                CHECK(val[k] >= out[k].lo && val[k] <= out[k].hi,
                      "formula %d: %.17g outside [%.17g, %.17g]", k, val[k], out[k].lo, out[k].hi);
            }
        }
    }
    CHECK(checked > 10000, "enough samples checked: %d", checked);
    ic_expr_free(e);
    /* periodic functions: extrema inside the interval */
    ic_interval s = ic_interval_sin((ic_interval){1.0, 2.0});
    CHECK(s.hi == 1.0 && s.lo <= sin(1.0) && s.lo > 0.84, "sin[1,2] = [%g, %g]", s.lo, s.hi);
    s = ic_interval_cos((ic_interval){3.0, 3.5});
    CHECK(s.lo == -1.0, "cos[3, 3.5] reaches -1 at pi");
    s = ic_interval_sin((ic_interval){-100.0, 100.0});
    CHECK(s.lo == -1.0 && s.hi == 1.0, "sin of a wide interval");
    s = ic_interval_tan((ic_interval){1.0, 2.0});
    CHECK(isinf(s.lo) && isinf(s.hi), "tan over a pole is the whole line");
    s = ic_interval_div((ic_interval){1.0, 2.0}, (ic_interval){-1.0, 1.0});
    CHECK(isinf(s.lo) && isinf(s.hi), "division by an interval holding 0");
    s = ic_interval_div((ic_interval){1.0, 2.0}, (ic_interval){0.0, 1.0});
    CHECK(s.lo <= 1.0 && s.lo > 0.99 && isinf(s.hi), "division by [0, 1] = [1, inf]");
    CHECK(ic_interval_is_empty(ic_interval_div((ic_interval){1, 2}, (ic_interval){0, 0})),
          "division by [0, 0] is empty");
    CHECK(ic_interval_is_empty(ic_interval_log((ic_interval){-2, -1})), "log of negatives");
    s = ic_interval_sqrt((ic_interval){-1.0, 4.0});
    CHECK(s.lo == 0.0 && s.hi >= 2.0 && s.hi < 2.0 + 1e-15, "sqrt[-1,4] = [0, 2]");
    s = ic_interval_atan2((ic_interval){-1, 1}, (ic_interval){-2, -1});
    CHECK(s.lo <= -3.14159 && s.hi >= 3.14159, "atan2 across the branch cut");
    s = ic_interval_pow_int((ic_interval){-2.0, 1.0}, 2);
    CHECK(s.lo == 0.0 && s.hi >= 4.0, "[-2,1]^2 = [0, 4]");
    s = ic_interval_add((ic_interval){0.1, 0.1}, (ic_interval){0.2, 0.2});
    CHECK(s.lo < 0.30000000000000004 && s.hi > 0.3, "outward rounding of 0.1 + 0.2");
}

/* Interval gradients (forward mode on intervals) enclose the jets' exact
 * first derivatives at every sampled point of random boxes. */
static void test_interval_gradients(harness_rng *rng)
{
    const char *const *formulas = INTERVAL_FORMULAS;
    const int nf = NUM_INTERVAL_FORMULAS;
    ic_expr *e = NULL;
    ic_jet_space *sp = NULL;
    if (!REQUIRE(ic_expr_compile(&e, formulas, nf, XYZ, 3, NULL, 0, NULL, NULL) == IC_OK,
                 "compile the interval formulas") ||
        !REQUIRE(ic_jet_space_new(&sp, 3, 1, NULL) == IC_OK, "jet space of 3 variables, order 1")) {
        ic_expr_free(e);
        return;
    }
    ic_interval_grad box[3], out[NUM_INTERVAL_FORMULAS], gwork[256];
    double X[3][4], J[9 * 4], work[4096];
    int checked = 0;
    for (int trial = 0; trial < 300 * harness_multiplier(); trial++) {
        for (int i = 0; i < 3; i++) {
            const double c = harness_uniform(rng, -1.5, 1.5);
            const double h = harness_uniform(rng, 0.0, 0.8);
            box[i].v = (ic_interval){c - h, c + h};
            for (int k = 0; k < 3; k++)
                box[i].d[k] = (ic_interval){i == k, i == k};
        }
        ic_expr_eval_interval_grad(e, out, box, 3, gwork);
        for (int s = 0; s < 20; s++) {
            for (int i = 0; i < 3; i++)
                ic_jet_set_var(X[i], harness_uniform(rng, box[i].v.lo, box[i].v.hi), i, sp);
            const double *in[3] = {X[0], X[1], X[2]};
            if (ic_expr_eval_jet(e, J, in, sp, work, NULL) != IC_OK)
                continue; /* undefined or not differentiable there */
            for (int k = 0; k < nf; k++)
                for (int j = 0; j < 3; j++) {
                    const double d = J[4 * k + 1 + j];
                    checked++;
                    CHECK(d >= out[k].d[j].lo && d <= out[k].d[j].hi,
                          "formula %d, d/d%s: %.17g outside [%.17g, %.17g]", k, XYZ[j], d,
                          out[k].d[j].lo, out[k].d[j].hi);
                }
        }
    }
    CHECK(checked > 30000, "enough derivatives checked: %d", checked);
    /* tight where the rules are exact: d(x^2 y)/dx over [1, 2] x {1} is [2, 4] to a
     * few ulps (1e-14: outward rounding of three operations) */
    const char *sq[] = {"x^2 * y"};
    ic_expr *q = NULL;
    if (!REQUIRE(ic_expr_compile(&q, sq, 1, XYZ, 3, NULL, 0, NULL, NULL) == IC_OK,
                 "compile x^2 y")) {
        ic_expr_free(e);
        ic_jet_space_free(sp);
        return;
    }
    box[0].v = (ic_interval){1, 2}, box[1].v = (ic_interval){1, 1}, box[2].v = (ic_interval){0, 0};
    ic_expr_eval_interval_grad(q, out, box, 3, gwork);
    CHECK(out[0].d[0].lo <= 2 && out[0].d[0].lo > 2 - 1e-14 && out[0].d[0].hi >= 4 &&
              out[0].d[0].hi < 4 + 1e-14 && fabs(out[0].d[2].lo) <= 1e-300 &&
              fabs(out[0].d[2].hi) <= 1e-300, /* outward rounding of 0: one subnormal */
          "d(x^2 y)/dx over [1,2] x {1}: [%.17g, %.17g]", out[0].d[0].lo, out[0].d[0].hi);
    ic_expr_free(q);
    ic_expr_free(e);
    ic_jet_space_free(sp);
}

int main(void)
{
    harness_rng rng = {0x2545F4914F6CDD1Dull};
    test_parse_errors();
    test_numbers_and_constants();
    test_tape();
    test_eval_domain();
    test_eval_jet();
    test_intervals(&rng);
    test_interval_gradients(&rng);
    return harness_finish("test_expr");
}
