/*
 * Locating a tangential point precisely (for the tracer's singular points):
 * Gauss-Newton on the overdetermined residuals of the pairing,
 *   implicit/implicit   unknowns X:          f_A/|grad f_A|, f_B/|grad f_B|, N_A x N_B
 *   parametric/implicit unknowns (u, v):     f(R)/|grad f|, N_A x N_B
 *   parametric/param.   unknowns (u,v,p,q):  R_A - R_B, N_A x N_B
 * with a forward-difference Jacobian and a small Levenberg-Marquardt damping (a
 * tangential curve makes the solution set a curve, and the normal equations
 * singular along it).
 *
 * At a contact of order m >= 4 (z = x^4 + y^4 against z = 0) the normals'
 * cross product vanishes to order m - 1: the root is multiple and plain
 * Gauss-Newton creeps towards it by a factor (m-2)/(m-1) per step, stopping
 * where the residual reaches 1e-12, about 6e-5 away for m = 4. There the
 * step is lengthened by the multiplicity (Schroeder 1870: x - k F/F' is
 * quadratic at a root of multiplicity k), the k that lowers the residual
 * most being chosen, and the difference step shrinks with the steps so that
 * the Jacobian stays right near the root.
 */
#include "common/args.h"
#include "tangential_residuals.h"
#include "common/vec3.h"

#include <float.h>
#include <math.h>
#include <string.h>

/* Each constant below is pinned by a test that fails when it is changed
 * tenfold (tests/test_constants.c, the contacts of order 2 to 16, the
 * tangential lines, far starts and the cone's apex), or says why that change
 * cannot matter (docs/testing.md, "Constants pinned"). */

/* dimensionless (the residuals are lengths over L and sines): a point is
 * tangential when every residual is below this */
#define LOCATE_ACCEPT 1e-12
/* (/10 cannot matter: located residuals are 1e-15 or less at every
 * contact measured, orders 2 to 16 in three pairings) */
/* iterations of plain Gauss-Newton (quadratic convergence needs a
 * handful), and of the lengthened steps at a multiple root (order 15: a few
 * dozen) */
#define LOCATE_PLAIN_ITERATIONS 40
#define LOCATE_MAX_ITERATIONS 100
/* (MAX x10 only caps time: the lengthened steps stop by step size or stall
 * within 20 iterations at every contact measured) */
/* dimensionless: a residual this small is a root (below, rounding of
 * normalized quantities at the origin only) */
#define LOCATE_FLOOR 1e-300
/* (tenfold either way is still zero for any residual of doubles) */
/* the longest lengthening of a step: the multiplicity of N_A x N_B at a
 * contact of order 16, the highest order the analysis reaches */
#define LOCATE_MAX_MULTIPLICITY 16
/* (x10 cannot matter: up to order 16 a k <= 16 leaves the smallest residual,
 * and the locator does not move along a tangential line at all) */
/* a plain step that lowers the residual by less than this factor is slow
 * (linear) convergence: a multiple root, and longer steps are tried */
#define LOCATE_SLOW_RATIO 0.1
/* (/10 cannot matter: a multiple root converges by at least 1/2 per step, a
 * simple one quadratically; no ratio falls between 0.01 and 0.1) */
/* relative: the forward-difference step, of the problem's size for a
 * coordinate, of (1 + |p|) for a parameter; near the root, a thousandth of
 * the last step */
#define LOCATE_DIFF_REL 1e-7
#define LOCATE_DIFF_OF_STEP 1e-3
/* (REL x10 and OF_STEP either way move the located point only within the
 * locator's own accuracy: 1e-14 L, 1e-11 L at order 16) */
/* dimensionless: the Levenberg-Marquardt damping, of the trace of J^T J
 * or of each unknown's own diagonal entry */
#define LOCATE_DAMPING 1e-14
/* (/10: as the difference steps, within 1e-11 L at order 16) */
/* difference steps tried per step at a multiple root */
#define LOCATE_DIFF_RETRIES 4
/* (x10 only caps time: the retries stop where the step stops shrinking) */
/* iterations without a better point before giving up */
#define LOCATE_STALL 3
/* (either way: the lengthened steps improve steadily to their step-size
 * stop at every contact measured) */

/* The unknowns' own size: a coordinate's is L, a parameter's 1. */
static double unit_of(const ic_tres *c)
{
    return c->params ? 1.0 : c->L;
}

/* Forward-difference Jacobian; the step is at most `cap` (and at least a few
 * units in the last place). 0, or -1 where a surface is singular. */
static int jacobian(const ic_tres *c, const double *z, const double *F, int m, double cap,
                    double J[6][4])
{
    for (int j = 0; j < c->n; j++) {
        double zj[4], Fj[6];
        memcpy(zj, z, sizeof zj);
        double h = LOCATE_DIFF_REL * (unit_of(c) + fabs(z[j]));
        h = fmax(fmin(h, cap), 16 * DBL_EPSILON * fabs(z[j]) + DBL_MIN);
        zj[j] += h;
        h = zj[j] - z[j]; /* the step actually taken */
        if (ic_tres_residuals(c, zj, Fj) != m)
            return -1;
        for (int i = 0; i < m; i++)
            J[i][j] = (Fj[i] - F[i]) / h;
    }
    return 0;
}

