/*
 * What the certificate's tests share (test_certificate.c,
 * test_certificate_singular.c): a problem traced from its JSON text, the
 * verdict of a sweep's case (complete and right, or honestly incomplete),
 * a result's curves in search coordinates, and the checker run by hand on
 * a claim that a test may have mutated.
 */
#ifndef IC_TESTS_CERTIFY_HARNESS_H
#define IC_TESTS_CERTIFY_HARNESS_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "api/api.h"
#include "certify/match.h"
#include "certify/plan.h"
#include "harness.h"
#include "intercurve.h"
#include "local/pair_access.h"

typedef struct {
    ic_problem *problem;
    ic_pair *pair;
    ic_trace_result *res;
    ic_trace_options opt;
} traced;

static inline void release(traced *t)
{
    ic_trace_result_free(t->res);
    ic_pair_free(t->pair);
    ic_problem_free(t->problem);
    memset(t, 0, sizeof *t);
}

/* A problem's JSON text traced with the defaults but a time limit in
 * seconds (0: none), a self-intersection with its one surface, as
 * `intercurve trace` pairs it. */
static inline int trace_json_with(traced *t, const char *name, const char *json,
                                  double time_limit, int keep_certificate)
{
    ic_error err;
    memset(t, 0, sizeof *t);
    ic_trace_defaults(&t->opt);
    t->opt.time_limit = time_limit;
    t->opt.keep_certificate = keep_certificate;
    ic_status st = ic_problem_parse(&t->problem, json, strlen(json), &err);
    if (st == IC_OK) {
        t->opt.has_box = ic_problem_box(t->problem, t->opt.box);
        st = ic_pair_new(&t->pair, ic_problem_surface(t->problem, 0),
                         ic_problem_is_self(t->problem) ? NULL
                                                        : ic_problem_surface(t->problem, 1),
                         &err);
    }
    if (st == IC_OK)
        st = ic_trace(&t->res, t->pair, &t->opt, &err);
    return REQUIRE(st == IC_OK, "%s: %s", name, err.message) ? 0 : -1;
}

static inline int trace_json_limited(traced *t, const char *name, const char *json,
                                     double time_limit)
{
    return trace_json_with(t, name, json, time_limit, 0);
}

/* The same with the certificate file kept (ic_trace_result_certificate). */
static inline int trace_json_keep(traced *t, const char *name, const char *json)
{
    return trace_json_with(t, name, json, 0, 1);
}

/* The same with the defaults. */
static inline int trace_json(traced *t, const char *name, const char *json)
{
    return trace_json_limited(t, name, json, 0.0);
}

/* The first `want` rows of ncols numbers (at most 6) of the truth file
 * tests/truth/NAME under src, lines starting with '#' skipped, into out
 * (row after row): 0, or -1 when the file or a row is missing. */
static inline int read_truth_rows(const char *src, const char *name, int ncols, int want,
                                  double *out)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/tests/truth/%s", src, name);
    FILE *f = fopen(path, "r");
    if (!REQUIRE(f, "cannot open %s", path))
        return -1;
    char line[256];
    int n = 0;
    while (n < want && fgets(line, sizeof line, f)) {
        double v[6];
        if (line[0] != '#' && sscanf(line, "%lf %lf %lf %lf %lf %lf", &v[0], &v[1], &v[2], &v[3],
                                     &v[4], &v[5]) >= ncols) {
            memcpy(out + (size_t)n * (size_t)ncols, v, (size_t)ncols * sizeof *v);
            n++;
        }
    }
    fclose(f);
    return REQUIRE(n == want, "%s: %d rows (want %d)", path, n, want) ? 0 : -1;
}

/* The verdicts of a sweep: `right` counts the tracer's right answers,
 * `missed` the right answers the certificate did not prove. */
typedef struct {
    int cases, proven, honest, right, missed;
} tally;

/* complete and right, or incomplete with the reason listed: never complete
 * and wrong. */
