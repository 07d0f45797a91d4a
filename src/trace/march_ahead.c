/*
 * The marches of a curve from a start point (ic_trace_march_both), and
 * start candidates marched ahead by the trace's threads. A march depends on
 * the pair and its start alone; what the trace makes of it (its ends
 * located and recorded, the curve added, the candidates it covers) stays in
 * the serial order (candidates.c), which takes a candidate's marches done ahead
 * when it comes to trace that candidate and otherwise marches itself: the
 * result is the same whatever the number of threads. Candidates that the
 * trace skips at their turn (a curve traced meanwhile covers them) were
 * marched for nothing: the next ones are chosen apart from each other, and
 * when most were for nothing the trace marches alone again.
 */
#include "march_ahead.h"
#include "core/trace_constants.h"
#include "workers.h"
#include "common/vec3.h"
#include "local/pair_access.h"

#include <stdlib.h>
#include <string.h>

/* Candidates marched ahead per thread in one batch, at most: a batch
 * starts at one a thread and grows while most of those marched are traced. */
#define AHEAD_PER_THREAD 4
/* relative: candidates marched in one batch lie at least this fraction of
 * L apart (candidates closer than that are mostly on one curve) */
#define AHEAD_APART 0.05

/* One march from pt in direction dir into slot k of m: IC_ERR_NOMEM when
 * its points cannot be copied. */
static ic_status march_one(ic_tracer *tr, const ic_local_point *pt, int dir, ic_trace_marches *m,
                           int k, ic_error *err)
{
    m->e[k] = IC_TRACE_FAILED;
    ic_error_clear(&m->err[k]);
    ic_status st = ic_tracer_start(tr, pt, dir, &m->err[k]);
    if (st == IC_OK)
        st = ic_tracer_run(tr, &m->e[k], &m->err[k]);
    m->st[k] = st;
    if (st == IC_ERR_NOMEM)
        return IC_OK; /* recorded: the trace ends there */
    const int n = ic_tracer_num_points(tr);
    /* room for one more: the end's tangential point (finish_end, curve_ends.c) */
    if (!(m->pts[k] = malloc((size_t)(n + 1) * sizeof *m->pts[k])))
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory");
    if (n > 0)
        memcpy(m->pts[k], ic_tracer_point(tr, 0), (size_t)n * sizeof *m->pts[k]);
    m->n[k] = n;
    return IC_OK;
}

ic_status ic_trace_march_both(ic_tracer *tr, const ic_local_point *pt, ic_trace_marches *m,
                              ic_error *err)
{
    memset(m, 0, sizeof *m);
    ic_status st = march_one(tr, pt, 1, m, 0, err);
    const int hard = m->st[0] != IC_OK && (m->e[0] != IC_TRACE_FAILED || m->st[0] == IC_ERR_NOMEM);
    if (st != IC_OK || hard || m->e[0] == IC_TRACE_CLOSED)
        return st;
    return march_one(tr, pt, -1, m, 1, err);
}

void ic_trace_marches_free(ic_trace_marches *m)
{
    free(m->pts[0]);
    free(m->pts[1]);
    m->pts[0] = m->pts[1] = NULL;
}

/* What a batch of candidates marched ahead shares. */
typedef struct {
    const ic_trace_options *opt;
    double deadline;
    const ic_candidate *cand;
    const int *which; /* the candidates of the batch */
    ic_trace_ahead *ahead;
} batch;

/* A candidate located, found transversal and marched, as
 * ic_trace_from_candidates does it, on the thread's own pair. */
static void march_candidate(void *ctx, int k, ic_pair *pair)
{
    const batch *b = ctx;
    const ic_candidate *c = &b->cand[b->which[k]];
    ic_trace_ahead *a = &b->ahead[b->which[k]];
    const long before = ic_pair_nomem_count(pair);
    ic_local_options lo = b->opt->local;
    ic_local_result res;
    ic_tracer *tr = NULL;
    a->valid = ic_local_locate_guess(pair, &a->pt, c->xyz, c->params, &lo, NULL) == IC_OK &&
               ic_local_apparatus(pair, &res, &a->pt, 2, IC_METHOD_JET, &lo, NULL) == IC_OK &&
               res.type == IC_POINT_TRANSVERSAL &&
               ic_tracer_new_absolute(&tr, pair, b->opt, NULL) == IC_OK;
    if (a->valid) {
        ic_tracer_set_deadline(tr, b->deadline);
        a->valid = ic_trace_march_both(tr, &a->pt, &a->m, NULL) == IC_OK;
    }
    ic_tracer_free(tr);
    /* out of memory here costs only this march: the trace does it itself */
    if (ic_pair_nomem_count(pair) != before) {
        ic_pair_nomem_restore(pair, before);
        a->valid = 0;
    }
    if (!a->valid)
        ic_trace_marches_free(&a->m);
}

/* Whether the serial order will likely trace candidate j as things stand:
 * no curve traced covers it (candidates.c's tests, less the pole gaps, which
 * the serial order checks anyway). */
static int untraced(const ic_trace_result *r, const ic_candidate *c, double radius)
{
    return !c->covered && !ic_trace_point_near_found(r, c->xyz, radius);
}

/* How many candidates the next batch marches: none once most of those
 * marched were skipped (one long curve through them), else per thread one
 * more for each one skipped in every used+1 traced. */
static int batch_size(int threads, int used, int lost)
{
    if (lost > used + threads)
        return 0;
    const int per = 1 + used / (1 + lost);
    return threads * (per < AHEAD_PER_THREAD ? per : AHEAD_PER_THREAD);
}

void ic_trace_march_ahead(ic_trace_result *r, ic_pair *pair, const ic_trace_options *opt,
                          const ic_candidate *cand, int nc, int i, int used, int lost,
                          ic_trace_ahead *ahead)
{
    enum { MOST = AHEAD_PER_THREAD * IC_TRACE_MAX_THREADS };
    const int want = batch_size(ic_trace_workers_count(r->workers), used, lost);
    if (want == 0)
        return;
    const double radius = IC_TRACE_ON_CURVE * r->scale, apart = AHEAD_APART * r->scale;
    int which[MOST], n = 0;
    which[n++] = i;
    for (int j = i + 1; j < nc && n < want; j++) {
        if (ahead[j].done || !untraced(r, &cand[j], radius))
            continue;
        int far = 1;
        for (int k = 0; k < n && far; k++) {
            double d[3];
            ic_axpy3(d, cand[j].xyz, -1.0, cand[which[k]].xyz);
            far = ic_norm3(d) > apart;
        }
        if (far)
            which[n++] = j;
    }
    for (int k = 0; k < n; k++)
        ahead[which[k]].done = 1;
    batch b = {.opt = opt, .deadline = r->budget.deadline, .cand = cand, .which = which,
               .ahead = ahead};
    ic_trace_workers_run(r->workers, pair, march_candidate, &b, n);
}
