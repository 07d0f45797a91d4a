/*
 * The certificate (issue 23, docs/tracing.md "The certificate"): complete is
 * the independent checker's verdict. Sweeps of the classes the issue names
 * where the certificate can speak today (transversal curves clipped by a
 * box or a domain edge, loops across a seam, tiny features far from the
 * origin): every case is right and complete, or honestly incomplete; never
 * complete and wrong. And mutations: the checker, given a true trace with a
 * curve dropped, doubled or cut short, or a cover with a crossing taken
 * away, or two arcs swapped inside one cell, refuses.
 *
 * Truth: the box-clipped circle's arcs in closed form (below); the seam
 * loops' lengths from tests/truth/gen_certificate_truth.py (mpmath, 40
 * digits) in tests/truth/certificate_seam_loops.txt.
 *
 * usage: test_certificate SOURCE_DIR
 */
#include <math.h>

#include "certify_harness.h"

#define PI 3.14159265358979323846

/* Every curve open (or closed: want_closed), of length want each within
 * TIER_LENGTH, n of them. */
static int curves_right(const ic_trace_result *r, int n, double want, int want_closed)
{
    if (ic_trace_result_num_curves(r) != n)
        return 0;
    for (int k = 0; k < n; k++) {
        const ic_trace_curve *c = ic_trace_result_curve(r, k);
        if (c->closed != want_closed || !harness_close(c->length, want, TIER_LENGTH, 1))
            return 0;
    }
    return 1;
}

static const double CLIP[] = {0.9, 0.99, 0.9999, 0.99999, 0.999999, 0.9999999};
#define NCLIP (int)(sizeof CLIP / sizeof CLIP[0])

/* The unit circle z = 0 cut by |x| <= b, |y| <= b: the four caps about the
 * axes, |theta - k pi/2| < acos b, go; four arcs of length pi/2 - 2 acos b
 * remain. First the sphere and the plane as implicit surfaces in the box
 * [-b, b]^2 x [-1/2, 1/2]; then the plane as a parametric patch over the
 * domain [-b, b]^2 against the implicit sphere (the domain's edges cut);
 * then that patch against the sphere's parametric net (two sheets); then
 * the sphere's net against the implicit plane in the box (the box cuts the
 * sheet). */
