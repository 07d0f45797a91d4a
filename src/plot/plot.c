/*
 * A figure: the title, the 3D panel (left) and the chart (right), on a
 * cairo surface chosen by the file's extension, streamed into a safe file
 * (json/safe_file.h: a temporary and a rename, or a device in place).
 */
#include "common/args.h"
#include "plot_html.h"

#include "json/safe_file.h"

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void ic_plot_defaults(ic_plot_options *opt)
{
    if (!opt)
        return;
    /* include/intercurve/defaults.h */
    opt->width = IC_PLOT_WIDTH_DEFAULT;
    opt->height = IC_PLOT_HEIGHT_DEFAULT;
    opt->azimuth = IC_PLOT_AZIMUTH_DEFAULT;
    opt->elevation = IC_PLOT_ELEVATION_DEFAULT;
    opt->frames = IC_PLOT_FRAMES_DEFAULT;
    opt->chart = 1;
    opt->mesh = IC_PLOT_MESH_DEFAULT;
}

void ic_plot_scene_of_problem(ic_plot_scene *scene, const ic_problem *problem,
                              const ic_trace_result *trace)
{
    if (!scene)
        return;
    memset(scene, 0, sizeof *scene);
    scene->title = ic_problem_title(problem);
    scene->has_box = ic_problem_box(problem, scene->box);
    scene->nsurfaces = ic_problem_is_self(problem) ? 1 : 2;
    for (int s = 0; s < scene->nsurfaces; s++) {
        scene->surfaces[s] = ic_problem_surface(problem, s);
        scene->names[s] = ic_problem_surface_name(problem, s);
    }
    scene->trace = trace;
}

typedef enum { FMT_SVG, FMT_PNG, FMT_PDF, FMT_HTML, FMT_NONE } plot_format;

static plot_format format_of(const char *path)
{
    const char *dot = strrchr(path, '.');
    if (!dot)
        return FMT_NONE;
    if (strcmp(dot, ".svg") == 0)
        return FMT_SVG;
    if (strcmp(dot, ".png") == 0)
        return FMT_PNG;
    if (strcmp(dot, ".pdf") == 0)
        return FMT_PDF;
    if (strcmp(dot, ".html") == 0)
        return FMT_HTML;
    return FMT_NONE;
}

/* The title, shrunk to fit the width. */
static void draw_title(cairo_t *cr, const char *title, double w)
{
    if (!title || !*title)
        return;
    double size = 20;
    while (size > 10 && ic_plot_text_width(cr, size, 1, title) > w - 40)
        size -= 1;
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    ic_plot_text(cr, 0.5 * w, 16, size, 1, title, 0.5, 0);
}

/* Where cairo's bytes go: the open file and the first write error, kept
 * apart from the caller's err so that no later message hides its reason. */
typedef struct {
    ic_safe_file *file;
    ic_status st;
    ic_error err;
} plot_sink;