static inline void judge(tally *t, const traced *tr, const char *name, int right)
{
    const ic_trace_report *rep = ic_trace_result_report(tr->res);
    t->cases++;
    t->right += right;
    t->missed += right && !rep->complete;
    if (rep->complete) {
        t->proven++;
        CHECK(right, "%s: complete, and wrong", name);
    } else {
        t->honest++;
        CHECK(rep->nfailures > 0, "%s: incomplete with no failure listed", name);
    }
    printf("%s: %s%s%s\n", name, rep->complete ? "proven" : "not proven: ",
           rep->complete ? "" : rep->certificate.reason,
           rep->complete || rep->certificate.checked ? "" : rep->nfailures ? rep->failures[0] : "");
}

/* The curves of a result in search coordinates (one block, freed by the
 * caller). */
static inline double *search_curves(const traced *t, const ic_pairing *pg, ic_certify_curve *cv)
{
    const int n = ic_trace_result_num_curves(t->res), dim = pg->kind->dim;
    size_t total = 0;
    for (int k = 0; k < n; k++)
        total += (size_t)ic_trace_result_curve(t->res, k)->npoints;
    double *z = malloc((total + 1) * (size_t)dim * sizeof *z);
    size_t at = 0;
    for (int k = 0; z && k < n; k++) {
        const ic_trace_curve *c = ic_trace_result_curve(t->res, k);
        cv[k] = (ic_certify_curve){z + at * (size_t)dim, c->npoints, c->closed, c->tangential};
        for (int i = 0; i < c->npoints; i++, at++) {
            double p[2][2];
            memcpy(p, c->points[i].params, sizeof p);
            pg->kind->flatten(pg, c->points[i].xyz, p, z + at * (size_t)dim);
        }
    }
    return z;
}

/* The cover of a check replayed from its certificate file (plan.h) gives
 * the same verdict, the same reason and the same cells and crossings: the
 * file holds the cover whole, and the replay proves each leaf as growing it
 * did (a cover refused where it could not decide a cell is refused at that
 * cell, with the replay's own reason). 1 so, 0 the test failed. */
static inline int same_on_replay(const ic_pairing *pg, const traced *t, const ic_certify_limits *lim,
                                 const ic_certify_claim *claim, const ic_certify_io *grown,
                                 const ic_certify_summary *s)
{
    ic_error err;
    ic_cover_plan *plan = NULL;
    char why[200];
    if (!REQUIRE(ic_api_read_certificate(grown->doc, "CERT", &plan, why, sizeof why, &err) ==
                         IC_OK &&
                     plan,
                 "certificate file: %s", err.message))
        return 0;
    ic_certify_io io = {.replay = plan};
    ic_certify_summary r;
    const ic_status st = ic_certify_run(pg, t->opt.box, t->opt.has_box, lim, claim, &io, &r, &err);
    ic_cover_plan_free(plan);
    return REQUIRE(st == IC_OK, "replay: %s", err.message) &&
           REQUIRE(r.accepted == s->accepted && r.cells == s->cells && r.empty == s->empty &&
                       r.regular == s->regular && r.crossings == s->crossings &&
                       (strcmp(r.reason, s->reason) == 0 ||
                        (!s->accepted && strstr(r.reason, "left undecided"))),
                   "replay: accepted %d, %ld cells, %ld regular, %ld crossings (%s); grown: %d, "
                   "%ld, %ld, %ld (%s)",
                   r.accepted, r.cells, r.regular, r.crossings, r.reason, s->accepted, s->cells,
                   s->regular, s->crossings, s->reason);
}

/* The checker's verdict on the cover of t's region and the claim (its
 * singular points, tangential tubes and curves), as ic_certify_run gives
 * it, and the same on its certificate file's replay (same_on_replay). With `drop_crossing` (no tubes), the cover grown by hand loses one
 * crossing of its first regular cell that has any (a crossing count off by
 * one). 1 accepted, 0 refused (reason says why), -1 the test failed. */
