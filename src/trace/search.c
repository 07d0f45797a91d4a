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
 */
#include "trace_internal.h"
#include "common/vec3.h"
#include "local/local_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    double lo[4], hi[4];
    int depth;
} cell;

typedef struct {
    ic_candidate *c;
    int n, cap;
} cand_list;

static int push_candidate(cand_list *l, const ic_candidate *c)
{
    if (l->n == l->cap) {
        const int cap = l->cap ? 2 * l->cap : 64;
        ic_candidate *p = realloc(l->c, (size_t)cap * sizeof *p);
        if (!p)
            return -1;
        l->c = p;
        l->cap = cap;
    }
    l->c[l->n++] = *c;
    return 0;
}

/* A Newton point is accepted when its distance to each surface is below
 * this fraction of (L + |x|): rounding leaves about 1e-15 of it. */
#define NEWTON_ACCEPT 1e-10

/* What one search needs: the pairing, the region, and the band around a
 * self-intersection's diagonal. */
typedef struct {
    const ic_pairing *pg;
    const ic_pairing_kind *kind;
    ic_surface *const *S;
    int dim;
    double lo[4], hi[4]; /* the whole search region */
    int periodic[4];     /* coordinates whose domain is a period */
    double band[2];      /* two leaf widths in (u, v) at the first search's depth */
    int proven;
    double L; /* the problem's size */
} search_ctx;

static ic_status ctx_init(search_ctx *x, ic_pair *pair, const ic_trace_options *opt,
                          ic_error *err)
{
    memset(x, 0, sizeof *x);
    x->pg = ic_pair_pairing(pair);
    x->kind = x->pg->kind;
    x->S = x->pg->S;
    x->dim = x->kind->dim;
    x->L = opt->local.scale > 0 ? opt->local.scale : 1.0;
    ic_status st = x->kind->region(x->pg, opt->box, opt->has_box, x->lo, x->hi, x->periodic, err);
    if (st != IC_OK)
        return st;
    /* can the surfaces be enclosed? (formula surfaces and primitives) */
    x->proven = x->kind->enclosable(x->pg, x->lo, x->hi);
    /* four parameters: one level less (16 children a split) */
    const int full = x->dim == 4 ? opt->depth - 1 : opt->depth;
    for (int k = 0; k < 2; k++)
        x->band[k] = 2 * (x->hi[k] - x->lo[k]) / (1 << full);
    return IC_OK;
}

/* Newton from the cell's centre: 1 with *cand set when it converged near
 * the cell (within a cell width, inside the region); *converged says
 * whether it converged at all. */
static int leaf_newton(const search_ctx *x, const cell *c, ic_candidate *cand, int *converged)
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
static void describe_cell(const search_ctx *x, const cell *c, ic_unresolved *u)
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
static int leaf_loop_free(const search_ctx *x, const cell *c)
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

typedef struct {
    ic_unresolved *u;
    int n, cap;
} unres_list;

static int push_unresolved(unres_list *l, const ic_unresolved *u)
{
    if (l->n == l->cap) {
        const int cap = l->cap ? 2 * l->cap : 64;
        ic_unresolved *p = realloc(l->u, (size_t)cap * sizeof *p);
        if (!p)
            return -1;
        l->u = p;
        l->cap = cap;
    }
    l->u[l->n++] = *u;
    return 0;
}

/* A leaf: Newton, centred forms, the loop test; a start point is kept, a
 * leaf that holds none, or that fails the loop test, is returned as
 * unresolved. -1: out of memory. */
static int process_leaf(const search_ctx *x, const cell *c, int level, cand_list *list,
                        unres_list *unres, ic_trace_report *rep)
{
    ic_candidate cand;
    int converged;
    const int ok = leaf_newton(x, c, &cand, &converged);
    /* nothing found: centred forms may still prove the leaf empty (they
     * separate two surfaces closer than a cell) */
    if (!ok && x->proven && x->kind->excluded_centred(x->pg, c->lo, c->hi)) {
        rep->cells_excluded++;
        rep->cells_excluded_centred++;
        return 0;
    }
    const int loop = !leaf_loop_free(x, c);
    if (x->proven) {
        if (loop)
            rep->loop_cells++;
        else
            rep->loop_free_cells++;
    }
    if (ok && push_candidate(list, &cand) != 0)
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
    return push_unresolved(unres, &u);
}

