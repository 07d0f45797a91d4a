/* The trace document (ic_trace_write_json) and the trace's text
 * (ic_trace_write_text), called directly: read back and compared with the
 * ic_trace result they came from, bit for bit, with the keys of
 * docs/output-formats.md in their order, and with Viviani's curve in
 * closed form. */
#include "json_doc.h"
#include "traced_example.h"

/* The length of Viviani's curve: |c'|^2 = 1 + cos^2(t/2) over t in [0, 4 pi]
 * gives 8 sqrt 2 E(m = 1/2) (mpmath: 15.280791156110849371) */
#define VIVIANI_LENGTH 15.280791156110848
/* the trace's length is good to about 1e-13 relative at the default tol
 * (docs/tracing.md: 3.6e-14); 1e-11 leaves margin, far below any error */
#define LENGTH_TOL 1e-11

static ic_status write_json(FILE *f, void *user, ic_error *err)
{
    const traced *t = user;
    return ic_trace_write_json(f, t->res, t->pair, err);
}

static ic_status write_text(FILE *f, void *user, ic_error *err)
{
    const traced *t = user;
    return ic_trace_write_text(f, t->res, t->problem ? ic_problem_title(t->problem) : NULL, err);
}

/* A point's "knot_line" (docs/nurbs.md, "Knot lines"): which surfaces'
 * knot lines it is on, and whose side its apparatus is of. */
static int knot_line_matches(const cJSON *o, const ic_trace_point *p)
{
    static const char *const keys[] = {"surfaces", "apparatus_of", NULL};
    const cJSON *on = doc_get(o, "surfaces");
    int ok = doc_keys_are(o, keys) && cJSON_GetArraySize(on) == 2 &&
             doc_string_is(doc_get(o, "apparatus_of"), p->knot_side < 0 ? "before" : "after");
    for (int s = 0; ok && s < 2; s++)
        ok = cJSON_IsBool(cJSON_GetArrayItem(on, s)) &&
             cJSON_IsTrue(cJSON_GetArrayItem(on, s)) == ((p->knot_line >> s) & 1);
    return ok;
}

static int point_matches(const cJSON *o, const ic_trace_point *p, const ic_trace_curve *c,
                         const traced *t, const int parametric[2])
{
    static const char *const keys[] = {"s",     "xyz", "params", "t",    "n", "b",
                                       "kappa", "tau", "angle",  "type", NULL};
    static const char *const knot_keys[] = {"s",   "xyz",   "params", "t",         "n", "b",
                                            "kappa", "tau", "angle",  "type", "knot_line", NULL};
    const int fd = p->frame_defined;
    const cJSON *params = doc_get(o, "params");
    int ok =
        doc_keys_are(o, p->knot_line ? knot_keys : keys) &&
        (!p->knot_line || knot_line_matches(doc_get(o, "knot_line"), p)) &&
        doc_number_is(doc_get(o, "s"), p->s) &&
        doc_vector_is(doc_get(o, "xyz"), p->xyz, 3) && doc_vector_is(doc_get(o, "t"), p->t, 3) &&
        (fd ? doc_vector_is(doc_get(o, "n"), p->n, 3) : cJSON_IsNull(doc_get(o, "n"))) &&
        (fd ? doc_vector_is(doc_get(o, "b"), p->b, 3) : cJSON_IsNull(doc_get(o, "b"))) &&
        doc_number_is(doc_get(o, "kappa"), p->kappa) &&
        doc_number_is(doc_get(o, "tau"), fd ? p->tau : NAN) &&
        doc_number_is(doc_get(o, "angle"), p->angle) &&
        doc_string_is(doc_get(o, "type"), ic_point_type_name(ic_trace_point_type(t->res, c, p)));
    for (int s = 0; ok && s < 2; s++)
        ok = parametric[s] ? doc_vector_is(cJSON_GetArrayItem(params, s), p->params[s], 2)
                           : cJSON_IsNull(cJSON_GetArrayItem(params, s));
    return ok;
}

/* A B-spline read back: degree, periodic, knots and control points bit
 * for bit. */