/* The damped Gauss-Newton step: (J^T J + mu D) dz = -J^T F. With
 * per_unknown, D is the diagonal of J^T J (Marquardt 1963: near a multiple
 * root a column of J is tiny beside the others and must still move); else
 * D = trace(J^T J) I (Levenberg 1944), which keeps the step short along a
 * tangential curve, where J^T J is singular. */
static void gauss_newton_step(const double J[6][4], const double *F, int m, int n,
                              int per_unknown, double *dz)
{
    double A[4][4] = {{0}}, b[4] = {0}, trace = 0;
    for (int a = 0; a < n; a++) {
        for (int bb = 0; bb < n; bb++)
            for (int i = 0; i < m; i++)
                A[a][bb] += J[i][a] * J[i][bb];
        for (int i = 0; i < m; i++)
            b[a] -= J[i][a] * F[i];
        trace += A[a][a];
    }
    for (int a = 0; a < n; a++)
        A[a][a] += LOCATE_DAMPING * (per_unknown ? A[a][a] : trace) + DBL_MIN;
    /* Gaussian elimination (symmetric positive definite, small) */
    for (int col = 0; col < n; col++)
        for (int r = col + 1; r < n; r++) {
            const double f = A[r][col] / A[col][col];
            for (int k = col; k < n; k++)
                A[r][k] -= f * A[col][k];
            b[r] -= f * b[col];
        }
    for (int r = n - 1; r >= 0; r--) {
        double sum = b[r];
        for (int k = r + 1; k < n; k++)
            sum -= A[r][k] * dz[k];
        dz[r] = sum / A[r][r];
    }
}

/* z + k dz for the multiplicity k = 1.. that leaves the smallest residual:
 * tried beyond k = 1 only when the plain step converges slowly. Returns
 * that residual; z and F are updated. */
static double take_step(const ic_tres *c, double *z, const double *dz, int m, double worst,
                        double *F)
{
    double best_z[4], best_F[6], best = INFINITY;
    for (int k = 1; k <= LOCATE_MAX_MULTIPLICITY; k++) {
        double zk[4], Fk[6];
        for (int j = 0; j < c->n; j++)
            zk[j] = z[j] + k * dz[j];
        const double w = ic_tres_worst(c, zk, m, Fk);
        if (w < best) {
            best = w;
            memcpy(best_z, zk, sizeof zk);
            memcpy(best_F, Fk, sizeof Fk);
        }
        if (k == 1 && (best == 0 || best < LOCATE_SLOW_RATIO * worst || !(best < worst)))
            break; /* fast convergence, or no progress along dz at all */
    }
    if (best < INFINITY) {
        memcpy(z, best_z, (size_t)c->n * sizeof *z);
        memcpy(F, best_F, (size_t)m * sizeof *F);
    }
    return best;
}

/* Plain Gauss-Newton from z (Levenberg damping, fixed difference steps) to
 * the root or the stall; *last is the last step's size and *ratio the last
 * step's residual ratio. Returns the residual. */
static double plain(const ic_tres *c, double *z, int m, double *F, double *last, double *ratio)
{
    double worst = ic_tres_worst(c, z, m, F);
    *last = 0;
    *ratio = 0;
    for (int it = 0; worst > LOCATE_FLOOR && it < LOCATE_PLAIN_ITERATIONS; it++) {
        double J[6][4], dz[4], zn = 0, size = 0;
        if (jacobian(c, z, F, m, INFINITY, J) != 0)
            return INFINITY;
        gauss_newton_step(J, F, m, c->n, 0, dz);
        for (int j = 0; j < c->n; j++) {
            z[j] += dz[j];
            size = fmax(size, fabs(dz[j]));
            zn = fmax(zn, fabs(z[j]));
        }
        const double w = ic_tres_worst(c, z, m, F);
        if (!(w < INFINITY))
            return INFINITY;
        *ratio = w / worst;
        *last = size;
        worst = w;
        if (size <= 1e-15 * (1 + zn))
            break;
    }
    return worst;
}

/* The Gauss-Newton step at a multiple root, with difference steps a
 * thousandth of the step: first of the last step, then, while the step
 * comes out far shorter (the last lengthened step landed much nearer the
 * root), of the new one. 0, or -1 where a surface is singular. */
static int multiple_step(const ic_tres *c, const double *z, const double *F, int m, double last,
                         double *dz)
{
    double cap = LOCATE_DIFF_OF_STEP * last;
    for (int tries = 0; tries < LOCATE_DIFF_RETRIES; tries++) {
        double J[6][4], size = 0;
        if (jacobian(c, z, F, m, cap, J) != 0)
            return -1;
        gauss_newton_step(J, F, m, c->n, 1, dz);
        for (int j = 0; j < c->n; j++)
            size = fmax(size, fabs(dz[j]));
        if (!(LOCATE_DIFF_OF_STEP * size < 0.1 * cap))
            break;
        cap = fmax(LOCATE_DIFF_OF_STEP * size, DBL_MIN);
    }
    return 0;
}

