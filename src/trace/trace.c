/*
 * The whole intersection: every start candidate not yet covered by a traced
 * curve starts one, traced in both directions and joined; tangential points
 * (curve ends, or candidates that are tangential themselves) are recorded;
 * each curve gets a shape from seed 001's corollaries.
 */
#include "trace_internal.h"
#include "common/vec3.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct ic_trace_result {
    ic_trace_curve *curves;
    ic_trace_point **storage; /* the points of each curve */
    int (*at)[2];             /* the exact tangential point at each end, or -1 */
    int ncurves, capc;
    ic_trace_special *specials;
    ic_local_point *special_pts; /* the located points, for their branches */
    int nspecials, caps;
    ic_trace_report report;
};

const char *ic_shape_name(ic_shape shape)
{
    static const char *const names[] = {"general", "line", "circle", "planar", "circular-helix",
                                        "helix"};
    return shape >= IC_SHAPE_GENERAL && shape <= IC_SHAPE_HELIX ? names[shape] : "unknown";
}

static void failure(ic_trace_report *rep, const char *fmt, ...)
{
    if (rep->nfailures >= IC_TRACE_MAX_FAILURES)
        return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(rep->failures[rep->nfailures++], sizeof rep->failures[0], fmt, ap);
    va_end(ap);
}

/* Points where the normals are this close to parallel carry large
 * transversal torsion errors (eps/angle^2 near Viviani's branch point, about
 * eps/angle^3.5 near seed 001 Ex. 5.1's: 500 at 1e-5 rad, 1e-5 at 1e-3 rad;
 * docs/tangential.md): the shape tests skip them. */
#define SHAPE_MIN_ANGLE 1e-2

/* Seed 001 corollaries 3.1-3.5 on the sampled kappa and tau, relative to the
 * largest curvature (lines: to the total turning kappa L). */
/* The shape; along a transversal curve the points near tangency are skipped
 * (their torsion is unreliable), along a tangential curve none is (its
 * apparatus comes from the height-difference method). */
static ic_shape classify(const ic_trace_point *p, int n, double length, double tol, int tangential)
{
    double kmax = 0, kmin = INFINITY, tmax = -INFINITY, tmin = INFINITY, rmax = -INFINITY,
           rmin = INFINITY;
    int framed = 0;
    for (int i = 0; i < n; i++) {
        if (p[i].angle < SHAPE_MIN_ANGLE && !tangential)
            continue;
        kmax = fmax(kmax, p[i].kappa);
        kmin = fmin(kmin, p[i].kappa);
        if (p[i].frame_defined) {
            framed++;
            tmax = fmax(tmax, p[i].tau);
            tmin = fmin(tmin, p[i].tau);
            if (p[i].tau != 0) {
                rmax = fmax(rmax, p[i].kappa / p[i].tau);
                rmin = fmin(rmin, p[i].kappa / p[i].tau);
            }
        }
    }
    if (kmax * length <= tol)
        return IC_SHAPE_LINE;
    if (!framed)
        return IC_SHAPE_GENERAL;
    const int planar = fmax(fabs(tmax), fabs(tmin)) <= tol * kmax;
    const int kconst = kmax - kmin <= tol * kmax;
    if (planar)
        return kconst ? IC_SHAPE_CIRCLE : IC_SHAPE_PLANAR;
    const double tbar = fmax(fabs(tmax), fabs(tmin));
    if (kconst && tmax - tmin <= tol * tbar)
        return IC_SHAPE_CIRCULAR_HELIX;
    if (tmin * tmax > 0 && rmax - rmin <= tol * fmax(fabs(rmax), fabs(rmin)))
        return IC_SHAPE_HELIX;
    return IC_SHAPE_GENERAL;
}

