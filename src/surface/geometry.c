/*
 * Local geometry of a surface at a point: unit normal, first and second
 * fundamental forms, principal curvatures and directions.
 *
 * Principal curvatures are the eigenvalues of II relative to I. Writing
 * I = R^T R (Cholesky) turns them into the eigenvalues of the symmetric
 * S = R^-T II R^-1 = [[a, b], [b, c]]: k = (a + c)/2 +- sqrt(((a - c)/2)^2 + b^2).
 * This form has no cancellation at umbilics, unlike H +- sqrt(H^2 - K),
 * which loses half the digits there.
 */
#include "common/args.h"
#include "surface_internal.h"

#include <math.h>
#include <string.h>

static double dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross3(double *c, const double *a, const double *b)
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

static double norm3(const double *a) { return sqrt(dot3(a, a)); }

/* From E, F, G, L, M, N and the basis: curvatures and directions. */
static void principal(ic_surface_geometry *g)
{
    const double E = g->first[0], F = g->first[1], G = g->first[2];
    const double L = g->second[0], M = g->second[1], N = g->second[2];
    /* R = [[r11, r12], [0, r22]], R^-1 = [[p11, p12], [0, p22]] */
    const double r11 = sqrt(E), r12 = F / r11, r22 = sqrt(G - r12 * r12);
    const double p11 = 1.0 / r11, p12 = -r12 / (r11 * r22), p22 = 1.0 / r22;
    const double a = p11 * p11 * L;
    const double b = p11 * (p12 * L + p22 * M);
    const double c = p12 * p12 * L + 2.0 * p12 * p22 * M + p22 * p22 * N;
    const double m = 0.5 * (a + c), d = 0.5 * (a - c), root = hypot(d, b);
    g->principal_curvatures[0] = m + root;
    g->principal_curvatures[1] = m - root;
    g->mean = m;
    g->gauss = (m + root) * (m - root);
    /* eigenvector of k1 in orthonormal coordinates: angle theta with
     * tan(2 theta) = 2b / (a - c); any direction at an umbilic (theta = 0) */
    const double theta = 0.5 * atan2(b, d);
    const double v[2][2] = {{cos(theta), sin(theta)}, {-sin(theta), cos(theta)}};
    for (int k = 0; k < 2; k++) {
        double *w = g->principal_directions_basis[k];
        w[0] = p11 * v[k][0] + p12 * v[k][1];
        w[1] = p22 * v[k][1];
        for (int i = 0; i < 3; i++)
            g->principal_directions[k][i] = w[0] * g->basis[0][i] + w[1] * g->basis[1][i];
    }
}

/* order 2: everything; order 1: the point, value, basis and normal only */
static ic_status parametric_geometry(ic_surface *s, ic_surface_geometry *g, const double *at,
                                     int order, ic_error *err)
{
    const ic_jet_space *sp = ic_surface_space(s, order, err);
    if (!sp)
        return err ? err->code : IC_ERR_NOMEM;
    /* slot 1: the Taylor backends may use slot 0 */
    double *t = ic_surface_work(s, IC_WORK_COMPOSE, 3 * 6);
    if (!t)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory");
    ic_status st = ic_surface_taylor(s, t, at, sp, err);
    if (st != IC_OK)
        return st;
    /* monomials: 1, u, v, u^2, uv, v^2; R_uu = 2 c[u^2], R_uv = c[uv] */
    const int n = order == 2 ? 6 : 3;
    double Ruu[3], Ruv[3], Rvv[3];
    for (int k = 0; k < 3; k++) {
        g->point[k] = t[n * k];
        g->basis[0][k] = t[n * k + 1];
        g->basis[1][k] = t[n * k + 2];
        Ruu[k] = order == 2 ? 2.0 * t[n * k + 3] : 0.0;
        Ruv[k] = order == 2 ? t[n * k + 4] : 0.0;
        Rvv[k] = order == 2 ? 2.0 * t[n * k + 5] : 0.0;
    }
    g->value = 0.0;
    double c[3];
    cross3(c, g->basis[0], g->basis[1]);
    const double len = norm3(c);
    const double scale = fmax(norm3(g->basis[0]), norm3(g->basis[1]));
    g->normal_length = len;
    if (!(len > IC_SURFACE_DEGENERATE * scale * scale))
        return ic_error_set(err, IC_ERR_DOMAIN, 0,
                            "degenerate point at (%.17g, %.17g): R_u x R_v = 0, the normal is "
                            "undefined (|R_u x R_v| = %g)",
                            at[0], at[1], len);
    for (int k = 0; k < 3; k++)
        g->normal[k] = c[k] / len;
    if (order < 2)
        return IC_OK;
    g->first[0] = dot3(g->basis[0], g->basis[0]);
    g->first[1] = dot3(g->basis[0], g->basis[1]);
    g->first[2] = dot3(g->basis[1], g->basis[1]);
    g->second[0] = dot3(Ruu, g->normal);
    g->second[1] = dot3(Ruv, g->normal);
    g->second[2] = dot3(Rvv, g->normal);
    principal(g);
    return IC_OK;
}

