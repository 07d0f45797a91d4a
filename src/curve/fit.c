/* A traced curve as B-splines (docs/bspline.md): quintic Hermite pieces
 * from the exact first and second derivatives at the traced points (the
 * curve in space by arc length; its parameter curves on the parametric
 * sheets by the chain rule), checked against corrected points of the
 * intersection between the points. */
#include "common/args.h"
#include "intercurve/bspline.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "common/vec3.h"
#include "curve/fit_check.h"
#include "curve/hermite.h"
#include "surface/surface_access.h"
#include "intercurve/trace.h"

/* (u', v') and (u'', v'') of a parametric sheet along the curve from c'
 * and c'': c' = R_u u' + R_v v' and c'' - (R_uu u'^2 + 2 R_uv u'v' + R_vv
 * v'^2) = R_u u'' + R_v v'', each solved by least squares (the normal
 * equations of the tangent basis). 0 where the sheet is degenerate. */
static int param_derivatives(ic_surface *S, const ic_jet_space *sp, const double uv[2],
                             const double *d1, const double *d2, double out1[2], double out2[2])
{
    double t[3 * 6];
    if (ic_surface_taylor(S, t, uv, sp, NULL) != IC_OK)
        return 0;
    const int iu = ic_jet_index(sp, (int[]){1, 0}), iv = ic_jet_index(sp, (int[]){0, 1});
    const int iuu = ic_jet_index(sp, (int[]){2, 0}), iuv = ic_jet_index(sp, (int[]){1, 1});
    const int ivv = ic_jet_index(sp, (int[]){0, 2});
    double Ru[3], Rv[3], Ruu[3], Ruv[3], Rvv[3];
    for (int k = 0; k < 3; k++) { /* Taylor coefficients to derivatives */
        Ru[k] = t[6 * k + iu], Rv[k] = t[6 * k + iv];
        Ruu[k] = 2 * t[6 * k + iuu], Ruv[k] = t[6 * k + iuv], Rvv[k] = 2 * t[6 * k + ivv];
    }
    const double E = ic_dot3(Ru, Ru), F = ic_dot3(Ru, Rv), G = ic_dot3(Rv, Rv), det = E * G - F * F;
    if (!(det > 1e-20 * (E * G)) || !isfinite(det))
        return 0;
    double a = ic_dot3(Ru, d1), b = ic_dot3(Rv, d1);
    out1[0] = (G * a - F * b) / det, out1[1] = (E * b - F * a) / det;
    double r[3];
    for (int k = 0; k < 3; k++)
        r[k] = d2[k] - (Ruu[k] * out1[0] * out1[0] + 2 * Ruv[k] * out1[0] * out1[1] +
                        Rvv[k] * out1[1] * out1[1]);
    a = ic_dot3(Ru, r), b = ic_dot3(Rv, r);
    out2[0] = (G * a - F * b) / det, out2[1] = (E * b - F * a) / det;
    return 1;
}

/* relative (of a domain's width): a parameter this close to a knot stands
 * on its knot line (the tracer's snap, IC_TRACE_KNOT_SNAP_REL) */
#define FIT_KNOT_SNAP_REL 1e-13

/* Whether the parameters x of sheet s stand on one of its knot lines or
 * periodic seams (never on an implicit surface). */
static int sheet_on_line(ic_pair *pair, int s, const double x[2])
{
    ic_surface *S = ic_pair_surface(pair, s);
    if (ic_surface_get_kind(S) != IC_PARAMETRIC)
        return 0;
    double dom[2][2], knot;
    ic_surface_get_domain(S, dom, NULL);
    for (int i = 0; i < 2; i++) {
        const double snap = FIT_KNOT_SNAP_REL * (dom[i][1] - dom[i][0]);
        if (ic_surface_knot_crossed(S, i, x[i] - snap, x[i] + snap, &knot) ||
            (ic_surface_knot_seam(S, i) &&
             (fabs(x[i] - dom[i][0]) <= snap || fabs(x[i] - dom[i][1]) <= snap)))
            return 1;
    }
    return 0;
}