static double segment_distance(const double *p, const double *a, const double *b)
{
    double ab[3], ap[3];
    ic_axpy3(ab, b, -1.0, a);
    ic_axpy3(ap, p, -1.0, a);
    const double l2 = ic_dot3(ab, ab);
    double t = l2 > 0 ? ic_dot3(ap, ab) / l2 : 0.0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    double q[3];
    ic_axpy3(q, a, t, ab);
    ic_axpy3(q, p, -1.0, q);
    return ic_norm3(q);
}

static void cover(ic_candidate *c, int n, const ic_trace_point *pts, int np, double radius)
{
    for (int i = 0; i < n; i++) {
        if (c[i].covered)
            continue;
        for (int k = 0; k + 1 < np || (np == 1 && k == 0); k++) {
            const double d = np == 1 ? segment_distance(c[i].xyz, pts[0].xyz, pts[0].xyz)
                                     : segment_distance(c[i].xyz, pts[k].xyz, pts[k + 1].xyz);
            if (d <= radius) {
                c[i].covered = 1;
                break;
            }
        }
    }
}

static ic_status add_special(ic_trace_result *r, ic_pair *pair, const ic_local_point *pt,
                             int approximate, const ic_trace_options *opt, int *index)
{
    int dummy;
    if (!index)
        index = &dummy;
    for (int i = 0; i < r->nspecials; i++) {
        double d[3];
        ic_axpy3(d, r->specials[i].xyz, -1.0, pt->xyz);
        const double same = r->specials[i].approximate || approximate ? 1e-3 : 1e-9;
        if (ic_norm3(d) < same) { /* the same point met from another curve */
            *index = i;
            return IC_OK;
        }
    }
    *index = r->nspecials;
    if (r->nspecials == r->caps) {
        const int cap = r->caps ? 2 * r->caps : 8;
        ic_trace_special *p = realloc(r->specials, (size_t)cap * sizeof *p);
        if (p)
            r->specials = p;
        ic_local_point *q = realloc(r->special_pts, (size_t)cap * sizeof *q);
        if (q)
            r->special_pts = q;
        if (!p || !q)
            return IC_ERR_NOMEM;
        r->caps = cap;
    }
    r->special_pts[r->nspecials] = *pt;
    ic_trace_special *s = &r->specials[r->nspecials++];
    memcpy(s->xyz, pt->xyz, sizeof s->xyz);
    s->approximate = approximate;
    /* classify: at a curve end the point is just off the tangential point,
     * so the threshold is relaxed there (docs/tracing.md) */
    ic_local_options o = opt->local;
    if (approximate)
        o.tangential_angle = 1e-3;
    ic_local_result res;
    if (ic_local_apparatus(pair, &res, pt, 2, IC_METHOD_AUTO, &o, NULL) == IC_OK) {
        s->type = res.type;
        s->nbranches = res.nbranches;
    } else {
        s->type = IC_POINT_TANGENTIAL;
        s->nbranches = -1;
    }
    return IC_OK;
}

static ic_status add_curve(ic_trace_result *r, ic_trace_point *pts, int n, int closed,
                           ic_trace_event e0, ic_trace_event e1, double shape_tol, int at0, int at1)
{
    if (r->ncurves == r->capc) {
        const int cap = r->capc ? 2 * r->capc : 8;
        ic_trace_curve *c = realloc(r->curves, (size_t)cap * sizeof *c);
        ic_trace_point **s = realloc(r->storage, (size_t)cap * sizeof *s);
        int(*at)[2] = realloc(r->at, (size_t)cap * sizeof *at);
        if (c)
            r->curves = c;
        if (s)
            r->storage = s;
        if (at)
            r->at = at;
        if (!c || !s || !at)
            return IC_ERR_NOMEM;
        r->capc = cap;
    }
    r->at[r->ncurves][0] = at0;
    r->at[r->ncurves][1] = at1;
    ic_trace_curve *c = &r->curves[r->ncurves];
    r->storage[r->ncurves++] = pts;
    memset(c, 0, sizeof *c);
    c->closed = closed;
    c->npoints = n;
    c->points = pts;
    c->length = pts[n - 1].s - pts[0].s;
    c->ends[0] = e0;
    c->ends[1] = e1;
    c->shape_tol = shape_tol;
    c->shape = classify(pts, n, c->length, shape_tol, 0);
    return IC_OK;
}

