/*
 * Deciding every cell the first search left open (docs/tracing.md,
 * "Completeness"). A leaf that interval arithmetic did not exclude is
 * decided when
 *  - the loop test proves it loop-free and a start point was found in it or
 *    something traced passes within its radius (loop-free and covered), or
 *  - it fails the loop test but holds a located singular point or a traced
 *    tangential curve, IC_TRACE_EXPLAIN_LEVELS below the first search
 *    (explained by that point's local analysis: the loop test cannot
 *    succeed where N_A x N_B vanishes).
 * Any other is subdivided, its new start points traced, adaptively (not to
 * a fixed depth), until decided or IC_TRACE_MAX_REFINE_LEVELS deep or out of
 * budget. What is left undecided is merged into regions, each listed in the
 * report's failures with its box and reason, and the result is not complete.
 */
#define _POSIX_C_SOURCE 200809L
#include "core/trace_constants.h"
#include "trace_internal.h"
#include "workers.h"
#include "common/vec3.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* A located singular point, a traced tangential curve, or a degenerate
 * point of a parametrization (a pole) that a traced curve passes, within
 * the cell's radius, once the cell is IC_TRACE_EXPLAIN_LEVELS deep. */
static int explained(const ic_trace_result *r, const ic_unresolved *u)
{
    if (u->level < IC_TRACE_EXPLAIN_LEVELS || !(u->radius > 0))
        return 0;
    if (u->degenerate && ic_trace_found_near(r, u))
        return 1;
    for (int k = 0; k < r->nspecials; k++) {
        double d[3];
        ic_axpy3(d, r->specials[k].xyz, -1.0, u->xyz);
        if (!r->specials[k].approximate && ic_norm3(d) <= u->radius)
            return 1;
    }
    for (int c = 0; c < r->ncurves; c++)
        if (r->curves[c].tangential &&
            ic_trace_polyline_distance(r->curves[c].points, r->curves[c].npoints, u->xyz,
                                       u->radius) <= u->radius)
            return 1;
    return 0;
}

static int decided(const ic_trace_result *r, const ic_unresolved *u)
{
    if (u->radius > 0 && ic_trace_in_coincident(r, u->xyz))
        return 0; /* a region of its own: never refined, listed */
    const int covered = u->radius > 0 && ic_trace_found_near(r, u);
    if (!r->report.proven) /* sampled only: nothing is proven anyway */
        return u->has_candidate || covered;
    if (!u->loop)
        return u->has_candidate || covered;
    return explained(r, u);
}

/* The open cells, and beside each the finer search done ahead for it by
 * the trace's threads (NULL: none yet; only with threads). */
typedef struct {
    ic_unresolved *u;
    ic_search_part **ahead;
    int n, cap;
} cell_stack;

static int push(cell_stack *s, const ic_unresolved *u, int n)
{
    if (n == 0)
        return 0;
    if (s->n + n > s->cap) {
        const int cap = 2 * (s->n + n) + 64;
        ic_unresolved *p = realloc(s->u, (size_t)cap * sizeof *p);
        if (!p)
            return -1;
        s->u = p;
        ic_search_part **a = s->ahead ? realloc(s->ahead, (size_t)cap * sizeof *a) : NULL;
        if (s->ahead && !a)
            return -1;
        s->ahead = a;
        for (int i = s->cap; a && i < cap; i++)
            a[i] = NULL;
        s->cap = cap;
    }
    memcpy(s->u + s->n, u, (size_t)n * sizeof *u);
    s->n += n;
    return 0;
}

/* One cell one level finer: its start points traced, its loop cells that
 * nothing passes near searched for an isolated contact, its open children
 * pushed on the stack. */
