/*
 * Interval enclosures of the parametric primitives and of their first
 * derivatives over a (u, v) box: the same formulas as their jets
 * (primitive.c) in interval arithmetic, each component a sum of products of
 * cos/sin/identity enclosures (rotated to space when placed), so a
 * parametric primitive is searched with proofs like a formula surface
 * (docs/tracing.md, "Completeness").
 */
#include "surface_internal.h"

#include <math.h>

static ic_interval cst(double c) { return (ic_interval){c, c}; }

static ic_interval mul(ic_interval a, ic_interval b) { return ic_interval_mul(a, b); }

static ic_interval add(ic_interval a, ic_interval b) { return ic_interval_add(a, b); }

/* c k a (a product of interval factors scaled by a constant). */
static ic_interval scaled(double k, ic_interval a) { return mul(cst(k), a); }

/* Fills the value and both partial derivatives of one component. */
static void set(ic_interval_grad *g, ic_interval v, ic_interval du, ic_interval dv)
{
    g->v = v;
    g->d[0] = du;
    g->d[1] = dv;
    g->d[2] = cst(0);
}

/* sphere and ellipsoid: (a cos u cos v, b sin u cos v, c sin v) */
static void ellipsoid(ic_interval_grad *o, const double k[3], ic_interval cu, ic_interval su,
                      ic_interval cv, ic_interval sv)
{
    set(&o[0], scaled(k[0], mul(cu, cv)), scaled(-k[0], mul(su, cv)), scaled(-k[0], mul(cu, sv)));
    set(&o[1], scaled(k[1], mul(su, cv)), scaled(k[1], mul(cu, cv)), scaled(-k[1], mul(su, sv)));
    set(&o[2], scaled(k[2], sv), cst(0), scaled(k[2], cv));
}

/* torus: ((R + r cos v) cos u, (R + r cos v) sin u, r sin v) */
static void torus(ic_interval_grad *o, double R, double r, ic_interval cu, ic_interval su,
                  ic_interval cv, ic_interval sv)
{
    const ic_interval w = add(cst(R), scaled(r, cv));
    set(&o[0], mul(w, cu), ic_interval_neg(mul(w, su)), scaled(-r, mul(sv, cu)));
    set(&o[1], mul(w, su), mul(w, cu), scaled(-r, mul(sv, su)));
    set(&o[2], scaled(r, sv), cst(0), scaled(r, cv));
}

/* A placed primitive: the local (x, y, z) and their (u, v) derivatives
 * rotated to space, R - center = Q R_local. */
static void to_space(const double frame[3][3], ic_interval_grad *o)
{
    for (int d = -1; d < 2; d++) { /* the value, then d/du and d/dv */
        ic_interval v[3];
        for (int k = 0; k < 3; k++)
            v[k] = d < 0 ? o[k].v : o[k].d[d];
        ic_placement_interval_to_space(frame, v);
        for (int k = 0; k < 3; k++)
            *(d < 0 ? &o[k].v : &o[k].d[d]) = v[k];
    }
}

void ic_primitive_param_interval_grad(const ic_surface *s, ic_interval_grad *o,
                                      const ic_interval *in)
{
    const ic_primitive *p = &s->prim;
    const ic_interval u = in[0], v = in[1];
    const ic_interval cu = ic_interval_cos(u), su = ic_interval_sin(u);
    const ic_interval cv = ic_interval_cos(v), sv = ic_interval_sin(v);
    switch (p->kind) {
    case IC_PRIM_PLANE:
        for (int k = 0; k < 3; k++)
            set(&o[k], add(scaled(s->plane_frame[0][k], u), scaled(s->plane_frame[1][k], v)),
                cst(s->plane_frame[0][k]), cst(s->plane_frame[1][k]));
        break;
    case IC_PRIM_SPHERE:
    case IC_PRIM_ELLIPSOID: {
        const int sph = p->kind == IC_PRIM_SPHERE;
        const double k[3] = {sph ? p->radius : p->axes[0], sph ? p->radius : p->axes[1],
                             sph ? p->radius : p->axes[2]};
        ellipsoid(o, k, cu, su, cv, sv);
        break;
    }
    case IC_PRIM_CYLINDER: /* (r cos u, r sin u, v) */
        set(&o[0], scaled(p->radius, cu), scaled(-p->radius, su), cst(0));
        set(&o[1], scaled(p->radius, su), scaled(p->radius, cu), cst(0));
        set(&o[2], v, cst(0), cst(1));
        break;
    case IC_PRIM_CONE: { /* (t v cos u, t v sin u, v), t = tan(half angle) as the jets */
        const double t = tan(p->half_angle);
        set(&o[0], scaled(t, mul(cu, v)), scaled(-t, mul(su, v)), scaled(t, cu));
        set(&o[1], scaled(t, mul(su, v)), scaled(t, mul(cu, v)), scaled(t, su));
        set(&o[2], v, cst(0), cst(1));
        break;
    }
    case IC_PRIM_TORUS:
        torus(o, p->major_radius, p->radius, cu, su, cv, sv);
        break;
    }
    if (s->placed)
        to_space(s->frame, o);
    for (int k = 0; k < 3; k++)
        o[k].v = add(o[k].v, cst(p->center[k]));
}
