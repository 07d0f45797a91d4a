/* Transversal points: the jet method against independent truth
 * (tests/truth/transversal_truth.txt) in every pairing, identities of the
 * frame at every tested point, and the errors of locating a point. */
#include <string.h>

#include "harness.h"
#include "intercurve/local.h"
#include "truth_file.h"

/* A surface of a test problem: parametric (xyz, params) or implicit (f);
 * NULL, a failed check, when it cannot be built. */
typedef struct {
    const char *xyz[3];
    const char *params[2];
    const char *f;
} surface_def;

static ic_surface *make_surface(const surface_def *d, const double (*domain)[2])
{
    ic_surface *s = NULL;
    ic_error err;
    ic_status st = d->f ? ic_surface_new_implicit(&s, d->f, NULL, 0, &err)
                        : ic_surface_new_parametric(&s, d->xyz, d->params[0] ? d->params : NULL,
                                                    NULL, 0, NULL, &err);
    if (!REQUIRE(st == IC_OK, "cannot build a test surface (%s): %s", d->f ? d->f : d->xyz[0],
                 err.message))
        return NULL;
    if (domain && !REQUIRE(ic_surface_set_domain(s, domain, NULL, &err) == IC_OK,
                           "the domain of a test surface: %s", err.message)) {
        ic_surface_free(s);
        return NULL;
    }
    return s;
}

/* A pair of test surfaces (B absent for a self-intersection); 0, after a
 * failed check, when it cannot be made. */
typedef struct {
    ic_surface *A, *B;
    ic_pair *pair;
} test_pair;

static int open_pair(test_pair *tp, const surface_def *a, const surface_def *b,
                     const double (*domain)[2])
{
    tp->A = make_surface(a, domain);
    tp->B = b ? make_surface(b, NULL) : NULL;
    tp->pair = NULL;
    if (!tp->A || (b && !tp->B))
        return 0;
    ic_error err;
    return REQUIRE(ic_pair_new(&tp->pair, tp->A, tp->B, &err) == IC_OK, "test pair: %s",
                   err.message);
}

static void close_pair(test_pair *tp)
{
    ic_pair_free(tp->pair);
    ic_surface_free(tp->A);
    ic_surface_free(tp->B);
}

static double vdist(const double *a, const double *b)
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                (a[2] - b[2]) * (a[2] - b[2]));
}

