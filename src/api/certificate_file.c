/*
 * A trace's certificate file written, and a certificate file read into the
 * cover to replay (api.h; certify/plan.h; docs/output-formats.md, "The
 * certificate file"). Only the file's shape is checked here, each error
 * naming its JSON path; whether its tree fits the problem's region, and
 * whether its leaves hold, the replay decides.
 */
#include "api/api.h"
#include "certify/plan.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* An integer in lo..hi, in *out; 0 when x is not one. */
static int integer(const cJSON *x, int lo, int hi, int *out)
{
    if (!cJSON_IsNumber(x) || !(x->valuedouble >= lo && x->valuedouble <= hi) ||
        x->valuedouble != floor(x->valuedouble))
        return 0;
    *out = (int)x->valuedouble;
    return 1;
}

/* n finite numbers into out; 0 when a is not such an array. */
static int finite_numbers(const cJSON *a, double *out, int n)
{
    if (!cJSON_IsArray(a) || cJSON_GetArraySize(a) != n)
        return 0;
    int i = 0;
    for (const cJSON *x = a->child; x; x = x->next, i++) {
        if (!cJSON_IsNumber(x) || !isfinite(x->valuedouble))
            return 0;
        out[i] = x->valuedouble;
    }
    return 1;
}

/* The header: format, version, pairing, dimension, region. */
static ic_status read_head(const cJSON *doc, const char *name, ic_cover_plan *p, ic_error *err)
{
    const cJSON *pairing = cJSON_GetObjectItemCaseSensitive(doc, "pairing");
    const cJSON *region = cJSON_GetObjectItemCaseSensitive(doc, "region");
    if (!cJSON_IsString(pairing) || strlen(pairing->valuestring) >= sizeof p->pairing)
        return ic_error_set(err, IC_ERR_INVALID, 0, "%s: pairing: not a pairing's name", name);
    strcpy(p->pairing, pairing->valuestring);
    if (!integer(cJSON_GetObjectItemCaseSensitive(doc, "dimension"), 2, 4, &p->dim))
        return ic_error_set(err, IC_ERR_INVALID, 0, "%s: dimension: not 2, 3 or 4", name);
    if (!finite_numbers(cJSON_GetObjectItemCaseSensitive(region, "lo"), p->lo, p->dim) ||
        !finite_numbers(cJSON_GetObjectItemCaseSensitive(region, "hi"), p->hi, p->dim))
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            "%s: region: lo and hi must be %d finite numbers each", name, p->dim);
    const cJSON *origin = cJSON_GetObjectItemCaseSensitive(region, "origin");
    if (origin && !finite_numbers(origin, p->origin, p->dim))
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            "%s: region: origin must be %d finite numbers", name, p->dim);
    return IC_OK;
}

/* One crossing of node k, item j of its list. */
static ic_status read_crossing(const cJSON *x, const char *name, long k, int j,
                               ic_cover_plan *p, ic_error *err)
{
    ic_plan_crossing *c = &p->crossings[p->ncrossings];
    if (!cJSON_IsArray(x) || cJSON_GetArraySize(x) != 4 ||
        !integer(cJSON_GetArrayItem(x, 0), -1, p->dim - 1, &c->face) ||
        !integer(cJSON_GetArrayItem(x, 1), 0, 1, &c->side) ||
        !integer(cJSON_GetArrayItem(x, 2), -1, 5, &c->box) ||
        !finite_numbers(cJSON_GetArrayItem(x, 3), c->z, p->dim))
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            "%s: cells[%ld][2][%d]: a crossing is [face -1..%d, side 0 or 1, "
                            "box -1..5, [%d numbers]]",
                            name, k, j, p->dim - 1, p->dim);
    p->ncrossings++;
    return IC_OK;
}

/* A regular node's crossings: the face crossings (box -1) then the box's. */
static ic_status read_crossings(const cJSON *list, const char *name, long k, ic_plan_node *nd,
                                ic_cover_plan *p, ic_error *err)
{
    if (!cJSON_IsArray(list))
        return ic_error_set(err, IC_ERR_INVALID, 0, "%s: cells[%ld][2]: not an array", name, k);
    nd->first = p->ncrossings;
    int j = 0;
    for (const cJSON *x = list->child; x; x = x->next, j++) {
        const ic_status st = read_crossing(x, name, k, j, p, err);
        if (st != IC_OK)
            return st;
        const ic_plan_crossing *x_read = &p->crossings[p->ncrossings - 1];
        if ((x_read->face < 0) != (x_read->box >= 0))
            return ic_error_set(err, IC_ERR_INVALID, 0,
                                "%s: cells[%ld][2][%d]: a crossing of a face (0..%d) has box -1, "
                                "one of the box (face -1) a box face 0..5",
                                name, k, j, p->dim - 1);
        if (x_read->box < 0)
            nd->ncross++;
        else
            nd->nbox++;
    }
    return IC_OK;
}

