/*
 * Start points by subdivision (docs/tracing.md, "Search"). Cells of the
 * pairing's search space (pairing/pairing.h: the box, a parametric sheet's
 * domain, or (u, v, p, q)) are split down to opt->depth levels; a cell that
 * the pairing's interval test proves empty is dropped. In each remaining
 * leaf the pairing's Newton iteration from the centre looks for a point on
 * both surfaces; a leaf where it finds none may still be proven empty by
 * centred forms; every leaf left gets the loop test (both the pairing's).
 * With `within`, one leaf is searched again a few levels finer. Surfaces
 * without interval evaluation (callbacks) cannot exclude anything: then the
 * leaves of a coarser grid are sampled and the report says so.
 *
 * With threads, subtrees of the first search and the finer searches of
 * open cells are done ahead (search_ahead.c) and taken in the serial order
 * in place of the cells they cover, where the budget allows what they took:
 * the result is the serial one whatever the number of threads.
 */
#include "search_internal.h"
#include "trace_internal.h"
#include "common/vec3.h"
#include "local/pair_access.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static int push_candidate(ic_search_part *l, const ic_candidate *c)
{
    if (l->ncand == l->capc) {
        const int cap = l->capc ? 2 * l->capc : 64;
        ic_candidate *p = realloc(l->cand, (size_t)cap * sizeof *p);
        if (!p)
            return -1;
        l->cand = p;
        l->capc = cap;
    }
    l->cand[l->ncand++] = *c;
    return 0;
}

static int push_unresolved(ic_search_part *l, const ic_unresolved *u)
{
    if (l->nunres == l->capu) {
        const int cap = l->capu ? 2 * l->capu : 64;
        ic_unresolved *p = realloc(l->unres, (size_t)cap * sizeof *p);
        if (!p)
            return -1;
        l->unres = p;
        l->capu = cap;
    }
    l->unres[l->nunres++] = *u;
    return 0;
}

void ic_search_part_free(ic_search_part *p)
{
    if (!p)
        return;
    ic_search_part_clear(p);
    free(p);
}

ic_search_part *ic_search_part_take_child(ic_search_part *p, int i)
{
    if (!p || !p->children || i < 0 || i >= p->nunres)
        return NULL;
    ic_search_part *c = p->children[i];
    p->children[i] = NULL;
    return c;
}

void ic_search_part_clear(ic_search_part *p)
{
    for (int i = 0; p->children && i < p->nunres; i++)
        ic_search_part_free(p->children[i]);
    free(p->children);
    free(p->cand);
    free(p->unres);
    memset(p, 0, sizeof *p);
}

/* A Newton point is accepted when its distance to each surface is below
 * this fraction of (L + |x|): rounding leaves about 1e-15 of it. */
#define NEWTON_ACCEPT 1e-10

int ic_search_full_depth(const ic_search_ctx *x, const ic_trace_options *opt)
{
    /* four parameters: one level less (16 children a split) */
    return x->dim == 4 ? opt->depth - 1 : opt->depth;
}

ic_status ic_search_ctx_init(ic_search_ctx *x, ic_pair *pair, const ic_trace_options *opt,
                             int proven, ic_error *err)
{
    memset(x, 0, sizeof *x);
    x->pg = ic_pair_pairing(pair);
    x->kind = x->pg->kind;
    x->dim = x->kind->dim;
    x->L = opt->local.scale > 0 ? opt->local.scale : 1.0;
    ic_status st = x->kind->region(x->pg, opt->box, opt->has_box, x->lo, x->hi, x->periodic, err);
    if (st != IC_OK)
        return st;
    /* can the surfaces be enclosed? (formula surfaces and primitives) */
    x->proven = proven >= 0 ? proven : x->kind->enclosable(x->pg, x->lo, x->hi);
    const int full = ic_search_full_depth(x, opt);
    for (int k = 0; k < 2; k++)
        x->band[k] = 2 * (x->hi[k] - x->lo[k]) / (1 << full);
    return IC_OK;
}

/* Newton from the cell's centre: 1 with *cand set when it converged near
 * the cell (within a cell width, inside the region); *converged says
 * whether it converged at all. */
