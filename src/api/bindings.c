/* Entry points for other languages (include/intercurve/bindings.h): the
 * commands' work with only handles, numbers and strings crossing. */
#include "api/api.h"
#include "common/args.h"
#include "intercurve/bindings.h"
#include "intercurve/plot.h"
#include "intercurve/writers.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* The ranges of `intercurve trace` and `plot` (include/intercurve/defaults.h):
 * relative tolerances at most MAX_REL_TOL of the problem's size, frames and
 * mesh cells per axis within these counts. */
#define MAX_REL_TOL IC_TRACE_REL_TOL_MAX
#define MAX_FRAMES IC_PLOT_FRAMES_MAX
#define MIN_MESH IC_PLOT_MESH_MIN
#define MAX_MESH IC_PLOT_MESH_MAX

void ic_free(void *mem) { free(mem); }

/* The pointers of ic_problem_trace checked, in the caller's name; *res and
 * *pair NULL. */
#define TRACE_ARGS_NOT_NULL()                                                                      \
    do {                                                                                           \
        IC_ARG_NOT_NULL(res, "res");                                                               \
        IC_ARG_NOT_NULL(pair, "pair");                                                             \
        *res = NULL;                                                                               \
        *pair = NULL;                                                                              \
        IC_ARG_NOT_NULL(problem, "problem");                                                       \
    } while (0)

/* ic_problem_trace, the certificate file kept or not (the pointers
 * checked). */
static ic_status trace_problem(ic_trace_result **res, ic_pair **pair, const ic_problem *problem,
                               double tol, int depth, double time_limit, int threads,
                               double fit_tol, int keep_certificate, ic_error *err)
{
    if (!(tol > 0 && tol <= MAX_REL_TOL))
        return ic_error_set(err, IC_ERR_INVALID, 0, "tol %g is not in (0, %g]", tol, MAX_REL_TOL);
    if (!(fit_tol >= 0 && fit_tol <= MAX_REL_TOL))
        return ic_error_set(err, IC_ERR_INVALID, 0, "fit_tol %g is not in [0, %g]", fit_tol,
                            MAX_REL_TOL);
    ic_trace_options opt;
    ic_trace_defaults(&opt);
    opt.tol = tol;
    opt.depth = depth;
    opt.time_limit = time_limit;
    opt.threads = threads; /* ic_trace refuses it out of range */
    opt.keep_certificate = keep_certificate;
    ic_api_stage failed;
    return ic_api_trace_problem(res, pair, problem, &opt, fit_tol, &failed, err);
}

ic_status ic_problem_trace(ic_trace_result **res, ic_pair **pair, const ic_problem *problem,
                           double tol, int depth, double time_limit, int threads,
                           double fit_tol, ic_error *err)
{
    TRACE_ARGS_NOT_NULL();
    return trace_problem(res, pair, problem, tol, depth, time_limit, threads, fit_tol, 0, err);
}

ic_status ic_problem_trace_keep_certificate(ic_trace_result **res, ic_pair **pair,
                                            const ic_problem *problem, double tol, int depth,
                                            double time_limit, int threads, double fit_tol,
                                            ic_error *err)
{
    TRACE_ARGS_NOT_NULL();
    return trace_problem(res, pair, problem, tol, depth, time_limit, threads, fit_tol, 1, err);
}

/* What a document writer needs, to be printed into a memory stream. */
typedef struct {
    const ic_trace_result *trace;
    const ic_local_result *point;
    const ic_trace_certificate *certificate;
    const ic_pair *pair;
    int order;
} document;

/* Prints the document into a NUL-terminated text the caller frees. */
static ic_status write_memory(char **json, size_t *len, const document *d, ic_error *err)
{
    size_t size = 0;
    FILE *mem = open_memstream(json, &size);
    if (!mem) {
        *json = NULL;
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory for the document");
    }
    ic_status st = d->trace         ? ic_trace_write_json(mem, d->trace, d->pair, err)
                   : d->certificate ? ic_certificate_write_json(mem, d->certificate, err)
                                    : ic_local_write_json(mem, d->point, d->pair, d->order, err);
    /* a memory stream fails only for want of memory */
    if (fclose(mem) != 0 || st == IC_ERR_IO)
        st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory for the document");
    if (st != IC_OK) {
        free(*json);
        *json = NULL;
        return st;
    }
    if (len)
        *len = size;
    return IC_OK;
}

ic_status ic_trace_json_alloc(char **json, size_t *len, const ic_trace_result *res,
                              const ic_pair *pair, ic_error *err)
{
    IC_ARG_NOT_NULL(json, "json");
    IC_ARG_NOT_NULL(res, "res");
    IC_ARG_NOT_NULL(pair, "pair");
    const document d = {res, NULL, NULL, pair, 0};
    return write_memory(json, len, &d, err);
}

