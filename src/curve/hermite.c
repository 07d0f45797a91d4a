/* Piecewise quintic Hermite curves as one B-spline, clamped or periodic
 * (hermite.h, docs/bspline.md). */
#include "curve/hermite.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { DEGREE = 5 };

/* Quintic Bezier of one segment matching x, x', x'' at both ends (with
 * respect to s over h = s1 - s0): b1 = x0 + h x0'/5, b2 = x0 + 2h x0'/5 +
 * h^2 x0''/20, and symmetrically at the far end. */
static void hermite_bezier(double *b, const ic_hermite_node *a, const ic_hermite_node *z, int dim)
{
    const double h = z->s - a->s;
    for (int j = 0; j < dim; j++) {
        b[0 * dim + j] = a->x[j];
        b[1 * dim + j] = a->x[j] + h * a->d1[j] / 5;
        b[2 * dim + j] = a->x[j] + 2 * h * a->d1[j] / 5 + h * h * a->d2[j] / 20;
        b[3 * dim + j] = z->x[j] - 2 * h * z->d1b[j] / 5 + h * h * z->d2b[j] / 20;
        b[4 * dim + j] = z->x[j] - h * z->d1b[j] / 5;
        b[5 * dim + j] = z->x[j];
    }
}

/* The quintic of Bezier net b over [s0, s0 + h] at s: its derivatives
 * 0..3 (ic_hermite_eval). */
static void bezier_eval(const double *b, double s0, double h, int dim, double s, double out[4][3])
{
    const double u = (s - s0) / h, v = 1 - u;
    /* Bernstein polynomials of degree 5, 4 and 3 at u */
    const double B5[6] = {v * v * v * v * v, 5 * u * v * v * v * v, 10 * u * u * v * v * v,
                          10 * u * u * u * v * v, 5 * u * u * u * u * v, u * u * u * u * u};
    const double B4[5] = {v * v * v * v, 4 * u * v * v * v, 6 * u * u * v * v, 4 * u * u * u * v,
                          u * u * u * u};
    const double B3[4] = {v * v * v, 3 * u * v * v, 3 * u * u * v, u * u * u};
    const double B2[3] = {v * v, 2 * u * v, u * u};
    for (int j = 0; j < dim; j++) {
        double x = 0, d1 = 0, d2 = 0, d3 = 0;
        for (int i = 0; i < 6; i++)
            x += B5[i] * b[i * dim + j];
        for (int i = 0; i < 5; i++)
            d1 += B4[i] * (b[(i + 1) * dim + j] - b[i * dim + j]);
        for (int i = 0; i < 4; i++)
            d2 += B3[i] * (b[(i + 2) * dim + j] - 2 * b[(i + 1) * dim + j] + b[i * dim + j]);
        for (int i = 0; i < 3; i++)
            d3 += B2[i] * (b[(i + 3) * dim + j] - 3 * b[(i + 2) * dim + j] +
                           3 * b[(i + 1) * dim + j] - b[i * dim + j]);
        out[0][j] = x;
        out[1][j] = 5 * d1 / h;
        out[2][j] = 20 * d2 / (h * h);
        out[3][j] = 60 * d3 / (h * h * h);
    }
}

void ic_hermite_eval(const ic_hermite_node *a, const ic_hermite_node *z, int dim, double s,
                     double out[4][3])
{
    double b[6 * 3];
    hermite_bezier(b, a, z, dim);
    bezier_eval(b, a->s, z->s - a->s, dim, s, out);
}

/* The torsion of a space curve from its first three derivatives: (c' x
 * c'') . c''' / |c' x c''|^2; NAN where c' x c'' vanishes. */
static double torsion(const double d[4][3])
{
    const double *a = d[1], *b = d[2];
    const double cr[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                          a[0] * b[1] - a[1] * b[0]};
    const double cc = cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2];
    return cc > 0 ? (cr[0] * d[3][0] + cr[1] * d[3][1] + cr[2] * d[3][2]) / cc : NAN;
}

/* Whether the quintic from nodes[a] to nodes[z] passes the nodes between
 * them (hermite.h, ic_hermite_merge). */
