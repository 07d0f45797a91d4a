/* Internal pieces of the tracer. */
#ifndef IC_TRACE_INTERNAL_H
#define IC_TRACE_INTERNAL_H

#include "intercurve/trace.h"

typedef struct ic_curve_index ic_curve_index;

/* A start candidate: a point on both surfaces found in a cell the interval
 * test could not exclude. */
typedef struct {
    double xyz[3];
    double params[2][2];
    int covered;
} ic_candidate;

/* A leaf cell that intervals could not exclude but where Newton found no
 * point: its centre in space (and on the parametric sheets) and a radius
 * covering it. */
typedef struct {
    double xyz[3];
    double params[2][2];
    double radius;           /* 0 when no point of the cell could be evaluated */
    int converged_elsewhere; /* Newton from the centre left the cell */
    int loop;                /* the loop test failed (the pairing's loop_free) */
    int has_candidate;       /* a start point was found in it (a loop cell) */
    int degenerate;          /* R_u x R_v of a parametric sheet may vanish in it */
    int overflow;            /* an enclosure over it is unbounded: not refined */
    int level;               /* levels of refinement below the first search */
    double lo[4], hi[4];     /* the cell in the search's coordinates */
} ic_unresolved;

/* The work limits of one trace (docs/tracing.md, "Work limits"): a wall
 * clock deadline and a count of search cells; `stopped` says which ran out. */
typedef struct {
    double deadline; /* seconds on the monotonic clock; 0: none */
    long cells_left; /* search cells that may still be examined */
    int stopped;     /* 0, or IC_TRACE_STOP_TIME / IC_TRACE_STOP_CELLS */
} ic_trace_budget;

enum { IC_TRACE_STOP_TIME = 1, IC_TRACE_STOP_CELLS = 2 };

/* march.c: the options with their lengths made absolute for a problem of
 * size L (tol, chord, max_step, min_step times L; the locators' scale L),
 * and a tracer taking such options. */
ic_trace_options ic_trace_absolute_options(const ic_trace_options *opt, double L);
ic_status ic_tracer_new_absolute(ic_tracer **tr, ic_pair *pair, const ic_trace_options *opt,
                                 ic_error *err);

/* Calls opt->progress when half a second has passed since the last call. */
void ic_trace_progress(ic_trace_result *r, const ic_trace_options *opt, const char *stage,
                       long done, long total);

/* Seconds on the monotonic clock. */
double ic_trace_now(void);
/* ic_tracer_run stops a curve (IC_TRACE_BUDGET) past this time (march.c). */
void ic_tracer_set_deadline(ic_tracer *tr, double deadline);
/* 1 (and b->stopped set) when the deadline has passed. */
int ic_trace_out_of_time(ic_trace_budget *b);

/* The threads of a trace (workers.h) and a part of the search done ahead
 * by them (search_internal.h). */
typedef struct ic_trace_workers ic_trace_workers;
typedef struct ic_search_part ic_search_part;

/* Start candidates by subdivision (search.c) of the whole search region
 * (its subtrees done ahead by the workers, NULL: none), or, when `within`
 * is not NULL, of that cell one level finer (`ahead`: that search done
 * ahead, or NULL); adds to the report's search part. *unres receives the
 * leaves without a start point and the loop leaves (has_candidate set
 * where one was found). Cells left when the budget runs out are returned as
 * unresolved too. *out and *unres are malloc'ed (free them). The result is
 * the same with and without workers or ahead. */
ic_status ic_trace_candidates(ic_pair *pair, const ic_trace_options *opt,
                              const ic_unresolved *within, ic_trace_workers *workers,
                              ic_search_part *ahead, ic_candidate **out, int *n,
                              ic_unresolved **unres, int *nunres, ic_trace_report *rep,
                              ic_trace_budget *budget, ic_error *err);
/* Whether an open cell found will be refined as things stand (called by
 * the workers while the trace waits for them: it only reads). */
typedef int ic_search_wanted(const void *ctx, const ic_unresolved *u);
/* search_ahead.c: the finer searches of the cells u[0..n-1] (as
 * ic_trace_candidates with within = u[i]) done by the workers into
 * parts[i] (NULL out of memory), with the trace's budget as it is now;
 * proven as in the report; and down their trees, those of the open cells
 * found that `wanted` says will be refined (ic_search_part_take_child). */
void ic_search_ahead_cells(ic_trace_workers *workers, ic_pair *pair, const ic_trace_options *opt,
                           int proven, const ic_unresolved *const *u, int n,
                           ic_search_wanted *wanted, const void *wanted_ctx,
                           const ic_trace_budget *budget, ic_search_part **parts);