/* A cell the budget left unexamined: returned as unresolved, unplaced
 * (radius 0), so that it is never counted as covered. */
static int push_unexamined(const search_ctx *x, const cell *c, int level, unres_list *unres)
{
    ic_unresolved u;
    memset(&u, 0, sizeof u);
    u.loop = 1;
    u.level = level;
    describe_cell(x, c, &u);
    u.radius = 0.0;
    return push_unresolved(unres, &u);
}

static int out_of_budget(ic_trace_budget *b)
{
    if (b->stopped)
        return 1;
    if (b->cells_left <= 0) {
        b->stopped = IC_TRACE_STOP_CELLS;
        return 1;
    }
    b->cells_left--;
    /* the clock is read every 256 cells: a cell costs microseconds */
    return (b->cells_left & 255) == 0 && ic_trace_out_of_time(b);
}

ic_status ic_trace_candidates(ic_pair *pair, const ic_trace_options *opt,
                              const ic_unresolved *within, ic_candidate **out, int *nout,
                              ic_unresolved **unres, int *nunres, ic_trace_report *rep,
                              ic_trace_budget *budget, ic_error *err)
{
    *out = NULL, *nout = 0, *unres = NULL, *nunres = 0;
    search_ctx x;
    ic_status st = ctx_init(&x, pair, opt, err);
    if (st != IC_OK)
        return st;
    if (!within)
        rep->proven = x.proven;
    x.proven = rep->proven; /* a finer search keeps the whole search's answer */
    /* four parameters: one level less (16 children a split); without
     * enclosures nothing is excluded: a coarser grid is sampled */
    const int full = x.dim == 4 ? opt->depth - 1 : opt->depth;
    int depth = x.proven ? full : (full < 4 ? full : 4), level = 0;
    double lo[4], hi[4];
    memcpy(lo, x.lo, sizeof lo), memcpy(hi, x.hi, sizeof hi);
    if (within) { /* a finer search of one cell: its 2^dim children */
        memcpy(lo, within->lo, sizeof lo), memcpy(hi, within->hi, sizeof hi);
        depth = 1;
        level = within->level + 1;
    }
    double size = 0.0;
    for (int k = 0; k < x.dim; k++)
        size = fmax(size, (hi[k] - lo[k]) / (1 << depth));
    rep->cell_size = within ? fmin(rep->cell_size, size) : size;
    cand_list list = {0};
    unres_list ul = {0};
    cell *stack = malloc(((size_t)16 * depth + 16) * sizeof *stack);
    if (!stack)
        st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory searching start points");
    int top = 0;
    if (st == IC_OK) {
        memcpy(stack[0].lo, lo, sizeof lo), memcpy(stack[0].hi, hi, sizeof hi);
        stack[0].depth = 0;
        top = 1;
    }
    while (st == IC_OK && top > 0) {
        const cell c = stack[--top];
        const int leaf = c.depth == depth;
        if (x.kind->skip && x.kind->skip(x.pg, c.lo, c.hi, leaf, x.band))
            continue;
        if (out_of_budget(budget)) {
            if (push_unexamined(&x, &c, level + c.depth - depth, &ul) != 0)
                st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory");
            continue;
        }
        rep->cells++;
        if (x.proven && x.kind->excluded(x.pg, c.lo, c.hi)) {
            rep->cells_excluded++;
            continue;
        }
        if (!leaf) { /* split into 2^dim children */
            for (int m = 0; m < (1 << x.dim); m++) {
                cell ch;
                ch.depth = c.depth + 1;
                for (int k = 0; k < x.dim; k++) {
                    const double mid = 0.5 * (c.lo[k] + c.hi[k]);
                    ch.lo[k] = (m >> k) & 1 ? mid : c.lo[k];
                    ch.hi[k] = (m >> k) & 1 ? c.hi[k] : mid;
                }
                stack[top++] = ch;
            }
            continue;
        }
        if (process_leaf(&x, &c, level, &list, &ul, rep) != 0)
            st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory searching start points");
    }
    free(stack);
    if (st != IC_OK) {
        free(list.c);
        free(ul.u);
        return st;
    }
    rep->candidates += list.n;
    *out = list.c, *nout = list.n;
    *unres = ul.u, *nunres = ul.n;
    return IC_OK;
}
