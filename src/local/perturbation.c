/*
 * The perturbation method at a tangential point (Bendrici and
 * Boumedien-Zidani (2022), section 3; docs/references.md).
 *
 * Singular points (3.1)-(3.3): the intersection points P(rho) on circles of
 * radius rho around P in the tangent plane are transversal; T (3.2) and n
 * (3.3) are the limits of their transversal values. Heights of each surface
 * above the circle are found pointwise by Newton along N (no series), the
 * roots of h_A - h_B on the circle give the points, the transversal jet
 * apparatus gives t, n, kappa, tau there. The two halves of a branch (at
 * angles phi and about phi + pi) are averaged, which cancels the O(rho)
 * terms, and the averages are Richardson-extrapolated in rho^2.
 * Tangential curves (3.4): B is shifted along N by epsilon, the two
 * transversal curves near P are found on the line through P across the
 * curve, averaged and extrapolated in epsilon.
 */
#include "tangential.h"
#include "common/mathconst.h"
#include "common/vec3.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define LEVELS 4
#define MAX_ROOTS 16

typedef struct {
    ic_jet_space *sp1[2]; /* order-1 spaces of 2 and 3 variables */
    double P[3], N[3], e1[3], e2[3];
} pctx;

/* Height h of sheet s above Q along N: f(Q + h N) = 0, or R(u, v) = Q + h N
 * (uv in: a start, out: the solution). */
static int point_height(const pctx *c, const ic_sheet *sh, const double *Q, double shift,
                        double *h, double *uv)
{
    double t[20];
    *h = 0.0;
    for (int it = 0; it < 60; it++) {
        if (sh->parametric) {
            if (ic_surface_taylor(sh->s, t, uv, c->sp1[0], NULL) != IC_OK)
                return -1;
            double F[3], A[3][3];
            for (int k = 0; k < 3; k++) {
                F[k] = t[3 * k] + shift * c->N[k] - Q[k] - *h * c->N[k];
                A[k][0] = t[3 * k + 1], A[k][1] = t[3 * k + 2], A[k][2] = -c->N[k];
            }
            /* Cramer's rule on [R_u R_v -N] */
            const double det = ic_det3((double[3]){A[0][0], A[1][0], A[2][0]},
                                       (double[3]){A[0][1], A[1][1], A[2][1]},
                                       (double[3]){A[0][2], A[1][2], A[2][2]});
            if (det == 0.0)
                return -1;
            double x[3];
            for (int j = 0; j < 3; j++) {
                double col[3][3];
                for (int r = 0; r < 3; r++)
                    for (int q = 0; q < 3; q++)
                        col[q][r] = q == j ? F[r] : A[r][q];
                x[j] = ic_det3(col[0], col[1], col[2]) / det;
            }
            uv[0] -= x[0], uv[1] -= x[1], *h -= x[2];
            if (fabs(x[0]) + fabs(x[1]) + fabs(x[2]) <= 1e-15 * (1 + fabs(*h)))
                return 0;
        } else {
            double X[3];
            ic_axpy3(X, Q, *h - shift, c->N);
            if (ic_surface_taylor(sh->s, t, X, c->sp1[1], NULL) != IC_OK)
                return -1;
            const double fN = t[1] * c->N[0] + t[2] * c->N[1] + t[3] * c->N[2];
            if (fN == 0.0)
                return -1;
            *h -= t[0] / fN;
            if (fabs(t[0] / fN) <= 1e-15 * (1 + fabs(*h)))
                return 0;
        }
    }
    return 0;
}

typedef struct {
    double X[3], uv[2][2];
} found_point;

/* g(Q) = h_A(Q) - h_B(Q) - shift for Q = P + a e + b e' ; uv carried along. */
static int height_gap(const pctx *c, const ic_sheet sh[2], const double *Q, double shift,
                      double uv[2][2], double *gap, double *hA)
{
    double h[2];
    for (int s = 0; s < 2; s++)
        if (point_height(c, &sh[s], Q, s == 1 ? shift : 0.0, &h[s], uv[s]) != 0)
            return -1;
    *gap = h[0] - h[1];
    *hA = h[0];
    return 0;
}

