/*
 * An ellipse of an exact path as a traced curve (exact_ellipse.h), where
 * exact_ellipse_plan.c puts its points: each with its exact apparatus.
 * p(theta) = c + a cos(theta) u + b sin(theta) v; the speed |p'| =
 * sqrt(a^2 sin^2 + b^2 cos^2), t = p' / |p'|, n = -(b cos u + a sin v) /
 * |p'| (towards the centre), b = u x v, kappa = a b / |p'|^3, tau = 0.
 */
#include "exact_ellipse.h"
#include "exact_common.h"
#include "common/mathconst.h"
#include "common/vec3.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void ic_exact_ellipse_extent(const ic_exact_ellipse *e, double extent[3])
{
    for (int k = 0; k < 3; k++)
        extent[k] = hypot(e->a * e->u[k], e->b * e->v[k]);
}

/* The arc length at point k of n from the quarter's table (q = n/4). */
static double arc_at(const double *S, int q, int k)
{
    if (k <= q)
        return S[k];
    if (k <= 2 * q)
        return 2 * S[q] - S[2 * q - k];
    if (k <= 3 * q)
        return 2 * S[q] + S[k - 2 * q];
    return 4 * S[q] - S[4 * q - k];
}

/* The angle between two normals, either way round: in [0, pi/2]. atan of
 * the quotient rather than atan2: half the time, within an ulp. */
static double normal_angle(const double *g, const double *h)
{
    double x[3];
    ic_cross3(x, g, h);
    const double sine = ic_norm3(x), cosine = fabs(ic_dot3(g, h));
    return sine == 0 ? 0.0 : cosine == 0 ? 0.5 * IC_PI : atan(sine / cosine);
}

/* The point at the angle of cosine cs and sine sn, its apparatus (not s;
 * the angle between the normals only when `angle` is set). The point was
 * zeroed (calloc: no parameters, no knot line): a memset of each point
 * here took a third of the time. */
void ic_exact_ellipse_point(ic_trace_point *p, const ic_exact_ellipse *e, const double *binormal,
                            double cs, double sn, int angle)
{
    const double ac = e->a * cs, bs = e->b * sn, as = e->a * sn, bc = e->b * cs;
    const double speed = sqrt(as * as + bc * bc), inv = 1 / speed;
    double g[2][3];
    for (int i = 0; i < 3; i++) {
        p->xyz[i] = e->c[i] + ac * e->u[i] + bs * e->v[i];
        p->t[i] = (bc * e->v[i] - as * e->u[i]) * inv;
        p->n[i] = -(bc * e->u[i] + as * e->v[i]) * inv;
        p->b[i] = binormal[i];
        for (int s = 0; s < 2; s++)
            g[s][i] = e->grad[s][0][i] + cs * e->grad[s][1][i] + sn * e->grad[s][2][i];
    }
    p->kappa = e->a * e->b * inv * inv * inv;
    p->tau = 0.0;
    if (angle)
        p->angle = normal_angle(g[0], g[1]);
    p->frame_defined = 1;
}

/* The n + 1 points (the last the first again) at phi_j = 2 pi j / n: the
 * cosines and sines of phi in the first octant reflected to all eight (as
 * the circles of exact_revolution.c), mapped to theta, each point's
 * apparatus; their arc length from the quarter's. */
static void ellipse_points(ic_trace_point *pts, const ic_exact_ellipse *e,
                           const ic_ellipse_plan *plan, const double (*phi)[2], const double *S)
{
    double binormal[3];
    ic_cross3(binormal, e->u, e->v);
    const int n = plan->n, q = n / 4;
    for (int j = 0; j <= n / 8; j++) {
        const double cs = phi[j][0], sn = phi[j][1];
        const int k[8] = {j, q - j, q + j, 2 * q - j, 2 * q + j, 3 * q - j, 3 * q + j, (n - j) % n};
        const double cc[8] = {cs, sn, -sn, -cs, -cs, -sn, sn, cs};
        const double ss[8] = {sn, cs, cs, sn, -sn, -cs, -cs, -sn};
        for (int m = 0; m < 8; m++) {
            /* symmetric: the angle at phi_j (m = 0) serves pi - phi_j, pi +
             * phi_j and 2 pi - phi_j (m = 3, 4, 7: theta is reflected with
             * phi), the one at pi/2 - phi_j (m = 1) the others */
            const int own = !e->symmetric || m < 2;
            double ct, st;
            ic_ellipse_theta(plan, cc[m], ss[m], &ct, &st);
            ic_exact_ellipse_point(&pts[k[m]], e, binormal, ct, st, own);
            if (!own)
                pts[k[m]].angle = pts[k[m == 3 || m == 4 || m == 7 ? 0 : 1]].angle;
            pts[k[m]].s = arc_at(S, q, k[m]);
        }
    }
    if (e->branch_ends) /* the normals are parallel there: exactly, not to rounding */
        pts[0].angle = pts[2 * q].angle = 0.0;
    pts[n] = pts[0];
    pts[n].s = 4 * S[q];
}

int ic_exact_ellipse_points(const ic_exact_ellipse *e, const ic_ellipse_plan *plan,
                            ic_trace_point **out)
{
    const int n = plan->n, q = n / 4;
    ic_trace_point *pts = calloc((size_t)n + 1, sizeof *pts);
    /* scratch: the quarter's cosines and sines of phi, its arc lengths */
    double(*phi)[2] = malloc((size_t)(q + 1) * sizeof *phi);
    double *S = malloc((size_t)(q + 1) * sizeof *S);
    if (!pts || !phi || !S) {
        free(pts), free(phi), free(S);
        return -1;
    }
    for (int j = 0; j <= n / 8; j++) { /* the second octant by reflection */
        phi[j][0] = phi[q - j][1] = cos(2 * IC_PI * j / n);
        phi[j][1] = phi[q - j][0] = sin(2 * IC_PI * j / n);
    }
    ic_exact_quarter_lengths(e, plan, (const double(*)[2])phi, S);
    ellipse_points(pts, e, plan, (const double(*)[2])phi, S);
    free(phi), free(S);
    *out = pts;
    return 0;
}

ic_status ic_exact_add_ellipse_points(ic_trace_result *r, const ic_exact_ellipse *e,
                                      ic_trace_point *pts, int np, const ic_trace_options *opt,
                                      ic_error *err)
{
    /* the shape test's verdict (shape.c), read from the semi-axes: tau is 0
     * exactly, so planar, or a circle where kappa, between b / a^2 and a /
     * b^2 at the ends of the axes (points of every ellipse: n is a multiple
     * of 4), varies by at most shape_tol of its largest value */
    const double lo = fmin(e->a, e->b), hi = fmax(e->a, e->b);
    const double kmax = hi / (lo * lo), kmin = lo / (hi * hi);
    const ic_shape shape = kmax - kmin <= opt->shape_tol * kmax ? IC_SHAPE_CIRCLE : IC_SHAPE_PLANAR;
    return ic_trace_add_shaped_curve(r, pts, np, 1, IC_TRACE_CLOSED, IC_TRACE_CLOSED,
                                     opt->shape_tol, shape, -1, -1, err);
}

ic_status ic_exact_add_ellipse(ic_trace_result *r, const ic_exact_ellipse *e,
                               const ic_ellipse_plan *plan, const ic_trace_options *opt,
                               ic_error *err)
{
    ic_trace_point *pts;
    if (ic_exact_ellipse_points(e, plan, &pts) != 0)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory adding a curve");
    return ic_exact_add_ellipse_points(r, e, pts, plan->n + 1, opt, err);
}
