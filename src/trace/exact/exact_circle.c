/* A circle of an exact path as traced points (exact_circle.h): equal arcs
 * with the exact apparatus, the crossings of the patches' knot lines put in
 * (a parameter curve is only C^1, or C^0, across a knot line: the B-spline
 * fit keeps a node on every one, as the general path's points give it),
 * and the parameters of every point on the recognised patches. */
#include "exact_circle.h"
#include "exact_profile.h"
#include "common/mathconst.h"
#include "common/vec3.h"
#include "local/pair_access.h"
#include "surface/surface_access.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* radians: a knot line crossed this near a point of the equal arcs (or
 * another crossing) is crossed there: one point carries both */
#define EXACT_SAME_ANGLE 1e-12

/* The point at angle phi (cosine cs, sine sn): its exact apparatus, t
 * about e (counterclockwise), n towards the axis, b = e, kappa = 1 / rho,
 * tau = 0. */
static void circle_point(ic_trace_point *p, double phi, const ic_exact_circle *c, double cs,
                         double sn)
{
    memset(p, 0, sizeof *p);
    p->s = c->rho * phi;
    for (int i = 0; i < 3; i++) {
        const double radial = cs * c->u[i] + sn * c->v[i];
        p->xyz[i] = c->centre[i] + c->rho * radial;
        p->t[i] = -sn * c->u[i] + cs * c->v[i];
        p->n[i] = -radial;
        p->b[i] = c->e[i];
    }
    p->kappa = 1.0 / c->rho;
    p->tau = 0.0;
    p->angle = c->angle;
    p->frame_defined = 1;
}

/* The n points of the equal arcs, n a multiple of 8: the cosine and sine of
 * one octant serve all eight (exact reflections). */
static void equal_arcs(ic_trace_point *pts, int n, const ic_exact_circle *c)
{
    const int q = n / 4;
    for (int j = 0; j <= n / 8; j++) {
        const double cs = cos(2 * IC_PI * j / n), sn = sin(2 * IC_PI * j / n);
        const int k[8] = {j, q - j, q + j, 2 * q - j, 2 * q + j, 3 * q - j, 3 * q + j, (n - j) % n};
        const double cc[8] = {cs, sn, -sn, -cs, -cs, -sn, sn, cs};
        const double ss[8] = {sn, cs, cs, sn, -sn, -cs, -cs, -sn};
        for (int m = 0; m < 8; m++)
            circle_point(&pts[k[m]], 2 * IC_PI * k[m] / n, c, cc[m], ss[m]);
    }
}

/* How each sheet's patch follows the circle: way[s] the sense its angle
 * turns in, theta0[s] its angle at the start, v[s] its profile parameter
 * (a revolved patch); the first revolved patch's seam is the start. 0, or
 * 1 where a revolved patch is not about the circle's axis. */
typedef struct {
    int way[2];
    double theta0[2], profile[2];
    int seam_sheet;
} sheet_setup;

static int setup_sheets(ic_exact_circle *c, const ic_exact_source src[2], double L, sheet_setup *ss)
{
    memset(ss, 0, sizeof *ss);
    ss->seam_sheet = -1;
    for (int s = 0; s < 2; s++) {
        const ic_net_shape *sh = src[s].net;
        if (!sh || sh->kind != IC_NET_REVOLVED)
            continue;
        if (!ic_exact_net_coaxial(&src[s], c->centre, c->e, L))
            return 1;
        ss->way[s] = ic_dot3(sh->frame[2], c->e) > 0 ? 1 : -1;
        if (ss->seam_sheet < 0) { /* start on its seam */
            ss->seam_sheet = s;
            ic_axpy3(c->u, sh->frame[0], -ic_dot3(sh->frame[0], c->e), c->e);
            ic_normalize3(c->u);
            ic_cross3(c->v, c->e, c->u);
        }
        double x0[3], w[3];
        ic_axpy3(x0, c->centre, c->rho, c->u);
        ss->theta0[s] =
            s == ss->seam_sheet ? (ss->way[s] > 0 ? 0 : 2 * IC_PI) : ic_net_angle_of(sh, x0);
        ic_axpy3(w, c->centre, -1.0, sh->origin);
        if (ic_net_profile_param(sh, c->rho, ic_dot3(w, sh->frame[2]), &ss->profile[s]) != 0)
            return 1;
    }
    return 0;
}

