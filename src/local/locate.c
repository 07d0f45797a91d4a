/*
 * Locating a point of the intersection.
 *
 * 1. Each parametric sheet: the parameters of the surface point closest to
 *    the given coordinates, by a grid search and a damped Newton iteration on
 *    |R(u, v) - X|^2 (several local minima are kept: a self-intersection has
 *    two preimages). Each implicit sheet: the distance by Newton projection
 *    along the gradient.
 * 2. A point farther than opt->point_tol from either surface is an error that
 *    says how far. When locating fails, pt->residual keeps the largest
 *    distance of the given point measured so far (infinite off an implicit
 *    sheet whose gradient vanishes there), so a caller can say first that
 *    the point is not on the surfaces.
 * 3. Refinement onto both surfaces: Newton on the equations of the pairing
 *    plus t . (X - X0) = 0, i.e. in the plane through X0 normal to the curve.
 */
#include "common/args.h"
#include "local_internal.h"
#include "common/vec3.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#define MAX_CANDIDATES 8

typedef struct {
    double uv[2];
    double dist;
} candidate;

/* Point, first and second derivatives of a parametric surface. */
static ic_status param_eval2(ic_pair *pair, ic_surface *s, const double *uv, double *R,
                             double Ru[3], double Rv[3], double Ruu[3], double Ruv[3],
                             double Rvv[3], ic_error *err)
{
    double t[18]; /* order 2: 1, u, v, u^2, uv, v^2 per component */
    ic_status st = ic_surface_taylor(s, t, uv, pair->near[0], err);
    if (st != IC_OK)
        return st;
    for (int k = 0; k < 3; k++) {
        R[k] = t[6 * k];
        Ru[k] = t[6 * k + 1];
        Rv[k] = t[6 * k + 2];
        Ruu[k] = 2 * t[6 * k + 3];
        Ruv[k] = t[6 * k + 4];
        Rvv[k] = 2 * t[6 * k + 5];
    }
    return IC_OK;
}

/* Value and gradient of an implicit surface. */
static ic_status implicit_eval1(ic_pair *pair, ic_surface *s, const double *x, double *f,
                                double grad[3], ic_error *err)
{
    double t[10];
    ic_status st = ic_surface_taylor(s, t, x, pair->near[1], err);
    if (st != IC_OK)
        return st;
    *f = t[0];
    grad[0] = t[1], grad[1] = t[2], grad[2] = t[3];
    return IC_OK;
}

/* The searchable box of a parameter: its domain, with infinite ends
 * replaced by a range scaled to the target point. */
static void search_range(double range[2][2], int periodic[2], const ic_surface *s,
                         const double *xyz)
{
    double domain[2][2];
    ic_surface_get_domain(s, domain, periodic);
    const double reach = 10.0 * (1.0 + ic_norm3(xyz));
    for (int i = 0; i < 2; i++) {
        range[i][0] = isfinite(domain[i][0]) ? domain[i][0] : -reach;
        range[i][1] = isfinite(domain[i][1]) ? domain[i][1] : reach;
    }
}

/* Keeps periodic parameters in their period, others in their domain. */
static void wrap(double *uv, const double domain[2][2], const int periodic[2])
{
    for (int i = 0; i < 2; i++) {
        const double lo = domain[i][0], hi = domain[i][1];
        if (periodic[i]) {
            const double w = hi - lo;
            uv[i] = lo + fmod(fmod(uv[i] - lo, w) + w, w);
        } else {
            if (uv[i] < lo)
                uv[i] = lo;
            if (uv[i] > hi)
                uv[i] = hi;
        }
    }
}

