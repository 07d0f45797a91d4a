/* Sound enclosures of a NURBS patch and its first derivatives over a
 * parameter box. On each span the box covers, the Bezier net of the piece
 * restricted to the box comes straight from the blossom (Ramshaw 1989: the
 * net of a degree-p polynomial over [a, b] is f(a^(p-k), b^k), k = 0..p);
 * the patch lies in its convex hull, and a rational one in the hull of the
 * projected net points (positive weights). Derivatives use the hodograph
 * nets made at creation and the quotient rule x_u = (X_u - x W_u) / W. */
#include "nurbs.h"
#include "nurbs_bernstein.h"

#include <float.h>
#include <math.h>

/* the larger and smaller of two finite numbers (fmax and fmin are calls) */
static inline double max2(double a, double b) { return a > b ? a : b; }
static inline double min2(double a, double b) { return a < b ? a : b; }

enum { MAXP = IC_NURBS_MAX_DEGREE + 1, DIM = 4 };

/* relative to the largest |coordinate| of a span's net: rounding of one
 * blossom level is at most 3 eps (the products and the sum of a convex
 * combination) plus 6 eps (alpha's own rounding times the spread, at most
 * 2 max|P|), and a hodograph point's difference quotient adds 3 eps; the
 * bound below is 16 eps per level, over the p + q levels plus one */
#define NET_ROUNDING_PER_LEVEL (16 * DBL_EPSILON)

/* One tensor net: degrees (p, q), spans (su, sv) of knots (ku, kv), source
 * net with rows of nv points; the piece over [ua, ub] x [va, vb] into hull. */
typedef struct {
    const double *net;
    int nv, p, q;
    const double *ku, *kv;
} tensor_net;

/* The Bezier net (p+1) x (q+1) of the piece on spans (su, sv) over the box,
 * and the bound on its rounding error (absolute, every coordinate). */
static double sub_net(const tensor_net *tn, int su, int sv, const double box[2][2],
                      double net[MAXP * MAXP * DIM])
{
    const int p = tn->p, q = tn->q;
    double tmp[MAXP * MAXP * DIM];
    for (int j = 0; j <= q; j++) /* along u, column by column */
        ic_nurbs_blossom(tmp + j * DIM, (q + 1) * DIM,
                         tn->net + DIM * ((su - p) * tn->nv + sv - q + j), tn->nv * DIM, DIM, p,
                         tn->ku, su, box[0][0], box[0][1]);
    for (int i = 0; i <= p; i++) /* then along v, row by row */
        ic_nurbs_blossom(net + i * (q + 1) * DIM, DIM, tmp + i * (q + 1) * DIM, DIM, DIM, q, tn->kv,
                         sv, box[1][0], box[1][1]);
    double big = 0;
    for (int i = 0; i <= p; i++)
        for (int j = 0; j <= q; j++)
            for (int e = 0; e < DIM; e++)
                big = max2(big, fabs(tn->net[DIM * ((su - p + i) * tn->nv + sv - q + j) + e]));
    return NET_ROUNDING_PER_LEVEL * (p + q + 1) * big;
}

static ic_interval hull_with(ic_interval h, ic_interval x)
{
    return (ic_interval){min2(h.lo, x.lo), max2(h.hi, x.hi)};
}

static ic_interval widened(double x, double err) { return (ic_interval){x - err, x + err}; }

/* A piece's Bezier net over the box and its rounding bound. */
typedef struct {
    int p, q;
    double net[MAXP * MAXP * DIM];
    double err;
} piece_net;

/* The value net of the piece (homogeneous points), or the hodograph net
 * along dir (dir >= 0): degree p - 1 along dir over the knots without
 * their first, so its span there is one less. */
static void piece_net_of(const ic_nurbs_patch *pt, int dir, int su, int sv,
                         const double box[2][2], piece_net *out)
{
    tensor_net tn = {dir < 0 ? pt->hom : pt->hodo[dir], pt->n[1], pt->p[0], pt->p[1],
                     pt->knots[0], pt->knots[1]};
    if (dir == 0)
        tn.p--, tn.ku++, su--;
    else if (dir == 1)
        tn.q--, tn.kv++, tn.nv--, sv--;
    out->p = tn.p, out->q = tn.q;
    out->err = sub_net(&tn, su, sv, box, out->net);
}

