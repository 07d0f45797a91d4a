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

/* The extent of the implicit surface s inside `box`: the bounding box of its
 * marching-tetrahedra mesh of `cells` per axis; *found = 0 where the mesh
 * is empty (the surface misses the box or is smaller than a cell). */
ic_status ic_plot_mesh_extent(ic_surface *s, const double box[3][2], int cells, double ext[3][2],
                           int *found, ic_error *err);

/* The region drawn (docs/plots.md, "The region drawn"): the scene's box;
 * without one, the bounding box of the parametric meshes (`parametric`, made
 * without a box) and the curves, grown where an implicit surface closes
 * within PLOT_REGION_REACH of its largest side, and a margin of
 * PLOT_REGION_MARGIN of the largest side on every side. */
#define PLOT_REGION_REACH 0.5   /* fraction of the largest side, searched beyond each face */
#define PLOT_REGION_MARGIN 0.05 /* fraction of the largest side, added on each face */
ic_status ic_plot_region(double box[3][2], const ic_plot_scene *scene, const plot_mesh *parametric,
                      int cells, ic_error *err);

/* The length in space of the Frenet arrows drawn on curve cv in a picture
 * whose box has the diagonal box_diagonal: PLOT_ARROW_BOX of that diagonal,
 * but at most PLOT_ARROW_CURVE of the diagonal of the curve's own bounding
 * box, so that the arrows never dwarf a small curve. */
#define PLOT_ARROW_BOX 0.08  /* fraction of the picture box's diagonal */
#define PLOT_ARROW_CURVE 0.2 /* fraction of the curve's bounding-box diagonal */
double ic_plot_arrow_length(const ic_trace_curve *cv, double box_diagonal);

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

/* The stretch of curve `curve` from its traced point k to k + 1 as smooth
 * cubic pieces on the screen (plot_curve.c): b[i] = x0, y0, ..., x3, y3 of
 * piece i, the first starting at point k; returns how many (1 to
 * PLOT_MAX_PIECES). ic_plot_curve_path appends them to cr's path (a
 * move_to, then curve_to's; cairo keeps 1/256 of a unit of them). */
enum { PLOT_MAX_PIECES = 64 };
int ic_plot_curve_pieces(const plot_camera *cam, const ic_trace_result *tr, int curve, int k,
                         double (*b)[8]);
void ic_plot_curve_path(cairo_t *cr, const plot_camera *cam, const ic_trace_result *tr, int curve,
                        int k);

/* Colours (the same in every figure): viridis for curvature, fixed ones for
 * t, n, b, the two surfaces, the curves of the chart and point types. */
void ic_plot_colormap(double t, double rgb[3]);
extern const double ic_plot_rgb_t[3], ic_plot_rgb_n[3], ic_plot_rgb_b[3];
extern const double ic_plot_rgb_surface[2][3];
void ic_plot_curve_color(int i, double rgb[3]);
enum { PLOT_CURVE_COLORS = 6 }; /* the curve palette; colours repeat after it */

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

/* A rectangle on the screen (pixels, or points in SVG and PDF). */
typedef struct {
    double x0, y0, x1, y1;
} plot_rect;

/* The axes of the 3D panel (docs/plots.md, "Axes"), laid out on the screen:
 * per axis its ticks, each with its mark, its label's rectangle and whether
 * the label is drawn, and the rectangle of the axis name. */
enum { PLOT_AXIS_TICKS = 12 };
typedef struct {
    double value;
    double x0, y0, x1, y1; /* the tick mark */
    plot_rect label;
    double width; /* of the label */
    int shown;    /* 0: the label would overlap another or leave the panel */
    char text[32];
} plot_tick;

typedef struct {
    plot_tick tick[3][PLOT_AXIS_TICKS];
    int nticks[3];
    plot_rect name[3];
    int name_shown[3];
} plot_axes;

/* Lays the axes out for the camera as it is. */
void ic_plot_axes_layout(plot_axes *axes, cairo_t *cr, const plot_camera *cam, const double box[3][2]);
/* Fits the camera so that the box, its tick labels and axis names and the
 * points `extra` (arrow tips) lie inside `area`, and lays the axes out;
 * a label still outside after that is not shown. */
void ic_plot_axes_fit(plot_axes *axes, cairo_t *cr, plot_camera *cam, const double box[3][2],
                   plot_rect area, const double (*extra)[3], int nextra);
/* The box's edges, the ticks, the shown labels and the names. */
void ic_plot_axes_draw(cairo_t *cr, const plot_camera *cam, const double box[3][2],
                    const plot_axes *axes);

/* The 3D panel in the rectangle (x, y, w, h). */
ic_status ic_plot_draw_3d(cairo_t *cr, const ic_plot_scene *scene, const ic_plot_options *opt,
                       double x, double y, double w, double h, ic_error *err);
/* How many "curve k" entries the chart's legend shows in `width`: the
 * first curves while they and "... and N more" fit, at most one per colour
 * of the palette; 0 when not even one fits. */
int ic_plot_legend_entries(cairo_t *cr, int ncurves, double width);
/* The chart of curvature and torsion against arc length; -1 out of memory. */
int ic_plot_draw_chart(cairo_t *cr, const ic_trace_result *trace, double x, double y, double w,
                       double h);

#endif