static void circle_point(const pctx *c, double rho, double phi, double *Q)
{
    for (int k = 0; k < 3; k++)
        Q[k] = c->P[k] + rho * (cos(phi) * c->e1[k] + sin(phi) * c->e2[k]);
}

/* Roots of the height gap on the circle of radius rho. */
static int circle_roots(const pctx *c, const ic_sheet sh[2], double rho, found_point *out)
{
    const int M = 720;
    double uv[2][2], prev = 0.0, Q[3], hA;
    memcpy(uv[0], sh[0].at, sizeof uv[0]);
    memcpy(uv[1], sh[1].at, sizeof uv[1]);
    int n = 0;
    for (int k = 0; k <= M && n < MAX_ROOTS; k++) {
        const double phi = 2 * IC_PI * k / M;
        double gap;
        circle_point(c, rho, phi, Q);
        if (height_gap(c, sh, Q, 0.0, uv, &gap, &hA) != 0)
            return -1;
        if (k > 0 && (prev < 0) != (gap < 0)) {
            double lo = 2 * IC_PI * (k - 1) / M, hi = phi, glo = prev, buv[2][2];
            memcpy(buv, uv, sizeof buv);
            for (int it = 0; it < 60; it++) {
                const double mid = 0.5 * (lo + hi);
                double gm;
                circle_point(c, rho, mid, Q);
                if (height_gap(c, sh, Q, 0.0, buv, &gm, &hA) != 0)
                    return -1;
                if ((gm < 0) == (glo < 0))
                    lo = mid, glo = gm;
                else
                    hi = mid;
            }
            ic_axpy3(out[n].X, Q, hA, c->N);
            memcpy(out[n].uv, buv, sizeof buv);
            n++;
        }
        prev = gap;
    }
    return n;
}

/* The transversal apparatus at a found point, t oriented away from P. The
 * point is first refined onto the intersection: near P the angle a between
 * the normals is small, and a point off the curve by r would change the
 * order-k quantities by about r / a^k. */
static int transversal_at(ic_pair *pair, const found_point *fp, const pctx *c,
                          const ic_local_options *opt, ic_branch *br)
{
    ic_local_point pt;
    ic_local_options o = *opt;
    o.tangential_angle = 0.0; /* near P the angle is small but nonzero */
    ic_status st = ic_local_locate_guess(pair, &pt, fp->X, fp->uv, &o, NULL);
    ic_local_result r;
    if (st != IC_OK || ic_local_apparatus(pair, &r, &pt, 3, IC_METHOD_JET, &o, NULL) != IC_OK ||
        r.type != IC_POINT_TRANSVERSAL)
        return -1;
    *br = r.branches[0];
    double d[3];
    ic_axpy3(d, pt.xyz, -1.0, c->P);
    if (ic_dot3(d, br->t) < 0)
        ic_branch_reverse(br);
    if (!br->frame_defined) /* a straight branch: kappa = 0, no n */
        br->tau = 0.0;
    return 0;
}

/* t and the curvature vector K = c'' = kappa n (the same on both halves of a
 * branch, and well defined where kappa is at noise level), and tau */
typedef struct {
    double t[3], K[3], tau;
} estimate;

/* Average of the two halves of a branch (second half reversed). */
static estimate average(const ic_branch *a, const ic_branch *b, int reverse_b)
{
    estimate e;
    const double s = reverse_b ? -1.0 : 1.0;
    for (int k = 0; k < 3; k++) {
        e.t[k] = 0.5 * (a->t[k] + s * b->t[k]);
        e.K[k] = 0.5 * (a->derivs[1][k] + b->derivs[1][k]);
    }
    ic_normalize3(e.t);
    e.tau = 0.5 * (a->tau + b->tau);
    return e;
}

