/* A primitive along a curve, one order at a time (surface_jets.h): the
 * formulas of parametric_on_jets and implicit_on_jets (primitive.c) on
 * one-variable series, each coefficient computed once. */
#include "surface_internal.h"

#include <math.h>
#include <string.h>

int ic_primitive_along_serves(const ic_surface *s) { return s->backend == BACKEND_PRIMITIVE; }

/* Order k of f g (the Cauchy product). */
static double product_step(const double *f, const double *g, int k)
{
    double sum = 0.0;
    for (int i = 0; i <= k; i++)
        sum += f[i] * g[k - i];
    return sum;
}

/* The local coordinates' order-k coefficients d[3] of the curve's x[3]:
 * the placement's rotation of x - center (the center is order 0 only). */
static void local_coords(const ic_surface *s, const double x[3], int k, double d[3])
{
    double v[3] = {x[0], x[1], x[2]};
    if (k == 0)
        for (int i = 0; i < 3; i++)
            v[i] -= s->prim.center[i];
    for (int j = 0; j < 3; j++)
        d[j] = s->placed ? s->frame[j][0] * v[0] + s->frame[j][1] * v[1] + s->frame[j][2] * v[2]
                         : v[j];
}

/* The local coordinates' order-k coefficients from the curve's. */
static void local_step(ic_primitive_along *pa, int k)
{
    const double x[3] = {pa->in[0][k], pa->in[1][k], pa->in[2][k]};
    double d[3];
    local_coords(pa->s, x, k, d);
    pa->d[0][k] = d[0], pa->d[1][k] = d[1], pa->d[2][k] = d[2];
}

/* The implicit torus' series at order k: the local coordinates, rho and
 * sum. */
static void torus_series(ic_primitive_along *pa, int k)
{
    const ic_primitive *p = &pa->s->prim;
    const double R = p->major_radius, r = p->radius;
    local_step(pa, k);
    pa->rho[k] = product_step(pa->d[0], pa->d[0], k) + product_step(pa->d[1], pa->d[1], k);
    pa->sum[k] = pa->rho[k] + product_step(pa->d[2], pa->d[2], k) + (k == 0 ? R * R - r * r : 0.0);
}

/* f's order-k coefficient from the series (torus_on_jets). */
static double torus_value(const ic_primitive_along *pa, int k)
{
    const ic_primitive *p = &pa->s->prim;
    return product_step(pa->sum, pa->sum, k) - 4.0 * p->major_radius * p->major_radius * pa->rho[k];
}

/* A quadric's order-k coefficient (implicit_on_jets):
 *     f_k = sum_i A_i [d_i^2]_k + B_i d_ik, and C at order 0. */
static double quadric_value(const ic_primitive_along *pa, int k)
{
    double f = k == 0 ? pa->C : 0.0;
    for (int i = 0; i < 3; i++)
        f += (pa->A[i] != 0.0 ? pa->A[i] * product_step(pa->d[i], pa->d[i], k) : 0.0) +
             pa->B[i] * pa->d[i][k];
    return f;
}

/* quadric_value at order k >= 3 when d's coefficients of order k are zero
 * and those of order k - 1 have just been found (last[3], as d holds them):
 * the same sums, term by term in the same order, without the terms that
 * are zero (the end terms d_0 d_k of each square, B . d_k): a sum that
 * starts at +0 never becomes -0, so adding a zero changes nothing, and the
 * jet method's results stay the same to the bit. The three sums go side by
 * side, so that they overlap. The newest coefficients come in registers,
 * not from d: read back just after they were written, a wide load the
 * compiler may make of two of them waits for the writes to reach the
 * cache, and each sum's second term waits on them. */
static double quadric_next(const ic_primitive_along *pa, int k, const double last[3])
{
    const double *x = pa->d[0], *y = pa->d[1], *z = pa->d[2];
    double s0 = 0.0 + x[1] * last[0], s1 = 0.0 + y[1] * last[1], s2 = 0.0 + z[1] * last[2];
    for (int j = 2; j <= k - 2; j++) {
        s0 += x[j] * x[k - j];
        s1 += y[j] * y[k - j];
        s2 += z[j] * z[k - j];
    }
    s0 += last[0] * x[1];
    s1 += last[1] * y[1];
    s2 += last[2] * z[1];
    double f = 0.0;
    f += pa->A[0] != 0.0 ? pa->A[0] * s0 : 0.0;
    f += pa->A[1] != 0.0 ? pa->A[1] * s1 : 0.0;
    f += pa->A[2] != 0.0 ? pa->A[2] * s2 : 0.0;
    return f;
}

/* Order k of sin a and cos a from a's coefficients up to k and theirs below:
 * k s_k = sum_{j=1..k} j a_j c_{k-j}, k c_k = -sum_{j=1..k} j a_j s_{k-j}
 * (E sin a = cos a E a, E the Euler operator; docs/jets.md). */
static void sin_cos_step(double *s, double *c, const double *a, int k)
{
    if (k == 0) {
        s[0] = sin(a[0]), c[0] = cos(a[0]);
        return;
    }
    double sk = 0.0, ck = 0.0;
    for (int j = 1; j <= k; j++) {
        sk += j * a[j] * c[k - j];
        ck -= j * a[j] * s[k - j];
    }
    s[k] = sk / k;
    c[k] = ck / k;
}