/* At a multiple root (the plain steps shrank the residual slowly): the
 * lengthened steps, per-unknown damping and difference steps shrinking with
 * the steps, never moving farther than LOCATE_MAX_MULTIPLICITY times the
 * distance `remaining` that the plain steps still had to go (their
 * geometric series) from where they stopped: a tangential curve, where the
 * solutions run on, is not followed. Keeps the best point met. */
static double multiple(const ic_tres *c, double *z, int m, double *F, double worst, double last,
                       double remaining)
{
    double z0[4], best_z[4], best = worst;
    memcpy(z0, z, sizeof z0);
    memcpy(best_z, z, sizeof best_z);
    const double reach = LOCATE_MAX_MULTIPLICITY * remaining;
    for (int it = 0, stall = 0; worst > LOCATE_FLOOR && it < LOCATE_MAX_ITERATIONS; it++) {
        double dz[4], size = 0, zn = 0;
        if (multiple_step(c, z, F, m, last, dz) != 0)
            break;
        for (int j = 0; j < c->n; j++) {
            size = fmax(size, fabs(dz[j]));
            zn = fmax(zn, fabs(z[j]));
        }
        worst = take_step(c, z, dz, m, worst, F);
        double moved = 0;
        for (int j = 0; j < c->n; j++)
            moved = fmax(moved, fabs(z[j] - z0[j]));
        if (!(worst < INFINITY) || moved > reach)
            break;
        last = fmax(size, DBL_MIN);
        stall = worst < best ? 0 : stall + 1;
        if (worst < best) {
            best = worst;
            memcpy(best_z, z, sizeof best_z);
        }
        if (size <= 1e-15 * (1 + zn) || stall >= LOCATE_STALL)
            break;
    }
    memcpy(z, best_z, sizeof best_z);
    return ic_tres_worst(c, z, m, F);
}

/* Gauss-Newton from z; returns the residual where it stops. */
static double solve(const ic_tres *c, double *z, int m, double *F)
{
    double last, ratio;
    const double worst = plain(c, z, m, F, &last, &ratio);
    if (!(worst > LOCATE_FLOOR && worst < INFINITY && ratio > LOCATE_SLOW_RATIO && ratio < 1))
        return worst;
    const double remaining = last / (1 - ratio);
    if (!c->two_sheets || !c->opt)
        return multiple(c, z, m, F, worst, last, remaining);
    ic_tres r;
    ic_tres_reduce(c, z, &r);
    double zr[4] = {z[0], z[1], 0, 0}, Fr[6];
    if (!(multiple(&r, zr, 6, Fr, ic_tres_worst(&r, zr, 6, Fr), last, remaining) < INFINITY))
        return worst;
    ic_local_point pt;
    ic_tres_unpack(&r, zr, &pt);
    if (ic_tres_reduced_at(&r, &pt, Fr) < 0)
        return worst;
    double back[4] = {pt.params[0][0], pt.params[0][1], pt.params[1][0], pt.params[1][1]};
    const double w = ic_tres_worst(c, back, m, F);
    if (w < worst) {
        memcpy(z, back, sizeof back);
        return w;
    }
    return ic_tres_worst(c, z, m, F);
}

ic_status ic_local_locate_tangential(ic_pair *pair, ic_local_point *pt, const ic_local_point *near,
                                     double reach, const ic_local_options *opt, ic_error *err)
{
    IC_ARG_NOT_NULL(pair, "pair");
    IC_ARG_NOT_NULL(pt, "pt");
    IC_ARG_NOT_NULL(near, "near");
    ic_tres c;
    double z[4] = {0}, F[6];
    ic_tres_setup(&c, pair, near, opt, z);
    const int m = ic_tres_residuals(&c, z, F);
    const double worst = m > 0 ? solve(&c, z, m, F) : INFINITY;
    double at[3];
    ic_frame_shown(&ic_pair_pairing(pair)->frame, near->xyz, at);
    if (!(worst <= LOCATE_ACCEPT))
        return ic_error_set(err, IC_ERR_UNABLE, 0,
                            "no tangential point converged near (%g, %g, %g) (residual %.3g)",
                            at[0], at[1], at[2], worst);
    ic_tres_unpack(&c, z, pt);
    if (ic_tres_position(&c, z, pt->xyz, err) != IC_OK)
        return IC_ERR_UNABLE;
    double d[3];
    ic_axpy3(d, pt->xyz, -1.0, near->xyz);
    if (ic_norm3(d) > reach)
        return ic_error_set(err, IC_ERR_UNABLE, 0,
                            "the nearest tangential point is %.3g away, beyond %g", ic_norm3(d),
                            reach);
    pt->residual = worst;
    return IC_OK;
}