static inline int verdict_of(const traced *t, const ic_certify_claim *claim, int drop_crossing,
                             char *reason)
{
    const ic_pairing *pg = ic_pair_pairing(t->pair);
    ic_error err;
    if (!drop_crossing) { /* the checker as the tracer runs it */
        const ic_certify_limits lim = ic_certify_limits_for(200000, 0);
        ic_certify_summary s;
        ic_certify_io io = {.keep = 1};
        if (!REQUIRE(ic_certify_run(pg, t->opt.box, t->opt.has_box, &lim, claim, &io, &s,
                                    &err) == IC_OK,
                     "certify: %s", err.message))
            return -1;
        const int same = same_on_replay(pg, t, &lim, claim, &io, &s);
        free(io.doc);
        snprintf(reason, 240, "%s", s.reason);
        return same ? s.accepted : -1;
    }
    ic_certificate *c = ic_certificate_new(pg, t->opt.box, t->opt.has_box, &err);
    if (!REQUIRE(c, "certificate: %s", err.message))
        return -1;
    const ic_certify_limits lim = {200000, 1e-6, 256, 0};
    int ok = ic_certificate_set_singular(c, claim->singular, claim->singular_scale,
                                         claim->nsingular) > 0 &&
             ic_certificate_add_corner_ends(c, claim->curves, claim->ncurves) > 0 &&
             ic_certify_cover(c, &lim, &err) == IC_OK && c->summary.accepted;
    for (long i = 0; ok && drop_crossing && i < c->ncells; i++) {
        ic_cell *cl = &c->cells[i];
        if (cl->kind == IC_CELL_REGULAR && cl->ncross > 0) {
            cl->ncross--; /* its last crossing is no longer the cell's */
            drop_crossing = 0;
        }
    }
    if (ok)
        ok = ic_certify_curves(c, claim->curves, claim->ncurves, &err) == IC_OK &&
             c->summary.accepted;
    snprintf(reason, 240, "%s", c->summary.reason);
    ic_certificate_free(c);
    return ok;
}

/* The verdict of `verify` on the saved document, mutated by `how`: 0 as
 * traced, 1 its first curve dropped, 2 its first curve doubled, 3 its
 * branch point moved by 1e-3 along x; cert: replay the certificate file.
 * 1 accepted, 0 refused, -1 the test failed. */
static inline int verify_doc(const traced *t, const char *name, int how, const char *cert)
{
    char *doc = NULL;
    size_t len = 0;
    ic_error err;
    if (!REQUIRE(ic_trace_json_alloc(&doc, &len, t->res, t->pair, &err) == IC_OK, "%s: %s", name,
                 err.message))
        return -1;
    cJSON *j = cJSON_Parse(doc);
    ic_free(doc);
    cJSON *curves = cJSON_GetObjectItemCaseSensitive(j, "curves");
    if (how == 1)
        cJSON_DeleteItemFromArray(curves, 0);
    if (how == 2)
        cJSON_AddItemToArray(curves, cJSON_Duplicate(cJSON_GetArrayItem(curves, 0), 1));
    if (how == 3) {
        cJSON *x = cJSON_GetArrayItem(cJSON_GetObjectItemCaseSensitive(
                                          cJSON_GetArrayItem(cJSON_GetObjectItemCaseSensitive(
                                                                 j, "points"),
                                                             0),
                                          "xyz"),
                                      0);
        cJSON_SetNumberValue(x, x->valuedouble + 1e-3);
    }
    char *text = cJSON_PrintUnformatted(j);
    cJSON_Delete(j);
    ic_trace_certificate out;
    const ic_status st = cert ? ic_problem_verify_certificate(t->problem, text, cert, &out, &err)
                              : ic_problem_verify(t->problem, text, &out, &err);
    free(text);
    return REQUIRE(st == IC_OK, "%s: verify: %s", name, err.message) ? out.accepted : -1;
}

/* A proven case accepted again by `verify` (grown afresh and from its
 * certificate file, which t must have kept: trace_json_keep) and its
 * mutations refused: a curve dropped, a curve doubled, and where it has
 * special points, the first moved by 1e-3. */
static inline void verify_saved(const traced *t, const char *name)
{
    if (!ic_trace_result_report(t->res)->complete)
        return;
    CHECK(verify_doc(t, name, 0, NULL) == 1, "%s: verify refuses the saved trace", name);
    CHECK(verify_doc(t, name, 0, ic_trace_result_certificate(t->res)) == 1,
          "%s: verify --certificate refuses the saved trace", name);
    CHECK(verify_doc(t, name, 1, NULL) == 0, "%s: a curve dropped is accepted", name);
    CHECK(verify_doc(t, name, 2, NULL) == 0, "%s: a curve doubled is accepted", name);
    if (ic_trace_result_num_specials(t->res) > 0)
        CHECK(verify_doc(t, name, 3, NULL) == 0, "%s: the branch point moved is accepted", name);
}

#endif