/* Damped Newton on |R(u, v) - X|^2 from uv. */
static ic_status closest_newton(ic_pair *pair, ic_surface *s, double *uv, double *dist,
                                const double *X, const ic_local_options *opt, ic_error *err)
{
    double domain[2][2];
    int periodic[2];
    ic_surface_get_domain(s, domain, periodic);
    double R[3], Ru[3], Rv[3], Ruu[3], Ruv[3], Rvv[3], d[3];
    ic_status st = param_eval2(pair, s, uv, R, Ru, Rv, Ruu, Ruv, Rvv, err);
    if (st != IC_OK)
        return st;
    ic_axpy3(d, R, -1.0, X);
    double f = ic_dot3(d, d);
    for (int it = 0; it < opt->max_newton; it++) {
        const double g[2] = {ic_dot3(d, Ru), ic_dot3(d, Rv)};
        double H[3] = {ic_dot3(Ru, Ru) + ic_dot3(d, Ruu), ic_dot3(Ru, Rv) + ic_dot3(d, Ruv),
                       ic_dot3(Rv, Rv) + ic_dot3(d, Rvv)};
        double det = H[0] * H[2] - H[1] * H[1];
        if (!(H[0] > 0 && det > 0)) { /* not convex here: Gauss-Newton */
            H[0] = ic_dot3(Ru, Ru), H[1] = ic_dot3(Ru, Rv), H[2] = ic_dot3(Rv, Rv);
            det = H[0] * H[2] - H[1] * H[1];
            if (!(det > 0))
                break; /* degenerate point: keep what we have */
        }
        double step[2] = {-(H[2] * g[0] - H[1] * g[1]) / det, -(H[0] * g[1] - H[1] * g[0]) / det};
        double lambda = 1.0, trial[2], fn = f;
        int accepted = 0;
        for (int h = 0; h < 40; h++, lambda *= 0.5) {
            trial[0] = uv[0] + lambda * step[0];
            trial[1] = uv[1] + lambda * step[1];
            wrap(trial, domain, periodic);
            st = param_eval2(pair, s, trial, R, Ru, Rv, Ruu, Ruv, Rvv, NULL);
            if (st != IC_OK)
                continue;
            double dn[3];
            ic_axpy3(dn, R, -1.0, X);
            fn = ic_dot3(dn, dn);
            if (fn <= f) {
                accepted = 1;
                memcpy(d, dn, sizeof d);
                break;
            }
        }
        if (!accepted)
            break;
        const double moved = fabs(trial[0] - uv[0]) + fabs(trial[1] - uv[1]);
        uv[0] = trial[0], uv[1] = trial[1];
        const double before = f;
        f = fn;
        if (moved <= 4 * DBL_EPSILON * (1 + fabs(uv[0]) + fabs(uv[1])) || before - f <= 0.0)
            break;
    }
    /* derivatives at the final point for the caller's next use */
    st = param_eval2(pair, s, uv, R, Ru, Rv, Ruu, Ruv, Rvv, err);
    if (st != IC_OK)
        return st;
    ic_axpy3(d, R, -1.0, X);
    *dist = ic_norm3(d);
    return IC_OK;
}

ic_status ic_local_project(ic_pair *pair, int which, double uv[2], const double X[3],
                           const ic_local_options *opt, double *dist)
{
    return closest_newton(pair, ic_pair_surface(pair, which), uv, dist, X, opt, NULL);
}

static double param_distance(const double *a, const double *b, const double domain[2][2],
                             const int periodic[2])
{
    double d = 0.0;
    for (int i = 0; i < 2; i++) {
        double delta = fabs(a[i] - b[i]);
        if (periodic[i])
            delta = fmin(delta, (domain[i][1] - domain[i][0]) - delta);
        d = fmax(d, delta);
    }
    return d;
}

/* Local minima of the distance on a grid, refined by Newton: the distinct
 * ones, nearest first. */
