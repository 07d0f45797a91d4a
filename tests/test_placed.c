/* Placed primitives (surface.h: axis, ref_direction) against independent
 * truth: the frame derived by hand (tests/placed_frames.h); each placed
 * primitive against the same surface written as formulas in that frame, in
 * both forms: points, Taylor coefficients to order 6, composition with a
 * curve jet, interval enclosures and their widths; the standard position's
 * fast path; bad placements. */
#include <string.h>

#include "harness.h"
#include "intercurve/surface.h"
#include "placed_frames.h"
#include "surface/surface_internal.h" /* the rotations on intervals */

#define ORDER 6
#define CURVE_ORDER 12

/* Enclosures of a placed primitive may be this many times as wide as its
 * formula twin's (plus WIDTH_SLACK): both evaluate the same products and
 * sums on the same rotated coordinates (the twin spells out the rotation,
 * the primitive rotates the local enclosure), so their widths differ by the
 * order of the operations only (measured worst ratio printed). */
#define WIDTH_FACTOR 2.0
/* absolute, in the units of the value: the outward rounding of a
 * point-thin enclosure (a few ulps of O(10) values) */
#define WIDTH_SLACK 1e-13

typedef struct {
    const char *name;
    ic_primitive prim; /* kind and sizes; the placement is set per case */
    const char *local[3];
    const char *imp; /* f_local in X, Y, Z; the plane's is |normal| Z */
} placed_case;

static const placed_case CASES[] = {
    {"plane", {.kind = IC_PRIM_PLANE}, {"u", "v", "0"}, NULL},
    {"sphere",
     {.kind = IC_PRIM_SPHERE, .radius = 2.5},
     {"2.5*cos(u)*cos(v)", "2.5*sin(u)*cos(v)", "2.5*sin(v)"},
     "X^2 + Y^2 + Z^2 - 6.25"},
    {"cylinder",
     {.kind = IC_PRIM_CYLINDER, .radius = 1.5},
     {"1.5*cos(u)", "1.5*sin(u)", "v"},
     "X^2 + Y^2 - 2.25"},
    {"cone",
     {.kind = IC_PRIM_CONE, .half_angle = 0.4},
     {"v*tan(0.4)*cos(u)", "v*tan(0.4)*sin(u)", "v"},
     "X^2 + Y^2 - tan(0.4)^2*Z^2"},
    {"torus",
     {.kind = IC_PRIM_TORUS, .major_radius = 2.0, .radius = 0.5},
     {"(2 + 0.5*cos(v))*cos(u)", "(2 + 0.5*cos(v))*sin(u)", "0.5*sin(v)"},
     "(X^2 + Y^2 + Z^2 + 3.75)^2 - 16*(X^2 + Y^2)"},
    {"ellipsoid",
     {.kind = IC_PRIM_ELLIPSOID, .axes = {1.5, 0.8, 1.1}},
     {"1.5*cos(u)*cos(v)", "0.8*sin(u)*cos(v)", "1.1*sin(v)"},
     "X^2/2.25 + Y^2/0.64 + Z^2/1.21 - 1"},
};
#define NCASES ((int)(sizeof CASES / sizeof CASES[0]))

/* A placement as given (any lengths, a ref not normal to the axis) and its
 * frame by hand. */
typedef struct {
    const char *name;
    double axis[3], ref[3];
    void (*frame)(placed_frame *f, const double c[3]);
} placement;

static const placement PLACEMENTS[] = {
    {"axis (2, 4, 4), ref (1, 0, 0)", {2, 4, 4}, {1, 0, 0}, tilted_frame},
    {"axis (1, 2, 2), default ref", {1, 2, 2}, {0, 0, 0}, tilted_frame},
    {"axis (3, 0, 0), ref (0, 0, 5)", {3, 0, 0}, {0, 0, 5}, along_x_frame},
};
#define NPLACEMENTS ((int)(sizeof PLACEMENTS / sizeof PLACEMENTS[0]))

static const double CENTER[3] = {0.3, -1.2, 0.7};

