/**
 * @file bindings.h
 * Entry points for other languages (the Python package, docs/python.md):
 * what `intercurve trace`, `point` and `plot` do, with only handles,
 * numbers and strings crossing, so that a foreign-function interface such
 * as ctypes needs no structure but ::ic_error. Documents come back as the
 * JSON of docs/output-formats.md in memory the library allocates and the
 * caller frees with ic_free.
 *
 * Threads: calls on different problems may run at the same time (nothing is
 * shared between them); a problem's surfaces keep evaluation workspaces, so
 * calls on one problem, or on its pairs and results, must not overlap.
 */
#ifndef INTERCURVE_BINDINGS_H
#define INTERCURVE_BINDINGS_H

#include <stddef.h>

#include "intercurve/common.h"
#include "intercurve/local.h"
#include "intercurve/problem.h"
#include "intercurve/trace.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Frees memory the library allocated for the caller (the documents
 *  below); NULL is allowed. */
IC_API void ic_free(void *mem);

/**
 * Traces a problem as `intercurve trace` does: a pair of its surfaces (its
 * one surface with itself for a self-intersection), the problem's box,
 * ic_trace with ic_trace_defaults except tol (relative, as --tol: in
 * (0, 1e-2]), depth (1..IC_TRACE_MAX_DEPTH), time_limit (seconds, 0:
 * none) and threads (as --threads: 0..IC_TRACE_MAX_THREADS, 0 all the
 * cores; the same result whatever the number); then, when fit_tol > 0, ic_trace_fit at fit_tol (relative, as
 * --fit-tol: at most 1e-2; 0: no B-splines). *res and *pair belong to the
 * caller (free res before pair); both are NULL on failure. IC_ERR_INVALID
 * for a value out of range or a pair the problem cannot make; ic_trace's
 * and ic_trace_fit's statuses otherwise.
 */
IC_API IC_NODISCARD ic_status ic_problem_trace(ic_trace_result **res, ic_pair **pair,
                                               const ic_problem *problem, double tol, int depth,
                                               double time_limit, int threads, double fit_tol,
                                               ic_error *err);

/** ic_problem_trace, and the checker's cover kept as a certificate file
 *  (ic_trace_options.keep_certificate): ic_trace_result_certificate(*res)
 *  gives its text (docs/output-formats.md, "The certificate file"). */
IC_API IC_NODISCARD ic_status ic_problem_trace_keep_certificate(
    ic_trace_result **res, ic_pair **pair, const ic_problem *problem, double tol, int depth,
    double time_limit, int threads, double fit_tol, ic_error *err);

/** The trace document of res, a trace of `pair` (ic_trace_write_json), as
 *  a NUL-terminated text in *json, *len bytes long without the NUL; the
 *  caller frees it with ic_free. *json is NULL on failure (ic_trace_write_json's
 *  statuses). */
IC_API IC_NODISCARD ic_status ic_trace_json_alloc(char **json, size_t *len,
                                                  const ic_trace_result *res,
                                                  const ic_pair *pair, ic_error *err);

/**
 * Checks a saved trace document (the JSON text of `intercurve trace`, NUL
 * terminated) of the problem again with the independent checker, without
 * the tracer, as `intercurve verify` does (docs/tracing.md, "The
 * certificate"): *out the checker's summary, out->accepted its verdict.
 * IC_OK whatever the verdict; IC_ERR_INVALID for a document that is not a
 * trace of this problem's kind (the message says where), IC_ERR_NOMEM.
 */
IC_API IC_NODISCARD ic_status ic_problem_verify(const ic_problem *problem,
                                                const char *trace_json,
                                                ic_trace_certificate *out, ic_error *err);

/** The same, the summary as the JSON text {"certificate": {...}}
 *  (ic_certificate_write_json) in *json (*len bytes; freed with ic_free). */
IC_API IC_NODISCARD ic_status ic_problem_verify_json(char **json, size_t *len,
                                                     const ic_problem *problem,
                                                     const char *trace_json, ic_error *err);

/**
 * ic_problem_verify with a certificate file (the text of `intercurve trace
 * --certificate`, NUL terminated) whose cover is replayed instead of grown,
 * as `intercurve verify --certificate` does (docs/tracing.md, "The
 * certificate file"): each of its leaves is proven again and must be what
 * the file says (else out->accepted is 0 and out->reason names the cell).
 * IC_ERR_INVALID also for a file that is not a certificate of this
 * problem's region (the message names the JSON path).
 */
IC_API IC_NODISCARD ic_status ic_problem_verify_certificate(const ic_problem *problem,
                                                            const char *trace_json,
                                                            const char *certificate_json,
                                                            ic_trace_certificate *out,
                                                            ic_error *err);

/** The same, the summary as ic_problem_verify_json writes it;
 *  certificate_json NULL: as ic_problem_verify_json. */
IC_API IC_NODISCARD ic_status ic_problem_verify_certificate_json(
    char **json, size_t *len, const ic_problem *problem, const char *trace_json,
    const char *certificate_json, ic_error *err);

/**
 * The point document of `intercurve point` (ic_local_write_json) as a
 * NUL-terminated text in *json (*len bytes; freed with ic_free): the point
 * of the problem found by ic_local_find from `values` (count 3 coordinates,
 * or with by_params the parameters of its parametric surfaces, as --params)
 * with ic_local_defaults but point_tol (a length, > 0), analysed by
 * ic_local_apparatus to `order` (1..IC_LOCAL_MAX_ORDER) with the method
 * called `method` ("auto", "jet", "closed-form", "perturbation",
 * "height-difference"). *json is NULL on failure: IC_ERR_INVALID for
 * wrong values, the statuses of ic_local_find and ic_local_apparatus.
 */
IC_API IC_NODISCARD ic_status ic_problem_point_json(char **json, size_t *len,
                                                    const ic_problem *problem,
                                                    const double *values, int count,
                                                    int by_params, int order, const char *method,
                                                    double point_tol, ic_error *err);

/**
 * Draws the problem's scene with the trace res (NULL: the surfaces only)
 * into `path` with ic_plot_write, the format by its extension, as
 * `intercurve plot` does: ic_plot_defaults except width and height,
 * azimuth and elevation (degrees), frames (0..200), chart (0 or 1) and
 * mesh (4..200). IC_ERR_INVALID for a value out of range; ic_plot_write's
 * statuses otherwise.
 */
IC_API IC_NODISCARD ic_status ic_problem_plot(const char *path, const ic_problem *problem,
                                              const ic_trace_result *res, int width, int height,
                                              double azimuth, double elevation, int frames,
                                              int chart, int mesh, ic_error *err);

#ifdef __cplusplus
}
#endif
#endif
