/* Distances from the exact surfaces, in closed form. */
#include <math.h>

#include "cases.h"

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

double exact_distance(const exact_surface *s, const double p[3])
{
    double q[3];
    for (int k = 0; k < 3; k++)
        q[k] = p[k] - s->center[k];
    const double h = dot3(q, s->axis); /* height along the axis */
    double off[3];                     /* the part of q normal to the axis */
    for (int k = 0; k < 3; k++)
        off[k] = q[k] - h * s->axis[k];
    const double rho = sqrt(dot3(off, off));
    switch (s->kind) {
    case EXACT_PLANE:
        return fabs(h);
    case EXACT_SPHERE:
        return fabs(sqrt(dot3(q, q)) - s->radius);
    case EXACT_CYLINDER:
        return fabs(rho - s->radius);
    case EXACT_TORUS:
        return fabs(hypot(rho - s->major, h) - s->radius);
    }
    return NAN;
}