static int bridges(const ic_hermite_node *nodes, int a, int z, int dim, double pos_tol,
                   double deriv_tol, double tau_tol, double curvature_floor)
{
    double b[6 * 3]; /* the quintic's net, made once for every node it passes */
    hermite_bezier(b, &nodes[a], &nodes[z], dim);
    for (int k = a + 1; k < z; k++) {
        double h[4][3], e0 = 0, e1 = 0, e2 = 0, size2 = 0;
        bezier_eval(b, nodes[a].s, nodes[z].s - nodes[a].s, dim, nodes[k].s, h);
        for (int j = 0; j < dim; j++) {
            e0 = fmax(e0, fabs(h[0][j] - nodes[k].x[j]));
            e1 = fmax(e1, fabs(h[1][j] - nodes[k].d1[j]));
            e2 = fmax(e2, fabs(h[2][j] - nodes[k].d2[j]));
            size2 += nodes[k].d2[j] * nodes[k].d2[j];
        }
        const double scale = fmax(sqrt(size2), curvature_floor);
        if (!(e0 <= pos_tol && e1 <= deriv_tol && e2 <= deriv_tol * scale))
            return 0;
        if (dim == 3 && isfinite(nodes[k].tau) &&
            !(fabs(torsion(h) - nodes[k].tau) <= tau_tol * scale))
            return 0;
    }
    return 1;
}

int ic_hermite_merge(const ic_hermite_node *nodes, const int *pinned, int n, int dim,
                     double pos_tol, double deriv_tol, double tau_tol, int *keep)
{
    if (n < 1)
        return 0;
    const double floor = 1 / fmax(nodes[n - 1].s - nodes[0].s, 1e-300);
    int m = 0;
    keep[m++] = 0;
    for (int a = 0; a < n - 1;) {
        int z = a + 1;
        while (z + 1 < n && z - a < IC_HERMITE_MAX_MERGE && !pinned[z] &&
               bridges(nodes, a, z + 1, dim, pos_tol, deriv_tol, tau_tol, floor))
            z++;
        keep[m++] = z;
        a = z;
    }
    return m;
}

/* Whether the curve is C^2 at a node: the stretches on both sides share
 * its derivatives (not so on a knot line where they jump). */
static int smooth_at(const ic_hermite_node *h, int dim)
{
    for (int j = 0; j < dim; j++)
        if (h->d1[j] != h->d1b[j] || h->d2[j] != h->d2b[j])
            return 0;
    return 1;
}

int ic_hermite_closes(const ic_hermite_node *nodes, int n, int dim)
{
    if (n < 2)
        return 0;
    const ic_hermite_node *a = &nodes[0], *z = &nodes[n - 1];
    for (int j = 0; j < dim; j++)
        if (a->x[j] != z->x[j] || a->d1[j] != z->d1b[j] || a->d2[j] != z->d2b[j])
            return 0;
    return 1;
}

static void put(ic_bspline *c, int *nc, const double *x)
{
    memcpy(c->control + (size_t)c->dim * (*nc)++, x, sizeof(double) * (size_t)c->dim);
}

static void put_knot(ic_bspline *c, int *nk, double s, int times)
{
    for (int r = 0; r < times; r++)
        c->knots[(*nk)++] = s;
}

/* The de Boor point that replaces b4, b5 = b0' and b1' where two quintic
 * pieces over h0 and h1 meet C^2 (knot multiplicity 3): d = b4 + (h1/h0)
 * (b4 - b3) = b1' + (h0/h1)(b1' - b2') (the two agree when the pieces meet
 * with equal x, x', x''; Farin 2002, the C^2 condition for Bezier pieces). */
static void de_boor_joint(double *d, const double *b3, const double *b4, double h0, double h1,
                          int dim)
{
    for (int j = 0; j < dim; j++)
        d[j] = b4[j] + (h1 / h0) * (b4[j] - b3[j]);
}

/* The clamped B-spline: where the curve is C^2 (every node but those on
 * knot lines) its knot has multiplicity 3 and one de Boor point stands for
 * the joint; elsewhere the Bezier nets are laid end to end (multiplicity
 * 5). c->knots and c->control have room for every joint a Bezier one. */