static ic_status closest_candidates(ic_pair *pair, ic_surface *s, const double *X, candidate *out,
                                    int *count, const ic_local_options *opt, ic_error *err)
{
    double range[2][2], domain[2][2];
    int periodic[2];
    search_range(range, periodic, s, X);
    ic_surface_get_domain(s, domain, periodic);
    const int g = opt->grid > 2 ? opt->grid : 3;
    double dist2[65][65];
    const int n = g > 64 ? 64 : g;
    for (int i = 0; i <= n; i++)
        for (int j = 0; j <= n; j++) {
            const double uv[2] = {range[0][0] + (range[0][1] - range[0][0]) * i / n,
                                  range[1][0] + (range[1][1] - range[1][0]) * j / n};
            double R[3];
            dist2[i][j] = INFINITY;
            if (ic_surface_eval(s, R, uv, NULL) == IC_OK) {
                double d[3];
                ic_axpy3(d, R, -1.0, X);
                dist2[i][j] = ic_dot3(d, d);
            }
        }
    /* grid local minima (with wrap-around on periodic parameters) */
    candidate seeds[64];
    int nseeds = 0;
    for (int i = 0; i <= n; i++)
        for (int j = 0; j <= n; j++) {
            int is_min = isfinite(dist2[i][j]);
            for (int di = -1; di <= 1 && is_min; di++)
                for (int dj = -1; dj <= 1 && is_min; dj++) {
                    int a = i + di, b = j + dj;
                    if (periodic[0])
                        a = (a + n) % n;
                    if (periodic[1])
                        b = (b + n) % n;
                    if (a < 0 || a > n || b < 0 || b > n || (di == 0 && dj == 0))
                        continue;
                    if (dist2[a][b] < dist2[i][j])
                        is_min = 0;
                }
            if (is_min && nseeds < 64) {
                seeds[nseeds].uv[0] = range[0][0] + (range[0][1] - range[0][0]) * i / n;
                seeds[nseeds].uv[1] = range[1][0] + (range[1][1] - range[1][0]) * j / n;
                seeds[nseeds].dist = dist2[i][j];
                nseeds++;
            }
        }
    /* the nearest seeds first */
    for (int a = 1; a < nseeds; a++)
        for (int b = a; b > 0 && seeds[b].dist < seeds[b - 1].dist; b--) {
            candidate tmp = seeds[b];
            seeds[b] = seeds[b - 1];
            seeds[b - 1] = tmp;
        }
    *count = 0;
    for (int k = 0; k < nseeds && k < 16; k++) {
        candidate c = seeds[k];
        ic_status st = closest_newton(pair, s, c.uv, &c.dist, X, opt, err);
        if (st != IC_OK)
            continue;
        int dup = 0;
        for (int m = 0; m < *count; m++)
            if (param_distance(out[m].uv, c.uv, domain, periodic) <= opt->distinct_params) {
                dup = 1;
                if (c.dist < out[m].dist)
                    out[m] = c;
            }
        if (!dup && *count < MAX_CANDIDATES)
            out[(*count)++] = c;
    }
    for (int a = 1; a < *count; a++)
        for (int b = a; b > 0 && out[b].dist < out[b - 1].dist; b--) {
            candidate tmp = out[b];
            out[b] = out[b - 1];
            out[b - 1] = tmp;
        }
    if (*count == 0)
        return ic_error_set(err, IC_ERR_UNABLE, 0,
                            "no point of the surface could be evaluated near the given point");
    return IC_OK;
}

/* Distance of X to an implicit surface: Newton projection along the gradient. */
static ic_status implicit_distance(ic_pair *pair, ic_surface *s, const double *X, double *dist,
                                   const ic_local_options *opt, ic_error *err)
{
    double Y[3] = {X[0], X[1], X[2]}, f, grad[3];
    for (int it = 0; it < opt->max_newton; it++) {
        ic_status st = implicit_eval1(pair, s, Y, &f, grad, err);
        if (st != IC_OK)
            return st;
        const double g2 = ic_dot3(grad, grad);
        if (!(g2 > 0.0)) {
            double moved[3];
            ic_axpy3(moved, Y, -1.0, X);
            *dist = f == 0.0 ? ic_norm3(moved) : INFINITY; /* f != 0: off, by no known length */
            return ic_error_set(err, IC_ERR_DOMAIN, 0,
                                "grad f = 0 at (%.17g, %.17g, %.17g): the implicit surface is "
                                "singular there",
                                Y[0], Y[1], Y[2]);
        }
        const double step = f / g2;
        ic_axpy3(Y, Y, -step, grad);
        if (fabs(step) * sqrt(g2) <= opt->newton_tol * (1 + ic_norm3(Y)))
            break;
    }
    double d[3];
    ic_axpy3(d, Y, -1.0, X);
    *dist = ic_norm3(d);
    return IC_OK;
}

