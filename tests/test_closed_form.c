/* The closed-form methods (the papers' formulas) against the jet method at
 * 1000 random transversal points of random quadric pairs, random analytic
 * parametric pairs and mixed pairs; each paper's own curvature and torsion
 * formulas against the jet values. */
#include <string.h>

#include "harness.h"
#include "local/local_internal.h"

static double worst[4];
static int counted[4];
/* the closed forms by index: implicit pairs, parametric pairs, any mix */
static const char *const PAPERS[3] = {
    "Abdel-All et al. (2012)", "Hassan and Badr (2016)",
    ("Bendrici and Boumedien-Zidani (2022) with Patrikalakis and Maekawa (2002)")};

static double rel(const double *a, const double *b)
{
    const double d = sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                          (a[2] - b[2]) * (a[2] - b[2]));
    return d / fmax(1.0, sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]));
}

/* A random quadric through X: sum q_ij x_i x_j + b.x + c with f(X) = 0. */
static void random_quadric(char *buf, size_t size, const double *X, harness_rng *rng)
{
    double q[6], b[3];
    for (int i = 0; i < 6; i++)
        q[i] = harness_uniform(rng, -1.0, 1.0);
    for (int i = 0; i < 3; i++)
        b[i] = harness_uniform(rng, -1.0, 1.0);
    const double x = X[0], y = X[1], z = X[2];
    const double c = -(q[0] * x * x + q[1] * y * y + q[2] * z * z + q[3] * x * y + q[4] * y * z +
                       q[5] * x * z + b[0] * x + b[1] * y + b[2] * z);
    snprintf(buf, size,
             "%.17g*x^2 + %.17g*y^2 + %.17g*z^2 + %.17g*x*y + %.17g*y*z + %.17g*x*z + %.17g*x + "
             "%.17g*y + %.17g*z + %.17g",
             q[0], q[1], q[2], q[3], q[4], q[5], b[0], b[1], b[2], c);
}

/* A random analytic parametric surface with R(0, 0) = X. */
static void random_parametric(char buf[3][512], const double *X, harness_rng *rng)
{
    for (int k = 0; k < 3; k++) {
        double a[7];
        for (int i = 0; i < 7; i++)
            a[i] = harness_uniform(rng, -1.0, 1.0);
        snprintf(buf[k], sizeof buf[k],
                 "%.17g + %.17g*u + %.17g*v + %.17g*u^2 + %.17g*u*v + %.17g*sin(v)*u + "
                 "%.17g*(cos(u) - 1) + %.17g*(exp(v/2) - 1)*v",
                 X[k], a[0] + (k == 0), a[1] + (k == 1), a[2], a[3], a[4], a[5], a[6]);
    }
}

/* kind: 0 implicit/implicit, 1 parametric/parametric, 2 parametric/implicit.
 * Returns 1 when the point was compared, 0 when it is drawn again (not well
 * transversal, a degenerate sheet), -1 when the setup failed (a failed check). */
