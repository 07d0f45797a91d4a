/*
 * Locating a tangential point precisely (for the tracer's singular points):
 * Gauss-Newton on the overdetermined residuals of the pairing,
 *   implicit/implicit   unknowns X:          f_A/|grad f_A|, f_B/|grad f_B|, N_A x N_B
 *   parametric/implicit unknowns (u, v):     f(R)/|grad f|, N_A x N_B
 *   parametric/param.   unknowns (u,v,p,q):  R_A - R_B, N_A x N_B
 * with a forward-difference Jacobian and a small Levenberg damping (a
 * tangential curve makes the solution set a curve, and the normal equations
 * singular along it).
 */
#include "local_internal.h"
#include "common/vec3.h"

#include <math.h>
#include <string.h>

typedef struct {
    ic_pair *pair;
    int par[2];
    int n; /* unknowns */
    ic_local_point base;
    double L; /* the problem's size: length residuals are divided by it */
} tctx;

/* Builds the point from the unknowns. */
static void unpack(const tctx *c, const double *z, ic_local_point *pt)
{
    *pt = c->base;
    int k = 0;
    if (!c->par[0] && !c->par[1]) {
        memcpy(pt->xyz, z, 3 * sizeof *z);
        return;
    }
    for (int s = 0; s < 2; s++)
        if (c->par[s]) {
            pt->params[s][0] = z[k++];
            pt->params[s][1] = z[k++];
        }
}

/* Residuals: returns their number, or -1 where a surface is singular. */
static int residuals(const tctx *c, const double *z, double *F)
{
    ic_local_point pt;
    unpack(c, z, &pt);
    ic_surface_geometry g[2];
    double X[2][3];
    for (int s = 0; s < 2; s++) {
        ic_surface *srf = ic_pair_surface(c->pair, s);
        if (c->par[s]) {
            if (ic_surface_normal_at(srf, &g[s], pt.params[s], NULL) != IC_OK)
                return -1;
            memcpy(X[s], g[s].point, sizeof X[s]);
        }
    }
    int m = 0;
    if (c->par[0] && c->par[1]) {
        for (int k = 0; k < 3; k++)
            F[m++] = (X[0][k] - X[1][k]) / c->L;
    } else {
        const double *P = c->par[0] ? X[0] : c->par[1] ? X[1] : pt.xyz;
        for (int s = 0; s < 2; s++)
            if (!c->par[s]) {
                if (ic_surface_normal_at(ic_pair_surface(c->pair, s), &g[s], P, NULL) != IC_OK)
                    return -1;
                F[m++] = g[s].value / g[s].normal_length / c->L;
            }
    }
    double cr[3];
    ic_cross3(cr, g[0].normal, g[1].normal);
    for (int k = 0; k < 3; k++)
        F[m++] = cr[k];
    return m;
}

ic_status ic_local_locate_tangential(ic_pair *pair, ic_local_point *pt, const ic_local_point *near,
                                     double reach, const ic_local_options *opt, ic_error *err)
{
    tctx c;
    memset(&c, 0, sizeof c);
    c.pair = pair;
    c.base = *near;
    c.L = opt->scale > 0 && isfinite(opt->scale) ? opt->scale : 1.0;
    double z[4];
    for (int s = 0; s < 2; s++) {
        c.par[s] = ic_surface_get_kind(ic_pair_surface(pair, s)) == IC_PARAMETRIC;
        if (c.par[s]) {
            z[c.n++] = near->params[s][0];
            z[c.n++] = near->params[s][1];
        }
    }
    if (c.n == 0) {
        memcpy(z, near->xyz, sizeof near->xyz);
        c.n = 3;
    }
    double F[6], J[6][4];
    int m = residuals(&c, z, F);
    double worst = INFINITY;
    for (int it = 0; m > 0 && it < 40; it++) {
        for (int j = 0; j < c.n; j++) { /* forward differences */
            double zj[4], Fj[6];
            memcpy(zj, z, sizeof zj);
            /* a coordinate steps by 1e-7 of the problem's size, a
             * parameter by 1e-7 of its own size */
            const double h = 1e-7 * ((c.par[0] || c.par[1] ? 1.0 : c.L) + fabs(z[j]));
            zj[j] += h;
            if (residuals(&c, zj, Fj) != m)
                return ic_error_set(err, IC_ERR_UNABLE, 0, "a surface is singular near the point");
            for (int i = 0; i < m; i++)
                J[i][j] = (Fj[i] - F[i]) / h;
        }
        /* (J^T J + mu I) dz = -J^T F */
        double A[4][4] = {{0}}, b[4] = {0}, trace = 0;
        for (int a = 0; a < c.n; a++) {
            for (int bb = 0; bb < c.n; bb++)
                for (int i = 0; i < m; i++)
                    A[a][bb] += J[i][a] * J[i][bb];
            for (int i = 0; i < m; i++)
                b[a] -= J[i][a] * F[i];
            trace += A[a][a];
        }
        for (int a = 0; a < c.n; a++)
            A[a][a] += 1e-14 * trace + 1e-300;
        /* Gaussian elimination (symmetric positive definite, small) */
        for (int col = 0; col < c.n; col++)
            for (int r = col + 1; r < c.n; r++) {
                const double f = A[r][col] / A[col][col];
                for (int k = col; k < c.n; k++)
                    A[r][k] -= f * A[col][k];
                b[r] -= f * b[col];
            }
        double dz[4];
        for (int r = c.n - 1; r >= 0; r--) {
            double sum = b[r];
            for (int k = r + 1; k < c.n; k++)
                sum -= A[r][k] * dz[k];
            dz[r] = sum / A[r][r];
        }
        double size = 0, zn = 0;
        for (int j = 0; j < c.n; j++) {
            z[j] += dz[j];
            size = fmax(size, fabs(dz[j]));
            zn = fmax(zn, fabs(z[j]));
        }
        m = residuals(&c, z, F);
        worst = 0;
        for (int i = 0; i < m; i++)
            worst = fmax(worst, fabs(F[i]));
        if (size <= 1e-15 * (1 + zn))
            break;
    }
    if (m < 0 || !(worst <= 1e-12))
        return ic_error_set(err, IC_ERR_UNABLE, 0,
                            "no tangential point converged near (%g, %g, %g) (residual %.3g)",
                            near->xyz[0], near->xyz[1], near->xyz[2], worst);
    unpack(&c, z, pt);
    if (c.par[0] || c.par[1]) {
        const int P = c.par[0] ? 0 : 1;
        if (ic_surface_eval(ic_pair_surface(pair, P), pt->xyz, pt->params[P], err) != IC_OK)
            return IC_ERR_UNABLE;
    }
    double d[3];
    ic_axpy3(d, pt->xyz, -1.0, near->xyz);
    if (ic_norm3(d) > reach)
        return ic_error_set(err, IC_ERR_UNABLE, 0,
                            "the nearest tangential point is %.3g away, beyond %g", ic_norm3(d),
                            reach);
    pt->residual = worst;
    (void)opt;
    return IC_OK;
}
