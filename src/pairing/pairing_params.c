/* Two parametric sheets R_A(u, v) = R_B(p, q), searched over (u, v, p, q)
 * (a self-intersection adds its own rules, pairing_self.c). */
#include "pairing.h"
#include "common/vec3.h"

#include <math.h>
#include <string.h>

static ic_status region(const ic_pairing *p, const double box[3][2], int has_box, double *lo,
                        double *hi, int *periodic, ic_error *err)
{
    (void)box, (void)has_box;
    if (ic_pairing_domain_box(p, 0, lo, hi, periodic, err) != IC_OK ||
        ic_pairing_domain_box(p, 1, lo + 2, hi + 2, periodic + 2, err) != IC_OK)
        return IC_ERR_INVALID;
    return IC_OK;
}

/* Both sheets' enclosures over the cell; 0 where either fails. */
static int enclose(const ic_pairing *p, const double *lo, const double *hi, ic_interval xa[3],
                   ic_interval xb[3])
{
    const ic_interval ua[2] = {{lo[0], hi[0]}, {lo[1], hi[1]}};
    const ic_interval ub[2] = {{lo[2], hi[2]}, {lo[3], hi[3]}};
    return ic_pairing_enclose_sheet(p, 0, ua, xa) && ic_pairing_enclose_sheet(p, 1, ub, xb);
}

static int enclosable(const ic_pairing *p, const double *lo, const double *hi)
{
    ic_interval xa[3], xb[3];
    return enclose(p, lo, hi, xa, xb);
}

static int excluded(const ic_pairing *p, const double *lo, const double *hi)
{
    ic_interval xa[3], xb[3];
    if (!enclose(p, lo, hi, xa, xb))
        return 0;
    for (int k = 0; k < 3; k++)
        if (ic_interval_is_empty(xa[k]) || ic_interval_is_empty(xb[k]) || xa[k].hi < xb[k].lo ||
            xb[k].hi < xa[k].lo)
            return 1;
    return 0;
}

static int overflows(const ic_pairing *p, const double *lo, const double *hi)
{
    ic_interval xa[3], xb[3];
    if (!enclose(p, lo, hi, xa, xb))
        return 1;
    for (int k = 0; k < 3; k++)
        if (ic_pairing_unbounded(xa[k]) || ic_pairing_unbounded(xb[k]))
            return 1;
    return 0;
}

/* One min-norm Newton step on R_A(u, v) - R_B(p, q): step = J^T (J J^T)^-1 F.
 * Returns its largest component, or -1 where J J^T is singular. */
static double newton_step(const double F[3], const double J[3][4], double *z)
{
    double M[3][3];
    for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++) {
            M[a][b] = 0;
            for (int j = 0; j < 4; j++)
                M[a][b] += J[a][j] * J[b][j];
        }
    const double det = ic_det3(M[0], M[1], M[2]);
    /* relative: det scales like the sixth power of the problem's size */
    if (!(fabs(det) > 1e-30 * fabs(M[0][0] * M[1][1] * M[2][2])))
        return -1;
    const double c0[3] = {M[0][0], M[1][0], M[2][0]}, c1[3] = {M[0][1], M[1][1], M[2][1]},
                 c2[3] = {M[0][2], M[1][2], M[2][2]};
    const double y[3] = {ic_det3(F, c1, c2) / det, ic_det3(c0, F, c2) / det,
                         ic_det3(c0, c1, F) / det};
    double size = 0;
    for (int j = 0; j < 4; j++) {
        const double step = J[0][j] * y[0] + J[1][j] * y[1] + J[2][j] * y[2];
        z[j] -= step;
        size = fmax(size, fabs(step));
    }
    return size;
}

