/*
 * `intercurve verify` (api.h): a saved trace document checked again without
 * the tracer (docs/tracing.md, "The certificate"). Its curves are read from
 * the document, put in the pairing's search coordinates, and held against a
 * cover grown afresh from the problem's surfaces: the certify layer's check,
 * with the document's own search size as its work limit.
 */
#include "api/api.h"
#include "certify/match.h"
#include "certify/plan.h"
#include "local/pair_access.h"
#include "trace/certify_result.h"
#include "trace/frame.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A number array of n numbers into out; 0 when it is not one. */
static int numbers(const cJSON *a, double *out, int n)
{
    if (!cJSON_IsArray(a) || cJSON_GetArraySize(a) != n)
        return 0;
    int i = 0;
    for (const cJSON *x = a->child; x; x = x->next, i++) {
        if (!cJSON_IsNumber(x))
            return 0;
        out[i] = x->valuedouble;
    }
    return 1;
}

/* One point's xyz and params (null for an implicit sheet). */
static int read_point(const cJSON *p, double xyz[3], double params[2][2])
{
    memset(params, 0, 4 * sizeof(double));
    if (!numbers(cJSON_GetObjectItemCaseSensitive(p, "xyz"), xyz, 3))
        return 0;
    const cJSON *pr = cJSON_GetObjectItemCaseSensitive(p, "params");
    if (!cJSON_IsArray(pr) || cJSON_GetArraySize(pr) != 2)
        return 0;
    for (int s = 0; s < 2; s++) {
        const cJSON *uv = cJSON_GetArrayItem(pr, s);
        if (!cJSON_IsNull(uv) && !numbers(uv, params[s], 2))
            return 0;
    }
    return 1;
}

/* The document's curves in search coordinates: curves[] and one block of
 * points (*z, the caller's to free). */
static ic_status read_curves(const cJSON *doc, const ic_pairing *pg, const char *name,
                             ic_certify_curve **curves, int *n, double **z, ic_error *err)
{
    const cJSON *cs = cJSON_GetObjectItemCaseSensitive(doc, "curves");
    if (!cJSON_IsArray(cs))
        return ic_error_set(err, IC_ERR_INVALID, 0, "%s: curves: not an array", name);
    const int dim = pg->kind->dim;
    size_t total = 0;
    *n = cJSON_GetArraySize(cs);
    for (const cJSON *c = cs->child; c; c = c->next)
        total += (size_t)cJSON_GetArraySize(cJSON_GetObjectItemCaseSensitive(c, "points"));
    *curves = calloc((size_t)*n + 1, sizeof **curves);
    *z = malloc((total + 1) * (size_t)dim * sizeof **z);
    if (!*curves || !*z)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory reading %s", name);
    size_t at = 0;
    int k = 0;
    for (const cJSON *c = cs->child; c; c = c->next, k++) {
        const cJSON *pts = cJSON_GetObjectItemCaseSensitive(c, "points");
        if (!cJSON_IsArray(pts))
            return ic_error_set(err, IC_ERR_INVALID, 0, "%s: curves[%d].points: not an array",
                                name, k);
        const int closed = cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(c, "closed"));
        const cJSON *type = cJSON_GetObjectItemCaseSensitive(c, "type");
        const int tangential =
            cJSON_IsString(type) && strcmp(type->valuestring, "tangential") == 0;
        (*curves)[k] =
            (ic_certify_curve){*z + at * (size_t)dim, cJSON_GetArraySize(pts), closed, tangential};
        int i = 0;
        for (const cJSON *p = pts->child; p; p = p->next, i++, at++) {
            double xyz[3], params[2][2];
            if (!read_point(p, xyz, params))
                return ic_error_set(err, IC_ERR_INVALID, 0,
                                    "%s: curves[%d].points[%d]: xyz must be 3 numbers and "
                                    "params two [u, v] pairs or null",
                                    name, k, i);
            ic_frame_move(&pg->frame, -1.0, xyz, params); /* where the check runs */
            pg->kind->flatten(pg, xyz, params, *z + at * (size_t)dim);
        }
    }
    return IC_OK;
}

/* A point's box size by its type, as the tracer's result gives it
 * (certify_result.c): cusps, tacnodes and higher-order contacts wider. */
static double box_scale(const cJSON *q)
{
    const cJSON *t = cJSON_GetObjectItemCaseSensitive(q, "type");
    const int wide = cJSON_IsString(t) && (strcmp(t->valuestring, "cusp") == 0 ||
                                           strcmp(t->valuestring, "tacnode") == 0 ||
                                           strcmp(t->valuestring, "higher-order-contact") == 0);
    return wide ? IC_CERTIFY_CONTACT_SCALE : 1.0;
}

