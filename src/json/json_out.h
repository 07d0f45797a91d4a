/* Writing the JSON documents of the writers (writers.h) straight to their
 * stream, in cJSON_Print's layout: an object's members one per line,
 * indented by tabs, "key":<tab>value; an array's items on one line,
 * separated by ", "; objects and arrays both count as a level of
 * indentation. No tree is built, nothing is allocated: a document fails
 * only when its stream does (ic_json_out_finish). The text goes through a
 * buffer of its own: the stream's lock is taken once per buffer, not once
 * per character. */
#ifndef IC_JSON_OUT_H
#define IC_JSON_OUT_H

#include <stdio.h>

#include "intercurve/common.h"

/* deeper than any document of the library */
#define IC_JSON_OUT_MAX_DEPTH 32
/* bytes gathered before each fwrite */
#define IC_JSON_OUT_BUFFER 8192

typedef struct {
    FILE *f;
    int depth;
    /* per level, bit `depth`: the container is an array; it has an item */
    unsigned long arrays, nonempty;
    size_t len; /* bytes in buf not yet written */
    char buf[IC_JSON_OUT_BUFFER];
} json_out;

void ic_json_out_start(json_out *j, FILE *f);
/* The key of an object's next member; its value follows. */
void ic_json_out_key(json_out *j, const char *key);
/* Values: in an array, each after the separator its position needs. */
void ic_json_out_object(json_out *j);
void ic_json_out_end_object(json_out *j);
void ic_json_out_array(json_out *j);
void ic_json_out_end_array(json_out *j);
/* A number written so that it reads back to the same double (15 digits
 * where they do, else 17; json_number.h), or null where it is not finite;
 * -0 becomes 0. */
void ic_json_out_number(json_out *j, double x);
void ic_json_out_int(json_out *j, int x);
/* Escaped as cJSON escapes (quote, backslash, control characters); NULL
 * is written null. */
void ic_json_out_string(json_out *j, const char *s);
void ic_json_out_bool(json_out *j, int b);
void ic_json_out_null(json_out *j);
/* An array of n numbers; of n ints. */
void ic_json_out_vector(json_out *j, const double *v, int n);
void ic_json_out_ints(json_out *j, const int *v, int n);
/* The newline after the document, the buffer written; IC_ERR_IO ("writing the WHAT output
 * failed") when the stream reports an error. */
ic_status ic_json_out_finish(json_out *j, const char *what, ic_error *err);

#endif