/* Whether p stands on a knot line or a periodic seam of a NURBS sheet. */
static int stands_on_line(ic_pair *pair, const ic_trace_point *p)
{
    return sheet_on_line(pair, 0, p->params[0]) || sheet_on_line(pair, 1, p->params[1]);
}

/* relative (of the curve's length): the shortest stretch between nodes. A
 * quintic's third derivative from its net carries the net's rounding
 * (about 1e-16 of the coordinates) over h^3: stretches of 1e-9 L, which
 * the tracer leaves beside branch points, gave torsions of 1e11 between
 * their ends. Traced points closer than this to the node before are left
 * out (a point on a knot line never: the node before it goes instead),
 * which the Hermite pieces bridge with error of order h^6. */
#define FIT_MIN_STRETCH_REL 1e-4

/* The space nodes of a traced curve: x, c' = t, c'' = kappa n (0 where the
 * curvature is 0 or not finite, a cusp at an end). Returns the number of
 * nodes; source[k] is node k's point. */
static int space_nodes(ic_pair *pair, const ic_trace_curve *c, ic_hermite_node *nodes, int *source,
                       int *pinned)
{
    const double shortest = FIT_MIN_STRETCH_REL * (c->points[c->npoints - 1].s - c->points[0].s);
    int n = 0;
    for (int i = 0; i < c->npoints; i++) {
        const ic_trace_point *p = &c->points[i];
        const int last = i == c->npoints - 1, keep = last || stands_on_line(pair, p);
        if (n > 0 && !(p->s - nodes[n - 1].s >= shortest)) {
            if (!keep)
                continue;
            /* the point must stay: the node before goes, unless it is the
             * first or must stay itself */
            if (n > 1 && !pinned[n - 1] && p->s > nodes[n - 2].s)
                n--;
            else if (!(p->s > nodes[n - 1].s))
                continue;
        }
        ic_hermite_node *h = &nodes[n];
        h->s = p->s;
        const int curved = p->frame_defined && isfinite(p->kappa);
        for (int k = 0; k < 3; k++) {
            h->x[k] = p->xyz[k];
            h->d1[k] = h->d1b[k] = p->t[k];
            h->d2[k] = h->d2b[k] = curved ? p->kappa * p->n[k] : 0;
        }
        h->tau = curved ? p->tau : NAN;
        pinned[n] = keep;
        source[n++] = i;
    }
    return n;
}

/* relative to the parameter speed: a curve whose parameter moves slower
 * than this along a knot line's normal touches the line rather than
 * crossing it (Viviani's curve at the top of a sphere written about y),
 * and lies on the side its second derivative points to, before and after */
#define FIT_TOUCHING_REL 1e-8

/* The knot sides of sheet s at a point on its knot lines for the stretch
 * after the point (way = +1) or before it (way = -1): the piece a
 * parameter moves into along the curve that way. side[i] = 0 off knots. */
static void knot_sides(ic_pair *pair, int s, const ic_trace_point *p, const double d1[2],
                       const double d2[2], int way, int side[2], double on[2])
{
    ic_surface *S = ic_pair_surface(pair, s);
    double dom[2][2], knot;
    ic_surface_get_domain(S, dom, NULL);
    const double speed = hypot(d1[0], d1[1]);
    for (int i = 0; i < 2; i++) {
        const double x = p->params[s][i], snap = FIT_KNOT_SNAP_REL * (dom[i][1] - dom[i][0]);
        side[i] = 0;
        on[i] = x;
        const int on_seam = ic_surface_knot_seam(S, i) &&
                            (fabs(x - dom[i][0]) <= snap || fabs(x - dom[i][1]) <= snap);
        if (!on_seam && !ic_surface_knot_crossed(S, i, x - snap, x + snap, &knot))
            continue;
        /* exactly on the line (a sheet that did not land there stands within
         * rounding of it): the side then picks the piece */
        on[i] = on_seam ? (fabs(x - dom[i][0]) <= snap ? dom[i][0] : dom[i][1]) : knot;
        if (fabs(d1[i]) > FIT_TOUCHING_REL * speed) /* crossing: the piece ahead that way */
            side[i] = (d1[i] > 0) == (way > 0) ? 1 : -1;
        else if (d2[i] != 0) /* touching the line: the curve stays on one side */
            side[i] = d2[i] > 0 ? 1 : -1;
    }
}