static int leaf_newton(const ic_search_ctx *x, const ic_search_cell *c, ic_candidate *cand,
                       int *converged)
{
    memset(cand, 0, sizeof *cand);
    double z[4], xyz[3] = {0, 0, 0};
    for (int k = 0; k < x->dim; k++)
        z[k] = 0.5 * (c->lo[k] + c->hi[k]);
    *converged = x->kind->newton(x->pg, NEWTON_ACCEPT, x->L, z, xyz) == 0;
    int ok = *converged;
    for (int k = 0; ok && k < x->dim; k++) {
        const double w = c->hi[k] - c->lo[k];
        ok = z[k] >= c->lo[k] - w && z[k] <= c->hi[k] + w && z[k] >= x->lo[k] && z[k] <= x->hi[k];
    }
    if (ok && x->kind->distinct) /* a self-intersection's distinct preimages */
        ok = x->kind->distinct(x->pg, z, x->band);
    x->kind->unflatten(x->pg, z, cand->params);
    memcpy(cand->xyz, xyz, sizeof xyz);
    return ok;
}

/* The place of a cell in space: its centre's point and a radius covering
 * the cell (0 where it cannot be placed: never counted as covered). */
static void describe_cell(const ic_search_ctx *x, const ic_search_cell *c, ic_unresolved *u)
{
    memcpy(u->lo, c->lo, sizeof u->lo);
    memcpy(u->hi, c->hi, sizeof u->hi);
    x->kind->place(x->pg, c->lo, c->hi, u->xyz, u->params, &u->radius);
}

/* 1 when the cell, enlarged by a quarter each side, is proven loop-free: a
 * closed curve of extent below a quarter cell through a point of this cell
 * lies inside the enlarged one. The enlargement stops at the region's
 * edges, where no curve is sought, except across a period (the curve goes
 * on there). */
static int leaf_loop_free(const ic_search_ctx *x, const ic_search_cell *c)
{
    if (!x->proven)
        return 0;
    double elo[4], ehi[4];
    for (int k = 0; k < x->dim; k++) {
        const double q = 0.25 * (c->hi[k] - c->lo[k]);
        elo[k] = c->lo[k] - q, ehi[k] = c->hi[k] + q;
        if (!x->periodic[k])
            elo[k] = fmax(elo[k], x->lo[k]), ehi[k] = fmin(ehi[k], x->hi[k]);
    }
    return x->kind->loop_free(x->pg, elo, ehi);
}

/* A leaf: Newton, centred forms, the loop test; a start point is kept, a
 * leaf that holds none, or that fails the loop test, is returned as
 * unresolved. -1: out of memory. */
static int process_leaf(const ic_search_ctx *x, const ic_search_cell *c, int level,
                        ic_search_part *out)
{
    ic_candidate cand;
    int converged;
    const int ok = leaf_newton(x, c, &cand, &converged);
    /* nothing found: centred forms may still prove the leaf empty (they
     * separate two surfaces closer than a cell) */
    if (!ok && x->proven && x->kind->excluded_centred(x->pg, c->lo, c->hi)) {
        out->counts.excluded++;
        out->counts.excluded_centred++;
        return 0;
    }
    const int loop = !leaf_loop_free(x, c);
    if (x->proven) {
        if (loop)
            out->counts.loop_cells++;
        else
            out->counts.loop_free_cells++;
    }
    if (ok && push_candidate(out, &cand) != 0)
        return -1;
    if (ok && !loop)
        return 0;
    ic_unresolved u;
    memset(&u, 0, sizeof u);
    u.converged_elsewhere = converged && !ok;
    u.loop = loop;
    u.has_candidate = ok;
    u.level = level;
    u.overflow = x->proven && x->kind->overflows(x->pg, c->lo, c->hi);
    u.degenerate = loop && x->kind->may_degenerate(x->pg, c->lo, c->hi);
    describe_cell(x, c, &u);
    return push_unresolved(out, &u);
}

/* A cell the budget left unexamined: returned as unresolved, unplaced
 * (radius 0), so that it is never counted as covered. */
