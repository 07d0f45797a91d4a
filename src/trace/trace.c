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
    int ncurves, capc;
    ic_trace_special *specials;
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
static ic_shape classify(const ic_trace_point *p, int n, double length, double tol)
{
    double kmax = 0, kmin = INFINITY, tmax = -INFINITY, tmin = INFINITY, rmax = -INFINITY,
           rmin = INFINITY;
    int framed = 0;
    for (int i = 0; i < n; i++) {
        if (p[i].angle < SHAPE_MIN_ANGLE)
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
                             int approximate, const ic_trace_options *opt)
{
    for (int i = 0; i < r->nspecials; i++) {
        double d[3];
        ic_axpy3(d, r->specials[i].xyz, -1.0, pt->xyz);
        if (ic_norm3(d) < 1e-3) /* the same point met from another curve */
            return IC_OK;
    }
    if (r->nspecials == r->caps) {
        const int cap = r->caps ? 2 * r->caps : 8;
        ic_trace_special *p = realloc(r->specials, (size_t)cap * sizeof *p);
        if (!p)
            return IC_ERR_NOMEM;
        r->specials = p;
        r->caps = cap;
    }
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
                           ic_trace_event e0, ic_trace_event e1, double shape_tol)
{
    if (r->ncurves == r->capc) {
        const int cap = r->capc ? 2 * r->capc : 8;
        ic_trace_curve *c = realloc(r->curves, (size_t)cap * sizeof *c);
        ic_trace_point **s = realloc(r->storage, (size_t)cap * sizeof *s);
        if (c)
            r->curves = c;
        if (s)
            r->storage = s;
        if (!c || !s)
            return IC_ERR_NOMEM;
        r->capc = cap;
    }
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
    c->shape = classify(pts, n, c->length, shape_tol);
    return IC_OK;
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
    const int n1 = ic_tracer_num_points(tr);
    ic_trace_point *fwd = malloc((size_t)n1 * sizeof *fwd);
    if (!fwd)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory");
    memcpy(fwd, ic_tracer_point(tr, 0), (size_t)n1 * sizeof *fwd);
    if (e1 == IC_TRACE_TANGENTIAL) {
        ic_local_point end = *pt;
        memcpy(end.xyz, fwd[n1 - 1].xyz, sizeof end.xyz);
        memcpy(end.params, fwd[n1 - 1].params, sizeof end.params);
        add_special(r, pair, &end, 1, opt);
    }
    if (e1 == IC_TRACE_CLOSED) {
        *pts_out = fwd;
        *n_out = n1;
        return add_curve(r, fwd, n1, 1, e1, e1, opt->shape_tol);
    }
    st = ic_tracer_start(tr, pt, -1, err);
    if (st == IC_OK)
        st = ic_tracer_run(tr, &e0, err);
    if (st != IC_OK)
        failure(&r->report, "curve from (%g, %g, %g), backwards: %s", pt->xyz[0], pt->xyz[1],
                pt->xyz[2], err ? err->message : "failed");
    const int n0 = ic_tracer_num_points(tr);
    ic_trace_point *all = malloc((size_t)(n0 + n1 - 1) * sizeof *all);
    if (!all) {
        free(fwd);
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory");
    }
    /* the backward part reversed: order, orientation (t, b) and arc length */
    const double S0 = ic_tracer_point(tr, n0 - 1)->s;
    for (int i = 0; i < n0; i++) {
        ic_trace_point p = *ic_tracer_point(tr, n0 - 1 - i);
        ic_scale3(p.t, p.t, -1.0);
        ic_scale3(p.b, p.b, -1.0);
        p.s = S0 - p.s;
        all[i] = p;
    }
    for (int i = 1; i < n1; i++) {
        all[n0 - 1 + i] = fwd[i];
        all[n0 - 1 + i].s += S0;
    }
    if (e0 == IC_TRACE_TANGENTIAL) {
        ic_local_point end = *pt;
        memcpy(end.xyz, all[0].xyz, sizeof end.xyz);
        memcpy(end.params, all[0].params, sizeof end.params);
        add_special(r, pair, &end, 1, opt);
    }
    free(fwd);
    *pts_out = all;
    *n_out = n0 + n1 - 1;
    return add_curve(r, all, n0 + n1 - 1, 0, e0, e1, opt->shape_tol);
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
            /* a tangential candidate: recorded, and covered around it */
            st = add_special(r, pair, &pt, 0, opt);
            ic_trace_point one;
            memset(&one, 0, sizeof one);
            memcpy(one.xyz, pt.xyz, sizeof one.xyz);
            cover(cand, nc, &one, 1, fmax(radius, 2 * r->report.cell_size));
            continue;
        }
        ic_trace_point *pts = NULL;
        int np2 = 0;
        st = trace_curve(r, tr, pair, &pt, opt, &pts, &np2, err);
        if (st == IC_OK)
            cover(cand, nc, pts, np2, radius);
        cand[i].covered = 1;
    }
    /* unresolved cells that nothing found passes near */
    for (int i = 0; st == IC_OK && i < nu; i++) {
        int near = 0;
        for (int k = 0; k < r->nspecials && !near; k++) {
            double d[3];
            ic_axpy3(d, r->specials[k].xyz, -1.0, unres[i].xyz);
            near = ic_norm3(d) <= unres[i].radius;
        }
        for (int c = 0; c < r->ncurves && !near; c++) {
            ic_candidate probe;
            memset(&probe, 0, sizeof probe);
            memcpy(probe.xyz, unres[i].xyz, sizeof probe.xyz);
            cover(&probe, 1, r->curves[c].points, r->curves[c].npoints, unres[i].radius);
            near = probe.covered;
        }
        if (!near) {
            if (r->report.uncovered_cells == 0 || r->report.uncovered_cells % 1000 == 0)
                failure(&r->report,
                        "a cell around (%.6g, %.6g, %.6g) may hold an intersection that was not "
                        "found (not excluded, no start point converged there)",
                        unres[i].xyz[0], unres[i].xyz[1], unres[i].xyz[2]);
            r->report.uncovered_cells++;
        }
    }
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
    free(r->specials);
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
