/* The document of `intercurve trace` (docs/output-formats.md,
 * "JSON"): the curves with their points, the special points, the report. */
#include "intercurve/writers.h"

#include "io/json_out.h"

#include <string.h>

static cJSON *point_json(json_out *j, const ic_trace_point *p, const ic_trace_curve *c,
                         const ic_trace_result *res, const int parametric[2])
{
    cJSON *o = cJSON_CreateObject();
    ic_json_out_add(j, o, "s", ic_json_out_number(j, p->s));
    ic_json_out_add(j, o, "xyz", ic_json_out_vector(j, p->xyz, 3));
    cJSON *params = cJSON_CreateArray();
    for (int s = 0; s < 2; s++)
        ic_json_out_append(j, params,
                        parametric[s] ? ic_json_out_vector(j, p->params[s], 2) : cJSON_CreateNull());
    ic_json_out_add(j, o, "params", params);
    ic_json_out_add(j, o, "t", ic_json_out_vector(j, p->t, 3));
    ic_json_out_add(j, o, "n", p->frame_defined ? ic_json_out_vector(j, p->n, 3) : cJSON_CreateNull());
    ic_json_out_add(j, o, "b", p->frame_defined ? ic_json_out_vector(j, p->b, 3) : cJSON_CreateNull());
    ic_json_out_add(j, o, "kappa", ic_json_out_number(j, p->kappa));
    ic_json_out_add(j, o, "tau", p->frame_defined ? ic_json_out_number(j, p->tau) : cJSON_CreateNull());
    ic_json_out_add(j, o, "angle", ic_json_out_number(j, p->angle));
    ic_json_out_add(j, o, "type",
                 cJSON_CreateString(ic_point_type_name(ic_trace_point_type(res, c, p))));
    if (p->knot_line) { /* docs/nurbs.md, "Knot lines" */
        cJSON *k = cJSON_CreateObject();
        cJSON *on = cJSON_CreateArray();
        for (int s = 0; s < 2; s++)
            ic_json_out_append(j, on, cJSON_CreateBool((p->knot_line >> s) & 1));
        ic_json_out_add(j, k, "surfaces", on);
        ic_json_out_add(j, k, "apparatus_of",
                        cJSON_CreateString(p->knot_side < 0 ? "before" : "after"));
        ic_json_out_add(j, o, "knot_line", k);
    }
    return o;
}

/* A B-spline as {"degree", "periodic", "knots", "control_points"}
 * (docs/bspline.md). */
static cJSON *bspline_json(json_out *j, const ic_bspline *b)
{
    cJSON *o = cJSON_CreateObject();
    ic_json_out_add(j, o, "degree", cJSON_CreateNumber(b->degree));
    ic_json_out_add(j, o, "periodic", cJSON_CreateBool(b->periodic));
    ic_json_out_add(j, o, "knots", ic_json_out_vector(j, b->knots, b->ncontrol + b->degree + 1));
    cJSON *pts = cJSON_CreateArray();
    for (int i = 0; i < b->ncontrol; i++)
        ic_json_out_append(j, pts, ic_json_out_vector(j, b->control + (size_t)b->dim * i, b->dim));
    ic_json_out_add(j, o, "control_points", pts);
    return o;
}

/* The curve's fitted B-spline and pcurves, or null where not fitted. */
static void fit_json(json_out *j, cJSON *o, const ic_curve_fit *fit)
{
    if (!fit) {
        ic_json_out_add(j, o, "bspline", cJSON_CreateNull());
        ic_json_out_add(j, o, "pcurves", cJSON_CreateNull());
        return;
    }
    ic_json_out_add(j, o, "bspline", bspline_json(j, &fit->curve));
    cJSON *pc = cJSON_CreateArray();
    for (int s = 0; s < 2; s++)
        ic_json_out_append(j, pc, fit->pcurves[s].ncontrol ? bspline_json(j, &fit->pcurves[s])
                                                           : cJSON_CreateNull());
    ic_json_out_add(j, o, "pcurves", pc);
}

static cJSON *curve_json(json_out *j, const ic_trace_curve *c, const ic_trace_result *res,
                         const int parametric[2], const ic_curve_fit *fit)
{
    cJSON *o = cJSON_CreateObject();
    ic_json_out_add(j, o, "closed", cJSON_CreateBool(c->closed));
    ic_json_out_add(j, o, "type", cJSON_CreateString(c->tangential ? "tangential" : "transversal"));
    ic_json_out_add(j, o, "shape", cJSON_CreateString(ic_shape_name(c->shape)));
    ic_json_out_add(j, o, "shape_tolerance", ic_json_out_number(j, c->shape_tol));
    ic_json_out_add(j, o, "length", ic_json_out_number(j, c->length));
    cJSON *ends = cJSON_CreateArray();
    for (int e = 0; e < 2; e++)
        ic_json_out_append(j, ends, cJSON_CreateString(ic_trace_event_name(c->ends[e])));
    ic_json_out_add(j, o, "ends", ends);
    fit_json(j, o, fit);
    cJSON *pts = cJSON_CreateArray();
    for (int k = 0; k < c->npoints; k++)
        ic_json_out_append(j, pts, point_json(j, &c->points[k], c, res, parametric));
    ic_json_out_add(j, o, "points", pts);
    return o;
}

