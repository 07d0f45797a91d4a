/* The exact intersection curves, in closed form, with their derivatives:
 * the circle; Viviani's curve c(t) = ((1 + cos t)/2, sin t / 2, sin(t/2)),
 * t in [0, 4 pi) (on x^2 + y^2 + z^2 = 1 and (x - 1/2)^2 + y^2 = 1/4);
 * Steinmetz's two ellipses (cos t, +-cos t, sin t) (on y^2 + z^2 = 1 and
 * x^2 + z^2 = 1). Curvature and torsion at the nearest point follow from
 * the derivatives. */
#include <math.h>

#include "cases.h"

/* samples per curve before Newton polishes the nearest one */
#define NEAREST_SAMPLES 2000
#define NEAREST_NEWTON_STEPS 8
/* |c' x c''| below this times |c'|^3 (a curvature of this, relative): no
 * binormal, no torsion */
#define FRENET_FLAT 1e-12

int truth_num_curves(const bench_case *c)
{
    switch (c->truth) {
    case TRUTH_NONE:
        return 0;
    case TRUTH_CIRCLE:
    case TRUTH_VIVIANI:
        return 1;
    case TRUTH_STEINMETZ:
        return 2;
    }
    return 0;
}

double truth_period(const bench_case *c)
{
    return c->truth == TRUTH_VIVIANI ? 4 * PEERS_PI : 2 * PEERS_PI;
}

static void circle_derivs(const bench_case *c, double t, double d[4][3])
{
    const double *a = c->circle_axis;
    /* e1: any unit vector normal to the axis; e2 = a x e1 */
    double e1[3] = {a[2], 0, -a[0]};
    if (fabs(a[0]) < 0.5 && fabs(a[2]) < 0.5)
        e1[0] = 0, e1[1] = -a[2], e1[2] = a[1];
    const double n1 = sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
    for (int k = 0; k < 3; k++)
        e1[k] /= n1;
    const double e2[3] = {a[1] * e1[2] - a[2] * e1[1], a[2] * e1[0] - a[0] * e1[2],
                          a[0] * e1[1] - a[1] * e1[0]};
    const double r = c->circle_radius, co = cos(t), si = sin(t);
    /* derivatives of (cos, sin): (-sin, cos), (-cos, -sin), (sin, -cos) */
    const double dc[4] = {co, -si, -co, si}, ds[4] = {si, co, -si, -co};
    for (int m = 0; m < 4; m++)
        for (int k = 0; k < 3; k++)
            d[m][k] = (m == 0 ? c->circle_center[k] : 0) + r * (dc[m] * e1[k] + ds[m] * e2[k]);
}

static void viviani_derivs(double t, double d[4][3])
{
    const double c1 = cos(t), s1 = sin(t), ch = cos(t / 2), sh = sin(t / 2);
    const double v[4][3] = {{(1 + c1) / 2, s1 / 2, sh},
                            {-s1 / 2, c1 / 2, ch / 2},
                            {-c1 / 2, -s1 / 2, -sh / 4},
                            {s1 / 2, -c1 / 2, -ch / 8}};
    for (int m = 0; m < 4; m++)
        for (int k = 0; k < 3; k++)
            d[m][k] = v[m][k];
}

static void steinmetz_derivs(int which, double t, double d[4][3])
{
    const double sign = which ? -1.0 : 1.0;
    const double dc[4] = {cos(t), -sin(t), -cos(t), sin(t)};
    const double ds[4] = {sin(t), cos(t), -sin(t), -cos(t)};
    for (int m = 0; m < 4; m++)
        d[m][0] = dc[m], d[m][1] = sign * dc[m], d[m][2] = ds[m];
}

