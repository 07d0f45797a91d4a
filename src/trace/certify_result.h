/* The checker's verdict on a trace (certify_result.c). */
#ifndef IC_TRACE_CERTIFY_RESULT_H
#define IC_TRACE_CERTIFY_RESULT_H

#include "certify/certificate.h"
#include "core/result.h"

/* The public summary of a check (accepted or not, and checked). */
void ic_trace_certificate_from(ic_trace_certificate *out, const ic_certify_summary *s);

/* When r claims the whole intersection, certifies it: r->report.complete
 * becomes the checker's verdict and the report's certificate its summary.
 * sum (NULL: not wanted) receives the summary, with the points of the arcs
 * no curve passes (no seeds when the checker did not run). IC_OK, or an
 * error out of memory. */
ic_status ic_trace_certify(ic_trace_result *r, ic_pair *pair, const ic_trace_options *opt,
                           ic_certify_summary *sum, ic_error *err);

/* A refusal of the last check, if any, goes to the report's failures. */
void ic_trace_certify_verdict(ic_trace_result *r);

#endif