/* A curve end at a tangential point: the point located precisely, appended
 * (the last step, about 2e-5, is straight to 1e-16) with the apparatus of
 * the branch continuing the curve, and recorded. Returns the special index,
 * or -1 (then the end is recorded approximately). */
static int finish_end(ic_trace_result *r, ic_pair *pair, const ic_trace_options *opt,
                      ic_trace_point *last, ic_trace_point *extra)
{
    ic_local_point near, P;
    memset(&near, 0, sizeof near);
    memcpy(near.xyz, last->xyz, sizeof near.xyz);
    memcpy(near.params, last->params, sizeof near.params);
    int index = -1;
    if (ic_local_locate_tangential(pair, &P, &near, 1e-3, &opt->local, NULL) != IC_OK) {
        add_special(r, pair, &near, 1, opt, NULL);
        return -1;
    }
    ic_local_result res;
    ic_local_options o = opt->local;
    if (ic_local_apparatus(pair, &res, &P, 3, IC_METHOD_AUTO, &o, NULL) != IC_OK ||
        add_special(r, pair, &P, 0, opt, &index) != IC_OK)
        return -1;
    double d[3];
    ic_axpy3(d, P.xyz, -1.0, last->xyz);
    *extra = *last;
    extra->s = last->s + ic_norm3(d);
    memcpy(extra->xyz, P.xyz, sizeof P.xyz);
    memcpy(extra->params, P.params, sizeof P.params);
    extra->angle = res.angle;
    /* the branch through P that continues the curve */
    int best = -1;
    double bd = 0;
    for (int b = 0; b < res.nbranches; b++)
        if (fabs(ic_dot3(res.branches[b].t, last->t)) > bd)
            bd = fabs(ic_dot3(res.branches[b].t, last->t)), best = b;
    if (best >= 0 && res.branches[best].regular) {
        const ic_branch *br = &res.branches[best];
        const double sg = ic_dot3(br->t, last->t) < 0 ? -1.0 : 1.0;
        ic_scale3(extra->t, br->t, sg);
        memcpy(extra->n, br->n, sizeof extra->n);
        ic_scale3(extra->b, br->b, sg);
        extra->kappa = br->kappa;
        extra->tau = br->tau;
        extra->frame_defined = br->frame_defined;
    }
    return index;
}

