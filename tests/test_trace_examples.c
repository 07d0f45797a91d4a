/* Whole traces of bundled examples (issue 5's test list) against lengths
 * integrated independently (tests/curve_lengths.h): two perpendicular
 * cylinders of radii 1 and 0.7 (two closed loops) and of equal radii (two
 * ellipses through two branch points), a loop smaller than 1% of the box, and
 * a tacnode (two parabolas tangent at a degenerate tangential point) and a
 * cusp. */
#include <stdio.h>
#include <string.h>

#include "curve_lengths.h"
#include "harness.h"
#include "intercurve.h"
#include "tacnode_parabolas.h"
#include "traced_example.h"

#define PI_L 3.14159265358979323846264338327950288L

/* The loop x = 0.7 cos t, z = 0.7 sin t, y = sqrt(1 - x^2) */
static long double loop_speed(long double t)
{
    const long double c = cosl(t), s = sinl(t), dy = 0.49L * c * s / sqrtl(1 - 0.49L * c * c);
    return sqrtl(0.49L + dy * dy);
}

/* The ellipse in the plane y = z: x = cos t, y = z = sin t (semi-axes 1, sqrt 2) */
static long double ellipse_speed(long double t)
{
    const long double s = sinl(t), c = cosl(t);
    return sqrtl(s * s + 2 * c * c);
}

/* n closed curves, each of length L to the 1e-9 relative, of the shape. */
static void check_curves(const traced *t, const char *name, int n, double L, ic_shape shape)
{
    CHECK(ic_trace_result_num_curves(t->res) == n, "%s: %d curves, not %d", name,
          ic_trace_result_num_curves(t->res), n);
    double worst = 0;
    for (int i = 0; i < ic_trace_result_num_curves(t->res); i++) {
        const ic_trace_curve *c = ic_trace_result_curve(t->res, i);
        worst = fmax(worst, fabs(c->length - L) / L);
        CHECK(c->closed && c->shape == shape && fabs(c->length - L) <= TIER_LENGTH * L,
              "%s curve %d: closed %d, %s, length %.17g of %.17g", name, i, c->closed,
              ic_shape_name(c->shape), c->length, L);
    }
    printf("%-24s %d closed %s curves, length error %.2g\n", name, n, ic_shape_name(shape), worst);
}

/* The parabola y = a X^2 (X in [-X1, X1]) in the tilted plane of
 * examples/tacnode.json: the plane is isometric to (X, y), so its length is
 * 2 * integral_0^X1 sqrt(1 + k^2 X^2) dX with k = 2|a| (closed form). */
static double parabola_length(double a, double X1)
{
    const long double k = 2 * fabsl((long double)a), X = X1;
    return (double)(X * sqrtl(1 + k * k * X * X) + asinhl(k * X) / k);
}

/* Both parabolas through the tacnode at the origin: one curve each, with the
 * tacnode an interior point (joined through it by its curvature vector). */
static void check_tacnode(const traced *t)
{
    const ic_trace_result *res = t->res;
    int found = 0;
    for (int i = 0; i < ic_trace_result_num_specials(res); i++) {
        const ic_trace_special *sp = ic_trace_result_special(res, i);
        /* located to 1e-12 as a simple root of the third derivative along
         * the kernel (Gauss-Newton on N_A x N_B = 0 alone stops about 2e-3
         * away, where the march meets the angle threshold) */
        found += sp->type == IC_POINT_TACNODE &&
                 hypot(hypot(sp->xyz[0], sp->xyz[1]), sp->xyz[2]) <= TIER_LOCATED;
    }
    CHECK(ic_trace_result_num_specials(res) == 1 && found == 1, "tacnode: one, at the origin");
    CHECK(ic_trace_result_num_curves(res) == 2, "tacnode: %d curves, not 2",
          ic_trace_result_num_curves(res));
    /* y = 3X^2/2 leaves through y = 1.2; y = -X^2/2 through x = +-1, X = 1/cos 0.3 */
    const double L[2] = {parabola_length(1.5, sqrt(0.8)), parabola_length(0.5, 1 / cos(0.3))};
    const double kappa0[2] = {3.0, 1.0}; /* 2|a| at the vertex */
    double worst = 0;
    for (int i = 0; i < ic_trace_result_num_curves(res) && i < 2; i++) {
        const ic_trace_curve *c = ic_trace_result_curve(res, i);
        const int k = fabs(c->length - L[0]) < fabs(c->length - L[1]) ? 0 : 1;
        worst = fmax(worst, fabs(c->length - L[k]) / L[k]);
        CHECK(!c->closed && fabs(c->length - L[k]) <= TIER_LENGTH * L[k],
              "tacnode curve %d: length %.17g of %.17g", i, c->length, L[k]);
        int through = 0;
        for (int j = 1; j + 1 < c->npoints; j++) {
            const double *x = c->points[j].xyz;
            if (hypot(hypot(x[0], x[1]), x[2]) <= 1e-12) {
                through = 1;
                /* the branch's apparatus at the tacnode (height-difference
                 * series, exact to rounding for these polynomials): 1e-10 */
                CHECK(fabs(c->points[j].kappa - kappa0[k]) <= 1e-10,
                      "tacnode curve %d: kappa %.17g at the vertex, not %g", i, c->points[j].kappa,
                      kappa0[k]);
            }
        }
        CHECK(through, "tacnode curve %d passes through the tacnode", i);
        const double ek = tacnode_kappa_error(c, k == 0 ? 1.5 : -0.5);
        CHECK(ek <= TACNODE_KAPPA_REL, "tacnode curve %d: kappa %g off at a traced point", i, ek);
    }
    printf("%-24s 2 parabolas through the tacnode, length error %.2g\n", "tacnode", worst);
}