static int push_unexamined(const ic_search_ctx *x, const ic_search_cell *c, int level,
                           ic_search_part *out)
{
    ic_unresolved u;
    memset(&u, 0, sizeof u);
    u.loop = 1;
    u.level = level;
    describe_cell(x, c, &u);
    u.radius = 0.0;
    return push_unresolved(out, &u);
}

/* Cells taken between two looks at the clock (and, ahead, at the cells
 * all the threads took): a cell costs microseconds. */
#define CLOCK_EVERY 256

/* Takes a cell from the budget: 1 when none is left (b->stopped set). */
static int out_of_budget(ic_trace_budget *b, ic_search_share *share)
{
    if (b->stopped)
        return 1;
    if (b->cells_left <= 0) {
        b->stopped = IC_TRACE_STOP_CELLS;
        return 1;
    }
    b->cells_left--;
    if ((b->cells_left & (CLOCK_EVERY - 1)) != 0)
        return 0;
    if (share && atomic_fetch_add(&share->used, CLOCK_EVERY) + CLOCK_EVERY > share->available) {
        b->stopped = IC_TRACE_STOP_CELLS;
        return 1;
    }
    return ic_trace_out_of_time(b);
}

static int same_cell(const ic_search_cell *a, const ic_search_cell *b, int dim)
{
    if (a->depth != b->depth)
        return 0;
    for (int k = 0; k < dim; k++)
        if (a->lo[k] != b->lo[k] || a->hi[k] != b->hi[k])
            return 0;
    return 1;
}

/* Whether the serial order, with budget b, gets what the part done ahead
 * found: the part is whole, the budget holds the cells it took,
 * and no look at the clock among them would have found the time up. */
static int part_usable(const ic_search_part *p, const ic_trace_budget *b)
{
    if (!p->complete || b->stopped || b->cells_left < p->used)
        return 0;
    /* the looks fall where cells_left, once taken, is a multiple of CLOCK_EVERY */
    const long first = b->cells_left - p->used, last = b->cells_left - 1;
    const int looks = p->used > 0 &&
                      (first % CLOCK_EVERY == 0 || first / CLOCK_EVERY != last / CLOCK_EVERY);
    return !(looks && b->deadline > 0 && ic_trace_now() > b->deadline);
}

/* Appends a part done ahead to out as if its cells had been walked. */
static int take_part(ic_search_part *out, const ic_search_part *p, ic_trace_budget *b)
{
    for (int i = 0; i < p->ncand; i++)
        if (push_candidate(out, &p->cand[i]) != 0)
            return -1;
    for (int i = 0; i < p->nunres; i++)
        if (push_unresolved(out, &p->unres[i]) != 0)
            return -1;
    out->counts.cells += p->counts.cells;
    out->counts.excluded += p->counts.excluded;
    out->counts.excluded_centred += p->counts.excluded_centred;
    out->counts.loop_cells += p->counts.loop_cells;
    out->counts.loop_free_cells += p->counts.loop_free_cells;
    b->cells_left -= p->used;
    out->used += p->used;
    return 0;
}

/* The part done ahead for cell c, when the serial order can take it. */
static const ic_search_part *part_for(ic_search_walk *w, const ic_search_cell *c)
{
    if (w->next >= w->nparts || !same_cell(&w->parts[w->next]->root, c, w->x->dim))
        return NULL;
    const ic_search_part *p = w->parts[w->next++];
    return part_usable(p, w->budget) ? p : NULL;
}

/* One cell popped from the walk's stack: pushes its children, or adds
 * what it holds to out. -1 out of memory. */