/* A point's type as the document names it, or -1. */
static int point_type(const cJSON *q)
{
    const cJSON *t = cJSON_GetObjectItemCaseSensitive(q, "type");
    for (int k = IC_POINT_TRANSVERSAL; cJSON_IsString(t) && k <= IC_POINT_SURFACE_SINGULAR; k++)
        if (strcmp(t->valuestring, ic_point_type_name((ic_point_type)k)) == 0)
            return k;
    return -1;
}

/* The most passages of curves through a point's box, from its type,
 * branches and approximate (ic_certify_passages_allowed); -1 when the
 * document does not say them. */
static int passages_allowed(const cJSON *q)
{
    const int type = point_type(q);
    const cJSON *b = cJSON_GetObjectItemCaseSensitive(q, "branches");
    const cJSON *a = cJSON_GetObjectItemCaseSensitive(q, "approximate");
    /* a count the tracer could give (IC_LOCAL_MAX_BRANCHES at most), else
     * not bounded: never a cast of a number out of int's range */
    if (type < 0 || !cJSON_IsNumber(b) || !cJSON_IsBool(a) || !(b->valuedouble >= 0) ||
        b->valuedouble > IC_LOCAL_MAX_BRANCHES || b->valuedouble != floor(b->valuedouble))
        return -1;
    return ic_certify_passages_allowed((ic_point_type)type, (int)b->valuedouble,
                                       cJSON_IsTrue(a));
}

/* The document's singular points (points[].xyz): *p, their boxes' sizes
 * *scale, the passages their types allow and whether each is a surface's
 * own singular point, the caller's to free, and their number. */
static ic_status read_singular(const cJSON *doc, const char *name, const ic_frame *fr,
                               double (**p)[3],
                               double **scale, int **passages, int *n,
                               ic_error *err)
{
    const cJSON *ps = cJSON_GetObjectItemCaseSensitive(doc, "points");
    if (ps && !cJSON_IsArray(ps))
        return ic_error_set(err, IC_ERR_INVALID, 0, "%s: points: not an array", name);
    *n = ps ? cJSON_GetArraySize(ps) : 0;
    *p = malloc((size_t)(*n + 1) * sizeof **p);
    *scale = malloc((size_t)(*n + 1) * sizeof **scale);
    *passages = malloc((size_t)(*n + 1) * sizeof **passages);
    if (!*p || !*scale || !*passages)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory reading %s", name);
    int k = 0;
    for (const cJSON *q = ps ? ps->child : NULL; q; q = q->next, k++) {
        if (!numbers(cJSON_GetObjectItemCaseSensitive(q, "xyz"), (*p)[k], 3))
            return ic_error_set(err, IC_ERR_INVALID, 0, "%s: points[%d].xyz: must be 3 numbers",
                                name, k);
        ic_frame_move(fr, -1.0, (*p)[k], NULL);
        (*scale)[k] = box_scale(q);
        (*passages)[k] = passages_allowed(q);
    }
    return IC_OK;
}

/* The document's tangential curves (curves[] of type "tangential", read
 * by read_curves already): tubes[] and one block of points (*xyz), the
 * caller's to free. */
static ic_status read_tubes(const cJSON *doc, const char *name, const ic_frame *fr,
                            ic_certify_tube **tubes, int *n, double **xyz, ic_error *err)
{
    const cJSON *cs = cJSON_GetObjectItemCaseSensitive(doc, "curves");
    size_t total = 0;
    *n = 0;
    for (const cJSON *c = cs->child; c; c = c->next)
        total += (size_t)cJSON_GetArraySize(cJSON_GetObjectItemCaseSensitive(c, "points"));
    *tubes = malloc((size_t)(cJSON_GetArraySize(cs) + 1) * sizeof **tubes);
    *xyz = malloc((total + 1) * 3 * sizeof **xyz);
    if (!*tubes || !*xyz)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory reading %s", name);
    size_t at = 0;
    for (const cJSON *c = cs->child; c; c = c->next) {
        const cJSON *type = cJSON_GetObjectItemCaseSensitive(c, "type");
        if (!cJSON_IsString(type) || strcmp(type->valuestring, "tangential") != 0)
            continue;
        const cJSON *pts = cJSON_GetObjectItemCaseSensitive(c, "points");
        const int closed = cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(c, "closed"));
        (*tubes)[(*n)++] = (ic_certify_tube){*xyz + 3 * at, cJSON_GetArraySize(pts), closed};
        for (const cJSON *p = pts->child; p; p = p->next, at++)
            if (numbers(cJSON_GetObjectItemCaseSensitive(p, "xyz"), *xyz + 3 * at, 3))
                ic_frame_move(fr, -1.0, *xyz + 3 * at, NULL);
    }
    return IC_OK;
}

