/*
 * A certificate file's cover checked again (plan.h): its tree checked for
 * shape first, then replayed by the cover (cover.c), which takes each
 * split from the file and proves each leaf afresh.
 */
#include "plan.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const KIND_NAMES[] = {
    [IC_CELL_SPLIT] = "split",           [IC_CELL_EMPTY] = "empty",
    [IC_CELL_OUTSIDE] = "outside",       [IC_CELL_DIAGONAL] = "diagonal",
    [IC_CELL_REGULAR] = "regular",       [IC_CELL_SINGULAR] = "singular",
    [IC_CELL_TANGENTIAL] = "tangential", [IC_CELL_REFUSED] = "undecided",
};

const char *ic_cell_kind_name(ic_cell_kind kind)
{
    return KIND_NAMES[kind];
}

int ic_cell_kind_from_name(const char *name)
{
    for (int k = 0; k <= (int)IC_CELL_REFUSED; k++)
        if (strcmp(KIND_NAMES[k], name) == 0)
            return k;
    return -1;
}

void ic_cover_plan_free(ic_cover_plan *p)
{
    if (!p)
        return;
    free(p->nodes);
    free(p->crossings);
    free(p);
}

/* The pairing, dimension and region are c's: a file of another problem is
 * bad input, not a failed proof. */
static ic_status same_region(const ic_cover_plan *p, const ic_certificate *c, ic_error *err)
{
    if (strcmp(p->pairing, c->pg->kind->name) != 0)
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            "%s: pairing '%s': this problem's is '%s' (a certificate of "
                            "another problem)",
                            p->where, p->pairing, c->pg->kind->name);
    if (p->dim != c->dim)
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            "%s: dimension %d: this problem's search has %d coordinates",
                            p->where, p->dim, c->dim);
    for (int k = 0; k < c->dim; k++)
        if (p->origin[k] != ic_certificate_origin(c, k))
            return ic_error_set(err, IC_ERR_INVALID, 0,
                                "%s: region: origin %d is %.17g, this problem's %.17g (a "
                                "certificate of another problem or box)",
                                p->where, k, p->origin[k], ic_certificate_origin(c, k));
    for (int k = 0; k < c->dim; k++)
        if (p->lo[k] != c->lo[k] || p->hi[k] != c->hi[k])
            return ic_error_set(err, IC_ERR_INVALID, 0,
                                "%s: region: coordinate %d is [%.17g, %.17g], this problem's "
                                "[%.17g, %.17g] (a certificate of another problem or box)",
                                p->where, k, p->lo[k], p->hi[k], c->lo[k], c->hi[k]);
    return IC_OK;
}

/* One split node against the cell it splits. */
static ic_status check_split(const ic_cover_plan *p, long k, const double *lo, const double *hi,
                             ic_error *err)
{
    const ic_plan_node *nd = &p->nodes[k];
    if (nd->axis < 0 || nd->axis >= p->dim)
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            "%s: cells[%ld]: split axis %d: the search has coordinates 0..%d", p->where,
                            k, nd->axis, p->dim - 1);
    if (!(nd->at > lo[nd->axis] && nd->at < hi[nd->axis]))
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            "%s: cells[%ld]: split at %.17g: not inside the cell's [%.17g, %.17g] "
                            "along coordinate %d",
                            p->where, k, nd->at, lo[nd->axis], hi[nd->axis], nd->axis);
    return IC_OK;
}