static cJSON *special_json(json_out *j, const ic_trace_special *sp)
{
    cJSON *o = cJSON_CreateObject();
    ic_json_out_add(j, o, "xyz", ic_json_out_vector(j, sp->xyz, 3));
    ic_json_out_add(j, o, "type", cJSON_CreateString(ic_point_type_name(sp->type)));
    ic_json_out_add(j, o, "branches", cJSON_CreateNumber(sp->nbranches));
    ic_json_out_add(j, o, "approximate", cJSON_CreateBool(sp->approximate));
    return o;
}

/* The report's keys, in the order of docs/output-formats.md's table. */
static cJSON *report_json(json_out *j, const ic_trace_report *rep)
{
    cJSON *ro = cJSON_CreateObject();
    ic_json_out_add(j, ro, "complete", cJSON_CreateBool(rep->complete));
    ic_json_out_add(j, ro, "method", cJSON_CreateString(rep->method ? rep->method : "search"));
    ic_json_out_add(j, ro, "cells", cJSON_CreateNumber(rep->cells));
    ic_json_out_add(j, ro, "cells_excluded_by_intervals", cJSON_CreateNumber(rep->cells_excluded));
    ic_json_out_add(j, ro, "cells_excluded_by_centred_forms",
                 cJSON_CreateNumber(rep->cells_excluded_centred));
    ic_json_out_add(j, ro, "exclusion_proven", cJSON_CreateBool(rep->proven));
    const int searched = !rep->method || strcmp(rep->method, "search") == 0;
    ic_json_out_add(j, ro, "sampled",
                 cJSON_CreateString(!searched ? "nothing: the intersection is in closed form"
                                    : rep->proven
                                        ? "start points inside the cells that were not excluded"
                                        : "everything: a surface has no interval evaluation"));
    ic_json_out_add(j, ro, "smallest_cell", ic_json_out_number(j, rep->cell_size));
    ic_json_out_add(j, ro, "start_candidates", cJSON_CreateNumber(rep->candidates));
    ic_json_out_add(j, ro, "uncovered_cells", cJSON_CreateNumber(rep->uncovered_cells));
    ic_json_out_add(j, ro, "unproven_cells", cJSON_CreateNumber(rep->unproven_cells));
    ic_json_out_add(j, ro, "loop_free_cells", cJSON_CreateNumber(rep->loop_free_cells));
    ic_json_out_add(j, ro, "loop_cells", cJSON_CreateNumber(rep->loop_cells));
    ic_json_out_add(j, ro, "refined_cells", cJSON_CreateNumber(rep->refined_cells));
    ic_json_out_add(j, ro, "undecided_loop_cells", cJSON_CreateNumber(rep->undecided_loop_cells));
    ic_json_out_add(j, ro, "coincident_cells", cJSON_CreateNumber(rep->coincident_cells));
    cJSON *failures = cJSON_CreateArray();
    for (int i = 0; i < rep->nfailures; i++)
        ic_json_out_append(j, failures, cJSON_CreateString(rep->failures[i]));
    ic_json_out_add(j, ro, "failures", failures);
    const int fitted = rep->fit_tol > 0;
    ic_json_out_add(j, ro, "fit_tolerance",
                    fitted ? ic_json_out_number(j, rep->fit_tol) : cJSON_CreateNull());
    ic_json_out_add(j, ro, "fit_error",
                    fitted ? ic_json_out_number(j, rep->fit_error) : cJSON_CreateNull());
    return ro;
}

ic_status ic_trace_write_json(FILE *f, const ic_trace_result *res, const ic_pair *pair,
                              ic_error *err)
{
    json_out j = {0};
    int parametric[2];
    for (int s = 0; s < 2; s++)
        parametric[s] = ic_surface_get_kind(ic_pair_surface(pair, s)) == IC_PARAMETRIC;
    cJSON *doc = cJSON_CreateObject();
    cJSON *curves = cJSON_CreateArray();
    for (int i = 0; i < ic_trace_result_num_curves(res); i++)
        ic_json_out_append(&j, curves, curve_json(&j, ic_trace_result_curve(res, i), res, parametric,
                                                  ic_trace_result_fit(res, i)));
    ic_json_out_add(&j, doc, "curves", curves);
    cJSON *points = cJSON_CreateArray();
    for (int i = 0; i < ic_trace_result_num_specials(res); i++)
        ic_json_out_append(&j, points, special_json(&j, ic_trace_result_special(res, i)));
    ic_json_out_add(&j, doc, "points", points);
    ic_json_out_add(&j, doc, "report", report_json(&j, ic_trace_result_report(res)));
    return ic_json_out_write(f, doc, &j, "trace JSON", err);
}