/* The check of the claim: the cover grown, or the file's replayed. */
static ic_status check(const ic_trace_moved *m, const ic_pair *pair, const cJSON *doc,
                       const ic_certify_claim *claim, ic_certify_io *io,
                       ic_trace_certificate *out, ic_error *err)
{
    const cJSON *cells = cJSON_GetObjectItemCaseSensitive(
        cJSON_GetObjectItemCaseSensitive(doc, "report"), "cells");
    const double(*box)[2] = m->box;
    const int has_box = m->has_box;
    const ic_certify_limits lim =
        ic_certify_limits_for(cJSON_IsNumber(cells) ? (long)cells->valuedouble : 0, 0);
    ic_certify_summary s;
    const ic_status st =
        ic_certify_run(ic_pair_pairing(pair), box, has_box, &lim, claim, io, &s, err);
    ic_trace_certificate_from(out, &s);
    out->accepted = st == IC_OK && s.accepted;
    return st;
}

/* The problem moved as its trace was (trace/frame.h), and its box. */
static ic_status moved_problem(ic_trace_moved *m, const ic_problem *problem, ic_pair *pair,
                               ic_error *err)
{
    double box[3][2];
    const int has_box = ic_problem_box(problem, box);
    ic_status st = ic_trace_move(m, pair, box, has_box, err);
    if (st == IC_OK && !m->pair)
        memcpy(m->box, box, sizeof m->box);
    m->has_box = has_box;
    return st;
}

/* The certificate file's cover (NULL: none given), or the verdict of a
 * file that holds none (*done then). */
static ic_status read_plan(const char *cert_text, const char *cert_name, ic_cover_plan **plan,
                           ic_trace_certificate *out, int *done, ic_error *err)
{
    *plan = NULL, *done = 0;
    if (!cert_text)
        return IC_OK;
    char reason[200];
    const ic_status st =
        ic_api_read_certificate(cert_text, cert_name, plan, reason, sizeof reason, err);
    if (st == IC_OK && !*plan) {
        *done = 1;
        out->checked = 1;
        snprintf(out->reason, sizeof out->reason,
                 "%s holds no cover: the trace's check did not run%s%s", cert_name,
                 reason[0] ? ": " : "", reason);
    }
    return st;
}

ic_status ic_api_verify(const ic_problem *problem, const char *doc_text, const char *name,
                        const char *cert_text, const char *cert_name, ic_trace_certificate *out,
                        ic_error *err)
{
    memset(out, 0, sizeof *out);
    cJSON *doc = cJSON_Parse(doc_text);
    if (!doc)
        return ic_error_set(err, IC_ERR_INVALID, 0, "%s: not a JSON document", name);
    ic_pair *pair = NULL;
    ic_certify_curve *curves = NULL;
    double *z = NULL;
    double(*sing)[3] = NULL;
    double *scale = NULL;
    int *passages = NULL;
    ic_certify_tube *tubes = NULL;
    double *txyz = NULL;
    int n = 0, nsing = 0, ntubes = 0;
    ic_trace_moved m = {0};
    ic_status st = ic_api_problem_pair(&pair, problem, err);
    if (st == IC_OK)
        st = moved_problem(&m, problem, pair, err);
    ic_pair *checked = m.pair ? m.pair : pair;
    const ic_frame *fr = &ic_pair_pairing(checked)->frame;
    if (st == IC_OK)
        st = read_curves(doc, ic_pair_pairing(checked), name, &curves, &n, &z, err);
    if (st == IC_OK)
        st = read_singular(doc, name, fr, &sing, &scale, &passages, &nsing, err);
    if (st == IC_OK)
        st = read_tubes(doc, name, fr, &tubes, &ntubes, &txyz, err);
    ic_cover_plan *plan = NULL;
    int done = 0;
    if (st == IC_OK)
        st = read_plan(cert_text, cert_name, &plan, out, &done, err);
    if (st == IC_OK && !done) {
        const ic_certify_claim claim = {.curves = curves,
                                        .ncurves = n,
                                        .singular = (const double(*)[3])sing,
                                        .singular_scale = scale,
                                        .singular_passages = passages,
                                        .nsingular = nsing,
                                        .tubes = tubes,
                                        .ntubes = ntubes};
        ic_certify_io io = {.replay = plan};
        st = check(&m, checked, doc, &claim, &io, out, err);
    }
    ic_cover_plan_free(plan);
    free(curves);
    free(z);
    free(sing);
    free(scale);
    free(passages);
    free(tubes);
    free(txyz);
    ic_trace_moved_release(&m);
    ic_pair_free(pair);
    cJSON_Delete(doc);
    return st;
}
