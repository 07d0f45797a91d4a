/*
 * The curves from the start candidates: every candidate not yet covered by
 * a traced curve starts one, traced in both directions (curve_ends.c); a
 * tangential candidate is recorded, a candidate the locator refuses at a
 * pole of a parametrization is nudged off it or deferred, and the deferred
 * ones that nothing traced passes near are listed as failures at the end.
 */
#include "common/vec3.h"
#include "core/trace_constants.h"
#include "local/pair_access.h"
#include "curve_ends.h"
#include "march_ahead.h"
#include "trace_internal.h"
#include "workers.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Marks the candidates within radius of the point x as covered. */
static void cover_point(ic_candidate *c, int n, const double *x, double radius)
{
    ic_trace_point one;
    memset(&one, 0, sizeof one);
    memcpy(one.xyz, x, sizeof one.xyz);
    ic_trace_cover(c, n, &one, 1, radius);
}

/* Traces a curve from every start candidate that no curve traced so far
 * covers; a tangential candidate is recorded (or its tangential curve
 * traced). */
static int defer_failure(ic_trace_result *r, const ic_candidate *c, const char *why)
{
    if (r->ndeferred == r->capd) {
        const int cap = r->capd ? 2 * r->capd : 8;
        ic_candidate *p = realloc(r->deferred, (size_t)cap * sizeof *p);
        if (p)
            r->deferred = p;
        char(*q)[200] = realloc(r->deferred_why, (size_t)cap * sizeof *q);
        if (q)
            r->deferred_why = q;
        if (!p || !q)
            return -1;
        r->capd = cap;
    }
    r->deferred[r->ndeferred] = *c;
    snprintf(r->deferred_why[r->ndeferred++], sizeof r->deferred_why[0], "%s", why);
    return 0;
}

/* The deferred start candidates that nothing traced passes near, listed
 * (one per place). */
void ic_trace_list_deferred(ic_trace_result *r, double radius)
{
    for (int i = 0; i < r->ndeferred; i++) {
        const double *x = r->deferred[i].xyz;
        int dup = 0;
        for (int j = 0; j < i && !dup; j++) {
            double d[3];
            ic_axpy3(d, r->deferred[j].xyz, -1.0, x);
            dup = ic_norm3(d) <= 1e-10 * (r->scale + ic_norm3(x));
        }
        double at[3];
        ic_frame_shown(&r->frame, x, at);
        if (!dup && !ic_trace_point_near_found(r, x, radius))
            ic_trace_failure(&r->report, "start candidate (%g, %g, %g): %s", at[0], at[1], at[2],
                             r->deferred_why[i]);
    }
}

/* Whether x lies within gap of a curve end that left a parameter domain
 * (at a pole of a parametrization, say): the joining bridges that gap
 * (ic_trace_join_curves, max_gap), and a curve started there would be a
 * sliver of the same curve. */
static int in_pole_gap(const ic_trace_result *r, const double *x, double gap)
{
    for (int c = 0; c < r->ncurves; c++)
        for (int e = 0; e < 2; e++) {
            const ic_trace_curve *cv = &r->curves[c];
            if (cv->closed || cv->ends[e] != IC_TRACE_LEFT_DOMAIN)
                continue;
            double d[3];
            ic_axpy3(d, cv->points[e ? cv->npoints - 1 : 0].xyz, -1.0, x);
            if (ic_norm3(d) <= gap)
                return 1;
        }
    return 0;
}

/* An exact (located) singular point within bound of x. */
static int near_exact_special(const ic_trace_result *r, const double *x, double bound)
{
    for (int k = 0; k < r->nspecials; k++) {
        double d[3];
        ic_axpy3(d, r->specials[k].xyz, -1.0, x);
        if (!r->specials[k].approximate && ic_norm3(d) <= bound)
            return 1;
    }
    return 0;
}

/* A parametric sheet degenerate at pt (R_u x R_v = 0, a pole): its
 * parameters moved IC_TRACE_POLE_NUDGE_REL of the domain along a parameter
 * to where the normal exists, and pt's position with them. 0 when no sheet
 * is degenerate there or no nudge helps. */
