/* IGES 5.x files (fixed 80-column records in sections S, G, D, P, T): the
 * records, the global section, the directory entries and the free-format
 * parameter data, for the CAD reader (cad.h). */
#ifndef IC_IGES_PARSE_H
#define IC_IGES_PARSE_H

#include <stddef.h>

#include "intercurve/common.h"

/* Most parameters of one entity. */
#define IC_IGES_MAX_PARAMS (4 * 1000000 + 64)

typedef struct {
    size_t at; /* the record's first byte in the text */
    int len;   /* its bytes, at most 80 (a shorter record reads as blanks after) */
} ic_iges_line;

typedef struct {
    int de;        /* directory-entry number: its first line's number in D (odd) */
    int type, form;
    int pointer;   /* first parameter line (1-based in P) */
    int nlines;    /* parameter lines */
    int matrix;    /* DE of the transformation matrix (124), 0 when none */
    char label[9];
    int subscript;
} ic_iges_entry;

typedef enum { IC_IGES_EMPTY, IC_IGES_NUMBER, IC_IGES_STRING } ic_iges_kind;

typedef struct {
    ic_iges_kind kind;
    double number;
    size_t at, len; /* IC_IGES_STRING: its characters in the owner's text */
} ic_iges_param;

/* A record of free-format parameters (global section, or one entity's). */
typedef struct {
    char *text; /* the concatenated columns */
    ic_iges_param *p;
    int n;
} ic_iges_params;

typedef struct {
    const char *text;
    size_t len;
    ic_iges_line *lines;
    int nlines;
    int first[4], count[4]; /* sections S, G, D, P: first line index and count */
    char pdelim, rdelim;
    ic_iges_params global;
    ic_iges_entry *entries; /* entries[k] is DE 2k + 1 */
    int nentries;
} ic_iges_file;

/* Reads the records, the global section and the directory. IC_ERR_PARSE
 * (IC_ERR_INVALID for the unsupported compressed and binary forms) with the
 * line and what is wrong; *f is then empty. */
ic_status ic_iges_parse(ic_iges_file *f, const char *text, size_t len, ic_error *err);
void ic_iges_free(ic_iges_file *f);

/* The directory entry DE `de`, or NULL. */
const ic_iges_entry *ic_iges_entry_at(const ic_iges_file *f, int de);
/* The parameters of entry e, the entity type first. */
ic_status ic_iges_entity_params(const ic_iges_file *f, const ic_iges_entry *e, ic_iges_params *out,
                                ic_error *err);
void ic_iges_params_free(ic_iges_params *p);
/* Parameter k as a number (an empty one is 0): 0, or -1. */
int ic_iges_number(const ic_iges_params *p, int k, double *x);
/* Parameter k as text into out (empty when not a string). */
void ic_iges_string(const ic_iges_params *p, int k, char *out, size_t size);

#endif
