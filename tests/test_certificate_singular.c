/*
 * The certificate beside singular points (issue 23, docs/tracing.md "The
 * certificate"): a singular point the result reports gets a singular box
 * of half width 1e-5 of the region's size; the cover proves everything
 * outside the boxes, and every branch into a box must be traced. Sweeps
 * (every case right and complete, or honestly incomplete; never complete
 * and wrong):
 *   - two unit cylinders crossing at six angles, implicit and with one as a
 *     parametric sheet: two ellipses through two branch points;
 *   - a sphere resting on a plane at six places and sizes, implicit and with
 *     the plane as a parametric patch: one isolated contact, no curve.
 * Mutations of a proven trace: a branch dropped, a singular point dropped
 * or moved off its place or added where a curve is smooth, a branch cut
 * short of its singular point: each refused.
 *
 * Truth: the ellipses' perimeters from tests/truth/
 * gen_certificate_singular_truth.py (mpmath, 40 digits, two ways) in
 * tests/truth/certificate_branch_cylinders.txt; the branch points (0, 0, +-1)
 * and the contact points in closed form (below).
 *
 * usage: test_certificate_singular SOURCE_DIR
 */
#include <math.h>

#include "certify_harness.h"

#define PI 3.14159265358979323846
#define NANGLES 6

typedef struct {
    double degrees[NANGLES], L1[NANGLES], L2[NANGLES];
} branch_truth;

static int read_truth(const char *src, branch_truth *t)
{
    double rows[NANGLES][3];
    if (read_truth_rows(src, "certificate_branch_cylinders.txt", 3, NANGLES, &rows[0][0]) != 0)
        return -1;
    for (int i = 0; i < NANGLES; i++)
        t->degrees[i] = rows[i][0], t->L1[i] = rows[i][1], t->L2[i] = rows[i][2];
    return 0;
}

/* Two branch points at (0, 0, +-1), each of two branches, within
 * TIER_LOCATED (they are located by Newton's method to a few ulps). */
static int branch_points_right(const ic_trace_result *r)
{
    if (ic_trace_result_num_specials(r) != 2)
        return 0;
    int seen[2] = {0, 0};
    for (int k = 0; k < 2; k++) {
        const ic_trace_special *s = ic_trace_result_special(r, k);
        const int top = s->xyz[2] > 0;
        seen[top] += s->type == IC_POINT_BRANCH && s->nbranches == 2 &&
                     fabs(s->xyz[0]) < TIER_LOCATED && fabs(s->xyz[1]) < TIER_LOCATED &&
                     fabs(s->xyz[2] - (top ? 1.0 : -1.0)) < TIER_LOCATED;
    }
    return seen[0] == 1 && seen[1] == 1;
}

/* The curves' lengths add up to the two perimeters (the tracer may cut an
 * ellipse at its branch points: the sum is what it must get), to
 * TIER_LENGTH. */
static int lengths_right(const ic_trace_result *r, double want)
{
    double sum = 0.0;
    for (int k = 0; k < ic_trace_result_num_curves(r); k++)
        sum += ic_trace_result_curve(r, k)->length;
    return harness_close(sum, want, TIER_LENGTH, 1);
}

/* Cylinder B: about (sin a, cos a, 0): |X|^2 - (X.d)^2 = 1. */
static void cylinder_b(double a, char *f, size_t size)
{
    snprintf(f, size, "x^2 + y^2 + z^2 - (%.17g*x + %.17g*y)^2 - 1", sin(a), cos(a));
}

