/* Building the JSON documents of the writers (writers.h) with cJSON. Every
 * item goes in through these helpers, which remember a failed allocation,
 * so a document is printed whole or reported as out of memory, never
 * printed with a key silently missing. */
#ifndef IC_JSON_OUT_H
#define IC_JSON_OUT_H

#include <cjson/cJSON.h>
#include <stdio.h>

#include "intercurve/common.h"

typedef struct {
    int failed; /* an allocation failed: the document is not whole */
} json_out;

/* A number written so that it reads back to the same double (15 digits
 * where they do, else 17), or null where it is not finite; -0 becomes 0. */
cJSON *ic_json_out_number(json_out *j, double x);
/* An array of n numbers (ic_json_out_number each). */
cJSON *ic_json_out_vector(json_out *j, const double *v, int n);
/* Adds item under key (to obj) or at the end (of array); a NULL item or
 * container, or a failed addition, marks j failed and frees the item. */
void ic_json_out_add(json_out *j, cJSON *obj, const char *key, cJSON *item);
void ic_json_out_append(json_out *j, cJSON *array, cJSON *item);
/* Prints doc (cJSON_Print's layout) and a newline into f and frees doc.
 * IC_ERR_NOMEM when the document is not whole, IC_ERR_IO ("writing the
 * WHAT output failed") when f reports an error. */
ic_status ic_json_out_write(FILE *f, cJSON *doc, const json_out *j, const char *what, ic_error *err);

#endif
