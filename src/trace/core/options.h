/* The options of a trace as every path uses them: checked, made absolute
 * for a problem of size L, and the clock of the work limits. */
#ifndef IC_TRACE_OPTIONS_H
#define IC_TRACE_OPTIONS_H

#include "result.h"

/* The options ic_trace accepts: IC_OK, or IC_ERR_INVALID saying which. */
ic_status ic_trace_check_options(const ic_trace_options *o, ic_error *err);

/* The options with their lengths made absolute for a problem of size L
 * (tol, chord, max_step, min_step times L; the locators' scale L). */
ic_trace_options ic_trace_absolute_options(const ic_trace_options *opt, double L);

/* The box where the problem's intersection is sought (scale.c): the box
 * for two implicit surfaces, else the parametric sheets' samples (cut to
 * the box when there is one); lo > hi along a coordinate nothing spans. */
void ic_trace_problem_bounds(ic_pair *pair, const ic_trace_options *opt, double lo[3],
                             double hi[3]);
/* The problem's length scale L, the diagonal of those bounds (scale.c;
 * docs/tracing.md, "Scale"). */
double ic_trace_problem_scale(ic_pair *pair, const ic_trace_options *opt);

/* Seconds on the monotonic clock. */
double ic_trace_now(void);
/* 1 (and b->stopped set) when the deadline has passed. */
int ic_trace_out_of_time(ic_trace_budget *b);
/* Calls opt->progress when half a second has passed since the last call. */
void ic_trace_progress(ic_trace_result *r, const ic_trace_options *opt, const char *stage,
                       long done, long total);

#endif