static void sweep_branch_cylinders(const char *src)
{
    branch_truth truth;
    if (read_truth(src, &truth) != 0)
        return;
    tally implicit = {0}, mixed = {0};
    for (int i = 0; i < NANGLES; i++) {
        const double a = truth.degrees[i] * PI / 180.0;
        char fb[160], json[600], name[80];
        cylinder_b(a, fb, sizeof fb);
        for (int form = 0; form < 2; form++) {
            if (form == 0)
                snprintf(json, sizeof json,
                         "{\"surfaces\": [{\"type\": \"implicit\", \"f\": \"x^2 + z^2 - 1\"},"
                         "{\"type\": \"implicit\", \"f\": \"%s\"}],"
                         "\"box\": [[-3.5, 3.5], [-3.5, 3.5], [-1.5, 1.5]]}",
                         fb);
            else
                snprintf(json, sizeof json,
                         "{\"surfaces\": [{\"type\": \"parametric\", \"xyz\": [\"cos(u)\", \"v\", "
                         "\"sin(u)\"], \"domain\": [[0, 6.283185307179586], [-3.5, 3.5]], "
                         "\"periodic\": [true, false]},"
                         "{\"type\": \"implicit\", \"f\": \"%s\"}]}",
                         fb);
            snprintf(name, sizeof name, "branch cylinders at %g degrees, %s", truth.degrees[i],
                     form ? "parametric/implicit" : "implicit");
            traced t;
            if (trace_json(&t, name, json) == 0)
                judge(form ? &mixed : &implicit, &t, name,
                      branch_points_right(t.res) &&
                          lengths_right(t.res, truth.L1[i] + truth.L2[i]));
            release(&t);
        }
    }
    /* every right answer proven: the boxes and the cover around them hold */
    CHECK(implicit.missed == 0 && mixed.missed == 0 && implicit.right == NANGLES &&
              mixed.right == NANGLES,
          "branch cylinders: %d + %d right of %d each, %d + %d of them not proven",
          implicit.right, mixed.right, NANGLES, implicit.missed, mixed.missed);
}

/* A sphere of radius R on the plane through c normal to n (unit), touching
 * it at c: the centre c + R n. */
typedef struct {
    double c[3], n[3], R;
} contact_case;

static const contact_case CONTACTS[] = {
    {{0, 0, 0}, {0, 0, 1}, 1.0},
    {{0.3, -0.2, 0.1}, {0, 0, 1}, 0.5},
    {{0, 0, 0}, {0.6, 0, 0.8}, 2.0},
    {{0.1, 0.2, -0.3}, {0, 0.6, 0.8}, 0.25},
    {{-0.2, 0.1, 0.05}, {0.48, 0.6, 0.64}, 1.5},
    {{0.05, -0.1, 0.2}, {-0.36, 0.48, 0.8}, 0.75},
};
#define NCONTACTS (int)(sizeof CONTACTS / sizeof CONTACTS[0])

/* No curve, one isolated contact at c within TIER_LOCATED (relative to R). */
static int contact_right(const ic_trace_result *r, const contact_case *k)
{
    if (ic_trace_result_num_curves(r) != 0 || ic_trace_result_num_specials(r) != 1)
        return 0;
    const ic_trace_special *s = ic_trace_result_special(r, 0);
    double d = 0.0;
    for (int i = 0; i < 3; i++)
        d = fmax(d, fabs(s->xyz[i] - k->c[i]));
    return s->type == IC_POINT_ISOLATED_CONTACT && d < TIER_LOCATED * (1.0 + k->R);
}

/* Two unit vectors e1, e2 spanning the plane normal to n. */
static void plane_frame(const double n[3], double e1[3], double e2[3])
{
    const double a[3] = {fabs(n[0]) < 0.9 ? 1.0 : 0.0, fabs(n[0]) < 0.9 ? 0.0 : 1.0, 0.0};
    const double d = a[0] * n[0] + a[1] * n[1] + a[2] * n[2];
    double len = 0.0;
    for (int i = 0; i < 3; i++)
        e1[i] = a[i] - d * n[i], len += e1[i] * e1[i];
    for (int i = 0; i < 3; i++)
        e1[i] /= sqrt(len);
    e2[0] = n[1] * e1[2] - n[2] * e1[1];
    e2[1] = n[2] * e1[0] - n[0] * e1[2];
    e2[2] = n[0] * e1[1] - n[1] * e1[0];
}