/* Small dense solve A x = b (n <= 4) by Gaussian elimination with partial
 * pivoting; 0 if singular. */
static int solve_small(int n, double A[4][4], double *b, double *x)
{
    for (int c = 0; c < n; c++) {
        int p = c;
        for (int r = c + 1; r < n; r++)
            if (fabs(A[r][c]) > fabs(A[p][c]))
                p = r;
        if (A[p][c] == 0.0)
            return 0;
        for (int k = 0; k < n; k++) {
            double tmp = A[c][k];
            A[c][k] = A[p][k];
            A[p][k] = tmp;
        }
        double tb = b[c];
        b[c] = b[p];
        b[p] = tb;
        for (int r = c + 1; r < n; r++) {
            const double m = A[r][c] / A[c][c];
            for (int k = c; k < n; k++)
                A[r][k] -= m * A[c][k];
            b[r] -= m * b[c];
        }
    }
    for (int r = n - 1; r >= 0; r--) {
        double sum = b[r];
        for (int k = r + 1; k < n; k++)
            sum -= A[r][k] * x[k];
        x[r] = sum / A[r][r];
    }
    return 1;
}

/* Unit normal of sheet `which` at the point. */
static ic_status sheet_normal(ic_pair *pair, const ic_local_point *pt, int which, double *N,
                              ic_error *err)
{
    ic_surface *s = pair->s[which];
    const int par = ic_surface_get_kind(s) == IC_PARAMETRIC;
    ic_surface_geometry g;
    ic_status st = ic_surface_normal_at(s, &g, par ? pt->params[which] : pt->xyz, err);
    if (st != IC_OK) {
        N[0] = N[1] = N[2] = 0.0;
        return ic_sheet_singular(err, st, which);
    }
    memcpy(N, g.normal, sizeof g.normal);
    return IC_OK;
}

/* Largest distance of the point to either surface (a length). */
static ic_status residual(ic_pair *pair, ic_local_point *pt, const ic_local_options *opt,
                          ic_error *err)
{
    double worst = 0.0;
    for (int s = 0; s < 2; s++) {
        ic_surface *srf = pair->s[s];
        double d;
        if (ic_surface_get_kind(srf) == IC_PARAMETRIC) {
            double R[3], diff[3];
            ic_status st = ic_surface_eval(srf, R, pt->params[s], err);
            if (st != IC_OK)
                return st;
            ic_axpy3(diff, R, -1.0, pt->xyz);
            d = ic_norm3(diff);
        } else {
            ic_status st = implicit_distance(pair, srf, pt->xyz, &d, opt, err);
            if (st != IC_OK)
                return st;
        }
        worst = fmax(worst, d);
    }
    pt->residual = worst;
    return IC_OK;
}