static int one_point(int kind, harness_rng *rng)
{
    const double X[3] = {harness_uniform(rng, -1, 1), harness_uniform(rng, -1, 1),
                         harness_uniform(rng, -1, 1)};
    char fA[512], fB[512], pA[3][512], pB[3][512];
    ic_surface *A = NULL, *B = NULL;
    ic_error err;
    const char *xyzA[3] = {pA[0], pA[1], pA[2]}, *xyzB[3] = {pB[0], pB[1], pB[2]};
    ic_status st;
    if (kind == 0) {
        random_quadric(fA, sizeof fA, X, rng);
        random_quadric(fB, sizeof fB, X, rng);
        st = ic_surface_new_implicit(&A, fA, NULL, 0, &err);
        if (st == IC_OK)
            st = ic_surface_new_implicit(&B, fB, NULL, 0, &err);
    } else {
        random_parametric(pA, X, rng);
        st = ic_surface_new_parametric(&A, xyzA, NULL, NULL, 0, NULL, &err);
        if (kind == 1) {
            random_parametric(pB, X, rng);
            if (st == IC_OK)
                st = ic_surface_new_parametric(&B, xyzB, NULL, NULL, 0, NULL, &err);
        } else {
            random_quadric(fB, sizeof fB, X, rng);
            if (st == IC_OK)
                st = ic_surface_new_implicit(&B, fB, NULL, 0, &err);
        }
    }
    ic_pair *pair = NULL;
    int used = -1;
    if (!REQUIRE(st == IC_OK, "kind %d: random surfaces: %s", kind, err.message) ||
        !REQUIRE(ic_pair_new(&pair, A, B, &err) == IC_OK, "kind %d: pair: %s", kind, err.message))
        goto done;
    used = 0;
    ic_local_point pt;
    memset(&pt, 0, sizeof pt);
    memcpy(pt.xyz, X, sizeof pt.xyz);
    ic_sheet sh[2];
    if (ic_sheet_at(pair, &sh[0], 0, &pt, NULL) != IC_OK ||
        ic_sheet_at(pair, &sh[1], 1, &pt, NULL) != IC_OK)
        goto done; /* a degenerate random surface: draw again */
    /* well transversal points only: the angle between the normals >= 0.3 rad,
     * where both methods are well conditioned */
    const double c = fabs(sh[0].geo.normal[0] * sh[1].geo.normal[0] +
                          sh[0].geo.normal[1] * sh[1].geo.normal[1] +
                          sh[0].geo.normal[2] * sh[1].geo.normal[2]);
    if (c > cos(0.3))
        goto done;
    ic_branch jet, closed;
    ic_local_options opt;
    ic_local_defaults(&opt);
    ic_paper_values paper;
    if (!REQUIRE(ic_jet_method(pair, &jet, sh, 3, &err) == IC_OK,
                 "kind %d: the jet method at a transversal point: %s", kind, err.message))
        goto done;
    ic_branch_finish(&jet, sh, &opt);
    ic_status (*methods[3])(ic_branch *, const ic_sheet *, ic_paper_values *, ic_error *) = {
        ic_closed_abdel_all, ic_closed_hassan_badr, ic_closed_patrikalakis_maekawa};
    for (int m = 0; m < 2; m++) {
        /* the pairing's own paper, then the any-mix form (Bendrici and
         * Boumedien-Zidani (2022) with Patrikalakis and Maekawa (2002)) */
        const int which = m == 0 ? kind : 2;
        if (m == 1 && kind == 2)
            break;
        st = methods[which](&closed, sh, &paper, &err);
        CHECK(st == IC_OK, "method %d on kind %d: %s", which, kind, err.message);
        if (st != IC_OK)
            continue;
        /* agreement of two exact methods (the target, harness.h) */
        for (int k = 0; k < 3; k++) {
            const double e = rel(closed.derivs[k], jet.derivs[k]);
            worst[which] = fmax(worst[which], e);
            CHECK(e <= TIER_METHODS_AGREE, "kind %d, %s: c^(%d) differs by %g", kind,
                  PAPERS[which], k + 1, e);
        }
        counted[which]++;
        CHECK(fabs(paper.kappa - jet.kappa) <= TIER_METHODS_AGREE * fmax(1, jet.kappa),
              "paper kappa %.17g vs %.17g", paper.kappa, jet.kappa);
        if (jet.tau_defined)
            CHECK(fabs(paper.tau - jet.tau) <= TIER_METHODS_AGREE * fmax(1, fabs(jet.tau)),
                  "kind %d method %d: paper tau %.17g vs %.17g", kind, which, paper.tau, jet.tau);
        if (which != 1 && kind != 0) /* parameter derivatives u', u'' of the any-mix form */
            for (int k = 0; k < 2; k++)
                CHECK(fabs(closed.param_derivs[0][k][0] - jet.param_derivs[0][k][0]) +
                              fabs(closed.param_derivs[0][k][1] - jet.param_derivs[0][k][1]) <=
                          1e-11 * (1 + fabs(jet.param_derivs[0][k][0]) +
                                   fabs(jet.param_derivs[0][k][1])),
                      "parameter derivatives of order %d", k + 1);
    }
    used = 1;
done:
    ic_pair_free(pair);
    ic_surface_free(A);
    ic_surface_free(B);
    return used;
}

int main(void)
{
    harness_rng rng = {0x853c49e6748fea9bull};
    int points = 0, draws = 0;
    const int want = 1000 * harness_multiplier();
    while (points < want && draws < 20 * want) {
        const int r = one_point(draws % 3, &rng);
        draws++;
        if (r > 0)
            points++;
    }
    CHECK(points == want, "transversal random points: %d of %d", points, want);
    printf("%d random points; worst relative difference to the jet method: %s %.2g (%d), "
           "%s %.2g (%d), %s %.2g (%d)\n",
           points, PAPERS[1], worst[1], counted[1], PAPERS[0], worst[0], counted[0], PAPERS[2],
           worst[2], counted[2]);
    return harness_finish("test_closed_form");
}