static void sweep_contacts(void)
{
    tally implicit = {0}, mixed = {0};
    for (int i = 0; i < NCONTACTS; i++) {
        const contact_case *k = &CONTACTS[i];
        double o[3], e1[3], e2[3];
        for (int j = 0; j < 3; j++)
            o[j] = k->c[j] + k->R * k->n[j];
        plane_frame(k->n, e1, e2);
        char sphere[200], json[900], name[80];
        snprintf(sphere, sizeof sphere,
                 "(x - %.17g)^2 + (y - %.17g)^2 + (z - %.17g)^2 - %.17g", o[0], o[1], o[2],
                 k->R * k->R);
        for (int form = 0; form < 2; form++) {
            if (form == 0)
                snprintf(json, sizeof json,
                         "{\"surfaces\": [{\"type\": \"implicit\", \"f\": \"%s\"},"
                         "{\"type\": \"implicit\", \"f\": \"%.17g*x + %.17g*y + %.17g*z - "
                         "%.17g\"}], \"box\": [[-1, 1], [-1, 1], [-1, 1]]}",
                         sphere, k->n[0], k->n[1], k->n[2],
                         k->n[0] * k->c[0] + k->n[1] * k->c[1] + k->n[2] * k->c[2]);
            else
                snprintf(json, sizeof json,
                         "{\"surfaces\": [{\"type\": \"parametric\", \"params\": [\"s\", \"t\"], "
                         "\"xyz\": [\"%.17g + %.17g*s + %.17g*t\", \"%.17g + %.17g*s + %.17g*t\", "
                         "\"%.17g + %.17g*s + %.17g*t\"], \"domain\": [[-0.8, 0.9], [-0.7, 1]]},"
                         "{\"type\": \"implicit\", \"f\": \"%s\"}]}",
                         k->c[0], e1[0], e2[0], k->c[1], e1[1], e2[1], k->c[2], e1[2], e2[2],
                         sphere);
            snprintf(name, sizeof name, "contact %d, %s", i,
                     form ? "parametric/implicit" : "implicit");
            traced t;
            if (trace_json(&t, name, json) == 0)
                judge(form ? &mixed : &implicit, &t, name, contact_right(t.res, k));
            release(&t);
        }
    }
    CHECK(implicit.missed == 0 && mixed.missed == 0 && implicit.right == NCONTACTS &&
              mixed.right == NCONTACTS,
          "contacts: %d + %d right of %d each, %d + %d of them not proven", implicit.right,
          mixed.right, NCONTACTS, implicit.missed, mixed.missed);
}

static double dist_inf(const double *a, const double *b)
{
    return fmax(fabs(a[0] - b[0]), fmax(fabs(a[1] - b[1]), fabs(a[2] - b[2])));
}

/* The closed implicit curve cv (x, y, z points) as an open one from its
 * point nearest p round to that point again (n + 1 points, malloc'd), or
 * NULL when it passes no closer than 1e-6 to p. */
static double *opened_at(const ic_certify_curve *cv, const double p[3])
{
    int best = -1;
    double dbest = 1e-6;
    for (int i = 0; i < cv->npoints; i++) {
        const double d = dist_inf(cv->z + 3 * i, p);
        if (d < dbest)
            dbest = d, best = i;
    }
    if (!cv->closed || best < 0)
        return NULL;
    double *z = malloc(3 * (size_t)(cv->npoints + 1) * sizeof *z);
    for (int s = 0; z && s <= cv->npoints; s++)
        memcpy(z + 3 * s, cv->z + 3 * ((best + s) % cv->npoints), 3 * sizeof *z);
    return z;
}

/* Mutations of the proven perpendicular cylinders (two ellipses, two
 * branch points): the checker must refuse each. */