ic_status ic_problem_verify(const ic_problem *problem, const char *trace_json,
                            ic_trace_certificate *out, ic_error *err)
{
    IC_ARG_NOT_NULL(problem, "problem");
    IC_ARG_NOT_NULL(trace_json, "trace_json");
    IC_ARG_NOT_NULL(out, "out");
    return ic_api_verify(problem, trace_json, "the trace document", NULL, NULL, out, err);
}

ic_status ic_problem_verify_certificate(const ic_problem *problem, const char *trace_json,
                                        const char *certificate_json, ic_trace_certificate *out,
                                        ic_error *err)
{
    IC_ARG_NOT_NULL(problem, "problem");
    IC_ARG_NOT_NULL(trace_json, "trace_json");
    IC_ARG_NOT_NULL(certificate_json, "certificate_json");
    IC_ARG_NOT_NULL(out, "out");
    return ic_api_verify(problem, trace_json, "the trace document", certificate_json,
                         "the certificate file", out, err);
}

ic_status ic_problem_verify_json(char **json, size_t *len, const ic_problem *problem,
                                 const char *trace_json, ic_error *err)
{
    IC_ARG_NOT_NULL(json, "json");
    *json = NULL;
    IC_ARG_NOT_NULL(problem, "problem");
    return ic_problem_verify_certificate_json(json, len, problem, trace_json, NULL, err);
}

ic_status ic_problem_verify_certificate_json(char **json, size_t *len, const ic_problem *problem,
                                             const char *trace_json, const char *certificate_json,
                                             ic_error *err)
{
    IC_ARG_NOT_NULL(json, "json");
    *json = NULL;
    IC_ARG_NOT_NULL(problem, "problem");
    ic_trace_certificate c;
    const ic_status st =
        certificate_json ? ic_problem_verify_certificate(problem, trace_json, certificate_json, &c,
                                                         err)
                         : ic_problem_verify(problem, trace_json, &c, err);
    if (st != IC_OK)
        return st;
    const document d = {NULL, NULL, &c, NULL, 0};
    return write_memory(json, len, &d, err);
}

ic_status ic_problem_point_json(char **json, size_t *len, const ic_problem *problem,
                                const double *values, int count, int by_params, int order,
                                const char *method, double point_tol, ic_error *err)
{
    IC_ARG_NOT_NULL(json, "json");
    IC_ARG_NOT_NULL(problem, "problem");
    IC_ARG_NOT_NULL(values, "values");
    IC_ARG_NOT_NULL(method, "method");
    *json = NULL;
    const int m = ic_method_from_name(method);
    if (m < 0)
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            "unknown method '%.40s': auto, jet, closed-form, perturbation or "
                            "height-difference",
                            method);
    if (!(point_tol > 0))
        return ic_error_set(err, IC_ERR_INVALID, 0, "point_tol %g is not positive", point_tol);
    ic_local_options opt;
    ic_local_defaults(&opt);
    opt.point_tol = point_tol;
    ic_pair *pair = NULL;
    ic_status st = ic_api_problem_pair(&pair, problem, err);
    ic_local_point pt;
    if (st == IC_OK)
        st = ic_local_find(pair, &pt, values, count, by_params, &opt, err);
    ic_local_result *res = st == IC_OK ? malloc(sizeof *res) : NULL; /* a large record */
    if (st == IC_OK && !res)
        st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory for the point's analysis");
    if (st == IC_OK)
        st = ic_local_apparatus(pair, res, &pt, order, (ic_method)m, &opt, err);
    if (st == IC_OK) {
        const document d = {NULL, res, NULL, pair, order};
        st = write_memory(json, len, &d, err);
    }
    free(res);
    ic_pair_free(pair);
    return st;
}

ic_status ic_problem_plot(const char *path, const ic_problem *problem, const ic_trace_result *res,
                          int width, int height, double azimuth, double elevation, int frames,
                          int chart, int mesh, ic_error *err)
{
    IC_ARG_NOT_NULL(path, "path");
    IC_ARG_NOT_NULL(problem, "problem");
    if (frames < 0 || frames > MAX_FRAMES || mesh < MIN_MESH || mesh > MAX_MESH)
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            "frames %d is not in 0..%d, or mesh %d not in %d..%d", frames,
                            MAX_FRAMES, mesh, MIN_MESH, MAX_MESH);
    if (!isfinite(azimuth) || !isfinite(elevation))
        return ic_error_set(err, IC_ERR_INVALID, 0, "the view's angles must be finite");
    ic_plot_options po;
    ic_plot_defaults(&po);
    po.width = width;
    po.height = height;
    po.azimuth = azimuth;
    po.elevation = elevation;
    po.frames = frames;
    po.chart = chart != 0;
    po.mesh = mesh;
    ic_plot_scene scene;
    ic_plot_scene_of_problem(&scene, problem, res);
    return ic_plot_write(path, &scene, &po, err);
}
