/* intercurve trace: the whole intersection as JSON (docs/output-formats.md). */
#include "cli.h"

#include "io/safe_file.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char TRACE_HELP[] =
    "usage: intercurve trace PROBLEM.json [--format json|csv|vtk|obj|text] [-o FILE] [--tol T]\n"
    "                        [--depth D] [--time-limit SECONDS]\n"
    "\n"
    "Finds the intersection curves of the problem's two surfaces and traces each, with\n"
    "t, n, b, curvature and torsion at every point, its length and its shape (line,\n"
    "circle, planar, circular-helix, helix, general), the tangential points met, and a\n"
    "report of what was proven (cells excluded by interval arithmetic), what was only\n"
    "sampled, and every failure. The report says \"complete\": true only when every part\n"
    "of the search was decided (docs/tracing.md, \"Completeness\").\n"
    "\n"
    "Two implicit surfaces are searched inside the problem's \"box\"; a parametric\n"
    "surface over its \"domain\" (both domains, or twice the one, for two parametric\n"
    "surfaces or a self-intersection). A curve ends where it leaves the box or a\n"
    "domain, closes, or meets a tangential point it cannot pass.\n"
    "\n"
    "  --format F   json (default), csv (one row per point), vtk (legacy PolyData with\n"
    "               t, n, b, kappa, tau as point data, for ParaView), obj (polylines) or\n"
    "               text (a summary table of the curves and points); docs/output-formats.md\n"
    "  -o FILE      write to FILE (through a temporary file and a rename)\n"
    "  --tol T      truncation error allowed per step, a fraction of the problem's size\n"
    "               (the diagonal of the region searched; default 1e-11)\n"
    "  --depth D    subdivision depth of the start-point search, 1..9 (default 6)\n"
    "  --time-limit SECONDS\n"
    "               stop after this wall time with what was found (complete: false);\n"
    "               default none (the search's own cell budget still bounds it)\n"
    "\n"
    "example:\n"
    "  intercurve trace examples/viviani-implicit.json -o viviani.json\n"
    "  intercurve trace examples/viviani-implicit.json --format vtk -o viviani.vtk\n";

static cJSON *point_json(const ic_trace_point *p, const ic_trace_curve *c,
                         const ic_trace_result *res, const ic_pair *pair)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddItemToObject(o, "s", ic_json_number_or_null(p->s));
    cJSON_AddItemToObject(o, "xyz", ic_json_vector(p->xyz, 3));
    cJSON *params = cJSON_CreateArray();
    for (int s = 0; s < 2; s++)
        cJSON_AddItemToArray(params, ic_surface_get_kind(ic_pair_surface(pair, s)) == IC_PARAMETRIC
                                         ? ic_json_vector(p->params[s], 2)
                                         : cJSON_CreateNull());
    cJSON_AddItemToObject(o, "params", params);
    cJSON_AddItemToObject(o, "t", ic_json_vector(p->t, 3));
    cJSON_AddItemToObject(o, "n", p->frame_defined ? ic_json_vector(p->n, 3) : cJSON_CreateNull());
    cJSON_AddItemToObject(o, "b", p->frame_defined ? ic_json_vector(p->b, 3) : cJSON_CreateNull());
    cJSON_AddItemToObject(o, "kappa", ic_json_number_or_null(p->kappa));
    cJSON_AddItemToObject(o, "tau",
                          p->frame_defined ? ic_json_number_or_null(p->tau) : cJSON_CreateNull());
    cJSON_AddItemToObject(o, "angle", ic_json_number_or_null(p->angle));
    cJSON_AddStringToObject(o, "type", ic_point_type_name(ic_trace_point_type(res, c, p)));
    return o;
}