static void mutations(void)
{
    const char *json = "{\"surfaces\": [{\"type\": \"implicit\", \"f\": \"x^2 + y^2 - 1\"},"
                       "{\"type\": \"implicit\", \"f\": \"x^2 + z^2 - 1\"}],"
                       "\"box\": [[-1.5, 1.5], [-1.5, 1.5], [-1.5, 1.5]]}";
    traced t;
    if (trace_json(&t, "singular mutations", json) != 0) {
        release(&t);
        return;
    }
    const ic_trace_result *r = t.res;
    const int n = ic_trace_result_num_curves(r), ns = ic_trace_result_num_specials(r);
    ic_certify_curve cv[8];
    double sing[4][3];
    double *z = n <= 8 && ns == 2 ? search_curves(&t, ic_pair_pairing(t.pair), cv) : NULL;
    if (REQUIRE(z && ic_trace_result_report(r)->complete, "singular mutations: %d curves, %d "
                                                          "points, not proven",
                n, ns)) {
        for (int k = 0; k < ns; k++)
            memcpy(sing[k], ic_trace_result_special(r, k)->xyz, sizeof sing[k]);
        char why[240];
        ic_certify_claim claim = {
            .curves = cv, .ncurves = n, .singular = (const double(*)[3])sing, .nsingular = ns};
        CHECK(verdict_of(&t, &claim, 0, why) == 1, "the true trace is refused: %s", why);
        claim.ncurves = n - 1;
        CHECK(verdict_of(&t, &claim, 0, why) == 0 && strstr(why, "not traced"),
              "a branch dropped is not refused as untraced: '%s'", why);
        claim.ncurves = n, claim.nsingular = 1;
        CHECK(verdict_of(&t, &claim, 0, why) == 0 && strstr(why, "neither empty nor regular"),
              "a singular point dropped is not refused: '%s'", why);
        claim.nsingular = 2;
        sing[1][0] += 1e-3; /* 1e-3 off, 20 box half widths */
        CHECK(verdict_of(&t, &claim, 0, why) == 0 && strstr(why, "neither empty nor regular"),
              "a singular point moved off its place is not refused: '%s'", why);
        sing[1][0] -= 1e-3;
        /* a third singular point claimed where a curve is smooth (the
         * tracer's spurious approximate points): refused by the checker's
         * own proof that the curve is smooth through its box */
        const ic_trace_curve *c0 = ic_trace_result_curve(r, 0);
        memcpy(sing[2], c0->points[c0->npoints / 2].xyz, sizeof sing[2]);
        claim.nsingular = 3;
        CHECK(verdict_of(&t, &claim, 0, why) == 0 && strstr(why, "is none"),
              "a singular point claimed on a smooth arc is not refused: '%s'", why);
        claim.nsingular = 2;
        /* the first curve opened at the branch point it passes through
         * (the same curve: accepted), then cut 0.05 short of it */
        double *open = opened_at(&cv[0], sing[0]);
        if (REQUIRE(open, "singular mutations: curve 1 does not pass through a branch point")) {
            const ic_certify_curve keep = cv[0];
            cv[0] = (ic_certify_curve){open, keep.npoints + 1, 0, 0};
            CHECK(verdict_of(&t, &claim, 0, why) == 1,
                  "the first curve opened at its branch point is refused: %s", why);
            while (cv[0].npoints > 2 && dist_inf(open + 3 * (cv[0].npoints - 1), sing[0]) < 0.05)
                cv[0].npoints--; /* 0.05 short: well outside the box */
            CHECK(verdict_of(&t, &claim, 0, why) == 0 && strstr(why, "ends inside"),
                  "a branch cut short of its singular point is not refused: '%s'", why);
            cv[0] = keep;
        }
        free(open);
        printf("singular mutations: a branch dropped, a point dropped, moved or added on a "
               "smooth arc, a branch cut short: all refused\n");
    }
    free(z);
    release(&t);
}

int main(int argc, char **argv)
{
    const char *src = argc > 1 ? argv[1] : ".";
    sweep_branch_cylinders(src);
    sweep_contacts();
    mutations();
    return harness_finish("test_certificate_singular");
}
