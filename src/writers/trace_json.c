/* The document of `intercurve trace` (docs/output-formats.md,
 * "JSON"): the curves with their points, the special points, the report. */
#include "common/args.h"
#include "intercurve/writers.h"
#include "parametric.h"

#include "json/json_out.h"

#include <string.h>

static void point_json(json_out *j, const ic_trace_point *p, const ic_trace_curve *c,
                       const ic_trace_result *res, const int parametric[2])
{
    ic_json_out_object(j);
    ic_json_out_key(j, "s");
    ic_json_out_number(j, p->s);
    ic_json_out_key(j, "xyz");
    ic_json_out_vector(j, p->xyz, 3);
    ic_json_out_key(j, "params");
    ic_json_out_array(j);
    for (int s = 0; s < 2; s++) {
        if (parametric[s])
            ic_json_out_vector(j, p->params[s], 2);
        else
            ic_json_out_null(j);
    }
    ic_json_out_end_array(j);
    ic_json_out_key(j, "t");
    ic_json_out_vector(j, p->t, 3);
    const double *frame[2] = {p->n, p->b};
    static const char *const frame_keys[2] = {"n", "b"};
    for (int k = 0; k < 2; k++) {
        ic_json_out_key(j, frame_keys[k]);
        if (p->frame_defined)
            ic_json_out_vector(j, frame[k], 3);
        else
            ic_json_out_null(j);
    }
    ic_json_out_key(j, "kappa");
    ic_json_out_number(j, p->kappa);
    ic_json_out_key(j, "tau");
    if (p->frame_defined)
        ic_json_out_number(j, p->tau);
    else
        ic_json_out_null(j);
    ic_json_out_key(j, "angle");
    ic_json_out_number(j, p->angle);
    ic_json_out_key(j, "type");
    ic_json_out_string(j, ic_point_type_name(ic_trace_point_type(res, c, p)));
    if (p->knot_line) { /* docs/nurbs.md, "Knot lines" */
        ic_json_out_key(j, "knot_line");
        ic_json_out_object(j);
        ic_json_out_key(j, "surfaces");
        ic_json_out_array(j);
        for (int s = 0; s < 2; s++)
            ic_json_out_bool(j, (p->knot_line >> s) & 1);
        ic_json_out_end_array(j);
        ic_json_out_key(j, "apparatus_of");
        ic_json_out_string(j, p->knot_side < 0 ? "before" : "after");
        ic_json_out_end_object(j);
    }
    ic_json_out_end_object(j);
}

/* A B-spline as {"degree", "periodic", "knots", "control_points"}
 * (docs/bspline.md). */
static void bspline_json(json_out *j, const ic_bspline *b)
{
    ic_json_out_object(j);
    ic_json_out_key(j, "degree");
    ic_json_out_int(j, b->degree);
    ic_json_out_key(j, "periodic");
    ic_json_out_bool(j, b->periodic);
    ic_json_out_key(j, "knots");
    ic_json_out_vector(j, b->knots, b->ncontrol + b->degree + 1);
    ic_json_out_key(j, "control_points");
    ic_json_out_array(j);
    for (int i = 0; i < b->ncontrol; i++)
        ic_json_out_vector(j, b->control + (size_t)b->dim * i, b->dim);
    ic_json_out_end_array(j);
    ic_json_out_end_object(j);
}

/* The curve's fitted B-spline and pcurves, or null where not fitted. */
static void fit_json(json_out *j, const ic_curve_fit *fit)
{
    ic_json_out_key(j, "bspline");
    if (!fit) {
        ic_json_out_null(j);
        ic_json_out_key(j, "pcurves");
        ic_json_out_null(j);
        return;
    }
    bspline_json(j, &fit->curve);
    ic_json_out_key(j, "pcurves");
    ic_json_out_array(j);
    for (int s = 0; s < 2; s++) {
        if (fit->pcurves[s].ncontrol)
            bspline_json(j, &fit->pcurves[s]);
        else
            ic_json_out_null(j);
    }
    ic_json_out_end_array(j);
}