static int nudge_off_pole(ic_pair *pair, ic_local_point *pt)
{
    for (int s = 0; s < 2; s++) {
        ic_surface *S = ic_pair_surface(pair, s);
        ic_surface_geometry g;
        if (ic_surface_get_kind(S) != IC_PARAMETRIC ||
            ic_surface_normal_at(S, &g, pt->params[s], NULL) == IC_OK)
            continue;
        double dom[2][2];
        ic_surface_get_domain(S, dom, NULL);
        for (int k = 0; k < 4; k++) { /* +v, -v, +u, -u */
            const int i = k < 2 ? 1 : 0;
            const double width = isfinite(dom[i][1] - dom[i][0]) ? dom[i][1] - dom[i][0] : 1;
            double uv[2] = {pt->params[s][0], pt->params[s][1]}, x[3];
            uv[i] += (k % 2 ? -1 : 1) * IC_TRACE_POLE_NUDGE_REL * width;
            if (uv[i] < dom[i][0] || uv[i] > dom[i][1] ||
                ic_surface_normal_at(S, &g, uv, NULL) != IC_OK ||
                ic_surface_eval(S, x, uv, NULL) != IC_OK)
                continue;
            memcpy(pt->params[s], uv, sizeof uv);
            memcpy(pt->xyz, x, sizeof x);
            return 1;
        }
    }
    return 0;
}

/* A candidate the locator refused because a parametrisation degenerates
 * there (a contact at a sphere's pole): classified from just beside the
 * pole, as an approximate point at the candidate's place. 1 if recorded. */
static int record_at_pole(ic_trace_result *r, ic_pair *pair, const ic_candidate *c,
                          const ic_trace_options *opt, ic_status *st)
{
    ic_local_point pt;
    memset(&pt, 0, sizeof pt);
    memcpy(pt.xyz, c->xyz, sizeof pt.xyz);
    memcpy(pt.params, c->params, sizeof pt.params);
    if (!nudge_off_pole(pair, &pt))
        return 0;
    /* only a contact: curves through a pole are joined across it
     * (in_pole_gap), and nothing but the search leads to a contact */
    ic_local_options o = opt->local;
    o.tangential_angle = IC_TRACE_APPROX_TANGENTIAL_ANGLE; /* as ic_trace_add_special */
    ic_local_result res;
    if (ic_local_apparatus(pair, &res, &pt, 3, IC_METHOD_AUTO, &o, NULL) != IC_OK ||
        (res.type != IC_POINT_ISOLATED_CONTACT && res.type != IC_POINT_HIGHER_ORDER_CONTACT))
        return 0;
    int index = -1;
    *st = ic_trace_add_special(r, pair, &pt, 1, opt, &index);
    if (*st != IC_OK || index < 0)
        return 0;
    memcpy(r->specials[index].xyz, c->xyz, sizeof c->xyz);
    return 1;
}

/* A candidate the locator refused (a pole's many preimages, say):
 * recorded at the pole, or deferred with the locator's reason. */
static ic_status unlocated_candidate(ic_trace_result *r, ic_pair *pair, ic_candidate *cand,
                                     int nc, int i, const ic_trace_options *opt, const char *why,
                                     ic_error *err)
{
    /* the candidates at the same place would fail the same way: one is kept */
    cover_point(cand, nc, cand[i].xyz, 1e-10 * (r->scale + ic_norm3(cand[i].xyz)));
    cand[i].covered = 1;
    ic_status st = IC_OK;
    if (record_at_pole(r, pair, &cand[i], opt, &st)) {
        cover_point(cand, nc, cand[i].xyz, fmax(2 * opt->chord, 2 * r->report.cell_size));
        return st;
    }
    if (st == IC_OK && defer_failure(r, &cand[i], why) != 0)
        st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory");
    return st;
}

/* A tangential candidate: recorded (or its tangential curve traced), and
 * covered around it; beside a singular point already located (a finer
 * search's Newton lands there) it is that point. */