static double norm3(const double v[3]) { return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

/* The placed primitive of case c (a plane takes the axis as its normal). */
static ic_primitive placed(const placed_case *c, const placement *pl)
{
    ic_primitive p = c->prim;
    memcpy(p.center, CENTER, sizeof CENTER);
    memcpy(p.ref_direction, pl->ref, sizeof pl->ref);
    if (p.kind == IC_PRIM_PLANE)
        memcpy(p.normal, pl->axis, sizeof pl->axis);
    else
        memcpy(p.axis, pl->axis, sizeof pl->axis);
    return p;
}

/* The formula twin of case c placed by pl, in form `implicit`. */
static ic_surface *twin(const placed_case *c, const placement *pl, int implicit)
{
    placed_frame f;
    pl->frame(&f, CENTER);
    ic_surface *q = NULL;
    ic_error err;
    ic_status st;
    if (implicit) {
        char tmpl[64], text[4096];
        if (!c->imp)
            snprintf(tmpl, sizeof tmpl, "%.17g*Z", norm3(pl->axis));
        const int fits = twin_implicit(text, sizeof text, &f, c->imp ? c->imp : tmpl) == 0;
        st = fits ? ic_surface_new_implicit(&q, text, NULL, 0, &err) : IC_ERR_INVALID;
    } else {
        char xyz[3][512];
        twin_parametric(xyz, &f, c->local);
        const char *const text[3] = {xyz[0], xyz[1], xyz[2]};
        st = ic_surface_new_parametric(&q, text, NULL, NULL, 0, NULL, &err);
    }
    return REQUIRE(st == IC_OK, "%s twin: %s", c->name, err.message) ? q : NULL;
}

/* largest |a - b| over len values, relative to max(1, largest |b|) */
static double relative_gap(const double *a, const double *b, int len)
{
    double worst = 0.0, scale = 1.0;
    for (int k = 0; k < len; k++) {
        worst = fmax(worst, fabs(a[k] - b[k]));
        scale = fmax(scale, fabs(b[k]));
    }
    return worst / scale;
}

static double worst_taylor, worst_compose, worst_width_ratio;

/* Points and Taylor coefficients to ORDER at random inputs. */
static void check_taylor(const char *what, ic_surface *p, ic_surface *q, const ic_jet_space *sp,
                         harness_rng *rng)
{
    const int n = ic_jet_space_len(sp), nout = ic_surface_num_outputs(p);
    for (int trial = 0; trial < 10; trial++) {
        double at[3], a[3 * 84], b[3 * 84], pa[3], pb[3];
        for (int k = 0; k < 3; k++)
            at[k] = CENTER[k] + harness_uniform(rng, -1.4, 1.4);
        if (!REQUIRE(ic_surface_taylor(p, a, at, sp, NULL) == IC_OK &&
                         ic_surface_taylor(q, b, at, sp, NULL) == IC_OK &&
                         ic_surface_eval(p, pa, at, NULL) == IC_OK &&
                         ic_surface_eval(q, pb, at, NULL) == IC_OK,
                     "%s: evaluation", what))
            return;
        const double gap = relative_gap(a, b, nout * n), point_gap = relative_gap(pa, pb, nout);
        worst_taylor = fmax(worst_taylor, gap);
        /* TIER_DERIVATIVE: the rotation adds three rounded products and two
         * sums per coefficient, the twin rounds the same terms in its own
         * order: a few ulps of the coefficients' scale either way */
        CHECK(gap <= TIER_DERIVATIVE && point_gap <= TIER_DERIVATIVE,
              "%s: Taylor coefficients %.3g, point %.3g from the formulas (relative)", what, gap,
              point_gap);
    }
}

/* The surface composed with a random curve jet of order CURVE_ORDER. */
static void check_compose(const char *what, ic_surface *p, ic_surface *q, const ic_jet_space *s1,
                          harness_rng *rng)
{
    const int nin = ic_surface_num_vars(p), nout = ic_surface_num_outputs(p);
    double curve[3][CURVE_ORDER + 1] = {{0}}, a[3 * (CURVE_ORDER + 1)], b[3 * (CURVE_ORDER + 1)];
    for (int k = 0; k < nin; k++) {
        curve[k][0] = CENTER[k] + harness_uniform(rng, -1.4, 1.4);
        curve[k][1] = harness_uniform(rng, -1.0, 1.0);
        curve[k][2] = harness_uniform(rng, -0.5, 0.5);
        curve[k][3] = harness_uniform(rng, -0.2, 0.2);
    }
    const double *in[3] = {curve[0], curve[1], curve[2]};
    if (!REQUIRE(ic_surface_compose(p, a, in, s1, NULL) == IC_OK &&
                     ic_surface_compose(q, b, in, s1, NULL) == IC_OK,
                 "%s: compose", what))
        return;
    const double gap = relative_gap(a, b, nout * (CURVE_ORDER + 1));
    worst_compose = fmax(worst_compose, gap);
    /* TIER_DERIVATIVE: jet products in the same order but for the rotation */
    CHECK(gap <= TIER_DERIVATIVE, "%s: composed %.3g from the formulas (relative)", what, gap);
}

/* One component's enclosure a against the twin's b: no wider than
 * WIDTH_FACTOR times; returns 1 when wider. */
static int too_wide(ic_interval a, ic_interval b)
{
    const double wa = a.hi - a.lo, wb = b.hi - b.lo;
    if (wb > WIDTH_SLACK)
        worst_width_ratio = fmax(worst_width_ratio, wa / wb);
    return !(wa <= WIDTH_FACTOR * wb + WIDTH_SLACK);
}

/* x within the enclosure a, beyond a slack of 16 ulps of its magnitude:
 * the sample is rounded, the enclosure is of the exact value. */
static int outside(double x, ic_interval a)
{
    const double slack = 16 * DBL_EPSILON * (1 + fmax(fabs(a.lo), fabs(a.hi)));
    return !(x >= a.lo - slack && x <= a.hi + slack);
}

/* A random box of the inputs around the center, of width 1e-4 to 1. */
static void random_box(ic_interval *box, int nin, harness_rng *rng)
{
    const double w = pow(10.0, harness_uniform(rng, -4, 0));
    for (int k = 0; k < nin; k++) {
        const double lo = (nin == 3 ? CENTER[k] : 0.0) + harness_uniform(rng, -2.5, 2.5);
        box[k] = (ic_interval){lo, lo + w};
    }
}

/* Enclosures of values and first derivatives over random boxes hold the
 * sampled values and derivatives, and are no wider than the twin's. */
static void check_intervals(const char *what, ic_surface *p, ic_surface *q, const ic_jet_space *s1,
                            harness_rng *rng)
{
    const int nin = ic_surface_num_vars(p), nout = ic_surface_num_outputs(p);
    const int n1 = nin + 1; /* value and first derivatives */
    int out = 0, wide = 0, failed = 0;
    for (int trial = 0; trial < 40; trial++) {
        ic_interval box[3];
        random_box(box, nin, rng);
        ic_interval_grad gp[3], gq[3];
        if (ic_surface_eval_interval_grad(p, gp, box, NULL) != IC_OK ||
            ic_surface_eval_interval_grad(q, gq, box, NULL) != IC_OK) {
            failed++;
            continue;
        }
        for (int k = 0; k < nout; k++)
            for (int d = -1; d < nin; d++)
                wide += too_wide(d < 0 ? gp[k].v : gp[k].d[d], d < 0 ? gq[k].v : gq[k].d[d]);
        for (int sample = 0; sample < 20; sample++) {
            double at[3], t[3 * 4];
            for (int k = 0; k < nin; k++)
                at[k] = harness_uniform(rng, box[k].lo, box[k].hi);
            if (ic_surface_taylor(p, t, at, s1, NULL) != IC_OK) {
                failed++;
                continue;
            }
            for (int k = 0; k < nout; k++)
                for (int d = 0; d < n1; d++)
                    out += outside(t[n1 * k + d], d == 0 ? gp[k].v : gp[k].d[d - 1]);
        }
        ic_interval v[3];
        if (ic_surface_eval_interval(p, v, box, NULL) != IC_OK)
            failed++;
        for (int k = 0; k < nout; k++)
            out += memcmp(&v[k], &gp[k].v, sizeof v[k]) != 0; /* the same enclosure */
    }
    CHECK(failed == 0, "%s: %d interval or sample evaluations failed", what, failed);
    CHECK(out == 0, "%s: %d samples outside their enclosures", what, out);
    CHECK(wide == 0, "%s: %d enclosures wider than %g times the formula's", what, wide,
          WIDTH_FACTOR);
}

/* The spaces the checks evaluate in: order ORDER in 2 and 3 variables,
 * order 1 in 2 and 3, a curve's order CURVE_ORDER. */
typedef struct {
    ic_jet_space *taylor[2], *first[2], *curve;
} spaces;

static void check_case(const placed_case *c, const placement *pl, int implicit, const spaces *sp,
                       harness_rng *rng)
{
    char what[160];
    snprintf(what, sizeof what, "%s %s, %s", implicit ? "implicit" : "parametric", c->name,
             pl->name);
    const ic_primitive prim = placed(c, pl);
    ic_surface *p = NULL, *q = twin(c, pl, implicit);
    ic_error err;
    if (REQUIRE(ic_surface_new_primitive(&p, &prim, implicit ? IC_IMPLICIT : IC_PARAMETRIC, &err) ==
                    IC_OK,
                "%s: %s", what, err.message) &&
        q) {
        check_taylor(what, p, q, sp->taylor[implicit], rng);
        check_compose(what, p, q, sp->curve, rng);
        check_intervals(what, p, q, sp->first[implicit], rng);
    }
    ic_surface_free(p);
    ic_surface_free(q);
}

static void test_match_formulas(harness_rng *rng)
{
    spaces sp = {{NULL, NULL}, {NULL, NULL}, NULL};
    if (REQUIRE(ic_jet_space_new(&sp.taylor[0], 2, ORDER, NULL) == IC_OK &&
                    ic_jet_space_new(&sp.taylor[1], 3, ORDER, NULL) == IC_OK &&
                    ic_jet_space_new(&sp.first[0], 2, 1, NULL) == IC_OK &&
                    ic_jet_space_new(&sp.first[1], 3, 1, NULL) == IC_OK &&
                    ic_jet_space_new(&sp.curve, 1, CURVE_ORDER, NULL) == IC_OK,
                "the jet spaces"))
        for (int k = 0; k < NPLACEMENTS; k++)
            for (int i = 0; i < NCASES; i++)
                for (int implicit = 0; implicit < 2; implicit++)
                    check_case(&CASES[i], &PLACEMENTS[k], implicit, &sp, rng);
    printf("placed vs formulas: Taylor %.2g, composed %.2g (relative), widest enclosure %.3g "
           "times the formula's\n",
           worst_taylor, worst_compose, worst_width_ratio);
    for (int i = 0; i < 2; i++) {
        ic_jet_space_free(sp.taylor[i]);
        ic_jet_space_free(sp.first[i]);
    }
    ic_jet_space_free(sp.curve);
}

/* The standard position, spelled out (axis z of any length, ref x), is
 * bit for bit the all-zero one: the fast path of today's primitives. */
static void test_standard_fast_path(void)
{
    ic_jet_space *sp[2] = {NULL, NULL};
    if (!REQUIRE(ic_jet_space_new(&sp[0], 2, ORDER, NULL) == IC_OK &&
                     ic_jet_space_new(&sp[1], 3, ORDER, NULL) == IC_OK,
                 "the jet spaces"))
        goto done;
    for (int i = 0; i < NCASES; i++)
        for (int implicit = 0; implicit < 2; implicit++) {
            ic_primitive zero = CASES[i].prim, spelled;
            memcpy(zero.center, CENTER, sizeof CENTER);
            if (zero.kind == IC_PRIM_PLANE)
                zero.normal[2] = 2.0;
            spelled = zero;
            spelled.ref_direction[0] = 3.0;
            if (zero.kind != IC_PRIM_PLANE)
                spelled.axis[2] = 7.0;
            ic_surface *a = NULL, *b = NULL;
            const ic_surface_kind form = implicit ? IC_IMPLICIT : IC_PARAMETRIC;
            double ta[3 * 84], tb[3 * 84];
            const double at[3] = {0.4, -0.9, 1.3};
            const size_t len = (implicit ? 1 : 3) * (size_t)ic_jet_space_len(sp[implicit]);
            ic_interval_grad ga[3], gb[3];
            const ic_interval box[3] = {{0.1, 0.3}, {-1.0, -0.5}, {0.9, 1.6}};
            CHECK(ic_surface_new_primitive(&a, &zero, form, NULL) == IC_OK &&
                      ic_surface_new_primitive(&b, &spelled, form, NULL) == IC_OK &&
                      ic_surface_taylor(a, ta, at, sp[implicit], NULL) == IC_OK &&
                      ic_surface_taylor(b, tb, at, sp[implicit], NULL) == IC_OK &&
                      memcmp(ta, tb, len * sizeof *ta) == 0 &&
                      ic_surface_eval_interval_grad(a, ga, box, NULL) == IC_OK &&
                      ic_surface_eval_interval_grad(b, gb, box, NULL) == IC_OK &&
                      memcmp(ga, gb, (implicit ? 1 : 3) * sizeof *ga) == 0,
                  "%s %s: the spelled-out standard position differs from the all-zero one",
                  implicit ? "implicit" : "parametric", CASES[i].name);
            ic_surface_free(a);
            ic_surface_free(b);
        }
done:
    ic_jet_space_free(sp[0]);
    ic_jet_space_free(sp[1]);
}

/* ic_primitive_frame against the frames by hand, and orthonormal and
 * right-handed for random and extreme placements. */
static void test_frames(harness_rng *rng)
{
    for (int k = 0; k < NPLACEMENTS; k++) {
        ic_primitive p = placed(&CASES[2], &PLACEMENTS[k]);
        placed_frame want;
        PLACEMENTS[k].frame(&want, CENTER);
        double got[3][3], worst = 0;
        CHECK(ic_primitive_frame(&p, got, NULL) == IC_OK, "%s: frame", PLACEMENTS[k].name);
        for (int j = 0; j < 3; j++)
            for (int i = 0; i < 3; i++)
                worst = fmax(worst, fabs(got[j][i] - want.e[j][i]));
        /* TIER_ROUNDING: a normalisation and a projection of O(1) numbers */
        CHECK(worst <= TIER_ROUNDING, "%s: frame %.3g from the one by hand", PLACEMENTS[k].name,
              worst);
    }
    double worst = 0;
    for (int trial = 0; trial < 1000; trial++) {
        ic_primitive p = {.kind = IC_PRIM_TORUS};
        /* lengths from 1e-300 to 1e300: normalised without overflow */
        const double sa = pow(10.0, harness_uniform(rng, -300, 300));
        const double sr = pow(10.0, harness_uniform(rng, -300, 300));
        for (int i = 0; i < 3; i++) {
            p.axis[i] = sa * harness_uniform(rng, -1, 1);
            p.ref_direction[i] = trial % 4 == 0 ? 0.0 : sr * harness_uniform(rng, -1, 1);
        }
        double e[3][3];
        if (ic_primitive_frame(&p, e, NULL) != IC_OK) /* a ref near the axis: tested below */
            continue;
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++) {
                const double dot = e[a][0] * e[b][0] + e[a][1] * e[b][1] + e[a][2] * e[b][2];
                worst = fmax(worst, fabs(dot - (a == b)));
            }
        /* e1 x e2 = e3 */
        const double c[3] = {e[0][1] * e[1][2] - e[0][2] * e[1][1],
                             e[0][2] * e[1][0] - e[0][0] * e[1][2],
                             e[0][0] * e[1][1] - e[0][1] * e[1][0]};
        for (int i = 0; i < 3; i++)
            worst = fmax(worst, fabs(c[i] - e[2][i]));
    }
    /* TIER_ROUNDING: orthonormal to a few ulps */
    CHECK(worst <= TIER_ROUNDING, "random frames: %.3g from orthonormal right-handed", worst);
}

