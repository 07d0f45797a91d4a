/* NURBS patches (docs/nurbs.md): validation with the field at fault,
 * points against an independent evaluator (the recursive definition of the
 * basis over the whole knot vector), the piece a curve heads into on a knot
 * line, and the interval enclosures' soundness and tightness. */
#include "harness.h"

#include <string.h>

#include "intercurve/problem.h"
#include "intercurve/surface.h"
#include "traced_example.h"

/* ---- an independent evaluator: N_i,p(t) by the defining recursion
 * (de Boor 1972, Cox 1972), each basis function on its own, with the
 * right-continuous convention except at the domain's right end ---- */
static double basis(const double *k, int i, int p, double t, int last_span)
{
    if (p == 0) {
        if (i == last_span)
            return k[i] <= t && t <= k[i + 1] ? 1.0 : 0.0;
        return k[i] <= t && t < k[i + 1] ? 1.0 : 0.0;
    }
    double v = 0;
    if (k[i + p] > k[i])
        v += (t - k[i]) / (k[i + p] - k[i]) * basis(k, i, p - 1, t, last_span);
    if (k[i + p + 1] > k[i + 1])
        v += (k[i + p + 1] - t) / (k[i + p + 1] - k[i + 1]) * basis(k, i + 1, p - 1, t, last_span);
    return v;
}

static int last_nonempty_span(const ic_nurbs *d, int dir)
{
    int s = d->count[dir] - 1;
    while (d->knots[dir][s] == d->knots[dir][s + 1])
        s--;
    return s;
}

static void reference_point(const ic_nurbs *d, double u, double v, double out[3])
{
    double num[3] = {0, 0, 0}, den = 0;
    const int lu = last_nonempty_span(d, 0), lv = last_nonempty_span(d, 1);
    for (int i = 0; i < d->count[0]; i++)
        for (int j = 0; j < d->count[1]; j++) {
            const int at = i * d->count[1] + j;
            const double w = d->weights ? d->weights[at] : 1.0;
            const double b = basis(d->knots[0], i, d->degree[0], u, lu) *
                             basis(d->knots[1], j, d->degree[1], v, lv) * w;
            for (int c = 0; c < 3; c++)
                num[c] += b * d->points[3 * at + c];
            den += b;
        }
    for (int c = 0; c < 3; c++)
        out[c] = num[c] / den;
}

/* A rational bicubic by quadratic patch with an interior double knot along
 * u (C^1 there) and a triple knot along v (C^0 there), irregular weights. */
enum { NU = 7, NV = 6 };
static const double KU[NU + 4] = {0, 0, 0, 0, 0.3, 0.6, 0.6, 1, 1, 1, 1};
static const double KV[NV + 3] = {-1, -1, -1, -0.2, 0.4, 0.4, 1, 1, 1};

static void make_net(double pts[NU * NV * 3], double w[NU * NV])
{
    for (int i = 0; i < NU; i++)
        for (int j = 0; j < NV; j++) {
            const int at = i * NV + j;
            pts[3 * at + 0] = i + 0.1 * j * j;
            pts[3 * at + 1] = j - 0.2 * i + 0.05 * i * j;
            pts[3 * at + 2] = sin(1.3 * i) * cos(0.7 * j) + 0.1 * i;
            w[at] = 1.0 + 0.4 * sin(2.1 * i + 1.7 * j) * sin(2.1 * i + 1.7 * j) + 0.1 * j;
        }
}

static ic_nurbs sample_patch(const double *pts, const double *w)
{
    ic_nurbs d;
    memset(&d, 0, sizeof d);
    d.degree[0] = 3, d.degree[1] = 2;
    d.count[0] = NU, d.count[1] = NV;
    d.knots[0] = KU, d.knots[1] = KV;
    d.points = pts, d.weights = w;
    return d;
}

/* The sample patch as a surface (the surface keeps its own copy of the
 * net); NULL, after a failed check, when it cannot be made. */
static ic_surface *sample_surface(void)
{
    double pts[NU * NV * 3], w[NU * NV];
    make_net(pts, w);
    const ic_nurbs d = sample_patch(pts, w);
    ic_surface *s = NULL;
    ic_error err;
    return REQUIRE(ic_surface_new_nurbs(&s, &d, &err) == IC_OK, "create: %s", err.message) ? s
                                                                                          : NULL;
}

/* length: the sample net's coordinates reach about 8; the two evaluators
 * each round O(p q) products of such terms (measured worst 2 ulps of 8);
 * 64 ulps of 8 is the bound */