static int by_angle(const void *a, const void *b)
{
    const double x = ((const ic_exact_knot *)a)->phi, y = ((const ic_exact_knot *)b)->phi;
    return (x > y) - (x < y);
}

/* The equal arcs and the crossings merged by angle into pts (room for
 * n + nk + 1, and n more where nk > 0), phi[] each point's angle, mark[]
 * its first crossing or -1; the first point again at the end. Returns the
 * count. */
static int merge(const ic_exact_circle *c, int n, const ic_exact_knot *k, int nk,
                 ic_trace_point *pts, double *phi, int *mark)
{
    /* the equal arcs in place, or after the room when crossings come in */
    ic_trace_point *arcs = nk ? pts + nk + 1 : pts;
    equal_arcs(arcs, n, c);
    int m = 0, j = 0;
    for (int i = 0; i <= n; i++) {
        const double at = 2 * IC_PI * i / n;
        for (; j < nk && k[j].phi < at - EXACT_SAME_ANGLE; j++) { /* a crossing between */
            if (m > 0 && mark[m - 1] >= 0 && k[j].phi - phi[m - 1] <= EXACT_SAME_ANGLE)
                continue; /* the same place as the last one */
            circle_point(&pts[m], k[j].phi, c, cos(k[j].phi), sin(k[j].phi));
            phi[m] = k[j].phi, mark[m++] = j;
        }
        if (i == n)
            break;
        if (&arcs[i] != &pts[m]) /* arcs[i] lies after pts + m */
            memcpy(&pts[m], &arcs[i], sizeof pts[m]);
        phi[m] = at, mark[m] = -1;
        for (; j < nk && k[j].phi <= at + EXACT_SAME_ANGLE; j++)
            if (mark[m] < 0)
                mark[m] = j;
        m++;
    }
    pts[m] = pts[0];
    pts[m].s = 2 * IC_PI * c->rho;
    phi[m] = 2 * IC_PI, mark[m] = mark[0];
    return m + 1;
}

/* Sheet s's turning parameter at the circle's angle phi: its patch's
 * angle there inverted; beyond one turn by whole periods (wrapping
 * patches only). 0, or -1. */
static int around_param(const ic_exact_source *src, const sheet_setup *ss, int s, double phi,
                        double *t)
{
    const ic_net_shape *sh = src->net;
    double dom[2][2];
    int periodic[2];
    ic_surface_get_domain(src->surface, dom, periodic);
    const double theta = ss->theta0[s] + ss->way[s] * phi, turn = 2 * IC_PI;
    if (s == ss->seam_sheet) /* within [0, 2 pi] by construction */
        return ic_net_around_param(sh, theta, t);
    const double k = floor(theta / turn);
    if (k != 0 && !periodic[sh->around])
        return -1;
    if (ic_net_around_param(sh, theta - k * turn, t) != 0)
        return -1;
    *t += k * (dom[sh->around][1] - dom[sh->around][0]);
    return 0;
}

/* Every point's parameters on the recognised patches, each checked
 * against its patch: 0, or 1. */
static int fill_params(ic_trace_point *pts, const double *phi, const int *mark, int np,
                       const ic_exact_knot *k, int nk, const ic_exact_source src[2],
                       const sheet_setup *ss, double L)
{
    for (int s = 0; s < 2; s++) {
        const ic_net_shape *sh = src[s].net;
        for (int i = 0; sh && i < np; i++) {
            double *uv = pts[i].params[s], S[3], d[3];
            if (sh->kind == IC_NET_PLANAR) {
                if (ic_net_params(sh, pts[i].xyz, uv) != 0)
                    return 1;
            } else {
                uv[1 - sh->around] = ss->profile[s];
                if (around_param(&src[s], ss, s, phi[i], &uv[sh->around]) != 0)
                    return 1;
            }
            for (int j = mark[i]; j >= 0 && j < nk && k[j].phi - k[mark[i]].phi <= EXACT_SAME_ANGLE;
                 j++)
                if (k[j].sheet == s) {
                    ic_exact_knot_snap(&src[s], &k[j], &uv[k[j].dir]);
                    pts[i].knot_line |= 1 << s;
                    pts[i].knot_side = 1;
                }
            ic_surface_nurbs_point(src[s].surface, uv, S);
            ic_axpy3(d, S, -1.0, pts[i].xyz);
            if (!(ic_norm3(d) <= IC_EXACT_ON_NET * L))
                return 1;
        }
    }
    return 0;
}