/* One bad placement: IC_ERR_INVALID from ic_primitive_frame and from the
 * constructor (no surface), the message holding `says`. */
static void check_bad(const char *what, const ic_primitive *p, const char *says)
{
    double e[3][3];
    ic_error err;
    ic_surface *s = NULL;
    const ic_status st = ic_primitive_frame(p, e, &err);
    CHECK(st == IC_ERR_INVALID && strstr(err.message, says),
          "%s: status %d, message '%s', not one with '%s'", what, (int)st, err.message, says);
    CHECK(ic_surface_new_primitive(&s, p, IC_IMPLICIT, &err) == IC_ERR_INVALID && !s &&
              strstr(err.message, says),
          "%s: the constructor says '%s'", what, err.message);
    ic_surface_free(s);
}

/* A ref_direction at `angle` radians from the axis (1, 2, 2)/3, tilted
 * towards e1 of the frame by hand. */
static ic_primitive ref_at_angle(double angle, double sign)
{
    placed_frame f;
    tilted_frame(&f, CENTER);
    ic_primitive p = {.kind = IC_PRIM_CYLINDER, .radius = 1};
    for (int i = 0; i < 3; i++) {
        p.axis[i] = f.e[2][i];
        p.ref_direction[i] = sign * cos(angle) * f.e[2][i] + sin(angle) * f.e[0][i];
    }
    return p;
}