static double vnorm(const double *a) { return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

static double dot(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static double worst_low, worst_high, worst_identity;

/* Identities that hold at every transversal point, whatever the truth. */
static void check_identities(const char *what, const ic_local_result *res)
{
    const ic_branch *br = &res->branches[0];
    /* the frame: unit, orthogonal, right-handed (a few roundings of O(1),
     * summed over seven terms: twice the tier) */
    const double tier = 2 * TIER_ROUNDING;
    double e = fabs(vnorm(br->t) - 1) + fabs(vnorm(br->n) - 1) + fabs(vnorm(br->b) - 1) +
               fabs(dot(br->t, br->n)) + fabs(dot(br->t, br->b)) + fabs(dot(br->n, br->b));
    double txn[3] = {br->t[1] * br->n[2] - br->t[2] * br->n[1],
                     br->t[2] * br->n[0] - br->t[0] * br->n[2],
                     br->t[0] * br->n[1] - br->t[1] * br->n[0]};
    e += vdist(txn, br->b);
    worst_identity = fmax(worst_identity, e / DBL_EPSILON);
    CHECK(e <= tier, "%s: frame not orthonormal right-handed (%g)", what, e);
    /* the point on both surfaces: the refinement's target */
    CHECK(res->point.residual <= 1e-13 * (1 + vnorm(res->point.xyz)),
          "%s: residual %g", what, res->point.residual);
    /* Meusnier: kappa_n = kappa n . N; kappa^2 = kappa_n^2 + kappa_g^2 */
    for (int s = 0; s < 2; s++) {
        const ic_darboux *dx = &br->surface[s];
        CHECK(fabs(dx->kappa_n - br->kappa * dot(br->n, res->normals[s])) <= 1e-14 * (1 + br->kappa),
              "%s: kappa_n on %d", what, s);
        CHECK(fabs(dx->kappa_n * dx->kappa_n + dx->kappa_g * dx->kappa_g - br->kappa * br->kappa) <=
                  1e-14 * (1 + br->kappa * br->kappa),
              "%s: kappa^2 = kappa_n^2 + kappa_g^2 on %d", what, s);
    }
    /* Frenet-Serret between orders: c''' . t = -kappa^2, c'''' . t = -3 kappa kappa'
     * (these come from |c'| = 1 at orders 3 and 4, not from the definitions) */
    if (br->order >= 3)
        CHECK(fabs(dot(br->derivs[2], br->t) + br->kappa * br->kappa) <= 1e-13 * (1 + br->kappa * br->kappa),
              "%s: c'''.t = -kappa^2", what);
    if (br->order >= 4)
        CHECK(fabs(dot(br->derivs[3], br->t) + 3 * br->kappa * br->kappa_prime) <=
                  1e-12 * (1 + fabs(br->kappa * br->kappa_prime)),
              "%s: c''''.t = -3 kappa kappa'", what);
}

/* Compares the branch with the truth, up to the orientation map. */
static void check_truth(const char *what, const ic_local_result *res, const truth_case *tc)
{
    const ic_branch *br = &res->branches[0];
    CHECK(vdist(res->point.xyz, tc->point) <= 1e-12 * (1 + vnorm(tc->point)),
          "%s: point (%g %g %g)", what, res->point.xyz[0], res->point.xyz[1], res->point.xyz[2]);
    const double sign = dot(br->t, tc->d[0]) < 0 ? -1.0 : 1.0;
    double s = 1.0;
    for (int k = 0; k < br->order && k < 8; k++) {
        s *= sign;
        double want[3] = {s * tc->d[k][0], s * tc->d[k][1], s * tc->d[k][2]};
        /* relative to max(1, |c^(k)|): the targets to order 4 and
         * to order 8 (harness.h) */
        const double err = vdist(br->derivs[k], want) / fmax(1.0, vnorm(want));
        if (k < 4)
            worst_low = fmax(worst_low, err);
        else
            worst_high = fmax(worst_high, err);
        CHECK(err <= (k < 4 ? TIER_APPARATUS_LOW : TIER_APPARATUS_HIGH), "%s: c^(%d) off by %g",
              what, k + 1, err);
    }
    /* kappa, tau and kappa' come from c^(1..4) */
    CHECK(fabs(br->kappa - tc->kappa) <= TIER_APPARATUS_LOW * fmax(1, tc->kappa),
          "%s: kappa %.17g vs %.17g", what, br->kappa, tc->kappa);
    if (br->tau_defined)
        CHECK(fabs(br->tau - tc->tau) <= TIER_APPARATUS_LOW * fmax(1, fabs(tc->tau)),
              "%s: tau %.17g vs %.17g", what, br->tau, tc->tau);
    if (br->kappa_prime_defined)
        CHECK(fabs(br->kappa_prime - sign * tc->kappa_p) <=
                  TIER_APPARATUS_LOW * fmax(1, fabs(tc->kappa_p)),
              "%s: kappa' %.17g vs %.17g", what, br->kappa_prime, sign * tc->kappa_p);
    if (br->tau_prime_defined)
        CHECK(fabs(br->tau_prime - sign * tc->tau_p) <= 1e-10 * fmax(1, fabs(tc->tau_p)),
              "%s: tau' %.17g vs %.17g", what, br->tau_prime, sign * tc->tau_p);
}

typedef struct {
    const char *truth;       /* case name in the truth file */
    const char *label;
    surface_def A, B;
    int self;
    const double (*domain)[2]; /* of A, when the search needs one; NULL: unbounded */
} pairing;

/* the domain of Hassan and Badr (2016), Example 2 */
static const double ENNEPER_DOMAIN[2][2] = {{-5, 5}, {-5, 5}};

static const pairing PAIRINGS[] = {
    {"viviani", "viviani param/param",
     {{"1 + cos(v)", "sin(v)", "u"}, {0}, NULL},
     {{"2*cos(u)*cos(v)", "2*sin(u)*cos(v)", "2*sin(v)"}, {0}, NULL}, 0, NULL},
    {"viviani", "viviani param/implicit",
     {{"1 + cos(v)", "sin(v)", "u"}, {0}, NULL}, {{0}, {0}, "x^2 + y^2 + z^2 - 4"}, 0, NULL},
    {"viviani", "viviani implicit/param",
     {{0}, {0}, "(x - 1)^2 + y^2 - 1"},
     {{"2*cos(u)*cos(v)", "2*sin(u)*cos(v)", "2*sin(v)"}, {0}, NULL}, 0, NULL},
    {"viviani", "viviani implicit/implicit",
     {{0}, {0}, "(x - 1)^2 + y^2 - 1"}, {{0}, {0}, "x^2 + y^2 + z^2 - 4"}, 0, NULL},
    {"circle", "sphere/plane param/implicit",
     {{"2*cos(u)*cos(v)", "2*sin(u)*cos(v)", "2*sin(v)"}, {0}, NULL}, {{0}, {0}, "z - 1"}, 0, NULL},
    {"circle", "sphere/plane implicit/param",
     {{0}, {0}, "x^2 + y^2 + z^2 - 4"}, {{"s", "t", "1"}, {"s", "t"}, NULL}, 0, NULL},
    {"helix", "cylinder/helicoid implicit/param",
     {{0}, {0}, "x^2 + y^2 - 1"}, {{"v*cos(u)", "v*sin(u)", "u/2"}, {0}, NULL}, 0, NULL},
    {"helix", "cylinder/helicoid param/implicit",
     {{"cos(u)", "sin(u)", "v"}, {0}, NULL}, {{0}, {0}, "x*sin(2*z) - y*cos(2*z)"}, 0, NULL},
    {"ellipse51", "Abdel-All et al. (2012) Ex 5.1 ellipsoids",
     {{0}, {0}, "x^2/0.36 + y^2/0.64 + z^2 - 1"},
     {{0}, {0}, "x^2/0.2025 + y^2/0.64 + z^2/1.5625 - 1"}, 0, NULL},
    {"enneper", "Hassan and Badr (2016) Ex 2 Enneper self-intersection",
     {{"u - u^3/3 + u*v^2", "-v - u^2*v + v^3/3", "u^2 - v^2"}, {0}, NULL}, {{0}, {0}, NULL}, 1,
     ENNEPER_DOMAIN},
    {"ex54", "Abdel-All et al. (2012) Ex 5.4", {{0}, {0}, "x^2 - y^2 + z - 1"},
     {{0}, {0}, "x^2 + y^2 + z^3"}, 0, NULL},
};

static void test_against_truth(const truth_case *cases, int ncases)
{
    ic_local_options opt;
    ic_local_defaults(&opt);
    int tested = 0;
    for (size_t pi = 0; pi < sizeof PAIRINGS / sizeof PAIRINGS[0]; pi++) {
        const pairing *pr = &PAIRINGS[pi];
        test_pair tp;
        if (!open_pair(&tp, &pr->A, pr->self ? NULL : &pr->B, pr->domain)) {
            fprintf(stderr, "  (the pairing %s)\n", pr->label);
            close_pair(&tp);
            continue;
        }
        ic_pair *pair = tp.pair;
        for (int c = 0; c < ncases; c++) {
            if (strcmp(cases[c].name, pr->truth) != 0)
                continue;
            char what[160];
            snprintf(what, sizeof what, "%s at %s", pr->label, cases[c].extra);
            ic_local_point pt;
            ic_error err;
            ic_status st = ic_local_locate(pair, &pt, cases[c].point, &opt, &err);
            CHECK(st == IC_OK, "%s: locate: %s", what, err.message);
            if (st != IC_OK)
                continue;
            ic_local_result res;
            st = ic_local_apparatus(pair, &res, &pt, 8, IC_METHOD_JET, &opt, &err);
            CHECK(st == IC_OK, "%s: apparatus: %s", what, err.message);
            if (st != IC_OK)
                continue;
            CHECK(res.type == IC_POINT_TRANSVERSAL && res.nbranches == 1, "%s: type", what);
            check_truth(what, &res, &cases[c]);
            check_identities(what, &res);
            tested++;
            /* the closed-form method (the pairing's paper) to order 3 */
            char cwhat[200];
            snprintf(cwhat, sizeof cwhat, "%s (closed-form)", what);
            st = ic_local_apparatus(pair, &res, &pt, 3, IC_METHOD_CLOSED_FORM, &opt, &err);
            CHECK(st == IC_OK, "%s: %s", cwhat, err.message);
            if (st == IC_OK) {
                check_truth(cwhat, &res, &cases[c]);
                check_identities(cwhat, &res);
            }
        }
        close_pair(&tp);
    }
    CHECK(tested >= 30, "points tested against truth: %d", tested);
    printf("truth: %d points; worst relative error c^(1..4) %.2g, c^(5..8) %.2g; frame "
           "identities %.1f ulps\n",
           tested, worst_low, worst_high, worst_identity);
}

/* Locating by parameters lands on the same point as by coordinates. */
static void test_locate_params(void)
{
    const surface_def cyl = {{"1 + cos(v)", "sin(v)", "u"}, {0}, NULL};
    const surface_def sph = {{"2*cos(u)*cos(v)", "2*sin(u)*cos(v)", "2*sin(v)"}, {0}, NULL};
    test_pair tp;
    if (!open_pair(&tp, &cyl, &sph, NULL)) {
        close_pair(&tp);
        return;
    }
    ic_pair *pair = tp.pair;
    ic_local_options opt;
    ic_local_defaults(&opt);
    /* theta = 0.7 on Viviani: cylinder (u, v) = (2 sin 0.35, 0.7); sphere
     * (atan2(sin 0.7, 1 + cos 0.7), asin(sin 0.35)) */
    const double th = 0.7;
    const double params[4] = {2 * sin(th / 2), th, atan2(sin(th), 1 + cos(th)), th / 2};
    ic_local_point pt;
    ic_error err;
    CHECK(ic_local_locate_params(pair, &pt, params, 4, &opt, &err) == IC_OK, "params: %s",
          err.message);
    const double want[3] = {1 + cos(th), sin(th), 2 * sin(th / 2)};
    CHECK(vdist(pt.xyz, want) <= 1e-14, "located by parameters: %g", vdist(pt.xyz, want));
    CHECK(ic_local_locate_params(pair, &pt, params, 2, &opt, &err) == IC_ERR_INVALID &&
              strstr(err.message, "expected 4 parameters"),
          "wrong parameter count: %s", err.message);
    const double apart[4] = {0.1, 0.2, 1.0, 0.3};
    CHECK(ic_local_locate_params(pair, &pt, apart, 4, &opt, &err) == IC_ERR_UNABLE &&
              strstr(err.message, "apart"),
          "parameters of two different points: %s", err.message);
    close_pair(&tp);
}

static void test_errors(void)
{
    const surface_def cyl = {{0}, {0}, "(x - 1)^2 + y^2 - 1"};
    const surface_def sph = {{"2*cos(u)*cos(v)", "2*sin(u)*cos(v)", "2*sin(v)"}, {0}, NULL};
    test_pair tp;
    if (!open_pair(&tp, &cyl, &sph, NULL)) {
        close_pair(&tp);
        return;
    }
    ic_pair *pair = tp.pair;
    ic_local_options opt;
    ic_local_defaults(&opt);
    ic_local_point pt;
    ic_local_result res;
    ic_error err;
    /* off the surfaces: an error that says how far */
    const double off[3] = {1.5, 0.8660254037844386, 1.2};
    CHECK(ic_local_locate(pair, &pt, off, &opt, &err) == IC_ERR_UNABLE &&
              strstr(err.message, "0.107 away from surface B"),
          "off the surfaces: %s", err.message);
    /* the sphere's pole is on Viviani's curve (theta = pi): singular sheet */
    const double pole[3] = {0, 0, 2};
    ic_status st = ic_local_locate(pair, &pt, pole, &opt, &err);
    if (st == IC_OK)
        st = ic_local_apparatus(pair, &res, &pt, 3, IC_METHOD_JET, &opt, &err);
    CHECK(st == IC_ERR_DOMAIN && strstr(err.message, "singular"), "pole: %d %s", st, err.message);
    /* the branch point (2, 0, 0) is tangential: classified (tests/test_tangential.c
     * checks its branches); the transversal-only method is refused there */
    const double branch[3] = {2, 0, 0};
    CHECK(ic_local_locate(pair, &pt, branch, &opt, &err) == IC_OK, "branch point located");
    st = ic_local_apparatus(pair, &res, &pt, 3, IC_METHOD_AUTO, &opt, &err);
    CHECK(st == IC_OK && res.type == IC_POINT_BRANCH && res.nbranches == 2,
          "branch point: %d %s", st, st ? err.message : "");
    CHECK(ic_local_apparatus(pair, &res, &pt, 3, IC_METHOD_CLOSED_FORM, &opt, &err) ==
                  IC_ERR_INVALID && strstr(err.message, "tangential point"),
          "closed form at a tangential point: %s", err.message);
    /* orders out of range */
    const double ok[3] = {1.5, 0.8660254037844386, 1.0};
    CHECK(ic_local_locate(pair, &pt, ok, &opt, &err) == IC_OK, "located");
    CHECK(ic_local_apparatus(pair, &res, &pt, IC_LOCAL_MAX_ORDER + 1, IC_METHOD_JET, &opt,
                             &err) == IC_ERR_INVALID,
          "order above the maximum");
    CHECK(ic_local_apparatus(pair, &res, &pt, 4, IC_METHOD_CLOSED_FORM, &opt, &err) ==
                  IC_ERR_INVALID && strstr(err.message, "up to order 3"),
          "closed form above order 3: %s", err.message);
    CHECK(ic_local_apparatus(pair, &res, &pt, 0, IC_METHOD_JET, &opt, &err) == IC_ERR_INVALID,
          "order 0");
    close_pair(&tp);
    /* a point of the Enneper surface that is not on its double curve */
    const surface_def enn = {{"u - u^3/3 + u*v^2", "-v - u^2*v + v^3/3", "u^2 - v^2"}, {0}, NULL};
    if (open_pair(&tp, &enn, NULL, ENNEPER_DOMAIN)) {
        pair = tp.pair;
        ic_surface *A = tp.A;
        const double uv[2] = {0.3, 0.4};
        double X[3];
        CHECK(ic_surface_eval(A, X, uv, NULL) == IC_OK, "eval");
        CHECK(ic_local_locate(pair, &pt, X, &opt, &err) == IC_ERR_UNABLE &&
                  strstr(err.message, "no second preimage"),
              "not a self-intersection: %s", err.message);
        const double same[4] = {0.3, 0.4, 0.3, 0.4};
        CHECK(ic_local_locate_params(pair, &pt, same, 4, &opt, &err) == IC_ERR_INVALID &&
                  strstr(err.message, "same point"),
              "one preimage twice: %s", err.message);
    }
    close_pair(&tp);
}

/* Two planes meet in a line: kappa = 0 and n, b, tau undefined (Abdel-All et
 * al. (2012), corollary 3.1); an ellipse of their Example 5.1 is planar
 * (corollary 3.2). */
static void test_line_and_plane_curve(void)
{
    const surface_def p1 = {{0}, {0}, "x + 2*y - z - 1"};
    const surface_def p2 = {{"u", "v", "0.5 + 0.3*u"}, {0}, NULL};
    test_pair tp;
    if (!open_pair(&tp, &p1, &p2, NULL)) {
        close_pair(&tp);
        return;
    }
    ic_pair *pair = tp.pair;
    ic_local_options opt;
    ic_local_defaults(&opt);
    ic_local_point pt;
    ic_local_result res;
    ic_error err;
    /* x + 2y - (0.5 + 0.3x) = 1 at x = 1: y = 0.4, z = 0.8 */
    const double X[3] = {1.0, 0.4, 0.8};
    CHECK(ic_local_locate(pair, &pt, X, &opt, &err) == IC_OK, "line: %s", err.message);
    CHECK(ic_local_apparatus(pair, &res, &pt, 5, IC_METHOD_JET, &opt, &err) == IC_OK, "line");
    const ic_branch *br = &res.branches[0];
    CHECK(br->kappa <= 1e-15 && !br->frame_defined && !br->tau_defined, "kappa = 0: %g", br->kappa);
    CHECK(ic_branch_is_line(br, 1e-12), "straight line");
    for (int k = 1; k < 5; k++)
        CHECK(vnorm(br->derivs[k]) <= 1e-15, "c^(%d) = 0 on a line", k + 1);
    close_pair(&tp);
    const surface_def e1 = {{0}, {0}, "x^2/0.36 + y^2/0.64 + z^2 - 1"};
    const surface_def e2 = {{0}, {0}, "x^2/0.2025 + y^2/0.64 + z^2/1.5625 - 1"};
    if (!open_pair(&tp, &e1, &e2, NULL)) {
        close_pair(&tp);
        return;
    }
    pair = tp.pair;
    /* the paper's point (27/160, 2 sqrt3/5, 5 sqrt7/32) */
    const double P[3] = {27.0 / 160, 2 * sqrt(3.0) / 5, 5 * sqrt(7.0) / 32};
    CHECK(ic_local_locate(pair, &pt, P, &opt, &err) == IC_OK, "Ex 5.1: %s", err.message);
    CHECK(ic_local_apparatus(pair, &res, &pt, 4, IC_METHOD_JET, &opt, &err) == IC_OK, "Ex 5.1");
    CHECK(ic_branch_is_planar(&res.branches[0], 1e-12) && !ic_branch_is_line(&res.branches[0], 1e-12),
          "Ex 5.1 is a plane curve: tau = %g", res.branches[0].tau);
    close_pair(&tp);
}

/* The jet method on implicit primitives, which follow the curve with their
 * own series (one call per order, ic_primitive_along_advance), against the
 * same surfaces written as formulas, composed with the curve's jet at every
 * order: the same equations, the surfaces' coefficients along the curve
 * made two ways, at every order up to the highest (IC_LOCAL_MAX_ORDER), at
 * the same located point, the formulas' coefficients the primitives' own.
 * The orders' Taylor coefficients c^(k)/k! are compared relative to the
 * largest of them: each order's surface coefficients may differ by a few
 * ulps of its terms (the two sum the same products, and here in the same
 * order: measured 0), which the solves of the orders above carry on; a
 * wrong or stale term is off by its whole size (measured 2e-9 to 1e2). */
#define TOL_PRIMITIVE_JETS 1e-13

static void check_primitive_jets(const char *what, const ic_primitive *pa, const ic_primitive *pb,
                                 const char *fa, const char *fb, const double at[3])
{
    ic_surface *s[4] = {NULL, NULL, NULL, NULL};
    ic_pair *prim = NULL, *form = NULL;
    ic_error err;
    if (REQUIRE(ic_surface_new_primitive(&s[0], pa, IC_IMPLICIT, &err) == IC_OK &&
                    ic_surface_new_primitive(&s[1], pb, IC_IMPLICIT, &err) == IC_OK &&
                    ic_surface_new_implicit(&s[2], fa, NULL, 0, &err) == IC_OK &&
                    ic_surface_new_implicit(&s[3], fb, NULL, 0, &err) == IC_OK &&
                    ic_pair_new(&prim, s[0], s[1], &err) == IC_OK &&
                    ic_pair_new(&form, s[2], s[3], &err) == IC_OK,
                "%s: %s", what, err.message)) {
        ic_local_options opt;
        ic_local_defaults(&opt);
        ic_local_point pt;
        static ic_local_result rp, rf;
        const int K = IC_LOCAL_MAX_ORDER;
        if (REQUIRE(ic_local_locate(prim, &pt, at, &opt, &err) == IC_OK &&
                        ic_local_apparatus(prim, &rp, &pt, K, IC_METHOD_JET, &opt, &err) == IC_OK &&
                        ic_local_apparatus(form, &rf, &pt, K, IC_METHOD_JET, &opt, &err) == IC_OK,
                    "%s: %s", what, err.message)) {
            double scale = 0.0, worst = 0.0, fact = 1.0;
            int worst_k = 0;
            for (int k = 1; k <= K; k++) {
                fact *= k;
                for (int c = 0; c < 3; c++) {
                    const double want = rf.branches[0].derivs[k - 1][c] / fact;
                    const double got = rp.branches[0].derivs[k - 1][c] / fact;
                    scale = fmax(scale, fabs(want));
                    if (!(fabs(got - want) <= worst))
                        worst = fabs(got - want), worst_k = k;
                }
            }
            CHECK(worst <= TOL_PRIMITIVE_JETS * scale,
                  "%s: c^(k)/k! differ by %g (of %g) at order %d", what, worst, scale, worst_k);
            printf("%s: primitives against formulas to order %d: %.1e\n", what, K, worst / scale);
        }
    }
    ic_pair_free(prim);
    ic_pair_free(form);
    for (int i = 0; i < 4; i++)
        ic_surface_free(s[i]);
}

static void test_primitive_jets(void)
{
    const double th = 0.7;
    const ic_primitive cyl = {.kind = IC_PRIM_CYLINDER, .center = {1, 0, 0}, .radius = 1};
    const ic_primitive sph = {.kind = IC_PRIM_SPHERE, .radius = 2};
    check_primitive_jets("Viviani", &cyl, &sph, "(x - 1)^2 + y^2 - 1", "x^2 + y^2 + z^2 - 4",
                         (const double[3]){1 + cos(th), sin(th), 2 * sin(th / 2)});
    /* 4x^2 + y^2 + z^2/4 = 1 and x^2 + 4y^2 + 4z^2 = 1 at z = 0.2: 15 y^2 = 2.37 */
    const ic_primitive e1 = {.kind = IC_PRIM_ELLIPSOID, .axes = {0.5, 1, 2}};
    const ic_primitive e2 = {.kind = IC_PRIM_ELLIPSOID, .axes = {1, 0.5, 0.5}};
    const double y = sqrt(2.37 / 15);
    check_primitive_jets("ellipsoids", &e1, &e2, "4*x^2 + y^2 + 0.25*z^2 - 1",
                         "x^2 + 4*y^2 + 4*z^2 - 1",
                         (const double[3]){sqrt((0.99 - y * y) / 4), y, 0.2});
    /* a cone (apex at the origin) and a plane, at x = 0.3 on the plane; the
     * cone's coefficient tan^2 as the primitive makes it */
    const ic_primitive cone = {.kind = IC_PRIM_CONE, .half_angle = atan(0.5)};
    const ic_primitive pl = {.kind = IC_PRIM_PLANE, .center = {0, 0, 1}, .normal = {0, 0.6, 0.8}};
    const double t = tan(cone.half_angle), z = 1 - 0.75 * 0.35;
    char fc[64];
    snprintf(fc, sizeof fc, "x^2 + y^2 - %.17g*z^2", t * t);
    check_primitive_jets("cone and plane", &cone, &pl, fc, "0.6*y + 0.8*(z - 1)",
                         (const double[3]){sqrt(t * t * z * z - 0.35 * 0.35), 0.35, z});
}

int main(int argc, char **argv)
{
    static truth_case cases[64];
    const int n = read_truth(argc > 1 ? argv[1] : "tests/truth/transversal_truth.txt", cases, 64);
    CHECK(n > 0, "truth file read: %d cases", n);
    test_against_truth(cases, n);
    test_locate_params();
    test_errors();
    test_line_and_plane_curve();
    test_primitive_jets();
    return harness_finish("test_local");
}
