/* What a recognised patch covers of its surface, against a circle about an
 * axis or a point found on that surface (exact_source.h): a sphere's or a
 * torus' net the whole surface; a revolved segment the band of its line
 * coordinates (a cylinder's heights, a cone's stretch of one nappe) or a
 * plane's annulus (a disc when it reaches the axis); a planar net its
 * parallelogram. The margin makes every answer safe: 1 and 0 only when the
 * circle is that far inside or outside. */
#include "exact_source.h"
#include "common/vec3.h"

#include <math.h>

/* The side of the value x of an interval [lo, hi] (an end `open` has no
 * edge: the profile reaches the axis there). */
static int interval_side(double x, double lo, double hi, int open_lo, int open_hi, double m)
{
    if ((!open_lo && x < lo - m) || (!open_hi && x > hi + m))
        return 0;
    if ((!open_lo && x < lo + m) || (!open_hi && x > hi - m))
        return -1;
    return 1;
}

/* A plane net of revolution: the annulus of radii [a, b] about the net's
 * axis (a = 0 and open when it reaches the axis), against the circle of
 * radius rho whose centre lies delta from that axis, in the plane. */
static int annulus_side(double a, double b, int open_a, double delta, double rho, double m)
{
    const double near = fabs(rho - delta), far = rho + delta; /* of the circle from the axis */
    if (far < (open_a ? -1 : a - m) || near > b + m)
        return 0;
    return far <= b - m && (open_a || near >= a + m) ? 1 : -1;
}

static int revolved_side(const ic_net_shape *sh, const double centre[3], double rho, double m)
{
    const ic_net_profile *pr = &sh->profile;
    if (pr->circle)
        return 1; /* a whole sphere or torus */
    double w[3];
    ic_axpy3(w, centre, -1.0, sh->origin);
    const double z = ic_dot3(w, sh->frame[2]);
    ic_axpy3(w, w, -z, sh->frame[2]);
    const double delta = ic_norm3(w);
    if (sh->prim.kind == IC_PRIM_PLANE) { /* x = c.x + tau d.x over [lo, hi] */
        const double x0 = pr->c[0] + pr->lo * pr->d[0], x1 = pr->c[0] + pr->hi * pr->d[0];
        const double a = fmin(x0, x1);
        return annulus_side(a, fmax(x0, x1), a <= IC_NET_REL * sh->size, delta, rho, m);
    }
    /* a cylinder or a cone about the same axis: the circle's place on the
     * line; the ends on the axis (a cone's apex) have no edge */
    const double tau = (rho - pr->c[0]) * pr->d[0] + (z - pr->c[1]) * pr->d[1];
    const double x_lo = pr->c[0] + pr->lo * pr->d[0], x_hi = pr->c[0] + pr->hi * pr->d[0];
    return interval_side(tau, pr->lo, pr->hi, fabs(x_lo) <= IC_NET_REL * sh->size,
                         fabs(x_hi) <= IC_NET_REL * sh->size, m);
}

/* The parallelogram corner + [0, 1] edge[0] + [0, 1] edge[1] against the
 * circle (centre, rho) in its plane. */
static int planar_side(const ic_net_shape *sh, const double centre[3], double rho, double m)
{
    int inside = 1, beyond = 0, within_circle = 1;
    for (int d = 0; d < 2; d++) {
        /* the edges along edge[d]: offsets along the normal to it in the plane */
        double n[3], w[3];
        ic_cross3(n, sh->frame[2], sh->edge[d]);
        ic_normalize3(n);
        const double other = ic_dot3(sh->edge[1 - d], n); /* the far edge's offset */
        const double sg = other > 0 ? 1 : -1;
        ic_axpy3(w, centre, -1.0, sh->corner);
        const double off = sg * ic_dot3(w, n), width = fabs(other);
        const double dist = fmin(off, width - off); /* to the nearer of the two edges */
        inside &= dist >= rho + m;
        beyond |= off < -(rho + m) || off > width + rho + m;
    }
    for (int k = 0; k < 4; k++) { /* every corner strictly inside the circle */
        double c[3];
        ic_axpy3(c, sh->corner, (double)(k & 1), sh->edge[0]);
        ic_axpy3(c, c, (double)(k >> 1), sh->edge[1]);
        ic_axpy3(c, c, -1.0, centre);
        within_circle &= ic_norm3(c) < rho - m;
    }
    return inside ? 1 : beyond || within_circle ? 0 : -1;
}

int ic_exact_covers(const ic_exact_source *src, const double centre[3], const double e[3],
                    double rho, double margin)
{
    (void)e; /* the circle's axis is the net's (checked by the caller) or
              * normal to the plane: its centre and radius place it */
    if (!src->net)
        return 1;
    return src->net->kind == IC_NET_PLANAR ? planar_side(src->net, centre, rho, margin)
                                           : revolved_side(src->net, centre, rho, margin);
}

int ic_exact_covers_point(const ic_exact_source *src, const double x[3], double margin)
{
    const ic_net_shape *sh = src->net;
    if (!sh)
        return 1;
    if (sh->kind == IC_NET_PLANAR)
        return planar_side(sh, x, 0, margin);
    /* the point as a circle about the net's own axis */
    double w[3], c[3];
    ic_axpy3(w, x, -1.0, sh->origin);
    ic_axpy3(c, sh->origin, ic_dot3(w, sh->frame[2]), sh->frame[2]);
    ic_axpy3(w, x, -1.0, c);
    return revolved_side(sh, c, ic_norm3(w), margin);
}