static ic_status refine(ic_trace_result *r, ic_tracer *tr, ic_pair *pair,
                        const ic_trace_options *opt, const ic_unresolved *u,
                        ic_search_part *ahead, cell_stack *work, ic_error *err)
{
    ic_candidate *cand = NULL;
    ic_unresolved *sub = NULL;
    int nc = 0, ns = 0;
    r->report.refined_cells++;
    ic_status st = ic_trace_candidates(pair, opt, u, NULL, ahead, &cand, &nc, &sub, &ns,
                                       &r->report, &r->budget, err);
    if (st == IC_OK)
        st = ic_trace_from_candidates(r, tr, pair, cand, nc, opt, err);
    for (int i = 0; st == IC_OK && i < ns; i++)
        if (sub[i].loop && !sub[i].has_candidate && sub[i].radius > 0 &&
            !ic_trace_found_near(r, &sub[i]))
            st = ic_trace_tangential_in_cell(r, tr, pair, &sub[i], opt);
    if (st == IC_OK && push(work, sub, ns) != 0)
        st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory");
    /* their finer searches done ahead, if any (matched to their cells when
     * taken: a part for another cell is never used) */
    for (int i = 0; st == IC_OK && work->ahead && i < ns; i++)
        work->ahead[work->n - ns + i] = ic_search_part_take_child(ahead, i);
    free(cand);
    free(sub);
    return st;
}

/* Whether an undecided cell is refined (not listed as it is); b: the
 * trace's budget, or a copy of it to ask without stopping the trace. */
static int can_refine(const ic_trace_result *r, const ic_unresolved *u, ic_trace_budget *b)
{
    return !u->overflow && !(u->radius > 0 && ic_trace_in_coincident(r, u->xyz)) &&
           r->report.proven && u->level < IC_TRACE_MAX_REFINE_LEVELS && !b->stopped &&
           !ic_trace_out_of_time(b);
}

/* ic_search_wanted: an open cell found ahead that will be refined, if
 * nothing is traced meanwhile. */
static int wanted(const void *ctx, const ic_unresolved *u)
{
    const ic_trace_result *r = ctx;
    ic_trace_budget b = r->budget;
    return !decided(r, u) && can_refine(r, u, &b);
}

/* Cells refined ahead in one batch, per thread: enough to share the work,
 * few enough that little is lost when a curve traced meanwhile decides
 * some of them. */
#define AHEAD_PER_THREAD 8

/* The finer searches of the top cells of the stack that are to be refined
 * now, done ahead by the threads: the cell just popped from slot `at`
 * first, then the ones below it. */
static void refine_ahead(const ic_trace_result *r, ic_pair *pair, const ic_trace_options *opt,
                         cell_stack *work, int at)
{
    enum { MOST = AHEAD_PER_THREAD * IC_TRACE_MAX_THREADS };
    const int want = AHEAD_PER_THREAD * ic_trace_workers_count(r->workers);
    const ic_unresolved *cells[MOST];
    int slot[MOST], n = 0;
    ic_trace_budget b = r->budget;
    for (int i = at; i >= 0 && n < want; i--)
        if (i == at || (!work->ahead[i] && !decided(r, &work->u[i]) &&
                        can_refine(r, &work->u[i], &b)))
            cells[n] = &work->u[i], slot[n++] = i;
    ic_search_part *parts[MOST];
    ic_search_ahead_cells(r->workers, pair, opt, r->report.proven, cells, n, wanted, r, &r->budget,
                          parts);
    for (int k = 0; k < n; k++)
        work->ahead[slot[k]] = parts[k];
}

