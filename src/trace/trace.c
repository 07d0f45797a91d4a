/*
 * The whole intersection (ic_trace), the pipeline alone: the exact paths
 * first (exact/exact.h); else the first search for start candidates and the
 * scale of what it found, the curves from the candidates (candidates.c), the
 * tangential points in the open cells and every branch out of the singular
 * points (singular.c), the refinement of the open cells (resolve.c), the
 * joining (join.c), and the report's verdict.
 */
#include "common/args.h"
#include "certify_result.h"
#include "core/trace_constants.h"
#include "exact/exact.h"
#include "frame.h"
#include "trace_internal.h"
#include "march_ahead.h"
#include "workers.h"
#include "local/pair_access.h"

#include <stdlib.h>
#include <string.h>

/* The dimension of the search space of the pair: 3 (x, y, z), 2 (u, v)
 * or 4 (u, v, p, q). */
static int search_dim(ic_pair *pair) { return ic_pair_pairing(pair)->kind->dim; }

/* complete: the search was proven, every cell decided, nothing failed and
 * no work limit was reached (docs/tracing.md, "Completeness"). */
static void set_complete(ic_trace_result *r)
{
    const ic_trace_report *rep = &r->report;
    r->report.complete = rep->proven && rep->nfailures == 0 && !r->budget.stopped &&
                         rep->uncovered_cells == 0 && rep->unproven_cells == 0 &&
                         rep->undecided_loop_cells == 0 && rep->coincident_cells == 0;
}

/* What the general path carries from stage to stage. The first search
 * runs with the options made absolute at the problem's size L0
 * (ic_trace_problem_scale); everything after it at the size L1 of what
 * that search found (ic_trace_found_scale): the report gives both
 * (search_scale, scale). */
typedef struct {
    ic_trace_options search_opt; /* absolute at L0 */
    ic_trace_options opt;        /* absolute at L1 */
    ic_candidate *cand;
    int nc;
    ic_unresolved *unres;
    int nu;
    ic_tracer *tr;
} pipeline;

/* The first search for start candidates over the whole region, then the
 * scale of the rest and what it needs: the curve index and the tracer. */
static ic_status first_search(ic_trace_result *r, ic_pair *pair, const ic_trace_options *user_opt,
                              pipeline *p, ic_error *err)
{
    const ic_trace_options *opt = &p->search_opt;
    if (opt->time_limit > 0)
        r->budget.deadline = ic_trace_now() + opt->time_limit;
    ic_status st = ic_trace_workers_new(&r->workers, pair, ic_trace_thread_count(opt->threads), err);
    if (st == IC_OK)
        st = ic_trace_candidates(pair, opt, NULL, r->workers, NULL, &p->cand, &p->nc, &p->unres,
                                 &p->nu, &r->report, &r->budget, err);
    r->first_cell_size = r->report.cell_size;
    /* the scale of the rest: where the first search left the intersection
     * (a parametric surface may reach far beyond it) */
    r->scale = ic_trace_found_scale(r->scale, p->cand, p->nc, p->unres, p->nu);
    p->opt = ic_trace_absolute_options(user_opt, r->scale);
    r->index = ic_curve_index_new(IC_TRACE_INDEX_CELL * r->scale);
    if (st == IC_OK && !r->index)
        st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory tracing");
    if (st == IC_OK)
        st = ic_tracer_new_absolute(&p->tr, pair, &p->opt, err);
    if (st == IC_OK)
        ic_tracer_set_deadline(p->tr, r->budget.deadline);
    return st;
}

/* The curves from the start candidates; then the open cells that nothing
 * found passes near: a tangential point is looked for in each (an isolated
 * contact has no curve to find it by); every branch out of the singular
 * points found is traced; then every open cell is refined until decided. */
static ic_status trace_found(ic_trace_result *r, ic_pair *pair, pipeline *p, ic_error *err)
{
    const ic_trace_options *opt = &p->opt;
    ic_status st = ic_trace_from_candidates(r, p->tr, pair, p->cand, p->nc, opt, err);
    for (int i = 0; st == IC_OK && i < p->nu && !ic_trace_out_of_time(&r->budget); i++) {
        const ic_unresolved *u = &p->unres[i];
        /* a loop-free cell has N_A x N_B != 0 throughout (or grad F != 0):
         * no tangential point there (the pairing's loop test) */
        if ((u->loop || !r->report.proven) && !u->has_candidate && u->radius > 0 &&
            !ic_trace_found_near(r, u))
            st = ic_trace_tangential_in_cell(r, p->tr, pair, u, opt);
    }
    if (st == IC_OK)
        st = ic_trace_complete_branches(r, p->tr, pair, opt);
    if (st == IC_OK)
        st = ic_trace_resolve_cells(r, p->tr, pair, opt, &p->unres, &p->nu, err);
    if (st == IC_OK)
        st = ic_trace_complete_branches(r, p->tr, pair, opt);
    return st;
}

/* The curves traced twice dropped, the rest joined through the singular
 * points at their ends and indexed anew; the deferred candidates and the
 * cells still open listed. */
