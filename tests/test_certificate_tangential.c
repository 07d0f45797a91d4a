/*
 * The certificate beside tangential curves (issue 23, docs/tracing.md "The
 * certificate"): a tangential curve the result reports gets a tube of
 * radius 5e-4 of the region's size; the cover proves everything outside
 * the tubes, and the tubes must neither come back on themselves nor meet.
 * Sweep (every case right and complete, or honestly incomplete; never
 * complete and wrong): a cylinder of radius R resting on the plane z = 0
 * along the horizontal direction a = (cos phi, sin phi, 0), six radii and
 * directions, in the box [-1, 1]^2 x [-1/2, 2R + 1/2]: one tangential line
 * through the origin, cut by the box.
 * Mutations of a proven trace: the tangential curve dropped, cut short,
 * traced twice over (an overlap), moved off its place: each refused.
 *
 * Truth in closed form: the line t a, |t cos phi| <= 1, |t sin phi| <= 1,
 * of length 2 / max(|cos phi|, |sin phi|).
 *
 * usage: test_certificate_tangential
 */
#include <math.h>

#include "certify_harness.h"

typedef struct {
    double R, phi;
} line_case;

static const line_case LINES[] = {{1.0, 0.3}, {0.5, 0.7}, {2.0, 1.1},
                                  {0.25, 0.2}, {1.5, 0.45}, {0.75, 1.3}};
#define NLINES (int)(sizeof LINES / sizeof LINES[0])

static void line_problem(const line_case *k, char *json, size_t size)
{
    const double c = cos(k->phi), s = sin(k->phi);
    snprintf(json, size,
             "{\"surfaces\": [{\"type\": \"implicit\", \"f\": \"x^2 + y^2 + (z - %.17g)^2 - "
             "(%.17g*x + %.17g*y)^2 - %.17g\"}, {\"type\": \"implicit\", \"f\": \"z\"}],"
             "\"box\": [[-1, 1], [-1, 1], [-0.5, 0.5]]}",
             k->R, c, s, k->R * k->R);
}

/* One open tangential curve of the line's length (TIER_LENGTH), its points
 * on the line t a within TIER_ON_CURVE, and no singular point. */
static int line_right(const ic_trace_result *r, const line_case *k)
{
    if (ic_trace_result_num_curves(r) != 1 || ic_trace_result_num_specials(r) != 0)
        return 0;
    const ic_trace_curve *cv = ic_trace_result_curve(r, 0);
    const double c = cos(k->phi), s = sin(k->phi);
    const double L = 2.0 / fmax(fabs(c), fabs(s));
    int on = cv->tangential && !cv->closed && harness_close(cv->length, L, TIER_LENGTH, 1);
    for (int i = 0; on && i < cv->npoints; i++) {
        const double *x = cv->points[i].xyz;
        on = fabs(x[0] * s - x[1] * c) < TIER_ON_CURVE && fabs(x[2]) < TIER_ON_CURVE;
    }
    return on;
}

static void sweep_lines(void)
{
    tally t = {0};
    for (int i = 0; i < NLINES; i++) {
        char json[600], name[80];
        line_problem(&LINES[i], json, sizeof json);
        snprintf(name, sizeof name, "tangential line R = %g, phi = %g", LINES[i].R, LINES[i].phi);
        traced tr;
        if (trace_json(&tr, name, json) == 0)
            judge(&t, &tr, name, line_right(tr.res, &LINES[i]));
        release(&tr);
    }
    CHECK(t.right == NLINES && t.missed == 0,
          "tangential lines: %d right of %d, %d of them not proven", t.right, NLINES, t.missed);
}

