/* The descriptions of CAD surfaces (cad_types.h) and what both format
 * readers share of them (cad_internal.h): freeing a description, growing a
 * list, and the message naming the entity at fault. Below the readers and
 * the dispatcher, calling neither. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cad_internal.h"

ic_status ic_cad_fail(ic_error *err, const char *who, const char *fmt, ...)
{
    char msg[IC_ERROR_MESSAGE_LEN];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    return ic_error_set(err, IC_ERR_INVALID, 0, "%s: %s", who, msg);
}

void ic_cad_surface_clear(ic_cad_surface *s)
{
    if (!s)
        return;
    free(s->knots_store);
    free(s->points_store);
    free(s->weights_store);
    memset(s, 0, sizeof *s);
}

void ic_cad_list_free(ic_cad_surface *list, int n)
{
    for (int k = 0; list && k < n; k++)
        ic_cad_surface_clear(&list[k]);
    free(list);
}

ic_status ic_cad_list_append(ic_cad_surface **list, int *n, int *cap, ic_cad_surface *s,
                             ic_error *err)
{
    if (*n == *cap) {
        const int grown = *cap ? 2 * *cap : 16;
        ic_cad_surface *l = realloc(*list, (size_t)grown * sizeof *l);
        if (!l) {
            ic_cad_surface_clear(s);
            return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory listing the surfaces");
        }
        *list = l;
        *cap = grown;
    }
    (*list)[(*n)++] = *s;
    memset(s, 0, sizeof *s);
    return IC_OK;
}