/* Newton refinement in the plane through pt->xyz normal to the curve. */
static ic_status refine(ic_pair *pair, ic_local_point *pt, const ic_local_options *opt,
                        ic_error *err)
{
    double NA[3], NB[3], t[3];
    ic_status st = sheet_normal(pair, pt, 0, NA, err);
    if (st == IC_OK)
        st = sheet_normal(pair, pt, 1, NB, err);
    if (st != IC_OK)
        return st;
    ic_cross3(t, NA, NB);
    const double sin_angle = ic_normalize3(t);
    if (sin_angle < sin(opt->tangential_angle))
        return residual(pair, pt, opt, err); /* tangential: no plane to refine in */
    /* Newton over the pairing's search coordinates (pairing/pairing.h) */
    const ic_pairing *pg = &pair->pairing;
    const double X0[3] = {pt->xyz[0], pt->xyz[1], pt->xyz[2]};
    double z[4], last = INFINITY;
    pg->kind->flatten(pg, pt->xyz, pt->params, z);
    for (int it = 0; it < opt->max_newton; it++) {
        double F[4], J[4][4], X[3], dz[4];
        st = pg->kind->section(pg, z, t, X0, F, J, X, err);
        if (st != IC_OK)
            return st;
        double size = 0.0;
        for (int k = 0; k < pg->kind->dim; k++)
            size = fmax(size, fabs(F[k]));
        if (size <= opt->newton_tol * (1 + ic_norm3(X)) || !(size < last))
            break;
        last = size;
        if (!solve_small(pg->kind->dim, J, F, dz))
            return ic_error_set(err, IC_ERR_UNABLE, 0,
                                "refinement onto the intersection: singular system");
        pg->kind->step(pg, z, dz);
    }
    /* the point from the final coordinates */
    pg->kind->unflatten(pg, z, pt->params);
    st = pg->kind->position(pg, z, pt->xyz, err);
    if (st != IC_OK)
        return st;
    return residual(pair, pt, opt, err);
}

static ic_status too_far(ic_error *err, const char *which, double dist, double tol)
{
    return ic_error_set(err, IC_ERR_UNABLE, 0,
                        "the point is %.3g away from surface %s (tolerance %g): it is not on "
                        "the intersection",
                        dist, which, tol);
}

/* The same for a parametric surface, naming the region searched (a grid
 * search can miss a far corner of an unbounded domain). */
static ic_status too_far_param(ic_error *err, const char *which, double dist, double tol,
                               const ic_surface *s, const double *X)
{
    double range[2][2];
    int periodic[2];
    search_range(range, periodic, s, X);
    return ic_error_set(err, IC_ERR_UNABLE, 0,
                        "the point is %.3g away from surface %s (tolerance %g): it is not on "
                        "the intersection (searched u in [%g, %g], v in [%g, %g]; give the "
                        "surface a \"domain\" if it lies elsewhere)",
                        dist, which, tol, range[0][0], range[0][1], range[1][0], range[1][1]);
}

ic_status ic_local_locate(ic_pair *pair, ic_local_point *pt, const double xyz[3],
                          const ic_local_options *opt, ic_error *err)
{
    IC_ARG_NOT_NULL(pair, "pair");
    IC_ARG_NOT_NULL(pt, "pt");
    IC_ARG_NOT_NULL(xyz, "xyz");
    IC_ARG_NOT_NULL(opt, "opt");
    memset(pt, 0, sizeof *pt);
    memcpy(pt->xyz, xyz, sizeof pt->xyz);
    for (int k = 0; k < 3; k++)
        if (!isfinite(xyz[k]))
            return ic_error_set(err, IC_ERR_INVALID, 0, "non-finite coordinate");
    static const char *const NAMES[2] = {"A", "B"};
    candidate cand[MAX_CANDIDATES];
    int ncand = 0;
    for (int s = 0; s < 2; s++) {
        ic_surface *srf = pair->s[s];
        if (ic_surface_get_kind(srf) == IC_IMPLICIT) {
            double d = 0.0;
            ic_status st = implicit_distance(pair, srf, xyz, &d, opt, err);
            pt->residual = fmax(pt->residual, d);
            if (st != IC_OK)
                return st;
            if (d > opt->point_tol)
                return too_far(err, NAMES[s], d, opt->point_tol);
            continue;
        }
        if (pair->self && s == 1) {
            /* the second preimage: the next candidate within tolerance */
            if (ncand < 2 || cand[1].dist > opt->point_tol)
                return ic_error_set(err, IC_ERR_UNABLE, 0,
                                    "the point is on the surface at (%.17g, %.17g) only; no "
                                    "second preimage within %g, so it is no self-intersection",
                                    cand[0].uv[0], cand[0].uv[1], opt->point_tol);
            pt->residual = fmax(pt->residual, cand[1].dist);
            memcpy(pt->params[1], cand[1].uv, sizeof cand[1].uv);
            continue;
        }
        ic_status st = closest_candidates(pair, srf, xyz, cand, &ncand, opt, err);
        if (st != IC_OK)
            return st;
        pt->residual = fmax(pt->residual, cand[0].dist);
        if (cand[0].dist > opt->point_tol)
            return too_far_param(err, NAMES[s], cand[0].dist, opt->point_tol, srf, xyz);
        memcpy(pt->params[s], cand[0].uv, sizeof cand[0].uv);
    }
    return refine(pair, pt, opt, err);
}

