/* Internal pieces of the plots: meshes, the camera, colours, the 3D panel
 * and the chart (docs/plots.md). */
#ifndef IC_PLOT_INTERNAL_H
#define IC_PLOT_INTERNAL_H

#include <cairo.h>

#include "intercurve/plot.h"
#include "intercurve/writers.h"

/* A triangle of a surface mesh. */
typedef struct {
    double v[3][3];
    int surface;
} plot_tri;

typedef struct {
    plot_tri *t;
    int n, cap;
} plot_mesh;

/* Meshes surface `which` of the scene: a parametric one over its domain, an
 * implicit one by marching tetrahedra inside `box`. Appends to mesh. */
ic_status ic_plot_mesh_surface(plot_mesh *mesh, ic_surface *s, int which, const double box[3][2],
                               int cells, ic_error *err);

/* An orthographic camera from azimuth and elevation (degrees): screen
 * coordinates (x right, y down) and a depth that grows away from the viewer. */
typedef struct {
    double right[3], up[3], toward[3];
    double scale, cx, cy, ox, oy;
} plot_camera;

void ic_plot_camera_init(plot_camera *cam, double azimuth, double elevation);
/* Fits the box (its 8 corners) into the rectangle (x0, y0, w, h). */
void ic_plot_camera_fit(plot_camera *cam, const double box[3][2], double x0, double y0, double w,
                        double h);
void ic_plot_camera_project(const plot_camera *cam, const double *p, double *sx, double *sy,
                            double *depth);

/* Colours (the same in every figure): viridis for curvature, fixed ones for
 * t, n, b, the two surfaces, the curves of the chart and point types. */
void ic_plot_colormap(double t, double rgb[3]);
extern const double ic_plot_rgb_t[3], ic_plot_rgb_n[3], ic_plot_rgb_b[3];
extern const double ic_plot_rgb_surface[2][3];
void ic_plot_curve_color(int i, double rgb[3]);

/* Stroke widths that identify the drawn elements in an SVG (tests count
 * the paths with them). */
#define PLOT_CURVE_WIDTH 3.5
#define PLOT_ARROW_WIDTH 2.25

/* Text helpers: the toy font API, sans-serif. */
void ic_plot_text(cairo_t *cr, double x, double y, double size, int bold, const char *text,
                  double align_x, double align_y);
double ic_plot_text_width(cairo_t *cr, double size, int bold, const char *text);
/* About n "nice" ticks (1, 2, 5 times a power of 10) covering [lo, hi]:
 * first tick, step and count. */
int ic_plot_ticks(double lo, double hi, int n, double *first, double *step);
/* A tick label, without trailing noise ("0.30000000000000004" -> "0.3"). */
void ic_plot_tick_label(char *buf, size_t size, double v, double step);

/* The 3D panel in the rectangle (x, y, w, h). */
ic_status ic_plot_draw_3d(cairo_t *cr, const ic_plot_scene *scene, const ic_plot_options *opt,
                          double x, double y, double w, double h, ic_error *err);
/* The chart of curvature and torsion against arc length; -1 out of memory. */
int ic_plot_draw_chart(cairo_t *cr, const ic_trace_result *trace, double x, double y, double w,
                       double h);

#endif