static ic_status finish(ic_trace_result *r, ic_pair *pair, pipeline *p, ic_status st,
                        ic_error *err)
{
    const ic_trace_options *opt = &p->opt;
    if (st == IC_OK)
        st = ic_trace_tidy_curves(r, pair, opt, err);
    /* after joining: the arcs meeting at a pole of a parametrization are
     * bridged there, and the cells around the pole are near the bridge */
    if (st == IC_OK) {
        ic_trace_list_deferred(r, IC_TRACE_DEFERRED_CHORDS * opt->chord);
        ic_trace_report_open_cells(r, p->unres, p->nu, search_dim(pair));
    }
    set_complete(r);
    return st;
}

/* A new result at the problem's size L0, the options checked. */
static ic_status new_result(ic_trace_result **out, ic_pair *pair, const ic_trace_options *user_opt,
                            ic_error *err)
{
    *out = NULL;
    const ic_status valid = ic_trace_check_options(user_opt, err);
    if (valid != IC_OK)
        return valid;
    ic_trace_result *r = calloc(1, sizeof *r);
    if (!r)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory tracing");
    r->budget.cells_left = IC_TRACE_MAX_CELLS;
    r->scale = ic_trace_problem_scale(pair, user_opt);
    r->report.search_scale = r->scale;
    r->report.method = ic_trace_method_search;
    r->frame = ic_pair_pairing(pair)->frame;
    *out = r;
    return IC_OK;
}

/* The general path: search, march, singular points, refinement, joining. */
static ic_status general_path(ic_trace_result *r, ic_pair *pair, const ic_trace_options *user_opt,
                              ic_error *err)
{
    pipeline p;
    memset(&p, 0, sizeof p);
    /* every length below is absolute: the user's fractions times L */
    p.search_opt = ic_trace_absolute_options(user_opt, r->scale);
    ic_status st = first_search(r, pair, user_opt, &p, err);
    if (st == IC_OK)
        st = trace_found(r, pair, &p, err);
    st = finish(r, pair, &p, st, err);
    if (st == IC_OK) /* the tracer proposes, the checker proves */
        st = ic_trace_certify_seeded(r, p.tr, pair, user_opt, &p.opt, err);
    ic_tracer_free(p.tr);
    ic_trace_workers_free(r->workers);
    r->workers = NULL;
    free(p.cand);
    free(p.unres);
    return st;
}

static ic_status trace(ic_trace_result **out, ic_pair *pair, const ic_trace_options *user_opt,
                       ic_error *err)
{
    *out = NULL;
    ic_trace_result *r;
    ic_status st = new_result(&r, pair, user_opt, err);
    if (st != IC_OK)
        return st;
    int exact = 0;
    st = ic_trace_exact(r, pair, user_opt, &exact, err);
    if (st == IC_OK && !exact)
        st = general_path(r, pair, user_opt, err);
    else if (st == IC_OK) { /* the tracer proposes, the checker proves */
        st = ic_trace_certify(r, pair, user_opt, NULL, err);
        ic_trace_certify_verdict(r);
    }
    if (st != IC_OK) {
        ic_trace_result_free(r);
        return st;
    }
    /* the size the rest used: what the first search, or the closed form, found */
    r->report.scale = r->scale;
    *out = r;
    return IC_OK;
}

/* Out of memory ends the trace, wherever it struck: the searches and the
 * march try another way after a failed step, so it is asked of the pair at
 * the end (ic_pair_nomem_check; tests/test_nomem.c). */
ic_status ic_trace(ic_trace_result **out, ic_pair *pair, const ic_trace_options *user_opt,
                   ic_error *err)
{
    IC_ARG_NOT_NULL(out, "res");
    IC_ARG_NOT_NULL(pair, "pair");
    IC_ARG_NOT_NULL(user_opt, "opt");
    *out = NULL;
    /* the options as the user gave them (a bad box named in their numbers) */
    ic_status st = ic_trace_check_options(user_opt, err);
    if (st != IC_OK)
        return st;
    /* far from the origin: traced moved near it, the result moved back */
    ic_trace_moved m;
    st = ic_trace_move(&m, pair, user_opt->box, user_opt->has_box, err);
    if (st != IC_OK)
        return st;
    ic_trace_options opt = *user_opt;
    if (m.pair && opt.has_box)
        memcpy(opt.box, m.box, sizeof opt.box);
    ic_pair *traced = m.pair ? m.pair : pair;
    const long before = ic_pair_nomem_count(traced);
    st = ic_pair_nomem_check(traced, before, trace(out, traced, &opt, err), err);
    if (st == IC_OK)
        ic_trace_result_move_back(*out, &m.frame);
    ic_trace_moved_release(&m);
    if (st == IC_ERR_NOMEM) {
        ic_trace_result_free(*out);
        *out = NULL;
        if (err && err->code != IC_ERR_NOMEM) /* a stage that said nothing */
            ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory tracing");
    }
    return st;
}
