/*
 * The certificate where J loses rank on the region's boundary (issue 23,
 * docs/tracing.md "The certificate"): the checker finds the sheets' poles
 * itself and boxes them, and boxes the points where a curve ends in a
 * corner or touches a face; cusps get a wider box. Sweeps (every case right
 * and complete, or honestly incomplete; never complete and wrong):
 *   - Viviani's curve through the poles of a parametric sphere, at six radii
 *     and turns of the cylinder, the cylinder implicit and parametric;
 *   - Viviani's curve touching the seam of a sphere about the y axis, three
 *     radii, the seam at u = +-pi or 0, periodic or a plain domain edge;
 *   - the cusp c u^3 = v^2 of z = c u^3 - v^2 and z = 0 on u in [-1, 1],
 *     v in [-sqrt c, sqrt c]: both branches end in corners of the domain,
 *     six values of c, the plane implicit and parametric;
 *   - the Whitney umbrella's self-intersection on six domains: the double
 *     curve from the pinch point, where its two preimages meet on the
 *     diagonal, of length min(a, b)^2.
 * Mutations of the proven Viviani trace (through both poles): the curve
 * dropped, and cut 0.05 short of a pole: each refused.
 *
 * Truth: Viviani's length 8 sqrt 2 a E(1/2) from tests/truth/
 * gen_certificate_boundary_truth.py (mpmath, 40 digits, two ways) in
 * tests/truth/certificate_viviani.txt; its double point (2a cos phi,
 * 2a sin phi, 0); the cusp's branches v = +-sqrt(c) u^(3/2), of length
 * (8 / 27c) ((1 + 9c/4)^(3/2) - 1) each (integral of sqrt(1 + 9c u / 4)).
 *
 * usage: test_certificate_boundary SOURCE_DIR
 */
#include <math.h>

#include "certify_harness.h"

#define PI 3.14159265358979323846
#define NRADII 6

typedef struct {
    double a[NRADII], L[NRADII];
} viviani_truth;

static int read_truth(const char *src, viviani_truth *t)
{
    double rows[NRADII][2];
    if (read_truth_rows(src, "certificate_viviani.txt", 2, NRADII, &rows[0][0]) != 0)
        return -1;
    for (int i = 0; i < NRADII; i++)
        t->a[i] = rows[i][0], t->L[i] = rows[i][1];
    return 0;
}

/* The curves' lengths add up to want, to TIER_LENGTH (the tracer may cut a
 * curve at its singular points: the sum is what it must get). */
static int total_length_right(const ic_trace_result *r, double want)
{
    double sum = 0.0;
    for (int k = 0; k < ic_trace_result_num_curves(r); k++)
        sum += ic_trace_result_curve(r, k)->length;
    return harness_close(sum, want, TIER_LENGTH, 1);
}

/* One singular point of the type, at p within TIER_LOCATED of `scale`. */
static int one_point_at(const ic_trace_result *r, ic_point_type type, const double p[3],
                        double scale)
{
    if (ic_trace_result_num_specials(r) != 1)
        return 0;
    const ic_trace_special *s = ic_trace_result_special(r, 0);
    double d = 0.0;
    for (int i = 0; i < 3; i++)
        d = fmax(d, fabs(s->xyz[i] - p[i]));
    return s->type == type && d < TIER_LOCATED * scale;
}

/* The sphere |X| = 2a about the z axis, poles at v = +-pi/2. */
static void pole_sphere(double a, char *out, size_t size)
{
    snprintf(out, size,
             "{\"type\": \"parametric\", \"xyz\": [\"%.17g*cos(v)*cos(u)\", "
             "\"%.17g*cos(v)*sin(u)\", \"%.17g*sin(v)\"], \"domain\": [[-3.141592653589793, "
             "3.141592653589793], [-1.5707963267948966, 1.5707963267948966]], "
             "\"periodic\": [true, false]}",
             2 * a, 2 * a, 2 * a);
}

