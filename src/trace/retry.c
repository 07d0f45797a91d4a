/*
 * The checker's refusal as the tracer's next start (docs/tracing.md,
 * "Starting again from the checker"): when the certificate is refused only
 * because some of its proven arcs carry no traced curve, a point of each
 * such arc is a point of the intersection the tracer's own search missed
 * (a small loop beside a singular point, say). The tracer marches from
 * those points as from start candidates, the curves are tidied again, and
 * the checker runs again on the new result, a few rounds at most. The
 * checker alone still decides complete.
 */
#include "certify_result.h"
#include "core/trace_constants.h"
#include "local/pair_access.h"
#include "trace_internal.h"

#include <string.h>

/* Rounds of starting again at most: each round traces every missed curve
 * the checker gave a point of (up to IC_CERTIFY_MAX_SEEDS points), so a
 * further round is needed only beyond that many missed arcs, and each one
 * costs a whole check. */
#define IC_TRACE_SEED_ROUNDS 3

/* While curves are traced a surface's singular point counts half-branches
 * (curve_ends.c), halved after the joining: back to half-branches (the
 * next halving rounds up) or halved. */
static void surface_singular_counts(ic_trace_result *r, int halve)
{
    for (int k = 0; k < r->nspecials; k++)
        if (r->specials[k].type == IC_POINT_SURFACE_SINGULAR)
            r->specials[k].nbranches =
                halve ? (r->specials[k].nbranches + 1) / 2 : 2 * r->specials[k].nbranches;
}

ic_status ic_trace_tidy_curves(ic_trace_result *r, ic_pair *pair, const ic_trace_options *opt,
                               ic_error *err)
{
    ic_status st = IC_OK;
    if (ic_trace_drop_duplicates(r, IC_TRACE_ON_CURVE * r->scale) != IC_OK)
        st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory dropping duplicate curves");
    if (st == IC_OK &&
        ic_trace_join_curves(r, pair, opt->shape_tol, IC_TRACE_POLE_GAP_CHORDS * opt->chord) !=
            IC_OK)
        st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory joining curves");
    if (st == IC_OK)
        ic_trace_drop_points_on_tangential(r, IC_TRACE_SAME_APPROX * r->scale);
    surface_singular_counts(r, 1);
    /* the curves changed: indexed anew */
    if (st == IC_OK) {
        ic_curve_index_clear(r->index);
        for (int c = 0; c < r->ncurves && st == IC_OK; c++)
            if (ic_curve_index_add(r->index, c, r->curves[c].points, r->curves[c].npoints) != 0)
                st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory");
    }
    return st;
}

/* The curves through the checker's seeds traced (and every branch out of
 * a singular point they reach), then tidied: *added 1 when anything was
 * found. */
static ic_status trace_seeds(ic_trace_result *r, ic_tracer *tr, ic_pair *pair,
                             const ic_trace_options *opt, const ic_certify_summary *s, int *added,
                             ic_error *err)
{
    const ic_pairing *pg = ic_pair_pairing(pair);
    ic_candidate cand[IC_CERTIFY_MAX_SEEDS];
    int n = 0;
    for (int i = 0; i < s->nseeds; i++) {
        ic_candidate *c = &cand[n];
        memset(c, 0, sizeof *c);
        c->seed = 1;
        pg->kind->unflatten(pg, s->seeds[i], c->params);
        ic_error e;
        if (pg->kind->position(pg, s->seeds[i], c->xyz, &e) == IC_OK)
            n++;
    }
    const int ncurves = r->ncurves, nspecials = r->nspecials;
    surface_singular_counts(r, 0);
    ic_status st = ic_trace_from_candidates(r, tr, pair, cand, n, opt, err);
    if (st == IC_OK)
        st = ic_trace_complete_branches(r, tr, pair, opt);
    *added = r->ncurves > ncurves || r->nspecials > nspecials;
    if (st == IC_OK)
        st = ic_trace_tidy_curves(r, pair, opt, err);
    return st;
}

ic_status ic_trace_certify_seeded(ic_trace_result *r, ic_tracer *tr, ic_pair *pair,
                                  const ic_trace_options *user_opt, const ic_trace_options *opt,
                                  ic_error *err)
{
    ic_trace_report *rep = &r->report;
    ic_certify_summary sum;
    ic_status st = ic_trace_certify(r, pair, user_opt, &sum, err);
    int restarts = 0;
    for (int round = 0; st == IC_OK && round < IC_TRACE_SEED_ROUNDS && !rep->complete &&
                        sum.nseeds > 0 && !ic_trace_out_of_time(&r->budget);
         round++) {
        int added = 0;
        st = trace_seeds(r, tr, pair, opt, &sum, &added, err);
        if (st != IC_OK || !added)
            break;
        restarts += sum.nseeds;
        /* a seed the tracer could not follow (a failure listed, the budget
         * spent) ends its own claim: nothing more to certify */
        if (rep->nfailures > 0 || r->budget.stopped) {
            rep->tracer_complete = 0;
            break;
        }
        rep->complete = rep->tracer_complete;
        st = ic_trace_certify(r, pair, user_opt, &sum, err);
    }
    rep->certificate.restarts = restarts;
    ic_trace_certify_verdict(r);
    return st;
}