static void sweep_clipped_circle(void)
{
    tally box = {0}, domain = {0}, sheets = {0}, net_box = {0};
    for (int i = 0; i < NCLIP; i++) {
        const double b = CLIP[i], arc = PI / 2 - 2 * acos(b);
        char json[1024], name[80];
        snprintf(json, sizeof json,
                 "{\"surfaces\": [{\"type\": \"implicit\", \"f\": \"x^2+y^2+z^2-1\"},"
                 "{\"type\": \"implicit\", \"f\": \"z\"}],"
                 "\"box\": [[%.17g, %.17g], [%.17g, %.17g], [-0.5, 0.5]]}",
                 -b, b, -b, b);
        snprintf(name, sizeof name, "circle in the box b = %.7f", b);
        traced t;
        if (trace_json(&t, name, json) == 0)
            judge(&box, &t, name, curves_right(t.res, 4, arc, 0));
        release(&t);
        snprintf(json, sizeof json,
                 "{\"surfaces\": [{\"type\": \"parametric\", \"xyz\": [\"u\", \"v\", \"0\"],"
                 "\"domain\": [[%.17g, %.17g], [%.17g, %.17g]]},"
                 "{\"type\": \"implicit\", \"f\": \"x^2+y^2+z^2-1\"}]}",
                 -b, b, -b, b);
        snprintf(name, sizeof name, "circle on the patch b = %.7f", b);
        if (trace_json(&t, name, json) == 0)
            judge(&domain, &t, name, curves_right(t.res, 4, arc, 0));
        release(&t);
        snprintf(json, sizeof json,
                 "{\"surfaces\": [{\"type\": \"sphere\", \"radius\": 1, \"form\": "
                 "\"parametric\"}, {\"type\": \"parametric\", \"xyz\": [\"u\", \"v\", \"0\"],"
                 "\"domain\": [[%.17g, %.17g], [%.17g, %.17g]]}]}",
                 -b, b, -b, b);
        snprintf(name, sizeof name, "circle on the patch and the sphere's net b = %.7f", b);
        if (trace_json(&t, name, json) == 0)
            judge(&sheets, &t, name, curves_right(t.res, 4, arc, 0));
        release(&t);
        snprintf(json, sizeof json,
                 "{\"surfaces\": [{\"type\": \"sphere\", \"radius\": 1, \"form\": "
                 "\"parametric\"}, {\"type\": \"implicit\", \"f\": \"z\"}],"
                 "\"box\": [[%.17g, %.17g], [%.17g, %.17g], [-0.5, 0.5]]}",
                 -b, b, -b, b);
        snprintf(name, sizeof name, "circle on the sphere's net in the box b = %.7f", b);
        if (trace_json(&t, name, json) == 0)
            judge(&net_box, &t, name, curves_right(t.res, 4, arc, 0));
        release(&t);
    }
    /* Where the tracer is wrong (two arcs joined across a cap outside the
     * box, the whole circle) the certificate refuses (judge); where it is
     * right the certificate proves it: a refusal would be honest, but then
     * it would say nothing on the class it was made for. */
    printf("clipped circles: the tracer right on %d and %d of %d, proven %d and %d\n",
           box.right, domain.right, NCLIP, box.proven, domain.proven);
    CHECK(box.missed == 0 && domain.missed == 0,
          "clipped circles: %d and %d right answers not proven", box.missed, domain.missed);
    /* and the tracer is right on all: a step that leaves the box or the
     * domain between two points inside ends there (march.c, the excursion
     * test), and ends that left a domain edge where nothing degenerates are
     * not joined across the cap outside (join.c) */
    CHECK(box.right == NCLIP && domain.right == NCLIP && sheets.right == NCLIP,
          "clipped circles: the tracer right on %d, %d and %d of %d", box.right, domain.right,
          sheets.right, NCLIP);
    /* two sheets: the sphere's net wraps at the arcs' ends, where a gap's
     * hull must be taken the short way round (pairing.c) */
    CHECK(sheets.missed == 0, "clipped circles on two sheets: %d right answers not proven",
          sheets.missed);
    /* a sheet across the box: the arcs' ends on it are roots of (F, R_k - b)
     * isolated in the cells the box cuts (boxcross.c) */
    CHECK(net_box.right == NCLIP && net_box.missed == 0,
          "clipped circles on the sphere's net in the box: %d right of %d, %d not proven",
          net_box.right, NCLIP, net_box.missed);
}

/* The seam loops' lengths (gen_certificate_truth.py). */
static int read_seam_truth(const char *src, double r[6], double L[6])
{
    char path[1024], line[256];
    snprintf(path, sizeof path, "%s/tests/truth/certificate_seam_loops.txt", src);
    FILE *f = fopen(path, "r");
    if (!REQUIRE(f, "cannot read %s", path))
        return 0;
    int n = 0;
    while (n < 6 && fgets(line, sizeof line, f))
        if (line[0] != '#' && sscanf(line, "%lf %lf", &r[n], &L[n]) == 2)
            n++;
    fclose(f);
    return REQUIRE(n == 6, "%s: %d of 6 radii", path, n);
}

/* The curves' lengths add up to want (TIER_LENGTH), in at most n curves. */
static int total_right(const ic_trace_result *r, int n, double want)
{
    double sum = 0.0;
    for (int k = 0; k < ic_trace_result_num_curves(r); k++)
        sum += ic_trace_result_curve(r, k)->length;
    const int m = ic_trace_result_num_curves(r);
    return m >= 1 && m <= n && harness_close(sum, want, TIER_LENGTH, 1);
}

/* A sphere of radius r about (1, 0, 0) and the unit cylinder, its u domain
 * [0, 2 pi] periodic or not: one loop across the seam u = 0, all of it
 * (the class lost half of it where the domain is not periodic): one
 * closed curve, or on a domain not marked periodic one or two curves ending
 * at the domain's edges, of the loop's length together. */
