/* A plane rational curve cut into pieces where its position (an angle about
 * a centre, or a coordinate along a line) is strictly monotone, and its
 * inversion (net_curve.h).
 *
 * Both readings are those of a plane polynomial F of the span: reading the
 * angle about c, F = (X - c_x W, Y - c_y W), whose angle is that of C - c
 * (W > 0); reading along a line, F = (W, (X - c W) . d), whose slope F_y /
 * F_x is the coordinate. Either way the position moves as cross(F, F')
 * (d angle / dt = cross(F, F') / |F|^2, d slope / dt = cross(F, F') / W^2),
 * a polynomial of degree 2p - 1 whose Bernstein coefficients, all of one
 * strict sign, prove it monotone. Reading angles, a piece whose Bezier
 * points all lie strictly on the side of a line through c where its middle
 * point is stays in that open half plane (convex hull, positive weights):
 * it turns by less than pi, exactly the signed angle between its ends. A
 * piece that fails either test is halved, up to NET_MAX_SPLITS times. */
#include "net_curve.h"
#include "nurbs.h"
#include "nurbs_bernstein.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { MAXP = IC_NURBS_MAX_DEGREE + 1 };

/* halvings of a span: a piece 1/64 of a span that still fails is taken as
 * turning back (a curve that stands still somewhere never passes) */
#define NET_MAX_SPLITS 6
/* relative to the largest coordinate of a piece's net: the rounding of the
 * blossom (16 eps a level, nurbs_interval.c) over p + 1 levels */
#define NET_ROUNDING_PER_LEVEL (16 * DBL_EPSILON)
/* iterations of the safeguarded Newton method: bisection alone reaches
 * the rounding of t in 60 */
#define NET_INVERT_ITERATIONS 100

static double cross2(const double *a, const double *b) { return a[0] * b[1] - a[1] * b[0]; }

/* F of the homogeneous point h (net_curve.h's reading). */
static void reading_of(const ic_net_pieces *pc, const double h[3], double F[2])
{
    const double x = h[0] - pc->c[0] * h[2], y = h[1] - pc->c[1] * h[2];
    if (pc->reading == IC_NET_ANGLE)
        F[0] = x, F[1] = y;
    else
        F[0] = h[2], F[1] = x * pc->d[0] + y * pc->d[1];
}

/* The position of F: its angle (in (-pi, pi]) or its slope. */
static double position_of(const ic_net_pieces *pc, const double F[2])
{
    return pc->reading == IC_NET_ANGLE ? atan2(F[1], F[0]) : F[1] / F[0];
}

/* The Bezier net of the curve over [a, b] on span s and that of F, and
 * F's rounding bound. */
static double piece_net(const ic_net_pieces *pc, const ic_net_curve *c, int s, double a, double b,
                        double net[MAXP][3], double F[MAXP][2])
{
    double big = 0;
    ic_nurbs_blossom(&net[0][0], 3, &c->hom[s - c->p][0], 3, 3, c->p, c->knots, s, a, b);
    for (int k = 0; k <= c->p; k++) {
        reading_of(pc, net[k], F[k]);
        big = fmax(big, fmax(fabs(F[k][0]), fabs(F[k][1])));
    }
    return NET_ROUNDING_PER_LEVEL * (c->p + 2) * big * (1 + fabs(pc->c[0]) + fabs(pc->c[1]));
}

/* The sign (+1, -1) of cross(F, F') on the piece when its Bernstein
 * coefficients prove it, else 0. */
static int turning_sign(const double F[MAXP][2], int p, double err)
{
    ic_bpoly f[2], g[2], a, b, cr;
    for (int e = 0; e < 2; e++) {
        f[e].du = p, f[e].dv = 0, f[e].err = err;
        g[e].du = p - 1, g[e].dv = 0, g[e].err = 2 * err;
        for (int k = 0; k <= p; k++)
            f[e].c[k] = F[k][e];
        for (int k = 0; k < p; k++) /* the hodograph, less its positive factor p / (b - a) */
            g[e].c[k] = F[k + 1][e] - F[k][e];
    }
    ic_bpoly_mul(&a, &f[0], &g[1]);
    ic_bpoly_mul(&b, &f[1], &g[0]);
    ic_bpoly_sub(&cr, &a, &b);
    int pos = 1, neg = 1;
    for (int k = 0; k <= cr.du; k++)
        pos &= cr.c[k] > cr.err, neg &= cr.c[k] < -cr.err;
    return pos ? 1 : neg ? -1 : 0;
}

