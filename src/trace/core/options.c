/* The options of a trace: their defaults, the check of what ic_trace
 * accepts, their lengths made absolute for a problem of size L, and the
 * clock of the work limits and of the progress calls. */
#define _POSIX_C_SOURCE 200809L
#include "options.h"
#include "trace_constants.h"

#include <math.h>
#include <string.h>
#include <time.h>

void ic_trace_defaults(ic_trace_options *opt)
{
    if (!opt)
        return;
    memset(opt, 0, sizeof *opt);
    /* fractions of the problem's size L (ic_trace_problem_scale): about the
     * absolute values of earlier versions for the bundled examples, whose L
     * is 3 to 14 (include/intercurve/defaults.h) */
    opt->tol = IC_TRACE_TOL_DEFAULT;
    opt->chord = IC_TRACE_CHORD_DEFAULT;
    opt->max_step = IC_TRACE_MAX_STEP_DEFAULT;
    opt->min_step = IC_TRACE_MIN_STEP_DEFAULT;
    opt->order = IC_TRACE_ORDER_DEFAULT;
    opt->max_points = IC_TRACE_MAX_POINTS_DEFAULT;
    opt->depth = IC_TRACE_DEPTH_DEFAULT;
    opt->shape_tol = IC_TRACE_SHAPE_TOL_DEFAULT;
    opt->exact_paths = 1;
    opt->threads = IC_TRACE_THREADS_DEFAULT; /* all the cores */
    opt->certify = 1;
    opt->keep_certificate = 0;
    ic_local_defaults(&opt->local);
}

ic_trace_options ic_trace_absolute_options(const ic_trace_options *opt, double L)
{
    ic_trace_options a = *opt;
    a.tol *= L;
    a.chord *= L;
    a.max_step *= L;
    a.min_step *= L;
    a.local.scale = L;
    a.local.point_tol = IC_TRACE_POINT_TOL * L;
    a.local.kappa_zero = opt->local.kappa_zero / L;
    return a;
}

/* The options ic_trace accepts: IC_OK, or IC_ERR_INVALID saying which. */
ic_status ic_trace_check_options(const ic_trace_options *o, ic_error *err)
{
    if (o->depth < 1 || o->depth > IC_TRACE_MAX_DEPTH)
        return ic_error_set(err, IC_ERR_INVALID, 0, "trace: depth %d is not in 1..%d", o->depth,
                            IC_TRACE_MAX_DEPTH);
    if (o->order < 3 || o->order > 12 || o->max_points < 2)
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            "trace: order %d is not in 3..12, or max_points %d below 2", o->order,
                            o->max_points);
    const double rel[4] = {o->tol, o->chord, o->max_step, o->min_step};
    for (int k = 0; k < 4; k++)
        if (!(rel[k] > 0) || !isfinite(rel[k]))
            return ic_error_set(err, IC_ERR_INVALID, 0,
                                "trace: tol, chord, max_step and min_step must be positive and "
                                "finite");
    if (o->certify != 0 && o->certify != 1)
        return ic_error_set(err, IC_ERR_INVALID, 0, "trace: certify %d is not 0 or 1",
                            o->certify);
    if (o->keep_certificate != 0 && o->keep_certificate != 1)
        return ic_error_set(err, IC_ERR_INVALID, 0, "trace: keep_certificate %d is not 0 or 1",
                            o->keep_certificate);
    if (o->threads < 0 || o->threads > IC_TRACE_MAX_THREADS)
        return ic_error_set(err, IC_ERR_INVALID, 0, "trace: threads %d is not in 0..%d",
                            o->threads, IC_TRACE_MAX_THREADS);
    if (!(o->time_limit >= 0) || !(o->shape_tol > 0))
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            "trace: time_limit must be 0 or positive, shape_tol positive");
    for (int k = 0; o->has_box && k < 3; k++)
        if (!isfinite(o->box[k][0]) || !isfinite(o->box[k][1]) || !(o->box[k][1] > o->box[k][0]))
            return ic_error_set(err, IC_ERR_INVALID, 0,
                                "trace: box[%d] = [%g, %g] is not a finite, increasing interval",
                                k, o->box[k][0], o->box[k][1]);
    return IC_OK;
}

double ic_trace_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int ic_trace_out_of_time(ic_trace_budget *b)
{
    if (b->deadline > 0 && ic_trace_now() > b->deadline) {
        b->stopped = IC_TRACE_STOP_TIME;
        return 1;
    }
    return 0;
}

void ic_trace_progress(ic_trace_result *r, const ic_trace_options *opt, const char *stage,
                       long done, long total)
{
    /* seconds between two reports: often enough to show life, rarely
     * enough to cost nothing */
    const double EVERY = 0.5;
    if (!opt->progress)
        return;
    const double now = ic_trace_now();
    if (r->last_progress == 0)
        r->last_progress = now;
    if (now - r->last_progress < EVERY)
        return;
    r->last_progress = now;
    opt->progress(opt->progress_user, stage, done, total);
}