/* The finer search done ahead for p's i-th unresolved cell (the caller's
 * from now on), or NULL. */
ic_search_part *ic_search_part_take_child(ic_search_part *p, int i);
void ic_search_part_free(ic_search_part *p);

/* Traces a curve from every start candidate that no curve traced so far
 * covers (trace.c). */
ic_status ic_trace_from_candidates(ic_trace_result *r, ic_tracer *tr, ic_pair *pair,
                                   ic_candidate *cand, int nc, const ic_trace_options *opt,
                                   ic_error *err);

/* resolve.c: every open cell refined until decided or out of levels or
 * budget (*cells is taken and replaced by the cells left open); then the
 * ones still open counted and listed, merged into regions of the search's
 * dim coordinates. */
ic_status ic_trace_resolve_cells(ic_trace_result *r, ic_tracer *tr, ic_pair *pair,
                                 const ic_trace_options *opt, ic_unresolved **cells, int *n,
                                 ic_error *err);
void ic_trace_report_open_cells(ic_trace_result *r, const ic_unresolved *u, int n, int dim);

/* A recorded singular point: where it was located, and its apparatus to
 * order 3 (res_ok: it could be computed), computed once and shared by every
 * curve end there. */
typedef struct {
    ic_local_point pt;
    ic_local_result res;
    int res_ok;
} ic_trace_located;

/* The result of ic_trace (trace.c, join.c, singular.c). */
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
    double scale;           /* the problem's length scale L (coincident.c) */
    /* points around which the two surfaces coincide (coincident.c) */
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
    ic_curve_fit **fits; /* ncurves B-spline fits (ic_trace_fit), or NULL */
    ic_trace_workers *workers; /* the trace's other threads (NULL: one thread) */
};

/* coincident.c: the problem's length scale L, and whether the surfaces
 * coincide around pt (a point of both with parallel normals). */
double ic_trace_problem_scale(ic_pair *pair, const ic_trace_options *opt);
int ic_trace_coincident_at(ic_pair *pair, const ic_local_point *pt, double L);
/* The diagonal of the bounding box of the first search's start points and
 * open cells, when between 1e-3 L and L; else L. */
double ic_trace_found_scale(double L, const ic_candidate *c, int nc, const ic_unresolved *u,
                            int nu);
/* Records a point where the surfaces coincide; 1 when x is within
 * IC_TRACE_COINCIDENT_REACH L of one recorded (trace.c). */
int ic_trace_add_coincident(ic_trace_result *r, const double *x);
int ic_trace_in_coincident(const ic_trace_result *r, const double *x);

/* curve_index.c: a spatial hash of the traced curves' segments (grid cell
 * size h). ic_curve_index_near: 1 when a segment lies within bound of x
 * (less its sagitta), 0 when none, -1 when the index cannot tell (then scan
 * every curve). */
ic_curve_index *ic_curve_index_new(double h);
void ic_curve_index_free(ic_curve_index *ix);
void ic_curve_index_clear(ic_curve_index *ix);
int ic_curve_index_add(ic_curve_index *ix, int curve, const ic_trace_point *pts, int n);
int ic_curve_index_near(ic_curve_index *ix, const ic_trace_result *r, const double *x,
                        double bound);

/* trace.c: the distance from x to the curve between two traced points (to
 * their chord, less the chord's sagitta), and that sagitta. */
double ic_trace_segment_distance(const ic_trace_point *p, const ic_trace_point *q, const double *x);
double ic_trace_segment_sagitta(const ic_trace_point *p, const ic_trace_point *q);

/* surface_singular.c: a point where an implicit surface's gradient
 * vanishes, on the other (implicit) surface, within 1e-2 L of near; 1 with
 * it in out. */
int ic_trace_locate_surface_singular(ic_pair *pair, const double *near, double L, double *out);

/* Whether a traced curve or recorded singular point lies within bound of x
 * (singular.c). */
int ic_trace_point_near_found(const ic_trace_result *r, const double *x, double bound);

/* trace.c: the report's failure list (at most IC_TRACE_MAX_FAILURES). */
void ic_trace_failure(ic_trace_report *rep, const char *fmt, ...) IC_PRINTF(2, 3);
/* Distance from x to the polyline pts (a single point when np = 1) when it
 * is at most `bound`; otherwise a value above bound (not always the
 * distance: far parts are skipped). */
double ic_trace_polyline_distance(const ic_trace_point *pts, int np, const double *x,
                                  double bound);
/* The box of the polyline pts widened by its largest sagitta and pad; and
 * whether x lies in a box. */