/* Traces the curve through pt: forward, and backward unless it closed. */
static ic_status trace_curve(ic_trace_result *r, ic_tracer *tr, ic_pair *pair,
                             const ic_local_point *pt, const ic_trace_options *opt,
                             ic_trace_point **pts_out, int *n_out, ic_error *err)
{
    ic_trace_event e1 = IC_TRACE_FAILED, e0 = IC_TRACE_FAILED;
    ic_status st = ic_tracer_start(tr, pt, 1, err);
    if (st == IC_OK)
        st = ic_tracer_run(tr, &e1, err);
    if (st != IC_OK && e1 != IC_TRACE_FAILED)
        return st;
    if (st != IC_OK)
        failure(&r->report, "curve from (%g, %g, %g): %s", pt->xyz[0], pt->xyz[1], pt->xyz[2],
                err ? err->message : "failed");
    if (e1 == IC_TRACE_BUDGET)
        failure(&r->report, "curve from (%g, %g, %g): stopped at the budget of %d points", pt->xyz[0],
                pt->xyz[1], pt->xyz[2], opt->max_points);
    int n1 = ic_tracer_num_points(tr);
    ic_trace_point *fwd = malloc((size_t)(n1 + 1) * sizeof *fwd);
    if (!fwd)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory");
    memcpy(fwd, ic_tracer_point(tr, 0), (size_t)n1 * sizeof *fwd);
    int at1 = -1, at0 = -1;
    if (e1 == IC_TRACE_TANGENTIAL && (at1 = finish_end(r, pair, opt, &fwd[n1 - 1], &fwd[n1])) >= 0)
        n1++;
    if (e1 == IC_TRACE_CLOSED) {
        *pts_out = fwd;
        *n_out = n1;
        return add_curve(r, fwd, n1, 1, e1, e1, opt->shape_tol, -1, -1);
    }
    st = ic_tracer_start(tr, pt, -1, err);
    if (st == IC_OK)
        st = ic_tracer_run(tr, &e0, err);
    if (st != IC_OK)
        failure(&r->report, "curve from (%g, %g, %g), backwards: %s", pt->xyz[0], pt->xyz[1],
                pt->xyz[2], err ? err->message : "failed");
    if (e0 == IC_TRACE_BUDGET)
        failure(&r->report, "curve from (%g, %g, %g), backwards: stopped at the budget of %d points",
                pt->xyz[0], pt->xyz[1], pt->xyz[2], opt->max_points);
    int n0 = ic_tracer_num_points(tr);
    ic_trace_point *back = malloc((size_t)(n0 + 1) * sizeof *back);
    if (!back) {
        free(fwd);
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory");
    }
    memcpy(back, ic_tracer_point(tr, 0), (size_t)n0 * sizeof *back);
    if (e0 == IC_TRACE_TANGENTIAL && (at0 = finish_end(r, pair, opt, &back[n0 - 1], &back[n0])) >= 0)
        n0++;
    ic_trace_point *all = malloc((size_t)(n0 + n1 - 1) * sizeof *all);
    if (!all) {
        free(fwd);
        free(back);
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory");
    }
    /* the backward part reversed: order, orientation (t, b) and arc length */
    const double S0 = back[n0 - 1].s;
    for (int i = 0; i < n0; i++) {
        ic_trace_point p = back[n0 - 1 - i];
        ic_scale3(p.t, p.t, -1.0);
        ic_scale3(p.b, p.b, -1.0);
        p.s = S0 - p.s;
        all[i] = p;
    }
    for (int i = 1; i < n1; i++) {
        all[n0 - 1 + i] = fwd[i];
        all[n0 - 1 + i].s += S0;
    }
    free(fwd);
    free(back);
    *pts_out = all;
    *n_out = n0 + n1 - 1;
    return add_curve(r, all, n0 + n1 - 1, 0, e0, e1, opt->shape_tol, at0, at1);
}

/* Reverses a curve in place: order, orientation (t, b) and arc length. */
static void reverse_curve(ic_trace_point *p, int n)
{
    const double L = p[n - 1].s + p[0].s;
    for (int i = 0; i < n / 2; i++) {
        const ic_trace_point tmp = p[i];
        p[i] = p[n - 1 - i];
        p[n - 1 - i] = tmp;
    }
    for (int i = 0; i < n; i++) {
        ic_scale3(p[i].t, p[i].t, -1.0);
        ic_scale3(p[i].b, p[i].b, -1.0);
        p[i].s = L - p[i].s;
    }
}

/* Joins curves through the tangential points at their ends where a branch
 * continues smoothly: the outgoing directions of the two ends are opposite.
 * A curve joined to itself is closed. */
