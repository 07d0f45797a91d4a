/* What a recognised patch covers of an ellipse of the conic paths
 * (exact_ellipse_nets.h), proven from the ellipse's closed form, not
 * sampled: a cylinder's or a cone's net covers a slab of heights along its
 * axis (its profile a segment, the height affine along it), a planar net a
 * parallelogram, the strip between two pairs of parallel edges. The
 * ellipse's extent along the axis or an edge's normal is exact. */
#include "exact_ellipse_nets.h"
#include "common/vec3.h"
#include "surface/net_shape.h"

#include <math.h>

int ic_exact_conic_source_ok(const ic_exact_source *src)
{
    const ic_net_shape *sh = src->net;
    if (!sh || sh->kind == IC_NET_PLANAR)
        return 1;
    double dom[2][2];
    int periodic[2];
    ic_surface_get_domain(src->surface, dom, periodic);
    return !sh->profile.circle && periodic[sh->around] &&
           (sh->prim.kind == IC_PRIM_CYLINDER || sh->prim.kind == IC_PRIM_CONE);
}

/* The range [lo, hi] of (x - o) . k over the ellipse's points x. */
static void ellipse_range(const ic_exact_ellipse *e, const double o[3], const double k[3],
                          double *lo, double *hi)
{
    double w[3];
    ic_axpy3(w, e->c, -1.0, o);
    const double mid = ic_dot3(w, k),
                 half = hypot(e->a * ic_dot3(e->u, k), e->b * ic_dot3(e->v, k));
    *lo = mid - half, *hi = mid + half;
}

/* The ellipse's range [lo, hi] against the interval [a, b]. */
static int range_side(double lo, double hi, double a, double b, double m)
{
    if (hi < a - m || lo > b + m)
        return 0;
    return lo >= a + m && hi <= b - m ? 1 : -1;
}

/* A cylinder's or a cone's net: the heights z = c.z + tau d.z of its
 * profile's segment tau in [lo, hi] (the ellipse on a nappe, where tau is
 * affine in the height; on the other nappe its heights lie beyond the
 * apex, outside). */
static int revolved_side(const ic_net_shape *sh, const ic_exact_ellipse *e, double m)
{
    const ic_net_profile *pr = &sh->profile;
    const double z0 = pr->c[1] + pr->lo * pr->d[1], z1 = pr->c[1] + pr->hi * pr->d[1];
    double lo, hi;
    ellipse_range(e, sh->origin, sh->frame[2], &lo, &hi);
    return range_side(lo, hi, fmin(z0, z1), fmax(z0, z1), m);
}

/* A planar net: the ellipse's offsets along the normal to each pair of
 * edges within their strip (inside both: inside; beyond either: outside;
 * else undecided, as near a corner). */
static int planar_side(const ic_net_shape *sh, const ic_exact_ellipse *e, double m)
{
    int inside = 1, beyond = 0;
    for (int d = 0; d < 2; d++) {
        double n[3], lo, hi;
        ic_cross3(n, sh->frame[2], sh->edge[d]);
        ic_normalize3(n);
        const double other = ic_dot3(sh->edge[1 - d], n); /* the far edge's offset */
        if (other < 0)
            ic_scale3(n, n, -1.0);
        ellipse_range(e, sh->corner, n, &lo, &hi);
        const int side = range_side(lo, hi, 0, fabs(other), m);
        inside &= side == 1;
        beyond |= side == 0;
    }
    return beyond ? 0 : inside ? 1 : -1;
}

int ic_exact_ellipse_covered(const ic_exact_source *src, const ic_exact_ellipse *e, double margin)
{
    const ic_net_shape *sh = src->net;
    if (!sh)
        return 1;
    if (!ic_exact_conic_source_ok(src))
        return -1;
    return sh->kind == IC_NET_PLANAR ? planar_side(sh, e, margin) : revolved_side(sh, e, margin);
}
