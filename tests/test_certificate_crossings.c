/*
 * Tangential circles the certificate's sweeps had not met (issue 23,
 * docs/tracing.md "Crossings of a tangential curve"). A is the unit sphere;
 * B touches it along the equator z = 0 (truth and its algebra:
 * tests/truth/gen_certificate_crossings_truth.py):
 *  - crossed: B = x^2 + y^2 - 1 + z^2 (1 + k (y - d)) meets A in the
 *    equator and the circle y = d, which crosses it at (+-sqrt(1 - d^2),
 *    d, 0): six (d, k), implicit, and A the sphere's net (u, v) on
 *    [-pi, pi] x [-pi/2, pi/2] against the implicit B (five: d = 0.95 costs
 *    15 s there). Right: one closed tangential curve of length 2 pi, one
 *    closed transversal curve of length 2 pi sqrt(1 - d^2), and two
 *    higher-order contacts at the crossings. Before crossing.c the circle's
 *    arcs stopped 0.0046 short of each crossing, with four approximate
 *    branch points, in all 12 cases.
 *  - loop: B = x^2 + y^2 - 1 + z^2 (1 + K s), s = |X - p|^2 - r^2, p on A
 *    at height gap + r: the equator and a loop of radius about r whose
 *    lowest point is gap above it; r = 1e-2 to 1e-3, gap 3e-4 to 1e-2, in
 *    both forms. Right: the tangential circle and one closed transversal
 *    loop of length 2 pi r sqrt(1 - r^2 / 4), no point.
 * Every case right and complete, or honestly incomplete; never complete and
 * wrong. Mutations of a proven crossed trace: a crossing dropped, the
 * transversal circle dropped: refused.
 *
 * usage: test_certificate_crossings [SOURCE_DIR]
 */
#include <math.h>

#include "certify/certificate.h"
#include "certify_harness.h"

/* A crossing the result gives as exact is placed to within
 * IC_TRACE_CROSSING_PLACE_REL L (its bend's bracket on the tangential
 * curve, a double root known across to about 1e-8 L in the parametric
 * form; measured: 1e-16 implicit, up to 1.5e-7 on the net), so its place is
 * held to that, and the transversal curve's length, whose ends (joined
 * there) moved by at most that each, to twice it. */
#define CROSSING_PLACE_REL 1e-6
#define PI 3.14159265358979323846

#define NCROSSED 6
#define NLOOPS 6
#define SPHERE_IMPLICIT "{\"type\": \"implicit\", \"f\": \"x^2 + y^2 + z^2 - 1\"}"
#define SPHERE_NET                                                                             \
    "{\"type\": \"parametric\", \"params\": [\"u\", \"v\"], \"xyz\": [\"cos(u)*cos(v)\", "     \
    "\"sin(u)*cos(v)\", \"sin(v)\"], \"domain\": [[\"-pi\", \"pi\"], [\"-pi/2\", \"pi/2\"]], " \
    "\"periodic\": [true, false]}"
#define BOX "\"box\": [[-1.5, 1.5], [-1.5, 1.5], [-1.5, 1.5]]"

static void problem(char *json, size_t size, int net, const char *B)
{
    snprintf(json, size,
             "{\"surfaces\": [%s, {\"type\": \"implicit\", \"f\": \"%s\"}], " BOX "}",
             net ? SPHERE_NET : SPHERE_IMPLICIT, B);
}

/* The result's tangential equator: one closed tangential curve of length
 * 2 pi; *transversal the index of the one other curve, closed. */
static int equator_and_one(const ic_trace_result *r, int *transversal)
{
    int tangential = 0, other = 0;
    for (int k = 0; k < ic_trace_result_num_curves(r); k++) {
        const ic_trace_curve *c = ic_trace_result_curve(r, k);
        if (c->tangential)
            tangential += c->closed && harness_close(c->length, 2 * PI, TIER_LENGTH, 1);
        else
            other++, *transversal = k;
    }
    return tangential == 1 && other == 1 && ic_trace_result_num_curves(r) == 2 &&
           ic_trace_result_curve(r, *transversal)->closed;
}

static int crossed_right(const ic_trace_result *r, const double *row)
{
    int t;
    const double place = CROSSING_PLACE_REL * ic_trace_result_report(r)->scale;
    if (!equator_and_one(r, &t) ||
        !harness_close(ic_trace_result_curve(r, t)->length, row[2], 2 * place, 0) ||
        ic_trace_result_num_specials(r) != 2)
        return 0;
    int at[2] = {0, 0};
    for (int k = 0; k < 2; k++) {
        const ic_trace_special *s = ic_trace_result_special(r, k);
        for (int side = 0; side < 2; side++) {
            const double want[3] = {side ? -row[3] : row[3], row[0], 0.0};
            at[side] += s->type == IC_POINT_HIGHER_ORDER_CONTACT && !s->approximate &&
                        fabs(s->xyz[0] - want[0]) + fabs(s->xyz[1] - want[1]) +
                                fabs(s->xyz[2]) <=
                            place;
        }
    }
    return at[0] == 1 && at[1] == 1;
}

static int loop_right(const ic_trace_result *r, const double *row)
{
    int t;
    return equator_and_one(r, &t) && ic_trace_result_num_specials(r) == 0 &&
           harness_close(ic_trace_result_curve(r, t)->length, row[3], TIER_LENGTH, 1);
}