static ic_status join_curves(ic_trace_result *r, double shape_tol)
{
    for (int changed = 1; changed;) {
        changed = 0;
        for (int a = 0; a < r->ncurves && !changed; a++)
            for (int ea = 0; ea < 2 && !changed; ea++) {
                const int k = r->at[a][ea];
                if (k < 0 || r->curves[a].closed)
                    continue;
                for (int b = a; b < r->ncurves && !changed; b++)
                    for (int eb = 0; eb < 2 && !changed; eb++) {
                        if ((b == a && eb == ea) || r->at[b][eb] != k)
                            continue;
                        /* outgoing directions: +t at a start, -t at an end */
                        const ic_trace_curve *ca = &r->curves[a], *cb = &r->curves[b];
                        const ic_trace_point *pa = ea ? &ca->points[ca->npoints - 1] : &ca->points[0];
                        const ic_trace_point *pb = eb ? &cb->points[cb->npoints - 1] : &cb->points[0];
                        double oa[3], ob[3];
                        ic_scale3(oa, pa->t, ea ? -1.0 : 1.0);
                        ic_scale3(ob, pb->t, eb ? -1.0 : 1.0);
                        if (ic_dot3(oa, ob) > -1 + 1e-6)
                            continue;
                        ic_trace_point *A = r->storage[a];
                        int na = ca->npoints;
                        if (b == a) { /* both ends of one curve: it closes */
                            r->curves[a].closed = 1;
                            r->curves[a].ends[0] = r->curves[a].ends[1] = IC_TRACE_CLOSED;
                            r->at[a][0] = r->at[a][1] = -1;
                            changed = 1;
                            continue;
                        }
                        /* a's joining end last, b's joining end first */
                        if (ea == 0)
                            reverse_curve(A, na);
                        ic_trace_point *B = r->storage[b];
                        const int nb = cb->npoints;
                        if (eb == 1)
                            reverse_curve(B, nb);
                        ic_trace_point *J = realloc(A, (size_t)(na + nb - 1) * sizeof *J);
                        if (!J)
                            return IC_ERR_NOMEM;
                        const double shift = J[na - 1].s - B[0].s;
                        for (int i = 1; i < nb; i++) {
                            J[na - 1 + i] = B[i];
                            J[na - 1 + i].s += shift;
                        }
                        const int at0 = r->at[a][ea == 0 ? 1 : 0], at1 = r->at[b][eb == 1 ? 0 : 1];
                        const ic_trace_event e0 = ca->ends[ea == 0 ? 1 : 0];
                        const ic_trace_event e1 = cb->ends[eb == 1 ? 0 : 1];
                        free(B);
                        /* b leaves the list; a becomes the joined curve */
                        r->storage[a] = J;
                        r->curves[b] = r->curves[r->ncurves - 1];
                        r->storage[b] = r->storage[r->ncurves - 1];
                        r->at[b][0] = r->at[r->ncurves - 1][0];
                        r->at[b][1] = r->at[r->ncurves - 1][1];
                        const int ai = a == r->ncurves - 1 ? b : a;
                        r->ncurves--;
                        ic_trace_curve *c = &r->curves[ai];
                        r->storage[ai] = J;
                        c->points = J;
                        c->npoints = na + nb - 1;
                        c->ends[0] = e0;
                        c->ends[1] = e1;
                        r->at[ai][0] = at0;
                        r->at[ai][1] = at1;
                        changed = 1;
                    }
            }
    }
    for (int i = 0; i < r->ncurves; i++) {
        ic_trace_curve *c = &r->curves[i];
        c->points = r->storage[i];
        c->length = c->points[c->npoints - 1].s - c->points[0].s;
        c->shape = classify(c->points, c->npoints, c->length, shape_tol, c->tangential);
    }
    return IC_OK;
}

/* Drops a curve that runs along another, longer one all the way (traced
 * twice from two start points: it happens where one trace stopped early, at a
 * degenerate point of a parametrization, before covering the other start). */
static void drop_duplicate_arcs(ic_trace_result *r, double radius)
{
    for (int a = 0; a < r->ncurves; a++) {
        const ic_trace_curve *ca = &r->curves[a];
        int inside = 0;
        for (int b = 0; b < r->ncurves && !inside; b++) {
            const ic_trace_curve *cb = &r->curves[b];
            if (b == a || cb->length < ca->length)
                continue;
            inside = 1;
            for (int k = 0; k < ca->npoints && inside; k++) {
                ic_candidate probe;
                memset(&probe, 0, sizeof probe);
                memcpy(probe.xyz, ca->points[k].xyz, sizeof probe.xyz);
                cover(&probe, 1, cb->points, cb->npoints, radius);
                inside = probe.covered;
            }
        }
        if (!inside)
            continue;
        free(r->storage[a]);
        const int last = --r->ncurves;
        r->curves[a] = r->curves[last];
        r->storage[a] = r->storage[last];
        r->at[a][0] = r->at[last][0], r->at[a][1] = r->at[last][1];
        a--;
    }
}

