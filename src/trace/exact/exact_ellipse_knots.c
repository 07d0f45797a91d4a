/* Where an ellipse of the conic paths crosses the knot lines of the
 * recognised patches (exact_ellipse_nets.h). Every such line lies in a
 * plane whose offset along the ellipse is affine in (cos, sin) of its
 * angle, K0 + K1 cos + K2 sin = 0, solved in closed form: a revolved net's
 * meridians (the half planes through its axis at its knots' angles and at
 * its seam: the ellipse winds once about the axis and crosses each once),
 * its parallels (planes normal to the axis at its profile's knots'
 * heights), a planar net's lines of constant f(u) or g(v). */
#include "exact_ellipse_nets.h"
#include "exact_profile.h"
#include "common/mathconst.h"
#include "common/vec3.h"
#include "surface/net_shape.h"

#include <math.h>
#include <stdlib.h>

/* The angles where the plane through o normal to the unit m meets the
 * ellipse: their count (0 or 2) in theta[], or -1 where it nearly touches
 * (|K0| within IC_EXACT_NEAR L of sqrt(K1^2 + K2^2)). */
static int plane_meets(const ic_exact_ellipse *e, const double o[3], const double m[3], double L,
                       double theta[2])
{
    double w[3];
    ic_axpy3(w, e->c, -1.0, o);
    const double k0 = ic_dot3(w, m), k1 = e->a * ic_dot3(e->u, m), k2 = e->b * ic_dot3(e->v, m);
    const double R = hypot(k1, k2);
    if (fabs(fabs(k0) - R) <= IC_EXACT_NEAR * L)
        return -1;
    if (fabs(k0) > R)
        return 0;
    const double beta = atan2(k2, k1), delta = acos(-k0 / R);
    theta[0] = beta - delta, theta[1] = beta + delta;
    return 2;
}

/* The ellipse's point at theta, less o, along r. */
static double along(const ic_exact_ellipse *e, double theta, const double o[3], const double r[3])
{
    double x[3];
    ic_axpy3(x, e->c, e->a * cos(theta), e->u);
    ic_axpy3(x, x, e->b * sin(theta), e->v);
    ic_axpy3(x, x, -1.0, o);
    return ic_dot3(x, r);
}

/* The meridian at angle alpha about the revolved net's axis: the one of
 * the plane's two crossings on its side of the axis. 0, 1, -1. */
static int meridian(const ic_exact_ellipse *e, const ic_net_shape *sh, double alpha, int sheet,
                    int seam, double value, double L, ic_exact_marks *k)
{
    double m[3], r[3], theta[2];
    for (int i = 0; i < 3; i++) {
        m[i] = -sin(alpha) * sh->frame[0][i] + cos(alpha) * sh->frame[1][i];
        r[i] = cos(alpha) * sh->frame[0][i] + sin(alpha) * sh->frame[1][i];
    }
    if (plane_meets(e, sh->origin, m, L, theta) != 2)
        return 1; /* it winds about the axis: two crossings */
    const int first = along(e, theta[0], sh->origin, r) > 0;
    if (first == (along(e, theta[1], sh->origin, r) > 0))
        return 1;
    return ic_exact_mark_add(k, theta[first ? 0 : 1], sheet, sh->around, seam, value);
}

/* The parallel at the height of the profile's knot (tau its position). */
static int parallel(const ic_exact_ellipse *e, const ic_net_shape *sh, double tau, int sheet,
                    double value, double L, ic_exact_marks *k)
{
    double o[3], theta[2];
    ic_axpy3(o, sh->origin, sh->profile.c[1] + tau * sh->profile.d[1], sh->frame[2]);
    const int n = plane_meets(e, o, sh->frame[2], L, theta);
    if (n < 0)
        return 1;
    for (int i = 0; i < n; i++)
        if (ic_exact_mark_add(k, theta[i], sheet, 1 - sh->around, 0, value) != 0)
            return -1;
    return 0;
}

static int revolved_knots(const ic_exact_ellipse *e, const ic_net_shape *sh, int sheet, double L,
                          ic_exact_marks *k)
{
    const ic_net_pieces *pc = &sh->pieces[0], *pr = &sh->pieces[1];
    int st = meridian(e, sh, 0.0, sheet, 1, pc->t[0], L, k); /* the seam */
    for (int i = 1; st == 0 && i < pc->n; i++)
        if (pc->span[i] != pc->span[i - 1])
            st = meridian(e, sh, pc->pos[i], sheet, 0, pc->t[i], L, k);
    for (int i = 1; st == 0 && i < pr->n; i++)
        if (pr->span[i] != pr->span[i - 1])
            st = parallel(e, sh, pr->pos[i], sheet, pr->t[i], L, k);
    return st;
}

/* A planar net: the lines f(u) = f(kappa) (g(v) = g(kappa)) of its
 * distinct interior knots. */
static int planar_knots(const ic_exact_ellipse *e, const ic_net_shape *sh, int sheet, double L,
                        ic_exact_marks *k)
{
    for (int d = 0; d < 2; d++) {
        const ic_net_curve *cv = &sh->curve[d];
        const double *kn = cv->knots, f0 = sh->pieces[d].pos[0];
        double m[3];
        ic_cross3(m, sh->frame[2], sh->E[1 - d]);
        ic_normalize3(m);
        for (int i = cv->p + 1; i < cv->n; i++) {
            if (!(kn[i] > kn[cv->p] && kn[i] < kn[cv->n]) || kn[i] == kn[i - 1])
                continue;
            double f[2], o[3], theta[2];
            ic_net_curve_point(cv, kn[i], f);
            ic_axpy3(o, sh->corner, f[0] - f0, sh->E[d]);
            const int n = plane_meets(e, o, m, L, theta);
            if (n < 0)
                return 1;
            for (int j = 0; j < n; j++)
                if (ic_exact_mark_add(k, theta[j], sheet, d, 0, kn[i]) != 0)
                    return -1;
        }
    }
    return 0;
}

int ic_exact_ellipse_knots(const ic_exact_ellipse *e, const ic_exact_source src[2], double L,
                           ic_exact_knot **out, int *n)
{
    ic_exact_marks k = {NULL, 0, 0};
    int st = 0;
    for (int s = 0; s < 2 && st == 0; s++) {
        const ic_net_shape *sh = src[s].net;
        if (sh)
            st = sh->kind == IC_NET_PLANAR ? planar_knots(e, sh, s, L, &k)
                                           : revolved_knots(e, sh, s, L, &k);
    }
    if (st != 0) {
        free(k.m);
        return st;
    }
    *out = k.m;
    *n = k.n;
    return 0;
}
