/*
 * Interval enclosures of the implicit primitives and of their gradients over
 * a box of space: the box's offsets from the center are taken to local
 * coordinates (an enclosure of the rotated box, when placed), f_local and
 * its gradient are enclosed there, and the gradient is rotated back, all in
 * outward-rounded interval arithmetic (expr.h), so the enclosures are sound.
 */
#include "surface_internal.h"

static ic_interval cst(double c) { return (ic_interval){c, c}; }

/* f_local over the local box d. */
static ic_interval local_value(const ic_primitive *p, const ic_interval d[3])
{
    ic_interval sq[3];
    for (int i = 0; i < 3; i++)
        sq[i] = ic_interval_pow_int(d[i], 2);
    if (p->kind == IC_PRIM_TORUS) {
        /* (|d|^2 + R^2 - r^2)^2 - 4 R^2 (dx^2 + dy^2) */
        const double R = p->major_radius, r = p->radius;
        const ic_interval rho = ic_interval_add(sq[0], sq[1]);
        const ic_interval sum = ic_interval_add(ic_interval_add(rho, sq[2]), cst(R * R - r * r));
        return ic_interval_sub(ic_interval_pow_int(sum, 2), ic_interval_mul(cst(4 * R * R), rho));
    }
    double A[3], B[3], C;
    ic_primitive_quadric_coefficients(p, A, B, &C);
    ic_interval f = cst(C);
    for (int i = 0; i < 3; i++) {
        f = ic_interval_add(f, ic_interval_mul(cst(A[i]), sq[i]));
        f = ic_interval_add(f, ic_interval_mul(cst(B[i]), d[i]));
    }
    return f;
}

/* grad f_local over the local box d. */
static void local_gradient(const ic_primitive *p, const ic_interval d[3], ic_interval g[3])
{
    if (p->kind == IC_PRIM_TORUS) {
        /* grad of (|d|^2 + R^2 - r^2)^2 - 4 R^2 (dx^2 + dy^2):
         * 4 sum d - 8 R^2 (dx, dy, 0) */
        const double R = p->major_radius, r = p->radius;
        ic_interval sum = cst(R * R - r * r);
        for (int i = 0; i < 3; i++)
            sum = ic_interval_add(sum, ic_interval_pow_int(d[i], 2));
        for (int i = 0; i < 3; i++) {
            const ic_interval k = i < 2 ? ic_interval_sub(sum, cst(2 * R * R)) : sum;
            g[i] = ic_interval_mul(ic_interval_mul(cst(4), d[i]), k);
        }
        return;
    }
    double A[3], B[3], C;
    ic_primitive_quadric_coefficients(p, A, B, &C);
    for (int i = 0; i < 3; i++) /* 2 A_i d_i + B_i */
        g[i] = ic_interval_add(ic_interval_mul(cst(2 * A[i]), d[i]), cst(B[i]));
}

/* The box's offsets from the center, in local coordinates. */
static void local_box(const ic_surface *s, const ic_interval *in, ic_interval d[3])
{
    for (int i = 0; i < 3; i++)
        d[i] = ic_interval_sub(in[i], cst(s->prim.center[i]));
    if (s->placed)
        ic_placement_interval_to_local(s->frame, d);
}

ic_status ic_primitive_interval(ic_surface *s, ic_interval *out, const ic_interval *in,
                                ic_error *err)
{
    ic_interval d[3];
    local_box(s, in, d);
    out[0] = local_value(&s->prim, d);
    (void)err;
    return IC_OK;
}

void ic_primitive_interval_grad(ic_surface *s, ic_interval_grad *out, const ic_interval *in)
{
    ic_interval d[3];
    local_box(s, in, d);
    out->v = local_value(&s->prim, d);
    local_gradient(&s->prim, d, out->d);
    if (s->placed) /* grad f = Q grad f_local */
        ic_placement_interval_to_space(s->frame, out->d);
}
