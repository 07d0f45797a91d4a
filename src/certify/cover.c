/*
 * The cover (certificate.h): the search region split into a tree of cells
 * until every leaf is proven (leaf.c), depth first. A cell is split across
 * its widest coordinate (relative to the region's width) a little off its
 * middle, alternately below and above it, so that the faces of the cover
 * rarely fall on a symmetry plane of the problem, where a curve could lie
 * in a face or cross it at an edge. The first leaf that cannot be proven
 * ends the cover: the certificate is refused with the reason.
 */
#include "certificate.h"
#include "plan.h"

#include <math.h>
#include <stdlib.h>
#include <time.h>

/* The split's offset from the middle, as a fraction of the cell's width
 * (irrational-looking numbers: no symmetric problem puts a curve there),
 * and its change from one coordinate to the next: two coordinates with the
 * same range are never split at the same value, or a curve along their
 * diagonal (u = p of two patches over one plane, say) would cross both
 * splits at once, at an edge of a cell, where no crossing can be isolated. */
#define IC_CERTIFY_SPLIT_OFFSET 0.0295
#define IC_CERTIFY_SPLIT_OFFSET_STEP 0.0173

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* The coordinate of cell i to split: the widest by ic_certificate_rel
 * (relative to the region, or in space where the coordinates' lengths
 * differ much: a region 3 wide and 7e-4 high is then cut into cells of
 * about equal sides in space, not of the region's shape); *rel the largest
 * width of the cell relative to the region's. */
static int widest(const ic_certificate *c, long i, double *rel)
{
    const ic_cell *cl = &c->cells[i];
    int best = 0;
    double best_len = -1.0;
    *rel = -1.0;
    for (int k = 0; k < c->dim; k++) {
        const double w = cl->hi[k] - cl->lo[k];
        const double len = ic_certificate_rel(c, k, w, 1);
        *rel = fmax(*rel, w / (c->hi[k] - c->lo[k]));
        if (len > best_len)
            best = k, best_len = len;
    }
    return best;
}

/* Where cell i is split across k: a little off its middle. */
static double split_point(const ic_certificate *c, long i, int k, int depth)
{
    const ic_cell *cl = &c->cells[i];
    const double off = IC_CERTIFY_SPLIT_OFFSET + k * IC_CERTIFY_SPLIT_OFFSET_STEP;
    const double f = 0.5 + (depth % 2 ? off : -off);
    return cl->lo[k] + f * (cl->hi[k] - cl->lo[k]);
}

/* Splits cell i across k at `at` into two new cells pushed on the stack. */
static int split(ic_certificate *c, long i, int k, double at, long *stack, int *n)
{
    ic_cell *cl = &c->cells[i];
    double lo[4], hi[4];
    for (int j = 0; j < c->dim; j++)
        lo[j] = cl->lo[j], hi[j] = cl->hi[j];
    hi[k] = at;
    const long a = ic_certificate_add_cell(c, lo, hi);
    lo[k] = at, hi[k] = c->cells[i].hi[k];
    const long b = a < 0 ? -1 : ic_certificate_add_cell(c, lo, hi);
    if (b < 0)
        return -1;
    cl = &c->cells[i];
    cl->kind = IC_CELL_SPLIT, cl->axis = k, cl->at = at;
    cl->child[0] = (int)a, cl->child[1] = (int)b;
    stack[(*n)++] = b;
    stack[(*n)++] = a;
    return 0;
}

/* Decides leaf i or splits it: 1 decided or split, 0 refused, -1 out of
 * memory. */
static int grow_leaf(ic_certificate *c, long i, int depth, const ic_certify_limits *lim,
                     long *stack, int *n)
{
    const int rc = ic_certify_leaf(c, i, lim);
    if (rc != 0) {
        if (rc > 0)
            ic_certificate_count(c, c->cells[i].kind);
        return rc;
    }
    double rel;
    const int k = widest(c, i, &rel);
    const ic_cell *cl = &c->cells[i];
    if (rel < lim->min_width) {
        ic_certificate_count(c, IC_CELL_REFUSED);
        ic_certificate_refuse(c, "a cell of width %.3g of the region at [%.9g, %.9g] x [%.9g, "
                                 "%.9g] (first two coordinates) is neither empty nor regular nor "
                                 "by a singular point or tangential curve found: one missed, a "
                                 "box edge across a sheet, or surfaces too close",
                              rel, cl->lo[0] + ic_certificate_origin(c, 0),
                              cl->hi[0] + ic_certificate_origin(c, 0),
                              cl->lo[1] + ic_certificate_origin(c, 1),
                              cl->hi[1] + ic_certificate_origin(c, 1));
        return 0;
    }
    if (c->ncells + 2 > lim->max_cells) {
        ic_certificate_count(c, IC_CELL_REFUSED);
        ic_certificate_refuse(c, "the cover needs more than %ld cells (undecided when they ran "
                                 "out: a cell of width %.3g of the region at [%.9g, %.9g] x "
                                 "[%.9g, %.9g], first two coordinates)",
                              lim->max_cells, rel, cl->lo[0] + ic_certificate_origin(c, 0),
                              cl->hi[0] + ic_certificate_origin(c, 0),
                              cl->lo[1] + ic_certificate_origin(c, 1),
                              cl->hi[1] + ic_certificate_origin(c, 1));
        return 0;
    }
    /* a pole's strip first: there the cell is singular whatever its
     * other widths (certificate.h) */
    double at;
    const int j = ic_certificate_pole_split(c, i, &at);
    if (j >= 0)
        return split(c, i, j, at, stack, n) < 0 ? -1 : 1;
    return split(c, i, k, split_point(c, i, k, depth), stack, n) < 0 ? -1 : 1;
}

/* Cell i as the plan's next node says (plan.h): split there, or a leaf
 * proven to be what the file says. 1 done, 0 refused, -1 out of memory. */
static int replay_leaf(ic_certificate *c, long i, const ic_certify_limits *lim, long *stack,
                       int *n)
{
    int axis;
    double at;
    const int rc = ic_certify_replay_node(c, i, c->plan_next++, lim, &axis, &at);
    if (rc == 2)
        return split(c, i, axis, at, stack, n) < 0 ? -1 : 1;
    if (rc == 1)
        ic_certificate_count(c, c->cells[i].kind);
    else if (rc == 0)
        ic_certificate_count(c, IC_CELL_REFUSED);
    return rc;
}

ic_status ic_certify_cover(ic_certificate *c, const ic_certify_limits *lim, ic_error *err)
{
    const double start = now();
    /* depth first: the stack never holds more than two cells per level */
    enum { MAX_STACK = 2 * (IC_CERTIFY_MAX_LEVELS + 1) };
    long *stack = malloc(MAX_STACK * sizeof *stack);
    int *depth = malloc(MAX_STACK * sizeof *depth);
    if (!stack || !depth) {
        free(stack), free(depth);
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory certifying");
    }
    int n = 1, rc = 1;
    stack[0] = 0, depth[0] = 0;
    c->summary.accepted = 1;
    while (n > 0 && rc == 1) {
        if (lim->deadline > 0 && now() > lim->deadline) {
            ic_certificate_refuse(c, "the time limit ran out certifying");
            rc = 0;
            break;
        }
        const long i = stack[--n];
        const int d = depth[n];
        const int before = n;
        if (n + 2 > MAX_STACK) {
            ic_certificate_refuse(c, "the cover is deeper than %d levels", MAX_STACK / 2);
            rc = 0;
            break;
        }
        rc = c->plan ? replay_leaf(c, i, lim, stack, &n) : grow_leaf(c, i, d, lim, stack, &n);
        for (int k = before; k < n; k++)
            depth[k] = d + 1;
    }
    free(stack), free(depth);
    c->summary.cells = c->ncells;
    c->summary.crossings = c->ncross;
    c->summary.arcs = c->ncross / 2;
    c->summary.seconds = now() - start;
    if (rc < 0)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory certifying");
    if (rc == 0)
        c->summary.accepted = 0;
    return IC_OK;
}