/* Whether a traced curve or a recorded point passes within the cell's radius. */
static int found_near(const ic_trace_result *r, const ic_unresolved *u)
{
    for (int k = 0; k < r->nspecials; k++) {
        double d[3];
        ic_axpy3(d, r->specials[k].xyz, -1.0, u->xyz);
        if (ic_norm3(d) <= u->radius)
            return 1;
    }
    for (int c = 0; c < r->ncurves; c++) {
        ic_candidate probe;
        memset(&probe, 0, sizeof probe);
        memcpy(probe.xyz, u->xyz, sizeof probe.xyz);
        cover(&probe, 1, r->curves[c].points, r->curves[c].npoints, u->radius);
        if (probe.covered)
            return 1;
    }
    return 0;
}

/* Records a tangential point near `near`: located to full precision on the
 * collinear-normals condition (ic_local_locate_tangential, within reach) and
 * classified. Where the location fails, the point is dropped, or kept as
 * approximate when keep_unrefined. A point of a tangential curve starts the
 * trace of that curve instead (*curve: its index, else -1). */
static ic_status record_tangential(ic_trace_result *r, ic_tracer *tr, ic_pair *pair,
                                   const ic_local_point *near, double reach, int keep_unrefined,
                                   const ic_trace_options *opt, int *curve)
{
    *curve = -1;
    ic_local_point pt;
    ic_local_options lo = opt->local;
    int approximate = 0;
    if (ic_local_locate_tangential(pair, &pt, near, reach, &lo, NULL) != IC_OK) {
        if (!keep_unrefined)
            return IC_OK;
        pt = *near;
        approximate = 1;
    }
    ic_local_result res;
    if (!approximate &&
        ic_local_apparatus(pair, &res, &pt, opt->order, IC_METHOD_JET, &lo, NULL) == IC_OK &&
        res.type == IC_POINT_TANGENTIAL_CURVE && res.nbranches >= 1) {
        ic_trace_point *pts;
        int n;
        ic_error e2;
        const ic_status st = trace_curve(r, tr, pair, &pt, opt, &pts, &n, &e2);
        if (st == IC_ERR_NOMEM)
            return st;
        if (st != IC_OK) {
            failure(&r->report, "the tangential curve through (%.6g, %.6g, %.6g): %s", pt.xyz[0],
                    pt.xyz[1], pt.xyz[2], e2.message);
            return IC_OK;
        }
        *curve = r->ncurves - 1;
        ic_trace_curve *c = &r->curves[*curve];
        c->tangential = 1;
        c->shape = classify(c->points, c->npoints, c->length, opt->shape_tol, 1);
        return IC_OK;
    }
    return add_special(r, pair, &pt, approximate, opt, NULL);
}

/* Distance from x to the nearest traced curve (polyline), or INFINITY. */
static double distance_to_curves(const ic_trace_result *r, const double *x)
{
    double best = INFINITY;
    for (int c = 0; c < r->ncurves; c++) {
        const ic_trace_curve *cv = &r->curves[c];
        for (int k = 0; k + 1 < cv->npoints; k++)
            best = fmin(best, segment_distance(x, cv->points[k].xyz, cv->points[k + 1].xyz));
    }
    return best;
}

/* Every branch out of every recorded singular point is traced, even when no
 * start candidate lay on it: a point a little way along each branch (second
 * order), in both directions, that no traced curve passes near, starts a
 * curve, which then ends at the singular point and is joined through it. */
