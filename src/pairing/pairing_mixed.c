/* A parametric sheet R(u, v) and an implicit surface f: f(R(u, v)) = 0,
 * searched over the sheet's (u, v) domain. */
#include "pairing.h"
#include "common/vec3.h"

#include <math.h>
#include <string.h>

static ic_status region(const ic_pairing *p, const double box[3][2], int has_box, double *lo,
                        double *hi, int *periodic, ic_error *err)
{
    (void)box, (void)has_box;
    return ic_pairing_domain_box(p, p->P, lo, hi, periodic, err);
}

/* f's enclosure over the sheet's image of the cell; 0 where either fails. */
static int enclose(const ic_pairing *p, const double *lo, const double *hi, ic_interval xyz[3],
                   ic_interval *f)
{
    const ic_interval box[2] = {{lo[0], hi[0]}, {lo[1], hi[1]}};
    return ic_pairing_enclose_sheet(p, p->P, box, xyz) &&
           ic_pairing_enclose_sheet(p, p->I, xyz, f);
}

static int enclosable(const ic_pairing *p, const double *lo, const double *hi)
{
    ic_interval xyz[3], f;
    return enclose(p, lo, hi, xyz, &f);
}

static int excluded(const ic_pairing *p, const double *lo, const double *hi)
{
    ic_interval xyz[3], f;
    return enclose(p, lo, hi, xyz, &f) && ic_pairing_excludes_zero(f);
}

static int overflows(const ic_pairing *p, const double *lo, const double *hi)
{
    ic_interval xyz[3], f;
    if (!enclose(p, lo, hi, xyz, &f))
        return 1;
    for (int k = 0; k < 3; k++)
        if (ic_pairing_unbounded(xyz[k]))
            return 1;
    return ic_pairing_unbounded(f);
}

/* Min-norm Newton onto f(R(u, v)) = 0 from z = (u, v). */
static int newton(const ic_pairing *p, double accept_rel, double L, double *z, double *xyz)
{
    for (int it = 0; it < 40; it++) {
        double t[9], f, g[3];
        if (ic_surface_taylor(p->S[p->P], t, z, p->sp2, NULL))
            return -1;
        const double X[3] = {t[0], t[3], t[6]};
        const double Ru[3] = {t[1], t[4], t[7]}, Rv[3] = {t[2], t[5], t[8]};
        if (ic_pairing_value_grad(p->S[p->I], p->sp3, X, &f, g))
            return -1;
        const double du = ic_dot3(g, Ru), dv = ic_dot3(g, Rv), nn = du * du + dv * dv;
        if (!(nn > 0))
            return -1;
        z[0] -= f * du / nn;
        z[1] -= f * dv / nn;
        memcpy(xyz, X, sizeof X);
        if (fabs(f) * sqrt(1 / nn) <= 1e-15 * (1 + fabs(z[0]) + fabs(z[1])))
            return fabs(f) / ic_norm3(g) < accept_rel * (L + ic_norm3(xyz)) ? 0 : -1;
    }
    return -1;
}

static void unflatten(const ic_pairing *p, const double *z, double params[2][2])
{
    params[p->P][0] = z[0], params[p->P][1] = z[1];
}

static void flatten(const ic_pairing *p, const double xyz[3], const double params[2][2],
                    double *z)
{
    (void)xyz;
    z[0] = params[p->P][0], z[1] = params[p->P][1];
}

/* f_I(R_P(u, v)) / |grad f| = 0, t . (R_P - X0) = 0 over z = (u, v) */
static ic_status section(const ic_pairing *p, const double *z, const double t[3],
                         const double X0[3], double F[4], double J[4][4], double X[3],
                         ic_error *err)
{
    memset(J, 0, 16 * sizeof(double));
    double R[3], Ru[3], Rv[3], f, grad[3], g;
    ic_status st = ic_pairing_sheet_eval1(p, p->P, z, R, Ru, Rv, err);
    if (st == IC_OK)
        st = ic_pairing_implicit_eval1(p, p->I, R, &f, grad, &g, err);
    if (st != IC_OK)
        return st;
    F[0] = f / g;
    J[0][0] = ic_dot3(grad, Ru) / g, J[0][1] = ic_dot3(grad, Rv) / g;
    double d[3];
    ic_axpy3(d, R, -1.0, X0);
    F[1] = ic_dot3(t, d);
    J[1][0] = ic_dot3(t, Ru), J[1][1] = ic_dot3(t, Rv);
    memcpy(X, R, sizeof R);
    return IC_OK;
}

