/* Revolved nets (net_shape.h; docs/nurbs.md, "Recognised nets"). With
 * weights w_ij = a_i b_j and control points P_ij = O + x_j Q_i + z_j e3, Q_i
 * in the plane of e1, e2 (i along the turning parameter, j along the
 * other), the patch is
 *
 *     S = O + X C + Z e3,  C = sum N_i a_i Q_i / sum N_i a_i,
 *     (X, Z) = sum M_j b_j (x_j, z_j) / sum M_j b_j
 *
 * (the double sums factor): the profile (X, Z) swept about the axis along
 * C. When C is the unit circle going round once from e1 (its identity on
 * every span, net_curve.c; its angle strictly increasing to 2 pi,
 * net_pieces.c) and X >= 0 (so are all x_j: X is their convex
 * combination), S is the whole surface of revolution of the profile. Here:
 * the structure, found from the widest row's circle and verified on every
 * control point and weight; the profile is classified in net_profile.c. */
#include "net_shape.h"
#include "common/mathconst.h"
#include "common/vec3.h"

#include <math.h>
#include <string.h>

/* sine: three points of the widest row closer than this to a line do not
 * fix a circle (the row is no circle) */
#define NET_MIN_TRIANGLE 1e-6
/* radians: the circle's total turn within this of 2 pi is one turn (a
 * closed curve turns by a multiple of 2 pi; rounding moves it by 1e-15) */
#define NET_TURN_SLACK 0.5

/* The net seen along the turning parameter i and the profile's j. */
typedef struct {
    const ic_nurbs_patch *pt;
    int around, ni, nj;
} net_view;

static const double *hom_at(const net_view *v, int i, int j)
{
    const int at = v->around == 0 ? i * v->pt->n[1] + j : j * v->pt->n[1] + i;
    return v->pt->hom + 4 * at;
}

static void point_at(const net_view *v, int i, int j, double P[3])
{
    const double *h = hom_at(v, i, j);
    for (int k = 0; k < 3; k++)
        P[k] = h[k] / h[3];
}

/* w_ij = a_i b_j within IC_NET_REL: a_i = w_i0 and b_j = w_0j / w_00 into
 * the curves' weights. */
static int separable(const net_view *v, ic_net_shape *sh)
{
    const double w00 = hom_at(v, 0, 0)[3];
    for (int i = 0; i < v->ni; i++)
        sh->curve[0].hom[i][2] = hom_at(v, i, 0)[3];
    for (int j = 0; j < v->nj; j++)
        sh->curve[1].hom[j][2] = hom_at(v, 0, j)[3] / w00;
    for (int i = 0; i < v->ni; i++)
        for (int j = 0; j < v->nj; j++) {
            const double w = hom_at(v, i, j)[3];
            if (!(fabs(w - sh->curve[0].hom[i][2] * sh->curve[1].hom[j][2]) <= IC_NET_REL * w))
                return 0;
        }
    return 1;
}

/* The row j with the widest spread of control points. */
static int widest_row(const net_view *v)
{
    int best = 0;
    double spread = -1;
    for (int j = 0; j < v->nj; j++) {
        double P0[3], P[3], d[3], m = 0;
        point_at(v, 0, j, P0);
        for (int i = 1; i < v->ni; i++) {
            point_at(v, i, j, P);
            ic_axpy3(d, P, -1.0, P0);
            m = fmax(m, ic_norm3(d));
        }
        if (m > spread)
            spread = m, best = j;
    }
    return best;
}

/* Row j's curve (weights a_i b_j, a common factor b_j) at t. */
static void row_point(const net_view *v, int j, double t, double out[3])
{
    const ic_nurbs_patch *pt = v->pt;
    const int p = pt->p[v->around];
    const double *kn = pt->knots[v->around];
    const int s = ic_knot_span(kn, p, v->ni, t, IC_NURBS_RIGHT);
    double b[1][IC_NURBS_MAX_DEGREE + 1], h[4] = {0, 0, 0, 0};
    ic_basis_taylor(b, kn, s, p, t, 0);
    for (int i = 0; i <= p; i++)
        for (int k = 0; k < 4; k++)
            h[k] += b[0][i] * hom_at(v, s - p + i, j)[k];
    for (int k = 0; k < 3; k++)
        out[k] = h[k] / h[3];
}

/* The circle through three points of row j at a third and two thirds of
 * the domain: the origin at its centre, e3 its normal (the points turning
 * counterclockwise about it), e1 towards the row's start. */
static int axis_from_row(const net_view *v, int j, ic_net_shape *sh, double *radius)
{
    const double *dom = v->pt->domain[v->around];
    double p[3][3], a[3], b[3], axb[3], w[3], num[3], c[3];
    for (int k = 0; k < 3; k++)
        row_point(v, j, dom[0] + (dom[1] - dom[0]) * k / 3.0, p[k]);
    ic_axpy3(a, p[0], -1.0, p[2]);
    ic_axpy3(b, p[1], -1.0, p[2]);
    ic_cross3(axb, a, b);
    const double n2 = ic_dot3(axb, axb);
    if (!(sqrt(n2) > NET_MIN_TRIANGLE * ic_norm3(a) * ic_norm3(b)))
        return 0;
    /* circumcentre: p2 + ((|a|^2 b - |b|^2 a) x (a x b)) / (2 |a x b|^2) */
    ic_scale3(w, b, ic_dot3(a, a));
    ic_axpy3(w, w, -ic_dot3(b, b), a);
    ic_cross3(num, w, axb);
    ic_axpy3(c, p[2], 0.5 / n2, num);
    memcpy(sh->origin, c, sizeof c);
    double *e1 = sh->frame[0], *e2 = sh->frame[1], *e3 = sh->frame[2];
    ic_axpy3(a, p[1], -1.0, p[0]);
    ic_axpy3(b, p[2], -1.0, p[0]);
    ic_cross3(e3, a, b);
    ic_normalize3(e3);
    ic_axpy3(e1, p[0], -1.0, c);
    *radius = ic_normalize3(e1);
    ic_axpy3(e1, e1, -ic_dot3(e1, e3), e3); /* exactly normal to e3 */
    ic_normalize3(e1);
    ic_cross3(e2, e3, e1);
    return *radius > IC_NET_REL * sh->size;
}