/* Mutations of the first line's proven trace. */
static void mutations(void)
{
    char json[600];
    line_problem(&LINES[0], json, sizeof json);
    traced t;
    if (trace_json(&t, "tangential mutations", json) != 0) {
        release(&t);
        return;
    }
    const ic_trace_result *r = t.res;
    ic_certify_curve cv[2];
    double *z = ic_trace_result_num_curves(r) == 1
                    ? search_curves(&t, ic_pair_pairing(t.pair), cv)
                    : NULL;
    if (REQUIRE(z && ic_trace_result_report(r)->complete, "tangential mutations: not proven")) {
        const int n = cv[0].npoints;
        ic_certify_tube tube[2] = {{z, n, 0}, {z, n, 0}};
        ic_certify_claim claim = {.curves = cv, .ncurves = 1, .tubes = tube, .ntubes = 1};
        char why[240];
        CHECK(verdict_of(&t, &claim, 0, why) == 1, "the true trace is refused: %s", why);
        claim.ncurves = 0, claim.ntubes = 0;
        CHECK(verdict_of(&t, &claim, 0, why) == 0 && strstr(why, "neither empty nor regular"),
              "the tangential curve dropped is not refused: '%s'", why);
        claim.ncurves = 1, claim.ntubes = 1;
        tube[0].n = n - n / 4; /* a quarter of its points short */
        CHECK(verdict_of(&t, &claim, 0, why) == 0 && strstr(why, "neither empty nor regular"),
              "the tangential curve cut short is not refused: '%s'", why);
        tube[0].n = n;
        claim.ntubes = 2; /* traced twice over */
        CHECK(verdict_of(&t, &claim, 0, why) == 0 && strstr(why, "meets another"),
              "the tangential curve traced twice is not refused: '%s'", why);
        claim.ntubes = 1;
        double *moved = malloc(3 * (size_t)n * sizeof *moved);
        for (int i = 0; moved && i < 3 * n; i++)
            moved[i] = z[i] + (i % 3 == 2 ? 0.01 : 0.0); /* 0.01 above the plane */
        tube[0].xyz = moved;
        CHECK(moved && verdict_of(&t, &claim, 0, why) == 0 &&
                  strstr(why, "neither empty nor regular"),
              "the tangential curve moved off its place is not refused: '%s'", why);
        free(moved);
        printf("tangential mutations: dropped, cut short, doubled, moved: all refused\n");
    }
    free(z);
    release(&t);
}

/* A torus (R, r) about the z axis resting on, or under, the plane z = +-r:
 * one tangential circle of radius R, and no singular point (the torus's
 * symmetry leaves none special; a tacnode was once reported on the top
 * circle, a point found on its own and classified off the curve). */
static void sweep_torus_circles(void)
{
    static const double K[][3] = {{2.0, 0.5, 1.0}, {3.0, 1.0, -1.0}, {2.5, 0.75, 1.0}};
    tally t = {0};
    for (int i = 0; i < 3; i++) {
        const double R = K[i][0], r = K[i][1], side = K[i][2];
        char json[600], name[80];
        snprintf(json, sizeof json,
                 "{\"surfaces\": [{\"type\": \"implicit\", \"f\": \"(x^2 + y^2 + z^2 + %.17g)^2 "
                 "- %.17g*(x^2 + y^2)\"}, {\"type\": \"implicit\", \"f\": \"z - %.17g\"}], "
                 "\"box\": [[%g, %g], [%g, %g], [%g, %g]]}",
                 R * R - r * r, 4 * R * R, side * r, -(R + 2 * r), R + 2 * r, -(R + 2 * r),
                 R + 2 * r, -2 * r, 2 * r);
        snprintf(name, sizeof name, "torus (%g, %g) %s the plane", R, r,
                 side > 0 ? "under" : "on");
        traced tr;
        if (trace_json(&tr, name, json) == 0) {
            const ic_trace_result *res = tr.res;
            const ic_trace_curve *c =
                ic_trace_result_num_curves(res) == 1 ? ic_trace_result_curve(res, 0) : NULL;
            judge(&t, &tr, name,
                  c && c->tangential && c->closed && ic_trace_result_num_specials(res) == 0 &&
                      harness_close(c->length, 2 * 3.14159265358979323846 * R, TIER_LENGTH, 1));
        }
        release(&tr);
    }
    CHECK(t.missed == 0 && t.right == 3, "torus circles: %d right of 3, %d of them not proven",
          t.right, t.missed);
}

int main(void)
{
    sweep_lines();
    sweep_torus_circles();
    mutations();
    return harness_finish("test_certificate_tangential");
}
