/*
 * A plane's section of a quadric primitive (exact_conic.h). In orthonormal
 * coordinates x of the plane, p = o + x1 u1 + x2 u2, the quadric's f
 * restricts to the conic q(x) = x^T A2 x + 2 b2 . x + c2; where A2 is
 * definite it is the ellipse (x - x0)^T A2 (x - x0) = k about the centre
 * x0 = -A2^-1 b2, with semi-axes sqrt(k / lambda) along A2's eigenvectors,
 * and that ellipse is the whole intersection. Everything else (a parabola,
 * a hyperbola, a pair of lines, a point) is left to the general path, as
 * are nearly degenerate ellipses and those along which the surfaces nearly
 * touch.
 */
#include "exact_conic.h"
#include "exact_profile.h"
#include "common/vec3.h"

#include <math.h>
#include <string.h>

int ic_quadric_of(const ic_primitive *p, ic_quadric *q)
{
    if (ic_primitive_frame(p, q->e, NULL) != IC_OK)
        return -1;
    q->p = p;
    memcpy(q->c, p->center, sizeof q->c);
    switch (p->kind) {
    case IC_PRIM_SPHERE:
    case IC_PRIM_CYLINDER:
        q->d[0] = q->d[1] = 1, q->d[2] = p->kind == IC_PRIM_SPHERE;
        q->k0 = p->radius * p->radius;
        return 0;
    case IC_PRIM_CONE: {
        const double t = tan(p->half_angle);
        q->d[0] = q->d[1] = 1, q->d[2] = -t * t;
        q->k0 = 0;
        return 0;
    }
    case IC_PRIM_ELLIPSOID:
        for (int i = 0; i < 3; i++)
            q->d[i] = 1 / (p->axes[i] * p->axes[i]);
        q->k0 = 1;
        return 0;
    case IC_PRIM_PLANE:
    case IC_PRIM_TORUS:
        break;
    }
    return -1;
}

/* y = 2 M x. */
static void twice_m(const ic_quadric *q, const double *x, double *y)
{
    double l[3];
    for (int i = 0; i < 3; i++)
        l[i] = 2 * q->d[i] * ic_dot3(q->e[i], x);
    for (int k = 0; k < 3; k++)
        y[k] = l[0] * q->e[0][k] + l[1] * q->e[1][k] + l[2] * q->e[2][k];
}

void ic_quadric_gradient_along(const ic_quadric *q, const ic_exact_ellipse *e, double g[3][3])
{
    double w[3], au[3], bv[3];
    ic_axpy3(w, e->c, -1.0, q->c);
    ic_scale3(au, e->u, e->a);
    ic_scale3(bv, e->v, e->b);
    twice_m(q, w, g[0]);
    twice_m(q, au, g[1]);
    twice_m(q, bv, g[2]);
}

/* The conic in the plane's coordinates: A2 (symmetric), b2, and the plane
 * point o (the foot of the quadric's centre). */
typedef struct {
    double A[2][2], b[2], o[3], det;
} conic2;

/* W_ij = e_i . u_j and the foot's local coordinates w = -delta nu (nu the
 * normal's, delta the centre's height above the plane): A2 = W^T D W, b2 =
 * W^T D w. det A2 by Cauchy-Binet: the 2x2 minors of W are the components
 * of u1 x u2 = n in the frame, so det = d1 d2 nu3^2 + d1 d3 nu2^2 + d2 d3
 * nu1^2, free of the cancellation of A11 A22 - A12^2 where all d_i agree. */
static void restrict_to_plane(const ic_quadric *q, const double (*pf)[3], double delta, conic2 *cn)
{
    double W[3][2], nu[3], w[3];
    for (int i = 0; i < 3; i++) {
        W[i][0] = ic_dot3(q->e[i], pf[0]), W[i][1] = ic_dot3(q->e[i], pf[1]);
        nu[i] = ic_dot3(q->e[i], pf[2]);
        w[i] = -delta * nu[i];
    }
    for (int j = 0; j < 2; j++) {
        cn->b[j] = 0;
        for (int l = 0; l < 2; l++)
            cn->A[j][l] = 0;
        for (int i = 0; i < 3; i++) {
            cn->b[j] += q->d[i] * W[i][j] * w[i];
            for (int l = 0; l < 2; l++)
                cn->A[j][l] += q->d[i] * W[i][j] * W[i][l];
        }
    }
    const double *d = q->d;
    cn->det =
        d[0] * d[1] * nu[2] * nu[2] + d[0] * d[2] * nu[1] * nu[1] + d[1] * d[2] * nu[0] * nu[0];
    ic_axpy3(cn->o, q->c, -delta, pf[2]);
}

/* The eigenvalues lo <= hi of a positive definite A2 (hi without
 * cancellation, lo = det / hi) and the unit eigenvector of lo. */
static void eigen2(const conic2 *cn, double *lo, double *hi, double vec[2])
{
    const double a = cn->A[0][0], b = cn->A[0][1], d = cn->A[1][1];
    *hi = 0.5 * (a + d + hypot(a - d, 2 * b));
    *lo = cn->det / *hi;
    /* (b, lo - a) and (lo - d, b) both lie along it: the longer is the
     * better conditioned */
    double x[2] = {b, *lo - a}, y[2] = {*lo - d, b};
    if (hypot(y[0], y[1]) > hypot(x[0], x[1]))
        x[0] = y[0], x[1] = y[1];
    const double len = hypot(x[0], x[1]);
    if (len > 0)
        vec[0] = x[0] / len, vec[1] = x[1] / len;
    else /* A2 = lambda I: a circle, any axis */
        vec[0] = 1, vec[1] = 0;
}