static void test_bad_placements(void)
{
    ic_primitive p = {.kind = IC_PRIM_SPHERE, .radius = 1, .ref_direction = {1, 0, 0}};
    check_bad("zero axis with a ref", &p, "axis is zero");
    p.axis[0] = NAN;
    check_bad("NaN axis", &p, "axis is not finite");
    p.axis[0] = 1, p.ref_direction[1] = INFINITY;
    check_bad("infinite ref", &p, "ref_direction is not finite");
    /* the threshold both ways: half and twice IC_PRIMITIVE_REF_MIN_ANGLE,
     * pointing along the axis and against it */
    for (int sign = -1; sign <= 1; sign += 2) {
        p = ref_at_angle(0.5 * IC_PRIMITIVE_REF_MIN_ANGLE, sign);
        check_bad("ref within the angle of the axis", &p, "1e-06 radians");
        p = ref_at_angle(2 * IC_PRIMITIVE_REF_MIN_ANGLE, sign);
        double e[3][3];
        placed_frame f;
        tilted_frame(&f, CENTER);
        CHECK(ic_primitive_frame(&p, e, NULL) == IC_OK &&
                  /* e1 is the hand frame's: the projection loses about
                   * 1 ulp / sin(angle) = 1e-10 */
                  fabs(e[0][0] - f.e[0][0]) + fabs(e[0][1] - f.e[0][1]) +
                          fabs(e[0][2] - f.e[0][2]) <=
                      1e-9,
              "a ref twice the smallest angle from the axis is accepted, e1 the hand frame's");
    }
    ic_primitive plane = {.kind = IC_PRIM_PLANE, .normal = {0, 0, 1}, .axis = {0, 0, 1}};
    check_bad("plane with an axis", &plane, "takes no axis");
    plane.axis[2] = 0, plane.ref_direction[2] = -3;
    check_bad("plane with a ref along its normal", &plane, "parallel to the normal");
    plane.normal[2] = 0;
    check_bad("plane with a zero normal", &plane, "normal is zero");
}

