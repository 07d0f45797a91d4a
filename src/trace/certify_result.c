/*
 * The tracer proposes, the checker proves (docs/tracing.md, "The
 * certificate"): when the tracer found the whole intersection by its own
 * account, the certify layer covers the search region with proven cells and
 * holds the traced curves against them; complete is its verdict.
 */
#include "certify_result.h"
#include "certify/match.h"
#include "core/options.h"
#include "local/pair_access.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>


/* Every curve's points in the pairing's search coordinates (freed by the
 * caller, one block): NULL out of memory. */
static double *search_points(const ic_trace_result *r, const ic_pairing *pg,
                             ic_certify_curve *curves)
{
    const int dim = pg->kind->dim;
    size_t total = 0;
    for (int k = 0; k < r->ncurves; k++)
        total += (size_t)r->curves[k].npoints;
    double *z = malloc((total ? total : 1) * (size_t)dim * sizeof *z);
    if (!z)
        return NULL;
    size_t at = 0;
    for (int k = 0; k < r->ncurves; k++) {
        const ic_trace_curve *c = &r->curves[k];
        curves[k] = (ic_certify_curve){z + at * (size_t)dim, c->npoints, c->closed, c->tangential};
        for (int i = 0; i < c->npoints; i++, at++) {
            double p[2][2];
            memcpy(p, c->points[i].params, sizeof p);
            pg->kind->flatten(pg, c->points[i].xyz, p, z + at * (size_t)dim);
        }
    }
    return z;
}

void ic_trace_certificate_from(ic_trace_certificate *out, const ic_certify_summary *s)
{
    out->checked = 1;
    out->accepted = s->accepted;
    out->cells = s->cells, out->empty = s->empty, out->outside = s->outside;
    out->diagonal = s->diagonal, out->regular = s->regular, out->singular = s->singular;
    out->tangential = s->tangential;
    out->refused = s->refused;
    out->crossings = s->crossings, out->arcs = s->arcs;
    out->poles = s->poles, out->corners = s->corners;
    out->seconds = s->seconds;
    memcpy(out->reason, s->reason, sizeof out->reason);
}

/* Lengths and arc lengths are finite, or nothing is proven. */
static int finite_lengths(const ic_trace_result *r)
{
    for (int k = 0; k < r->ncurves; k++) {
        const ic_trace_curve *c = &r->curves[k];
        if (!isfinite(c->length))
            return 0;
        for (int i = 0; i < c->npoints; i++)
            if (!isfinite(c->points[i].s))
                return 0;
    }
    return 1;
}

/* The tangential curves' points, tubes[] and one block of points (freed by
 * the caller); *n of them. NULL out of memory. */
static double *tangential_tubes(const ic_trace_result *r, ic_certify_tube *tubes, int *n)
{
    size_t total = 0;
    for (int k = 0; k < r->ncurves; k++)
        total += r->curves[k].tangential ? (size_t)r->curves[k].npoints : 0;
    double *xyz = malloc((total + 1) * 3 * sizeof *xyz);
    size_t at = 0;
    *n = 0;
    for (int k = 0; xyz && k < r->ncurves; k++) {
        const ic_trace_curve *c = &r->curves[k];
        if (!c->tangential)
            continue;
        tubes[(*n)++] = (ic_certify_tube){xyz + 3 * at, c->npoints, c->closed};
        for (int i = 0; i < c->npoints; i++, at++)
            memcpy(xyz + 3 * at, c->points[i].xyz, 3 * sizeof *xyz);
    }
    return xyz;
}

/* The singular points' places (freed by the caller): NULL out of memory;
 * their boxes' sizes in scale (cusps, tacnodes and higher-order contacts
 * wider). */
static double (*singular_points(const ic_trace_result *r, double *scale))[3]
{
    double(*p)[3] = malloc((size_t)(r->nspecials + 1) * sizeof *p);
    for (int k = 0; p && scale && k < r->nspecials; k++) {
        memcpy(p[k], r->specials[k].xyz, sizeof p[k]);
        const ic_point_type t = r->specials[k].type;
        scale[k] = t == IC_POINT_CUSP || t == IC_POINT_TACNODE || t == IC_POINT_HIGHER_ORDER_CONTACT
                       ? IC_CERTIFY_CONTACT_SCALE
                       : 1.0;
    }
    return p;
}

ic_status ic_trace_certify(ic_trace_result *r, ic_pair *pair, const ic_trace_options *opt,
                           ic_certify_summary *sum_out, ic_error *err)
{
    ic_trace_report *rep = &r->report;
    if (sum_out)
        sum_out->nseeds = 0;
    rep->tracer_complete = rep->complete;
    free(r->certificate); /* a file of an earlier round's check */
    r->certificate = NULL;
    if (!rep->complete)
        return IC_OK;
    if (!opt->certify) {
        rep->complete = 0;
        ic_trace_failure(rep, "not proven: the certificate was switched off (certify = 0)");
        return IC_OK;
    }
    if (!finite_lengths(r)) {
        rep->complete = 0;
        ic_trace_failure(rep, "a curve's length is not a finite number: doubles cannot resolve it");
        return IC_OK;
    }
    const ic_pairing *pg = ic_pair_pairing(pair);
    const ic_certify_limits lim = ic_certify_limits_for(rep->cells, r->budget.deadline);
    ic_certify_curve *curves = malloc((size_t)(r->ncurves + 1) * sizeof *curves);
    double *z = curves ? search_points(r, pg, curves) : NULL;
    double *scale = malloc((size_t)(r->nspecials + 1) * sizeof *scale);
    double(*sing)[3] = singular_points(r, scale);
    int *passages = malloc((size_t)(r->nspecials + 1) * sizeof *passages);
    for (int k = 0; passages && k < r->nspecials; k++) {
        passages[k] = ic_certify_passages_allowed(r->specials[k].type, r->specials[k].nbranches,
                                                  r->specials[k].approximate);
    }
    ic_certify_tube *tubes = malloc((size_t)(r->ncurves + 1) * sizeof *tubes);
    int ntubes = 0;
    double *txyz = tubes ? tangential_tubes(r, tubes, &ntubes) : NULL;
    const ic_certify_claim claim = {.curves = curves,
                                    .ncurves = r->ncurves,
                                    .singular = (const double(*)[3])sing,
                                    .singular_scale = scale,
                                    .singular_passages = passages,
                                    .nsingular = r->nspecials,
                                    .tubes = tubes,
                                    .ntubes = ntubes};
    ic_certify_summary sum;
    ic_certify_io io = {.keep = opt->keep_certificate};
    ic_status st = z && sing && scale && txyz && passages
                       ? ic_certify_run(pg, opt->box, opt->has_box, &lim, &claim, &io, &sum, err)
                       : ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory certifying");
    r->certificate = io.doc;
    free(txyz);
    free(tubes);
    free(passages);
    free(sing);
    free(scale);
    free(z);
    free(curves);
    if (st == IC_OK)
        ic_trace_certificate_from(&rep->certificate, &sum);
    if (st == IC_OK && sum_out)
        *sum_out = sum;
    rep->complete = st == IC_OK && rep->certificate.accepted;
    return st;
}

void ic_trace_certify_verdict(ic_trace_result *r)
{
    ic_trace_report *rep = &r->report;
    if (rep->certificate.checked && !rep->certificate.accepted)
        ic_trace_failure(rep, "not proven by the certificate: %s", rep->certificate.reason);
}