static void step(const ic_pairing *p, double *z, const double *dz)
{
    ic_pairing_step_sheet(p, p->P, z, dz);
}

static ic_status position(const ic_pairing *p, const double *z, double xyz[3], ic_error *err)
{
    return ic_surface_eval(p->S[p->P], xyz, z, err);
}

/* f(R) / |grad f| / L, N_A x N_B at R = R_P(z) */
static int contact_residuals(const ic_pairing *p, const double *z, double L, double *F)
{
    ic_surface_geometry g[2];
    if (ic_surface_normal_at(p->S[p->P], &g[p->P], z, NULL) != IC_OK ||
        ic_surface_normal_at(p->S[p->I], &g[p->I], g[p->P].point, NULL) != IC_OK)
        return -1;
    F[0] = g[p->I].value / g[p->I].normal_length / L;
    ic_cross3(F + 1, g[0].normal, g[1].normal);
    return 4;
}

static void place(const ic_pairing *p, const double *lo, const double *hi, double xyz[3],
                  double params[2][2], double *radius)
{
    const double c[2] = {0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])};
    unflatten(p, c, params);
    ic_pairing_place_sheet(p, p->P, lo, hi, xyz, radius);
}

/* R and grad f over the cell (f at R's enclosure); 0 where either fails. */
static int enclose_grad(const ic_pairing *p, const ic_interval box[2], ic_interval_grad R[3],
                        ic_interval_grad *f)
{
    if (ic_surface_eval_interval_grad(p->S[p->P], R, box, NULL) != IC_OK)
        return 0;
    const ic_interval X[3] = {R[0].v, R[1].v, R[2].v};
    return ic_surface_eval_interval_grad(p->S[p->I], f, X, NULL) == IC_OK;
}

/* F_j = grad f(R) . R_j, the partial derivatives of F = f(R(u, v)). */
static void partials(const ic_interval_grad R[3], const ic_interval_grad *f, ic_interval G[2])
{
    for (int j = 0; j < 2; j++) {
        G[j] = ic_pairing_point(0.0);
        for (int i = 0; i < 3; i++)
            G[j] = ic_interval_add(G[j], ic_interval_mul(f->d[i], R[i].d[j]));
    }
}

/* The curve is the zero set of F = f(R(u, v)); a closed one bounds a disc
 * in the (convex) cell on whose interior F has an extremum, where
 * grad F = 0: if F_u or F_v keeps one sign over the cell, there is none. */
static int loop_free(const ic_pairing *p, const double *lo, const double *hi)
{
    const ic_interval box[2] = {{lo[0], hi[0]}, {lo[1], hi[1]}};
    ic_interval_grad R[3], f;
    ic_interval G[2];
    if (!enclose_grad(p, box, R, &f))
        return 0;
    partials(R, &f, G);
    return ic_pairing_excludes_zero(G[0]) || ic_pairing_excludes_zero(G[1]);
}

/* The centred form of F = f(R(u, v)). */
static int excluded_centred(const ic_pairing *p, const double *lo, const double *hi)
{
    const ic_interval box[2] = {{lo[0], hi[0]}, {lo[1], hi[1]}};
    const ic_interval cbox[2] = {ic_pairing_point(0.5 * (lo[0] + hi[0])),
                                 ic_pairing_point(0.5 * (lo[1] + hi[1]))};
    ic_interval_grad R[3], Rc[3], f, fc;
    if (!enclose_grad(p, box, R, &f) || !enclose_grad(p, cbox, Rc, &fc))
        return 0;
    ic_interval G[2];
    partials(R, &f, G);
    return ic_pairing_centred_excludes(fc.v, G, lo, hi, 2);
}

static int may_degenerate(const ic_pairing *p, const double *lo, const double *hi)
{
    return ic_pairing_sheet_may_degenerate(p->S[p->P], lo, hi);
}

const ic_pairing_kind ic_pairing_mixed = {
    .name = "parametric/implicit",
    .dim = 2,
    .nparams = 2,
    IC_PAIRING_OPERATIONS,
};
