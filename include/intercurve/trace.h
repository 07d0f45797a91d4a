/**
 * @file trace.h
 * Marching along an intersection curve (DESIGN.md 2.3), step by step.
 *
 * From a transversal point the tracer steps along the curve: a Taylor
 * predictor from the local jet of order `order` (the point and, on each
 * parametric sheet, the parameters), the step h from the truncation error
 * |c^(K)/K!| h^K <= tol and the chord height kappa h^2 / 8 <= chord, a Newton
 * corrector in the plane through the predicted point normal to the curve
 * (ic_local_locate's refinement), and the full apparatus at every accepted
 * point. Each step reports an event: the curve continues, closed on its
 * start, left a parameter domain or the box, reached a tangential point, or
 * the point budget ran out.
 *
 * This is the marching core; start points, singular points located on the
 * way and whole-intersection tracing come with the tracing issue.
 */
#ifndef INTERCURVE_TRACE_H
#define INTERCURVE_TRACE_H

#include "intercurve/common.h"
#include "intercurve/local.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    double tol;       /**< length: truncation error allowed per step (default 1e-10) */
    double chord;     /**< length: chord-height bound of a step (default 1e-3) */
    double max_step;  /**< length: longest step (default 0.5) */
    double min_step;  /**< length: a step shorter than this fails (default 1e-12) */
    int order;        /**< predictor order K, 3..12 (default 6) */
    int max_points;   /**< point budget of one curve (default 100000) */
    int has_box;      /**< 1: stop when the curve leaves box */
    double box[3][2];
    ic_local_options local;
} ic_trace_options;

void ic_trace_defaults(ic_trace_options *opt);

typedef enum {
    IC_TRACE_CONTINUE,
    IC_TRACE_CLOSED,       /**< back at the start point: a closed curve */
    IC_TRACE_LEFT_DOMAIN,  /**< a parameter left its (non-periodic) domain */
    IC_TRACE_LEFT_BOX,     /**< the curve left the box */
    IC_TRACE_TANGENTIAL,   /**< the next point is tangential (not passed yet) */
    IC_TRACE_BUDGET,       /**< max_points reached */
    IC_TRACE_FAILED        /**< the step shrank below min_step: err says why */
} ic_trace_event;

const char *ic_trace_event_name(ic_trace_event ev);

/** One point of a traced curve (t oriented along the marching direction). */
typedef struct {
    double s;               /**< arc length from the start */
    double xyz[3];
    double params[2][2];
    double t[3], n[3], b[3];
    double kappa, tau;
    int frame_defined;      /**< 0 where kappa = 0: n, b, tau undefined */
} ic_trace_point;

typedef struct ic_tracer ic_tracer;

/** A tracer for a pair (not owned). */
IC_NODISCARD ic_status ic_tracer_new(ic_tracer **tr, ic_pair *pair, const ic_trace_options *opt,
                                     ic_error *err);
void ic_tracer_free(ic_tracer *tr);

/** Starts a curve at a located transversal point, marching along +t
 *  (direction = +1) or -t (-1). IC_ERR_UNABLE at a tangential point. */
IC_NODISCARD ic_status ic_tracer_start(ic_tracer *tr, const ic_local_point *start, int direction,
                                       ic_error *err);
/** One step: appends a point (unless the event ends the curve before it). */
IC_NODISCARD ic_status ic_tracer_step(ic_tracer *tr, ic_trace_event *event, ic_error *err);
/** Steps until an event other than IC_TRACE_CONTINUE. */
IC_NODISCARD ic_status ic_tracer_run(ic_tracer *tr, ic_trace_event *event, ic_error *err);

int ic_tracer_num_points(const ic_tracer *tr);
const ic_trace_point *ic_tracer_point(const ic_tracer *tr, int i);

#ifdef __cplusplus
}
#endif
#endif