static int bspline_matches(const cJSON *o, const ic_bspline *b)
{
    static const char *const keys[] = {"degree", "periodic", "knots", "control_points", NULL};
    const cJSON *pts = doc_get(o, "control_points"), *periodic = doc_get(o, "periodic");
    int ok = doc_keys_are(o, keys) && doc_number_is(doc_get(o, "degree"), b->degree) &&
             cJSON_IsBool(periodic) && cJSON_IsTrue(periodic) == !!b->periodic &&
             doc_vector_is(doc_get(o, "knots"), b->knots, b->ncontrol + b->degree + 1) &&
             cJSON_GetArraySize(pts) == b->ncontrol;
    for (int i = 0; ok && i < b->ncontrol; i++)
        ok = doc_vector_is(cJSON_GetArrayItem(pts, i), b->control + (size_t)b->dim * i, b->dim);
    return ok;
}

/* "bspline" and "pcurves": null without a fit; else the fit's, a pcurve
 * null where the fit has none. */
static int fit_matches(const cJSON *o, const ic_curve_fit *fit)
{
    const cJSON *b = doc_get(o, "bspline"), *pc = doc_get(o, "pcurves");
    if (!fit)
        return cJSON_IsNull(b) && cJSON_IsNull(pc);
    int ok = bspline_matches(b, &fit->curve) && cJSON_GetArraySize(pc) == 2;
    for (int s = 0; ok && s < 2; s++)
        ok = fit->pcurves[s].ncontrol ? bspline_matches(cJSON_GetArrayItem(pc, s), &fit->pcurves[s])
                                      : cJSON_IsNull(cJSON_GetArrayItem(pc, s));
    return ok;
}

static void check_curves(const cJSON *curves, const traced *t, const char *name)
{
    static const char *const keys[] = {"closed", "type", "shape",  "shape_tolerance",
                                       "length", "ends", "bspline", "pcurves", "points", NULL};
    int parametric[2];
    for (int s = 0; s < 2; s++)
        parametric[s] = ic_surface_get_kind(ic_pair_surface(t->pair, s)) == IC_PARAMETRIC;
    const int nc = ic_trace_result_num_curves(t->res);
    CHECK(cJSON_GetArraySize(curves) == nc, "%s: %d curves", name, nc);
    for (int i = 0; i < nc && i < cJSON_GetArraySize(curves); i++) {
        const ic_trace_curve *c = ic_trace_result_curve(t->res, i);
        const cJSON *o = cJSON_GetArrayItem(curves, i), *ends = doc_get(o, "ends");
        const cJSON *pts = doc_get(o, "points");
        CHECK(doc_keys_are(o, keys) && cJSON_IsBool(doc_get(o, "closed")) &&
                  cJSON_IsTrue(doc_get(o, "closed")) == !!c->closed &&
                  doc_string_is(doc_get(o, "type"), c->tangential ? "tangential" : "transversal") &&
                  doc_string_is(doc_get(o, "shape"), ic_shape_name(c->shape)) &&
                  doc_number_is(doc_get(o, "shape_tolerance"), c->shape_tol) &&
                  doc_number_is(doc_get(o, "length"), c->length) &&
                  doc_string_is(cJSON_GetArrayItem(ends, 0), ic_trace_event_name(c->ends[0])) &&
                  doc_string_is(cJSON_GetArrayItem(ends, 1), ic_trace_event_name(c->ends[1])) &&
                  cJSON_GetArraySize(pts) == c->npoints,
              "%s: curve %d's keys and values", name, i);
        CHECK(fit_matches(o, ic_trace_result_fit(t->res, i)), "%s: curve %d's B-splines", name,
              i);
        int bad = 0;
        for (int k = 0; k < c->npoints && k < cJSON_GetArraySize(pts); k++)
            bad += !point_matches(cJSON_GetArrayItem(pts, k), &c->points[k], c, t, parametric);
        CHECK(bad == 0, "%s: curve %d, %d of %d points differ", name, i, bad, c->npoints);
    }
}

static void check_specials(const cJSON *points, const traced *t, const char *name)
{
    static const char *const keys[] = {"xyz", "type", "branches", "approximate", NULL};
    const int ns = ic_trace_result_num_specials(t->res);
    int bad = cJSON_GetArraySize(points) != ns;
    for (int i = 0; !bad && i < ns; i++) {
        const ic_trace_special *sp = ic_trace_result_special(t->res, i);
        const cJSON *o = cJSON_GetArrayItem(points, i);
        bad += !doc_keys_are(o, keys) || !doc_vector_is(doc_get(o, "xyz"), sp->xyz, 3) ||
               !doc_string_is(doc_get(o, "type"), ic_point_type_name(sp->type)) ||
               !doc_number_is(doc_get(o, "branches"), sp->nbranches) ||
               cJSON_IsTrue(doc_get(o, "approximate")) != !!sp->approximate;
    }
    CHECK(bad == 0, "%s: the %d special points read back", name, ns);
}

