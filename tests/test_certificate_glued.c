/*
 * Self-intersections of sheets whose opposite domain edges are one curve
 * of the surface, not marked periodic (issue 23's class: "a figure-8 Klein
 * bottle's self-intersection on a domain that cuts its seam ... 119 s,
 * ending with 98 unclassified tangential points"). The tracer and the
 * checker take the points the glue identifies as one point of the surface
 * (src/pairing/pairing_glue.c, docs/tracing.md "Glued edges").
 *
 * The figure-8 Klein bottle of radius a,
 *   R(u, v) = ((a + cos(u/2) sin v - sin(u/2) sin 2v) cos u,
 *              (a + cos(u/2) sin v - sin(u/2) sin 2v) sin u,
 *              sin(u/2) sin v + cos(u/2) sin 2v),
 * has R(u + 2 pi, v) = R(u, -v) (cos and sin of u/2 change sign, and the
 * figure-8 (sin v, sin 2v) is odd). Its cross-section (sin v, sin 2v),
 * turned by u/2, meets itself only at v = 0 and v = pi, where it is the
 * origin: the double curve is the circle x^2 + y^2 = a^2, z = 0, of length
 * 2 pi a, with preimages (u, 0) and (u, pi); there is no other pair of
 * distinct preimages with one image (the figure-8 (sin v, sin 2v) is one-to-
 * one elsewhere, and the rotation by u/2 with the turn by u keeps points
 * of different u apart: |R| projected on the plane z = 0 has angle u).
 * Seven domains, v periodic, u cut at 0, 1, -2 or 0.5, v at 0, -pi, 0.5,
 * -1 or 1e-4: one or more curves of total length 2 pi a (TIER_LENGTH,
 * relative: the tracer's tol), no special point. An embedded torus with u
 * not marked periodic has no self-intersection at all.
 * Mutations: a curve dropped or doubled in the saved document is refused.
 */
#include <math.h>

#include "certify_harness.h"

static const double PI = 3.14159265358979323846;

typedef struct {
    double a;
    const char *u0, *v0; /* the domain's lower ends; each is 2 pi wide */
} klein_case;

static const klein_case CASES[] = {
    {3, "0", "0"}, {3, "1", "0"}, {3, "1", "0.5"}, {3, "-2", "-1"}, {2.5, "0.5", "0"},
    {4, "0", "0.0001"}, {3, "0", "-pi"},
};
#define NCASES (int)(sizeof CASES / sizeof CASES[0])

static void klein_problem(const klein_case *k, char *json, size_t size)
{
    snprintf(json, size,
             "{\"self\": true, \"surfaces\": [{\"type\": \"parametric\", \"xyz\": ["
             "\"(%.17g + cos(u/2)*sin(v) - sin(u/2)*sin(2*v))*cos(u)\","
             "\"(%.17g + cos(u/2)*sin(v) - sin(u/2)*sin(2*v))*sin(u)\","
             "\"sin(u/2)*sin(v) + cos(u/2)*sin(2*v)\"],"
             "\"domain\": [[\"%s\", \"%s + 2*pi\"], [\"%s\", \"%s + 2*pi\"]],"
             "\"periodic\": [false, true]}]}",
             k->a, k->a, k->u0, k->u0, k->v0, k->v0);
}

static int klein_right(const ic_trace_result *r, double a)
{
    double sum = 0;
    for (int c = 0; c < ic_trace_result_num_curves(r); c++)
        sum += ic_trace_result_curve(r, c)->length;
    const double want = 2 * PI * a;
    return ic_trace_result_num_specials(r) == 0 && fabs(sum - want) <= TIER_LENGTH * want;
}

