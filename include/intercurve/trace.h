/**
 * @file trace.h
 * Marching along an intersection curve (docs/tracing.md), step by step.
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
 * ic_tracer is the marching core; ic_trace below traces the whole
 * intersection: start points, every curve, the special points on the way
 * (docs/tracing.md).
 */
#ifndef INTERCURVE_TRACE_H
#define INTERCURVE_TRACE_H

#include "intercurve/common.h"
#include "intercurve/bspline.h"
#include "intercurve/defaults.h"
#include "intercurve/local.h"

#ifdef __cplusplus
extern "C" {
#endif

/** The deepest start-point search ic_trace accepts: 2^9 cells per axis. */
#define IC_TRACE_MAX_DEPTH 9
/** The most threads ic_trace uses (ic_trace_options.threads). */
#define IC_TRACE_MAX_THREADS 256

typedef struct {
    /* The four lengths below are fractions of the problem's size L: the
     * diagonal of the box for two implicit surfaces, else of the bounding
     * box of the parametric surfaces over their domains, cut to the box
     * (docs/tracing.md, "Scale"). A problem scaled by any factor is then
     * traced with the same points and the same relative accuracy. */
    double tol;      /**< relative: truncation error allowed per step (IC_TRACE_TOL_DEFAULT) */
    double chord;    /**< relative: chord-height bound of a step (IC_TRACE_CHORD_DEFAULT) */
    double max_step; /**< relative: longest step (IC_TRACE_MAX_STEP_DEFAULT) */
    double min_step; /**< relative: a step shorter than this fails (IC_TRACE_MIN_STEP_DEFAULT) */
    int order;       /**< predictor order K, 3..12 (IC_TRACE_ORDER_DEFAULT) */
    int max_points;  /**< point budget of one curve (IC_TRACE_MAX_POINTS_DEFAULT) */
    int has_box;     /**< 1: stop when the curve leaves box */
    double box[3][2];
    int depth;        /**< subdivision depth of the start-point search, 1..IC_TRACE_MAX_DEPTH
                       *   (IC_TRACE_DEPTH_DEFAULT: 2^6 cells per axis) */
    double shape_tol; /**< relative tolerance of the shape tests (IC_TRACE_SHAPE_TOL_DEFAULT) */
    double time_limit; /**< seconds of wall time for the whole trace; 0: none (default).
                        *   Reaching it stops with what was found, complete = 0 */
    /** called about twice a second during a long trace (NULL: never):
     *  the stage ("tracing start points", "refining open cells"), how many
     *  of its items are done and how many are known so far */
    void (*progress)(void *user, const char *stage, long done, long total);
    void *progress_user;
    ic_local_options local;
    /** 1: pairs with a closed form are solved in it (coaxial surfaces of
     *  revolution, implicit primitives or NURBS patches recognised as them;
     *  a plane's ellipse on a quadric; two equal cylinders whose axes meet:
     *  docs/tracing.md, "Exact paths"); 0: always the search and the
     *  marching, the reference (default 1) */
    int exact_paths;
    /** threads searching at once: 1 one (the calling thread), 0 all the
     *  machine's online cores (default), at most IC_TRACE_MAX_THREADS. The
     *  result is the same, byte for byte, whatever the number (docs/tracing.md,
     *  "Threads"); callback surfaces are always traced in one thread */
    int threads;
    /** 1: the independent checker proves the result when the tracer finds it
     *  complete, and complete is its verdict (default, docs/tracing.md, "The
     *  certificate"); 0: the checker is not run, complete is always 0 (the
     *  tracer's own account is in tracer_complete): for callers who need the
     *  curves only, and fast */
    int certify;
    /** 1: the checker's cover is kept as a certificate file
     *  (ic_trace_result_certificate; docs/output-formats.md, "The
     *  certificate file"), which `intercurve verify --certificate` checks
     *  again cell by cell; 0: not kept (default: a cover may hold a million
     *  cells) */
    int keep_certificate;
} ic_trace_options;

IC_API void ic_trace_defaults(ic_trace_options *opt);

typedef enum {
    IC_TRACE_CONTINUE,
    IC_TRACE_CLOSED,      /**< back at the start point: a closed curve */
    IC_TRACE_LEFT_DOMAIN, /**< a parameter left its (non-periodic) domain */
    IC_TRACE_LEFT_BOX,    /**< the curve left the box */
    IC_TRACE_TANGENTIAL,  /**< the next point is tangential (not passed yet) */
    IC_TRACE_BUDGET,      /**< max_points reached */
    IC_TRACE_FAILED       /**< the step shrank below min_step: err says why */
} ic_trace_event;

/** "continue", "closed", ...: a static string. */
IC_API const char *ic_trace_event_name(ic_trace_event ev);

/** One point of a traced curve (t oriented along the marching direction). */
typedef struct {
    double s; /**< arc length from the start */
    double xyz[3];
    double params[2][2];
    double t[3], n[3], b[3];
    double kappa, tau;
    double angle;      /**< between the normals, radians */
    int frame_defined; /**< 0 where kappa = 0: n, b, tau undefined */
    /** on a knot line of a NURBS surface: bit 0 (1) of A, bit 1 (2) of B
     *  (docs/nurbs.md); 0 elsewhere */
    int knot_line;
    /** on a knot line, whose side the apparatus is: +1 the curve after the
     *  point (larger s; where the tracer went), -1 the curve before it */
    int knot_side;
} ic_trace_point;

/** Reverses a run of curve points in place: their order, their
 *  orientation (t and b change sign, as in ic_branch_reverse) and their arc
 *  length (s -> p[0].s + p[n-1].s - s, so the run covers the same range). */
IC_API void ic_trace_points_reverse(ic_trace_point *p, int n);

typedef struct ic_tracer ic_tracer;

/** A tracer for a pair (not owned). */
IC_API IC_NODISCARD ic_status ic_tracer_new(ic_tracer **tr, ic_pair *pair,
                                            const ic_trace_options *opt, ic_error *err);
IC_API void ic_tracer_free(ic_tracer *tr);

/** Starts a curve at a located transversal point, marching along +t
 *  (direction = +1) or -t (-1). IC_ERR_UNABLE at a tangential point. */
IC_API IC_NODISCARD ic_status ic_tracer_start(ic_tracer *tr, const ic_local_point *start,
                                              int direction, ic_error *err);
/** One step: appends a point (unless the event ends the curve before it). */
IC_API IC_NODISCARD ic_status ic_tracer_step(ic_tracer *tr, ic_trace_event *event, ic_error *err);
/** Steps until an event other than IC_TRACE_CONTINUE. */
IC_API IC_NODISCARD ic_status ic_tracer_run(ic_tracer *tr, ic_trace_event *event, ic_error *err);

/** 0 for a NULL tracer. */
IC_API int ic_tracer_num_points(const ic_tracer *tr);
/** Point i of the current curve, NULL out of range. Valid until the next
 *  ic_tracer_start, ic_tracer_step or ic_tracer_run (the points grow by
 *  reallocation) or ic_tracer_free. */
IC_API const ic_trace_point *ic_tracer_point(const ic_tracer *tr, int i);

/* ---- the whole intersection ---- */

/** Shapes of a traced curve (Abdel-All et al. (2012), corollaries 3.1-3.5). */
typedef enum {
    IC_SHAPE_GENERAL,
    IC_SHAPE_LINE,
    IC_SHAPE_CIRCLE,
    IC_SHAPE_PLANAR,
    IC_SHAPE_CIRCULAR_HELIX,
    IC_SHAPE_HELIX
} ic_shape;

/** "general", "line", "circle", "planar", "circular-helix", "helix": a
 *  static string. */
IC_API const char *ic_shape_name(ic_shape shape);

typedef struct {
    int closed;
    int npoints;
    const ic_trace_point *points; /**< owned by the result */
    double length;
    ic_trace_event ends[2]; /**< how the two ends stopped (both CLOSED for a loop) */
    int tangential;         /**< 1: the surfaces touch all along it (a tangential curve) */
    ic_shape shape;
    double shape_tol; /**< relative tolerance of the shape test */
} ic_trace_curve;

/** A tangential point met: at a curve end (approximate: the last transversal
 *  point before it, within about the tangential threshold) or on its own. */
typedef struct {
    double xyz[3];
    ic_point_type type;
    int nbranches;
    int approximate;
} ic_trace_special;

#define IC_TRACE_MAX_FAILURES 16

/** The certificate's summary (docs/tracing.md, "The certificate"): the
 *  independent checker's cover of the search region and its verdict. */
typedef struct {
    /** 1: the checker ran (it runs when the tracer found the whole
     *  intersection by its own account; complete is then its verdict) */
    int checked;
    int accepted; /**< 1: every cell proven and every arc traced exactly once */
    long cells;   /**< cells of the cover, splits included */
    long empty, outside, diagonal, regular, refused; /**< leaves by kind */
    /** leaves in the box of a singular point the result reports (half width
     *  1e-5 of the region's size): not examined (docs/tracing.md) */
    long singular;
    /** leaves in the tube about a tangential curve the result reports (radius
     *  5e-4 of the region's size): not examined (docs/tracing.md) */
    long tangential;
    long crossings; /**< crossings of the regular cells' faces, each root-isolated */
    long arcs;      /**< arcs of the regular cells (half the crossings) */
    /** singular boxes the checker placed itself: at the sheets' poles (domain
     *  edges whose image is one point), and where a curve meets the
     *  boundary at a corner or touches it (docs/tracing.md) */
    int poles, corners;
    /** points of arcs the checker proved but found no traced curve on, that
     *  the tracer started again from before the last check (docs/tracing.md,
     *  "Starting again from the checker"); 0 when it did not */
    int restarts;
    double seconds; /**< the checker's wall time */
    char reason[240]; /**< why it refused ("" when accepted or not run) */
} ic_trace_certificate;

/** What the search proved and what it only sampled (docs/tracing.md). */
typedef struct {
    /** 1 only when every part of the search space was proven free of
     *  curves, proven loop-free and passed near by what was traced, or
     *  traced, and every curve ended where it should (docs/tracing.md,
     *  "Completeness"); 0 lists in failures every region left undecided */
    int complete;
    /** the tracer's own account before the checker (the conditions of
     *  complete above without the certificate): 1 where the tracer believes
     *  it found everything; complete is 1 only when the certificate also
     *  accepts (docs/tracing.md, "The certificate") */
    int tracer_complete;
    int cells;          /**< cells examined by the subdivision */
    int cells_excluded; /**< cells proven empty by interval arithmetic */
    int cells_excluded_centred; /**< of those, leaves cleared by centred forms */
    int proven;         /**< 1: every surface had interval evaluation */
    int candidates;     /**< start candidates found by Newton in the remaining cells */
    double cell_size;   /**< the smallest cell (length or parameter units) */
    /** leaf cells not excluded, where no start point was found, and that no
     *  traced curve or recorded point passes near: an intersection may hide
     *  there unfound (a tangential curve, for one); listed in failures */
    int uncovered_cells;
    /** leaf cells not excluded where Newton converged outside the cell, and
     *  that nothing found passes near: not proven empty */
    int unproven_cells;
    /** leaf cells not excluded where the normal cones prove that no closed
     *  curve lies wholly inside (the loop test, docs/tracing.md); these two counts
     *  include the leaves of the finer searches */
    int loop_free_cells;
    /** leaf cells not excluded where the loop test fails: the only places a
     *  closed curve smaller than a cell can be (near tangency the test
     *  cannot succeed: N_A x N_B vanishes there) */
    int loop_cells;
    /** cells subdivided again after the first search, adaptively, until
     *  decided (docs/tracing.md, "Completeness"); their finer cells join the
     *  counts above */
    int refined_cells;
    /** cells left undecided because a closed curve may hide there (the loop
     *  test failed down to the finest level) or the work ran out first */
    int undecided_loop_cells;
    /** cells where the two surfaces coincide (a region of both, listed in
     *  failures by its box): complete is then 0 */
    int coincident_cells;
    int nfailures;
    char failures[IC_TRACE_MAX_FAILURES][240];
    /** length: the B-spline fit tolerance used (ic_trace_fit; 0: not fitted) */
    double fit_tol;
    /** length: the largest fit error found over the curves (ic_curve_fit) */
    double fit_error;
    /** how the intersection was found, a static string: "search" (the
     *  subdivision search and the marching), "closed form: coaxial surfaces
     *  of revolution" (two implicit primitives), "closed form: NURBS nets
     *  recognised as coaxial surfaces of revolution", "closed form: plane
     *  sections of quadrics" (two implicit primitives) or "closed form: NURBS
     *  nets recognised as plane sections of quadrics" (docs/tracing.md,
     *  "Exact paths": nothing was
     *  searched, the cell counts are 0, complete is 1) */
    const char *method;
    /** length: the problem's size L0, the diagonal of the region searched
     *  (docs/tracing.md, "Scale"): the first search's lengths are fractions
     *  of it */
    double search_scale;
    /** length: the size L1 of what the first search found (the diagonal of
     *  its start points' and open cells' box, between 1e-3 L0 and L0), or on
     *  an exact path of what the closed form found: the marching's, the
     *  refinement's, the singular points' and the fit's lengths (tol, chord,
     *  the steps, fit_tol) are fractions of it */
    double scale;
    /** the independent checker's verdict on the whole result */
    ic_trace_certificate certificate;
} ic_trace_report;

typedef struct ic_trace_result ic_trace_result;

/**
 * Traces the whole intersection of the pair: start points by subdivision of
 * the box (implicit/implicit; opt->has_box required) or of the parametric
 * surface's domain (parametric/implicit; a finite domain required) or of
 * both domains (two parametric surfaces; a self-intersection, with the
 * preimage pairs ordered and the diagonal left out), every curve traced in
 * both directions, tangential curve ends recorded. The result is freed with
 * ic_trace_result_free.
 */
IC_API IC_NODISCARD ic_status ic_trace(ic_trace_result **res, ic_pair *pair,
                                       const ic_trace_options *opt, ic_error *err);
IC_API void ic_trace_result_free(ic_trace_result *res);
/* The accessors' pointers (NULL for a NULL result or an index out of range)
 * point into the result: valid until ic_trace_result_free. The counts are 0
 * for a NULL result. */
IC_API int ic_trace_result_num_curves(const ic_trace_result *res);
IC_API const ic_trace_curve *ic_trace_result_curve(const ic_trace_result *res, int i);
IC_API int ic_trace_result_num_specials(const ic_trace_result *res);
IC_API const ic_trace_special *ic_trace_result_special(const ic_trace_result *res, int i);
IC_API const ic_trace_report *ic_trace_result_report(const ic_trace_result *res);
/** The certificate file of the last check (JSON text, NUL terminated;
 *  docs/output-formats.md, "The certificate file") when the trace kept it
 *  (ic_trace_options.keep_certificate) and the checker ran; else NULL. */
IC_API const char *ic_trace_result_certificate(const ic_trace_result *res);
/** The classification of a point of curve c: a recorded special point's type
 *  where the point is one (a tangential curve end), tangential-curve along a
 *  tangential curve, transversal otherwise (and without a point p). */
IC_API ic_point_type ic_trace_point_type(const ic_trace_result *res, const ic_trace_curve *c,
                                         const ic_trace_point *p);

/**
 * A traced curve as B-splines (docs/bspline.md): in space, parametrised by
 * the curve's arc length s, and on each parametric sheet a curve in its
 * parameter plane with the same knots, so that R_sheet(pcurve(s)) = curve(s).
 * Piecewise quintic: on each stretch between traced points the quintic that
 * matches the point, c' and c'' exactly at both ends (C^2 at the knots).
 */
typedef struct {
    ic_bspline curve;
    /** dim 2; ncontrol 0 and NULL arrays for an implicit surface, or where
     *  the sheet's parametrisation degenerates on the curve (a pole) */
    ic_bspline pcurves[2];
    /** length: the largest distance found, at the middle of every stretch
     *  between nodes, from the curve to either surface (to a parametric
     *  sheet with a pcurve: from the pcurve's image) */
    double fit_error;
    int checks; /**< how many places were checked */
    /** 1 where a pcurve strayed from the curve by more than the tolerance
     *  (its sheet's parametrisation degenerates on the curve, a sphere's
     *  pole: the parameters jump there) and is not given */
    int pcurve_dropped[2];
} ic_curve_fit;

/**
 * Fits every curve of a result of ic_trace on `pair` as B-splines (the
 * result keeps them; ic_trace_result_fit gives them), fit_tol a fraction of
 * the problem's size L (docs/bspline.md; IC_TRACE_FIT_TOL_DEFAULT on the
 * command line); sets the report's fit_tol (a length) and fit_error. A curve that
 * cannot be fitted (one point) has none. IC_ERR_NOMEM out of memory.
 */
IC_API IC_NODISCARD ic_status ic_trace_fit(ic_trace_result *res, ic_pair *pair, double fit_tol,
                                           ic_error *err);
/** Curve i's B-splines, or NULL (not fitted, or i out of range). */
IC_API const ic_curve_fit *ic_trace_result_fit(const ic_trace_result *res, int i);

/** Fits curve c of a trace of `pair` (curves of at least 2 points) to
 *  fit_tol (a length): stretches that miss it get a located point at their
 *  middle, for up to 4 rounds; a pcurve whose image strays beyond it is
 *  dropped. fit_error is what is left. */
IC_API IC_NODISCARD ic_status ic_curve_fit_new(ic_curve_fit **fit, ic_pair *pair,
                                               const ic_trace_curve *c, double fit_tol,
                                               ic_error *err);
IC_API void ic_curve_fit_free(ic_curve_fit *fit);

#ifdef __cplusplus
}
#endif
#endif