/* The report's keys in the order of docs/output-formats.md's table. */
static void check_report(const cJSON *ro, const ic_trace_report *rep, const char *name)
{
    static const char *const keys[] = {"complete",
                                       "tracer_complete",
                                       "method",
                                       "cells",
                                       "cells_excluded_by_intervals",
                                       "cells_excluded_by_centred_forms",
                                       "exclusion_proven",
                                       "sampled",
                                       "smallest_cell",
                                       "start_candidates",
                                       "uncovered_cells",
                                       "unproven_cells",
                                       "loop_free_cells",
                                       "loop_cells",
                                       "refined_cells",
                                       "undecided_loop_cells",
                                       "coincident_cells",
                                       "failures",
                                       "fit_tolerance",
                                       "fit_error",
                                       "search_scale",
                                       "scale",
                                       "certificate",
                                       NULL};
    const int counts[] = {rep->cells,
                          rep->cells_excluded,
                          rep->cells_excluded_centred,
                          rep->candidates,
                          rep->uncovered_cells,
                          rep->unproven_cells,
                          rep->loop_free_cells,
                          rep->loop_cells,
                          rep->refined_cells,
                          rep->undecided_loop_cells,
                          rep->coincident_cells};
    const char *count_keys[] = {"cells",
                                "cells_excluded_by_intervals",
                                "cells_excluded_by_centred_forms",
                                "start_candidates",
                                "uncovered_cells",
                                "unproven_cells",
                                "loop_free_cells",
                                "loop_cells",
                                "refined_cells",
                                "undecided_loop_cells",
                                "coincident_cells"};
    const cJSON *cert = doc_get(ro, "certificate");
    int ok = doc_keys_are(ro, keys) && cJSON_IsTrue(doc_get(ro, "complete")) == !!rep->complete &&
             cJSON_IsTrue(doc_get(ro, "tracer_complete")) == !!rep->tracer_complete &&
             cJSON_IsTrue(doc_get(cert, "accepted")) == !!rep->certificate.accepted &&
             doc_number_is(doc_get(cert, "crossings"), (double)rep->certificate.crossings) &&
             cJSON_IsTrue(doc_get(ro, "exclusion_proven")) == !!rep->proven &&
             rep->method && doc_string_is(doc_get(ro, "method"), rep->method) &&
             doc_number_is(doc_get(ro, "smallest_cell"), rep->cell_size) &&
             doc_number_is(doc_get(ro, "search_scale"), rep->search_scale) &&
             doc_number_is(doc_get(ro, "scale"), rep->scale) &&
             cJSON_GetArraySize(doc_get(ro, "failures")) == rep->nfailures;
    for (int i = 0; ok && i < 11; i++)
        ok = doc_number_is(doc_get(ro, count_keys[i]), counts[i]);
    for (int i = 0; ok && i < rep->nfailures; i++)
        ok = doc_string_is(cJSON_GetArrayItem(doc_get(ro, "failures"), i), rep->failures[i]);
    if (rep->fit_tol > 0)
        ok = ok && doc_number_is(doc_get(ro, "fit_tolerance"), rep->fit_tol) &&
             doc_number_is(doc_get(ro, "fit_error"), rep->fit_error);
    else
        ok = ok && cJSON_IsNull(doc_get(ro, "fit_tolerance")) &&
             cJSON_IsNull(doc_get(ro, "fit_error"));
    CHECK(ok, "%s: the report's keys in order and its values", name);
}

static void check_document(const traced *t, const char *name)
{
    static const char *const keys[] = {"curves", "points", "report", NULL};
    cJSON *doc = doc_parse(write_json, (void *)t, name);
    if (!doc)
        return;
    CHECK(doc_keys_are(doc, keys), "%s: curves, points, report", name);
    check_curves(doc_get(doc, "curves"), t, name);
    check_specials(doc_get(doc, "points"), t, name);
    check_report(doc_get(doc, "report"), ic_trace_result_report(t->res), name);
    cJSON_Delete(doc);
}

/* Viviani's curve as two implicit surfaces: one closed figure-eight of the
 * closed-form length through the branch point (2, 0, 0), complete by the
 * tracer's account and not proven by the certificate (a branch point has no
 * singular box yet: docs/tracing.md, "The certificate"). */