/* The glue found on a sheet (its pairing's): axis, flip and c. */
static void check_glue(const char *name, const char *json, int axis, int flip, double c,
                       double period)
{
    ic_problem *pr = NULL;
    ic_pair *pair = NULL;
    ic_error err;
    if (REQUIRE(ic_problem_parse(&pr, json, strlen(json), &err) == IC_OK &&
                    ic_pair_new(&pair, ic_problem_surface(pr, 0), NULL, &err) == IC_OK,
                "%s: %s", name, err.message)) {
        const ic_pairing_glue *g = &ic_pair_pairing(pair)->glue;
        const double dc = period > 0 ? remainder(g->c - c, period) : g->c - c;
        CHECK(g->axis == axis && (axis < 0 || (g->flip == flip && fabs(dc) <= 1e-12)),
              "%s: glue axis %d flip %d c %.17g, want %d %d %.17g", name, g->axis, g->flip,
              g->c, axis, flip, c);
    }
    ic_pair_free(pair);
    ic_problem_free(pr);
}

static void glue_found(void)
{
    char json[1600];
    klein_problem(&CASES[1], json, sizeof json);
    /* R(1, w) = R(1 + 2 pi, -w): c = 0 modulo the period 2 pi */
    check_glue("Klein bottle", json, 0, 1, 0.0, 2 * PI);
    const char *torus =
        "{\"self\": true, \"surfaces\": [{\"type\": \"parametric\", \"xyz\": [\"(2 + "
        "0.5*cos(v))*cos(u)\", \"(2 + 0.5*cos(v))*sin(u)\", \"0.5*sin(v)\"], \"domain\": "
        "[[0.3, \"0.3 + 2*pi\"], [0, \"2*pi\"]], \"periodic\": [false, true]}]}";
    check_glue("torus, u not marked periodic", torus, 0, 0, 0.0, 2 * PI);
    /* u/2 off by 1e-7: the edges differ by about 1e-7, no glue */
    const char *near =
        "{\"self\": true, \"surfaces\": [{\"type\": \"parametric\", \"xyz\": ["
        "\"(3 + cos(u/2.0000001)*sin(v) - sin(u/2.0000001)*sin(2*v))*cos(u)\","
        "\"(3 + cos(u/2.0000001)*sin(v) - sin(u/2.0000001)*sin(2*v))*sin(u)\","
        "\"sin(u/2.0000001)*sin(v) + cos(u/2.0000001)*sin(2*v)\"],"
        "\"domain\": [[0, \"2*pi\"], [0, \"2*pi\"]], \"periodic\": [false, true]}]}";
    check_glue("Klein bottle a little off", near, -1, 0, 0.0, 0.0);
    /* the edges u = 0 and 2 pi are one line (1, 0, v), but the radius
     * 1 + 0.3 sin(u/4) sin(u/2) makes a crease there: the sheet does not
     * continue across, and the checker could not use the glue beside it */
    const char *crease =
        "{\"self\": true, \"surfaces\": [{\"type\": \"parametric\", \"xyz\": ["
        "\"(1 + 0.3*sin(u/4)*sin(u/2))*cos(u)\", \"(1 + 0.3*sin(u/4)*sin(u/2))*sin(u)\", "
        "\"v\"], \"domain\": [[0, \"2*pi\"], [-1, 1]]}]}";
    check_glue("a crease at the edges", crease, -1, 0, 0.0, 0.0);
    const char *patch =
        "{\"self\": true, \"surfaces\": [{\"type\": \"parametric\", \"xyz\": [\"u\", \"v\", "
        "\"u*v\"], \"domain\": [[-1, 1], [-1, 1]]}]}";
    check_glue("a saddle patch", patch, -1, 0, 0.0, 0.0);

    traced t;
    if (trace_json(&t, "torus, u not marked periodic", torus) == 0)
        CHECK(ic_trace_result_report(t.res)->complete && ic_trace_result_num_curves(t.res) == 0 &&
                  ic_trace_result_num_specials(t.res) == 0,
              "embedded torus: not proven empty (%d curves, %d points)",
              ic_trace_result_num_curves(t.res), ic_trace_result_num_specials(t.res));
    release(&t);
}