/* Richardson extrapolation of LEVELS estimates in steps h^2 halving by 4. */
static estimate richardson(estimate *v, int levels, double *change)
{
    for (int l = 1; l < levels; l++) {
        const double q = pow(4.0, l);
        for (int i = 0; i + l < levels; i++) {
            estimate *a = &v[i], *b = &v[i + 1];
            for (int k = 0; k < 3; k++) {
                a->t[k] = (q * b->t[k] - a->t[k]) / (q - 1);
                a->K[k] = (q * b->K[k] - a->K[k]) / (q - 1);
            }
            a->tau = (q * b->tau - a->tau) / (q - 1);
        }
        if (l == levels - 1 && change) {
            /* the last step's size: how much the extrapolation still moved */
            double m = 0.0;
            for (int k = 0; k < 3; k++)
                m = fmax(m, fmax(fabs(v[0].t[k] - v[1].t[k]), fabs(v[0].K[k] - v[1].K[k])));
            *change = m;
        }
    }
    ic_normalize3(v[0].t);
    return v[0];
}

static void store(ic_branch *br, const estimate *e, const ic_sheet sh[2],
                  const ic_local_options *opt)
{
    memset(br, 0, sizeof *br);
    br->order = 2;
    br->regular = 1;
    memcpy(br->derivs[0], e->t, sizeof e->t);
    memcpy(br->derivs[1], e->K, sizeof e->K);
    ic_branch_finish(br, sh, opt);
    br->tau = e->tau;
    br->tau_defined = br->frame_defined;
    /* the orientation of the other methods: first clearly nonzero t_i > 0 */
    for (int k = 0; k < 3; k++)
        if (fabs(br->t[k]) > 1e-9) {
            if (br->t[k] < 0) {
                ic_scale3(br->t, br->t, -1.0);
                ic_scale3(br->b, br->b, -1.0);
                ic_scale3(br->derivs[0], br->derivs[0], -1.0);
                for (int s = 0; s < 2; s++)
                    br->surface[s].kappa_g = -br->surface[s].kappa_g;
            }
            break;
        }
}

/* Pairs the halves found on one circle: cost |t_i + t_j| + |K_i - K_j|. */
static int pair_halves(const ic_branch *h, int n, estimate *out)
{
    int used[MAX_ROOTS] = {0}, count = 0;
    for (int i = 0; i < n; i++) {
        if (used[i])
            continue;
        int best = -1;
        double bc = INFINITY;
        for (int j = 0; j < n; j++) {
            if (j == i || used[j])
                continue;
            double st[3], dk[3];
            ic_axpy3(st, h[i].t, 1.0, h[j].t);
            ic_axpy3(dk, h[i].derivs[1], -1.0, h[j].derivs[1]);
            const double cost = ic_norm3(st) + ic_norm3(dk) / fmax(1.0, ic_norm3(h[i].derivs[1]));
            if (cost < bc)
                bc = cost, best = j;
        }
        if (best < 0 || bc > 0.5)
            return -1; /* no opposite half: not a smooth branch (a cusp) */
        used[i] = used[best] = 1;
        out[count++] = average(&h[i], &h[best], 1);
    }
    return count;
}