/* Walks the tree in preorder with the cells' boxes on a stack. */
static ic_status check_tree(const ic_cover_plan *p, const ic_certificate *c, ic_error *err)
{
    typedef struct {
        double lo[4], hi[4];
        int depth;
    } cell_box;
    enum { MAX_STACK = 2 * (IC_CERTIFY_MAX_LEVELS + 1) };
    cell_box *stack = malloc(MAX_STACK * sizeof *stack);
    if (!stack)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory reading %s", p->where);
    int n = 1;
    memcpy(stack[0].lo, c->lo, sizeof c->lo);
    memcpy(stack[0].hi, c->hi, sizeof c->hi);
    stack[0].depth = 0;
    ic_status st = IC_OK;
    long k = 0;
    for (; k < p->nnodes && n > 0 && st == IC_OK; k++) {
        const cell_box b = stack[--n];
        if (p->nodes[k].kind != IC_CELL_SPLIT)
            continue;
        st = check_split(p, k, b.lo, b.hi, err);
        if (st == IC_OK && (b.depth >= IC_CERTIFY_MAX_LEVELS || n + 2 > MAX_STACK))
            st = ic_error_set(err, IC_ERR_INVALID, 0,
                              "%s: cells[%ld]: the tree is deeper than %d levels", p->where, k,
                              IC_CERTIFY_MAX_LEVELS);
        if (st != IC_OK)
            break;
        const int a = p->nodes[k].axis;
        stack[n + 1] = b, stack[n] = b; /* the lower half on top, next in preorder */
        stack[n + 1].hi[a] = p->nodes[k].at;
        stack[n].lo[a] = p->nodes[k].at;
        stack[n].depth = stack[n + 1].depth = b.depth + 1;
        n += 2;
    }
    free(stack);
    if (st != IC_OK)
        return st;
    if (n > 0)
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            "%s: cells: the tree ends early: %d cells after its %ld nodes have "
                            "none",
                            p->where, n, p->nnodes);
    if (k < p->nnodes)
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            "%s: cells[%ld]: after the end of the tree (%ld nodes make it)", p->where, k,
                            k);
    return IC_OK;
}

ic_status ic_cover_plan_check(const ic_cover_plan *p, const ic_certificate *c, ic_error *err)
{
    const ic_status st = same_region(p, c, err);
    return st != IC_OK ? st : check_tree(p, c, err);
}

/* The check's crossings of regular cell i are the node's, in order: the
 * same face, side and box face, and the file's point in the enclosure. */
static int same_crossings(ic_certificate *c, long i, long k)
{
    const ic_plan_node *nd = &c->plan->nodes[k];
    const ic_cell *cl = &c->cells[i];
    if (cl->axis != nd->axis || cl->ncross != nd->ncross || cl->nbox != nd->nbox) {
        ic_certificate_refuse(c,
                              "%s: cells[%ld]: the file's regular cell is monotone along %d with %d + %d "
                              "crossings, the check finds %d with %d + %d",
                              c->plan->where, k, nd->axis, nd->ncross, nd->nbox, cl->axis,
                              cl->ncross, cl->nbox);
        return 0;
    }
    for (int j = 0; j < cl->ncross + cl->nbox; j++) {
        ic_crossing tight = c->cross[cl->first + j], *x = &tight;
        ic_certify_tighten(c, x); /* as the file's writer did (cover_doc.c) */
        const ic_plan_crossing *f = &c->plan->crossings[nd->first + j];
        int inside = x->face == f->face && x->side == f->side && x->box == f->box;
        for (int d = 0; inside && d < c->dim; d++)
            inside = f->z[d] >= x->K[d].lo && f->z[d] <= x->K[d].hi;
        if (!inside) {
            ic_certificate_refuse(c,
                                  "%s: cells[%ld]: crossing %d of the file (face %d, side %d) is not the "
                                  "root the check isolates there",
                                  c->plan->where, k, j, f->face, f->side);
            return 0;
        }
    }
    return 1;
}

int ic_certify_replay_node(ic_certificate *c, long i, long k, const ic_certify_limits *lim,
                           int *axis, double *at)
{
    const ic_cover_plan *p = c->plan;
    const ic_plan_node *nd = &p->nodes[k];
    if (nd->kind == IC_CELL_SPLIT) {
        *axis = nd->axis, *at = nd->at;
        return 2;
    }
    if (nd->kind == IC_CELL_REFUSED) {
        ic_certificate_refuse(c, "%s: cells[%ld]: a cell the file's cover left undecided (%s)",
                              p->where, k, p->reason[0] ? p->reason : "the file gives no reason");
        return 0;
    }
    const int rc = ic_certify_leaf(c, i, lim);
    if (rc < 0)
        return -1;
    if (rc == 0 || c->cells[i].kind != nd->kind) {
        ic_certificate_refuse(c, "%s: cells[%ld]: the file says %s, the check finds %s", p->where, k,
                              ic_cell_kind_name(nd->kind),
                              rc == 0 ? "neither that nor any other leaf"
                                      : ic_cell_kind_name(c->cells[i].kind));
        return 0;
    }
    return nd->kind != IC_CELL_REGULAR || same_crossings(c, i, k);
}