/* cairo's write callback: passes the bytes on until the first failure. */
static cairo_status_t sink_write(void *closure, const unsigned char *data, unsigned int length)
{
    plot_sink *s = closure;
    if (s->st == IC_OK)
        s->st = ic_safe_write(s->file, data, length, &s->err);
    return s->st == IC_OK ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

static ic_status cairo_failed(ic_error *err, const char *path, cairo_status_t cs)
{
    return ic_error_set(err, IC_ERR_IO, 0, "cannot write %s: %s", path, cairo_status_to_string(cs));
}

/* The figure: background, title, 3D panel and chart. */
static ic_status draw_figure(cairo_t *cr, const ic_plot_scene *scene, const ic_plot_options *opt,
                             ic_error *err)
{
    const double W = opt->width, H = opt->height;
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    draw_title(cr, scene->title, W);
    /* the chart only where there is a curve to chart */
    const int chart = opt->chart && scene->trace && ic_trace_result_num_curves(scene->trace) > 0;
    const double w3 = chart ? 0.62 * W : W;
    ic_status st = ic_plot_draw_3d(cr, scene, opt, 0, 40, w3, H - 40, err);
    if (st == IC_OK && chart &&
        ic_plot_draw_chart(cr, scene->trace, w3 + 10, 50, W - w3 - 20, H - 60) != 0)
        st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory drawing the chart");
    return st;
}

/* Draws the figure and streams it into the sink's file: SVG and PDF as cairo
 * finishes them, PNG from an image surface at the end. */
static ic_status render(plot_sink *sink, plot_format fmt, const char *path,
                        const ic_plot_scene *scene, const ic_plot_options *opt, ic_error *err)
{
    const double W = opt->width, H = opt->height;
    cairo_surface_t *surf =
        fmt == FMT_SVG   ? cairo_svg_surface_create_for_stream(sink_write, sink, W, H)
        : fmt == FMT_PDF ? cairo_pdf_surface_create_for_stream(sink_write, sink, W, H)
                         : cairo_image_surface_create(CAIRO_FORMAT_ARGB32, opt->width, opt->height);
    cairo_t *cr = cairo_create(surf);
    ic_status st = cairo_status(cr) == CAIRO_STATUS_SUCCESS
                       ? draw_figure(cr, scene, opt, err)
                       : cairo_failed(err, path, cairo_status(cr));
    cairo_destroy(cr);
    cairo_status_t cs = CAIRO_STATUS_SUCCESS;
    if (st == IC_OK && fmt == FMT_PNG)
        cs = cairo_surface_write_to_png_stream(surf, sink_write, sink);
    cairo_surface_finish(surf);
    if (cs == CAIRO_STATUS_SUCCESS)
        cs = cairo_surface_status(surf);
    cairo_surface_destroy(surf);
    if (sink->st != IC_OK) /* the system's reason, e.g. "No space left on device" */
        return ic_error_set(err, sink->st, 0, "%s", sink->err.message);
    if (st == IC_OK && cs != CAIRO_STATUS_SUCCESS)
        st = cairo_failed(err, path, cs);
    return st;
}

ic_status ic_plot_write(const char *path, const ic_plot_scene *scene, const ic_plot_options *opt,
                        ic_error *err)
{
    IC_ARG_NOT_NULL(path, "path");
    IC_ARG_NOT_NULL(scene, "scene");
    ic_plot_options defaults;
    if (!opt) { /* NULL: the defaults */
        ic_plot_defaults(&defaults);
        opt = &defaults;
    }
    const plot_format fmt = format_of(path);
    if (fmt == FMT_NONE)
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            "cannot tell the picture's format from '%s': use .svg, .png, .pdf or .html",
                            path);
    if (opt->width < IC_PLOT_WIDTH_MIN || opt->height < IC_PLOT_HEIGHT_MIN ||
        opt->width > IC_PLOT_SIZE_MAX || opt->height > IC_PLOT_SIZE_MAX)
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            "a picture of %d x %d: the width must be in %d..%d and the height in "
                            "%d..%d",
                            opt->width, opt->height, IC_PLOT_WIDTH_MIN, IC_PLOT_SIZE_MAX,
                            IC_PLOT_HEIGHT_MIN, IC_PLOT_SIZE_MAX);
    if (scene->nsurfaces < 1 || scene->nsurfaces > 2)
        return ic_error_set(err, IC_ERR_INVALID, 0, "a picture shows one or two surfaces");
    if (fmt == FMT_HTML) /* the interactive page (plot_html.c) */
        return ic_plot_write_html(path, scene, opt, err);
    plot_sink sink = {NULL, IC_OK, {0}};
    ic_status st = ic_safe_open(&sink.file, path, err);
    if (st != IC_OK)
        return st;
    st = render(&sink, fmt, path, scene, opt, err);
    if (st != IC_OK) {
        ic_safe_abort(sink.file);
        return st;
    }
    return ic_safe_commit(sink.file, err);
}