static ic_status singular_point(ic_pair *pair, ic_local_result *res, const ic_sheet sh[2],
                                const pctx *c, double L, const ic_local_options *opt,
                                ic_error *err)
{
    estimate lev[IC_LOCAL_MAX_BRANCHES][LEVELS];
    int nb = -1;
    for (int l = 0; l < LEVELS; l++) {
        const double rho = 0.05 * L / pow(2.0, l);
        found_point fp[MAX_ROOTS];
        ic_branch halves[MAX_ROOTS];
        const int n = circle_roots(c, sh, rho, fp);
        if (n < 0)
            return ic_error_set(err, IC_ERR_UNABLE, 0, "perturbation: heights not found");
        for (int i = 0; i < n; i++)
            if (transversal_at(pair, &fp[i], c, opt, &halves[i]) != 0)
                return ic_error_set(err, IC_ERR_UNABLE, 0,
                                    "perturbation: a nearby point is not transversal");
        estimate e[MAX_ROOTS];
        const int m = pair_halves(halves, n, e);
        if (m < 0)
            return ic_error_set(err, IC_ERR_UNABLE, 0,
                                "perturbation: the branches do not come in opposite halves "
                                "(a cusp is not resolved by this method)");
        if (nb < 0)
            nb = m;
        if (m != nb || m > IC_LOCAL_MAX_BRANCHES)
            return ic_error_set(err, IC_ERR_UNABLE, 0,
                                "perturbation: %d branches at radius %g, %d before", m, rho, nb);
        /* match to the branches of the first level by tangent, then curvature vector */
        for (int b = 0; b < m; b++) {
            int best = b;
            double bc = INFINITY;
            for (int j = 0; j < m && l > 0; j++) {
                double kn[3];
                ic_axpy3(kn, e[j].K, -1.0, lev[b][0].K);
                const double cost = 1 - fabs(ic_dot3(e[j].t, lev[b][0].t)) + ic_norm3(kn);
                if (cost < bc)
                    bc = cost, best = j;
            }
            lev[b][l] = e[best];
            if (ic_dot3(lev[b][l].t, lev[b][0].t) < 0)
                ic_scale3(lev[b][l].t, lev[b][l].t, -1.0);
        }
    }
    res->nbranches = nb;
    res->error_estimate = 0.0;
    for (int b = 0; b < nb; b++) {
        double change;
        estimate e = richardson(lev[b], LEVELS, &change);
        res->error_estimate = fmax(res->error_estimate, change);
        store(&res->branches[b], &e, sh, opt);
    }
    return IC_OK;
}

/* A cusp (Bendrici and Boumedien-Zidani (2022), Example 2): both
 * half-branches leave P on one side, each a root of the circle; t and n at
 * the nearby points converge like rho^(1/2), so the radii shrink by 4 and
 * Richardson works in sqrt(rho) (ratio 2). The curvature diverges: the
 * half-branches get one-sided t, n, b only. */
static ic_status cusp(ic_pair *pair, ic_local_result *res, const ic_sheet sh[2], const pctx *c,
                      double L, const ic_local_options *opt, ic_error *err)
{
    double t[2][LEVELS][3], n[2][LEVELS][3];
    for (int l = 0; l < LEVELS; l++) {
        const double rho = 0.05 * L / pow(4.0, l);
        found_point fp[MAX_ROOTS];
        ic_branch half[MAX_ROOTS];
        const int m = circle_roots(c, sh, rho, fp);
        if (m != 2)
            return ic_error_set(err, IC_ERR_UNABLE, 0,
                                "perturbation: %d nearby points of the cusp at radius %g, not 2",
                                m, rho);
        for (int i = 0; i < 2; i++)
            if (transversal_at(pair, &fp[i], c, opt, &half[i]) != 0 || !half[i].frame_defined)
                return ic_error_set(err, IC_ERR_UNABLE, 0,
                                    "perturbation: a nearby point of the cusp is not transversal");
        for (int i = 0; i < 2; i++) { /* keep each half-branch by the side of its normal */
            const int k = l == 0 ? i : (ic_dot3(half[i].n, n[0][0]) > 0 ? 0 : 1);
            memcpy(t[k][l], half[i].t, sizeof t[k][l]);
            memcpy(n[k][l], half[i].n, sizeof n[k][l]);
        }
    }
    res->error_estimate = 0.0;
    for (int k = 0; k < 2; k++) {
        for (int lev = 1; lev < LEVELS; lev++) { /* Richardson in sqrt(rho), ratio 2 */
            const double q = pow(2.0, lev);
            for (int i = 0; i + lev < LEVELS; i++)
                for (int d = 0; d < 3; d++) {
                    t[k][i][d] = (q * t[k][i + 1][d] - t[k][i][d]) / (q - 1);
                    n[k][i][d] = (q * n[k][i + 1][d] - n[k][i][d]) / (q - 1);
                }
            if (lev == LEVELS - 1)
                for (int d = 0; d < 3; d++)
                    res->error_estimate = fmax(res->error_estimate,
                                               fmax(fabs(t[k][0][d] - t[k][1][d]),
                                                    fabs(n[k][0][d] - n[k][1][d])));
        }
        ic_branch *br = &res->branches[k];
        memset(br, 0, sizeof *br);
        br->order = 1;
        br->regular = 0;
        br->frame_defined = 1;
        memcpy(br->t, t[k][0], sizeof br->t);
        memcpy(br->n, n[k][0], sizeof br->n);
        ic_normalize3(br->t);
        ic_axpy3(br->n, br->n, -ic_dot3(br->n, br->t), br->t); /* orthonormal */
        ic_normalize3(br->n);
        ic_cross3(br->b, br->t, br->n);
        memcpy(br->derivs[0], br->t, sizeof br->t);
    }
    res->nbranches = 2;
    return IC_OK;
}