/* A cylinder over the closed curve g(u) = (u(1 - u), u(1 - u) q(u)),
 * q = t^3 - a^2 t with t = u - 1/2 and a = 1/2 - d, whose ends meet at
 * the origin at an angle: g(u) = g(1 - u) where q(u) = q(1 - u), and
 * q(u) - q(1 - u) = 2 t (t^2 - a^2) = 2 (u - 1/2)(u - d)(u - 1 + d), so a
 * transversal double line at x = d (1 - d), y = 0, of length 1, its
 * preimages u = d and 1 - d beside the edges (from a review: with the glue
 * taken from the edges alone, the checker proved it away). Marked periodic
 * it is refused (the surface does not continue across its ends); unmarked
 * it is not glued, and any complete answer holds the line. */
static void double_line_by_the_edges(void)
{
    const double d = 0.01;
    const char *marked =
        "{\"self\": true, \"surfaces\": [{\"type\": \"parametric\", \"xyz\": [\"u*(1-u)\", "
        "\"u*(1-u)*((u-0.5)^3 - 0.49^2*(u-0.5))\", \"v\"], \"domain\": [[0, 1], [0, 1]], "
        "\"periodic\": [true, false]}]}";
    ic_problem *pr = NULL;
    ic_error err;
    CHECK(ic_problem_parse(&pr, marked, strlen(marked), &err) == IC_ERR_INVALID &&
              strstr(err.message, "does not continue across"),
          "a tube whose ends meet at an angle, marked periodic: accepted (%s)", err.message);
    ic_problem_free(pr);
    const char *unmarked =
        "{\"self\": true, \"surfaces\": [{\"type\": \"parametric\", \"xyz\": [\"u*(1-u)\", "
        "\"u*(1-u)*((u-0.5)^3 - 0.49^2*(u-0.5))\", \"v\"], \"domain\": [[0, 1], [0, 1]]}]}";
    check_glue("a tube whose ends meet at an angle", unmarked, -1, 0, 0.0, 0.0);
    traced t;
    tally one = {0};
    if (trace_json(&t, "double line by the edges", unmarked) == 0) {
        int found = 0;
        for (int c = 0; c < ic_trace_result_num_curves(t.res); c++) {
            const ic_trace_curve *cv = ic_trace_result_curve(t.res, c);
            found |= fabs(cv->length - 1) <= TIER_LENGTH &&
                     fabs(cv->points[0].xyz[0] - d * (1 - d)) <= TIER_ON_CURVE &&
                     fabs(cv->points[0].xyz[1]) <= TIER_ON_CURVE;
        }
        judge(&one, &t, "double line by the edges", found);
        CHECK(found, "double line by the edges: the line at x = d (1 - d) not traced");
    }
    release(&t);
}

int main(void)
{
    glue_found();
    double_line_by_the_edges();
    tally t = {0};
    for (int i = 0; i < NCASES; i++) {
        char json[1600], name[120];
        klein_problem(&CASES[i], json, sizeof json);
        snprintf(name, sizeof name, "Klein bottle a = %g on [%s, ..] x [%s, ..]", CASES[i].a,
                 CASES[i].u0, CASES[i].v0);
        traced tr;
        if (trace_json_keep(&tr, name, json) == 0) {
            judge(&t, &tr, name, klein_right(tr.res, CASES[i].a));
            if (i == 0) /* a re-check grows the cover again: one case, for time */
                verify_saved(&tr, name);
        }
        release(&tr);
    }
    printf("Klein bottles: %d cases, %d proven, %d honestly incomplete, %d right\n", t.cases,
           t.proven, t.honest, t.right);
    /* as measured: all right, all proven but v cut at -pi, where the
     * tracer closes the circle across the glued edge and the checker finds
     * the loop ending inside the region (honestly incomplete); before the
     * glue none was proven, with 2 to 206 unclassified tangential points */
    CHECK(t.proven >= NCASES - 1 && t.right == NCASES, "%d of %d proven, %d right", t.proven,
          NCASES, t.right);
    return harness_finish("certificate_glued");
}