static void sweep_seam_loops(const char *src)
{
    double r[6], L[6];
    if (!read_seam_truth(src, r, L))
        return;
    tally open = {0}, closed = {0};
    for (int i = 0; i < 6; i++)
        for (int periodic = 0; periodic < 2; periodic++) {
            char json[1024], name[80];
            snprintf(json, sizeof json,
                     "{\"surfaces\": [{\"type\": \"parametric\","
                     "\"xyz\": [\"cos(u)\", \"sin(u)\", \"v\"],"
                     "\"domain\": [[0, \"2*pi\"], [-2, 2]], \"periodic\": [%s, false]},"
                     "{\"type\": \"implicit\", \"f\": \"(x-1)^2+y^2+z^2-%.17g\"}]}",
                     periodic ? "true" : "false", r[i] * r[i]);
            snprintf(name, sizeof name, "seam loop r = %.1f, %s", r[i],
                     periodic ? "periodic" : "not periodic");
            traced t;
            if (trace_json(&t, name, json) == 0)
                judge(periodic ? &closed : &open, &t, name,
                      periodic ? curves_right(t.res, 1, L[i], 1) : total_right(t.res, 2, L[i]));
            release(&t);
        }
    CHECK(open.proven == 6 && closed.proven == 6 && open.missed == 0 && closed.missed == 0,
          "seam loops: %d and %d of 6 proven", open.proven, closed.proven);
}

/* Tiny features far out: two placed cylinders of radii rho and 0.7 rho
 * about perpendicular axes through (s, s, s): two loops, each of length
 * rho TINY_LOOP_UNIT (tests/truth/gen_certificate_tiny_far_truth.py, by
 * mpmath quadrature), to TIER_LENGTH. A length that is not a finite number
 * is never complete. The problem is traced moved to (s, s, s) where s is
 * more than 64 times the box ("Far from the origin" in docs/tracing.md):
 * a feature 1e11 times smaller than its place keeps its digits. */
#define TINY_LOOP_UNIT 4.576228150201309645645984
static void sweep_tiny_far(void)
{
    static const double SCALE[][2] = {{1e-4, 1000}, {1e-4, 1e4},  {1e-3, 1e5},
                                      {1e-2, 1e6},  {1e-5, 10},   {1e-4, -1000},
                                      {1e-5, 1e6},  {1e-6, 1e5},  {1e-4, -3e7}};
    const int n = (int)(sizeof SCALE / sizeof SCALE[0]);
    tally t6 = {0};
    for (int i = 0; i < n; i++) {
        const double rho = SCALE[i][0], s = SCALE[i][1];
        char json[1024], name[80];
        snprintf(json, sizeof json,
                 "{\"surfaces\": [{\"type\": \"cylinder\", \"center\": [%.17g, %.17g, %.17g],"
                 "\"axis\": [0, 0, 1], \"radius\": %.17g},"
                 "{\"type\": \"cylinder\", \"center\": [%.17g, %.17g, %.17g],"
                 "\"axis\": [1, 0, 0], \"radius\": %.17g}],"
                 "\"box\": [[%.17g, %.17g], [%.17g, %.17g], [%.17g, %.17g]]}",
                 s, s, s, rho, s, s, s, 0.7 * rho, s - 2 * rho, s + 2 * rho, s - 2 * rho,
                 s + 2 * rho, s - 2 * rho, s + 2 * rho);
        snprintf(name, sizeof name, "cylinders of radius %g at %g", rho, s);
        traced t;
        if (trace_json(&t, name, json) == 0) {
            int finite = 1;
            for (int k = 0; k < ic_trace_result_num_curves(t.res); k++)
                finite = finite && isfinite(ic_trace_result_curve(t.res, k)->length);
            CHECK(finite || !ic_trace_result_report(t.res)->complete,
                  "%s: complete with a length that is not finite", name);
            int right = finite && ic_trace_result_num_curves(t.res) == 2;
            for (int k = 0; right && k < 2; k++) {
                const ic_trace_curve *cv = ic_trace_result_curve(t.res, k);
                right = cv->closed && fabs(cv->length - rho * TINY_LOOP_UNIT) <=
                                          TIER_LENGTH * rho * TINY_LOOP_UNIT;
            }
            judge(&t6, &t, name, right);
        }
        release(&t);
    }
    CHECK(t6.proven == n, "tiny far cylinders: %d of %d proven", t6.proven, n);
}

/* The checker's verdict on the cover of t's region and the curves cv (no
 * singular points). */
static int verdict(const traced *t, const ic_certify_curve *cv, int n, int drop_crossing,
                   char *reason)
{
    const ic_certify_claim claim = {.curves = cv, .ncurves = n};
    return verdict_of(t, &claim, drop_crossing, reason);
}

