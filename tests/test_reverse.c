/* The one orientation map (the house issue, item 2): ic_branch_reverse and
 * ic_trace_points_reverse against an independent computation of the
 * reversed curve. Swapping the two surfaces of a pair reverses the
 * intersection's orientation (t = N_A x N_B becomes N_B x N_A): the whole
 * apparatus of (B, A) at the same point, computed afresh by the library's
 * methods, is the reversed apparatus of (A, B), with the sheets' Darboux
 * quantities and parameter curves swapped. Checked for two implicit
 * surfaces, a parametric and an implicit one, and two parametric ones, at
 * order 8, for every field ic_branch_reverse touches or must leave alone
 * (a reversal that forgets kappa_g, tau' or an odd derivative, or that
 * flips n, tau or tau_g, fails here); and a traced curve's points reversed
 * against the definitions (order, t along it, a right-handed frame). */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "harness.h"
#include "intercurve.h"

/* relative: both apparatus come from the same formulas with the operands
 * of N_A x N_B swapped; rounding differs by a few ulps of each quantity's
 * scale, amplified up to order 8 by the recurrences (the tier of the local
 * apparatus against truth to order 4, harness.h) */
#define REVERSE_TOL TIER_APPARATUS_LOW

#define ORDER 8

typedef struct {
    const char *name;
    const char *A[3], *B[3]; /* implicit: [0] only */
    double dom[2][2];
    double at[3]; /* a transversal point */
} pair_case;

static int make(ic_surface **s, const char *const f[3], const double dom[2][2])
{
    if (!f[1])
        return ic_surface_new_implicit(s, f[0], NULL, 0, NULL) == IC_OK;
    const int per[2] = {0, 0};
    return ic_surface_new_parametric(s, f, NULL, NULL, 0, NULL, NULL) == IC_OK &&
           ic_surface_set_domain(*s, dom, per, NULL) == IC_OK;
}

static double rel(double a, double b) { return fabs(a - b) / fmax(1.0, fmax(fabs(a), fabs(b))); }

static double vec_rel(const double *a, const double *b, int n)
{
    double w = 0;
    for (int i = 0; i < n; i++)
        w = fmax(w, rel(a[i], b[i]));
    return w;
}

/* The worst difference between branches r and q: every field, the sheets
 * swapped when `swap` (r of A, B reversed against q of B, A). */
static double branch_difference(const ic_branch *r, const ic_branch *q, int swap)
{
    double w = fmax(vec_rel(r->t, q->t, 3), fmax(vec_rel(r->n, q->n, 3), vec_rel(r->b, q->b, 3)));
    w = fmax(w, fmax(rel(r->kappa, q->kappa), rel(r->tau, q->tau)));
    w = fmax(w, fmax(rel(r->kappa_prime, q->kappa_prime), rel(r->tau_prime, q->tau_prime)));
    for (int k = 0; k < ORDER; k++)
        w = fmax(w, vec_rel(r->derivs[k], q->derivs[k], 3));
    for (int s = 0; s < 2; s++) {
        const int o = swap ? 1 - s : s;
        const ic_darboux *a = &r->surface[s], *b = &q->surface[o];
        w = fmax(w, fmax(rel(a->kappa_n, b->kappa_n),
                         fmax(rel(a->kappa_g, b->kappa_g), rel(a->tau_g, b->tau_g))));
        for (int k = 0; k < r->param_order && k < q->param_order; k++)
            w = fmax(w, vec_rel(r->param_derivs[s][k], q->param_derivs[o][k], 2));
    }
    return w;
}

static int apparatus(ic_surface *A, ic_surface *B, const double at[3], ic_local_result *res)
{
    ic_pair *pair = NULL;
    ic_local_options opt;
    ic_local_defaults(&opt);
    ic_local_point pt;
    int ok = ic_pair_new(&pair, A, B, NULL) == IC_OK &&
             ic_local_locate(pair, &pt, at, &opt, NULL) == IC_OK &&
             ic_local_apparatus(pair, res, &pt, ORDER, IC_METHOD_JET, &opt, NULL) == IC_OK &&
             res->nbranches == 1;
    ic_pair_free(pair);
    return ok;
}

static void check_branches(const pair_case *c)
{
    ic_surface *A = NULL, *B = NULL;
    ic_local_result ab, ba;
    if (!make(&A, c->A, c->dom) || !make(&B, c->B, c->dom) || !apparatus(A, B, c->at, &ab) ||
        !apparatus(B, A, c->at, &ba)) {
        CHECK(0, "%s: the apparatus both ways", c->name);
    } else {
        ic_branch r = ab.branches[0];
        ic_branch_reverse(&r);
        const double d = branch_difference(&r, &ba.branches[0], 1);
        CHECK(d <= REVERSE_TOL, "%s: reversed branch vs the swapped pair's: %.3g", c->name, d);
        /* and the reversal is not the identity: t moved */
        CHECK(vec_rel(r.t, ab.branches[0].t, 3) > 1, "%s: t not reversed", c->name);
        ic_branch_reverse(&r); /* twice: the branch itself */
        const double twice = branch_difference(&r, &ab.branches[0], 0);
        CHECK(twice == 0, "%s: reversing twice is the identity (%.3g)", c->name, twice);
    }
    ic_surface_free(A);
    ic_surface_free(B);
}