static ic_status complete_branches(ic_trace_result *r, ic_tracer *tr, ic_pair *pair,
                                   const ic_trace_options *opt)
{
    ic_local_options lo = opt->local;
    for (int k = 0; k < r->nspecials; k++) {
        if (r->specials[k].approximate || r->specials[k].nbranches < 1)
            continue;
        const ic_local_point at = r->special_pts[k];
        ic_local_result res;
        if (ic_local_apparatus(pair, &res, &at, 2, IC_METHOD_AUTO, &lo, NULL) != IC_OK)
            continue;
        for (int b = 0; b < res.nbranches; b++)
            for (int sgn = -1; sgn <= 1; sgn += 2) {
                const ic_branch *br = &res.branches[b];
                const double delta = fmin(20 * opt->chord, 0.2 / fmax(br->kappa, 1e-300));
                double q[3];
                ic_axpy3(q, at.xyz, sgn * delta, br->t);
                if (br->frame_defined)
                    ic_axpy3(q, q, 0.5 * delta * delta * br->kappa, br->n);
                if (distance_to_curves(r, q) <= 0.25 * delta)
                    continue;
                ic_local_point pt;
                ic_local_result there;
                double d[3], e[3];
                if (ic_local_locate(pair, &pt, q, &lo, NULL) != IC_OK ||
                    ic_local_apparatus(pair, &there, &pt, 2, IC_METHOD_JET, &lo, NULL) != IC_OK ||
                    there.type != IC_POINT_TRANSVERSAL)
                    continue;
                ic_axpy3(d, pt.xyz, -1.0, q);
                ic_axpy3(e, pt.xyz, -1.0, at.xyz);
                if (ic_norm3(d) > 0.25 * delta || ic_norm3(e) < 0.5 * delta)
                    continue; /* the locator went elsewhere */
                ic_trace_point *pts;
                int n;
                ic_error e2;
                const ic_status st = trace_curve(r, tr, pair, &pt, opt, &pts, &n, &e2);
                if (st == IC_ERR_NOMEM)
                    return st;
                if (st != IC_OK)
                    failure(&r->report, "branch %d out of (%.6g, %.6g, %.6g): %s", b, at.xyz[0],
                            at.xyz[1], at.xyz[2], e2.message);
            }
    }
    return IC_OK;
}

/* Looks for a tangential point in an unresolved cell: this is how isolated
 * contacts, which have no curve to lead to them, are found. */
static ic_status tangential_in_cell(ic_trace_result *r, ic_tracer *tr, ic_pair *pair,
                                    const ic_unresolved *u, const ic_trace_options *opt)
{
    int curve;
    ic_local_point near;
    memset(&near, 0, sizeof near);
    memcpy(near.xyz, u->xyz, sizeof near.xyz);
    memcpy(near.params, u->params, sizeof near.params);
    return record_tangential(r, tr, pair, &near, u->radius, 0, opt, &curve);
}

