/*
 * Second-order enclosures (expr/interval_hess.c, surface_interval_hess.c):
 * at point boxes they hold sympy's exact values, gradients and Hessians
 * (tests/truth/interval_hess_truth.txt, gen_interval_hess_truth.py) to a
 * few units of rounding; over random boxes they hold the second derivatives
 * of the jets (Taylor recurrences, their own truth in test_jet_truth) at
 * every sampled point; operations with no second derivative written give a
 * result that proves nothing; the quadric primitives' constant Hessians
 * match their closed forms.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "harness.h"
#include "intercurve/expr.h"
#include "intercurve/jet.h"
#include "intercurve/surface.h"

static const char *const XYZ[3] = {"x", "y", "z"};
/* the formulas of gen_interval_hess_truth.py, in its order */
static const char *const FORMULAS[] = {
    "sin(3*x) * cos(y) + z^2",
    "tan(x) - atan(y*z)",
    "x / (y - 3)",
    "sqrt(x + 2) * log(y + 2) - exp(z)",
    "asin(x/2) + acos(y/3) * sinh(z)",
    "cosh(z) - tanh(x*y) + abs(x + 4)^3",
    "(x + 3)^2.5 - (y + 4)^-1.5 + x^2*y^2 - z^5",
    "(x + 2)^(y + 1)",
};
enum { NF = 8, NCASES = 32 };

/* A point box: each enclosure holds the exact value to TIGHT relative to
 * its size (a few dozen operations, each rounded outward by an ulp, and
 * the decimal inputs' own rounding of 1e-16 times the next derivative,
 * below 1e2 here), and is no wider. */
#define TIGHT 1e-13

static void box_of(const double *lo, const double *hi, ic_interval_hess x[3])
{
    memset(x, 0, 3 * sizeof *x);
    for (int i = 0; i < 3; i++) {
        x[i].v = (ic_interval){lo[i], hi[i]};
        x[i].d[i] = (ic_interval){1.0, 1.0};
    }
}

static int tight(ic_interval got, double want)
{
    const double slack = TIGHT * (1.0 + fabs(want));
    return got.lo <= want + slack && got.hi >= want - slack && got.hi - got.lo <= slack;
}

static void check_truth(const ic_expr *e, const char *path)
{
    FILE *f = fopen(path, "r");
    if (!REQUIRE(f, "cannot open %s", path))
        return;
    char line[1024];
    int n = 0, k = -1;
    double p[3] = {0, 0, 0}, v = 0, d[3] = {0}, h[6] = {0};
    ic_interval_hess x[3], out[NF], work[256];
    while (fgets(line, sizeof line, f)) {
        if (sscanf(line, "case %d %lf %lf %lf", &k, &p[0], &p[1], &p[2]) == 4)
            continue;
        if (sscanf(line, "v %lf", &v) == 1 ||
            sscanf(line, "d %lf %lf %lf", &d[0], &d[1], &d[2]) == 3)
            continue;
        if (sscanf(line, "h %lf %lf %lf %lf %lf %lf", &h[0], &h[1], &h[2], &h[3], &h[4], &h[5]) !=
                6 ||
            k < 0 || k >= NF)
            continue;
        box_of(p, p, x);
        CHECK(ic_expr_eval_interval_hess(e, out, x, 3, work) == 1, "formula %d: whole", k);
        CHECK(tight(out[k].v, v), "formula %d at (%g, %g, %g): value", k, p[0], p[1], p[2]);
        for (int j = 0; j < 3; j++)
            CHECK(tight(out[k].d[j], d[j]), "formula %d: d/d%s [%.17g, %.17g] want %.17g", k,
                  XYZ[j], out[k].d[j].lo, out[k].d[j].hi, d[j]);
        for (int j = 0; j < 6; j++)
            CHECK(tight(out[k].h[j], h[j]), "formula %d: h[%d] [%.17g, %.17g] want %.17g", k, j,
                  out[k].h[j].lo, out[k].h[j].hi, h[j]);
        n++;
    }
    fclose(f);
    CHECK(n == NCASES, "%d truth cases read (want %d)", n, NCASES);
}

/* Over random boxes in [-1.5, 1.5]^3 every Hessian entry holds the jets'
 * second derivatives (2 c for a square's coefficient c, c for a mixed one)
 * at 20 points of the box. */