static cJSON *result_json(const ic_trace_result *r, const ic_pair *pair)
{
    cJSON *doc = cJSON_CreateObject();
    cJSON *curves = cJSON_CreateArray();
    for (int i = 0; i < ic_trace_result_num_curves(r); i++) {
        const ic_trace_curve *c = ic_trace_result_curve(r, i);
        cJSON *o = cJSON_CreateObject();
        cJSON_AddBoolToObject(o, "closed", c->closed);
        cJSON_AddStringToObject(o, "type", c->tangential ? "tangential" : "transversal");
        cJSON_AddStringToObject(o, "shape", ic_shape_name(c->shape));
        cJSON_AddNumberToObject(o, "shape_tolerance", c->shape_tol);
        cJSON_AddItemToObject(o, "length", ic_json_number_or_null(c->length));
        cJSON *ends = cJSON_CreateArray();
        cJSON_AddItemToArray(ends, cJSON_CreateString(ic_trace_event_name(c->ends[0])));
        cJSON_AddItemToArray(ends, cJSON_CreateString(ic_trace_event_name(c->ends[1])));
        cJSON_AddItemToObject(o, "ends", ends);
        cJSON *pts = cJSON_CreateArray();
        for (int k = 0; k < c->npoints; k++)
            cJSON_AddItemToArray(pts, point_json(&c->points[k], c, r, pair));
        cJSON_AddItemToObject(o, "points", pts);
        cJSON_AddItemToArray(curves, o);
    }
    cJSON_AddItemToObject(doc, "curves", curves);
    cJSON *points = cJSON_CreateArray();
    for (int i = 0; i < ic_trace_result_num_specials(r); i++) {
        const ic_trace_special *sp = ic_trace_result_special(r, i);
        cJSON *o = cJSON_CreateObject();
        cJSON_AddItemToObject(o, "xyz", ic_json_vector(sp->xyz, 3));
        cJSON_AddStringToObject(o, "type", ic_point_type_name(sp->type));
        cJSON_AddNumberToObject(o, "branches", sp->nbranches);
        cJSON_AddBoolToObject(o, "approximate", sp->approximate);
        cJSON_AddItemToArray(points, o);
    }
    cJSON_AddItemToObject(doc, "points", points);
    const ic_trace_report *rep = ic_trace_result_report(r);
    cJSON *ro = cJSON_CreateObject();
    cJSON_AddBoolToObject(ro, "complete", rep->complete);
    cJSON_AddNumberToObject(ro, "cells", rep->cells);
    cJSON_AddNumberToObject(ro, "cells_excluded_by_intervals", rep->cells_excluded);
    cJSON_AddNumberToObject(ro, "cells_excluded_by_centred_forms", rep->cells_excluded_centred);
    cJSON_AddBoolToObject(ro, "exclusion_proven", rep->proven);
    cJSON_AddStringToObject(ro, "sampled",
                            rep->proven ? "start points inside the cells that were not excluded"
                                        : "everything: a surface has no interval evaluation");
    cJSON_AddNumberToObject(ro, "smallest_cell", rep->cell_size);
    cJSON_AddNumberToObject(ro, "start_candidates", rep->candidates);
    cJSON_AddNumberToObject(ro, "uncovered_cells", rep->uncovered_cells);
    cJSON_AddNumberToObject(ro, "unproven_cells", rep->unproven_cells);
    cJSON_AddNumberToObject(ro, "loop_free_cells", rep->loop_free_cells);
    cJSON_AddNumberToObject(ro, "loop_cells", rep->loop_cells);
    cJSON_AddNumberToObject(ro, "refined_cells", rep->refined_cells);
    cJSON_AddNumberToObject(ro, "undecided_loop_cells", rep->undecided_loop_cells);
    cJSON_AddNumberToObject(ro, "coincident_cells", rep->coincident_cells);
    cJSON *f = cJSON_CreateArray();
    for (int i = 0; i < rep->nfailures; i++)
        cJSON_AddItemToArray(f, cJSON_CreateString(rep->failures[i]));
    cJSON_AddItemToObject(ro, "failures", f);
    cJSON_AddItemToObject(doc, "report", ro);
    return doc;
}

typedef enum { FORMAT_JSON, FORMAT_CSV, FORMAT_VTK, FORMAT_OBJ, FORMAT_TEXT } out_format;