static void sweep_poles(const char *src)
{
    viviani_truth truth;
    if (read_truth(src, &truth) != 0)
        return;
    tally mixed = {0}, params = {0};
    for (int i = 0; i < NRADII; i++) {
        const double a = truth.a[i], phi = (50.0 * i + 10.0) * PI / 180.0;
        const double cx = a * cos(phi), cy = a * sin(phi);
        const double dp[3] = {2 * cx, 2 * cy, 0.0};
        char sphere[400], cyl[400], json[1000], name[80];
        pole_sphere(a, sphere, sizeof sphere);
        for (int form = 0; form < 2; form++) {
            if (form == 0)
                snprintf(cyl, sizeof cyl,
                         "{\"type\": \"implicit\", \"f\": \"(x - %.17g)^2 + (y - %.17g)^2 - "
                         "%.17g\"}",
                         cx, cy, a * a);
            else
                snprintf(cyl, sizeof cyl,
                         "{\"type\": \"parametric\", \"params\": [\"s\", \"t\"], \"xyz\": "
                         "[\"%.17g + %.17g*cos(s)\", \"%.17g + %.17g*sin(s)\", \"t\"], "
                         "\"domain\": [[0, 6.283185307179586], [%.17g, %.17g]], "
                         "\"periodic\": [true, false]}",
                         cx, a, cy, a, -2.5 * a, 2.5 * a);
            snprintf(json, sizeof json, "{\"surfaces\": [%s, %s]}", sphere, cyl);
            snprintf(name, sizeof name, "Viviani through the poles, a = %g, phi = %.0f, %s", a,
                     phi * 180.0 / PI, form ? "parametric" : "parametric/implicit");
            traced t;
            if (trace_json(&t, name, json) == 0)
                judge(form ? &params : &mixed, &t, name,
                      total_length_right(t.res, truth.L[i]) &&
                          one_point_at(t.res, IC_POINT_BRANCH, dp, 2 * a));
            release(&t);
        }
    }
    CHECK(mixed.missed == 0 && params.missed == 0 && mixed.right == NRADII &&
              params.right == NRADII,
          "Viviani through the poles: %d + %d right of %d each, %d + %d of them not proven",
          mixed.right, params.right, NRADII, mixed.missed, params.missed);
}

static void sweep_seam_touch(const char *src)
{
    viviani_truth truth;
    if (read_truth(src, &truth) != 0)
        return;
    tally all = {0};
    for (int i = 0; i < 3; i++)
        for (int seam = 0; seam < 2; seam++)
            for (int periodic = 0; periodic < 2; periodic++) {
                const int row = 2 * i; /* a = 0.5, 1, 1.5 */
                const double a = truth.a[row], lo = seam ? 0.0 : -PI;
                char json[1000], name[100];
                snprintf(json, sizeof json,
                         "{\"surfaces\": [{\"type\": \"parametric\", \"xyz\": "
                         "[\"%.17g*cos(v)*sin(u)\", \"%.17g*sin(v)\", \"%.17g*cos(v)*cos(u)\"], "
                         "\"domain\": [[%.17g, %.17g], [-1.5707963267948966, "
                         "1.5707963267948966]], \"periodic\": [%s, false]},"
                         "{\"type\": \"implicit\", \"f\": \"(x - %.17g)^2 + y^2 - %.17g\"}]}",
                         2 * a, 2 * a, 2 * a, lo, lo + 2 * PI, periodic ? "true" : "false", a,
                         a * a);
                snprintf(name, sizeof name, "Viviani touching the seam at u = %s, a = %g, %s",
                         seam ? "0" : "+-pi", a, periodic ? "periodic" : "a domain edge");
                const double dp[3] = {2 * a, 0.0, 0.0};
                traced t;
                if (trace_json(&t, name, json) == 0)
                    judge(&all, &t, name,
                          total_length_right(t.res, truth.L[row]) &&
                              one_point_at(t.res, IC_POINT_BRANCH, dp, 2 * a));
                release(&t);
            }
    CHECK(all.missed == 0 && all.right == 12,
          "Viviani touching the seam: %d right of 12, %d of them not proven", all.right,
          all.missed);
}

static void sweep_cusp_corners(void)
{
    static const double C[] = {1.0, 0.5, 2.0, 3.0, 0.25, 1.5};
    tally mixed = {0}, params = {0};
    for (int i = 0; i < 6; i++) {
        const double c = C[i], b = sqrt(c);
        const double L = 2.0 * 8.0 / (27.0 * c) * (pow(1.0 + 2.25 * c, 1.5) - 1.0);
        char sheet[300], plane[300], json[800], name[80];
        snprintf(sheet, sizeof sheet,
                 "{\"type\": \"parametric\", \"xyz\": [\"u\", \"v\", \"%.17g*u^3 - v^2\"], "
                 "\"domain\": [[-1, 1], [%.17g, %.17g]]}",
                 c, -b, b);
        for (int form = 0; form < 2; form++) {
            snprintf(plane, sizeof plane, "%s",
                     form ? "{\"type\": \"parametric\", \"params\": [\"s\", \"t\"], \"xyz\": "
                            "[\"s\", \"t\", \"0\"], \"domain\": [[-1.5, 1.5], [-2, 2]]}"
                          : "{\"type\": \"implicit\", \"f\": \"z\"}");
            snprintf(json, sizeof json, "{\"surfaces\": [%s, %s]}", sheet, plane);
            snprintf(name, sizeof name, "cusp into the corners, c = %g, %s", c,
                     form ? "parametric" : "parametric/implicit");
            const double origin[3] = {0, 0, 0};
            traced t;
            if (trace_json(&t, name, json) == 0)
                judge(form ? &params : &mixed, &t, name,
                      total_length_right(t.res, L) &&
                          one_point_at(t.res, IC_POINT_CUSP, origin, 1.0));
            release(&t);
        }
    }
    CHECK(mixed.missed == 0 && params.missed == 0 && mixed.right == 6 && params.right == 6,
          "cusps into the corners: %d + %d right of 6 each, %d + %d of them not proven",
          mixed.right, params.right, mixed.missed, params.missed);
}

