/*
 * The start-point search's pieces shared by search.c (the search itself,
 * in its serial order) and search_ahead.c (parts of it done ahead in other
 * threads, used by the serial order where they give what it would).
 */
#ifndef IC_SEARCH_INTERNAL_H
#define IC_SEARCH_INTERNAL_H

#include "trace_internal.h"
#include "pairing/pairing.h"

#include <stdatomic.h>

typedef struct {
    double lo[4], hi[4];
    int depth;
} ic_search_cell;

/* What one search needs: the pairing, the region, and the band around a
 * self-intersection's diagonal. */
typedef struct {
    const ic_pairing *pg;
    const ic_pairing_kind *kind;
    int dim;
    double lo[4], hi[4]; /* the whole search region */
    int periodic[4];     /* coordinates whose domain is a period */
    double band[2];      /* two leaf widths in (u, v) at the first search's depth */
    int proven;
    double L; /* the problem's size */
} ic_search_ctx;

/* The search's counts in the report. */
typedef struct {
    int cells, excluded, excluded_centred, loop_cells, loop_free_cells;
} ic_search_counts;

/* What the search of one cell's subtree found, in the serial order. */
struct ic_search_part {
    ic_search_cell root;
    ic_candidate *cand;
    int ncand, capc;
    ic_unresolved *unres;
    int nunres, capu;
    ic_search_counts counts;
    long used;    /* cells taken from the budget */
    int complete; /* 0: stopped by the budget or out of memory (unusable) */
    /* the finer searches of the unresolved cells done ahead too (per
     * unres entry, NULL: none), or NULL */
    ic_search_part **children;
};

/* The cells the searches done ahead may take in all: they stop once past
 * it (the serial order would have stopped at the budget anyway). */
typedef struct {
    atomic_long used;
    long available;
} ic_search_share;

/* How a walk of the cells runs: its leaf depth and refinement level; the
 * parts done ahead that it takes in place of cells at their depth (in the
 * serial order); ahead: the walk is itself done ahead, and stops at the
 * budget rather than listing the cells left. */
typedef struct {
    const ic_search_ctx *x;
    int depth, level;
    ic_trace_budget *budget;
    ic_search_share *share; /* ahead only */
    int ahead;
    ic_search_part **parts;
    int nparts, next;
} ic_search_walk;

/* The search's context for the pair; proven < 0: found out (the whole
 * search), else given (a finer search keeps the whole search's answer). */
ic_status ic_search_ctx_init(ic_search_ctx *x, ic_pair *pair, const ic_trace_options *opt,
                             int proven, ic_error *err);
/* The first search's leaf depth. */
int ic_search_full_depth(const ic_search_ctx *x, const ic_trace_options *opt);
/* Walks the subtree of root into out (out->root set by the caller): 0, or
 * -1 out of memory. out->complete says whether an ahead walk finished. */
int ic_search_walk_run(ic_search_walk *w, ic_search_part *out);
void ic_search_part_clear(ic_search_part *p);

/* search_ahead.c: the parts of the first search's subtrees at a few levels
 * down, done by the workers; *parts NULL when not worth it (few cells or
 * one thread). The parts are in the serial order. */
void ic_search_ahead_first(ic_trace_workers *workers, ic_pair *pair, const ic_search_ctx *x,
                           const ic_trace_options *opt, int depth,
                           const ic_trace_budget *budget, ic_search_part ***parts,
                           int *nparts);

#endif
