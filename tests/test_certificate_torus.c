/*
 * A torus touching a sphere along a circle (issue 23's class of the torus
 * and sphere as B-spline surfaces): the torus (R, r) about the z axis as
 * the rational biquadratic NURBS net of a circle revolved (9 x 9 points,
 * weights 1 and sqrt(2)/2, periodic both ways), the sphere about (0, 0, c)
 * implicit, of radius sqrt(R^2 + c^2) + side r, touching the tube outside
 * (side 1) or inside (-1): six placements. Right: one closed tangential
 * curve, a circle at the truth's height, of the truth's length
 * (tests/truth/gen_certificate_torus_truth.py), no point; never complete
 * and wrong. Measured: all six proven, 1 to 4 s each. Both as NURBS (not
 * here: 13 to 32 s each), the closed form of coaxial surfaces of revolution
 * gives the circle and the certificate proves 1 of 6 within its cells
 * (docs/tracing.md).
 *
 * usage: test_certificate_torus [SOURCE_DIR]
 */
#include <math.h>

#include "certify_harness.h"

#define NCASES 6
#define H 0.70710678118654752440 /* a quarter circle's middle weight */

static const double CIRCLE[9][2] = {{1, 0},  {1, 1},   {0, 1},  {-1, 1}, {-1, 0},
                                    {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
static const double CIRCLE_W[9] = {1, H, 1, H, 1, H, 1, H, 1};

/* Appends to json (of size, *at used) what fmt says; 0, or -1 out of room. */
static int put(char *json, size_t size, size_t *at, const char *fmt, double a, double b, double c)
{
    const int n = snprintf(json + *at, size - *at, fmt, a, b, c);
    if (n < 0 || (size_t)n >= size - *at)
        return -1;
    *at += (size_t)n;
    return 0;
}

/* The problem: the NURBS torus (R, r) and the sphere (c, rho), the box the
 * torus's with a margin of 1. */
static int problem(char *json, size_t size, double R, double r, double c, double rho)
{
    const double prof[9][2] = {{R - r, 0}, {R - r, -r}, {R, -r}, {R + r, -r}, {R + r, 0},
                               {R + r, r},  {R, r},     {R - r, r}, {R - r, 0}};
    const char *knots = "[0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1]";
    size_t at = 0;
    int bad = put(json, size, &at, "{\"surfaces\": [{\"type\": \"nurbs\", \"degree\": [2, 2], "
                                   "\"periodic\": [true, true], \"control_points\": [",
                  0, 0, 0);
    for (int i = 0; i < 9 && !bad; i++)
        for (int j = 0; j < 9 && !bad; j++)
            bad = put(json, size, &at, j ? ", [%.17g, %.17g, %.17g]" : "[[%.17g, %.17g, %.17g]",
                      prof[j][0] * CIRCLE[i][0], prof[j][0] * CIRCLE[i][1], prof[j][1]) ||
                  (j == 8 && put(json, size, &at, i < 8 ? "], " : "]], \"weights\": [", 0, 0, 0));
    for (int i = 0; i < 9 && !bad; i++)
        for (int j = 0; j < 9 && !bad; j++)
            bad = put(json, size, &at, j ? ", %.17g" : "[%.17g", CIRCLE_W[i] * CIRCLE_W[j], 0, 0) ||
                  (j == 8 && put(json, size, &at, i < 8 ? "], " : "]], ", 0, 0, 0));
    const double m = R + r + 1;
    if (!bad)
        bad = snprintf(json + at, size - at,
                       "\"knots\": [%s, %s]}, {\"type\": \"implicit\", \"f\": \"x^2 + y^2 + (z - "
                       "(%.17g))^2 - %.17g\"}], \"box\": [[%g, %g], [%g, %g], [%g, %g]]}",
                       knots, knots, c, rho * rho, -m, m, -m, m, -m, m) >= (int)(size - at);
    return REQUIRE(!bad, "the problem does not fit its buffer") ? 0 : -1;
}

/* One closed tangential circle of the truth's length about the axis at the
 * truth's height (points within TIER_ON_CURVE), no point. */
static int right(const ic_trace_result *res, const double *row)
{
    if (ic_trace_result_num_curves(res) != 1 || ic_trace_result_num_specials(res) != 0)
        return 0;
    const ic_trace_curve *cv = ic_trace_result_curve(res, 0);
    const double radius = row[4] / (2 * 3.14159265358979323846);
    int on = cv->tangential && cv->closed && harness_close(cv->length, row[4], TIER_LENGTH, 1);
    for (int i = 0; on && i < cv->npoints; i++) {
        const double *x = cv->points[i].xyz;
        on = fabs(hypot(x[0], x[1]) - radius) < TIER_ON_CURVE && fabs(x[2] - row[5]) < TIER_ON_CURVE;
    }
    return on;
}

int main(int argc, char **argv)
{
    const char *src = argc > 1 ? argv[1] : ".";
    double rows[NCASES][6];
    if (read_truth_rows(src, "certificate_torus.txt", 6, NCASES, &rows[0][0]) != 0)
        return harness_finish("test_certificate_torus");
    tally t = {0};
    for (int i = 0; i < NCASES; i++) {
        const double *row = rows[i];
        const double R = row[0], r = row[1], c = row[2], side = row[3];
        static char json[16384];
        char name[100];
        snprintf(name, sizeof name, "NURBS torus (%g, %g), sphere at %g %s", R, r, c,
                 side > 0 ? "outside" : "inside");
        traced tr;
        if (problem(json, sizeof json, R, r, c, hypot(R, c) + side * r) == 0 &&
            trace_json(&tr, name, json) == 0)
            judge(&t, &tr, name, right(tr.res, row));
        release(&tr);
    }
    CHECK(t.proven == NCASES && t.right == NCASES, "torus and sphere: %d right, %d proven of %d",
          t.right, t.proven, NCASES);
    return harness_finish("test_certificate_torus");
}