/* The curve's c'' on the stretch after (way = +1) or before (-1) a point on
 * knot lines: the apparatus with each sheet's piece on that side forced. */
static int side_curvature(ic_pair *pair, const ic_trace_point *p, const double on[2][2],
                          int sides[2][2], double d2[3])
{
    for (int s = 0; s < 2; s++)
        if (ic_surface_get_kind(ic_pair_surface(pair, s)) == IC_PARAMETRIC)
            ic_surface_set_knot_side(ic_pair_surface(pair, s), sides[s]);
    ic_local_options opt;
    ic_local_defaults(&opt);
    ic_local_point pt;
    memset(&pt, 0, sizeof pt);
    memcpy(pt.xyz, p->xyz, sizeof pt.xyz);
    memcpy(pt.params, on, sizeof pt.params);
    ic_local_result res;
    const int ok = ic_local_apparatus(pair, &res, &pt, 2, IC_METHOD_JET, &opt, NULL) == IC_OK &&
                   res.type == IC_POINT_TRANSVERSAL;
    for (int s = 0; s < 2; s++)
        ic_surface_set_knot_side(ic_pair_surface(pair, s), NULL);
    if (!ok)
        return 0;
    for (int k = 0; k < 3; k++) /* c'' = kappa n whichever way t points */
        d2[k] = res.branches[0].frame_defined ? res.branches[0].kappa * res.branches[0].n[k] : 0;
    return 1;
}

/* The knot sides of sheet s at a point, for the stretch before
 * (sides[0][s]) and after (sides[1][s]) it, and the parameters on[s] there. */
static void sheet_ways(ic_pair *pair, int s, const ic_trace_point *p, const ic_jet_space *sp,
                       const ic_hermite_node *h, int sides[2][2][2], double on[2][2])
{
    double d1[2], d2[2];
    memset(sides[0][s], 0, sizeof sides[0][s]);
    memset(sides[1][s], 0, sizeof sides[1][s]);
    memcpy(on[s], p->params[s], sizeof on[s]);
    /* any point may stand on a knot line: a branch point the tracer ended a
     * curve at, not only the points it landed there; off every line the
     * sides stay 0 without the sheet's derivatives (most points) */
    if (!sheet_on_line(pair, s, p->params[s]) ||
        !param_derivatives(ic_pair_surface(pair, s), sp, p->params[s], h->d1, h->d2, d1, d2))
        return;
    knot_sides(pair, s, p, d1, d2, -1, sides[0][s], on[s]);
    knot_sides(pair, s, p, d1, d2, +1, sides[1][s], on[s]);
}

/* The knot sides of every sheet at a point on knot lines (sheet_ways). */
static void knot_ways(ic_pair *pair, const ic_trace_point *p, const ic_jet_space *sp,
                      const ic_hermite_node *h, int sides[2][2][2], double on[2][2])
{
    for (int s = 0; s < 2; s++)
        sheet_ways(pair, s, p, sp, h, sides, on);
}

/* Both sides' c'' at a point on knot lines (the trace gives one side's). */
static void knot_node(ic_pair *pair, const ic_trace_point *p, const ic_jet_space *sp,
                      ic_hermite_node *h)
{
    int sides[2][2][2];
    double on[2][2];
    knot_ways(pair, p, sp, h, sides, on);
    int any = 0;
    for (int i = 0; i < 8; i++)
        any |= ((int *)sides)[i] != 0;
    if (!any) /* on no knot line: the traced apparatus serves both sides */
        return;
    side_curvature(pair, p, on, sides[0], h->d2b);
    side_curvature(pair, p, on, sides[1], h->d2);
}

/* Sheet s's (u', v') and (u'', v'') on both sides of a node (its pieces on
 * each side of a knot line where it is on one). 0 where degenerate. */