ic_status ic_trace_resolve_cells(ic_trace_result *r, ic_tracer *tr, ic_pair *pair,
                                 const ic_trace_options *opt, ic_unresolved **cells, int *n,
                                 ic_error *err)
{
    cell_stack work = {*cells, NULL, *n, *n}, open = {0};
    *cells = NULL;
    *n = 0;
    ic_status st = IC_OK;
    if (r->workers && work.cap > 0 && !(work.ahead = calloc((size_t)work.cap, sizeof *work.ahead)))
        st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory");
    long done = 0;
    while (st == IC_OK && work.n > 0) {
        ic_trace_progress(r, opt, "refining open cells", done, done + work.n);
        done++;
        const ic_unresolved u = work.u[--work.n];
        /* the slot's part is taken now: refine's children reuse the slot */
        ic_search_part *ahead = work.ahead ? work.ahead[work.n] : NULL;
        if (work.ahead)
            work.ahead[work.n] = NULL;
        const int open_cell = !decided(r, &u);
        if (open_cell && can_refine(r, &u, &r->budget)) {
            if (work.ahead && !ahead) {
                refine_ahead(r, pair, opt, &work, work.n);
                ahead = work.ahead[work.n];
                work.ahead[work.n] = NULL;
            }
            st = refine(r, tr, pair, opt, &u, ahead, &work, err);
        } else if (open_cell && push(&open, &u, 1) != 0)
            st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory");
        ic_search_part_free(ahead);
    }
    for (int i = 0; work.ahead && i < work.n; i++)
        ic_search_part_free(work.ahead[i]);
    free(work.ahead);
    free(work.u);
    if (st != IC_OK) {
        free(open.u);
        return st;
    }
    *cells = open.u;
    *n = open.n;
    return IC_OK;
}

/* ---- what is left: counted, merged into regions, listed ---- */

enum {
    WHY_LOOP = 1,
    WHY_ELSEWHERE = 2,
    WHY_NOTHING = 4,
    WHY_UNPLACED = 8,
    WHY_SAMPLED = 16,
    WHY_COINCIDENT = 32,
    WHY_OVERFLOW = 64
};

typedef struct {
    double lo[4], hi[4];
    int cells, why;
} region;

static int why_open(const ic_trace_result *r, const ic_unresolved *u)
{
    if (r->budget.stopped == IC_TRACE_STOP_TIME)
        return WHY_UNPLACED;
    if (u->radius > 0 && ic_trace_in_coincident(r, u->xyz))
        return WHY_COINCIDENT;
    if (!r->report.proven)
        return WHY_SAMPLED;
    if (u->overflow)
        return WHY_OVERFLOW;
    if (!(u->radius > 0))
        return WHY_UNPLACED;
    if (u->loop && u->has_candidate)
        return WHY_LOOP;
    if (u->converged_elsewhere)
        return WHY_ELSEWHERE;
    return u->loop ? WHY_LOOP : WHY_NOTHING;
}

static int touches(const region *g, const ic_unresolved *u, int dim)
{
    for (int k = 0; k < dim; k++) {
        const double w = u->hi[k] - u->lo[k];
        if (u->lo[k] > g->hi[k] + w || u->hi[k] < g->lo[k] - w)
            return 0;
    }
    return 1;
}

static void grow(const ic_trace_result *r, region *g, const ic_unresolved *u, int dim)
{
    for (int k = 0; k < dim; k++) {
        g->lo[k] = fmin(g->lo[k], u->lo[k]);
        g->hi[k] = fmax(g->hi[k], u->hi[k]);
    }
    g->cells++;
    g->why |= why_open(r, u);
}

/* Greedy merging: a cell joins the first region it touches (within a cell
 * width); past IC_TRACE_MAX_REGIONS regions it joins the last one. */
static int merge_regions(const ic_trace_result *r, const ic_unresolved *u, int n, int dim,
                         region *g)
{
    int ng = 0;
    for (int i = 0; i < n; i++) {
        int j = 0;
        while (j < ng && !touches(&g[j], &u[i], dim))
            j++;
        if (j == ng && ng < IC_TRACE_MAX_REGIONS) {
            memcpy(g[ng].lo, u[i].lo, sizeof g[ng].lo);
            memcpy(g[ng].hi, u[i].hi, sizeof g[ng].hi);
            g[ng].cells = 0, g[ng].why = 0;
            ng++;
        } else if (j == ng)
            j = ng - 1;
        grow(r, &g[j], &u[i], dim);
    }
    return ng;
}