/* Min-norm Newton onto R_A(u, v) = R_B(p, q) from z = (u, v, p, q). */
static int newton(const ic_pairing *p, double accept_rel, double L, double *z, double *xyz)
{
    for (int it = 0; it < 40; it++) {
        double ta[9], tb[9];
        if (ic_surface_taylor(p->S[0], ta, z, p->sp2, NULL) ||
            ic_surface_taylor(p->S[1], tb, z + 2, p->sp2, NULL))
            return -1;
        double F[3], J[3][4];
        for (int k = 0; k < 3; k++) {
            F[k] = ta[3 * k] - tb[3 * k];
            J[k][0] = ta[3 * k + 1], J[k][1] = ta[3 * k + 2];
            J[k][2] = -tb[3 * k + 1], J[k][3] = -tb[3 * k + 2];
        }
        xyz[0] = ta[0], xyz[1] = ta[3], xyz[2] = ta[6];
        const double size = newton_step(F, J, z);
        if (size < 0)
            return -1;
        if (size <= 1e-15 * (1 + fabs(z[0]) + fabs(z[1]) + fabs(z[2]) + fabs(z[3])))
            return ic_norm3(F) < accept_rel * (L + ic_norm3(xyz)) ? 0 : -1;
    }
    return -1;
}

static void unflatten(const ic_pairing *p, const double *z, double params[2][2])
{
    (void)p;
    params[0][0] = z[0], params[0][1] = z[1];
    params[1][0] = z[2], params[1][1] = z[3];
}

static void flatten(const ic_pairing *p, const double xyz[3], const double params[2][2],
                    double *z)
{
    (void)p, (void)xyz;
    z[0] = params[0][0], z[1] = params[0][1];
    z[2] = params[1][0], z[3] = params[1][1];
}

/* R_A(u, v) - R_B(p, q) = 0, t . (R_A - X0) = 0 over z = (u, v, p, q) */
static ic_status section(const ic_pairing *p, const double *z, const double t[3],
                         const double X0[3], double F[4], double J[4][4], double X[3],
                         ic_error *err)
{
    memset(J, 0, 16 * sizeof(double));
    double R[2][3], Ru[2][3], Rv[2][3];
    for (int s = 0; s < 2; s++) {
        ic_status st = ic_pairing_sheet_eval1(p, s, z + 2 * s, R[s], Ru[s], Rv[s], err);
        if (st != IC_OK)
            return st;
    }
    for (int k = 0; k < 3; k++) {
        F[k] = R[0][k] - R[1][k];
        J[k][0] = Ru[0][k], J[k][1] = Rv[0][k];
        J[k][2] = -Ru[1][k], J[k][3] = -Rv[1][k];
        X[k] = R[0][k];
    }
    double d[3];
    ic_axpy3(d, R[0], -1.0, X0);
    F[3] = ic_dot3(t, d);
    J[3][0] = ic_dot3(t, Ru[0]), J[3][1] = ic_dot3(t, Rv[0]);
    return IC_OK;
}

static void step(const ic_pairing *p, double *z, const double *dz)
{
    ic_pairing_step_sheet(p, 0, z, dz);
    ic_pairing_step_sheet(p, 1, z + 2, dz + 2);
}

static ic_status position(const ic_pairing *p, const double *z, double xyz[3], ic_error *err)
{
    return ic_surface_eval(p->S[0], xyz, z, err);
}

/* (R_A - R_B) / L, N_A x N_B at z = (u, v, p, q) */
static int contact_residuals(const ic_pairing *p, const double *z, double L, double *F)
{
    ic_surface_geometry g[2];
    for (int s = 0; s < 2; s++)
        if (ic_surface_normal_at(p->S[s], &g[s], z + 2 * s, NULL) != IC_OK)
            return -1;
    for (int k = 0; k < 3; k++)
        F[k] = (g[0].point[k] - g[1].point[k]) / L;
    ic_cross3(F + 3, g[0].normal, g[1].normal);
    return 6;
}

static void place(const ic_pairing *p, const double *lo, const double *hi, double xyz[3],
                  double params[2][2], double *radius)
{
    double c[4];
    for (int k = 0; k < 4; k++)
        c[k] = 0.5 * (lo[k] + hi[k]);
    unflatten(p, c, params);
    ic_pairing_place_sheet(p, 0, lo, hi, xyz, radius);
}