static void check_boxes(const ic_expr *e, harness_rng *rng)
{
    ic_jet_space *sp = NULL;
    if (!REQUIRE(ic_jet_space_new(&sp, 3, 2, NULL) == IC_OK, "jet space of order 2"))
        return;
    ic_interval_hess x[3], out[NF], work[256];
    double X[3][10], J[NF * 10], jwork[8192];
    int checked = 0;
    for (int trial = 0; trial < 200 * harness_multiplier(); trial++) {
        double lo[3], hi[3];
        for (int i = 0; i < 3; i++) {
            const double c = harness_uniform(rng, -1.5, 1.5), w = harness_uniform(rng, 0.0, 0.4);
            lo[i] = c - w, hi[i] = c + w;
        }
        box_of(lo, hi, x);
        if (!ic_expr_eval_interval_hess(e, out, x, 3, work))
            continue; /* a box where some formula is undefined: proves nothing */
        for (int s = 0; s < 20; s++) {
            for (int i = 0; i < 3; i++)
                ic_jet_set_var(X[i], harness_uniform(rng, lo[i], hi[i]), i, sp);
            const double *in[3] = {X[0], X[1], X[2]};
            if (ic_expr_eval_jet(e, J, in, sp, jwork, NULL) != IC_OK)
                continue;
            for (int k = 0; k < NF; k++)
                for (int j = 0; j < 6; j++) {
                    const int square = j == 0 || j == 3 || j == 5;
                    const double h = (square ? 2.0 : 1.0) * J[10 * k + 4 + j];
                    checked++;
                    CHECK(h >= out[k].h[j].lo && h <= out[k].h[j].hi,
                          "formula %d, h[%d] = %.17g outside [%.17g, %.17g]", k, j, h,
                          out[k].h[j].lo, out[k].h[j].hi);
                }
        }
    }
    CHECK(checked > 50000, "enough second derivatives checked: %d", checked);
    ic_jet_space_free(sp);
}

/* No second derivative written (atan2) or none on the box (abs across 0):
 * the evaluation is not whole; abs away from 0 is. */
static void check_not_whole(void)
{
    const char *const f[] = {"atan2(y, x)", "abs(x - y)^3", "abs(x + 4)"};
    const int want[] = {0, 0, 1};
    for (int i = 0; i < 3; i++) {
        ic_expr *e = NULL;
        if (!REQUIRE(ic_expr_compile(&e, &f[i], 1, XYZ, 3, NULL, 0, NULL, NULL) == IC_OK,
                     "compile %s", f[i]))
            continue;
        const double lo[3] = {-1, -1, -1}, hi[3] = {1, 1, 1};
        ic_interval_hess x[3], out, work[16];
        box_of(lo, hi, x);
        CHECK(ic_expr_eval_interval_hess(e, &out, x, 3, work) == want[i], "%s: whole %d", f[i],
              want[i]);
        ic_expr_free(e);
    }
}

/* The closed forms: a sphere 2 I; a cylinder of unit axis a 2 (I - a a^T);
 * a cone of half angle t about a 2 (I - a a^T) - 2 tan^2 t a a^T. To 1e-15:
 * a rotation of unit vectors rounded in interval arithmetic. */
static void check_quadrics(void)
{
    const double r3 = 1.0 / sqrt(3.0), t = 0.4;
    const ic_primitive_kind kinds[3] = {IC_PRIM_SPHERE, IC_PRIM_CYLINDER, IC_PRIM_CONE};
    for (int q = 0; q < 3; q++) {
        ic_primitive p;
        memset(&p, 0, sizeof p);
        p.kind = kinds[q];
        p.center[0] = 0.3, p.center[1] = -1.2, p.center[2] = 2.0;
        p.radius = 1.1, p.half_angle = t;
        p.axis[0] = p.axis[1] = p.axis[2] = 1.0;
        ic_surface *s = NULL;
        ic_error err;
        if (!REQUIRE(ic_surface_new_primitive(&s, &p, IC_IMPLICIT, &err) == IC_OK, "%s",
                     err.message))
            continue;
        const ic_interval box[3] = {{0, 1}, {-2, -1}, {1, 3}};
        ic_interval_hess H;
        CHECK(ic_surface_eval_interval_hess(s, &H, box, &err) == IC_OK, "quadric %d: %s", q,
              err.message);
        for (int j = 0; j < 3; j++)
            for (int k = j; k < 3; k++) {
                const double aa = r3 * r3, id = j == k ? 1.0 : 0.0;
                const double want = q == 0   ? 2.0 * id
                                    : q == 1 ? 2.0 * (id - aa)
                                             : 2.0 * (id - aa) - 2.0 * tan(t) * tan(t) * aa;
                const ic_interval h = H.h[ic_interval_hess_index(j, k)];
                CHECK(h.lo <= want + 1e-15 && h.hi >= want - 1e-15 && h.hi - h.lo < 1e-14,
                      "quadric %d: H[%d][%d] = [%.17g, %.17g], want %.17g", q, j, k, h.lo, h.hi,
                      want);
            }
        ic_surface_free(s);
    }
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: test_interval_hess TRUTH_FILE\n");
        return 2;
    }
    harness_rng rng = {0x9E3779B97F4A7C15ull};
    ic_expr *e = NULL;
    if (REQUIRE(ic_expr_compile(&e, FORMULAS, NF, XYZ, 3, NULL, 0, NULL, NULL) == IC_OK,
                "compile the formulas")) {
        check_truth(e, argv[1]);
        check_boxes(e, &rng);
    }
    ic_expr_free(e);
    check_not_whole();
    check_quadrics();
    return harness_finish("test_interval_hess");
}
