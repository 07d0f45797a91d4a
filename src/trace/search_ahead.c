/*
 * Parts of the search done ahead by a trace's threads (search.c takes them
 * in its serial order): the first search's subtrees a few levels down, and
 * the finer searches of open cells. Each part is walked on the worker's own
 * pair with a budget of its own (the trace's deadline, the cells left when
 * the batch began); the serial order takes a part only where the trace's
 * budget holds what it took, so the result does not depend on the threads.
 */
#include "search_internal.h"
#include "workers.h"

#include <stdlib.h>
#include <string.h>

/* Subtrees of the first search per thread: their costs differ a lot (most
 * are excluded at once), and many small ones keep every thread busy. */
#define SUBTREES_PER_THREAD 16

/* Finer searches one job of a batch of open cells does at most: its cell's
 * and, while the job lasts, those of the open cells found in it, and so on
 * down (the refinement goes down one cell's tree before the next). */
#define PARTS_PER_JOB 256

/* What a batch of parts shares: how each is walked. */
typedef struct {
    const ic_trace_options *opt;
    int proven, depth;
    const ic_unresolved *const *cells; /* the open cells refined (NULL: the first search) */
    ic_search_wanted *wanted;          /* whether an open cell found will be refined */
    const void *wanted_ctx;
    ic_trace_budget budget; /* as the batch began */
    ic_search_share *share;
    ic_search_part **parts;
} batch;

/* Walks part p (its root set) at refinement level `level`; an incomplete
 * part is left empty (the serial order walks its cell). */
static void walk_one(const batch *b, const ic_search_ctx *x, ic_search_part *p, int level)
{
    ic_trace_budget own = b->budget;
    ic_search_walk w = {.x = x, .depth = b->depth, .level = level, .budget = &own,
                        .share = b->share, .ahead = 1};
    if (ic_search_walk_run(&w, p) != 0 || !p->complete) {
        const ic_search_cell root = p->root;
        ic_search_part_clear(p);
        p->root = root;
    }
}

/* The finer search of an open cell, as ic_trace_candidates walks it. */
static ic_search_part *cell_part(const ic_unresolved *u)
{
    ic_search_part *p = calloc(1, sizeof *p);
    if (p) {
        memcpy(p->root.lo, u->lo, sizeof u->lo);
        memcpy(p->root.hi, u->hi, sizeof u->hi);
    }
    return p;
}

/* A refinement tree done ahead: p's finer search, then those of its open
 * cells that will be refined, in the serial order, while *left lasts. */
static void walk_tree(const batch *b, const ic_search_ctx *x, ic_search_part *p, int level,
                      int *left)
{
    walk_one(b, x, p, level);
    if (!p->complete || !b->wanted || p->nunres == 0 || *left <= 0 ||
        !(p->children = calloc((size_t)p->nunres, sizeof *p->children)))
        return;
    for (int j = p->nunres - 1; j >= 0 && *left > 0; j--) /* popped last first */
        if (b->wanted(b->wanted_ctx, &p->unres[j]) && (p->children[j] = cell_part(&p->unres[j]))) {
            (*left)--;
            walk_tree(b, x, p->children[j], p->unres[j].level + 1, left);
        }
}

static void walk_part(void *ctx, int i, ic_pair *pair)
{
    const batch *b = ctx;
    ic_search_part *p = b->parts[i];
    ic_search_ctx x;
    if (!p || ic_search_ctx_init(&x, pair, b->opt, b->proven, NULL) != IC_OK)
        return; /* p->complete stays 0: the serial order walks the cell */
    int left = PARTS_PER_JOB - 1;
    if (b->cells)
        walk_tree(b, &x, p, b->cells[i]->level + 1, &left);
    else
        walk_one(b, &x, p, 0);
}

/* The cells at depth `split` of the first search in its serial order
 * (those above that it skips or excludes have none); their number. */
static int split_cells(const ic_search_ctx *x, const ic_search_cell *root, int split,
                       ic_search_cell *out, ic_search_cell *stack)
{
    int top = 1, n = 0;
    stack[0] = *root;
    while (top > 0) {
        const ic_search_cell c = stack[--top];
        if (c.depth == split) {
            out[n++] = c;
            continue;
        }
        if ((x->kind->skip && x->kind->skip(x->pg, c.lo, c.hi, 0, x->band)) ||
            (x->proven && x->kind->excluded(x->pg, c.lo, c.hi)))
            continue;
        for (int m = 0; m < (1 << x->dim); m++) { /* as search.c's visit */
            ic_search_cell ch = {.depth = c.depth + 1};
            for (int k = 0; k < x->dim; k++) {
                const double mid = 0.5 * (c.lo[k] + c.hi[k]);
                ch.lo[k] = (m >> k) & 1 ? mid : c.lo[k];
                ch.hi[k] = (m >> k) & 1 ? c.hi[k] : mid;
            }
            stack[top++] = ch;
        }
    }
    return n;
}

/* New parts with their roots; NULL out of memory (nothing is then done ahead). */
static ic_search_part **new_parts(const ic_search_cell *roots, int n)
{
    ic_search_part **parts = calloc((size_t)n, sizeof *parts);
    for (int i = 0; parts && i < n; i++) {
        if (!(parts[i] = calloc(1, sizeof *parts[i]))) {
            while (i-- > 0)
                free(parts[i]);
            free(parts);
            return NULL;
        }
        parts[i]->root = roots[i];
    }
    return parts;
}

void ic_search_ahead_first(ic_trace_workers *workers, ic_pair *pair, const ic_search_ctx *x,
                           const ic_trace_options *opt, int depth,
                           const ic_trace_budget *budget, ic_search_part ***parts,
                           int *nparts)
{
    *parts = NULL, *nparts = 0;
    const int threads = ic_trace_workers_count(workers);
    if (threads < 2)
        return;
    int split = 1;
    while ((1L << (x->dim * split)) < (long)SUBTREES_PER_THREAD * threads)
        split++;
    if (split >= depth)
        return; /* a search this small is not worth the threads */
    const size_t most = (size_t)1 << (x->dim * split);
    ic_search_cell *cells = malloc(most * sizeof *cells);
    ic_search_cell *stack = malloc(((size_t)16 * split + 16) * sizeof *stack);
    ic_search_cell root = {.depth = 0};
    memcpy(root.lo, x->lo, sizeof root.lo), memcpy(root.hi, x->hi, sizeof root.hi);
    const int n = cells && stack ? split_cells(x, &root, split, cells, stack) : 0;
    ic_search_part **p = n > 0 ? new_parts(cells, n) : NULL;
    free(cells);
    free(stack);
    if (!p)
        return;
    ic_search_share share = {.available = budget->cells_left};
    batch b = {.opt = opt, .proven = x->proven, .depth = depth, .budget = *budget,
               .share = &share, .parts = p};
    ic_trace_workers_run(workers, pair, walk_part, &b, n);
    *parts = p, *nparts = n;
}

void ic_search_ahead_cells(ic_trace_workers *workers, ic_pair *pair, const ic_trace_options *opt,
                           int proven, const ic_unresolved *const *u, int n,
                           ic_search_wanted *wanted, const void *wanted_ctx,
                           const ic_trace_budget *budget, ic_search_part **parts)
{
    for (int i = 0; i < n; i++)
        parts[i] = cell_part(u[i]);
    batch b = {.opt = opt, .proven = proven, .depth = 1, .cells = u, .wanted = wanted,
               .wanted_ctx = wanted_ctx, .budget = *budget, .parts = parts};
    ic_trace_workers_run(workers, pair, walk_part, &b, n);
}