/* B shifted by `shift` along N: a callback surface over the original. */
typedef struct {
    ic_surface *base;
    double shift[3];
} shifted_surface;

static int shifted_eval(void *user, double *derivs, const double *at, const ic_jet_space *sp)
{
    const shifted_surface *ss = user;
    const int parametric = ic_surface_get_kind(ss->base) == IC_PARAMETRIC;
    const int n = ic_jet_space_len(sp);
    double x[3];
    if (parametric) {
        x[0] = at[0], x[1] = at[1];
    } else {
        for (int k = 0; k < 3; k++)
            x[k] = at[k] - ss->shift[k];
    }
    if (ic_surface_taylor(ss->base, derivs, x, sp, NULL) != IC_OK)
        return 1;
    const int nout = parametric ? 3 : 1;
    for (int k = 0; k < nout; k++) {
        if (parametric)
            derivs[k * n] += ss->shift[k];
        for (int i = 0; i < n; i++)
            derivs[k * n + i] *= ic_jet_factorial(sp, i);
    }
    return 0;
}

static ic_status tangential_curve(ic_local_result *res, const ic_sheet sh[2], const pctx *c,
                                  double L, const ic_local_options *opt, ic_error *err)
{
    /* the direction across the curve: the eigenvector of II_A - II_B (both
     * relative to N) with the largest eigenvalue in magnitude */
    const double sB = ic_dot3(sh[1].geo.normal, c->N) < 0 ? -1.0 : 1.0;
    double d[3];
    double D[2][2];
    const double *E[2] = {c->e1, c->e2};
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++)
            D[i][j] = ic_sheet_second_form(&sh[0], E[i], E[j]) -
                      sB * ic_sheet_second_form(&sh[1], E[i], E[j]);
    const double m = 0.5 * (D[0][0] + D[1][1]), dd = 0.5 * (D[0][0] - D[1][1]);
    const double root = hypot(dd, D[0][1]);
    const double lam = fabs(m + root) >= fabs(m - root) ? m + root : m - root;
    const double th = 0.5 * atan2(D[0][1], dd) + (lam == m + root ? 0.0 : 0.5 * IC_PI);
    for (int k = 0; k < 3; k++)
        d[k] = cos(th) * c->e1[k] + sin(th) * c->e2[k];
    estimate lev[LEVELS];
    for (int l = 0; l < LEVELS; l++) {
        const double lam0 = 0.05 * L / pow(2.0, l);
        const double eps = 0.5 * lam * lam0 * lam0; /* h_A - h_B = eps at +-lam0 */
        shifted_surface ss = {sh[1].s, {eps * c->N[0], eps * c->N[1], eps * c->N[2]}};
        ic_surface *Be = NULL;
        ic_pair *pe = NULL;
        ic_status st = ic_surface_new_callback(&Be, ic_surface_get_kind(sh[1].s), shifted_eval,
                                               &ss, err);
        if (st == IC_OK)
            st = ic_pair_new(&pe, sh[0].s, Be, err);
        ic_branch half[2];
        for (int side = 0; side < 2 && st == IC_OK; side++) {
            /* Newton on the gap along the line P + a d, from a = +-lam0 */
            double a = side ? -lam0 : lam0, uv[2][2], Q[3], gap = 0.0, hA = 0.0;
            memcpy(uv[0], sh[0].at, sizeof uv[0]);
            memcpy(uv[1], sh[1].at, sizeof uv[1]);
            for (int it = 0; it < 60; it++) {
                double g1, Q1[3];
                ic_axpy3(Q, c->P, a, d);
                ic_axpy3(Q1, c->P, a * (1 + 1e-7), d);
                double uv1[2][2];
                memcpy(uv1, uv, sizeof uv1);
                if (height_gap(c, sh, Q, eps, uv, &gap, &hA) != 0 ||
                    height_gap(c, sh, Q1, eps, uv1, &g1, &hA) != 0) {
                    st = ic_error_set(err, IC_ERR_UNABLE, 0, "perturbation: heights not found");
                    break;
                }
                const double slope = (g1 - gap) / (a * 1e-7);
                const double step = gap / slope;
                a -= step;
                if (fabs(step) <= 1e-15 * lam0)
                    break;
            }
            if (st != IC_OK)
                break;
            ic_axpy3(Q, c->P, a, d);
            if (height_gap(c, sh, Q, eps, uv, &gap, &hA) != 0)
                st = ic_error_set(err, IC_ERR_UNABLE, 0, "perturbation: heights not found");
            found_point fp;
            ic_axpy3(fp.X, Q, hA, c->N);
            memcpy(fp.uv, uv, sizeof uv);
            if (transversal_at(pe, &fp, c, opt, &half[side]) != 0)
                st = ic_error_set(err, IC_ERR_UNABLE, 0,
                                  "perturbation: a point of the shifted problem is not "
                                  "transversal");
        }
        if (st == IC_OK)
            lev[l] = average(&half[0], &half[1], ic_dot3(half[0].t, half[1].t) < 0);
        ic_pair_free(pe);
        ic_surface_free(Be);
        if (st != IC_OK)
            return st;
        if (l > 0 && ic_dot3(lev[l].t, lev[0].t) < 0)
            ic_scale3(lev[l].t, lev[l].t, -1.0);
    }
    double change;
    estimate e = richardson(lev, LEVELS, &change);
    res->error_estimate = change;
    res->nbranches = 1;
    store(&res->branches[0], &e, sh, opt);
    return IC_OK;
}

