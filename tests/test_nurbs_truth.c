/* NURBS derivatives against exact truth: every partial derivative to order
 * 8 of four patches (polynomial and rational, clamped and unclamped, on and
 * off knot lines, each side of a knot), from tests/truth/nurbs_derivs.txt
 * (gen_nurbs_derivs.py: sympy, exact rationals, checked by a second exact
 * route; format in the script's header). */
#include "harness.h"

#include <string.h>

#include "intercurve/surface.h"

/* relative to the largest truth derivative of the same order: the
 * surface-derivative tier (harness.h); the homogeneous sums round O(p q)
 * products and jet division adds a few ulps per order up to 8 (measured
 * worst 9 ulps, printed at the end as a fraction of this) */
#define DERIV_TRUTH_TOL TIER_DERIVATIVE

enum { MAX_NET = 64, MAX_KNOTS = 32, ORDER = 8 };

typedef struct {
    char name[32];
    int p, q, nu, nv, rational;
    double ku[MAX_KNOTS], kv[MAX_KNOTS];
    double pts[MAX_NET * 3], w[MAX_NET];
    ic_surface *s;
} patch;

static int read_knots(const char *line, double *k, int want)
{
    int m = 0, used = 0;
    if (sscanf(line, "%d%n", &m, &used) != 1 || m != want || m > MAX_KNOTS)
        return 0;
    line += used;
    for (int i = 0; i < m; i++) {
        if (sscanf(line, "%lf%n", &k[i], &used) != 1)
            return 0;
        line += used;
    }
    return 1;
}

static int make_surface(patch *pt)
{
    ic_nurbs d;
    memset(&d, 0, sizeof d);
    d.degree[0] = pt->p, d.degree[1] = pt->q;
    d.count[0] = pt->nu, d.count[1] = pt->nv;
    d.knots[0] = pt->ku, d.knots[1] = pt->kv;
    d.points = pt->pts;
    d.weights = pt->rational ? pt->w : NULL;
    ic_error err;
    return REQUIRE(ic_surface_new_nurbs(&pt->s, &d, &err) == IC_OK, "%s: %s", pt->name,
                   err.message);
}

typedef struct {
    double taylor[3 * 45];
    double worst; /* largest error / tolerance seen */
    int points;
} checker;

/* One derivative line "a b x y z" against the Taylor coefficients. */
static void check_derivative(checker *c, const ic_jet_space *sp, const double *scale,
                             const char *line, const patch *pt, const double at[2])
{
    int a, b;
    double want[3];
    if (!REQUIRE(sscanf(line, "%d %d %lf %lf %lf", &a, &b, &want[0], &want[1], &want[2]) == 5,
                 "bad line: %s", line))
        return;
    const int idx = ic_jet_index(sp, (int[]){a, b});
    const double fact = ic_jet_factorial(sp, idx);
    for (int k = 0; k < 3; k++) {
        const double got = c->taylor[k * 45 + idx] * fact;
        const double tol = DERIV_TRUTH_TOL * fmax(1, scale[a + b]);
        c->worst = fmax(c->worst, fabs(got - want[k]) / tol);
        CHECK(fabs(got - want[k]) <= tol, "%s at (%g, %g): d%d%d[%d] = %.17g, want %.17g",
              pt->name, at[0], at[1], a, b, k, got, want[k]);
    }
}

/* The surface composed with the line (u0 + a s, v0 + b s), heading into the
 * truth's pieces (a, b of the truth's sides), to order 8: the coefficient
 * of s^k is sum over i + j = k of d^(i+j)R/du^i dv^j a^i b^j / (i! j!),
 * from the truth's derivatives; relative to the sum of those terms' sizes. */
static void check_composition(checker *c, const patch *pt, const double at[2], const int side[2],
                              char lines[45][256])
{
    ic_jet_space *line = NULL;
    ic_error err;
    if (!REQUIRE(ic_jet_space_new(&line, 1, ORDER, &err) == IC_OK, "space"))
        return;
    const double a = 0.7 * side[0], b = 0.4 * side[1];
    double ju[ORDER + 1] = {at[0], a}, jv[ORDER + 1] = {at[1], b}, out[3 * (ORDER + 1)];
    const double *in[2] = {ju, jv};
    double want[3][ORDER + 1] = {{0}}, size[ORDER + 1] = {0};
    for (int i = 0; i < 45; i++) {
        int p, q;
        double x[3];
        sscanf(lines[i] + 2, "%d %d %lf %lf %lf", &p, &q, &x[0], &x[1], &x[2]);
        const double w = pow(a, p) * pow(b, q) / (tgamma(p + 1) * tgamma(q + 1));
        for (int k = 0; k < 3; k++) {
            want[k][p + q] += x[k] * w;
            size[p + q] = fmax(size[p + q], fabs(x[k] * w));
        }
    }
    if (REQUIRE(ic_surface_compose(pt->s, out, in, line, &err) == IC_OK, "%s: compose: %s",
                pt->name, err.message))
        for (int k = 0; k < 3; k++)
            for (int d = 0; d <= ORDER; d++) {
                /* the terms of one order, each within the tier, summed */
                const double tol = DERIV_TRUTH_TOL * (d + 1) * (d + 1) * fmax(1, size[d]);
                c->worst = fmax(c->worst, fabs(out[k * (ORDER + 1) + d] - want[k][d]) / tol);
                CHECK(fabs(out[k * (ORDER + 1) + d] - want[k][d]) <= tol,
                      "%s at (%g, %g): composed coefficient %d of %d: %.17g, want %.17g",
                      pt->name, at[0], at[1], d, k, out[k * (ORDER + 1) + d], want[k][d]);
            }
    ic_jet_space_free(line);
}