/* (x, y, z) over the piece: the hull of the projected net points; *weight
 * the hull of the weights. */
static ic_status piece_values(const piece_net *pn, ic_interval out[3], ic_interval *weight)
{
    for (int e = 0; e < 3; e++)
        out[e] = (ic_interval){INFINITY, -INFINITY};
    *weight = (ic_interval){INFINITY, -INFINITY};
    for (int k = 0; k < (pn->p + 1) * (pn->q + 1); k++) {
        const double *P = pn->net + k * DIM;
        const ic_interval w = widened(P[3], pn->err);
        if (!(w.lo > 0))
            return IC_ERR_UNABLE; /* weights far below the net's size: no bound */
        *weight = hull_with(*weight, w);
        for (int e = 0; e < 3; e++)
            out[e] = hull_with(out[e], ic_quotient_positive(P[e], pn->err, P[3], pn->err));
    }
    return IC_OK;
}

static void net_hull(const piece_net *pn, ic_interval hull[DIM])
{
    for (int e = 0; e < DIM; e++)
        hull[e] = (ic_interval){INFINITY, -INFINITY};
    for (int k = 0; k < (pn->p + 1) * (pn->q + 1); k++)
        for (int e = 0; e < DIM; e++)
            hull[e] = hull_with(hull[e], widened(pn->net[k * DIM + e], pn->err));
}

/* Coordinate e of a net as a Bernstein polynomial. */
static void as_bpoly(ic_bpoly *f, const piece_net *pn, int e)
{
    f->du = pn->p, f->dv = pn->q, f->err = pn->err;
    for (int k = 0; k < (pn->p + 1) * (pn->q + 1); k++)
        f->c[k] = pn->net[k * DIM + e];
}

/* x_dir = (X_dir W - X W_dir) / W^2 of a rational piece as one rational
 * Bernstein function: the hull of its coefficient ratios, which tends to
 * the range as the box shrinks (the quotient rule on separate hulls stays
 * some 20 times too wide, its terms being strongly correlated). */
static ic_interval rational_derivative(const piece_net *val, const piece_net *hodo,
                                       const ic_bpoly *W, const ic_bpoly *D, int dir, int e)
{
    ic_bpoly X, Xd, Wd, A, B, N, Ne;
    as_bpoly(&X, val, e);
    as_bpoly(&Xd, hodo, e);
    as_bpoly(&Wd, hodo, 3);
    ic_bpoly_mul(&A, &Xd, W);
    ic_bpoly_mul(&B, &X, &Wd);
    ic_bpoly_sub(&N, &A, &B);
    ic_bpoly_elevate(&Ne, &N, dir);
    return ic_bpoly_ratio_hull(&Ne, D);
}

static ic_interval intersect(ic_interval a, ic_interval b)
{
    return (ic_interval){max2(a.lo, b.lo), min2(a.hi, b.hi)};
}

/* Values and (with_grad) derivatives over one piece, joined into out. */
static ic_status piece_enclose(const ic_nurbs_patch *pt, int su, int sv, const double box[2][2],
                               ic_interval_grad out[3], int with_grad)
{
    piece_net val, hodo;
    piece_net_of(pt, -1, su, sv, box, &val);
    ic_interval x[3], w;
    if (piece_values(&val, x, &w) != IC_OK)
        return IC_ERR_UNABLE;
    for (int e = 0; e < 3; e++)
        out[e].v = hull_with(out[e].v, x[e]);
    ic_bpoly W, D; /* the weight and its square, the derivatives' denominator */
    if (with_grad && pt->rational) {
        as_bpoly(&W, &val, 3);
        ic_bpoly_mul(&D, &W, &W);
    }
    for (int dir = 0; with_grad && dir < 2; dir++) {
        ic_interval h[DIM];
        piece_net_of(pt, dir, su, sv, box, &hodo);
        net_hull(&hodo, h);
        for (int e = 0; e < 3; e++) {
            /* the quotient rule x_dir = (X_dir - x W_dir) / W on the hulls
             * (W is constant for a polynomial patch), and for a rational
             * one the tighter single quotient, both sound: their meet */
            ic_interval d = pt->rational ? ic_interval_sub(h[e], ic_interval_mul(x[e], h[3])) : h[e];
            d = ic_interval_div(d, w);
            if (pt->rational)
                d = intersect(d, rational_derivative(&val, &hodo, &W, &D, dir, e));
            out[e].d[dir] = hull_with(out[e].d[dir], d);
        }
    }
    return IC_OK;
}

