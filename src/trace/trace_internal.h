/* Internal pieces of the general path of the tracer: the search, the march,
 * the singular points, the refinement of open cells and the joining. What
 * every path shares (the result, the options, polylines) is in core/. */
#ifndef IC_TRACE_INTERNAL_H
#define IC_TRACE_INTERNAL_H

#include "core/curve_index.h"
#include "core/near.h"
#include "core/options.h"
#include "core/polyline.h"
#include "core/result.h"
#include "intercurve/trace.h"

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

/* march.c: a tracer taking options made absolute (ic_trace_absolute_options,
 * core/options.h). */
ic_status ic_tracer_new_absolute(ic_tracer **tr, ic_pair *pair, const ic_trace_options *opt,
                                 ic_error *err);
/* ic_tracer_run stops a curve (IC_TRACE_BUDGET) past this time (march.c). */
void ic_tracer_set_deadline(ic_tracer *tr, double deadline);
/* 1 when pt lies outside a non-periodic domain of a sheet or the box (march.c). */
int ic_tracer_outside(const ic_tracer *tr, const ic_local_point *pt);

/* The threads of a trace (workers.h) and a part of the search done ahead
 * by them (search_internal.h). */
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
 * covers (candidates.c); and, at the end, lists as failures the deferred
 * candidates that nothing traced passes within radius of. */
ic_status ic_trace_from_candidates(ic_trace_result *r, ic_tracer *tr, ic_pair *pair,
                                   ic_candidate *cand, int nc, const ic_trace_options *opt,
                                   ic_error *err);
void ic_trace_list_deferred(ic_trace_result *r, double radius);

/* resolve.c: every open cell refined until decided or out of levels or
 * budget (*cells is taken and replaced by the cells left open); then the
 * ones still open counted and listed, merged into regions of the search's
 * dim coordinates. */
ic_status ic_trace_resolve_cells(ic_trace_result *r, ic_tracer *tr, ic_pair *pair,
                                 const ic_trace_options *opt, ic_unresolved **cells, int *n,
                                 ic_error *err);
void ic_trace_report_open_cells(ic_trace_result *r, const ic_unresolved *u, int n, int dim);

/* coincident.c: whether the surfaces coincide around pt (a point of both
 * with parallel normals). */
int ic_trace_coincident_at(ic_pair *pair, const ic_local_point *pt, double L);
/* The diagonal of the bounding box of the first search's start points and
 * open cells, when between 1e-3 L and L; else L. */
double ic_trace_found_scale(double L, const ic_candidate *c, int nc, const ic_unresolved *u,
                            int nu);
/* surface_singular.c: a point where an implicit surface's gradient
 * vanishes, on the other (implicit) surface, within 1e-2 L of near; 1 with
 * it in out. */
int ic_trace_locate_surface_singular(ic_pair *pair, const double *near, double L, double *out);


/* Traces the curve through pt in both directions into a new curve of r
 * (curve_ends.c). */
ic_status ic_trace_both_ways(ic_trace_result *r, ic_tracer *tr, ic_pair *pair,
                             const ic_local_point *pt, const ic_trace_options *opt,
                             ic_trace_point **pts_out, int *n_out, ic_error *err);

/* shape.c */
ic_shape ic_trace_shape(const ic_trace_point *p, int n, double length, double tol, int tangential);

/* join.c; the arc length from p (travelling along t0) to q (along t1) */
double ic_trace_gap_length(const ic_trace_point *p, const double *t0, const ic_trace_point *q,
                           const double *t1);
/* max_gap: the largest gap bridged where a curve passes a degenerate point
 * of a parametrization */
ic_status ic_trace_join_curves(ic_trace_result *r, ic_pair *pair, double shape_tol,
                               double max_gap);
/* IC_ERR_NOMEM when out of memory (join.c) */
ic_status ic_trace_drop_duplicates(ic_trace_result *r, double radius);

/* retry.c: the curves traced twice dropped, the rest joined through the
 * singular points at their ends, the points on tangential curves dropped,
 * a surface's singular points' half-branches halved, and the curves
 * indexed anew. */
ic_status ic_trace_tidy_curves(ic_trace_result *r, ic_pair *pair, const ic_trace_options *opt,
                               ic_error *err);
/* retry.c: r certified (certify_result.h); while the checker refuses for
 * arcs without a traced curve, the tracer tr (at the absolute options opt)
 * marches from a point of each and the checker runs again, a few rounds at
 * most; the last refusal goes to the failures. */
ic_status ic_trace_certify_seeded(ic_trace_result *r, ic_tracer *tr, ic_pair *pair,
                                  const ic_trace_options *user_opt, const ic_trace_options *opt,
                                  ic_error *err);

/* singular.c */
int ic_trace_found_near(const ic_trace_result *r, const ic_unresolved *u);
ic_status ic_trace_record_tangential(ic_trace_result *r, ic_tracer *tr, ic_pair *pair,
                                     const ic_local_point *near, double reach, int keep_unrefined,
                                     const ic_trace_options *opt, int *curve);
ic_status ic_trace_complete_branches(ic_trace_result *r, ic_tracer *tr, ic_pair *pair,
                                     const ic_trace_options *opt);
ic_status ic_trace_tangential_in_cell(ic_trace_result *r, ic_tracer *tr, ic_pair *pair,
                                      const ic_unresolved *u, const ic_trace_options *opt);
/* Drops the tangential points (contacts, cusps, tacnodes, higher-order
 * contacts, unclassified) within radius of a tangential curve and of no
 * curve's end: points of that curve, classified off it. */
void ic_trace_drop_points_on_tangential(ic_trace_result *r, double radius);

/* Curve points just before a located singular point pts[n] (the curve's
 * end, continued by branch br with orientation sg) where the normals are
 * nearly parallel: their t, n, b, kappa and tau are recomputed from the
 * branch's Taylor series (refit.c). */
void ic_trace_refit_near_special(ic_trace_point *pts, int n, const ic_branch *br, double sg);

#endif