ic_status ic_local_locate_params(ic_pair *pair, ic_local_point *pt, const double *params,
                                 int nparams, const ic_local_options *opt, ic_error *err)
{
    IC_ARG_NOT_NULL(pair, "pair");
    IC_ARG_NOT_NULL(pt, "pt");
    IC_ARG_NOT_NULL(params, "params");
    IC_ARG_NOT_NULL(opt, "opt");
    memset(pt, 0, sizeof *pt);
    const ic_pairing *pg = &pair->pairing;
    const int want = pg->kind->nparams;
    if (want == 0 || nparams != want)
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            want == 0 ? "both surfaces are implicit: give the point by "
                                        "coordinates, not parameters"
                                      : "expected %d parameters, got %d",
                            want, nparams);
    for (int i = 0; i < nparams; i++)
        if (!isfinite(params[i]))
            return ic_error_set(err, IC_ERR_INVALID, 0, "non-finite parameter");
    pg->kind->unflatten(pg, params, pt->params);
    ic_status st = pg->kind->position(pg, params, pt->xyz, err);
    if (st != IC_OK)
        return st;
    if (pair->self) {
        double domain[2][2];
        int periodic[2];
        ic_surface_get_domain(pair->s[0], domain, periodic);
        if (param_distance(pt->params[0], pt->params[1], domain, periodic) <= opt->distinct_params)
            return ic_error_set(err, IC_ERR_INVALID, 0,
                                "the two preimages (%g, %g) and (%g, %g) are the same point "
                                "of the surface",
                                pt->params[0][0], pt->params[0][1], pt->params[1][0],
                                pt->params[1][1]);
    }
    /* how far apart the given parameters put the two surfaces */
    st = residual(pair, pt, opt, err);
    if (st != IC_OK)
        return st;
    if (pt->residual > opt->point_tol)
        return ic_error_set(err, IC_ERR_UNABLE, 0,
                            "the given parameters are %.3g apart on the two surfaces "
                            "(tolerance %g): not a point of the intersection",
                            pt->residual, opt->point_tol);
    return refine(pair, pt, opt, err);
}

ic_status ic_local_locate_guess(ic_pair *pair, ic_local_point *pt, const double xyz[3],
                                const double params[2][2], const ic_local_options *opt,
                                ic_error *err)
{
    IC_ARG_NOT_NULL(pair, "pair");
    IC_ARG_NOT_NULL(pt, "pt");
    IC_ARG_NOT_NULL(xyz, "xyz");
    IC_ARG_NOT_NULL(params, "params");
    IC_ARG_NOT_NULL(opt, "opt");
    const ic_pairing *pg = &pair->pairing;
    double flat[4];
    if (pg->kind->nparams == 0)
        return ic_local_locate(pair, pt, xyz, opt, err);
    pg->kind->flatten(pg, xyz, params, flat);
    return ic_local_locate_params(pair, pt, flat, pg->kind->nparams, opt, err);
}