ic_status ic_perturbation(ic_pair *pair, ic_local_result *res, const ic_sheet sh[2],
                          const ic_local_options *opt, ic_error *err)
{
    pctx c;
    memset(&c, 0, sizeof c);
    memcpy(c.N, sh[0].geo.normal, sizeof c.N);
    memcpy(c.P, sh[0].parametric ? sh[0].geo.point : sh[0].at, sizeof c.P);
    memcpy(c.e1, sh[0].geo.basis[0], sizeof c.e1);
    ic_axpy3(c.e1, c.e1, -ic_dot3(c.e1, c.N), c.N);
    ic_normalize3(c.e1);
    ic_cross3(c.e2, c.N, c.e1);
    /* the length scale: the largest principal curvature radius involved */
    double kmax = 0.0;
    for (int s = 0; s < 2; s++)
        for (int i = 0; i < 2; i++)
            kmax = fmax(kmax, fabs(sh[s].geo.principal_curvatures[i]));
    const double L = kmax > 0 ? fmin(1.0 / kmax, 1.0) : 1.0;
    ic_status st = ic_jet_space_new(&c.sp1[0], 2, 1, err);
    if (st == IC_OK)
        st = ic_jet_space_new(&c.sp1[1], 3, 1, err);
    if (st == IC_OK) {
        switch (res->type) {
        case IC_POINT_ISOLATED_CONTACT:
            res->nbranches = 0;
            break;
        case IC_POINT_TANGENTIAL_CURVE:
            st = tangential_curve(res, sh, &c, L, opt, err);
            break;
        case IC_POINT_CUSP:
            st = cusp(pair, res, sh, &c, L, opt, err);
            break;
        default:
            st = singular_point(pair, res, sh, &c, L, opt, err);
        }
    }
    ic_jet_space_free(c.sp1[0]);
    ic_jet_space_free(c.sp1[1]);
    return st;
}
