/* Recognising a NURBS patch (net_shape.h): a revolved net turning along u,
 * then along v, then a planar affine net; and the parameters of a point of
 * the recognised surface by inverting the structure: its angle about the
 * axis along the circle, its place on the profile or the parallelogram's
 * edges along those curves (net_pieces.c). */
#include "net_shape.h"
#include "common/mathconst.h"
#include "common/vec3.h"

#include <math.h>
#include <stdlib.h>

/* The diagonal of the box of the control points. */
static double net_size(const ic_nurbs_patch *pt)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int i = 0; i < pt->n[0] * pt->n[1]; i++)
        for (int k = 0; k < 3; k++) {
            const double x = pt->hom[4 * i + k] / pt->hom[4 * i + 3];
            lo[k] = fmin(lo[k], x), hi[k] = fmax(hi[k], x);
        }
    return sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

int ic_net_recognize(const ic_nurbs_patch *pt, ic_net_shape **out)
{
    *out = NULL;
    const double size = net_size(pt);
    if (!(size > 0) || !isfinite(size))
        return 0;
    for (int attempt = 0; attempt < 3; attempt++) {
        ic_net_shape *sh = calloc(1, sizeof *sh);
        if (!sh)
            return -1;
        sh->size = size;
        const int st = attempt < 2 ? ic_net_recognize_revolved(pt, attempt, sh)
                                   : ic_net_recognize_planar(pt, sh);
        if (st == 0) {
            sh->kind = attempt < 2 ? IC_NET_REVOLVED : IC_NET_PLANAR;
            *out = sh;
            return 0;
        }
        ic_net_shape_free(sh);
        if (st < 0)
            return -1;
    }
    return 0;
}

void ic_net_shape_free(ic_net_shape *sh)
{
    if (!sh)
        return;
    for (int d = 0; d < 2; d++) {
        ic_net_curve_free(&sh->curve[d]);
        ic_net_pieces_free(&sh->pieces[d]);
    }
    free(sh);
}

double ic_net_angle_of(const ic_net_shape *sh, const double xyz[3])
{
    double w[3];
    ic_axpy3(w, xyz, -1.0, sh->origin);
    const double a = atan2(ic_dot3(w, sh->frame[1]), ic_dot3(w, sh->frame[0]));
    return a < 0 ? a + 2 * IC_PI : a;
}

/* pos moved onto the pieces' range when it lies within slack of it; the
 * range's ends give the curve's ends exactly. 0, or -1 beyond. */
static int invert_clamped(const ic_net_pieces *pc, const ic_net_curve *c, double pos, double slack,
                          double *t)
{
    const int up = pc->sign > 0;
    const double lo = up ? pc->pos[0] : pc->pos[pc->n], hi = up ? pc->pos[pc->n] : pc->pos[0];
    if (!(pos >= lo - slack && pos <= hi + slack))
        return -1;
    if (pos <= lo) {
        *t = up ? pc->t[0] : pc->t[pc->n];
        return 0;
    }
    if (pos >= hi) {
        *t = up ? pc->t[pc->n] : pc->t[0];
        return 0;
    }
    return ic_net_pieces_invert(pc, c, pos, t);
}

/* radians: an angle this far beyond the circle's range [0, 2 pi] (its ends
 * computed to rounding) is still on it */
#define NET_ANGLE_SLACK 1e-12

int ic_net_around_param(const ic_net_shape *sh, double angle, double *t)
{
    return invert_clamped(&sh->pieces[0], &sh->curve[0], angle, NET_ANGLE_SLACK, t);
}

int ic_net_profile_param(const ic_net_shape *sh, double x, double z, double *t)
{
    const ic_net_profile *pr = &sh->profile;
    const ic_net_pieces *pc = &sh->pieces[1];
    const double tol = IC_NET_REL * sh->size;
    if (!pr->circle)
        return invert_clamped(pc, &sh->curve[1],
                              (x - pr->c[0]) * pr->d[0] + (z - pr->c[1]) * pr->d[1], tol, t);
    /* the least representative of the point's angle about the centre from
     * the arc's range on (on a closed circle's seam, the range's lower end) */
    const double lo = fmin(pc->pos[0], pc->pos[pc->n]), slack = tol / pr->r;
    double a = atan2(z - pr->c[1], x - pr->c[0]);
    a += 2 * IC_PI * ceil((lo - slack - a) / (2 * IC_PI));
    return invert_clamped(pc, &sh->curve[1], a, slack, t);
}

/* (s, t) with w = s E1 + t E2 (E1, E2 unit, not parallel). */
static void oblique(const ic_net_shape *sh, const double w[3], double st[2])
{
    const double c = ic_dot3(sh->E[0], sh->E[1]), r1 = ic_dot3(w, sh->E[0]);
    const double r2 = ic_dot3(w, sh->E[1]), det = 1 - c * c;
    st[0] = (r1 - c * r2) / det, st[1] = (r2 - c * r1) / det;
}

int ic_net_params(const ic_net_shape *sh, const double xyz[3], double uv[2])
{
    double w[3];
    const double tol = IC_NET_REL * sh->size;
    if (sh->kind == IC_NET_PLANAR) {
        double st[2];
        ic_axpy3(w, xyz, -1.0, sh->corner);
        oblique(sh, w, st);
        for (int d = 0; d < 2; d++) {
            const double f0 = sh->pieces[d].pos[0];
            if (invert_clamped(&sh->pieces[d], &sh->curve[d], f0 + st[d], tol, &uv[d]) != 0)
                return -1;
        }
        return 0;
    }
    ic_axpy3(w, xyz, -1.0, sh->origin);
    const double z = ic_dot3(w, sh->frame[2]);
    ic_axpy3(w, w, -z, sh->frame[2]);
    const double x = ic_norm3(w);
    if (!(x > tol))
        return -1; /* on the axis: no angle */
    return ic_net_around_param(sh, ic_net_angle_of(sh, xyz), &uv[sh->around]) == 0 &&
                   ic_net_profile_param(sh, x, z, &uv[1 - sh->around]) == 0
               ? 0
               : -1;
}