/* A summary table for people: the curves, the singular points, the report. */
static int write_summary(FILE *f, const ic_trace_result *r, const char *title)
{
    if (title && *title)
        fprintf(f, "%s\n", title);
    const int nc = ic_trace_result_num_curves(r), ns = ic_trace_result_num_specials(r);
    fprintf(f, "curves: %d\n", nc);
    if (nc > 0)
        fprintf(f, "  %-3s %-7s %-12s %-20s %-7s %-14s %s\n", "#", "closed", "type", "length",
                "points", "shape", "ends");
    for (int i = 0; i < nc; i++) {
        const ic_trace_curve *c = ic_trace_result_curve(r, i);
        char ends[64];
        if (c->closed)
            snprintf(ends, sizeof ends, "-");
        else
            snprintf(ends, sizeof ends, "%s, %s", ic_trace_event_name(c->ends[0]),
                     ic_trace_event_name(c->ends[1]));
        fprintf(f, "  %-3d %-7s %-12s %-20.15g %-7d %-14s %s\n", i + 1, c->closed ? "yes" : "no",
                c->tangential ? "tangential" : "transversal", c->length, c->npoints,
                ic_shape_name(c->shape), ends);
    }
    fprintf(f, "singular points: %d\n", ns);
    if (ns > 0)
        fprintf(f, "  %-3s %-20s %-22s %-22s %-22s %s\n", "#", "type", "x", "y", "z", "branches");
    for (int i = 0; i < ns; i++) {
        const ic_trace_special *sp = ic_trace_result_special(r, i);
        fprintf(f, "  %-3d %-20s %-22.15g %-22.15g %-22.15g %d%s\n", i + 1,
                ic_point_type_name(sp->type), sp->xyz[0], sp->xyz[1], sp->xyz[2], sp->nbranches,
                sp->approximate ? " (approximate)" : "");
    }
    const ic_trace_report *rep = ic_trace_result_report(r);
    fprintf(f, "result: %s\n",
            rep->complete ? "complete (every cell of the search was decided)"
                          : "INCOMPLETE (see the failures: parts of the search were not decided)");
    fprintf(f,
            "search: %d cells, %d excluded by interval arithmetic (%s), %d loop-free, %d where a "
            "small loop is not excluded, %d refined, %d uncovered, %d unproven, %d undecided "
            "loop cells, %d coincident\n",
            rep->cells, rep->cells_excluded, rep->proven ? "proven" : "sampled only",
            rep->loop_free_cells, rep->loop_cells, rep->refined_cells, rep->uncovered_cells,
            rep->unproven_cells, rep->undecided_loop_cells, rep->coincident_cells);
    fprintf(f, "failures: %d\n", rep->nfailures);
    for (int i = 0; i < rep->nfailures; i++)
        fprintf(f, "  %s\n", rep->failures[i]);
    return ferror(f) ? -1 : 0;
}

/* Writes the result in the format to an open stream; 0 on success. */
static int write_result(FILE *f, out_format fmt, const ic_trace_result *res, const ic_pair *pair,
                        const char *title)
{
    ic_error err;
    switch (fmt) {
    case FORMAT_TEXT:
        return write_summary(f, res, title);
    case FORMAT_CSV:
        return ic_trace_write_csv(f, res, pair, &err) == IC_OK ? 0 : -1;
    case FORMAT_VTK:
        return ic_trace_write_vtk(f, res, &err) == IC_OK ? 0 : -1;
    case FORMAT_OBJ:
        return ic_trace_write_obj(f, res, &err) == IC_OK ? 0 : -1;
    case FORMAT_JSON:
        break;
    }
    return ic_json_write(f, result_json(res, pair));
}

/* What write_atomic hands to the safe file's stream. */
typedef struct {
    out_format fmt;
    const ic_trace_result *res;
    const ic_pair *pair;
    const char *title;
} trace_output;

static int fill_output(FILE *f, void *ctx)
{
    const trace_output *o = ctx;
    return write_result(f, o->fmt, o->res, o->pair, o->title);
}