static int param_node(ic_pair *pair, int s, const ic_trace_point *p, const ic_jet_space *sp,
                      const ic_hermite_node *space, ic_hermite_node *h)
{
    ic_surface *S = ic_pair_surface(pair, s);
    int sides[2][2][2] = {{{0}}};
    double on[2][2];
    sheet_ways(pair, s, p, sp, space, sides, on); /* this sheet's only */
    ic_surface_set_knot_side(S, sides[1][s]);
    int ok = param_derivatives(S, sp, on[s], space->d1, space->d2, h->d1, h->d2);
    /* the same piece and the same c', c'' on both sides (off knot lines and
     * junctions): the side before is the side after, bit for bit */
    const int same = memcmp(sides[0][s], sides[1][s], sizeof sides[0][s]) == 0 &&
                     memcmp(space->d1, space->d1b, sizeof space->d1) == 0 &&
                     memcmp(space->d2, space->d2b, sizeof space->d2) == 0;
    if (same) {
        memcpy(h->d1b, h->d1, sizeof h->d1);
        memcpy(h->d2b, h->d2, sizeof h->d2);
    } else {
        ic_surface_set_knot_side(S, sides[0][s]);
        ok = ok && param_derivatives(S, sp, on[s], space->d1b, space->d2b, h->d1b, h->d2b);
    }
    ic_surface_set_knot_side(S, NULL);
    return ok;
}

/* relative: a traced point whose tangent leaves the chord to its neighbour
 * by more than this angle (its cosine below) stands where branches cross
 * (a branch point: its apparatus is one branch's); chords otherwise turn
 * by half of kappa h, far below it */
#define FIT_JUNCTION_COS 0.99

/* The branch through a singular point along a chord: its c' (oriented as
 * the chord) and c''. 0 where the analysis fails. */
static int branch_along(ic_pair *pair, const ic_trace_point *p, const double chord[3], double d1[3],
                        double d2[3])
{
    ic_local_options opt;
    ic_local_defaults(&opt);
    ic_local_point pt;
    memset(&pt, 0, sizeof pt);
    memcpy(pt.xyz, p->xyz, sizeof pt.xyz);
    memcpy(pt.params, p->params, sizeof pt.params);
    ic_local_result res;
    if (ic_local_apparatus(pair, &res, &pt, 2, IC_METHOD_AUTO, &opt, NULL) != IC_OK ||
        res.nbranches < 1)
        return 0;
    int best = 0;
    for (int b = 1; b < res.nbranches; b++)
        if (fabs(ic_dot3(res.branches[b].t, chord)) > fabs(ic_dot3(res.branches[best].t, chord)))
            best = b;
    const ic_branch *br = &res.branches[best];
    const double sign = ic_dot3(br->t, chord) < 0 ? -1 : 1;
    for (int k = 0; k < 3; k++) {
        d1[k] = sign * br->t[k];
        d2[k] = br->frame_defined ? br->kappa * br->n[k] : 0;
    }
    return 1;
}

/* Nodes where branches cross: each side takes the branch along its chord. */
static void junction_nodes(ic_pair *pair, const ic_trace_curve *c, ic_hermite_node *nodes,
                           const int *source, int n)
{
    for (int k = 0; k < n; k++) {
        const ic_trace_point *p = &c->points[source[k]];
        for (int side = 0; side < 2; side++) { /* 0: before, 1: after */
            const int other = side ? k + 1 : k - 1;
            if (other < 0 || other >= n)
                continue;
            double chord[3];
            ic_axpy3(chord, nodes[other].x, -1.0, nodes[k].x);
            const double len = ic_norm3(chord);
            if (!(len > 0))
                continue;
            ic_scale3(chord, chord, side ? 1 / len : -1 / len); /* along the curve */
            double *d1 = side ? nodes[k].d1 : nodes[k].d1b, *d2 = side ? nodes[k].d2 : nodes[k].d2b;
            if (ic_dot3(d1, chord) < FIT_JUNCTION_COS)
                branch_along(pair, p, chord, d1, d2);
        }
    }
}

/* The nodes of sheet s's parameter curve from the space nodes; 0 where the
 * sheet is degenerate at some node (a pole): no pcurve then. */