static void check_viviani(const traced *t)
{
    cJSON *doc = doc_parse(write_json, (void *)t, "Viviani");
    const cJSON *c = cJSON_GetArrayItem(doc_get(doc, "curves"), 0);
    const cJSON *p = cJSON_GetArrayItem(doc_get(doc, "points"), 0);
    const double branch_point[3] = {2, 0, 0};
    const cJSON *xyz = doc_get(p, "xyz");
    int near = cJSON_GetArraySize(xyz) == 3;
    for (int k = 0; near && k < 3; k++)
        near = harness_close(cJSON_GetArrayItem(xyz, k)->valuedouble, branch_point[k], 1e-12, 0);
    CHECK(cJSON_GetArraySize(doc_get(doc, "curves")) == 1 && cJSON_IsTrue(doc_get(c, "closed")) &&
              harness_close(doc_get(c, "length")->valuedouble, VIVIANI_LENGTH, LENGTH_TOL, 1),
          "Viviani: one closed curve of length 8 sqrt 2 E(1/2)");
    const cJSON *rep = doc_get(doc, "report");
    CHECK(doc_string_is(doc_get(p, "type"), "branch-point") && near &&
              cJSON_IsTrue(doc_get(rep, "tracer_complete")) &&
              cJSON_IsTrue(doc_get(rep, "complete")) &&
              cJSON_IsTrue(doc_get(doc_get(rep, "certificate"), "accepted")) &&
              cJSON_IsNumber(doc_get(doc_get(rep, "certificate"), "singular")) &&
              doc_get(doc_get(rep, "certificate"), "singular")->valuedouble > 0 &&
              cJSON_IsNull(doc_get(doc_get(rep, "certificate"), "reason")),
          "Viviani: the branch point (2, 0, 0) in its singular box, proven");
    cJSON_Delete(doc);
    ic_error err;
    ic_status st;
    char *text = doc_text(write_text, (void *)t, &st, &err);
    CHECK(st == IC_OK && text && strstr(text, "\ncurves: 1\n") && strstr(text, "15.2807911561") &&
              strstr(text, "\nsingular points: 1\n") && strstr(text, "branch-point") &&
              strstr(text, "\nresult: complete (proven by the certificate)") &&
              strstr(text, "\ncertificate: accepted"),
          "Viviani's text: one curve of its length, the branch point, proven");
    free(text);
    FILE *full = fopen("/dev/full", "w");
    if (full) {
        setvbuf(full, NULL, _IONBF, 0);
        CHECK(ic_trace_write_json(full, t->res, t->pair, &err) == IC_ERR_IO &&
                  ic_trace_write_text(full, t->res, "title", &err) == IC_ERR_IO,
              "the trace's writers report a failed write");
        fclose(full);
    }
}

/* Two planes z = 0 and y = 0 in the box [-1, 1]^3: one line, kappa 0 at
 * every point, so n, b and tau are null throughout. */
static void check_line(void)
{
    traced t;
    memset(&t, 0, sizeof t);
    ic_surface *A = NULL, *B = NULL;
    ic_trace_options opt;
    ic_trace_defaults(&opt);
    opt.has_box = 1;
    for (int k = 0; k < 3; k++)
        opt.box[k][0] = -1, opt.box[k][1] = 1;
    ic_error err;
    if (ic_surface_new_implicit(&A, "z", NULL, 0, &err) == IC_OK &&
        ic_surface_new_implicit(&B, "y", NULL, 0, &err) == IC_OK &&
        ic_pair_new(&t.pair, A, B, &err) == IC_OK &&
        ic_trace(&t.res, t.pair, &opt, &err) == IC_OK) {
        check_document(&t, "two planes");
        cJSON *doc = doc_parse(write_json, &t, "two planes");
        const cJSON *c = cJSON_GetArrayItem(doc_get(doc, "curves"), 0);
        const cJSON *p = cJSON_GetArrayItem(doc_get(c, "points"), 1);
        CHECK(doc_string_is(doc_get(c, "shape"), "line") && doc_number_is(doc_get(p, "kappa"), 0) &&
                  cJSON_IsNull(doc_get(p, "n")) && cJSON_IsNull(doc_get(p, "tau")),
              "two planes: a line, kappa 0, n and tau null");
        cJSON_Delete(doc);
    } else {
        CHECK(0, "two planes traced: %s", err.message);
    }
    ic_trace_result_free(t.res);
    ic_pair_free(t.pair);
    ic_surface_free(A);
    ic_surface_free(B);
}