/* Mutations of a proven trace: the circle in the box b = 0.99 (four arcs). */
static void mutations(void)
{
    const char *json = "{\"surfaces\": [{\"type\": \"implicit\", \"f\": \"x^2+y^2+z^2-1\"},"
                       "{\"type\": \"implicit\", \"f\": \"z\"}],"
                       "\"box\": [[-0.99, 0.99], [-0.99, 0.99], [-0.5, 0.5]]}";
    traced t;
    if (trace_json(&t, "mutations", json) != 0) {
        release(&t);
        return;
    }
    const int n = ic_trace_result_num_curves(t.res);
    ic_certify_curve cv[8];
    double *z = n == 4 ? search_curves(&t, ic_pair_pairing(t.pair), cv) : NULL;
    if (REQUIRE(z, "mutations: %d curves (want 4)", n)) {
        char why[240];
        CHECK(verdict(&t, cv, 4, 0, why) == 1, "the true trace is refused: %s", why);
        CHECK(verdict(&t, cv, 3, 0, why) == 0 && strstr(why, "not traced"),
              "a curve dropped is not refused as untraced: '%s'", why);
        cv[4] = cv[0];
        CHECK(verdict(&t, cv, 5, 0, why) == 0 && strstr(why, "more than once"),
              "a curve doubled is not refused: '%s'", why);
        ic_certify_curve cut[4] = {cv[0], cv[1], cv[2], cv[3]};
        cut[2].npoints = cut[2].npoints * 2 / 3;
        CHECK(verdict(&t, cut, 4, 0, why) == 0 && strstr(why, "ends inside"),
              "a curve cut short is not refused: '%s'", why);
        CHECK(verdict(&t, cv, 4, 1, why) == 0,
              "a cover with a crossing taken away accepts the trace");
        printf("mutations: dropped, doubled, cut short and a crossing less all refused\n");
    }
    free(z);
    release(&t);
}

/* Mutations where the box cuts a sheet: the sphere's net against z = 0 in
 * the box b = 0.99 (four arcs ending on the box, inside cells it cuts). */
static void box_mutations(void)
{
    const char *json = "{\"surfaces\": [{\"type\": \"sphere\", \"radius\": 1, \"form\": "
                       "\"parametric\"}, {\"type\": \"implicit\", \"f\": \"z\"}],"
                       "\"box\": [[-0.99, 0.99], [-0.99, 0.99], [-0.5, 0.5]]}";
    traced t;
    if (trace_json(&t, "box mutations", json) != 0) {
        release(&t);
        return;
    }
    const int n = ic_trace_result_num_curves(t.res);
    ic_certify_curve cv[8];
    double *z = n == 4 ? search_curves(&t, ic_pair_pairing(t.pair), cv) : NULL;
    if (REQUIRE(z, "box mutations: %d curves (want 4)", n)) {
        char why[240];
        CHECK(verdict(&t, cv, 4, 0, why) == 1, "the true trace is refused: %s", why);
        CHECK(verdict(&t, cv, 3, 0, why) == 0 && strstr(why, "not traced"),
              "an arc ending on the box dropped is not refused as untraced: '%s'", why);
        ic_certify_curve cut[4] = {cv[0], cv[1], cv[2], cv[3]};
        cut[1].npoints -= 3; /* short of the box by three points */
        CHECK(verdict(&t, cut, 4, 0, why) == 0 && strstr(why, "ends inside"),
              "an arc cut short of the box is not refused: '%s'", why);
        cut[1] = cv[1];
        cut[1].z += 3 * (size_t)ic_pair_pairing(t.pair)->kind->dim; /* three points late */
        cut[1].npoints -= 3;
        CHECK(verdict(&t, cut, 4, 0, why) == 0 && strstr(why, "starts inside"),
              "an arc starting short of the box is not refused: '%s'", why);
        printf("box mutations: an arc dropped, cut short at either end: all refused\n");
    }
    free(z);
    release(&t);
}

/* The point of arc cv nearest to (x, y): its index, and *d the distance. */
static int nearest(const ic_certify_curve *cv, double x, double y, double *d)
{
    int best = 0;
    *d = INFINITY;
    for (int i = 0; i < cv->npoints; i++) {
        const double e = hypot(cv->z[3 * i] - x, cv->z[3 * i + 1] - y);
        if (e < *d)
            *d = e, best = i;
    }
    return best;
}

/* Arc cv as an array of points in search coordinates (3 each), reversed
 * when `flip`: a copy to free. */
static double *oriented(const ic_certify_curve *cv, int flip)
{
    double *z = malloc((size_t)cv->npoints * 3 * sizeof *z);
    for (int i = 0; z && i < cv->npoints; i++)
        memcpy(z + 3 * i, cv->z + 3 * (flip ? cv->npoints - 1 - i : i), 3 * sizeof *z);
    return z;
}

