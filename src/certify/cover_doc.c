/*
 * The certificate file (plan.h; docs/output-formats.md, "The certificate
 * file"): the cover of a check as JSON, the tree in preorder, each node an
 * array: ["split", axis, at], ["regular", axis, [crossings]], or a leaf's
 * kind alone (["empty"], ["outside"], ["diagonal"], ["singular"],
 * ["tangential"], ["undecided"]). A crossing is [face, side, box, [point]].
 */
#include "plan.h"
#include "json/json_out.h"

#include <stdlib.h>

static void write_crossings(json_out *j, const ic_certificate *c, const ic_cell *cl)
{
    ic_json_out_array(j);
    for (int x = cl->first; x < cl->first + cl->ncross + cl->nbox; x++) {
        ic_crossing tight = c->cross[x], *cr = &tight;
        ic_certify_tighten(c, cr); /* the root to a few ulps, for the file's reader */
        double mid[4];
        for (int d = 0; d < c->dim; d++)
            mid[d] = 0.5 * cr->K[d].lo + 0.5 * cr->K[d].hi;
        ic_json_out_array(j);
        ic_json_out_int(j, cr->face);
        ic_json_out_int(j, cr->side);
        ic_json_out_int(j, cr->box);
        ic_json_out_vector(j, mid, c->dim);
        ic_json_out_end_array(j);
    }
    ic_json_out_end_array(j);
}

static void write_node(json_out *j, const ic_certificate *c, const ic_cell *cl)
{
    ic_json_out_array(j);
    ic_json_out_string(j, ic_cell_kind_name(cl->kind));
    if (cl->kind == IC_CELL_SPLIT || cl->kind == IC_CELL_REGULAR)
        ic_json_out_int(j, cl->axis);
    if (cl->kind == IC_CELL_SPLIT)
        ic_json_out_number(j, cl->at);
    if (cl->kind == IC_CELL_REGULAR)
        write_crossings(j, c, cl);
    ic_json_out_end_array(j);
}

/* The tree in preorder, the lower half first; 0 out of memory. */
static int write_tree(json_out *j, const ic_certificate *c)
{
    long *stack = malloc((size_t)(c->ncells + 1) * sizeof *stack);
    if (!stack)
        return 0;
    long n = 0;
    stack[n++] = 0;
    ic_json_out_array(j);
    while (n > 0) {
        const ic_cell *cl = &c->cells[stack[--n]];
        write_node(j, c, cl);
        if (cl->kind == IC_CELL_SPLIT) {
            stack[n++] = cl->child[1];
            stack[n++] = cl->child[0];
        }
    }
    ic_json_out_end_array(j);
    free(stack);
    return 1;
}

static void write_region(json_out *j, const ic_certificate *c)
{
    int periodic[4];
    for (int k = 0; k < c->dim; k++)
        periodic[k] = c->periodic[k] != 0;
    ic_json_out_key(j, "region");
    ic_json_out_object(j);
    ic_json_out_key(j, "lo");
    ic_json_out_vector(j, c->lo, c->dim);
    ic_json_out_key(j, "hi");
    ic_json_out_vector(j, c->hi, c->dim);
    ic_json_out_key(j, "periodic");
    ic_json_out_ints(j, periodic, c->dim);
    double origin[4];
    int moved = 0;
    for (int k = 0; k < c->dim; k++)
        moved |= (origin[k] = ic_certificate_origin(c, k)) != 0.0;
    if (moved) { /* the problem was moved (docs/tracing.md, "Far from the origin") */
        ic_json_out_key(j, "origin");
        ic_json_out_vector(j, origin, c->dim);
    }
    ic_json_out_end_object(j);
}

/* What the leaves were proven against: the singular boxes (centre, half
 * width) and the tubes' radius; for readers, not read back (the check
 * places its own from the trace). */
static void write_boxes(json_out *j, const ic_certificate *c)
{
    ic_json_out_key(j, "singular_boxes");
    ic_json_out_array(j);
    for (int s = 0; s < c->nsingular; s++) {
        ic_json_out_object(j);
        ic_json_out_key(j, "centre");
        ic_json_out_vector(j, c->singular[s], 3);
        ic_json_out_key(j, "half");
        ic_json_out_number(j, c->singular_half * c->singular_scale[s]);
        ic_json_out_end_object(j);
    }
    ic_json_out_end_array(j);
    ic_json_out_key(j, "tubes");
    ic_json_out_int(j, c->ntubes);
    ic_json_out_key(j, "tube_half");
    ic_json_out_number(j, c->tube_half);
}

static void write_head(json_out *j, int checked)
{
    ic_json_out_key(j, "format");
    ic_json_out_string(j, IC_CERTIFY_FILE_FORMAT);
    ic_json_out_key(j, "version");
    ic_json_out_int(j, IC_CERTIFY_FILE_VERSION);
    ic_json_out_key(j, "checked");
    ic_json_out_bool(j, checked);
}

ic_status ic_certificate_write_cover(FILE *f, const ic_certificate *c, ic_error *err)
{
    json_out j;
    ic_json_out_start(&j, f);
    ic_json_out_object(&j);
    write_head(&j, 1);
    ic_json_out_key(&j, "accepted");
    ic_json_out_bool(&j, c->summary.accepted);
    ic_json_out_key(&j, "reason");
    ic_json_out_string(&j, c->summary.reason);
    ic_json_out_key(&j, "pairing");
    ic_json_out_string(&j, c->pg->kind->name);
    ic_json_out_key(&j, "dimension");
    ic_json_out_int(&j, c->dim);
    write_region(&j, c);
    write_boxes(&j, c);
    ic_json_out_key(&j, "cells");
    const int ok = write_tree(&j, c);
    ic_json_out_end_object(&j);
    const ic_status st = ic_json_out_finish(&j, "certificate", err);
    if (!ok)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory writing the certificate");
    return st;
}

ic_status ic_certificate_write_unchecked(FILE *f, const char *reason, ic_error *err)
{
    json_out j;
    ic_json_out_start(&j, f);
    ic_json_out_object(&j);
    write_head(&j, 0);
    ic_json_out_key(&j, "accepted");
    ic_json_out_bool(&j, 0);
    ic_json_out_key(&j, "reason");
    ic_json_out_string(&j, reason);
    ic_json_out_end_object(&j);
    return ic_json_out_finish(&j, "certificate", err);
}
