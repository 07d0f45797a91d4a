/**
 * @file plot.h
 * Pictures of an intersection (docs/plots.md): a 3D view of both surfaces
 * as shaded, partly transparent meshes, the traced curves coloured by
 * curvature with a colour bar, Frenet frames along them, the singular
 * points labelled by type, axes with ticks; and a chart of curvature and
 * torsion against arc length. Drawn with cairo into SVG, PNG or PDF, or
 * written as an interactive HTML page (three.js).
 */
#ifndef INTERCURVE_PLOT_H
#define INTERCURVE_PLOT_H

#include "intercurve/common.h"
#include "intercurve/problem.h"
#include "intercurve/surface.h"
#include "intercurve/trace.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    /** pixels (PNG) or points (SVG, PDF); IC_PLOT_WIDTH_DEFAULT x IC_PLOT_HEIGHT_DEFAULT */
    int width, height;
    /** the view, degrees (IC_PLOT_AZIMUTH_DEFAULT, IC_PLOT_ELEVATION_DEFAULT) */
    double azimuth, elevation;
    int frames;    /**< Frenet frames drawn along the curves (IC_PLOT_FRAMES_DEFAULT) */
    int chart;     /**< 1: the curvature and torsion panel (default) */
    int mesh;      /**< mesh cells per parameter or box axis (IC_PLOT_MESH_DEFAULT) */
} ic_plot_options;

IC_API void ic_plot_defaults(ic_plot_options *opt);

/** What a picture shows. Nothing is owned: the surfaces, title, names and
 *  trace must outlive the scene's use. A parametric surface is
 *  meshed over its domain (and cut to the box if there is one), an implicit
 *  one inside the box (or, without a box, inside the other surface's and the
 *  curves' bounding box). trace may be NULL: surfaces only. */
typedef struct {
    const char *title;
    ic_surface *surfaces[2];
    const char *names[2];
    int nsurfaces; /**< 1 for a self-intersection */
    int has_box;
    double box[3][2];
    const ic_trace_result *trace;
} ic_plot_scene;

/** The scene of a problem file (title, surfaces, names, box) with a trace
 *  of it (NULL: surfaces only); the problem keeps owning the surfaces. */
IC_API void ic_plot_scene_of_problem(ic_plot_scene *scene, const ic_problem *problem,
                                     const ic_trace_result *trace);

/**
 * Draws the scene into `path`; the format comes from its extension (.svg,
 * .png or .pdf, or .html for the interactive page of docs/plots.md;
 * IC_ERR_INVALID otherwise). Written through a temporary file and a rename
 * (IC_ERR_IO when that fails). Where the trace has no curve and no point, the
 * figure says "no intersection". opt NULL: ic_plot_defaults. A library built
 * without three.js (no web/node_modules) refuses .html with IC_ERR_UNABLE.
 */
IC_API IC_NODISCARD ic_status ic_plot_write(const char *path, const ic_plot_scene *scene,
                                            const ic_plot_options *opt, ic_error *err);

#ifdef __cplusplus
}
#endif
#endif