static ic_status implicit_geometry(ic_surface *s, ic_surface_geometry *g, const double *at,
                                   int order, ic_error *err)
{
    const ic_jet_space *sp = ic_surface_space(s, order, err);
    if (!sp)
        return err ? err->code : IC_ERR_NOMEM;
    double *t = ic_surface_work(s, IC_WORK_COMPOSE, 10);
    if (!t)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory");
    ic_status st = ic_surface_taylor(s, t, at, sp, err);
    if (st != IC_OK)
        return st;
    /* monomials: 1, x, y, z, x^2, xy, xz, y^2, yz, z^2 */
    const double grad[3] = {t[1], t[2], t[3]};
    double Hs[3][3] = {{0}};
    if (order == 2) {
        const double H[3][3] = {
            {2 * t[4], t[5], t[6]}, {t[5], 2 * t[7], t[8]}, {t[6], t[8], 2 * t[9]}};
        memcpy(Hs, H, sizeof H);
    }
    memcpy(g->point, at, 3 * sizeof *at);
    g->value = t[0];
    const double len = norm3(grad);
    g->normal_length = len;
    if (!(len > 0.0) || !isfinite(len))
        return ic_error_set(err, IC_ERR_DOMAIN, 0,
                            "degenerate point at (%.17g, %.17g, %.17g): grad f = 0, the normal "
                            "is undefined",
                            at[0], at[1], at[2]);
    for (int k = 0; k < 3; k++)
        g->normal[k] = grad[k] / len;
    if (order < 2)
        return IC_OK;
    /* e1: the coordinate axis least aligned with N, made orthogonal */
    int m = 0;
    for (int k = 1; k < 3; k++)
        if (fabs(g->normal[k]) < fabs(g->normal[m]))
            m = k;
    double *e1 = g->basis[0], *e2 = g->basis[1];
    for (int k = 0; k < 3; k++)
        e1[k] = (k == m) - g->normal[m] * g->normal[k];
    const double l1 = norm3(e1);
    for (int k = 0; k < 3; k++)
        e1[k] /= l1;
    cross3(e2, g->normal, e1);
    g->first[0] = 1.0;
    g->first[1] = 0.0;
    g->first[2] = 1.0;
    /* II(X, Y) = -X^T H Y / |grad f| */
    double He[2][3];
    for (int a = 0; a < 2; a++)
        for (int i = 0; i < 3; i++)
            He[a][i] = dot3(Hs[i], g->basis[a]);
    g->second[0] = -dot3(e1, He[0]) / len;
    g->second[1] = -dot3(e1, He[1]) / len;
    g->second[2] = -dot3(e2, He[1]) / len;
    principal(g);
    return IC_OK;
}

ic_status ic_surface_geometry_at(ic_surface *s, ic_surface_geometry *g, const double *at,
                                 ic_error *err)
{
    IC_ARG_NOT_NULL(s, "s");
    IC_ARG_NOT_NULL(g, "g");
    IC_ARG_NOT_NULL(at, "at");
    memset(g, 0, sizeof *g);
    if (s->kind == IC_PARAMETRIC)
        return parametric_geometry(s, g, at, 2, err);
    return implicit_geometry(s, g, at, 2, err);
}

ic_status ic_surface_normal_at(ic_surface *s, ic_surface_geometry *g, const double *at,
                               ic_error *err)
{
    IC_ARG_NOT_NULL(s, "s");
    IC_ARG_NOT_NULL(g, "g");
    IC_ARG_NOT_NULL(at, "at");
    memset(g, 0, sizeof *g);
    if (s->kind == IC_PARAMETRIC)
        return parametric_geometry(s, g, at, 1, err);
    return implicit_geometry(s, g, at, 1, err);
}
