/*
 * Self-intersections on periodic domains that start anywhere (issue 23:
 * "an embedded torus posed as a self-intersection with a shifted periodic
 * domain ... runs to the time limit"). Before: the tracer took preimages a
 * whole period apart for distinct (40 s, 225 spurious tangential points,
 * incomplete), and the checker cut both periods at the domain's start, so a
 * double curve along v = 0 with u = p lay in a face of the region. Sweeps
 * (every case right and complete, or honestly incomplete; never complete
 * and wrong; here all six of each must be proven):
 *   - embedded tori ((R + r cos v) cos u, (R + r cos v) sin u, r sin v),
 *     R > r > 0, periodic in u and v, the domains shifted: no curve;
 *   - figure-eight tori ((R + sin v) cos u, (R + sin v) sin u, sin 2v),
 *     R > 1: one double circle;
 * and mutations of a proven figure-eight trace: the circle dropped, and
 * doubled, each refused.
 *
 * Truth, derived by hand (no code of the project involved):
 *   embedded torus: R(u, v) = R(p, q) gives the same distance from the z
 *   axis, R + r cos v = R + r cos q (both positive), the same angle about
 *   it, u = p mod 2 pi, and the same height, sin v = sin q; with cos v =
 *   cos q that is v = q mod 2 pi: R is one-to-one, no double point.
 *   figure-eight torus: the distance from the axis R + sin v = R + sin q
 *   (R > 1: positive) gives u = p mod 2 pi and sin v = sin q; the height
 *   sin 2v = sin 2q = 2 sin q cos q then gives cos v = cos q (so v = q) or
 *   sin v = sin q = 0 with v != q, {v, q} = {0, pi} mod 2 pi: the double
 *   curve is the circle of radius R in z = 0, preimages (u, 0) and (u, pi),
 *   of length 2 pi R, crossed transversally (the section's tangents (1, 2)
 *   at v = 0 and (-1, 2) at v = pi are apart).
 *
 * usage: test_certificate_periodic_self
 */
#include <math.h>

#include "certify_harness.h"

#define PI 3.14159265358979323846

/* A self-intersection of the parametric surface xyz on the periodic domain
 * [u0, u0 + 2 pi] x [v0, v0 + 2 pi]. */
static void problem(char *json, size_t size, const char *x, const char *y, const char *z,
                    double u0, double v0)
{
    snprintf(json, size,
             "{\"surfaces\": [{\"type\": \"parametric\", \"params\": [\"u\", \"v\"], "
             "\"xyz\": [\"%s\", \"%s\", \"%s\"], \"domain\": [[%.17g, %.17g], [%.17g, %.17g]], "
             "\"periodic\": [true, true]}], \"self\": true}",
             x, y, z, u0, u0 + 2 * PI, v0, v0 + 2 * PI);
}

/* R, r, and the domain's start in u and v. */
static const double TORI[6][4] = {{2, 1, 1, -2},   {2, 1, 0, 0},       {3, 0.5, -3, 0.5},
                                  {1.5, 1, 0.5, 3}, {2.5, 0.7, -100, 7}, {4, 2, 2.2, -PI}};

static void sweep_tori(void)
{
    tally all = {0};
    for (int i = 0; i < 6; i++) {
        const double *t = TORI[i];
        char x[120], y[120], z[80], json[900], name[120];
        snprintf(x, sizeof x, "(%.17g + %.17g*cos(v))*cos(u)", t[0], t[1]);
        snprintf(y, sizeof y, "(%.17g + %.17g*cos(v))*sin(u)", t[0], t[1]);
        snprintf(z, sizeof z, "%.17g*sin(v)", t[1]);
        problem(json, sizeof json, x, y, z, t[2], t[3]);
        snprintf(name, sizeof name, "torus R %g r %g from (%g, %g)", t[0], t[1], t[2], t[3]);
        traced tr;
        if (trace_json(&tr, name, json) == 0)
            judge(&all, &tr, name, ic_trace_result_num_curves(tr.res) == 0);
        release(&tr);
    }
    CHECK(all.right == 6 && all.missed == 0, "embedded tori: %d right of 6, %d not proven",
          all.right, all.missed);
}

