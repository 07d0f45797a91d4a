/* Two implicit surfaces f_A = f_B = 0, searched over the box (x, y, z). */
#include "pairing.h"
#include "common/vec3.h"
#include "surface/surface_access.h"

#include <math.h>
#include <string.h>

static ic_status region(const ic_pairing *p, const double box[3][2], int has_box, double *lo,
                        double *hi, int *periodic, ic_error *err)
{
    (void)p;
    if (!has_box)
        return ic_error_set(err, IC_ERR_INVALID, 0, "tracing two implicit surfaces needs a \"box\"");
    for (int k = 0; k < 3; k++) {
        lo[k] = box[k][0], hi[k] = box[k][1], periodic[k] = 0;
        if (!isfinite(hi[k] - lo[k]) || !(hi[k] > lo[k]))
            return ic_error_set(err, IC_ERR_INVALID, 0,
                                "the box must have finite, increasing bounds");
    }
    return IC_OK;
}

static void to_box(const double *lo, const double *hi, ic_interval *box)
{
    for (int k = 0; k < 3; k++)
        box[k] = (ic_interval){lo[k], hi[k]};
}

static int enclosable(const ic_pairing *p, const double *lo, const double *hi)
{
    ic_interval box[3], f;
    to_box(lo, hi, box);
    return ic_pairing_enclose_sheet(p, 0, box, &f) && ic_pairing_enclose_sheet(p, 1, box, &f);
}

static int excluded(const ic_pairing *p, const double *lo, const double *hi)
{
    ic_interval box[3], f;
    to_box(lo, hi, box);
    for (int s = 0; s < 2; s++)
        if (ic_pairing_enclose_sheet(p, s, box, &f) && ic_pairing_excludes_zero(f))
            return 1;
    return 0;
}

static int overflows(const ic_pairing *p, const double *lo, const double *hi)
{
    ic_interval box[3], f;
    to_box(lo, hi, box);
    for (int s = 0; s < 2; s++)
        if (!ic_pairing_enclose_sheet(p, s, box, &f) || ic_pairing_unbounded(f))
            return 1;
    return 0;
}

/* Min-norm Newton onto f_A = f_B = 0 from z = x. */
static int newton(const ic_pairing *p, double accept_rel, double L, double *z, double *xyz)
{
    double *x = z;
    for (int it = 0; it < 40; it++) {
        double fa, fb, ga[3], gb[3];
        if (ic_pairing_value_grad(p->S[0], p->sp3, x, &fa, ga) ||
            ic_pairing_value_grad(p->S[1], p->sp3, x, &fb, gb))
            return -1;
        const double a = ic_dot3(ga, ga), b = ic_dot3(ga, gb), c = ic_dot3(gb, gb);
        const double det = a * c - b * b;
        if (!(det > 1e-30 * a * c))
            return -1;
        const double y0 = (c * fa - b * fb) / det, y1 = (a * fb - b * fa) / det;
        double step[3];
        for (int k = 0; k < 3; k++)
            step[k] = y0 * ga[k] + y1 * gb[k];
        ic_axpy3(x, x, -1.0, step);
        memcpy(xyz, x, 3 * sizeof *x);
        if (ic_norm3(step) <= 1e-15 * (L + ic_norm3(x))) {
            const double accept = accept_rel * (L + ic_norm3(x));
            return fabs(fa) / sqrt(a) < accept && fabs(fb) / sqrt(c) < accept ? 0 : -1;
        }
    }
    return -1;
}

static void unflatten(const ic_pairing *p, const double *z, double params[2][2])
{
    (void)p, (void)z, (void)params;
}

static void flatten(const ic_pairing *p, const double xyz[3], const double params[2][2],
                    double *z)
{
    (void)p, (void)params;
    memcpy(z, xyz, 3 * sizeof *z);
}

/* f_A(X) = 0, f_B(X) = 0, t . (X - X0) = 0 over z = X */
static ic_status section(const ic_pairing *p, const double *z, const double t[3],
                         const double X0[3], double F[4], double J[4][4], double X[3],
                         ic_error *err)
{
    memset(J, 0, 16 * sizeof(double));
    memcpy(X, z, 3 * sizeof *X);
    for (int s = 0; s < 2; s++) {
        double f, grad[3], g;
        ic_status st = ic_pairing_implicit_eval1(p, s, X, &f, grad, &g, err);
        if (st != IC_OK)
            return st;
        F[s] = f / g;
        for (int k = 0; k < 3; k++)
            J[s][k] = grad[k] / g;
    }
    double d[3];
    ic_axpy3(d, X, -1.0, X0);
    F[2] = ic_dot3(t, d);
    for (int k = 0; k < 3; k++)
        J[2][k] = t[k];
    return IC_OK;
}

static void step(const ic_pairing *p, double *z, const double *dz)
{
    (void)p;
    for (int k = 0; k < 3; k++)
        z[k] -= dz[k];
}

static ic_status position(const ic_pairing *p, const double *z, double xyz[3], ic_error *err)
{
    (void)p, (void)err;
    memcpy(xyz, z, 3 * sizeof *z);
    return IC_OK;
}

