/* Small 3-vector helpers shared by the geometry code. */
#ifndef IC_VEC3_H
#define IC_VEC3_H

#include <math.h>

static inline double ic_dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static inline void ic_cross3(double *c, const double *a, const double *b)
{
    const double x = a[1] * b[2] - a[2] * b[1];
    const double y = a[2] * b[0] - a[0] * b[2];
    const double z = a[0] * b[1] - a[1] * b[0];
    c[0] = x, c[1] = y, c[2] = z;
}

static inline double ic_norm3(const double *a) { return sqrt(ic_dot3(a, a)); }

/* det[a; b; c] = a . (b x c) */
static inline double ic_det3(const double *a, const double *b, const double *c)
{
    double bc[3];
    ic_cross3(bc, b, c);
    return ic_dot3(a, bc);
}

static inline void ic_scale3(double *c, const double *a, double s)
{
    c[0] = s * a[0], c[1] = s * a[1], c[2] = s * a[2];
}

/* c = a + s b */
static inline void ic_axpy3(double *c, const double *a, double s, const double *b)
{
    c[0] = a[0] + s * b[0], c[1] = a[1] + s * b[1], c[2] = a[2] + s * b[2];
}

static inline double ic_normalize3(double *a)
{
    const double len = ic_norm3(a);
    if (len > 0.0)
        ic_scale3(a, a, 1.0 / len);
    return len;
}

/* The distance between the points a and b. */
static inline double ic_dist3(const double *a, const double *b)
{
    return hypot(hypot(a[0] - b[0], a[1] - b[1]), a[2] - b[2]);
}

/* An orthonormal basis e1, e2 of the plane normal to the unit vector n (e1
 * from the axis x, or y when n is near x). */
static inline void ic_plane_basis3(const double *n, double *e1, double *e2)
{
    const double ax[3] = {fabs(n[0]) < 0.6 ? 1 : 0, fabs(n[0]) < 0.6 ? 0 : 1, 0};
    ic_cross3(e1, n, ax);
    ic_scale3(e1, e1, 1 / ic_norm3(e1));
    ic_cross3(e2, n, e1);
}

#endif