/* Whitney umbrellas (u v, v, u^2) on u in [-a, b], v in [-c, d]: the
 * double curve x = y = 0, z = u^2 from the pinch point (its preimages
 * (u, 0) and (-u, 0) meet on the diagonal there) to z = min(a, b)^2, that
 * long; the pinch point's box holds the cells beside the diagonal. */
static void sweep_pinch(void)
{
    static const double D[][4] = {{1.2, 1.5, 0.7, 1.1}, {1.0, 0.8, 0.9, 0.6},
                                  {0.5, 0.9, 1.3, 0.4}, {1.7, 1.1, 0.6, 0.8},
                                  {0.9, 0.6, 0.5, 1.2}, {1.4, 1.3, 1.0, 0.7}};
    tally all = {0};
    for (int i = 0; i < 6; i++) {
        const double *d = D[i], m = fmin(d[0], d[1]);
        char json[600], name[80];
        snprintf(json, sizeof json,
                 "{\"surfaces\": [{\"type\": \"parametric\", \"xyz\": [\"u*v\", \"v\", "
                 "\"u^2\"], \"domain\": [[%.17g, %.17g], [%.17g, %.17g]]}], \"self\": true}",
                 -d[0], d[1], -d[2], d[3]);
        snprintf(name, sizeof name, "Whitney umbrella on [-%g, %g] x [-%g, %g]", d[0], d[1],
                 d[2], d[3]);
        traced t;
        if (trace_json(&t, name, json) == 0)
            judge(&all, &t, name, total_length_right(t.res, m * m));
        release(&t);
    }
    CHECK(all.missed == 0 && all.right == 6,
          "Whitney umbrellas: %d right of 6, %d of them not proven", all.right, all.missed);
}

/* Curve 0 of t with the points within r of p (xyz) taken out: the open
 * curve from the first point after them round to the last before (search
 * coordinates, malloc'd: *n points), or NULL when none lies that close. */
static double *cut_around(const traced *t, const ic_certify_curve *cv, const double p[3],
                          double r, int *n)
{
    const ic_trace_curve *c = ic_trace_result_curve(t->res, 0);
    const int dim = ic_pair_pairing(t->pair)->kind->dim, np = c->npoints;
    int first_out = -1, any_in = 0;
    for (int i = 0; i < np; i++) {
        const double *x = c->points[i].xyz;
        const int in = fmax(fabs(x[0] - p[0]), fmax(fabs(x[1] - p[1]), fabs(x[2] - p[2]))) < r;
        any_in |= in;
        if (in && first_out < 0)
            first_out = -2; /* a point inside seen: the next outside one starts */
        else if (!in && first_out == -2)
            first_out = i;
    }
    if (!any_in || first_out < 0)
        return NULL;
    double *z = malloc((size_t)np * (size_t)dim * sizeof *z);
    *n = 0;
    for (int s = 0; z && s < np; s++) {
        const int i = (first_out + s) % np;
        const double *x = c->points[i].xyz;
        if (fmax(fabs(x[0] - p[0]), fmax(fabs(x[1] - p[1]), fabs(x[2] - p[2]))) < r)
            break;
        memcpy(z + (size_t)(*n)++ * (size_t)dim, cv->z + (size_t)i * (size_t)dim,
               (size_t)dim * sizeof *z);
    }
    return z;
}

/* Mutations of the proven Viviani trace through both poles (a = 1, the
 * cylinder implicit): the checker must refuse each, and find the poles. */