static void curve_json(json_out *j, const ic_trace_curve *c, const ic_trace_result *res,
                       const int parametric[2], const ic_curve_fit *fit)
{
    ic_json_out_object(j);
    ic_json_out_key(j, "closed");
    ic_json_out_bool(j, c->closed);
    ic_json_out_key(j, "type");
    ic_json_out_string(j, c->tangential ? "tangential" : "transversal");
    ic_json_out_key(j, "shape");
    ic_json_out_string(j, ic_shape_name(c->shape));
    ic_json_out_key(j, "shape_tolerance");
    ic_json_out_number(j, c->shape_tol);
    ic_json_out_key(j, "length");
    ic_json_out_number(j, c->length);
    ic_json_out_key(j, "ends");
    ic_json_out_array(j);
    for (int e = 0; e < 2; e++)
        ic_json_out_string(j, ic_trace_event_name(c->ends[e]));
    ic_json_out_end_array(j);
    fit_json(j, fit);
    ic_json_out_key(j, "points");
    ic_json_out_array(j);
    for (int k = 0; k < c->npoints; k++)
        point_json(j, &c->points[k], c, res, parametric);
    ic_json_out_end_array(j);
    ic_json_out_end_object(j);
}

static void special_json(json_out *j, const ic_trace_special *sp)
{
    ic_json_out_object(j);
    ic_json_out_key(j, "xyz");
    ic_json_out_vector(j, sp->xyz, 3);
    ic_json_out_key(j, "type");
    ic_json_out_string(j, ic_point_type_name(sp->type));
    ic_json_out_key(j, "branches");
    ic_json_out_int(j, sp->nbranches);
    ic_json_out_key(j, "approximate");
    ic_json_out_bool(j, sp->approximate);
    ic_json_out_end_object(j);
}

static void int_member(json_out *j, const char *key, int x)
{
    ic_json_out_key(j, key);
    ic_json_out_int(j, x);
}

/* The certificate's summary (docs/output-formats.md, "certificate"); its
 * wall time stays out, so that a document is the same from run to run. */
static void write_certificate(json_out *j, const ic_trace_certificate *c)
{
    ic_json_out_key(j, "certificate");
    ic_json_out_object(j);
    ic_json_out_key(j, "checked");
    ic_json_out_bool(j, c->checked);
    ic_json_out_key(j, "accepted");
    ic_json_out_bool(j, c->accepted);
    const struct {
        const char *key;
        long n;
    } counts[] = {{"cells", c->cells},       {"empty", c->empty},         {"outside", c->outside},
                  {"diagonal", c->diagonal}, {"regular", c->regular},     {"singular", c->singular},
                  {"tangential", c->tangential},
                  {"refused", c->refused},
                  {"crossings", c->crossings}, {"arcs", c->arcs},
                  {"poles", c->poles},         {"corners", c->corners},
                  {"restarts", c->restarts}};
    for (size_t i = 0; i < sizeof counts / sizeof counts[0]; i++)
        int_member(j, counts[i].key, (int)counts[i].n);
    ic_json_out_key(j, "reason");
    if (c->reason[0])
        ic_json_out_string(j, c->reason);
    else
        ic_json_out_null(j);
    ic_json_out_end_object(j);
}

