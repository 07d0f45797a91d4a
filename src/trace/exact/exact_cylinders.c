/*
 * Two cylinders of equal radius r whose axes meet (exact_conic.h). With
 * unit axes a, b through the common point c and w = p - c, F_A = |w|^2 -
 * (w.a)^2 - r^2 and F_B = |w|^2 - (w.b)^2 - r^2, so F_A - F_B =
 * (w.(b - a)) (w.(b + a)): the intersection is cylinder A's sections by
 * the two planes through c normal to b - a and to b + a, two ellipses.
 * Their common line c + t m, m = a x b / |a x b|, meets A at c +- r m,
 * where both ellipses pass and the cylinders touch (w.a = w.b = 0, one
 * normal w): two branch points, the ellipses crossing there at right
 * angles. A point c + s (a + b) / |a + b| of the first plane is on A where
 * s^2 (1 - |a + b|^2 / 4) = s^2 |a - b|^2 / 4 = r^2: the first ellipse has
 * semi-axes r along m and 2 r / |a - b| along a + b; the second r along m
 * and 2 r / |a + b| along b - a.
 */
#include "exact_conic.h"
#include "exact_profile.h"
#include "common/vec3.h"

#include <math.h>
#include <string.h>

/* The point c of A's axis nearest B's (a common point within
 * IC_EXACT_COAXIAL L), and m = a x b / |a x b|: 0, or -1 when the axes are
 * nearly parallel (within IC_EXACT_MIN_ANGLE, either way) or do not meet. */
static int axes_meet(const ic_quadric *A, const ic_quadric *B, double L, double *c, double *m)
{
    const double *a = A->e[2], *b = B->e[2];
    double w[3];
    ic_cross3(m, a, b);
    const double s = ic_norm3(m), beta = ic_dot3(a, b);
    if (atan2(s, fabs(beta)) < IC_EXACT_MIN_ANGLE)
        return -1;
    ic_scale3(m, m, 1 / s);
    ic_axpy3(w, B->c, -1.0, A->c);
    if (fabs(ic_dot3(w, m)) > IC_EXACT_COAXIAL * L)
        return -1;
    /* (c - c_B) normal to b and c = c_A + t a: t (1 - beta^2) = w.a - beta w.b */
    const double t = (ic_dot3(w, a) - beta * ic_dot3(w, b)) / (s * s);
    ic_axpy3(c, A->c, t, a);
    return 0;
}

/* The ellipse c + r cos(theta) u + h sin(theta) v on A, traced from the
 * branch point c + r u, with both cylinders' gradients along it. */
static void section(ic_exact_ellipse *e, const ic_quadric *A, const ic_quadric *B, const double *c,
                    const double *u, const double *v, double r, double h)
{
    memset(e, 0, sizeof *e);
    memcpy(e->c, c, sizeof e->c);
    memcpy(e->u, u, sizeof e->u);
    memcpy(e->v, v, sizeof e->v);
    e->a = r, e->b = h;
    /* the reflection in the plane of the axes (m to -m: theta to pi -
     * theta) and the point reflection through c (theta to theta + pi) map each
     * cylinder to itself */
    e->branch_ends = e->symmetric = 1;
    ic_quadric_gradient_along(A, e, e->grad[0]);
    ic_quadric_gradient_along(B, e, e->grad[1]);
}

int ic_exact_equal_cylinders(const ic_quadric *A, const ic_quadric *B, double L,
                             ic_conic_found *out)
{
    const double r = A->p->radius, rb = B->p->radius;
    double c[3], m[3], minus_m[3], sum[3], diff[3];
    if (A->p->kind != IC_PRIM_CYLINDER || B->p->kind != IC_PRIM_CYLINDER ||
        fabs(r - rb) > IC_EXACT_SAME_RADIUS * fmax(r, rb) || axes_meet(A, B, L, c, m) != 0)
        return -1;
    ic_axpy3(sum, A->e[2], 1.0, B->e[2]);
    ic_axpy3(diff, B->e[2], -1.0, A->e[2]);
    const double ls = ic_normalize3(sum), ld = ic_normalize3(diff);
    ic_scale3(minus_m, m, -1.0);
    memset(out, 0, sizeof *out);
    section(&out->ellipse[0], A, B, c, m, sum, r, 2 * r / ld);
    section(&out->ellipse[1], A, B, c, minus_m, diff, r, 2 * r / ls);
    out->nellipses = 2;
    ic_axpy3(out->branch[0], c, r, m);
    ic_axpy3(out->branch[1], c, -r, m);
    out->nbranch = 2;
    return ic_exact_ellipse_fair(&out->ellipse[0], L) && ic_exact_ellipse_fair(&out->ellipse[1], L)
               ? 0
               : -1;
}
