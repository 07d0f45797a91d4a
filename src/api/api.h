/* The library's entry points for the command (src/cli) beyond the public
 * headers, which the bindings (bindings.c) share: a problem's pair, and the
 * problem paired, traced and fitted in one call, so that `intercurve trace`
 * and ic_problem_trace cannot drift apart; and the listing of a CAD file's
 * surfaces, so that the command needs none of the CAD reader's internals. */
#ifndef IC_API_H
#define IC_API_H

#include <stdio.h>

#include "intercurve/problem.h"
#include "intercurve/trace.h"

/* The pair of the problem's surfaces (its one surface with itself for a
 * self-intersection): ic_pair_new's statuses. */
ic_status ic_api_problem_pair(ic_pair **pair, const ic_problem *problem, ic_error *err);

/* The step of ic_api_trace_problem that failed, for the caller's message. */
typedef enum { IC_API_PAIR, IC_API_TRACE, IC_API_FIT } ic_api_stage;

/* Pairs the problem's surfaces (its one surface with itself for a
 * self-intersection), sets opt->has_box and opt->box from the problem,
 * traces the pair with *opt (its progress callback included), then, when
 * fit_tol > 0, fits the curves' B-splines at fit_tol (ic_trace_fit). *res
 * and *pair belong to the caller (free res before pair); both are NULL on
 * failure, when *failed says which step it was. */
ic_status ic_api_trace_problem(ic_trace_result **res, ic_pair **pair, const ic_problem *problem,
                               ic_trace_options *opt, double fit_tol, ic_api_stage *failed,
                               ic_error *err);

/* Every surface of the STEP or IGES file `path` written to f as text lines
 * or (json) one document (docs/cad-files.md, "Listing a file"). On failure
 * *read_failed is 1 when the file could not be read (the message begins
 * with the path; IC_ERR_NOMEM, or the reader's statuses), 0 when writing
 * to f failed (IC_ERR_IO, IC_ERR_NOMEM). */
ic_status ic_api_list_surfaces(FILE *f, const char *path, int json, int *read_failed,
                               ic_error *err);

/* The trace document doc_text (named `name` in messages) checked against
 * the problem without the tracer (docs/tracing.md, "The certificate"): its
 * curves held against a cover grown afresh; *out the verdict. IC_OK when the
 * check ran (accepted or refused: out says), IC_ERR_INVALID for a document
 * that is not a trace of curves (the message names the JSON path), the
 * pair's or the region's errors, IC_ERR_NOMEM. With cert_text (NULL: none)
 * the certificate file's cover is replayed instead of grown
 * (certify/plan.h): every leaf proven again, refused where the file says
 * otherwise; IC_ERR_INVALID for a file that is not a certificate of this
 * problem's region. */
ic_status ic_api_verify(const ic_problem *problem, const char *doc_text, const char *name,
                        const char *cert_text, const char *cert_name, ic_trace_certificate *out,
                        ic_error *err);

/* A certificate file (its text; name for messages) read into the cover it
 * holds (certificate_read.c): *plan the caller's to free
 * (ic_cover_plan_free), NULL for a file of a check that did not run, whose
 * reason is copied into reason[size]. IC_ERR_INVALID naming the JSON path
 * of what is wrong, IC_ERR_NOMEM. */
typedef struct ic_cover_plan ic_cover_plan;

/* The certificate file of a trace res (an ic_trace_result kept with
 * keep_certificate; void * to be an ic_file_writer): the checker's cover,
 * or where the checker did not run a file that says so and why
 * (ic_api_unchecked_reason). IC_ERR_IO when f fails. */
ic_status ic_api_write_certificate(FILE *f, void *res, ic_error *err);
const char *ic_api_unchecked_reason(const ic_trace_result *res);
ic_status ic_api_read_certificate(const char *text, const char *name, ic_cover_plan **plan,
                                  char *reason, size_t size, ic_error *err);

#endif
