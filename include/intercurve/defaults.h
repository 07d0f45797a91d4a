/**
 * @file defaults.h
 * Every default and range of the options users set through the command, the
 * entry points for other languages and the Python package, in one place
 * (the bounds that are the library's own limits stay beside their types:
 * IC_TRACE_MAX_DEPTH, IC_TRACE_MAX_THREADS, IC_LOCAL_MAX_ORDER):
 * the library's ic_trace_defaults, ic_local_defaults and ic_plot_defaults,
 * the checks of the entry points for other languages (bindings.h), the
 * command's option tables and its --help (hence docs/cli.md, which the
 * tests hold to --help), and the Python package (through ic_default_value)
 * all read them from here. Lengths marked relative are fractions of the
 * problem's size L (docs/tracing.md, "Scale").
 */
#ifndef INTERCURVE_DEFAULTS_H
#define INTERCURVE_DEFAULTS_H

#include "intercurve/common.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ic_trace_options (ic_trace_defaults; `intercurve trace` and `plot`) */
/** relative: truncation error allowed per step (--tol) */
#define IC_TRACE_TOL_DEFAULT 1e-11
/** relative: chord-height bound of a step */
#define IC_TRACE_CHORD_DEFAULT 1e-4
/** relative: the longest step */
#define IC_TRACE_MAX_STEP_DEFAULT 0.05
/** relative: a step shorter than this fails */
#define IC_TRACE_MIN_STEP_DEFAULT 1e-13
/** the predictor's order K */
#define IC_TRACE_ORDER_DEFAULT 6
/** the point budget of one curve */
#define IC_TRACE_MAX_POINTS_DEFAULT 100000
/** levels: subdivision depth of the start-point search (--depth) */
#define IC_TRACE_DEPTH_DEFAULT 6
/** the shape tests' tolerance, relative to the largest curvature */
#define IC_TRACE_SHAPE_TOL_DEFAULT 1e-6
/** threads: 0, all the machine's online cores (--threads) */
#define IC_TRACE_THREADS_DEFAULT 0
/** relative: the largest --tol and --fit-tol the command and the bindings
 *  accept */
#define IC_TRACE_REL_TOL_MAX 1e-2
/** seconds: the largest --time-limit (0, the default: none) */
#define IC_TRACE_TIME_LIMIT_MAX 1e6
/** relative: the B-spline fit's tolerance unless told (--fit-tol;
 *  docs/bspline.md) */
#define IC_TRACE_FIT_TOL_DEFAULT 1e-9

/* ic_local_options (ic_local_defaults; `intercurve point` and `eval`) */
/** length: how far from the surfaces a point search may start (--point-tol) */
#define IC_LOCAL_POINT_TOL_DEFAULT 1e-6
/** the highest derivative c^(K) `intercurve point` gives (--order); with
 *  the closed forms, which stop at the third, that one unless told */
#define IC_POINT_ORDER_DEFAULT 4
/** the closed forms' default order: their highest, IC_CLOSED_FORM_MAX_ORDER
 *  (a static assertion in src/api/defaults.c holds the two together) */
#define IC_POINT_CLOSED_FORM_ORDER_DEFAULT 3
/** the highest order of the derivative tensor `intercurve eval` gives (--order) */
#define IC_EVAL_ORDER_DEFAULT 4

/* ic_plot_options (ic_plot_defaults; `intercurve plot`) */
/** pixels (PNG) or points (SVG, PDF): the picture's size and its ranges */
#define IC_PLOT_WIDTH_DEFAULT 1400
#define IC_PLOT_HEIGHT_DEFAULT 800
#define IC_PLOT_WIDTH_MIN 200
#define IC_PLOT_HEIGHT_MIN 150
#define IC_PLOT_SIZE_MAX 10000
/** degrees: the view's azimuth and elevation */
#define IC_PLOT_AZIMUTH_DEFAULT 35
#define IC_PLOT_ELEVATION_DEFAULT 25
/** Frenet frames drawn along the curves, and the most */
#define IC_PLOT_FRAMES_DEFAULT 8
#define IC_PLOT_FRAMES_MAX 200
/** mesh cells per parameter or box axis, and their range */
#define IC_PLOT_MESH_DEFAULT 36
#define IC_PLOT_MESH_MIN 4
#define IC_PLOT_MESH_MAX 200

/**
 * The default or limit called `name`, for languages that cannot read the
 * macros above: "tol", "depth", "fit_tol", "threads", "rel_tol_max",
 * "time_limit_max", "point_tol", "point_order", "point_closed_form_order",
 * "width", "height",
 * "azimuth", "elevation", "frames", "mesh" (the command's option names);
 * NaN for any other name or NULL.
 */
IC_API double ic_default_value(const char *name);

#ifdef __cplusplus
}
#endif

#endif
