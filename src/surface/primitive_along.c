/* A parametric primitive along a parameter curve, one order at a time
 * (surface_jets.h): the formulas of parametric_on_jets (primitive.c) on
 * one-variable series, each coefficient computed once. */
#include "surface_internal.h"

#include <math.h>

int ic_primitive_along_serves(const ic_surface *s)
{
    return s->backend == BACKEND_PRIMITIVE && s->kind == IC_PARAMETRIC;
}

void ic_primitive_along_start(ic_primitive_along *pa, const ic_surface *s, double u0, double v0)
{
    pa->s = s;
    for (int k = 0; k <= IC_JET_MAX_ORDER; k++)
        pa->u[k] = pa->v[k] = 0.0;
    pa->u[0] = u0, pa->v[0] = v0;
    pa->cu[0] = cos(u0), pa->su[0] = sin(u0);
    pa->cv[0] = cos(v0), pa->sv[0] = sin(v0);
    pa->w[0] = s->prim.major_radius + s->prim.radius * pa->cv[0];
}

/* Order k of sin a and cos a from a's coefficients up to k and theirs below:
 * k s_k = sum_{j=1..k} j a_j c_{k-j}, k c_k = -sum_{j=1..k} j a_j s_{k-j}
 * (E sin a = cos a E a, E the Euler operator; docs/jets.md). */
static void sin_cos_step(double *s, double *c, const double *a, int k)
{
    double sk = 0.0, ck = 0.0;
    for (int j = 1; j <= k; j++) {
        sk += j * a[j] * c[k - j];
        ck -= j * a[j] * s[k - j];
    }
    s[k] = sk / k;
    c[k] = ck / k;
}

/* Order k of f g (the Cauchy product). */
static double product_step(const double *f, const double *g, int k)
{
    double sum = 0.0;
    for (int i = 0; i <= k; i++)
        sum += f[i] * g[k - i];
    return sum;
}

void ic_primitive_along_step(ic_primitive_along *pa, int k, double out[3])
{
    const ic_surface *s = pa->s;
    const ic_primitive *p = &s->prim;
    sin_cos_step(pa->su, pa->cu, pa->u, k);
    sin_cos_step(pa->sv, pa->cv, pa->v, k);
    double l[3] = {0.0, 0.0, 0.0}; /* local coordinates */
    switch (p->kind) {
    case IC_PRIM_PLANE:
        for (int c = 0; c < 3; c++)
            l[c] = s->plane_frame[0][c] * pa->u[k] + s->plane_frame[1][c] * pa->v[k];
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
        l[2] = pa->v[k];
        break;
    case IC_PRIM_CONE: {
        const double t = tan(p->half_angle);
        l[0] = t * product_step(pa->cu, pa->v, k);
        l[1] = t * product_step(pa->su, pa->v, k);
        l[2] = pa->v[k];
        break;
    }
    case IC_PRIM_TORUS:
        pa->w[k] = p->radius * pa->cv[k]; /* w = R + r cos v */
        l[0] = product_step(pa->w, pa->cu, k);
        l[1] = product_step(pa->w, pa->su, k);
        l[2] = p->radius * pa->sv[k];
        break;
    }
    /* to space: the placement's rotation (the center is order 0 only) */
    for (int c = 0; c < 3; c++)
        out[c] = s->placed ? s->frame[0][c] * l[0] + s->frame[1][c] * l[1] + s->frame[2][c] * l[2]
                           : l[c];
}