/* P_ij = O + x_j Q_i + z_j e3 within IC_NET_REL D: Q_i from row jw (of
 * radius rw), x_j and z_j by least squares, every point checked; the
 * circle's points a_i Q_i and the profile's b_j (x_j, z_j) into the
 * curves. */
static int structure(const net_view *v, int jw, double rw, ic_net_shape *sh)
{
    const double tol = IC_NET_REL * sh->size;
    double qq = 0;
    for (int i = 0; i < v->ni; i++) {
        double P[3], L[3];
        point_at(v, i, jw, P);
        ic_axpy3(L, P, -1.0, sh->origin);
        if (!(fabs(ic_dot3(L, sh->frame[2])) <= tol))
            return 0;
        const double q[2] = {ic_dot3(L, sh->frame[0]) / rw, ic_dot3(L, sh->frame[1]) / rw};
        const double a = sh->curve[0].hom[i][2];
        sh->curve[0].hom[i][0] = a * q[0], sh->curve[0].hom[i][1] = a * q[1];
        qq += q[0] * q[0] + q[1] * q[1];
    }
    for (int j = 0; j < v->nj; j++) {
        double x = 0, z = 0, P[3], L[3];
        for (int i = 0; i < v->ni; i++) {
            point_at(v, i, j, P);
            ic_axpy3(L, P, -1.0, sh->origin);
            const double *h = sh->curve[0].hom[i];
            x += (ic_dot3(L, sh->frame[0]) * h[0] + ic_dot3(L, sh->frame[1]) * h[1]) / h[2];
            z += ic_dot3(L, sh->frame[2]);
        }
        x /= qq, z /= v->ni;
        if (!(x >= -tol))
            return 0; /* the profile crosses the axis */
        for (int i = 0; i < v->ni; i++) {
            const double *h = sh->curve[0].hom[i];
            double model[3];
            point_at(v, i, j, P);
            ic_axpy3(model, sh->origin, z, sh->frame[2]);
            ic_axpy3(model, model, x * h[0] / h[2], sh->frame[0]);
            ic_axpy3(model, model, x * h[1] / h[2], sh->frame[1]);
            ic_axpy3(L, P, -1.0, model);
            if (!(ic_norm3(L) <= tol))
                return 0;
        }
        const double b = sh->curve[1].hom[j][2];
        sh->curve[1].hom[j][0] = b * x, sh->curve[1].hom[j][1] = b * z;
    }
    return 1;
}

/* C is the unit circle (to IC_NET_REL D at the widest x), closed, its
 * angle strictly increasing from the seam once round. */
static int one_turn(ic_net_shape *sh, double xmax, int *nomem)
{
    const ic_net_curve *c = &sh->curve[0];
    const double origin[2] = {0, 0};
    if (!(ic_net_curve_circle_gap(c, origin, 1.0) * xmax <= IC_NET_REL * sh->size))
        return 0;
    double first[2], last[2];
    ic_net_curve_point(c, c->knots[c->p], first);
    ic_net_curve_point(c, c->knots[c->n], last);
    if (!(hypot(last[0] - first[0], last[1] - first[1]) * xmax <= IC_NET_REL * sh->size))
        return 0;
    const int st = ic_net_pieces_make(&sh->pieces[0], c, IC_NET_ANGLE, origin, NULL);
    *nomem = st < 0;
    if (st != 0)
        return 0;
    const ic_net_pieces *pc = &sh->pieces[0];
    return pc->sign > 0 && fabs(pc->pos[pc->n] - pc->pos[0] - 2 * IC_PI) < NET_TURN_SLACK;
}

int ic_net_recognize_revolved(const ic_nurbs_patch *pt, int around, ic_net_shape *sh)
{
    const net_view v = {pt, around, pt->n[around], pt->n[1 - around]};
    sh->around = around;
    if (ic_net_curve_alloc(&sh->curve[0], pt->p[around], v.ni, pt->knots[around]) != 0 ||
        ic_net_curve_alloc(&sh->curve[1], pt->p[1 - around], v.nj, pt->knots[1 - around]) != 0)
        return -1;
    double rw;
    const int jw = widest_row(&v);
    if (!separable(&v, sh) || !axis_from_row(&v, jw, sh, &rw) || !structure(&v, jw, rw, sh))
        return 1;
    double xmax = 0;
    for (int j = 0; j < v.nj; j++)
        xmax = fmax(xmax, sh->curve[1].hom[j][0] / sh->curve[1].hom[j][2]);
    int nomem = 0;
    if (!one_turn(sh, xmax, &nomem))
        return nomem ? -1 : 1;
    return ic_net_classify_profile(sh);
}