static void sweep_crossed(const double rows[][4], tally *t)
{
    for (int net = 0; net < 2; net++)
        for (int i = 0; i < NCROSSED; i++) {
            const double *row = rows[i];
            if (net && row[0] == 0.95)
                continue; /* 15 s, proven (docs/tracing.md) */
            char B[200], json[900], name[120];
            snprintf(B, sizeof B, "x^2 + y^2 - 1 + z^2*(1 + %.17g*(y - (%.17g)))", row[1], row[0]);
            problem(json, sizeof json, net, B);
            snprintf(name, sizeof name, "crossed %s d = %g, k = %g",
                     net ? "parametric/implicit" : "implicit", row[0], row[1]);
            traced tr;
            if (trace_json(&tr, name, json) == 0)
                judge(&t[net], &tr, name, crossed_right(tr.res, row));
            release(&tr);
        }
}

static void sweep_loops(const double rows[][4], tally *t)
{
    for (int net = 0; net < 2; net++)
        for (int i = 0; i < NLOOPS; i++) {
            const double *row = rows[NCROSSED + i];
            const double r = row[0], pz = row[1] + r, px = sqrt(1 - pz * pz);
            char B[300], json[1000], name[120];
            snprintf(B, sizeof B,
                     "x^2 + y^2 - 1 + z^2*(1 + %.17g*((x - %.17g)^2 + y^2 + (z - %.17g)^2 - "
                     "%.17g))",
                     row[2], px, pz, r * r);
            problem(json, sizeof json, net, B);
            snprintf(name, sizeof name, "loop %s r = %g, gap = %g",
                     net ? "parametric/implicit" : "implicit", r, row[1]);
            traced tr;
            if (trace_json(&tr, name, json) == 0)
                judge(&t[net], &tr, name, loop_right(tr.res, row));
            release(&tr);
        }
}

/* Mutations of the first crossed case's proven trace: the claim as the
 * tracer makes it (the tangential curve in its tube, the crossings' boxes
 * IC_CERTIFY_CONTACT_SCALE wide) is accepted; a crossing dropped, or the
 * transversal circle, refused. */
static void mutations(const double *row)
{
    char B[200], json[900];
    snprintf(B, sizeof B, "x^2 + y^2 - 1 + z^2*(1 + %.17g*(y - (%.17g)))", row[1], row[0]);
    problem(json, sizeof json, 0, B);
    traced t;
    if (trace_json(&t, "crossing mutations", json) != 0) {
        release(&t);
        return;
    }
    const ic_trace_result *r = t.res;
    const int n = ic_trace_result_num_curves(r), ns = ic_trace_result_num_specials(r);
    ic_certify_curve cv[2];
    double *z = n == 2 && ns == 2 ? search_curves(&t, ic_pair_pairing(t.pair), cv) : NULL;
    if (REQUIRE(z && ic_trace_result_report(r)->complete, "crossing mutations: not proven")) {
        double sing[2][3];
        const double scale[2] = {IC_CERTIFY_CONTACT_SCALE, IC_CERTIFY_CONTACT_SCALE};
        for (int k = 0; k < ns; k++)
            memcpy(sing[k], ic_trace_result_special(r, k)->xyz, sizeof sing[k]);
        const int tan = cv[0].tangential ? 0 : 1;
        /* implicit: the search coordinates are (x, y, z) */
        ic_certify_tube tube = {cv[tan].z, cv[tan].npoints, cv[tan].closed};
        ic_certify_curve order[2] = {cv[1 - tan], cv[tan]}; /* the transversal first */
        ic_certify_claim claim = {.curves = order, .ncurves = 2,
                                  .singular = (const double(*)[3])sing, .singular_scale = scale,
                                  .nsingular = 2, .tubes = &tube, .ntubes = 1};
        char why[240];
        CHECK(verdict_of(&t, &claim, 0, why) == 1, "the true trace is refused: %s", why);
        claim.nsingular = 1;
        CHECK(verdict_of(&t, &claim, 0, why) == 0, "a crossing dropped is not refused");
        claim.nsingular = 2, claim.curves = order + 1, claim.ncurves = 1;
        CHECK(verdict_of(&t, &claim, 0, why) == 0 && strstr(why, "not traced"),
              "the transversal circle dropped is not refused as untraced: '%s'", why);
        printf("crossing mutations: a crossing dropped, the circle dropped: refused\n");
    }
    free(z);
    release(&t);
}

int main(int argc, char **argv)
{
    const char *src = argc > 1 ? argv[1] : ".";
    double rows[NCROSSED + NLOOPS][4];
    if (read_truth_rows(src, "certificate_crossings.txt", 4, NCROSSED + NLOOPS, &rows[0][0]) !=
        0)
        return harness_finish("test_certificate_crossings");
    tally crossed[2] = {{0}, {0}}, loops[2] = {{0}, {0}};
    sweep_crossed(rows, crossed);
    sweep_loops(rows, loops);
    mutations(rows[0]);
    /* measured: crossed 6 of 6 and 4 of 5 proven (the net at d = 0: the
     * circle through its poles on the seam), loops 6 of 6 and 6 of 6 (the
     * net's search misses loops of radius 1e-3; the checker sees their arcs
     * and the tracer starts again from them) */
    CHECK(crossed[0].proven >= 6 && crossed[1].proven >= 4,
          "crossed: %d implicit and %d parametric proven", crossed[0].proven, crossed[1].proven);
    CHECK(loops[0].proven >= 6 && loops[1].proven >= 6, "loops: %d implicit and %d parametric proven",
          loops[0].proven, loops[1].proven);
    printf("crossed: %d + %d right, %d + %d proven; loops: %d + %d right, %d + %d proven\n",
           crossed[0].right, crossed[1].right, crossed[0].proven, crossed[1].proven, loops[0].right,
           loops[1].right, loops[0].proven, loops[1].proven);
    return harness_finish("test_certificate_crossings");
}