/* f_A / |grad f_A| / L, f_B / |grad f_B| / L, N_A x N_B at X = z */
static int contact_residuals(const ic_pairing *p, const double *z, double L, double *F)
{
    ic_surface_geometry g[2];
    for (int s = 0; s < 2; s++) {
        if (ic_surface_normal_at(p->S[s], &g[s], z, NULL) != IC_OK)
            return -1;
        F[s] = g[s].value / g[s].normal_length / L;
    }
    ic_cross3(F + 2, g[0].normal, g[1].normal);
    return 5;
}

static void place(const ic_pairing *p, const double *lo, const double *hi, double xyz[3],
                  double params[2][2], double *radius)
{
    (void)p, (void)params;
    double half[3];
    for (int k = 0; k < 3; k++) {
        xyz[k] = 0.5 * (lo[k] + hi[k]);
        half[k] = 0.5 * (hi[k] - lo[k]);
    }
    *radius = 2 * ic_norm3(half);
}

/* The tangent cone T = grad f_A x grad f_B over the box. */
static int loop_free(const ic_pairing *p, const double *lo, const double *hi)
{
    ic_interval box[3], T[3];
    to_box(lo, hi, box);
    ic_interval_grad fa, fb;
    if (ic_surface_eval_interval_grad(p->S[0], &fa, box, NULL) != IC_OK ||
        ic_surface_eval_interval_grad(p->S[1], &fb, box, NULL) != IC_OK)
        return 0;
    ic_pairing_cross(T, fa.d, fb.d);
    return ic_pairing_one_sided(T);
}

/* The Taylor form of h = f_B - mu f_A to second order (pairing.h): where
 * the surfaces nearly coincide, h's gradient and Hessian nearly vanish. */
static int second_order_excludes(const ic_pairing *p, const ic_interval *box, const double *c,
                                 const ic_interval *gc, ic_interval mu, ic_interval hc)
{
    ic_interval_hess H[2];
    for (int s = 0; s < 2; s++)
        if (ic_surface_eval_interval_hess(p->S[s], &H[s], box, NULL) != IC_OK)
            return 0;
    ic_interval Hh[IC_INTERVAL_HESS_LEN];
    for (int i = 0; i < IC_INTERVAL_HESS_LEN; i++)
        Hh[i] = ic_interval_sub(H[1].h[i], ic_interval_mul(mu, H[0].h[i]));
    return ic_pairing_taylor2_excludes(hc, gc, Hh, box, c, 3);
}

/* Centred forms of f_A, f_B and f_B - mu f_A, mu making the combination's
 * gradient small at the centre (any common zero is a zero of it). */
static int excluded_centred(const ic_pairing *p, const double *lo, const double *hi)
{
    ic_interval box[3], cbox[3];
    to_box(lo, hi, box);
    for (int k = 0; k < 3; k++)
        cbox[k] = ic_pairing_point(0.5 * (lo[k] + hi[k]));
    ic_interval_grad f[2], fc[2];
    for (int s = 0; s < 2; s++)
        if (ic_surface_eval_interval_grad(p->S[s], &f[s], box, NULL) != IC_OK ||
            ic_surface_eval_interval_grad(p->S[s], &fc[s], cbox, NULL) != IC_OK)
            return 0;
    for (int s = 0; s < 2; s++)
        if (ic_pairing_centred_excludes(fc[s].v, f[s].d, lo, hi, 3))
            return 1;
    /* mu = grad f_B . grad f_A / |grad f_A|^2 at the centre */
    double ab = 0, aa = 0;
    for (int k = 0; k < 3; k++) {
        const double ga = ic_pairing_mid(fc[0].d[k]).lo, gb = ic_pairing_mid(fc[1].d[k]).lo;
        ab += ga * gb, aa += ga * ga;
    }
    if (!(aa > 0) || !isfinite(ab / aa))
        return 0;
    const ic_interval mu = ic_pairing_point(ab / aa);
    ic_interval G[3];
    for (int k = 0; k < 3; k++)
        G[k] = ic_interval_sub(f[1].d[k], ic_interval_mul(mu, f[0].d[k]));
    const ic_interval hc = ic_interval_sub(fc[1].v, ic_interval_mul(mu, fc[0].v));
    if (ic_pairing_centred_excludes(hc, G, lo, hi, 3))
        return 1;
    ic_interval gc[3], h;
    const double c[3] = {cbox[0].lo, cbox[1].lo, cbox[2].lo};
    for (int k = 0; k < 3; k++)
        gc[k] = ic_interval_sub(fc[1].d[k], ic_interval_mul(mu, fc[0].d[k]));
    if (!ic_pairing_gap_beyond_slope(hc, gc, box, c, 3))
        return 0;
    return (ic_surface_combined_interval(p->S[0], ic_interval_neg(mu), p->S[1],
                                         ic_pairing_point(1.0), box, &h) &&
            ic_pairing_excludes_zero(h)) ||
           second_order_excludes(p, box, c, gc, mu, hc);
}

static int may_degenerate(const ic_pairing *p, const double *lo, const double *hi)
{
    (void)p, (void)lo, (void)hi;
    return 0; /* no parametrization */
}

const ic_pairing_kind ic_pairing_implicit = {
    .name = "implicit/implicit",
    .dim = 3,
    .nparams = 0,
    IC_PAIRING_OPERATIONS,
};