/* The tangent cone T = N_A x N_B over (u, v) x (p, q). */
static int loop_free(const ic_pairing *p, const double *lo, const double *hi)
{
    ic_interval NA[3], NB[3], T[3];
    if (!ic_pairing_param_normal(p->S[0], lo, hi, NA) ||
        !ic_pairing_param_normal(p->S[1], lo + 2, hi + 2, NB))
        return 0;
    ic_pairing_cross(T, NA, NB);
    return ic_pairing_one_sided(T);
}

/* N . D over the cell, N = R_u x R_v of A at the centre (midpoints), D and
 * its gradient G given: the distance along the normal, which separates
 * sheets that touch. */
static int normal_component_excludes(const ic_interval_grad Rc[3], const ic_interval Dc[3],
                                     const ic_interval G[3][4], const double *lo,
                                     const double *hi)
{
    double Ru[3], Rv[3], N[3];
    for (int i = 0; i < 3; i++)
        Ru[i] = ic_pairing_mid(Rc[i].d[0]).lo, Rv[i] = ic_pairing_mid(Rc[i].d[1]).lo;
    N[0] = Ru[1] * Rv[2] - Ru[2] * Rv[1];
    N[1] = Ru[2] * Rv[0] - Ru[0] * Rv[2];
    N[2] = Ru[0] * Rv[1] - Ru[1] * Rv[0];
    if (!isfinite(N[0] + N[1] + N[2]))
        return 0;
    ic_interval hc = ic_pairing_point(0.0), H[4];
    for (int k = 0; k < 4; k++)
        H[k] = ic_pairing_point(0.0);
    for (int i = 0; i < 3; i++) {
        hc = ic_interval_add(hc, ic_interval_mul(ic_pairing_point(N[i]), Dc[i]));
        for (int k = 0; k < 4; k++)
            H[k] = ic_interval_add(H[k], ic_interval_mul(ic_pairing_point(N[i]), G[i][k]));
    }
    return ic_pairing_centred_excludes(hc, H, lo, hi, 4);
}

/* Centred forms of the components of D = R_A(u, v) - R_B(p, q) and of
 * N . D. */
static int excluded_centred(const ic_pairing *p, const double *lo, const double *hi)
{
    ic_interval_grad R[2][3], Rc[2][3];
    for (int s = 0; s < 2; s++) {
        const double *l = lo + 2 * s, *h = hi + 2 * s;
        const ic_interval box[2] = {{l[0], h[0]}, {l[1], h[1]}};
        const ic_interval cbox[2] = {ic_pairing_point(0.5 * (l[0] + h[0])),
                                     ic_pairing_point(0.5 * (l[1] + h[1]))};
        if (ic_surface_eval_interval_grad(p->S[s], R[s], box, NULL) != IC_OK ||
            ic_surface_eval_interval_grad(p->S[s], Rc[s], cbox, NULL) != IC_OK)
            return 0;
    }
    /* D's gradient: (R_A,u, R_A,v, -R_B,p, -R_B,q) */
    ic_interval G[3][4], Dc[3];
    for (int i = 0; i < 3; i++) {
        Dc[i] = ic_interval_sub(Rc[0][i].v, Rc[1][i].v);
        G[i][0] = R[0][i].d[0], G[i][1] = R[0][i].d[1];
        G[i][2] = ic_interval_neg(R[1][i].d[0]), G[i][3] = ic_interval_neg(R[1][i].d[1]);
        if (ic_pairing_centred_excludes(Dc[i], G[i], lo, hi, 4))
            return 1;
    }
    return normal_component_excludes(Rc[0], Dc, G, lo, hi);
}

static int may_degenerate(const ic_pairing *p, const double *lo, const double *hi)
{
    return ic_pairing_sheet_may_degenerate(p->S[0], lo, hi) ||
           ic_pairing_sheet_may_degenerate(p->S[1], lo + 2, hi + 2);
}

const ic_pairing_kind ic_pairing_params = {
    .name = "parametric/parametric",
    .dim = 4,
    .nparams = 4,
    IC_PAIRING_OPERATIONS,
};
