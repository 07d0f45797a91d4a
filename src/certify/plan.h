/*
 * A certificate file's cover, to be checked again (docs/tracing.md, "The
 * certificate file"; docs/output-formats.md). The file is the tree of cells
 * in preorder (a split, then its lower half's subtree, then its upper
 * half's) with each leaf's kind and a regular leaf's crossings. Replaying it
 * (replay.c) takes only the splits from the file: every leaf is proven
 * afresh by ic_certify_leaf, and its kind and crossings must be the file's.
 * A file therefore cannot make the checker accept what it would refuse; it
 * spares the search for the cover, and says what was proven, cell by cell.
 */
#ifndef IC_CERTIFY_PLAN_H
#define IC_CERTIFY_PLAN_H

#include <stdio.h>

#include "certificate.h"

/* The format's name and version, written and required. */
#define IC_CERTIFY_FILE_FORMAT "intercurve-certificate"
#define IC_CERTIFY_FILE_VERSION 1

/* A crossing as the file gives it: the face and side of the cell, the box
 * face (-1: none; certificate.h, ic_crossing.box), and the centre of its
 * enclosure narrowed by ic_certify_tighten, which must lie in the
 * enclosure the check finds, narrowed the same way. */
typedef struct {
    int face, side, box;
    double z[4];
} ic_plan_crossing;

typedef struct {
    ic_cell_kind kind; /* IC_CELL_SPLIT, a leaf's kind, IC_CELL_REFUSED: undecided */
    int axis;          /* split: the coordinate; regular: the monotone one */
    double at;         /* split: where */
    long first;        /* regular: its crossings, crossings[first..] */
    int ncross, nbox;  /* of the faces, then of the box */
} ic_plan_node;

struct ic_cover_plan {
    char pairing[64];
    int dim;
    double lo[4], hi[4];
    double origin[4]; /* where the region was moved from (region.origin; 0 absent) */
    ic_plan_node *nodes;
    long nnodes;
    ic_plan_crossing *crossings;
    long ncrossings;
    /* the file's name, for messages, and the reason it gives for a refusal */
    char where[200];
    char reason[240];
};

/* A leaf kind's name in the file ("split" for a split, "undecided" for a
 * cell the cover did not decide), and back: -1 for an unknown name. */
const char *ic_cell_kind_name(ic_cell_kind kind);
int ic_cell_kind_from_name(const char *name);

void ic_cover_plan_free(ic_cover_plan *p);

/* The plan is one whole tree over c's region: its pairing, dimension and
 * region are c's, every split's axis is a coordinate and its value lies
 * strictly inside the cell it splits, no deeper than the cover may be, and
 * the tree ends with the last node. IC_OK, or IC_ERR_INVALID saying which
 * node ("WHERE[N]: ..."). */
ic_status ic_cover_plan_check(const ic_cover_plan *p, const ic_certificate *c, ic_error *err);

/* The deepest cover, in levels (cover.c's stack holds two cells a level). */
#define IC_CERTIFY_MAX_LEVELS 2047

/* Node k of c->plan for cell i (replay.c): a split returns 2 with its
 * axis and value, for the cover to make; a leaf is proven by
 * ic_certify_leaf and must be what the node says: 1 it is, 0 refused (the
 * reason names the node), -1 out of memory. */
int ic_certify_replay_node(ic_certificate *c, long i, long k, const ic_certify_limits *lim,
                           int *axis, double *at);

/* The cover c as a certificate file (cover_doc.c): its region, its
 * singular boxes and tubes, the verdict, and the tree; IC_ERR_IO when f
 * fails. */
ic_status ic_certificate_write_cover(FILE *f, const ic_certificate *c, ic_error *err);

/* The file of a check that did not run: format, version, checked false
 * and the reason. */
ic_status ic_certificate_write_unchecked(FILE *f, const char *reason, ic_error *err);

#endif