/* k = -f(C) at the centre C = o + x0 . (u1, u2), evaluated in the frame. */
static double value_at_centre(const ic_quadric *q, const conic2 *cn, const double (*pf)[3],
                              double *C)
{
    const double x0 = -(cn->A[1][1] * cn->b[0] - cn->A[0][1] * cn->b[1]) / cn->det;
    const double x1 = -(cn->A[0][0] * cn->b[1] - cn->A[0][1] * cn->b[0]) / cn->det;
    double w[3];
    for (int k = 0; k < 3; k++)
        C[k] = cn->o[k] + x0 * pf[0][k] + x1 * pf[1][k];
    ic_axpy3(w, C, -1.0, q->c);
    double f = -q->k0;
    for (int i = 0; i < 3; i++) {
        const double l = ic_dot3(q->e[i], w);
        f += q->d[i] * l * l;
    }
    return -f;
}

/* An ellipsoid's gap: how far the plane (its centre at height delta) is
 * from the tangent plane parallel to it, sqrt(n^T M^-1 n) - |delta|
 * (positive where it cuts the ellipsoid). */
static double ellipsoid_gap(const ic_quadric *q, const double *n, double delta)
{
    double h2 = 0;
    for (int i = 0; i < 3; i++) {
        const double nu = ic_dot3(q->e[i], n);
        h2 += nu * nu / q->d[i];
    }
    return sqrt(h2) - fabs(delta);
}

/* The largest |g[0] + cos g[1] + sin g[2]| is at most |g[0]| plus the
 * largest singular value of (g[1] g[2]). */
static double gradient_bound(const double (*g)[3])
{
    const double p = ic_dot3(g[1], g[1]), r = ic_dot3(g[2], g[2]), s = ic_dot3(g[1], g[2]);
    return ic_norm3(g[0]) + sqrt(0.5 * (p + r + hypot(p - r, 2 * s)));
}

/* Whether the angle between the normals stays above IC_EXACT_MIN_ANGLE all
 * along. Its sine is |g_t| / |g|, g_t the gradient's part in the plane,
 * which is q's gradient 2 A2 (x - x0) in the plane's coordinates. On the
 * ellipse x - x0 = A cos E1 + B sin E2 (lo A^2 = hi B^2 = k) that is
 * 2 sqrt(k) sqrt(lo cos^2 + hi sin^2) >= 2 sqrt(k lo); |g| is bounded by
 * gradient_bound. A lower bound of the sine: the true angle is larger. */
static int angle_clear(double k, double lo, const double (*g)[3])
{
    return 2 * sqrt(k * lo) >= sin(IC_EXACT_MIN_ANGLE) * gradient_bound(g);
}

/* The coaxial cases belong to the revolution path (exact_revolution.c),
 * which runs first: what it left is for the general path. A sphere is
 * coaxial with every plane; a cylinder or cone when its axis is along the
 * plane's normal. */
static int revolution_case(const ic_quadric *q, const double *n)
{
    double x[3];
    ic_cross3(x, q->e[2], n);
    return q->p->kind == IC_PRIM_SPHERE ||
           (q->p->kind != IC_PRIM_ELLIPSOID && ic_norm3(x) <= IC_EXACT_COAXIAL);
}

int ic_exact_plane_section(const ic_primitive *plane, const ic_quadric *q, double L,
                           ic_exact_ellipse *out)
{
    double pf[3][3], C[3];
    if (ic_primitive_frame(plane, pf, NULL) != IC_OK || revolution_case(q, pf[2]))
        return -1;
    const double delta = ic_dot3(pf[2], q->c) - ic_dot3(pf[2], plane->center);
    if (q->p->kind == IC_PRIM_CONE && fabs(delta) < IC_EXACT_APEX_CLEARANCE * L)
        return -1;
    if (q->p->kind == IC_PRIM_ELLIPSOID) {
        const double gap = ellipsoid_gap(q, pf[2], delta);
        if (fabs(gap) <= IC_EXACT_NEAR * L)
            return -1;
        if (gap < 0)
            return 0;
    }
    conic2 cn;
    restrict_to_plane(q, (const double(*)[3])pf, delta, &cn);
    if (!(cn.det > 0) || !(cn.A[0][0] + cn.A[1][1] > 0)) /* no ellipse */
        return -1;
    double lo, hi, vec[2];
    eigen2(&cn, &lo, &hi, vec);
    const double k = value_at_centre(q, &cn, (const double(*)[3])pf, C);
    if (!(k > 0))
        return -1;
    memset(out, 0, sizeof *out);
    memcpy(out->c, C, sizeof out->c);
    for (int j = 0; j < 3; j++)
        out->u[j] = vec[0] * pf[0][j] + vec[1] * pf[1][j];
    ic_cross3(out->v, pf[2], out->u);
    out->a = sqrt(k / lo), out->b = sqrt(k / hi);
    if (!ic_exact_ellipse_fair(out, L))
        return -1;
    memcpy(out->grad[0][0], pf[2], sizeof pf[2]);
    ic_quadric_gradient_along(q, out, out->grad[1]);
    return angle_clear(k, lo, (const double(*)[3])out->grad[1]) ? 1 : -1;
}