static int visit(ic_search_walk *w, const ic_search_cell *c, ic_search_cell *stack, int *top,
                 ic_search_part *out)
{
    const ic_search_ctx *x = w->x;
    const int leaf = c->depth == w->depth;
    if (x->kind->skip && x->kind->skip(x->pg, c->lo, c->hi, leaf, x->band))
        return 0;
    const long before = w->budget->cells_left;
    if (out_of_budget(w->budget, w->share)) {
        if (w->ahead)
            return 0;
        return push_unexamined(x, c, w->level + c->depth - w->depth, out);
    }
    out->used += before - w->budget->cells_left;
    out->counts.cells++;
    if (x->proven && x->kind->excluded(x->pg, c->lo, c->hi)) {
        out->counts.excluded++;
        return 0;
    }
    if (leaf)
        return process_leaf(x, c, w->level, out);
    for (int m = 0; m < (1 << x->dim); m++) { /* 2^dim children */
        ic_search_cell ch = {.depth = c->depth + 1};
        for (int k = 0; k < x->dim; k++) {
            const double mid = 0.5 * (c->lo[k] + c->hi[k]);
            ch.lo[k] = (m >> k) & 1 ? mid : c->lo[k];
            ch.hi[k] = (m >> k) & 1 ? c->hi[k] : mid;
        }
        stack[(*top)++] = ch;
    }
    return 0;
}

int ic_search_walk_run(ic_search_walk *w, ic_search_part *out)
{
    ic_search_cell *stack = malloc(((size_t)16 * w->depth + 16) * sizeof *stack);
    if (!stack)
        return -1;
    int top = 1, rc = 0;
    stack[0] = out->root;
    while (rc == 0 && top > 0 && !(w->ahead && w->budget->stopped)) {
        const ic_search_cell c = stack[--top];
        const ic_search_part *p = w->nparts > 0 ? part_for(w, &c) : NULL;
        rc = p ? take_part(out, p, w->budget) : visit(w, &c, stack, &top, out);
    }
    free(stack);
    out->complete = rc == 0 && !(w->ahead && w->budget->stopped);
    return rc;
}

ic_status ic_trace_candidates(ic_pair *pair, const ic_trace_options *opt,
                              const ic_unresolved *within, ic_trace_workers *workers,
                              ic_search_part *ahead, ic_candidate **out, int *nout,
                              ic_unresolved **unres, int *nunres, ic_trace_report *rep,
                              ic_trace_budget *budget, ic_error *err)
{
    *out = NULL, *nout = 0, *unres = NULL, *nunres = 0;
    ic_search_ctx x;
    ic_status st = ic_search_ctx_init(&x, pair, opt, within ? rep->proven : -1, err);
    if (st != IC_OK)
        return st;
    if (!within)
        rep->proven = x.proven;
    /* without enclosures nothing is excluded: a coarser grid is sampled */
    const int full = ic_search_full_depth(&x, opt);
    ic_search_walk w = {.x = &x, .depth = x.proven ? full : (full < 4 ? full : 4),
                        .budget = budget};
    ic_search_part part;
    memset(&part, 0, sizeof part);
    memcpy(part.root.lo, x.lo, sizeof x.lo), memcpy(part.root.hi, x.hi, sizeof x.hi);
    if (within) { /* a finer search of one cell: its 2^dim children */
        memcpy(part.root.lo, within->lo, sizeof x.lo), memcpy(part.root.hi, within->hi, sizeof x.hi);
        w.depth = 1;
        w.level = within->level + 1;
    }
    double size = 0.0;
    for (int k = 0; k < x.dim; k++)
        size = fmax(size, (part.root.hi[k] - part.root.lo[k]) / (1 << w.depth));
    rep->cell_size = within ? fmin(rep->cell_size, size) : size;
    if (within && ahead) {
        w.parts = &ahead;
        w.nparts = 1;
    } else if (!within)
        ic_search_ahead_first(workers, pair, &x, opt, w.depth, budget, &w.parts, &w.nparts);
    const int rc = ic_search_walk_run(&w, &part);
    if (!within) {
        for (int i = 0; i < w.nparts; i++)
            ic_search_part_free(w.parts[i]);
        free(w.parts);
    }
    if (rc != 0) {
        ic_search_part_clear(&part);
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory searching start points");
    }
    rep->cells += part.counts.cells;
    rep->cells_excluded += part.counts.excluded;
    rep->cells_excluded_centred += part.counts.excluded_centred;
    rep->loop_cells += part.counts.loop_cells;
    rep->loop_free_cells += part.counts.loop_free_cells;
    rep->candidates += part.ncand;
    *out = part.cand, *nout = part.ncand;
    *unres = part.unres, *nunres = part.nunres;
    return IC_OK;
}