/* Reading angles: every Bezier point strictly on the side of the middle
 * point (de Casteljau at 1/2) of a line through the centre. */
static int in_half_plane(const double F[MAXP][2], int p, double err)
{
    double m[MAXP][2];
    memcpy(m, F, sizeof m);
    for (int j = 1; j <= p; j++)
        for (int k = 0; k + j <= p; k++)
            for (int e = 0; e < 2; e++)
                m[k][e] = 0.5 * (m[k][e] + m[k + 1][e]);
    const double len = hypot(m[0][0], m[0][1]);
    if (!(len > 0))
        return 0;
    for (int k = 0; k <= p; k++)
        if (!((F[k][0] * m[0][0] + F[k][1] * m[0][1]) / len > 2 * err))
            return 0;
    return 1;
}

typedef struct {
    int cap;
    int sign; /* 0 until the first piece */
} growth;

/* Room for cap pieces: 0, or -1 out of memory. */
static int grow(ic_net_pieces *pc, int cap)
{
    double *t = realloc(pc->t, sizeof *t * (size_t)(cap + 1));
    if (t)
        pc->t = t;
    double *pos = realloc(pc->pos, sizeof *pos * (size_t)(cap + 1));
    if (pos)
        pc->pos = pos;
    int *span = realloc(pc->span, sizeof *span * (size_t)cap);
    if (span)
        pc->span = span;
    double *net = realloc(pc->net, sizeof *net * 3 * (size_t)(pc->p + 1) * (size_t)cap);
    if (net)
        pc->net = net;
    return t && pos && span && net ? 0 : -1;
}

static int append(ic_net_pieces *pc, growth *g, int s, const double net[MAXP][3], double b,
                  double pos_b, int sign)
{
    if (g->sign != 0 && sign != g->sign)
        return 1; /* the position turns back */
    g->sign = sign;
    if (pc->n + 1 > g->cap) {
        if (grow(pc, 2 * g->cap + 8) != 0)
            return -1;
        g->cap = 2 * g->cap + 8;
    }
    memcpy(pc->net + 3 * (size_t)(pc->p + 1) * (size_t)pc->n, net,
           sizeof(double) * 3 * (size_t)(pc->p + 1));
    pc->span[pc->n] = s;
    pc->t[pc->n + 1] = b;
    pc->pos[pc->n + 1] = pos_b;
    pc->n++;
    return 0;
}

/* The piece [a, b] of span s, halved until it passes: 0, 1 (not
 * provable), -1 (out of memory). */
static int cut(ic_net_pieces *pc, growth *g, const ic_net_curve *c, int s, double a, double b,
               int depth)
{
    double F[MAXP][2], net[MAXP][3];
    const double err = piece_net(pc, c, s, a, b, net, F);
    const int sign = turning_sign(F, c->p, err);
    if (sign != 0 && (pc->reading == IC_NET_ALONG || in_half_plane(F, c->p, err))) {
        /* the end's position: the turn from the start (less than pi), or
         * the slope */
        const double *Fa = F[0], *Fb = F[c->p];
        const double pos_b =
            pc->reading == IC_NET_ANGLE
                ? pc->pos[pc->n] + atan2(cross2(Fa, Fb), Fa[0] * Fb[0] + Fa[1] * Fb[1])
                : position_of(pc, Fb);
        return append(pc, g, s, net, b, pos_b, sign);
    }
    if (depth >= NET_MAX_SPLITS)
        return 1;
    const double mid = 0.5 * (a + b);
    const int st = cut(pc, g, c, s, a, mid, depth + 1);
    return st != 0 ? st : cut(pc, g, c, s, mid, b, depth + 1);
}