/* The parts of [lo, hi] along dir inside the natural domain: one, or two
 * across the seam of a wrapping parameter. 0 where the box leaves the
 * domain of a parameter that does not wrap (or is not a box). */
static int domain_parts(const ic_nurbs_patch *pt, int dir, ic_interval in, double part[2][2])
{
    const double d0 = pt->domain[dir][0], d1 = pt->domain[dir][1];
    if (!(in.lo <= in.hi))
        return 0;
    if (!pt->periodic[dir]) {
        if (in.lo < d0 || in.hi > d1)
            return 0;
        part[0][0] = in.lo, part[0][1] = in.hi;
        return 1;
    }
    if (in.hi - in.lo >= d1 - d0) {
        part[0][0] = d0, part[0][1] = d1;
        return 1;
    }
    /* one ulp of the domain's size either way covers the rounding of the shift */
    const double ulp = 4 * DBL_EPSILON * max2(fabs(d0), fabs(d1));
    const double lo = ic_nurbs_wrap(pt, dir, in.lo), hi = lo + (in.hi - in.lo);
    part[0][0] = max2(d0, lo - ulp), part[0][1] = min2(d1, hi + ulp);
    if (hi + ulp <= d1)
        return 1;
    part[1][0] = d0, part[1][1] = min2(d1, d0 + (hi - d1) + ulp);
    return 2;
}

ic_status ic_nurbs_interval_grad(const ic_nurbs_patch *pt, ic_interval_grad *out,
                                 const ic_interval in[2], int with_grad, ic_error *err)
{
    double parts[2][2][2];
    int nparts[2];
    for (int d = 0; d < 2; d++)
        if (!(nparts[d] = domain_parts(pt, d, in[d], parts[d])))
            return ic_error_set(err, IC_ERR_DOMAIN, 0,
                                "the box leaves the NURBS patch's parameter domain");
    for (int e = 0; e < 3; e++) {
        out[e].v = (ic_interval){INFINITY, -INFINITY};
        out[e].d[0] = out[e].d[1] = out[e].v;
    }
    for (int a = 0; a < nparts[0]; a++)
        for (int b = 0; b < nparts[1]; b++) {
            const double *pu = parts[0][a], *pv = parts[1][b];
            const int u0 = ic_nurbs_find_span(pt, 0, pu[0], IC_NURBS_RIGHT),
                      u1 = ic_nurbs_find_span(pt, 0, pu[1], IC_NURBS_LEFT),
                      v0 = ic_nurbs_find_span(pt, 1, pv[0], IC_NURBS_RIGHT),
                      v1 = ic_nurbs_find_span(pt, 1, pv[1], IC_NURBS_LEFT);
            /* a box of zero width on a knot: its LEFT span is below its RIGHT one */
            const int u1c = u1 < u0 ? u0 : u1, v1c = v1 < v0 ? v0 : v1;
            for (int su = u0; su <= u1c; su++)
                for (int sv = v0; sv <= v1c; sv++) {
                    const double *ku = pt->knots[0], *kv = pt->knots[1];
                    if (ku[su] == ku[su + 1] || kv[sv] == kv[sv + 1])
                        continue; /* an empty span */
                    const double box[2][2] = {{max2(pu[0], ku[su]), min2(pu[1], ku[su + 1])},
                                              {max2(pv[0], kv[sv]), min2(pv[1], kv[sv + 1])}};
                    if (piece_enclose(pt, su, sv, box, out, with_grad) != IC_OK)
                        return ic_error_set(err, IC_ERR_UNABLE, 0,
                                            "NURBS patch: weights too small to bound a piece");
                }
        }
    for (int e = 0; e < 3; e++) /* never an empty enclosure: callers read that as excluded */
        if (ic_interval_is_empty(out[e].v) ||
            (with_grad && (ic_interval_is_empty(out[e].d[0]) || ic_interval_is_empty(out[e].d[1]))))
            return ic_error_set(err, IC_ERR_UNABLE, 0, "NURBS patch: no piece covers the box");
    return IC_OK;
}