static const char *why_text(int why)
{
    if (why & WHY_COINCIDENT)
        return "the surfaces coincide there: a region of both, not a curve";
    if (why & WHY_OVERFLOW)
        return "the surfaces' values overflow double precision there (or a pole)";
    if (why & WHY_SAMPLED)
        return "sampled only: a surface has no interval evaluation, nothing was excluded";
    if (why & WHY_UNPLACED)
        return "not examined (the work budget ran out) or not evaluable there";
    if (why & WHY_LOOP)
        return "a closed curve may hide there: the loop test failed down to the finest cells";
    if (why & WHY_NOTHING)
        return "a curve may pass there unfound: not excluded, no start point converged";
    return "not excluded: Newton converged only outside these cells";
}

static void list_region(ic_trace_result *r, const region *g, int dim)
{
    static const char *const coords[3] = {"(x, y, z)", "(u, v)", "(u, v, p, q)"};
    ic_trace_report *rep = &r->report;
    char box[160];
    int len = 0;
    for (int k = 0; k < dim && len < (int)sizeof box; k++) {
        const double o = ic_frame_search_origin(&r->frame, dim, k);
        /* far out, the digits that tell the cells apart come after the place's */
        const int digits = r->frame.moved ? 13 : 6;
        len += snprintf(box + len, sizeof box - (size_t)len, "%s[%.*g, %.*g]", k ? " x " : "",
                        digits, g->lo[k] + o, digits, g->hi[k] + o);
    }
    ic_trace_failure(rep, "undecided: %d cell%s in %s %s: %s", g->cells, g->cells == 1 ? "" : "s",
                     coords[dim == 3 ? 0 : dim == 2 ? 1 : 2], box, why_text(g->why));
}

/* 1 when the cell counts as open in the report; past the time limit every
 * cell left does, unexamined (deciding them costs what the limit forbids). */
static int still_open(const ic_trace_result *r, const ic_unresolved *u)
{
    return r->budget.stopped == IC_TRACE_STOP_TIME || !decided(r, u);
}

void ic_trace_report_open_cells(ic_trace_result *r, const ic_unresolved *u, int n, int dim)
{
    ic_trace_report *rep = &r->report;
    int left = 0;
    for (int i = 0; i < n; i++) {
        if (!still_open(r, &u[i]))
            continue;
        const int why = why_open(r, &u[i]);
        rep->undecided_loop_cells += why == WHY_LOOP || why == WHY_UNPLACED || why == WHY_OVERFLOW;
        rep->unproven_cells += why == WHY_ELSEWHERE;
        rep->uncovered_cells += why == WHY_NOTHING || why == WHY_SAMPLED;
        rep->coincident_cells += why == WHY_COINCIDENT;
        left++;
    }
    if (!rep->proven)
        ic_trace_failure(rep, "sampled only: a surface has no interval evaluation (a callback), "
                              "so nothing was proven");
    if (r->budget.stopped == IC_TRACE_STOP_TIME)
        ic_trace_failure(rep, "stopped at the time limit: the search and the curves are cut short");
    else if (r->budget.stopped == IC_TRACE_STOP_CELLS)
        ic_trace_failure(rep, "stopped at the work limit of %ld search cells", IC_TRACE_MAX_CELLS);
    if (left == 0)
        return;
    ic_unresolved *open = malloc((size_t)left * sizeof *open);
    region *g = malloc(IC_TRACE_MAX_REGIONS * sizeof *g);
    if (!open || !g) {
        ic_trace_failure(rep, "undecided: %d cells (out of memory listing them)", left);
        free(open);
        free(g);
        return;
    }
    int k = 0;
    for (int i = 0; i < n; i++)
        if (still_open(r, &u[i]))
            open[k++] = u[i];
    const int ng = merge_regions(r, open, k, dim, g);
    /* as many regions as the failure list holds; the rest counted in one line */
    const int room = IC_TRACE_MAX_FAILURES - rep->nfailures;
    const int shown = ng <= room ? ng : room - 1;
    int rest_cells = 0;
    for (int j = 0; j < ng; j++) {
        if (j < shown)
            list_region(r, &g[j], dim);
        else
            rest_cells += g[j].cells;
    }
    if (shown < ng)
        ic_trace_failure(rep, "undecided: %d more regions of %d cells in all", ng - shown,
                         rest_cells);
    free(open);
    free(g);
}