/* The parametric primitive's series at order k: sin and cos of u and v,
 * and the torus' w. */
static void parametric_series(ic_primitive_along *pa, int k)
{
    const ic_primitive *p = &pa->s->prim;
    sin_cos_step(pa->su, pa->cu, pa->in[0], k);
    sin_cos_step(pa->sv, pa->cv, pa->in[1], k);
    if (p->kind == IC_PRIM_TORUS) /* w = R + r cos v */
        pa->w[k] = p->radius * pa->cv[k] + (k == 0 ? p->major_radius : 0.0);
}

/* R's order-k coefficient in local coordinates from the series
 * (parametric_on_jets). */
static void parametric_value(const ic_primitive_along *pa, int k, double l[3])
{
    const ic_surface *s = pa->s;
    const ic_primitive *p = &s->prim;
    const double *u = pa->in[0], *v = pa->in[1];
    switch (p->kind) {
    case IC_PRIM_PLANE:
        for (int c = 0; c < 3; c++)
            l[c] = s->plane_frame[0][c] * u[k] + s->plane_frame[1][c] * v[k];
        break;
    case IC_PRIM_SPHERE:
    case IC_PRIM_ELLIPSOID: {
        const int sph = p->kind == IC_PRIM_SPHERE;
        l[0] = (sph ? p->radius : p->axes[0]) * product_step(pa->cu, pa->cv, k);
        l[1] = (sph ? p->radius : p->axes[1]) * product_step(pa->su, pa->cv, k);
        l[2] = (sph ? p->radius : p->axes[2]) * pa->sv[k];
        break;
    }
    case IC_PRIM_CYLINDER:
        l[0] = p->radius * pa->cu[k];
        l[1] = p->radius * pa->su[k];
        l[2] = v[k];
        break;
    case IC_PRIM_CONE: {
        const double t = tan(p->half_angle);
        l[0] = t * product_step(pa->cu, v, k);
        l[1] = t * product_step(pa->su, v, k);
        l[2] = v[k];
        break;
    }
    case IC_PRIM_TORUS:
        l[0] = product_step(pa->w, pa->cu, k);
        l[1] = product_step(pa->w, pa->su, k);
        l[2] = p->radius * pa->sv[k];
        break;
    }
}

void ic_primitive_along_start(ic_primitive_along *pa, const ic_surface *s, const double *at)
{
    /* the series are written order by order before they are read: only the
     * curve starts zero */
    memset(pa->in, 0, sizeof pa->in);
    pa->s = s;
    const int nin = s->kind == IC_PARAMETRIC ? 2 : 3;
    for (int i = 0; i < nin; i++)
        pa->in[i][0] = at[i];
    pa->quadric = s->kind == IC_IMPLICIT && s->prim.kind != IC_PRIM_TORUS;
    if (s->kind == IC_IMPLICIT)
        ic_primitive_quadric_coefficients(&s->prim, pa->A, pa->B, &pa->C);
    ic_primitive_along_finish(pa, 0);
}

void ic_primitive_along_finish(ic_primitive_along *pa, int k)
{
    if (pa->quadric) /* its only series: the local coordinates */
        local_step(pa, k);
    else if (pa->s->kind == IC_IMPLICIT)
        torus_series(pa, k);
    else
        parametric_series(pa, k);
}

void ic_primitive_along_step(ic_primitive_along *pa, int k, double *out)
{
    const ic_surface *s = pa->s;
    ic_primitive_along_finish(pa, k);
    if (pa->quadric) {
        out[0] = quadric_value(pa, k);
        return;
    }
    if (s->kind == IC_IMPLICIT) {
        out[0] = torus_value(pa, k);
        return;
    }
    double l[3] = {0.0, 0.0, 0.0}; /* local coordinates */
    parametric_value(pa, k, l);
    /* to space: the placement's rotation, then (order 0) the center */
    for (int c = 0; c < 3; c++) {
        out[c] = s->placed ? s->frame[0][c] * l[0] + s->frame[1][c] * l[1] + s->frame[2][c] * l[2]
                           : l[c];
        if (k == 0)
            out[c] += s->prim.center[c];
    }
}

void ic_primitive_along_advance(ic_primitive_along *pa, int k, double in0, double in1, double in2,
                                double *next)
{
    const ic_surface *s = pa->s;
    pa->in[0][k] = in0, pa->in[1][k] = in1;
    if (s->kind == IC_IMPLICIT)
        pa->in[2][k] = in2;
    if (!pa->quadric || k < 2) {
        ic_primitive_along_finish(pa, k);
        ic_primitive_along_step(pa, k + 1, next);
        return;
    }
    /* the local coordinates of order k >= 2 (local_step's, the center
     * being of order 0 only) */
    double d[3] = {in0, in1, in2};
    if (s->placed)
        for (int j = 0; j < 3; j++)
            d[j] = s->frame[j][0] * in0 + s->frame[j][1] * in1 + s->frame[j][2] * in2;
    pa->d[0][k] = d[0], pa->d[1][k] = d[1], pa->d[2][k] = d[2];
    next[0] = quadric_next(pa, k + 1, d);
}