static int param_nodes(ic_pair *pair, int s, const ic_trace_curve *c, const ic_hermite_node *space,
                       const int *source, int n, const ic_jet_space *sp, ic_hermite_node *out)
{
    ic_surface *S = ic_pair_surface(pair, s);
    double dom[2][2];
    int periodic[2];
    ic_surface_get_domain(S, dom, periodic);
    for (int k = 0; k < n; k++) {
        const double *uv = c->points[source[k]].params[s];
        ic_hermite_node *h = &out[k];
        memset(h, 0, sizeof *h);
        h->s = space[k].s;
        if (!param_node(pair, s, &c->points[source[k]], sp, &space[k], h))
            return 0;
        for (int i = 0; i < 2; i++) {
            const double prev =
                k > 0 ? out[k - 1].x[i] + (h->s - out[k - 1].s) * out[k - 1].d1[i] : uv[i];
            h->x[i] = ic_fit_unwrap(uv[i], prev, periodic[i] ? dom[i][1] - dom[i][0] : 0);
        }
    }
    return 1;
}

void ic_curve_fit_free(ic_curve_fit *f)
{
    if (!f)
        return;
    free(f->curve.knots);
    free(f->curve.control);
    for (int s = 0; s < 2; s++) {
        free(f->pcurves[s].knots);
        free(f->pcurves[s].control);
    }
    free(f);
}

/* Whether the curve in space is smooth across every knot line of the pair:
 * each parametric sheet a net recognised as a plane or a surface of
 * revolution (ic_surface_net_shape). Such a net lies within 4 IC_NET_REL of
 * its size on that smooth surface (docs/nurbs.md), the surface the exact
 * paths trace on, so the curve's c'' is the same on both sides of a knot
 * line up to that: the traced c'' serves both, the joint is C^2 like the
 * others, and only the pcurves (whose pieces change there) keep two sides. */
static int smooth_across_knots(ic_pair *pair)
{
    for (int s = 0; s < 2; s++) {
        ic_surface *S = ic_pair_surface(pair, s);
        const ic_net_shape *shape = NULL;
        if (ic_surface_get_kind(S) == IC_PARAMETRIC &&
            (ic_surface_net_shape(S, &shape) != 0 || !shape)) /* out of memory: the full way */
            return 0;
    }
    return 1;
}

/* The nodes of the traced points of c: positions and derivatives, with
 * their sides on knot lines and at junctions; returns how many (source[k]:
 * node k's point; pinned[k]: it must stay). */
static int curve_nodes(ic_pair *pair, const ic_trace_curve *c, const ic_jet_space *sp,
                       ic_hermite_node *nodes, int *source, int *pinned)
{
    const int n = space_nodes(pair, c, nodes, source, pinned);
    /* on a tangential curve the side apparatus finds a tangential point,
     * never a transversal one (side_curvature keeps the traced c'' then):
     * a full tangential analysis per knot point, for nothing */
    if (!c->tangential && !smooth_across_knots(pair))
        for (int k = 0; k < n; k++)
            knot_node(pair, &c->points[source[k]], sp, &nodes[k]);
    junction_nodes(pair, c, nodes, source, n);
    return n;
}

/* relative to the fit tolerance: a stretch grows over a traced point only
 * where its quintic passes this close to it, leaving the rest of the
 * tolerance to the error between the points (checked after) */
#define FIT_MERGE_POS 0.1
/* relative: and with its c' and c'' (of max(kappa, 1 / length)) this
 * close to the point's exact ones, and its torsion within FIT_MERGE_TAU of
 * max(kappa, 1 / length), so that curvature and torsion between the knots
 * stay well within 1e-6 and 1e-5 (docs/bspline.md) */
#define FIT_MERGE_DERIV 1e-7
#define FIT_MERGE_TAU 1e-6

/* The points of c that a coarser fit keeps (ic_hermite_merge, the knots
 * merged where the error allows): a new array in *pts (owned by the
 * caller), or NULL where nothing is merged. */
