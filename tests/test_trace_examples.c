/* Whole traces of bundled examples (issue 5's test list) against lengths
 * integrated independently (tests/curve_lengths.h): two perpendicular
 * cylinders of radii 1 and 0.7 (two closed loops) and of equal radii (two
 * ellipses through two branch points), and a loop smaller than 1% of the box. */
#include <stdio.h>
#include <string.h>

#include "curve_lengths.h"
#include "harness.h"
#include "intercurve.h"
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
        CHECK(c->closed && c->shape == shape && fabs(c->length - L) <= 1e-9 * L,
              "%s curve %d: closed %d, %s, length %.17g of %.17g", name, i, c->closed,
              ic_shape_name(c->shape), c->length, L);
    }
    printf("%-24s %d closed %s curves, length error %.2g\n", name, n, ic_shape_name(shape), worst);
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
                    hypot(hypot(fabs(sp->xyz[0]) - 1, sp->xyz[1]), sp->xyz[2]) <= 1e-12;
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
    return harness_finish("test_trace_examples");
}