static void mutations(void)
{
    char sphere[400], json[900];
    pole_sphere(1.0, sphere, sizeof sphere);
    snprintf(json, sizeof json,
             "{\"surfaces\": [%s, {\"type\": \"implicit\", \"f\": \"(x - "
             "0.98480775301220802)^2 + (y - 0.17364817766693033)^2 - 1\"}]}",
             sphere);
    traced t;
    if (trace_json(&t, "pole mutations", json) != 0) {
        release(&t);
        return;
    }
    const ic_trace_result *r = t.res;
    const int n = ic_trace_result_num_curves(r), ns = ic_trace_result_num_specials(r);
    ic_certify_curve cv[4];
    double sing[4][3];
    double *z = n == 1 && ns == 1 ? search_curves(&t, ic_pair_pairing(t.pair), cv) : NULL;
    if (REQUIRE(z && cv[0].closed && ic_trace_result_report(r)->complete &&
                    ic_trace_result_report(r)->certificate.poles == 2,
                "pole mutations: %d curves, %d points, %d poles, not proven", n, ns,
                ic_trace_result_report(r)->certificate.poles)) {
        memcpy(sing[0], ic_trace_result_special(r, 0)->xyz, sizeof sing[0]);
        char why[240];
        ic_certify_claim claim = {
            .curves = cv, .ncurves = 1, .singular = (const double(*)[3])sing, .nsingular = 1};
        CHECK(verdict_of(&t, &claim, 0, why) == 1, "the true trace is refused: %s", why);
        claim.ncurves = 0;
        CHECK(verdict_of(&t, &claim, 0, why) == 0 && strstr(why, "not traced"),
              "the curve dropped is not refused as untraced: '%s'", why);
        claim.ncurves = 1;
        /* the curve cut 0.05 short of the north pole, well outside its box */
        const double pole[3] = {0, 0, 2};
        int m = 0;
        double *cut = cut_around(&t, &cv[0], pole, 0.05, &m);
        if (REQUIRE(cut && m > 2, "pole mutations: the curve does not pass the pole")) {
            const ic_certify_curve keep = cv[0];
            cv[0] = (ic_certify_curve){cut, m, 0, 0};
            CHECK(verdict_of(&t, &claim, 0, why) == 0 &&
                      (strstr(why, "ends inside") || strstr(why, "starts inside")),
                  "the curve cut short of a pole is not refused: '%s'", why);
            cv[0] = keep;
        }
        free(cut);
        printf("pole mutations: the curve dropped, cut short of a pole: refused\n");
    }
    free(z);
    release(&t);
}

/* The public re-check (ic_problem_verify, ic_problem_verify_json): a
 * proven trace's document through the pole accepted again, the same
 * document with its curve taken out refused. */
static void public_verify(void)
{
    char sphere[400], json[900];
    pole_sphere(1.0, sphere, sizeof sphere);
    snprintf(json, sizeof json,
             "{\"surfaces\": [%s, {\"type\": \"implicit\", \"f\": \"(x - 1)^2 + y^2 - 1\"}]}",
             sphere);
    traced t;
    char *doc = NULL, *out = NULL;
    size_t len = 0;
    ic_error err;
    if (trace_json(&t, "public verify", json) == 0 &&
        REQUIRE(ic_trace_json_alloc(&doc, &len, t.res, t.pair, &err) == IC_OK, "%s",
                err.message)) {
        ic_trace_certificate c;
        CHECK(ic_problem_verify(t.problem, doc, &c, &err) == IC_OK && c.checked && c.accepted &&
                  c.poles == 2,
              "the proven trace through the poles is not accepted again: %s", c.reason);
        size_t out_len = 0;
        CHECK(ic_problem_verify_json(&out, &out_len, t.problem, doc, &err) == IC_OK && out &&
                  strstr(out, "\"accepted\":\ttrue") && strstr(out, "\"poles\":\t2"),
              "ic_problem_verify_json: %s", out ? out : err.message);
        /* the document's own keys, one tab in (a curve has points too) */
        char *curves = strstr(doc, "\"curves\":"), *points = strstr(doc, "\n\t\"points\":");
        if (REQUIRE(curves && points && points > curves, "no curves in the trace document")) {
            /* "curves": [] followed by the rest of the document */
            const size_t head = (size_t)(curves - doc);
            char *cut = malloc(len + 16);
            if (cut) {
                memcpy(cut, doc, head);
                snprintf(cut + head, len + 16 - head, "\"curves\": [], %s", points);
                const ic_status st = ic_problem_verify(t.problem, cut, &c, &err);
                CHECK(st == IC_OK && c.checked && !c.accepted && strstr(c.reason, "not traced"),
                      "the document without its curve is not refused: %s",
                      st == IC_OK ? c.reason : err.message);
                free(cut);
            }
        }
    }
    ic_free(out);
    ic_free(doc);
    release(&t);
}

int main(int argc, char **argv)
{
    const char *src = argc > 1 ? argv[1] : ".";
    sweep_poles(src);
    sweep_seam_touch(src);
    sweep_cusp_corners();
    sweep_pinch();
    mutations();
    public_verify();
    return harness_finish("test_certificate_boundary");
}
