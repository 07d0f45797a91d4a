/* IGES's fixed 80-column records (IGES 5.3, section 2): free-format
 * fields packed into lines of the S, G and P sections, a field never split
 * across two lines, each line ending in its section letter and sequence
 * number. The IGES writer of curves (curve_iges.c) uses it. */
#ifndef IC_IGES_RECORDS_H
#define IC_IGES_RECORDS_H

#include <stdio.h>

typedef struct {
    FILE *f;      /* NULL: only count the lines */
    char section; /* 'S', 'G' or 'P' */
    int width;    /* columns for the data: 72, or 64 in P (then the DE pointer) */
    int de;       /* P: the directory entry the parameters belong to */
    int seq;      /* lines written so far in this section */
    int used;     /* columns used in the line being filled */
    char line[73];
} iges_records;

/* Starts a section (seq 0) writing to f (NULL: counting only). */
void ic_iges_records_start(iges_records *r, FILE *f, char section);
/* Appends text (at most r->width characters) to the current line, or to a
 * new line when it does not fit. */
void ic_iges_records_put(iges_records *r, const char *text);
/* Writes out the line being filled (padded with blanks), if any. */
void ic_iges_records_end_line(iges_records *r);

#endif
