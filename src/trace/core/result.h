/* The result of a trace as every path fills it, the general path (search and
 * march) and the closed forms alike: its curves, its special points, its
 * report and its work limits, and the calls that add to it. */
#ifndef IC_TRACE_RESULT_H
#define IC_TRACE_RESULT_H

#include "common/args.h"
#include "intercurve/trace.h"
#include "common/frame.h"

typedef struct ic_curve_index ic_curve_index;
/* The threads of a trace (trace/workers.h). */
typedef struct ic_trace_workers ic_trace_workers;

/* A start candidate: a point on both surfaces found in a cell the interval
 * test could not exclude, or (seed) a point of an arc the checker proved
 * and no traced curve met (retry.c). */
typedef struct {
    double xyz[3];
    double params[2][2];
    int covered;
    int seed;
} ic_candidate;

/* The work limits of one trace (docs/tracing.md, "Work limits"): a wall
 * clock deadline and a count of search cells; `stopped` says which ran out. */
typedef struct {
    double deadline; /* seconds on the monotonic clock; 0: none */
    long cells_left; /* search cells that may still be examined */
    int stopped;     /* 0, or IC_TRACE_STOP_TIME / IC_TRACE_STOP_CELLS */
} ic_trace_budget;

enum { IC_TRACE_STOP_TIME = 1, IC_TRACE_STOP_CELLS = 2 };

/* A recorded singular point: where it was located, and its apparatus to
 * order 3 (res_ok: it could be computed), computed once and shared by every
 * curve end there. */
typedef struct {
    ic_local_point pt;
    ic_local_result res;
    int res_ok;
    double place_radius; /* the radius it is known to: an approximate contact's, a
                          * crossing's (crossing.c); else 0 */
    int crossing;        /* a crossing of a tangential curve, placed by crossing.c */
} ic_trace_located;

/* The result of ic_trace (trace/core/result.c, trace/join.c, trace/singular.c). */
struct ic_trace_result {
    ic_trace_curve *curves;
    ic_trace_point **storage; /* the points of each curve */
    int (*at)[2];             /* the exact tangential point at each end, or -1 */
    int ncurves, capc;
    ic_trace_special *specials;
    ic_trace_located *located; /* each special's point and apparatus */
    int nspecials, caps;
    ic_trace_report report;
    ic_trace_budget budget;
    double first_cell_size; /* the first search's leaf size */
    double scale;           /* the problem's length scale L (trace/core/scale.c) */
    /* points around which the two surfaces coincide (trace/coincident.c) */
    double (*coincident)[3];
    int ncoincident, capk;
    ic_curve_index *index; /* the curves' segments by place (curve_index.c) */
    double last_progress;  /* when opt->progress was last called */
    /* start candidates where the location failed (a pole of a
     * parametrization, say): listed as failures only when nothing traced
     * passes there in the end */
    ic_candidate *deferred;
    char (*deferred_why)[200];
    int ndeferred, capd;
    /* ncurves B-spline fits made by the curve layer (ic_trace_fit), or
     * NULL, and the curve layer's function that frees them: the result
     * never calls up into that layer itself */
    ic_curve_fit **fits;
    void (*free_fits)(ic_curve_fit **fits, int n);
    ic_trace_workers *workers; /* the trace's other threads (NULL: one thread) */
    char *certificate; /* the last check's certificate file, when kept */
    /* where the traced problem was moved from (trace/frame.h): the
     * failures give points as the user's, xyz + frame.xyz */
    ic_frame frame;
};

/* The report's method of the general path. */
extern const char ic_trace_method_search[];

/* The report's failure list (at most IC_TRACE_MAX_FAILURES). */
void ic_trace_failure(ic_trace_report *rep, const char *fmt, ...) IC_PRINTF(2, 3);

/* Records a located tangential point (once), classified; *index its slot
 * (result.c). */
ic_status ic_trace_add_special(ic_trace_result *r, ic_pair *pair, const ic_local_point *pt,
                               int approximate, const ic_trace_options *opt, int *index);
/* The same for a point known to within place (a length: a crossing of a
 * tangential curve, crossing.c), classified with that uncertainty;
 * place < 0: not known, measured for a contact (ic_local_tangential_place). */
ic_status ic_trace_add_placed_special(ic_trace_result *r, ic_pair *pair, const ic_local_point *pt,
                                      int approximate, double place, const ic_trace_options *opt,
                                      int *index);

/* Adds the curve of the points pts (the result's from now on, freed with it
 * even when this fails) of a shape known; and a special point known exactly
 * (no apparatus computed): 0, or -1 out of memory. */
ic_status ic_trace_add_shaped_curve(ic_trace_result *r, ic_trace_point *pts, int n, int closed,
                                    ic_trace_event e0, ic_trace_event e1, double shape_tol,
                                    ic_shape shape, int at0, int at1, ic_error *err);
int ic_trace_add_exact_special(ic_trace_result *r, const double *xyz, ic_point_type type);

/* Records a point where the surfaces coincide; 1 when x is within
 * IC_TRACE_COINCIDENT_REACH L of one recorded. */
int ic_trace_add_coincident(ic_trace_result *r, const double *x);
int ic_trace_in_coincident(const ic_trace_result *r, const double *x);

#endif