void ic_trace_curve_box(const ic_trace_point *pts, int np, double pad, double *lo, double *hi);
int ic_trace_in_box(const double *x, const double *lo, const double *hi);
/* Marks the candidates within radius of the polyline pts as covered. */
void ic_trace_cover(ic_candidate *c, int n, const ic_trace_point *pts, int np, double radius);
/* Records a located tangential point (once), classified; *index its slot. */
ic_status ic_trace_add_special(ic_trace_result *r, ic_pair *pair, const ic_local_point *pt,
                               int approximate, const ic_trace_options *opt, int *index);
/* Traces the curve through pt in both directions into a new curve of r. */
ic_status ic_trace_both_ways(ic_trace_result *r, ic_tracer *tr, ic_pair *pair,
                             const ic_local_point *pt, const ic_trace_options *opt,
                             ic_trace_point **pts_out, int *n_out, ic_error *err);

/* exact_revolution.c: the pair in closed form when its surfaces are
 * coaxial surfaces of revolution, implicit primitives or NURBS patches
 * recognised as them (the user's options, relative; r->scale the problem's
 * size L): *done = 1 with r filled, its scale that of what was found and
 * its report complete, else *done = 0 and r untouched; IC_ERR_NOMEM out of
 * memory. The report's method strings. */
ic_status ic_trace_exact_revolution(ic_trace_result *r, ic_pair *pair,
                                    const ic_trace_options *user_opt, int *done, ic_error *err);
extern const char ic_trace_method_search[];
extern const char ic_trace_method_revolution[];
extern const char ic_trace_method_revolution_nets[];

/* exact_conic.c: the same for a plane and a quadric primitive meeting in an
 * ellipse, and for two cylinders of equal radius whose axes meet, implicit
 * or NURBS patches recognised as them (tried
 * after the revolution path, which keeps the coaxial cases); and the same
 * on the two implicit primitives themselves. */
ic_status ic_trace_exact_conic(ic_trace_result *r, ic_pair *pair,
                               const ic_trace_options *user_opt, int *done, ic_error *err);
ic_status ic_trace_exact_conic_primitives(ic_trace_result *r, const ic_primitive *pa,
                                          const ic_primitive *pb,
                                          const ic_trace_options *user_opt, int *done,
                                          ic_error *err);
extern const char ic_trace_method_conic[];
extern const char ic_trace_method_conic_nets[];

/* trace.c: adds the curve of the points pts (the result's from now on,
 * freed with it even when this fails) of a shape known; and a special point
 * known exactly (no apparatus computed): 0, or -1 out of memory. */
ic_status ic_trace_add_shaped_curve(ic_trace_result *r, ic_trace_point *pts, int n, int closed,
                                    ic_trace_event e0, ic_trace_event e1, double shape_tol,
                                    ic_shape shape, int at0, int at1, ic_error *err);
int ic_trace_add_exact_special(ic_trace_result *r, const double *xyz, ic_point_type type);

/* shape.c */
ic_shape ic_trace_shape(const ic_trace_point *p, int n, double length, double tol, int tangential);

/* join.c; the arc length from p (travelling along t0) to q (along t1) */
double ic_trace_gap_length(const ic_trace_point *p, const double *t0, const ic_trace_point *q,
                           const double *t1);
/* max_gap: the largest gap bridged where a curve passes a degenerate point
 * of a parametrization */
ic_status ic_trace_join_curves(ic_trace_result *r, double shape_tol, double max_gap);
/* IC_ERR_NOMEM when out of memory (join.c) */
ic_status ic_trace_drop_duplicates(ic_trace_result *r, double radius);

/* singular.c */
int ic_trace_found_near(const ic_trace_result *r, const ic_unresolved *u);
ic_status ic_trace_record_tangential(ic_trace_result *r, ic_tracer *tr, ic_pair *pair,
                                     const ic_local_point *near, double reach, int keep_unrefined,
                                     const ic_trace_options *opt, int *curve);
ic_status ic_trace_complete_branches(ic_trace_result *r, ic_tracer *tr, ic_pair *pair,
                                     const ic_trace_options *opt);
ic_status ic_trace_tangential_in_cell(ic_trace_result *r, ic_tracer *tr, ic_pair *pair,
                                      const ic_unresolved *u, const ic_trace_options *opt);

/* Curve points just before a located singular point pts[n] (the curve's
 * end, continued by branch br with orientation sg) where the normals are
 * nearly parallel: their t, n, b, kappa and tau are recomputed from the
 * branch's Taylor series (singular.c). */
void ic_trace_refit_near_special(ic_trace_point *pts, int n, const ic_branch *br, double sg);

#endif