/* A sphere r = 1 and the plane z = 1/2 as primitives: traced in closed form
 * (docs/tracing.md, "Exact paths"), the report says so and what was
 * sampled: nothing; the same with exact_paths off says "search". */
static void check_closed_form(void)
{
    const ic_primitive sphere = {.kind = IC_PRIM_SPHERE, .radius = 1};
    const ic_primitive plane = {.kind = IC_PRIM_PLANE, .center = {0, 0, 0.5}, .normal = {0, 0, 1}};
    ic_surface *A = NULL, *B = NULL;
    ic_error err;
    int ok = REQUIRE(ic_surface_new_primitive(&A, &sphere, IC_IMPLICIT, &err) == IC_OK &&
                         ic_surface_new_primitive(&B, &plane, IC_IMPLICIT, &err) == IC_OK,
                     "primitives: %s", err.message);
    for (int exact = 1; ok && exact >= 0; exact--) {
        traced t;
        memset(&t, 0, sizeof t);
        ic_trace_options opt;
        ic_trace_defaults(&opt);
        opt.exact_paths = exact;
        opt.has_box = 1;
        for (int k = 0; k < 3; k++)
            opt.box[k][0] = -2, opt.box[k][1] = 2;
        if (!REQUIRE(ic_pair_new(&t.pair, A, B, &err) == IC_OK &&
                         ic_trace(&t.res, t.pair, &opt, &err) == IC_OK,
                     "sphere and plane traced: %s", err.message)) {
            ic_pair_free(t.pair);
            break;
        }
        const char *name = exact ? "sphere and plane, closed form" : "sphere and plane, search";
        check_document(&t, name);
        cJSON *doc = doc_parse(write_json, &t, name);
        const cJSON *ro = doc_get(doc, "report");
        CHECK(exact ? doc_string_is(doc_get(ro, "method"),
                                    "closed form: coaxial surfaces of revolution") &&
                          doc_string_is(doc_get(ro, "sampled"),
                                        "nothing: the intersection is in closed form")
                    : doc_string_is(doc_get(ro, "method"), "search") &&
                          doc_string_is(doc_get(ro, "sampled"),
                                        "start points inside the cells that were not excluded"),
              "%s: the report's method and what it sampled", name);
        cJSON_Delete(doc);
        ic_trace_result_free(t.res);
        ic_pair_free(t.pair);
    }
    ic_surface_free(A);
    ic_surface_free(B);
}

/* A sphere's and a plane's NURBS nets, recognised: the circle in closed form
 * with both nets' parameters at every point and points on their knot lines
 * (docs/tracing.md, "Exact paths"), written as any trace is, fitted or not,
 * and the report says how it was found. */
static void check_closed_form_nets(const char *dir)
{
    char path[600];
    snprintf(path, sizeof path, "%s/tests/data/nurbs/problem-sphere-plane-nets.json", dir);
    traced t;
    if (trace_file(&t, path) == 0) {
        const char *name = "sphere's and plane's nets";
        check_document(&t, name);
        ic_error err;
        if (REQUIRE(ic_trace_fit(t.res, t.pair, 1e-9, &err) == IC_OK, "fit: %s", err.message))
            check_document(&t, name);
        cJSON *doc = doc_parse(write_json, &t, name);
        CHECK(doc_string_is(doc_get(doc_get(doc, "report"), "method"),
                            "closed form: NURBS nets recognised as coaxial surfaces of revolution"),
              "%s: the report's method", name);
        cJSON_Delete(doc);
    }
    release(&t);
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : ".";
    /* implicit pair with a branch point; a parametric self-intersection
     * (params of both preimages); a tangential curve (torus and sphere) */
    const char *examples[] = {"viviani-implicit.json", "enneper-self.json", "torus-sphere.json"};
    for (int e = 0; e < 3; e++) {
        traced t;
        if (trace_example(&t, dir, examples[e]) == 0) {
            check_document(&t, examples[e]); /* not fitted: nulls */
            ic_error err;
            if (REQUIRE(ic_trace_fit(t.res, t.pair, 1e-9, &err) == IC_OK, "fit: %s", err.message))
                check_document(&t, examples[e]); /* fitted: the B-splines */
            if (e == 0)
                check_viviani(&t);
        }
        release(&t);
    }
    check_line();
    check_closed_form();
    check_closed_form_nets(dir);
    return harness_finish("test_trace_document");
}
