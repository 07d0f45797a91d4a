/* The five cases (issue 12, item 6) and a variant of the last, all in the
 * standard placement a CAD kernel gives by default: axes along z (or x, y),
 * seams on the reference direction. So Viviani's curve passes through both poles of the sphere's
 * net and its branch point lies on both seams, the tangential circle of
 * case 4 on the torus' tube seam, and the contact point of case 5 at the
 * sphere's pole: what a CAD file would hold (docs/peers.md). The sixth case
 * turns the sphere of the fifth so that its contact point is a regular point
 * of the net. */
#include <math.h>
#include <string.h>

#include "cases.h"

/* Viviani's curve: 4 sqrt(2) E(1/2) (E the complete elliptic integral of the
 * second kind, parameter m = 1/2), from mpmath at 30 digits:
 * 4*sqrt(2)*ellipe(0.5) and quad of |c'| over [0, 4 pi] agree. */
#define VIVIANI_LENGTH 7.6403955780554240358
/* two ellipses of semi-axes sqrt 2 and 1: 2 * 4 sqrt(2) E(1/2), mpmath as above */
#define STEINMETZ_LENGTH 15.280791156110848072

static const double X[3] = {1, 0, 0}, Y[3] = {0, 1, 0}, Z[3] = {0, 0, 1};

static exact_surface placed(exact_kind kind, double cx, double cy, double cz, const double axis[3],
                            const double ref[3])
{
    exact_surface s;
    memset(&s, 0, sizeof s);
    s.kind = kind;
    s.center[0] = cx, s.center[1] = cy, s.center[2] = cz;
    memcpy(s.axis, axis, sizeof s.axis);
    memcpy(s.ref, ref, sizeof s.ref);
    return s;
}

static exact_surface sphere(double cz, double r)
{
    exact_surface s = placed(EXACT_SPHERE, 0, 0, cz, Z, X);
    s.radius = r;
    return s;
}

static exact_surface cylinder(double cx, const double axis[3], const double ref[3], double r)
{
    exact_surface s = placed(EXACT_CYLINDER, cx, 0, 0, axis, ref);
    s.radius = r, s.half_length = 1.5;
    return s;
}

static exact_surface plane_z(double z)
{
    exact_surface s = placed(EXACT_PLANE, 0, 0, z, Z, X);
    s.half_length = 2;
    return s;
}

static void set_circle(bench_case *c, double cz, double r)
{
    c->truth = TRUTH_CIRCLE;
    c->circle_center[2] = cz;
    memcpy(c->circle_axis, Z, sizeof c->circle_axis);
    c->circle_radius = r;
    c->expect_curves = 1;
    c->expect_length = 2 * PEERS_PI * r;
}

int bench_cases_build(bench_case cases[BENCH_NUM_CASES])
{
    memset(cases, 0, sizeof(bench_case) * BENCH_NUM_CASES);
    bench_case *c = cases;

    c->name = "viviani";
    c->title = "sphere r = 1 and cylinder (x - 1/2)^2 + y^2 = 1/4: one curve, a branch point";
    c->A = sphere(0, 1), c->B = cylinder(0.5, Z, X, 0.5);
    c->truth = TRUTH_VIVIANI, c->expect_curves = 1, c->expect_length = VIVIANI_LENGTH;
    c++;

    c->name = "steinmetz";
    c->title = "cylinders y^2 + z^2 = 1 and x^2 + z^2 = 1: two ellipses, two branch points";
    c->A = cylinder(0, X, Y, 1), c->B = cylinder(0, Y, X, 1);
    c->truth = TRUTH_STEINMETZ, c->expect_curves = 2, c->expect_length = STEINMETZ_LENGTH;
    c++;

    c->name = "sphere-plane";
    c->title = "sphere r = 1 and plane z = 1/2: a circle of radius sqrt(3)/2";
    c->A = sphere(0, 1), c->B = plane_z(0.5);
    set_circle(c, 0.5, sqrt(3) / 2);
    c++;

    c->name = "torus-sphere";
    c->title = "torus R = 2, r = 1/2 and sphere r = 5/2: touching along a circle";
    c->A = placed(EXACT_TORUS, 0, 0, 0, Z, X);
    c->A.major = 2, c->A.radius = 0.5;
    c->B = sphere(0, 2.5);
    set_circle(c, 0, 2.5);
    c++;

    c->name = "sphere-touch";
    c->title = "sphere r = 1 centred (0, 0, 1) on the plane z = 0: one contact point";
    c->A = sphere(1, 1), c->B = plane_z(0);
    c->truth = TRUTH_NONE, c->expect_points = 1;
    c++;

    /* case 5 again with the sphere's poles on the x axis: the contact point
     * is then a regular point of the net, not its degenerate pole */
    c->name = "sphere-touch-x";
    c->title = "as sphere-touch, the sphere's net turned: pole axis x, contact off the poles";
    c->A = placed(EXACT_SPHERE, 0, 0, 1, X, Y);
    c->A.radius = 1;
    c->B = plane_z(0);
    c->truth = TRUTH_NONE, c->expect_points = 1;
    c++;

    for (int i = 0; i < BENCH_NUM_CASES; i++) {
        net_from_exact(&cases[i].netA, &cases[i].A);
        net_from_exact(&cases[i].netB, &cases[i].B);
    }
    return BENCH_NUM_CASES;
}