/* The 45 derivative lines after an "at" line; their largest magnitude per
 * order is the scale of that order (read first, then checked). */
static void check_point(checker *c, FILE *f, const patch *pt, const ic_jet_space *sp,
                        const char *at_line)
{
    double at[2];
    int side[2];
    if (!REQUIRE(sscanf(at_line, "%lf %lf %d %d", &at[0], &at[1], &side[0], &side[1]) == 4,
                 "bad at line"))
        return;
    char lines[45][256];
    double scale[ORDER + 1] = {0};
    for (int i = 0; i < 45; i++) {
        int a, b;
        double x[3];
        if (!REQUIRE(fgets(lines[i], sizeof lines[i], f) && lines[i][0] == 'd' &&
                         sscanf(lines[i] + 2, "%d %d %lf %lf %lf", &a, &b, &x[0], &x[1],
                                &x[2]) == 5,
                     "%s: truncated derivative list", pt->name))
            return;
        for (int k = 0; k < 3; k++)
            scale[a + b] = fmax(scale[a + b], fabs(x[k]));
    }
    ic_error err;
    ic_surface_set_knot_side(pt->s, side);
    const ic_status st = ic_surface_taylor(pt->s, c->taylor, at, sp, &err);
    ic_surface_set_knot_side(pt->s, NULL);
    if (!REQUIRE(st == IC_OK, "%s: taylor: %s", pt->name, err.message))
        return;
    c->points++;
    for (int i = 0; i < 45; i++)
        check_derivative(c, sp, scale, lines[i] + 2, pt, at);
    check_composition(c, pt, at, side, lines);
}

/* The header lines of a patch (degree .. cp); 1 at its first "at" line. */
static int read_patch_line(patch *pt, const char *line)
{
    if (sscanf(line, "degree %d %d", &pt->p, &pt->q) == 2)
        return 0;
    if (sscanf(line, "count %d %d", &pt->nu, &pt->nv) == 2) {
        CHECK(pt->nu * pt->nv <= MAX_NET, "%s: net too large for the test", pt->name);
        return 0;
    }
    if (sscanf(line, "rational %d", &pt->rational) == 1)
        return 0;
    if (strncmp(line, "knots_u ", 8) == 0)
        CHECK(read_knots(line + 8, pt->ku, pt->nu + pt->p + 1), "%s: knots_u", pt->name);
    else if (strncmp(line, "knots_v ", 8) == 0)
        CHECK(read_knots(line + 8, pt->kv, pt->nv + pt->q + 1), "%s: knots_v", pt->name);
    else if (strncmp(line, "cp ", 3) == 0) {
        int i, j;
        double x[4];
        if (REQUIRE(sscanf(line + 3, "%d %d %lf %lf %lf %lf", &i, &j, &x[0], &x[1], &x[2],
                           &x[3]) == 6 &&
                        i >= 0 && i < pt->nu && j >= 0 && j < pt->nv,
                    "%s: bad cp line", pt->name)) {
            memcpy(&pt->pts[3 * (i * pt->nv + j)], x, sizeof(double) * 3);
            pt->w[i * pt->nv + j] = x[3];
        }
    }
    return 0;
}

int main(int argc, char **argv)
{
    FILE *f = argc > 1 ? fopen(argv[1], "r") : NULL;
    if (!REQUIRE(f, "usage: test_nurbs_truth tests/truth/nurbs_derivs.txt"))
        return harness_finish("nurbs_truth");
    ic_jet_space *sp = NULL;
    ic_error err;
    if (!REQUIRE(ic_jet_space_new(&sp, 2, ORDER, &err) == IC_OK, "space")) {
        fclose(f);
        return harness_finish("nurbs_truth");
    }
    static patch pt;
    checker c = {.worst = 0};
    int patches = 0;
    char line[4096];
    while (fgets(line, sizeof line, f)) {
        if (line[0] == '#')
            continue;
        if (strncmp(line, "patch ", 6) == 0) {
            memset(&pt, 0, sizeof pt);
            sscanf(line + 6, "%31s", pt.name);
        } else if (strncmp(line, "at ", 3) == 0) {
            if (!pt.s && !make_surface(&pt))
                break;
            check_point(&c, f, &pt, sp, line + 3);
        } else if (strncmp(line, "end", 3) == 0) {
            ic_surface_free(pt.s);
            pt.s = NULL;
            patches++;
        } else {
            read_patch_line(&pt, line);
        }
    }
    ic_surface_free(pt.s);
    fclose(f);
    ic_jet_space_free(sp);
    CHECK(patches == 4 && c.points == 31, "read %d patches and %d points (want 4 and 31)",
          patches, c.points);
    printf("largest error: %.3g of the tolerance\n", c.worst);
    return harness_finish("nurbs_truth");
}