static ic_status tangential_candidate(ic_trace_result *r, ic_tracer *tr, ic_pair *pair,
                                      ic_candidate *cand, int nc, const ic_local_point *pt,
                                      const ic_trace_options *opt, ic_error *err)
{
    const double radius = IC_TRACE_ON_CURVE * r->scale;
    const double near_point = 2 * opt->chord; /* beside a singular point */
    if (near_exact_special(r, pt->xyz, fmax(near_point, 2 * r->first_cell_size)) ||
        ic_trace_in_coincident(r, pt->xyz))
        return IC_OK;
    /* surfaces that coincide around it: a region, not a point */
    if (ic_trace_coincident_at(pair, pt, r->scale))
        return ic_trace_add_coincident(r, pt->xyz) != 0
                   ? ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory")
                   : IC_OK;
    int curve;
    /* within about a first-search cell (in space) */
    const double reach = 4 * r->scale / (1 << opt->depth) + 1e-7 * r->scale;
    const ic_status st = ic_trace_record_tangential(r, tr, pair, pt, reach, 1, opt, &curve);
    cover_point(cand, nc, pt->xyz, fmax(near_point, 2 * r->report.cell_size));
    if (curve >= 0)
        ic_trace_cover(cand, nc, r->curves[curve].points, r->curves[curve].npoints, radius);
    return st;
}

/* The curve through candidate i marched ahead or, if it was not, here. */
static ic_status trace_candidate(ic_trace_result *r, ic_tracer *tr, ic_pair *pair,
                                 const ic_local_point *pt, ic_trace_ahead *ahead,
                                 const ic_trace_options *opt, ic_trace_point **pts, int *n,
                                 ic_error *err)
{
    if (!ahead || !ahead->valid)
        return ic_trace_both_ways(r, tr, pair, pt, opt, pts, n, err);
    const ic_status st = ic_trace_add_marches(r, pair, pt, opt, &ahead->m, pts, n, err);
    ic_trace_marches_free(&ahead->m);
    ahead->valid = 0;
    return st;
}

ic_status ic_trace_from_candidates(ic_trace_result *r, ic_tracer *tr, ic_pair *pair,
                                   ic_candidate *cand, int nc, const ic_trace_options *opt,
                                   ic_error *err)
{
    /* a start candidate is a point of the intersection (Newton converged
     * there): it lies on a traced curve when within the curve's sagitta
     * (ic_trace_polyline_distance) and this fraction of L. A wider radius
     * would take a second curve beside the first for the first. */
    const double radius = IC_TRACE_ON_CURVE * r->scale;
    /* with threads, candidates marched ahead (none where this fails) */
    ic_trace_ahead *ahead = r->workers && nc > 1 ? calloc((size_t)nc, sizeof *ahead) : NULL;
    int used = 0, lost = 0;
    ic_status st = IC_OK;
    for (int i = 0; st == IC_OK && i < nc; i++) {
        /* a seed lies on an arc no curve met: never a sliver in a pole's gap
         * (in a strip narrower than the gap every curve end is near) */
        if (cand[i].covered || ic_trace_point_near_found(r, cand[i].xyz, radius) ||
            (!cand[i].seed &&
             in_pole_gap(r, cand[i].xyz, IC_TRACE_POLE_GAP_CHORDS * opt->chord))) {
            lost += ahead && ahead[i].valid;
            continue;
        }
        if (ic_trace_out_of_time(&r->budget))
            break;
        ic_trace_progress(r, opt, "tracing start points", i, nc);
        if (ahead && !ahead[i].done)
            ic_trace_march_ahead(r, pair, opt, cand, nc, i, used, lost, ahead);
        ic_local_point pt;
        ic_local_options lo = opt->local;
        ic_error e2;
        ic_local_result res;
        if (ahead && ahead[i].valid) /* located and transversal */
            pt = ahead[i].pt, used++;
        else if (ic_local_locate_guess(pair, &pt, cand[i].xyz, cand[i].params, &lo, &e2) != IC_OK) {
            st = unlocated_candidate(r, pair, cand, nc, i, opt, e2.message, err);
            continue;
        } else if (ic_local_apparatus(pair, &res, &pt, 2, IC_METHOD_JET, &lo, &e2) != IC_OK ||
                   res.type != IC_POINT_TRANSVERSAL) {
            st = tangential_candidate(r, tr, pair, cand, nc, &pt, opt, err);
            continue;
        }
        ic_trace_point *pts = NULL;
        int np2 = 0;
        st = trace_candidate(r, tr, pair, &pt, ahead ? &ahead[i] : NULL, opt, &pts, &np2, err);
        if (st == IC_OK && np2 > 0)
            ic_trace_cover(cand, nc, pts, np2, radius);
        cand[i].covered = 1;
    }
    for (int i = 0; ahead && i < nc; i++)
        ic_trace_marches_free(&ahead[i].m);
    free(ahead);
    return st;
}