#define POINT_TOL (64 * DBL_EPSILON * 8)

static void test_points_against_definition(void)
{
    double pts[NU * NV * 3], w[NU * NV];
    make_net(pts, w);
    const ic_nurbs d = sample_patch(pts, w);
    ic_surface *s = NULL;
    ic_error err;
    if (!REQUIRE(ic_surface_new_nurbs(&s, &d, &err) == IC_OK, "create: %s", err.message))
        return;
    harness_rng rng = {0x5eed1234ull};
    const double us[] = {0, 0.3, 0.6, 1, 0.45}, vs[] = {-1, -0.2, 0.4, 1, 0.1};
    for (int k = 0; k < 60; k++) {
        const double u = k < 25 ? us[k % 5] : harness_uniform(&rng, 0, 1);
        const double v = k < 25 ? vs[k / 5] : harness_uniform(&rng, -1, 1);
        double got[3], want[3];
        if (!REQUIRE(ic_surface_eval(s, got, (double[]){u, v}, &err) == IC_OK, "eval: %s",
                     err.message))
            break;
        reference_point(&d, u, v, want);
        for (int c = 0; c < 3; c++)
            CHECK(fabs(got[c] - want[c]) <= POINT_TOL, "R(%g, %g)[%d] = %.17g, want %.17g",
                  u, v, c, got[c], want[c]);
    }
    ic_surface_free(s);
}

/* The second u-derivative of the sample patch along u at (u, v), from
 * Taylor coefficients (2 * coefficient of u^2). */
static double r_uu(ic_surface *s, double u, double v, int c)
{
    ic_jet_space *sp = NULL;
    double t[3 * 6];
    ic_error err;
    if (ic_jet_space_new(&sp, 2, 2, &err) != IC_OK)
        return NAN;
    const int ok = ic_surface_taylor(s, t, (double[]){u, v}, sp, &err) == IC_OK;
    const double r = ok ? 2 * t[c * 6 + ic_jet_index(sp, (int[]){2, 0})] : NAN;
    ic_jet_space_free(sp);
    return r;
}

/* On the double knot u = 0.6 (the patch is C^1 there) a parameter curve
 * heading to smaller u takes the left piece's second derivative, one
 * heading to larger u the right one's, and they differ. */
static void test_side_on_knot_line(void)
{
    ic_surface *s = sample_surface();
    ic_jet_space *sp = NULL;
    ic_error err;
    if (!s || !REQUIRE(ic_jet_space_new(&sp, 1, 2, &err) == IC_OK, "space")) {
        ic_surface_free(s);
        return;
    }
    const double knot = 0.6, v = 0.1, h = 1e-7;
    for (int heading = -1; heading <= 1; heading += 2) {
        double ju[3] = {knot, heading, 0}, jv[3] = {v, 0, 0}, out[9];
        const double *in[2] = {ju, jv};
        if (!REQUIRE(ic_surface_compose(s, out, in, sp, &err) == IC_OK, "compose: %s",
                     err.message))
            break;
        for (int c = 0; c < 3; c++) {
            /* R_uu of the piece the curve goes into, just inside it: off by
             * h |R_uuu| (about 1e-6 here) from its value on the knot line */
            const double want = r_uu(s, knot + heading * h, v, c);
            const double other = r_uu(s, knot - heading * h, v, c);
            CHECK(fabs(2 * out[3 * c + 2] - want) <= 1e-5 * fmax(1, fabs(want)),
                  "heading %d, coordinate %d: R_uu %.12g, the piece's %.12g", heading, c,
                  2 * out[3 * c + 2], want);
            if (c == 2)
                CHECK(fabs(want - other) > 1e-2, "the two pieces' R_uu differ: %g and %g", want,
                      other);
        }
    }
    ic_jet_space_free(sp);
    ic_surface_free(s);
}

static int inside(ic_interval iv, double x) { return iv.lo <= x && x <= iv.hi; }

/* The jet method at a point on the double knot line u = 0.6: the sample
 * patch cut by the plane through R(0.6, 0.1) normal to R_v, so the curve
 * crosses the knot line. Its curvature is that of the piece the curve heads
 * into (the tracer's forced side, ic_surface_set_knot_side, agrees), with
 * the pair in both orders (the curve heads to either side). */