/* Writes the result to path as a safe file (io/safe_file.h): a temporary and
 * a rename, so an interrupted run never leaves half a file, or a device in
 * place. Prints the reason of a failure. */
static int write_atomic(const char *path, out_format fmt, const ic_trace_result *res,
                        const ic_pair *pair, const char *title)
{
    trace_output o = {fmt, res, pair, title};
    ic_error err;
    if (ic_safe_write_stream(path, fill_output, &o, &err) == IC_OK)
        return 0;
    fprintf(stderr, "intercurve trace: %s\n", err.message);
    return -1;
}

int ic_cmd_trace(int argc, char **argv)
{
    const char *file = NULL, *outpath = NULL, *format = "json";
    ic_trace_options opt;
    ic_trace_defaults(&opt);
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            fputs(TRACE_HELP, stdout);
            return 0;
        }
        const int has_value = i + 1 < argc;
        if (strcmp(argv[i], "--format") == 0 && has_value)
            format = argv[++i];
        else if (strcmp(argv[i], "-o") == 0 && has_value)
            outpath = argv[++i];
        else if (strcmp(argv[i], "--tol") == 0 && has_value) {
            double v;
            if (ic_cli_parse_list(&v, 1, argv[++i], "--tol") != 1 || !(v > 0) || v > 1e-2) {
                fprintf(stderr, "intercurve trace: --tol expects a fraction of the problem's size in (0, 1e-2]\n");
                return EXIT_INPUT;
            }
            opt.tol = v;
        } else if (strcmp(argv[i], "--depth") == 0 && has_value) {
            if (ic_cli_parse_int(&opt.depth, argv[++i], 1, 9, "--depth") < 0)
                return EXIT_INPUT;
        } else if (strcmp(argv[i], "--time-limit") == 0 && has_value) {
            double v;
            if (ic_cli_parse_list(&v, 1, argv[++i], "--time-limit") != 1 || !(v > 0) ||
                !(v <= 1e6)) {
                fprintf(stderr, "intercurve trace: --time-limit expects seconds in (0, 1e6]\n");
                return EXIT_INPUT;
            }
            opt.time_limit = v;
        } else if (argv[i][0] == '-' && argv[i][1] != '\0') {
            fprintf(stderr,
                    "intercurve trace: unknown option or missing value: %s\n"
                    "try 'intercurve trace --help'\n",
                    argv[i]);
            return EXIT_INPUT;
        } else if (!file)
            file = argv[i];
        else {
            fprintf(stderr, "intercurve trace: unexpected argument '%s'\n", argv[i]);
            return EXIT_INPUT;
        }
    }
    if (!file) {
        fprintf(stderr, "intercurve trace: needs PROBLEM.json\n%s", TRACE_HELP);
        return EXIT_INPUT;
    }
    static const char *const format_names[] = {"json", "csv", "vtk", "obj", "text"};
    out_format fmt = FORMAT_JSON;
    while (fmt <= FORMAT_TEXT && strcmp(format, format_names[fmt]) != 0)
        fmt++;
    if (fmt > FORMAT_TEXT) {
        fprintf(stderr, "intercurve trace: --format %s is not one of json, csv, vtk, obj, text\n",
                format);
        return EXIT_INPUT;
    }
    ic_cli_traced t;
    int rc = ic_cli_trace_file(file, &opt, &t);
    if (rc != 0)
        return rc;
    const ic_trace_result *res = t.res;
    const ic_pair *pair = t.pair;
    const char *title = ic_problem_title(t.problem);
    if (outpath) {
        rc = write_atomic(outpath, fmt, res, pair, title) == 0 ? 0 : EXIT_COMPUTE;
    } else {
        rc = write_result(stdout, fmt, res, pair, title) == 0 && fflush(stdout) == 0 ? 0
                                                                                     : EXIT_COMPUTE;
        if (rc != 0)
            fprintf(stderr, "intercurve trace: writing the output failed\n");
    }
    ic_cli_traced_free(&t);
    return rc;
}