/* Node k: [kind], ["split", axis, at] or ["regular", axis, [crossings]]. */
static ic_status read_node(const cJSON *a, const char *name, long k, ic_cover_plan *p,
                           ic_error *err)
{
    ic_plan_node *nd = &p->nodes[k];
    memset(nd, 0, sizeof *nd);
    const cJSON *kind = cJSON_IsArray(a) ? a->child : NULL;
    const int kk = cJSON_IsString(kind) ? ic_cell_kind_from_name(kind->valuestring) : -1;
    if (kk < 0)
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            "%s: cells[%ld]: not [kind, ...] with kind split, empty, outside, "
                            "diagonal, regular, singular, tangential or undecided",
                            name, k);
    nd->kind = (ic_cell_kind)kk;
    const int n = cJSON_GetArraySize(a);
    const int want = nd->kind == IC_CELL_SPLIT || nd->kind == IC_CELL_REGULAR ? 3 : 1;
    if (n != want || (want == 3 && !integer(cJSON_GetArrayItem(a, 1), 0, p->dim - 1, &nd->axis)))
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            "%s: cells[%ld]: a node of kind %s is %s", name, k,
                            kind->valuestring,
                            want == 1 ? "its kind alone"
                                      : "[kind, axis 0..dimension-1, at or crossings]");
    if (nd->kind == IC_CELL_SPLIT) {
        const cJSON *at = cJSON_GetArrayItem(a, 2);
        if (!cJSON_IsNumber(at) || !isfinite(at->valuedouble))
            return ic_error_set(err, IC_ERR_INVALID, 0, "%s: cells[%ld][2]: not a number",
                                name, k);
        nd->at = at->valuedouble;
    }
    return nd->kind == IC_CELL_REGULAR ? read_crossings(cJSON_GetArrayItem(a, 2), name, k, nd,
                                                        p, err)
                                       : IC_OK;
}

/* Every crossing of the file, counted first to size the block. */
static long count_crossings(const cJSON *cells)
{
    long n = 0;
    for (const cJSON *a = cells->child; a; a = a->next) {
        const cJSON *list = cJSON_GetArrayItem(a, 2);
        if (cJSON_IsArray(a) && cJSON_GetArraySize(a) == 3 && cJSON_IsArray(list))
            n += cJSON_GetArraySize(list);
    }
    return n;
}

static ic_status read_cells(const cJSON *doc, const char *name, ic_cover_plan *p, ic_error *err)
{
    const cJSON *cells = cJSON_GetObjectItemCaseSensitive(doc, "cells");
    if (!cJSON_IsArray(cells))
        return ic_error_set(err, IC_ERR_INVALID, 0, "%s: cells: not an array", name);
    const long n = cJSON_GetArraySize(cells);
    p->nodes = malloc((size_t)(n + 1) * sizeof *p->nodes);
    p->crossings = malloc((size_t)(count_crossings(cells) + 1) * sizeof *p->crossings);
    if (!p->nodes || !p->crossings)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory reading %s", name);
    long k = 0;
    for (const cJSON *a = cells->child; a; a = a->next, k++) {
        const ic_status st = read_node(a, name, k, p, err);
        if (st != IC_OK)
            return st;
    }
    p->nnodes = n;
    return IC_OK;
}

/* format, version and checked; the reason of an unchecked file. */
static ic_status read_kind(const cJSON *doc, const char *name, int *checked, char *reason,
                           size_t size, ic_error *err)
{
    const cJSON *format = cJSON_GetObjectItemCaseSensitive(doc, "format");
    if (!cJSON_IsString(format) || strcmp(format->valuestring, IC_CERTIFY_FILE_FORMAT) != 0)
        return ic_error_set(err, IC_ERR_INVALID, 0, "%s: format: not \"%s\"", name,
                            IC_CERTIFY_FILE_FORMAT);
    int version = 0;
    if (!integer(cJSON_GetObjectItemCaseSensitive(doc, "version"), 0, 1000000, &version) ||
        version != IC_CERTIFY_FILE_VERSION)
        return ic_error_set(err, IC_ERR_INVALID, 0, "%s: version: this build reads version %d",
                            name, IC_CERTIFY_FILE_VERSION);
    const cJSON *c = cJSON_GetObjectItemCaseSensitive(doc, "checked");
    if (!cJSON_IsBool(c))
        return ic_error_set(err, IC_ERR_INVALID, 0, "%s: checked: not true or false", name);
    *checked = cJSON_IsTrue(c);
    const cJSON *r = cJSON_GetObjectItemCaseSensitive(doc, "reason");
    snprintf(reason, size, "%s", cJSON_IsString(r) ? r->valuestring : "");
    return IC_OK;
}

ic_status ic_api_read_certificate(const char *text, const char *name, ic_cover_plan **plan,
                                  char *reason, size_t size, ic_error *err)
{
    *plan = NULL;
    const char *end = NULL;
    cJSON *doc = cJSON_ParseWithOpts(text, &end, 1); /* nothing after the document */
    if (!doc)
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            "%s: not one JSON document (it stops being one at byte %ld)", name,
                            end ? (long)(end - text) : 0L);
    int checked = 0;
    ic_status st = read_kind(doc, name, &checked, reason, size, err);
    ic_cover_plan *p = st == IC_OK && checked ? calloc(1, sizeof *p) : NULL;
    if (st == IC_OK && checked && !p)
        st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory reading %s", name);
    if (p) {
        snprintf(p->where, sizeof p->where, "%s", name);
        snprintf(p->reason, sizeof p->reason, "%s", reason);
        st = read_head(doc, name, p, err);
        if (st == IC_OK)
            st = read_cells(doc, name, p, err);
    }
    cJSON_Delete(doc);
    if (st != IC_OK)
        ic_cover_plan_free(p);
    else
        *plan = p;
    return st;
}

ic_status ic_api_write_certificate(FILE *f, void *res, ic_error *err)
{
    const ic_trace_result *r = res;
    const char *doc = ic_trace_result_certificate(r);
    if (doc) {
        fputs(doc, f);
        return ferror(f) ? ic_error_set(err, IC_ERR_IO, 0, "writing the certificate failed")
                         : IC_OK;
    }
    return ic_certificate_write_unchecked(f, ic_api_unchecked_reason(r), err);
}

const char *ic_api_unchecked_reason(const ic_trace_result *r)
{
    const ic_trace_report *rep = ic_trace_result_report(r);
    return !rep->tracer_complete
               ? "the tracer did not find the whole intersection by its own account (the "
                 "report's failures say why)"
               : "the checker was not run (the report's failures say why)";
}