/* Viviani's curve (the sphere x^2 + y^2 + z^2 = 4 and the cylinder
 * (x - 1)^2 + y^2 = 1) traced, its points reversed: the order is reversed,
 * each t points along the new order (t . (x_{i+1} - x_i) > 0), the frame
 * stays right-handed (b = t x n, n unchanged), s increases over the same
 * range, and reversing twice gives the points back. */
static void check_trace_points(void)
{
    ic_surface *S = NULL, *C = NULL;
    ic_pair *pair = NULL;
    ic_trace_result *res = NULL;
    ic_trace_options opt;
    ic_trace_defaults(&opt);
    opt.has_box = 1;
    for (int k = 0; k < 3; k++)
        opt.box[k][0] = -2.5, opt.box[k][1] = 2.5;
    const int ok = ic_surface_new_implicit(&S, "x^2 + y^2 + z^2 - 4", NULL, 0, NULL) == IC_OK &&
                   ic_surface_new_implicit(&C, "(x - 1)^2 + y^2 - 1", NULL, 0, NULL) == IC_OK &&
                   ic_pair_new(&pair, S, C, NULL) == IC_OK &&
                   ic_trace(&res, pair, &opt, NULL) == IC_OK && ic_trace_result_num_curves(res) >= 1;
    CHECK(ok, "Viviani traced");
    if (ok) {
        const ic_trace_curve *a = ic_trace_result_curve(res, 0);
        static ic_trace_point pts[8192];
        const int n = a->npoints < 8192 ? a->npoints : 8192;
        memcpy(pts, a->points, (size_t)n * sizeof *pts);
        ic_trace_points_reverse(pts, n);
        int bad_order = 0, bad_t = 0, bad_frame = 0, bad_s = 0;
        for (int i = 0; i < n; i++) {
            const ic_trace_point *p = &pts[i], *q = &a->points[n - 1 - i];
            bad_order += memcmp(p->xyz, q->xyz, sizeof p->xyz) != 0;
            if (i + 1 < n) {
                double d[3], dot = 0;
                for (int k = 0; k < 3; k++)
                    d[k] = pts[i + 1].xyz[k] - p->xyz[k], dot += d[k] * p->t[k];
                bad_t += !(dot > 0);
                bad_s += !(pts[i + 1].s >= p->s);
            }
            /* b . (t x n) = 1 and n as before */
            const double txn[3] = {p->t[1] * p->n[2] - p->t[2] * p->n[1],
                                   p->t[2] * p->n[0] - p->t[0] * p->n[2],
                                   p->t[0] * p->n[1] - p->t[1] * p->n[0]};
            const double triple = p->b[0] * txn[0] + p->b[1] * txn[1] + p->b[2] * txn[2];
            bad_frame += !(fabs(triple - 1) <= 1e-12) || vec_rel(p->n, q->n, 3) != 0;
        }
        CHECK(!bad_order && !bad_t && !bad_frame && !bad_s,
              "Viviani reversed: %d out of order, %d t against the order, %d frames, %d s", bad_order,
              bad_t, bad_frame, bad_s);
        CHECK(pts[0].s == a->points[0].s && pts[n - 1].s == a->points[n - 1].s,
              "the reversed run covers the same arc length range");
        ic_trace_points_reverse(pts, n);
        /* s -> L - s twice rounds twice: within an ulp of L each */
        int differ = 0;
        for (int i = 0; i < n; i++) {
            const ic_trace_point *p = &pts[i], *q = &a->points[i];
            differ += fabs(p->s - q->s) > 4 * DBL_EPSILON * a->points[n - 1].s;
            differ += memcmp(p->xyz, q->xyz, sizeof p->xyz) || memcmp(p->t, q->t, sizeof p->t) ||
                      memcmp(p->n, q->n, sizeof p->n) || memcmp(p->b, q->b, sizeof p->b) ||
                      memcmp(p->params, q->params, sizeof p->params) || p->kappa != q->kappa ||
                      p->tau != q->tau || p->frame_defined != q->frame_defined;
        }
        CHECK(differ == 0, "reversing twice: %d points differ", differ);
    }
    ic_trace_result_free(res);
    ic_pair_free(pair);
    ic_surface_free(S);
    ic_surface_free(C);
}

int main(void)
{
    static const pair_case cases[] = {
        {"implicit/implicit (Viviani)",
         {"x^2 + y^2 + z^2 - 4"},
         {"(x - 1)^2 + y^2 - 1"},
         {{0, 0}, {0, 0}},
         {1, 1, 1.4142135623730951}},
        /* the graph through (0.5, 0.5, 0.175) and the sphere about the
         * origin through that point */
        {"parametric/implicit (a graph and a sphere)",
         {"u", "v", "0.3*u^2 + 0.2*u*v + 0.1*v"},
         {"x^2 + y^2 + z^2 - 0.530625"},
         {{-2, 2}, {-2, 2}},
         {0.5, 0.5, 0.175}},
        {"parametric/parametric (sphere and cylinder patches)",
         {"2*cos(u)*cos(v)", "2*sin(u)*cos(v)", "2*sin(v)"},
         {"1 + cos(u)", "sin(u)", "v"},
         {{-3, 3}, {-1.5, 1.5}},
         {1, 1, 1.4142135623730951}},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
        check_branches(&cases[i]);
    check_trace_points();
    return harness_finish("reverse");
}