static ic_status merged_points(ic_pair *pair, const ic_trace_curve *c, double fit_tol,
                               const ic_jet_space *sp, ic_trace_point **pts, int *npts,
                               ic_error *err)
{
    *pts = NULL;
    ic_hermite_node *nodes = malloc(sizeof *nodes * (size_t)c->npoints);
    int *source = malloc(sizeof *source * (size_t)c->npoints * 3);
    int *pinned = source ? source + c->npoints : NULL, *keep = source ? pinned + c->npoints : NULL;
    ic_status st = nodes && source ? IC_OK : ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory");
    const int n = st == IC_OK ? curve_nodes(pair, c, sp, nodes, source, pinned) : 0;
    const int m = n >= 2 ? ic_hermite_merge(nodes, pinned, n, 3, FIT_MERGE_POS * fit_tol,
                                            FIT_MERGE_DERIV, FIT_MERGE_TAU, keep)
                         : 0;
    if (m >= 2 && m < c->npoints) {
        *pts = malloc(sizeof **pts * (size_t)m);
        if (!*pts)
            st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory fitting a curve");
        for (int k = 0; *pts && k < m; k++)
            (*pts)[k] = c->points[source[keep[k]]];
        *npts = m;
    }
    free(nodes);
    free(source);
    return st;
}

/* One fit of the points of c; bad (c->npoints doubles) receives the middles
 * of the stretches beyond tol. */
static ic_status fit_once(ic_curve_fit **out, ic_pair *pair, const ic_trace_curve *c,
                          double fit_tol, const fit_spaces *spaces, double *bad, int *nbad,
                          ic_error *err)
{
    *out = NULL;
    *nbad = 0;
    ic_curve_fit *f = calloc(1, sizeof *f);
    ic_hermite_node *nodes = malloc(sizeof *nodes * (size_t)c->npoints * 2);
    int *source = malloc(sizeof *source * (size_t)c->npoints * 2), *pinned = source + c->npoints;
    const ic_jet_space *sp = spaces->sheet;
    ic_status st =
        f && nodes && source ? IC_OK : ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory");
    const int n = st == IC_OK ? curve_nodes(pair, c, sp, nodes, source, pinned) : 0;
    if (st == IC_OK && n < 2)
        st = ic_error_set(err, IC_ERR_INVALID, 0, "curve fit: the curve has no length");
    if (st == IC_OK)
        st = ic_hermite_bspline(&f->curve, nodes, n, 3, c->closed && ic_hermite_closes(nodes, n, 3),
                                err);
    for (int s = 0; st == IC_OK && s < 2; s++)
        if (ic_surface_get_kind(ic_pair_surface(pair, s)) == IC_PARAMETRIC &&
            param_nodes(pair, s, c, nodes, source, n, sp, nodes + c->npoints))
            st = ic_hermite_bspline(&f->pcurves[s], nodes + c->npoints, n, 2,
                                    c->closed && ic_hermite_closes(nodes + c->npoints, n, 2), err);
    if (st == IC_OK)
        st = ic_fit_check_all(pair, f, c, nodes, source, n, fit_tol, spaces, bad, nbad, err);
    free(nodes);
    free(source);
    if (st != IC_OK) {
        ic_curve_fit_free(f);
        return st;
    }
    *out = f;
    return IC_OK;
}

/* A point of the intersection at the fitted curve's s: located from the
 * curve's point (the pcurves' parameters, else the node's, as the guess),
 * with its apparatus oriented along the curve. 0 where that fails (a
 * tangential point: no refinement there). */
static int point_at(ic_pair *pair, const ic_curve_fit *f, const ic_trace_point *near, double s,
                    ic_trace_point *p, int *nomem)
{
    double d[6], params[2][2];
    if (ic_bspline_eval(&f->curve, s, 1, d, NULL) != IC_OK)
        return 0;
    memcpy(params, near->params, sizeof params);
    for (int k = 0; k < 2; k++)
        if (f->pcurves[k].ncontrol &&
            ic_bspline_eval(&f->pcurves[k], s, 0, params[k], NULL) != IC_OK)
            return 0;
    ic_local_options opt;
    ic_local_defaults(&opt);
    ic_local_point pt;
    ic_local_result res;
    ic_status st = ic_local_locate_guess(pair, &pt, d, params, &opt, NULL);
    if (st != IC_OK && st != IC_ERR_NOMEM)
        st = ic_local_locate(pair, &pt, d, &opt, NULL);
    if (st == IC_OK)
        st = ic_local_apparatus(pair, &res, &pt, 2, IC_METHOD_JET, &opt, NULL);
    *nomem |= st == IC_ERR_NOMEM;
    if (st != IC_OK || res.type != IC_POINT_TRANSVERSAL)
        return 0;
    const ic_branch *br = &res.branches[0];
    const double sign = ic_dot3(br->t, d + 3) < 0 ? -1 : 1;
    memset(p, 0, sizeof *p);
    p->s = s;
    memcpy(p->xyz, pt.xyz, sizeof p->xyz);
    memcpy(p->params, pt.params, sizeof p->params);
    ic_scale3(p->t, br->t, sign);
    memcpy(p->n, br->n, sizeof p->n);
    ic_scale3(p->b, br->b, sign);
    p->kappa = br->kappa;
    p->tau = br->tau;
    p->frame_defined = br->frame_defined;
    return 1;
}