int ic_net_pieces_make(ic_net_pieces *pc, const ic_net_curve *c, ic_net_reading reading,
                       const double c0[2], const double d[2])
{
    memset(pc, 0, sizeof *pc);
    pc->reading = reading;
    pc->p = c->p;
    pc->c[0] = c0[0], pc->c[1] = c0[1];
    if (d)
        pc->d[0] = d[0], pc->d[1] = d[1];
    growth g = {8, 0};
    if (grow(pc, g.cap) != 0) {
        ic_net_pieces_free(pc);
        return -1;
    }
    const double t0 = c->knots[c->p];
    double F0[2], h0[3] = {0, 0, 0}, P[2];
    ic_net_curve_point(c, t0, P);
    for (int e = 0; e < 2; e++) /* the start as a homogeneous point of weight 1 */
        h0[e] = P[e];
    h0[2] = 1;
    reading_of(pc, h0, F0);
    pc->t[0] = t0;
    pc->pos[0] = position_of(pc, F0);
    int st = 0;
    for (int s = c->p; st == 0 && s < c->n; s++)
        if (c->knots[s] < c->knots[s + 1])
            st = cut(pc, &g, c, s, c->knots[s], c->knots[s + 1], 0);
    pc->sign = g.sign;
    if (st != 0 || pc->n == 0) {
        ic_net_pieces_free(pc);
        return st < 0 ? -1 : 1;
    }
    return 0;
}

void ic_net_pieces_free(ic_net_pieces *pc)
{
    free(pc->t);
    free(pc->pos);
    free(pc->span);
    free(pc->net);
    pc->t = pc->pos = pc->net = NULL;
    pc->span = NULL;
    pc->n = 0;
}

/* The Bernstein polynomial of coefficients g[0..p] at x, and its
 * derivative, by de Casteljau's scheme. */
static double bernstein_at(const double *g, int p, double x, double *dg)
{
    double b[MAXP];
    memcpy(b, g, sizeof(double) * (size_t)(p + 1));
    for (int j = 1; j < p; j++)
        for (int i = 0; i + j <= p; i++)
            b[i] += x * (b[i + 1] - b[i]);
    *dg = p * (b[1] - b[0]);
    return b[0] + x * (b[1] - b[0]);
}

/* The piece holding pos (positions ordered by sign), or -1. */
static int piece_of(const ic_net_pieces *pc, double pos)
{
    const double lo = pc->sign > 0 ? pc->pos[0] : pc->pos[pc->n];
    const double hi = pc->sign > 0 ? pc->pos[pc->n] : pc->pos[0];
    if (!(pos >= lo && pos <= hi))
        return -1;
    int a = 0, b = pc->n - 1; /* the first piece whose end is at or beyond pos */
    while (a < b) {
        const int m = (a + b) / 2;
        if (pc->sign * (pc->pos[m + 1] - pos) >= 0)
            b = m;
        else
            a = m + 1;
    }
    return a;
}

int ic_net_pieces_invert(const ic_net_pieces *pc, const ic_net_curve *c, double pos, double *t)
{
    (void)c; /* the pieces keep their nets */
    const int k = piece_of(pc, pos), p = pc->p;
    if (k < 0)
        return -1;
    /* g = cross(d, F): the sine of the angle from the target direction d
     * times |F|, or the coordinate less pos times W; a polynomial of degree
     * p on the piece (its Bernstein coefficients those of the net's
     * points), of one sign on either side of its one root there, growing
     * through it when the position does (sign) */
    const double d[2] = {pc->reading == IC_NET_ANGLE ? cos(pos) : 1.0,
                         pc->reading == IC_NET_ANGLE ? sin(pos) : pos};
    double g[MAXP];
    for (int i = 0; i <= p; i++) {
        double F[2];
        reading_of(pc, pc->net + 3 * ((size_t)(p + 1) * (size_t)k + (size_t)i), F);
        g[i] = pc->sign * cross2(d, F);
    }
    double lo = 0, hi = 1, x = g[0] < g[p] ? g[0] / (g[0] - g[p]) : 0;
    for (int it = 0; it < NET_INVERT_ITERATIONS; it++) {
        double dg;
        const double v = bernstein_at(g, p, x, &dg);
        if (v == 0)
            break;
        if (v > 0)
            hi = x;
        else
            lo = x;
        double next = dg > 0 ? x - v / dg : 0.5 * (lo + hi);
        if (!(next > lo && next < hi))
            next = 0.5 * (lo + hi);
        const double step = fabs(next - x);
        x = next;
        if (step <= 4 * DBL_EPSILON || hi - lo <= 4 * DBL_EPSILON)
            break;
    }
    *t = pc->t[k] + x * (pc->t[k + 1] - pc->t[k]);
    return 0;
}