static void clamped(ic_bspline *c, const ic_hermite_node *nodes, int n, double *b)
{
    const int dim = c->dim, segments = n - 1;
    int nc = 0, nk = 0;
    double *prev = b, *next = b + 6 * dim;
    hermite_bezier(prev, &nodes[0], &nodes[1], dim);
    put_knot(c, &nk, nodes[0].s, DEGREE + 1);
    for (int r = 0; r < 4; r++)
        put(c, &nc, prev + r * dim);
    for (int i = 1; i < segments; i++) {
        hermite_bezier(next, &nodes[i], &nodes[i + 1], dim);
        if (smooth_at(&nodes[i], dim)) {
            double d[3];
            de_boor_joint(d, prev + 3 * dim, prev + 4 * dim, nodes[i].s - nodes[i - 1].s,
                          nodes[i + 1].s - nodes[i].s, dim);
            put(c, &nc, d);
            put_knot(c, &nk, nodes[i].s, 3);
        } else {
            put(c, &nc, prev + 4 * dim);
            put(c, &nc, prev + 5 * dim);
            put(c, &nc, next + 1 * dim);
            put_knot(c, &nk, nodes[i].s, DEGREE);
        }
        put(c, &nc, next + 2 * dim);
        put(c, &nc, next + 3 * dim);
        double *t = prev;
        prev = next, next = t;
    }
    put(c, &nc, prev + 4 * dim);
    put(c, &nc, prev + 5 * dim);
    put_knot(c, &nk, nodes[n - 1].s, DEGREE + 1);
    c->ncontrol = nc;
}

/* The clamped curve of a smoothly closed one made periodic. Its control
 * points are C[0] = b0, C[1] = b1 of the first stretch, the inner ones,
 * then C[nc-2] = b4, C[nc-1] = b5 of the last; the start becomes a C^2
 * joint like the others: b4, b5 = b0 and b1 give way to one de Boor point
 * d0. The m = nc - 3 distinct points are b3 of the last stretch, d0, and
 * the inner ones up to b2 of the last stretch; the first 5 are repeated at
 * the end. The knots are the joints' (s0 three times, then the inner ones)
 * continued by the period L on both sides: u_k = q[(k - 3) mod m] + L
 * floor((k - 3) / m), so the parameter runs from u_5 = s0 to u_{m+5} =
 * s0 + L (Piegl and Tiller 1997, sec. 12.2, the unclamped closed form).
 * work: room for nc + 5 points. */
static void make_periodic(ic_bspline *c, const ic_hermite_node *nodes, int n, double *work)
{
    const int dim = c->dim, nc = c->ncontrol, m = nc - 3;
    const size_t pt = sizeof(double) * (size_t)dim;
    const double *C = c->control;
    double *P = work;
    memcpy(P, C + (size_t)(nc - 3) * dim, pt);
    de_boor_joint(P + dim, C + (size_t)(nc - 3) * dim, C + (size_t)(nc - 2) * dim,
                  nodes[n - 1].s - nodes[n - 2].s, nodes[1].s - nodes[0].s, dim);
    memcpy(P + 2 * dim, C + 2 * dim, pt * (size_t)(nc - 5));
    for (int k = 0; k < DEGREE; k++)
        memcpy(P + (size_t)(m + k) * dim, P + (size_t)(k % m) * dim, pt);
    memcpy(c->control, P, pt * (size_t)(m + DEGREE));
    /* q: s0 three times, then the clamped knots strictly inside */
    const double L = nodes[n - 1].s - nodes[0].s;
    double *q = work; /* m values: the points are copied out already */
    q[0] = q[1] = q[2] = nodes[0].s;
    memcpy(q + 3, c->knots + DEGREE + 1, sizeof(double) * (size_t)(m - 3));
    for (int k = 0; k < m + 2 * DEGREE + 1; k++) {
        const int i = k - 3, wrap = i >= 0 ? i / m : -((-i + m - 1) / m);
        c->knots[k] = q[i - wrap * m] + wrap * L;
    }
    c->ncontrol = m + DEGREE;
    c->periodic = 1;
}

ic_status ic_hermite_bspline(ic_bspline *c, const ic_hermite_node *nodes, int n, int dim,
                             int periodic, ic_error *err)
{
    memset(c, 0, sizeof *c);
    c->dim = dim;
    c->degree = DEGREE;
    const size_t most = (size_t)DEGREE * (n - 1) + 1 + DEGREE; /* every joint a Bezier one */
    c->knots = malloc(sizeof(double) * (most + DEGREE + 1));
    c->control = malloc(sizeof(double) * most * (size_t)dim);
    double *work = malloc(sizeof(double) * (most * (size_t)dim + 12 * (size_t)dim));
    if (!c->knots || !c->control || !work) {
        free(work);
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory fitting a curve");
    }
    clamped(c, nodes, n, work);
    if (periodic)
        make_periodic(c, nodes, n, work);
    free(work);
    return IC_OK;
}