/* The rotations on intervals round outward: point intervals rotated
 * either way enclose the exact rotation of the frame's numbers (long double
 * sums of products of doubles, exact to 1e-19 relative, below the 1 ulp the
 * outward rounding adds; a rounded-to-nearest rotation misses it at most
 * trials). */
static void test_rotation_rounding(harness_rng *rng)
{
    int missed = 0;
    for (int trial = 0; trial < 200; trial++) {
        ic_primitive p = {.kind = IC_PRIM_CONE};
        double x[3], e[3][3];
        for (int i = 0; i < 3; i++) {
            p.axis[i] = harness_uniform(rng, -1, 1);
            p.ref_direction[i] = harness_uniform(rng, -1, 1);
            x[i] = harness_uniform(rng, -10, 10);
        }
        if (ic_primitive_frame(&p, e, NULL) != IC_OK)
            continue;
        ic_interval space[3], local[3];
        for (int i = 0; i < 3; i++)
            space[i] = local[i] = (ic_interval){x[i], x[i]};
        ic_placement_interval_to_space((const double(*)[3])e, space);
        ic_placement_interval_to_local((const double(*)[3])e, local);
        for (int k = 0; k < 3; k++) {
            long double to_space = 0, to_local = 0;
            for (int j = 0; j < 3; j++) {
                to_space += (long double)e[j][k] * x[j];
                to_local += (long double)e[k][j] * x[j];
            }
            missed += !(space[k].lo <= to_space && to_space <= space[k].hi);
            missed += !(local[k].lo <= to_local && to_local <= local[k].hi);
        }
    }
    CHECK(missed == 0, "rotations of point intervals: %d exact values outside", missed);
}

int main(void)
{
    harness_rng rng = {0x9e3779b97f4a7c15ull};
    test_frames(&rng);
    test_bad_placements();
    test_rotation_rounding(&rng);
    test_standard_fast_path();
    test_match_formulas(&rng);
    return harness_finish("test_placed");
}