static void test_jet_method_on_knot_line(void)
{
    ic_surface *s = sample_surface(), *plane = NULL;
    ic_jet_space *sp = NULL;
    ic_error err;
    double t[9], P[3], Rv[3];
    if (!s || !REQUIRE(ic_jet_space_new(&sp, 2, 1, &err) == IC_OK, "space") ||
        !REQUIRE(ic_surface_taylor(s, t, (double[]){0.6, 0.1}, sp, &err) == IC_OK, "taylor"))
        goto done;
    for (int c = 0; c < 3; c++)
        P[c] = t[3 * c], Rv[c] = t[3 * c + 2];
    ic_primitive pl = {.kind = IC_PRIM_PLANE};
    memcpy(pl.center, P, sizeof P);
    memcpy(pl.normal, Rv, sizeof Rv);
    if (!REQUIRE(ic_surface_new_primitive(&plane, &pl, IC_IMPLICIT, &err) == IC_OK, "plane"))
        goto done;
    for (int first = 0; first < 2; first++) {
        ic_pair *pair = NULL;
        ic_local_options opt;
        ic_local_defaults(&opt);
        ic_local_point pt;
        if (!REQUIRE(ic_pair_new(&pair, first ? plane : s, first ? s : plane, &err) == IC_OK &&
                         ic_local_locate(pair, &pt, P, &opt, &err) == IC_OK,
                     "locate: %s", err.message)) {
            ic_pair_free(pair);
            break;
        }
        memcpy(pt.xyz, P, sizeof P); /* exactly on the knot line */
        pt.params[first][0] = 0.6, pt.params[first][1] = 0.1;
        double kappa[3]; /* heading by itself, forced left, forced right */
        int heading = 0;
        for (int side = 0; side < 3; side++) {
            ic_surface_set_knot_side(s, (int[]){side == 0 ? 0 : side == 1 ? -1 : 1, 0});
            ic_local_result res;
            kappa[side] = NAN;
            if (ic_local_apparatus(pair, &res, &pt, 3, IC_METHOD_JET, &opt, &err) == IC_OK)
                kappa[side] = res.branches[0].kappa;
            if (side == 0)
                heading = res.branches[0].param_derivs[first][0][0] > 0 ? 1 : -1;
        }
        ic_surface_set_knot_side(s, (int[]){0, 0});
        const double want = kappa[heading > 0 ? 2 : 1];
        CHECK(fabs(kappa[0] - want) <= 1e-12 * fabs(want),
              "pair order %d, heading %d: kappa %.15g, the piece's %.15g", first, heading,
              kappa[0], want);
        CHECK(fabs(kappa[1] - kappa[2]) > 1e-3 * fabs(want), "the pieces' kappa differ: %g %g",
              kappa[1], kappa[2]);
        ic_pair_free(pair);
    }
done:
    ic_jet_space_free(sp);
    ic_surface_free(plane);
    ic_surface_free(s);
}

/* Random boxes (across knot lines, tiny, of zero width on a knot): every
 * sampled point and first derivative lies in the enclosures. Returns the
 * largest ratio of enclosure width to sampled spread on boxes of width
 * `width` (the tightness). */