ic_status ic_trace(ic_trace_result **out, ic_pair *pair, const ic_trace_options *opt,
                   ic_error *err)
{
    *out = NULL;
    ic_trace_result *r = calloc(1, sizeof *r);
    if (!r)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory tracing");
    ic_candidate *cand = NULL;
    ic_unresolved *unres = NULL;
    int nc = 0, nu = 0;
    ic_tracer *tr = NULL;
    ic_status st = ic_trace_candidates(pair, opt, &cand, &nc, &unres, &nu, &r->report, err);
    if (st == IC_OK)
        st = ic_tracer_new(&tr, pair, opt, err);
    const double radius = 2 * opt->chord + 1e-9;
    for (int i = 0; st == IC_OK && i < nc; i++) {
        if (cand[i].covered)
            continue;
        ic_local_point pt;
        ic_local_options lo = opt->local;
        double flat[4];
        int np = 0;
        for (int s = 0; s < 2; s++)
            if (ic_surface_get_kind(ic_pair_surface(pair, s)) == IC_PARAMETRIC) {
                flat[np++] = cand[i].params[s][0];
                flat[np++] = cand[i].params[s][1];
            }
        ic_error e2;
        if ((np ? ic_local_locate_params(pair, &pt, flat, np, &lo, &e2)
                : ic_local_locate(pair, &pt, cand[i].xyz, &lo, &e2)) != IC_OK) {
            failure(&r->report, "start candidate (%g, %g, %g): %s", cand[i].xyz[0],
                    cand[i].xyz[1], cand[i].xyz[2], e2.message);
            cand[i].covered = 1;
            continue;
        }
        ic_local_result res;
        if (ic_local_apparatus(pair, &res, &pt, 2, IC_METHOD_JET, &lo, &e2) != IC_OK ||
            res.type != IC_POINT_TRANSVERSAL) {
            /* a tangential candidate: recorded (or its tangential curve
             * traced), and covered around it */
            int curve;
            st = record_tangential(r, tr, pair, &pt, 2 * r->report.cell_size + 1e-6, 1, opt, &curve);
            ic_trace_point one;
            memset(&one, 0, sizeof one);
            memcpy(one.xyz, pt.xyz, sizeof one.xyz);
            cover(cand, nc, &one, 1, fmax(radius, 2 * r->report.cell_size));
            if (curve >= 0)
                cover(cand, nc, r->curves[curve].points, r->curves[curve].npoints, radius);
            continue;
        }
        ic_trace_point *pts = NULL;
        int np2 = 0;
        st = trace_curve(r, tr, pair, &pt, opt, &pts, &np2, err);
        if (st == IC_OK)
            cover(cand, nc, pts, np2, radius);
        cand[i].covered = 1;
    }
    /* unresolved cells that nothing found passes near: a tangential point is
     * looked for in each (an isolated contact has no curve to find it by);
     * then every branch out of the singular points found so far is traced;
     * what is still far from everything found is counted */
    for (int i = 0; st == IC_OK && i < nu; i++)
        if (!found_near(r, &unres[i]))
            st = tangential_in_cell(r, tr, pair, &unres[i], opt);
    if (st == IC_OK)
        st = complete_branches(r, tr, pair, opt);
    for (int i = 0; st == IC_OK && i < nu; i++) {
        const int near = found_near(r, &unres[i]);
        if (!near && unres[i].converged_elsewhere) {
            r->report.unproven_cells++;
        } else if (!near) {
            if (r->report.uncovered_cells == 0 || r->report.uncovered_cells % 1000 == 0)
                failure(&r->report,
                        "a cell around (%.6g, %.6g, %.6g) may hold an intersection that was not "
                        "found (not excluded, no start point converged there)",
                        unres[i].xyz[0], unres[i].xyz[1], unres[i].xyz[2]);
            r->report.uncovered_cells++;
        }
    }
    if (st == IC_OK)
        drop_duplicate_arcs(r, radius);
    if (st == IC_OK && join_curves(r, opt->shape_tol) != IC_OK)
        st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory joining curves");
    ic_tracer_free(tr);
    free(cand);
    free(unres);
    if (st != IC_OK) {
        ic_trace_result_free(r);
        return st;
    }
    *out = r;
    return IC_OK;
}

void ic_trace_result_free(ic_trace_result *r)
{
    if (!r)
        return;
    for (int i = 0; i < r->ncurves; i++)
        free(r->storage[i]);
    free(r->storage);
    free(r->curves);
    free(r->at);
    free(r->specials);
    free(r->special_pts);
    free(r);
}

int ic_trace_result_num_curves(const ic_trace_result *r) { return r->ncurves; }
const ic_trace_curve *ic_trace_result_curve(const ic_trace_result *r, int i)
{
    return i >= 0 && i < r->ncurves ? &r->curves[i] : NULL;
}
int ic_trace_result_num_specials(const ic_trace_result *r) { return r->nspecials; }
const ic_trace_special *ic_trace_result_special(const ic_trace_result *r, int i)
{
    return i >= 0 && i < r->nspecials ? &r->specials[i] : NULL;
}
const ic_trace_report *ic_trace_result_report(const ic_trace_result *r) { return &r->report; }