/* Two curves swapped between two arcs inside one cell: P ends at the box
 * face x = b below the axis, Q starts there above it, and both ends lie in
 * one cell. F1 follows P into that cell and leaves along Q; F2 comes in
 * along Q and leaves along P. Every crossing is still met exactly once: only
 * the rule that a passage follows one arc of the cell (match.c) refuses. */
static void swapped_arcs(void)
{
    const double b = 0.9999, s = sqrt(1 - b * b);
    char json[512];
    snprintf(json, sizeof json,
             "{\"surfaces\": [{\"type\": \"implicit\", \"f\": \"x^2+y^2+z^2-1\"},"
             "{\"type\": \"implicit\", \"f\": \"z\"}],"
             "\"box\": [[%.17g, %.17g], [%.17g, %.17g], [-0.5, 0.5]]}",
             -b, b, -b, b);
    traced t;
    ic_certify_curve cv[4];
    double *z = NULL, *P = NULL, *Q = NULL, *f1 = NULL, *f2 = NULL;
    if (trace_json(&t, "swapped arcs", json) != 0 ||
        !REQUIRE(ic_trace_result_num_curves(t.res) == 4, "swapped arcs: 4 curves"))
        goto done;
    z = search_curves(&t, ic_pair_pairing(t.pair), cv);
    int p = -1, q = -1, pflip = 0, qflip = 0;
    for (int k = 0; k < 4; k++) {
        double d;
        const int i = nearest(&cv[k], b, -s, &d);
        if (d < 1e-6 && (i == 0 || i == cv[k].npoints - 1))
            p = k, pflip = i == 0; /* P must end there */
        const int j = nearest(&cv[k], b, s, &d);
        if (d < 1e-6 && (j == 0 || j == cv[k].npoints - 1))
            q = k, qflip = j != 0; /* Q must start there */
    }
    if (!REQUIRE(p >= 0 && q >= 0 && p != q, "swapped arcs: the arcs at the cap not found"))
        goto done;
    P = oriented(&cv[p], pflip), Q = oriented(&cv[q], qflip);
    const int np = cv[p].npoints, nq = cv[q].npoints;
    ic_error err;
    ic_certificate *c = ic_certificate_new(ic_pair_pairing(t.pair), t.opt.box, 1, &err);
    const ic_certify_limits lim = {200000, 1e-6, 256, 0};
    if (!REQUIRE(c && ic_certify_cover(c, &lim, &err) == IC_OK && c->summary.accepted,
                 "swapped arcs: the cover"))
        goto free_cert;
    /* k: P's first point from which it stays in the cell of its end; j: Q's
     * last point up to which it is in the cell of its start */
    const long L = ic_certificate_locate(c, P + 3 * (np - 1), -1, 0);
    int k = np - 1, j = 0;
    while (k > 0 && ic_certificate_locate(c, P + 3 * (k - 1), -1, 0) == L)
        k--;
    while (j + 1 < nq && ic_certificate_locate(c, Q + 3 * (j + 1), -1, 0) == L)
        j++;
    if (!REQUIRE(ic_certificate_locate(c, Q, -1, 0) == L && k > 0 && k < np - 1 && j > 0 &&
                     j < nq - 1,
                 "swapped arcs: the cap's two ends are not in one cell with points inside"))
        goto free_cert;
    f1 = malloc((size_t)(np + nq) * 3 * sizeof *f1);
    f2 = malloc((size_t)(np + nq) * 3 * sizeof *f2);
    if (!REQUIRE(f1 && f2, "out of memory"))
        goto free_cert;
    memcpy(f1, P, (size_t)(k + 1) * 3 * sizeof *f1); /* P[0..k], Q[j..] */
    memcpy(f1 + 3 * (k + 1), Q + 3 * j, (size_t)(nq - j) * 3 * sizeof *f1);
    memcpy(f2, Q, (size_t)(j + 1) * 3 * sizeof *f2); /* Q[0..j], P[k..] */
    memcpy(f2 + 3 * (j + 1), P + 3 * k, (size_t)(np - k) * 3 * sizeof *f2);
    ic_certify_curve mix[4];
    int m = 0;
    for (int a = 0; a < 4; a++)
        if (a != p && a != q)
            mix[m++] = cv[a];
    mix[m++] = (ic_certify_curve){f1, k + 1 + nq - j, 0, 0};
    mix[m++] = (ic_certify_curve){f2, j + 1 + np - k, 0, 0};
    CHECK(ic_certify_curves(c, mix, 4, &err) == IC_OK && !c->summary.accepted &&
              strstr(c->summary.reason, "other than along one of its arcs"),
          "two arcs swapped inside a cell are not refused: '%s'", c->summary.reason);
    printf("swapped arcs: refused (%s)\n", c->summary.reason);
free_cert:
    ic_certificate_free(c);
done:
    free(f1), free(f2), free(P), free(Q), free(z);
    release(&t);
}