static double check_boxes(ic_surface *s, const double dom[2][2], double width, int trials,
                          harness_rng *rng, double *deriv_ratio)
{
    double dlo[3][2], dhi[3][2];
    *deriv_ratio = 0;
    ic_jet_space *sp = NULL;
    ic_error err;
    double worst_ratio = 0;
    if (!REQUIRE(ic_jet_space_new(&sp, 2, 1, &err) == IC_OK, "space"))
        return INFINITY;
    for (int t = 0; t < trials; t++) {
        ic_interval box[2];
        for (int d = 0; d < 2; d++) {
            const double span = dom[d][1] - dom[d][0], wd = width * span;
            const double lo = harness_uniform(rng, dom[d][0], dom[d][1] - wd);
            box[d] = (ic_interval){lo, lo + wd};
        }
        ic_interval_grad g[3];
        if (!REQUIRE(ic_surface_eval_interval_grad(s, g, box, &err) == IC_OK, "enclose: %s",
                     err.message))
            break;
        double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
        for (int c = 0; c < 3; c++)
            for (int d = 0; d < 2; d++)
                dlo[c][d] = INFINITY, dhi[c][d] = -INFINITY;
        for (int k = 0; k < 25; k++) {
            const double at[2] = {box[0].lo + (box[0].hi - box[0].lo) * (k % 5) / 4.0,
                                  box[1].lo + (box[1].hi - box[1].lo) * (k / 5) / 4.0};
            double tay[9];
            if (!REQUIRE(ic_surface_taylor(s, tay, at, sp, &err) == IC_OK, "taylor"))
                break;
            for (int c = 0; c < 3; c++) {
                lo[c] = fmin(lo[c], tay[3 * c]), hi[c] = fmax(hi[c], tay[3 * c]);
                for (int d = 0; d < 2; d++)
                    dlo[c][d] = fmin(dlo[c][d], tay[3 * c + 1 + d]),
                    dhi[c][d] = fmax(dhi[c][d], tay[3 * c + 1 + d]);
                CHECK(inside(g[c].v, tay[3 * c]) && inside(g[c].d[0], tay[3 * c + 1]) &&
                          inside(g[c].d[1], tay[3 * c + 2]),
                      "box [%g, %g] x [%g, %g] at (%g, %g), coordinate %d: %g (%g, %g) outside "
                      "[%g, %g] ([%g, %g], [%g, %g])",
                      box[0].lo, box[0].hi, box[1].lo, box[1].hi, at[0], at[1], c, tay[3 * c],
                      tay[3 * c + 1], tay[3 * c + 2], g[c].v.lo, g[c].v.hi, g[c].d[0].lo,
                      g[c].d[0].hi, g[c].d[1].lo, g[c].d[1].hi);
            }
        }
        for (int c = 0; c < 3; c++) {
            if (hi[c] - lo[c] > 0)
                worst_ratio = fmax(worst_ratio, (g[c].v.hi - g[c].v.lo) / (hi[c] - lo[c]));
            for (int d = 0; d < 2; d++)
                if (dhi[c][d] - dlo[c][d] > 1e-9)
                    *deriv_ratio = fmax(*deriv_ratio, (g[c].d[d].hi - g[c].d[d].lo) /
                                                          (dhi[c][d] - dlo[c][d]));
        }
    }
    ic_jet_space_free(sp);
    return worst_ratio;
}

static void test_enclosures(void)
{
    ic_surface *s = sample_surface();
    ic_error err;
    if (!s)
        return;
    const double dom[2][2] = {{0, 1}, {-1, 1}};
    harness_rng rng = {0xb0c5ull};
    const int n = 40 * harness_multiplier();
    double dratio;
    check_boxes(s, dom, 0.5, n, &rng, &dratio);
    check_boxes(s, dom, 0.05, n, &rng, &dratio);
    /* on boxes a thousandth of the domain the hull of the blossomed net
     * exceeds the range by O(width^2) (a few percent of it for this net,
     * measured 1.02); an enclosure from the whole span's net would be
     * hundreds of times too wide. The derivatives of this rational patch,
     * as one rational Bernstein function, likewise (measured 1.07; the
     * quotient rule on separate hulls gives 102 here) */
    const double ratio = check_boxes(s, dom, 1e-3, n, &rng, &dratio);
    CHECK(ratio < 1.1, "enclosure width / sampled spread on small boxes: %g", ratio);
    CHECK(dratio < 1.1, "derivative enclosure width / sampled spread on small boxes: %g", dratio);
    printf("enclosure / spread on small boxes: values %.3g, derivatives %.3g\n", ratio, dratio);
    /* zero-width boxes on knot lines and at the domain's corners: the width
     * left is the rounding bound, 16 eps per blossom level over 6 levels
     * times the homogeneous net's size (about 13), in both numerator and
     * weight of the division: about 5e-12 */
    const double on[][2] = {{0.6, 0.4}, {0.3, -0.2}, {0, -1}, {1, 1}, {0.6, 1}};
    for (size_t k = 0; k < sizeof on / sizeof on[0]; k++) {
        const ic_interval box[2] = {{on[k][0], on[k][0]}, {on[k][1], on[k][1]}};
        ic_interval_grad g[3];
        double x[3];
        if (!REQUIRE(ic_surface_eval_interval_grad(s, g, box, &err) == IC_OK &&
                         ic_surface_eval(s, x, on[k], &err) == IC_OK,
                     "point box: %s", err.message))
            continue;
        for (int c = 0; c < 3; c++)
            CHECK(inside(g[c].v, x[c]) && g[c].v.hi - g[c].v.lo < 1e-11,
                  "point box (%g, %g): [%.17g, %.17g] and %.17g", on[k][0], on[k][1], g[c].v.lo,
                  g[c].v.hi, x[c]);
    }
    /* a box leaving the domain is refused, not enclosed by extrapolation */
    const ic_interval out[2] = {{0.9, 1.1}, {0, 0.5}};
    ic_interval_grad g[3];
    CHECK(ic_surface_eval_interval_grad(s, g, out, &err) == IC_ERR_DOMAIN,
          "a box past the domain: %s", err.message);
    ic_surface_free(s);
}