/* The report's keys, in the order of docs/output-formats.md's table. */
static void report_json(json_out *j, const ic_trace_report *rep)
{
    ic_json_out_object(j);
    ic_json_out_key(j, "complete");
    ic_json_out_bool(j, rep->complete);
    ic_json_out_key(j, "tracer_complete");
    ic_json_out_bool(j, rep->tracer_complete);
    ic_json_out_key(j, "method");
    ic_json_out_string(j, rep->method ? rep->method : "search");
    int_member(j, "cells", rep->cells);
    int_member(j, "cells_excluded_by_intervals", rep->cells_excluded);
    int_member(j, "cells_excluded_by_centred_forms", rep->cells_excluded_centred);
    ic_json_out_key(j, "exclusion_proven");
    ic_json_out_bool(j, rep->proven);
    ic_json_out_key(j, "sampled");
    const int searched = !rep->method || strcmp(rep->method, "search") == 0;
    ic_json_out_string(j, !searched      ? "nothing: the intersection is in closed form"
                          : rep->proven ? "start points inside the cells that were not excluded"
                                        : "everything: a surface has no interval evaluation");
    ic_json_out_key(j, "smallest_cell");
    ic_json_out_number(j, rep->cell_size);
    int_member(j, "start_candidates", rep->candidates);
    int_member(j, "uncovered_cells", rep->uncovered_cells);
    int_member(j, "unproven_cells", rep->unproven_cells);
    int_member(j, "loop_free_cells", rep->loop_free_cells);
    int_member(j, "loop_cells", rep->loop_cells);
    int_member(j, "refined_cells", rep->refined_cells);
    int_member(j, "undecided_loop_cells", rep->undecided_loop_cells);
    int_member(j, "coincident_cells", rep->coincident_cells);
    ic_json_out_key(j, "failures");
    ic_json_out_array(j);
    for (int i = 0; i < rep->nfailures; i++)
        ic_json_out_string(j, rep->failures[i]);
    ic_json_out_end_array(j);
    const int fitted = rep->fit_tol > 0;
    ic_json_out_key(j, "fit_tolerance");
    if (fitted)
        ic_json_out_number(j, rep->fit_tol);
    else
        ic_json_out_null(j);
    ic_json_out_key(j, "fit_error");
    if (fitted)
        ic_json_out_number(j, rep->fit_error);
    else
        ic_json_out_null(j);
    /* which size L each stage's lengths are fractions of (docs/tracing.md, "Scale") */
    ic_json_out_key(j, "search_scale");
    ic_json_out_number(j, rep->search_scale);
    ic_json_out_key(j, "scale");
    ic_json_out_number(j, rep->scale);
    write_certificate(j, &rep->certificate);
    ic_json_out_end_object(j);
}

ic_status ic_certificate_write_json(FILE *f, const ic_trace_certificate *c, ic_error *err)
{
    IC_ARG_NOT_NULL(f, "f");
    IC_ARG_NOT_NULL(c, "c");
    json_out j;
    ic_json_out_start(&j, f);
    ic_json_out_object(&j);
    write_certificate(&j, c);
    ic_json_out_end_object(&j);
    return ic_json_out_finish(&j, "certificate JSON", err);
}

ic_status ic_trace_write_json(FILE *f, const ic_trace_result *res, const ic_pair *pair,
                              ic_error *err)
{
    IC_ARG_NOT_NULL(f, "f");
    IC_ARG_NOT_NULL(res, "res");
    IC_ARG_NOT_NULL(pair, "pair");
    int parametric[2];
    ic_writer_parametric(pair, parametric);
    json_out j;
    ic_json_out_start(&j, f);
    ic_json_out_object(&j);
    ic_json_out_key(&j, "curves");
    ic_json_out_array(&j);
    for (int i = 0; i < ic_trace_result_num_curves(res); i++)
        curve_json(&j, ic_trace_result_curve(res, i), res, parametric, ic_trace_result_fit(res, i));
    ic_json_out_end_array(&j);
    ic_json_out_key(&j, "points");
    ic_json_out_array(&j);
    for (int i = 0; i < ic_trace_result_num_specials(res); i++)
        special_json(&j, ic_trace_result_special(res, i));
    ic_json_out_end_array(&j);
    ic_json_out_key(&j, "report");
    report_json(&j, ic_trace_result_report(res));
    ic_json_out_end_object(&j);
    return ic_json_out_finish(&j, "trace JSON", err);
}