int ic_exact_circle_points(ic_exact_circle *c, int n, const ic_exact_source src[2], double L,
                           ic_trace_point **pts, int *npts)
{
    *pts = NULL;
    sheet_setup ss;
    if (setup_sheets(c, src, L, &ss) != 0)
        return 1;
    ic_exact_knot *k = NULL;
    int nk = 0;
    const int st = ic_exact_circle_knots(c, src, ss.theta0, ss.way, &k, &nk, L);
    if (st != 0)
        return st;
    for (int i = 0; i < nk; i++) /* a crossing at the end of the turn is at its start */
        if (k[i].phi > 2 * IC_PI - EXACT_SAME_ANGLE)
            k[i].phi = 0;
    if (nk > 1) /* (none: no array at all) */
        qsort(k, (size_t)nk, sizeof *k, by_angle);
    const size_t room = (size_t)(n + nk + 1);
    ic_trace_point *p = malloc(sizeof *p * (room + (nk ? (size_t)n : 0)));
    double *phi = malloc(sizeof *phi * room);
    int *mark = malloc(sizeof *mark * room);
    int out = !p || !phi || !mark ? -1 : 0;
    if (out == 0) {
        *npts = merge(c, n, k, nk, p, phi, mark);
        out = fill_params(p, phi, mark, *npts, k, nk, src, &ss, L);
    }
    free(k);
    free(phi);
    free(mark);
    if (out != 0) {
        free(p);
        return out;
    }
    *pts = p;
    return 0;
}

/* Sheet s's normal at the point: a parametric sheet's R_u x R_v at its
 * parameters, an implicit one's gradient (the pair's spaces of order 2: no
 * allocation). 0, or -1 where it cannot be evaluated. */
static int sheet_normal(ic_pair *pair, int s, const ic_trace_point *p, double n[3])
{
    ic_surface *S = ic_pair_surface(pair, s);
    const int parametric = ic_surface_get_kind(S) == IC_PARAMETRIC;
    const ic_jet_space *sp = ic_pair_near_space(pair, parametric ? 2 : 3);
    const int len = ic_jet_space_len(sp);
    double t[3 * 10];
    if (3 * len > 30 ||
        ic_surface_taylor(S, t, parametric ? p->params[s] : p->xyz, sp, NULL) != IC_OK)
        return -1;
    if (!parametric) {
        for (int k = 0; k < 3; k++)
            n[k] = t[ic_jet_index(sp, (const int[]){k == 0, k == 1, k == 2})];
        return 0;
    }
    const int iu = ic_jet_index(sp, (const int[]){1, 0}),
              iv = ic_jet_index(sp, (const int[]){0, 1});
    const double Ru[3] = {t[iu], t[len + iu], t[2 * len + iu]};
    const double Rv[3] = {t[iv], t[len + iv], t[2 * len + iv]};
    ic_cross3(n, Ru, Rv);
    return 0;
}

void ic_exact_orient_at(ic_pair *pair, ic_trace_point *pts, int n, int at)
{
    double a[3], b[3], t[3];
    if (n < 2 || sheet_normal(pair, 0, &pts[at], a) != 0 || sheet_normal(pair, 1, &pts[at], b) != 0)
        return;
    ic_cross3(t, a, b);
    if (ic_dot3(t, pts[at].t) < 0)
        ic_trace_points_reverse(pts, n);
}

void ic_exact_circle_orient(ic_pair *pair, ic_trace_point *pts, int n)
{
    ic_exact_orient_at(pair, pts, n, 0);
}