/* Bendrici and Boumedien-Zidani (2022), Example 2: z = u^3 - v^2 against
 * z = 0, the cusp u^3 = v^2 at the origin; each arc v = +-u^(3/2), u in [0, 1], has length
 * integral_0^1 sqrt(1 + 9u/4) du = (8/27) ((13/4)^(3/2) - 1). */
static void check_cusp(const traced *t)
{
    const ic_trace_result *res = t->res;
    const ic_trace_special *sp = ic_trace_result_special(res, 0);
    /* located as a simple root of h'' along the kernel (Gauss-Newton alone
     * stopped 8e-9 away, where the point classified as a branch point) */
    CHECK(ic_trace_result_num_specials(res) == 1 && sp->type == IC_POINT_CUSP && !sp->approximate &&
              hypot(hypot(sp->xyz[0], sp->xyz[1]), sp->xyz[2]) <= TIER_LOCATED,
          "cusp: one, at the origin, classified cusp");
    const double L = 8.0 / 27 * (pow(3.25, 1.5) - 1);
    double worst = 0;
    CHECK(ic_trace_result_num_curves(res) == 2, "cusp: two arcs");
    for (int i = 0; i < ic_trace_result_num_curves(res); i++) {
        const ic_trace_curve *c = ic_trace_result_curve(res, i);
        worst = fmax(worst, fabs(c->length - L) / L);
        CHECK(fabs(c->length - L) <= TIER_LENGTH * L, "cusp arc %d: length %.17g of %.17g", i, c->length,
              L);
    }
    printf("%-24s 2 arcs to the cusp, length error %.2g\n", "cusp", worst);
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : ".";
    traced t;
    if (trace_example(&t, dir, "cylinders.json") == 0) {
        check_curves(&t, "cylinders 1 and 0.7", 2, simpson_length(loop_speed, 0, 2 * PI_L),
                     IC_SHAPE_GENERAL);
        CHECK(ic_trace_result_num_specials(t.res) == 0, "cylinders 1 and 0.7: no singular point");
    }
    release(&t);
    if (trace_example(&t, dir, "cylinders-equal.json") == 0) {
        check_curves(&t, "equal cylinders", 2, simpson_length(ellipse_speed, 0, 2 * PI_L),
                     IC_SHAPE_PLANAR);
        int at_x = 0;
        for (int i = 0; i < ic_trace_result_num_specials(t.res); i++) {
            const ic_trace_special *sp = ic_trace_result_special(t.res, i);
            /* located on N_A x N_B = 0 to 1e-12 */
            at_x += sp->type == IC_POINT_BRANCH &&
                    hypot(hypot(fabs(sp->xyz[0]) - 1, sp->xyz[1]), sp->xyz[2]) <= TIER_LOCATED;
        }
        CHECK(ic_trace_result_num_specials(t.res) == 2 && at_x == 2,
              "equal cylinders: branch points at (+-1, 0, 0)");
    }
    release(&t);
    if (trace_example(&t, dir, "small-loop.json") == 0) {
        /* the bead of radius 0.01 cut 0.005 off centre: radius sqrt(7.5e-5); the
         * tracer's 1e-10 is absolute, so on this short curve (0.054) it is
         * larger relative to the length (measured 1.8e-11) */
        check_curves(&t, "loop of 0.9% of the box", 1, (double)(2 * PI_L * sqrtl(7.5e-5L)),
                     IC_SHAPE_CIRCLE);
    }
    release(&t);
    if (trace_example(&t, dir, "tacnode.json") == 0)
        check_tacnode(&t);
    release(&t);
    if (trace_example(&t, dir, "cusp.json") == 0)
        check_cusp(&t);
    release(&t);
    return harness_finish("test_trace_examples");
}