/* A problem holding the NURBS surface `patch` and a sphere. */
static ic_status parse_with(const char *patch, ic_error *err)
{
    char doc[2048];
    snprintf(doc, sizeof doc,
             "{\"surfaces\": [{\"name\": \"P\", \"type\": \"nurbs\", %s}, "
             "{\"type\": \"sphere\", \"radius\": 1}]}",
             patch);
    ic_problem *p = NULL;
    const ic_status st = ic_problem_parse(&p, doc, strlen(doc), err);
    ic_problem_free(p);
    return st;
}

#define KNOTS_OK "\"knots\": [[0, 0, 1, 1], [0, 0, 1, 1]]"
#define NET_OK "\"control_points\": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 0.5]]]"

/* Every inconsistency is an error whose JSON path names the field. */
static void test_problem_errors(void)
{
    static const struct {
        const char *patch, *path;
    } cases[] = {
        {"\"degree\": [1, 1], " KNOTS_OK ", " NET_OK, NULL},
        {"\"degree\": [1, 10], " KNOTS_OK ", " NET_OK, "surfaces[0].degree[1]"},
        {"\"degree\": [1.5, 1], " KNOTS_OK ", " NET_OK, "surfaces[0].degree[0]"},
        {KNOTS_OK ", " NET_OK, "surfaces[0]"},
        {"\"degree\": [1, 1], \"knots\": [[0, 0, 1, 1], [0, 0, 1]], " NET_OK,
         "surfaces[0].knots[1]"},
        {"\"degree\": [1, 1], \"knots\": [[0, 0.5, 0.2, 1], [0, 0, 1, 1]], " NET_OK,
         "surfaces[0].knots[0][2]"},
        {"\"degree\": [1, 1], \"knots\": [[0, 1, 1, 1], [0, 0, 1, 1]], " NET_OK,
         "surfaces[0].knots[0]"},
        {"\"degree\": [1, 1], " KNOTS_OK
         ", \"control_points\": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0]]]",
         "surfaces[0].control_points[1]"},
        {"\"degree\": [1, 1], " KNOTS_OK
         ", \"control_points\": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1]]]",
         "surfaces[0].control_points[1][1]"},
        {"\"degree\": [1, 1], " KNOTS_OK ", " NET_OK ", \"weights\": [[1, 1], [1, 0]]",
         "surfaces[0].weights[1][1]"},
        {"\"degree\": [1, 1], " KNOTS_OK ", " NET_OK ", \"weights\": [[1, 1], [1]]",
         "surfaces[0].weights[1]"},
        {"\"degree\": [1, 1], " KNOTS_OK ", " NET_OK ", \"periodic\": [true, false]",
         "surfaces[0].periodic"},
        {"\"degree\": [2, 1], " KNOTS_OK ", " NET_OK, "surfaces[0].knots[0]"},
        {"\"degree\": [1, 1], " KNOTS_OK ", " NET_OK ", \"colour\": 1", "surfaces[0]"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        ic_error err;
        ic_error_clear(&err);
        const ic_status st = parse_with(cases[k].patch, &err);
        if (!cases[k].path) {
            CHECK(st == IC_OK, "case %zu: %s", k, err.message);
            continue;
        }
        CHECK(st == IC_ERR_INVALID && strcmp(err.path, cases[k].path) == 0,
              "case %zu: status %d, path \"%s\" (want \"%s\"): %s", k, st, err.path,
              cases[k].path, err.message);
    }
}

/* The points of a curve marked as on knot lines: each flagged sheet's
 * parameters put it on one of the knots, within the tracer's snap (1e-13 of
 * the domain's width 10: the landed sheet exactly, the other within
 * rounding). Returns how many there are. */
static int knot_points_on_knots(const ic_trace_curve *c, const double *ku, int nku,
                                const double *kv, int nkv)
{
    const double snap = 1e-13 * 10;
    int n = 0;
    for (int i = 0; i < c->npoints; i++) {
        const ic_trace_point *p = &c->points[i];
        if (!p->knot_line)
            continue;
        for (int s = 0; s < 2; s++) {
            if (!((p->knot_line >> s) & 1))
                continue;
            int on = 0;
            for (int k = 0; k < nku; k++)
                on |= fabs(p->params[s][0] - ku[k]) <= snap;
            for (int k = 0; k < nkv; k++)
                on |= fabs(p->params[s][1] - kv[k]) <= snap;
            CHECK(on, "knot-line point %d, sheet %d at (%.17g, %.17g) is on no knot", i, s,
                  p->params[s][0], p->params[s][1]);
        }
        n++;
    }
    return n;
}

/* The Enneper-type surface of Hassan and Badr (2016), Example 2, written
 * exactly as a bicubic B-spline with interior knots
 * (tests/truth/gen_enneper_nurbs.py) crosses itself along two curves of
 * length 131.07476547127208 each (tests/truth/gen_enneper_length.py, from
 * the formula, not from intercurve). */
static void test_enneper_self(const char *dir)
{
    char path[512];
    snprintf(path, sizeof path, "%s/tests/data/nurbs/enneper-nurbs.json", dir);
    traced t;
    if (trace_file(&t, path) != 0)
        return;
    const double L = 131.07476547127208;
    const double ku[] = {-2, 0, 2.5}, kv[] = {-1, 1.5};
    const int n = ic_trace_result_num_curves(t.res);
    const ic_trace_report *rep = ic_trace_result_report(t.res);
    CHECK(n == 2 && rep->tracer_complete, "%d curves, complete %d", n, rep->tracer_complete);
    int crossings = 0;
    for (int c = 0; c < n; c++) {
        const ic_trace_curve *curve = ic_trace_result_curve(t.res, c);
        CHECK_CLOSE(curve->length, L, TIER_LENGTH, "double curve length");
        crossings += knot_points_on_knots(curve, ku, 3, kv, 2);
    }
    /* the crossings, from the preimages' ranges: one curve's sheets run
     * u in [-5, -2] and [2, 5] with v from 2.7 to -2.7 (u = -2 twice, u = 2.5
     * twice, v = 1.5 and v = -1 once, met by both sheets at one point): 6;
     * the other's run u from 2.7 to -2.7 on both sheets with |v| >= sqrt(3)
     * (u = 2.5, 0, -2, each met by both sheets at one point): 3 */
    CHECK(crossings == 9, "the double curves cross knot lines: %d points on them, want 9",
          crossings);
    release(&t);
}

/* geomdl files: read like the inline patch; what is wrong with one is
 * named by the problem's path and the file's own path. */
static void test_geomdl_errors(const char *dir)
{
    static const struct {
        const char *entry, *path, *words;
    } cases[] = {
        {"\"file\": \"%s/tests/data/nurbs/no-such-file.json\"", "surfaces[0].file", "cannot open"},
        {"\"file\": \"%s/tests/data/nurbs/geomdl-knotline.json\", \"index\": 1", "surfaces[0]",
         "past the last surface"},
        {"\"file\": \"%s/tests/data/nurbs/problem-knotline-plane.json\"", "surfaces[0]",
         "no \"shape\""},
        {"\"file\": \"%s/tests/data/nurbs\"", "surfaces[0].file", "not a regular file"},
        {"\"file\": \"%s/tests/data/nurbs/geomdl-knotline.json\", \"index\": -1",
         "surfaces[0].index", "whole number"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        char entry[600], doc[1200];
        snprintf(entry, sizeof entry, cases[k].entry, dir);
        snprintf(doc, sizeof doc,
                 "{\"surfaces\": [{\"type\": \"geomdl\", %s}, {\"type\": \"sphere\", "
                 "\"radius\": 1}]}",
                 entry);
        ic_problem *p = NULL;
        ic_error err;
        const ic_status st = ic_problem_parse(&p, doc, strlen(doc), &err);
        CHECK(st != IC_OK && strcmp(err.path, cases[k].path) == 0 &&
                  strstr(err.message, cases[k].words),
              "geomdl case %zu: status %d, path \"%s\", message \"%s\"", k, st, err.path,
              err.message);
        ic_problem_free(p);
    }
}

int main(int argc, char **argv)
{
    test_points_against_definition();
    test_side_on_knot_line();
    test_jet_method_on_knot_line();
    test_enclosures();
    test_problem_errors();
    if (REQUIRE(argc > 1, "usage: test_nurbs SOURCE_DIR"))
        test_enneper_self(argv[1]);
    if (argc > 1)
        test_geomdl_errors(argv[1]);
    return harness_finish("nurbs");
}