/* Every point of the one closed curve on the circle of radius R in z = 0
 * (to TIER_ON_CURVE of R), and its length 2 pi R (to TIER_LENGTH). */
static int double_circle(const ic_trace_result *r, double R)
{
    if (ic_trace_result_num_curves(r) != 1)
        return 0;
    const ic_trace_curve *c = ic_trace_result_curve(r, 0);
    for (int i = 0; i < c->npoints; i++) {
        const double *p = c->points[i].xyz;
        if (fabs(hypot(p[0], p[1]) - R) > TIER_ON_CURVE * R || fabs(p[2]) > TIER_ON_CURVE * R)
            return 0;
    }
    return c->closed && harness_close(c->length, 2 * PI * R, TIER_LENGTH, 1);
}

/* R and the domain's start in u and v. */
static const double EIGHTS[6][3] = {{2, 0, 0},   {2, 1, -2},   {3, -3, 0.5},
                                    {1.5, 0.5, 3}, {2, 0, PI}, {2.5, -100, 7}};

static void figure_eight(char *json, size_t size, const double *e)
{
    char x[120], y[120];
    snprintf(x, sizeof x, "(%.17g + sin(v))*cos(u)", e[0]);
    snprintf(y, sizeof y, "(%.17g + sin(v))*sin(u)", e[0]);
    problem(json, size, x, y, "sin(2*v)", e[1], e[2]);
}

static void sweep_eights(void)
{
    tally all = {0};
    for (int i = 0; i < 6; i++) {
        char json[900], name[120];
        figure_eight(json, sizeof json, EIGHTS[i]);
        snprintf(name, sizeof name, "figure-eight torus R %g from (%g, %g)", EIGHTS[i][0],
                 EIGHTS[i][1], EIGHTS[i][2]);
        traced tr;
        if (trace_json(&tr, name, json) == 0)
            judge(&all, &tr, name, double_circle(tr.res, EIGHTS[i][0]));
        release(&tr);
    }
    CHECK(all.right == 6 && all.missed == 0,
          "figure-eight tori: %d right of 6, %d not proven", all.right, all.missed);
}

/* The proven trace of EIGHTS[1]: the circle dropped, or twice, refused. */
static void mutations(void)
{
    char json[900];
    figure_eight(json, sizeof json, EIGHTS[1]);
    traced t;
    if (trace_json(&t, "figure-eight mutations", json) != 0) {
        release(&t);
        return;
    }
    ic_certify_curve cv[2];
    const int n = ic_trace_result_num_curves(t.res);
    double *z = n == 1 ? search_curves(&t, ic_pair_pairing(t.pair), cv) : NULL;
    if (REQUIRE(z && ic_trace_result_report(t.res)->complete,
                "figure-eight mutations: %d curves, not proven", n)) {
        char why[240];
        ic_certify_claim claim = {.curves = cv, .ncurves = 1};
        CHECK(verdict_of(&t, &claim, 0, why) == 1, "the true trace is refused: %s", why);
        claim.ncurves = 0;
        CHECK(verdict_of(&t, &claim, 0, why) == 0 && strstr(why, "not traced"),
              "the circle dropped is not refused as untraced: '%s'", why);
        cv[1] = cv[0];
        claim.ncurves = 2;
        CHECK(verdict_of(&t, &claim, 0, why) == 0 && strstr(why, "more than once"),
              "the circle doubled is not refused as traced twice: '%s'", why);
        printf("figure-eight mutations: the circle dropped, doubled: refused\n");
    }
    free(z);
    release(&t);
}

int main(void)
{
    sweep_tori();
    sweep_eights();
    mutations();
    return harness_finish("test_certificate_periodic_self");
}