/* The points of c with a located point at each s of bad[] (sorted) put in:
 * a new point array in *pts (owned by the caller); *more = 0 when none
 * could be made. IC_ERR_NOMEM when memory ran out (never a coarser fit). */
static ic_status refined_points(ic_pair *pair, const ic_curve_fit *f, const ic_trace_curve *c,
                                const double *bad, int nbad, ic_trace_point **pts, int *n,
                                int *more, ic_error *err)
{
    *more = 0;
    ic_trace_point *out = malloc(sizeof *out * (size_t)(c->npoints + nbad));
    int k = 0, b = 0, nomem = !out;
    for (int i = 0; out && i < c->npoints; i++) {
        for (; b < nbad && bad[b] < c->points[i].s; b++)
            k += point_at(pair, f, &c->points[i > 0 ? i - 1 : 0], bad[b], &out[k], &nomem);
        out[k++] = c->points[i];
    }
    *pts = out;
    *n = k;
    *more = k > c->npoints;
    return nomem ? ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory refining a curve's fit")
                 : IC_OK;
}

/* rounds of refinement: each halves the stretches that missed the tolerance */
#define FIT_MAX_ROUNDS 4

ic_status ic_curve_fit_new(ic_curve_fit **out, ic_pair *pair, const ic_trace_curve *c,
                           double fit_tol, ic_error *err)
{
    IC_ARG_NOT_NULL(out, "fit");
    *out = NULL;
    IC_ARG_NOT_NULL(pair, "pair");
    IC_ARG_NOT_NULL(c, "c");
    if (c->npoints < 2 || !c->points)
        return ic_error_set(err, IC_ERR_INVALID, 0, "curve fit: no curve of two points or more");
    if (!(fit_tol > 0) || !isfinite(fit_tol))
        return ic_error_set(err, IC_ERR_INVALID, 0, "curve fit: the tolerance must be positive");
    ic_trace_curve cur = *c;
    ic_trace_point *owned = NULL;
    ic_curve_fit *f = NULL;
    fit_spaces spaces;
    ic_status st = ic_fit_spaces_new(&spaces, err);
    if (st != IC_OK)
        return st;
    st = merged_points(pair, c, fit_tol, spaces.sheet, &owned, &cur.npoints, err);
    if (owned)
        cur.points = owned;
    for (int round = 0; st == IC_OK && round <= FIT_MAX_ROUNDS; round++) {
        double *bad = malloc(sizeof *bad * (size_t)cur.npoints);
        int nbad = 0;
        if (!bad) {
            st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory fitting a curve");
            break;
        }
        ic_curve_fit_free(f);
        st = fit_once(&f, pair, &cur, fit_tol, &spaces, bad, &nbad, err);
        ic_trace_point *next = NULL;
        int n = 0, more = 0;
        if (st == IC_OK && nbad > 0 && round < FIT_MAX_ROUNDS)
            st = refined_points(pair, f, &cur, bad, nbad, &next, &n, &more, err);
        free(bad);
        if (!more || st != IC_OK) {
            free(next);
            break;
        }
        free(owned);
        owned = next;
        cur.points = owned;
        cur.npoints = n;
    }
    ic_fit_spaces_free(&spaces);
    free(owned);
    if (st != IC_OK) {
        ic_curve_fit_free(f);
        return st;
    }
    *out = f;
    return IC_OK;
}