/* Two free-form bicubic patches over one plane (tests/truth/gen_nurbs_freeform.py):
 * their curve has u = p and v = q, so a cover that split two coordinates of
 * the same range at the same value would meet it at cells' edges, where no
 * crossing can be isolated (cover.c, IC_CERTIFY_SPLIT_OFFSET_STEP). Proven,
 * one closed curve. */
static void diagonal_patches(const char *src)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/tests/data/nurbs/problem-freeform-bicubic.json", src);
    ic_problem *pb = NULL;
    ic_pair *pair = NULL;
    ic_trace_result *r = NULL;
    ic_error err;
    ic_trace_options opt;
    ic_trace_defaults(&opt);
    ic_status st = ic_problem_load(&pb, path, &err);
    if (st == IC_OK)
        st = ic_pair_new(&pair, ic_problem_surface(pb, 0), ic_problem_surface(pb, 1), &err);
    if (st == IC_OK)
        st = ic_trace(&r, pair, &opt, &err);
    if (REQUIRE(st == IC_OK, "%s: %s", path, err.message))
        CHECK(ic_trace_result_report(r)->complete && ic_trace_result_num_curves(r) == 1 &&
                  ic_trace_result_curve(r, 0)->closed,
              "free-form patches over one plane: not proven (%s)",
              ic_trace_result_report(r)->certificate.reason);
    ic_trace_result_free(r);
    ic_pair_free(pair);
    ic_problem_free(pb);
}

/* certify = 0: the checker is not run and complete is never 1; the tracer's
 * account stays in tracer_complete, the reason in the failures. */
static void certify_off(void)
{
    const char *json = "{\"surfaces\": [{\"type\": \"implicit\", \"f\": \"x^2+y^2+z^2-1\"},"
                       "{\"type\": \"implicit\", \"f\": \"z\"}],"
                       "\"box\": [[-2, 2], [-2, 2], [-2, 2]]}";
    ic_problem *pb = NULL;
    ic_pair *pair = NULL;
    ic_trace_result *r = NULL;
    ic_error err;
    ic_trace_options opt;
    ic_trace_defaults(&opt);
    opt.certify = 0;
    ic_status st = ic_problem_parse(&pb, json, strlen(json), &err);
    if (st == IC_OK) {
        opt.has_box = ic_problem_box(pb, opt.box);
        st = ic_pair_new(&pair, ic_problem_surface(pb, 0), ic_problem_surface(pb, 1), &err);
    }
    if (st == IC_OK)
        st = ic_trace(&r, pair, &opt, &err);
    if (REQUIRE(st == IC_OK, "certify off: %s", err.message)) {
        const ic_trace_report *rep = ic_trace_result_report(r);
        CHECK(!rep->complete && rep->tracer_complete && !rep->certificate.checked &&
                  rep->nfailures == 1 && strstr(rep->failures[0], "certify = 0"),
              "certify off: complete %d, tracer_complete %d, checked %d, %d failures",
              rep->complete, rep->tracer_complete, rep->certificate.checked, rep->nfailures);
    }
    opt.certify = 2;
    ic_trace_result *bad = NULL;
    CHECK(pair && ic_trace(&bad, pair, &opt, &err) == IC_ERR_INVALID &&
              strstr(err.message, "certify"),
          "certify = 2 is not refused");
    ic_trace_result_free(bad);
    ic_trace_result_free(r);
    ic_pair_free(pair);
    ic_problem_free(pb);
}

int main(int argc, char **argv)
{
    const char *src = argc > 1 ? argv[1] : ".";
    sweep_clipped_circle();
    sweep_seam_loops(src);
    sweep_tiny_far();
    mutations();
    box_mutations();
    swapped_arcs();
    diagonal_patches(src);
    certify_off();
    return harness_finish("test_certificate");
}