void truth_derivs(const bench_case *c, int k, double t, double d[4][3])
{
    if (c->truth == TRUTH_CIRCLE)
        circle_derivs(c, t, d);
    else if (c->truth == TRUTH_VIVIANI)
        viviani_derivs(t, d);
    else
        steinmetz_derivs(k, t, d);
}

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross3(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

void frenet_from_derivs(const double d1[3], const double d2[3], const double d3[3],
                        double *kappa, double *tau, int *has_tau)
{
    double b[3];
    cross3(d1, d2, b);
    const double speed = sqrt(dot3(d1, d1)), bb = dot3(b, b);
    *kappa = sqrt(bb) / (speed * speed * speed);
    *has_tau = sqrt(bb) > FRENET_FLAT * speed * speed * speed;
    *tau = *has_tau ? dot3(b, d3) / bb : 0.0;
}

static double distance_at(const bench_case *c, int k, double t, const double p[3])
{
    double d[4][3];
    truth_derivs(c, k, t, d);
    const double q[3] = {d[0][0] - p[0], d[0][1] - p[1], d[0][2] - p[2]};
    return sqrt(dot3(q, q));
}

/* Newton on g(t) = (c(t) - p) . c'(t), from a sample. */
static double polish(const bench_case *c, int k, double t, const double p[3])
{
    for (int it = 0; it < NEAREST_NEWTON_STEPS; it++) {
        double d[4][3];
        truth_derivs(c, k, t, d);
        const double q[3] = {d[0][0] - p[0], d[0][1] - p[1], d[0][2] - p[2]};
        const double g = dot3(q, d[1]), dg = dot3(d[1], d[1]) + dot3(q, d[2]);
        if (dg <= 0)
            break;
        t -= g / dg;
    }
    return t;
}

/* A local minimum of the sampled distance at sample i (cyclic). */
static int local_minimum(const double *dist, int i)
{
    const int prev = (i + NEAREST_SAMPLES - 1) % NEAREST_SAMPLES, next = (i + 1) % NEAREST_SAMPLES;
    return dist[i] <= dist[prev] && dist[i] <= dist[next];
}

int truth_nearest(const bench_case *c, const double p[3], double *dist,
                  double kappa[TRUTH_MAX_TIES], double tau[TRUTH_MAX_TIES])
{
    const int n = truth_num_curves(c);
    if (n == 0)
        return 0;
    /* every local minimum polished: near a crossing the best sample may sit on
     * the other branch */
    double found_t[2 * TRUTH_MAX_TIES], found_d[2 * TRUTH_MAX_TIES], sampled[NEAREST_SAMPLES];
    int found_k[2 * TRUTH_MAX_TIES], nfound = 0;
    const double period = truth_period(c);
    for (int k = 0; k < n; k++) {
        for (int i = 0; i < NEAREST_SAMPLES; i++)
            sampled[i] = distance_at(c, k, period * i / NEAREST_SAMPLES, p);
        for (int i = 0; i < NEAREST_SAMPLES; i++) {
            if (!local_minimum(sampled, i))
                continue;
            const double t = polish(c, k, period * i / NEAREST_SAMPLES, p);
            const double d = fmin(distance_at(c, k, t, p), sampled[i]);
            const double t_best = d < sampled[i] ? t : period * i / NEAREST_SAMPLES;
            /* keep the 2 * TRUTH_MAX_TIES nearest */
            int slot = nfound < 2 * TRUTH_MAX_TIES ? nfound++ : -1;
            if (slot < 0)
                for (int j = 0; j < nfound; j++)
                    if (found_d[j] > d && (slot < 0 || found_d[j] > found_d[slot]))
                        slot = j;
            if (slot >= 0)
                found_t[slot] = t_best, found_d[slot] = d, found_k[slot] = k;
        }
    }
    double best = INFINITY;
    for (int j = 0; j < nfound; j++)
        best = fmin(best, found_d[j]);
    int ties = 0;
    for (int j = 0; j < nfound && ties < TRUTH_MAX_TIES; j++) {
        if (found_d[j] > best + TRUTH_TIE)
            continue;
        double d[4][3];
        int has_tau;
        truth_derivs(c, found_k[j], found_t[j], d);
        frenet_from_derivs(d[1], d[2], d[3], kappa + ties, tau + ties, &has_tau);
        ties++;
    }
    *dist = best;
    return ties;
}
