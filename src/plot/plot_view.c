/* The camera, the colours and the text helpers of the pictures. */
#include "plot_internal.h"
#include "common/mathconst.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

void ic_plot_camera_init(plot_camera *cam, double azimuth, double elevation)
{
    const double a = azimuth * IC_PI / 180, e = elevation * IC_PI / 180;
    /* toward the viewer; right is horizontal; up completes the frame */
    const double w[3] = {cos(e) * cos(a), cos(e) * sin(a), sin(e)};
    const double r[3] = {-sin(a), cos(a), 0};
    const double u[3] = {-sin(e) * cos(a), -sin(e) * sin(a), cos(e)};
    memcpy(cam->toward, w, sizeof w);
    memcpy(cam->right, r, sizeof r);
    memcpy(cam->up, u, sizeof u);
    cam->scale = 1, cam->cx = cam->cy = cam->ox = cam->oy = 0;
}

static double dot(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

void ic_plot_camera_fit(plot_camera *cam, const double box[3][2], double x0, double y0, double w,
                        double h)
{
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int c = 0; c < 8; c++) {
        const double p[3] = {box[0][c & 1], box[1][(c >> 1) & 1], box[2][(c >> 2) & 1]};
        const double s[2] = {dot(p, cam->right), dot(p, cam->up)};
        for (int k = 0; k < 2; k++)
            lo[k] = fmin(lo[k], s[k]), hi[k] = fmax(hi[k], s[k]);
    }
    const double sx = w / fmax(hi[0] - lo[0], 1e-300), sy = h / fmax(hi[1] - lo[1], 1e-300);
    cam->scale = fmin(sx, sy);
    cam->cx = 0.5 * (lo[0] + hi[0]);
    cam->cy = 0.5 * (lo[1] + hi[1]);
    cam->ox = x0 + 0.5 * w;
    cam->oy = y0 + 0.5 * h;
}

void ic_plot_camera_project(const plot_camera *cam, const double *p, double *sx, double *sy,
                            double *depth)
{
    *sx = cam->ox + cam->scale * (dot(p, cam->right) - cam->cx);
    *sy = cam->oy - cam->scale * (dot(p, cam->up) - cam->cy);
    if (depth)
        *depth = -dot(p, cam->toward);
}

/* viridis at 9 stops */
static const double VIRIDIS[9][3] = {
    {0.267, 0.005, 0.329}, {0.278, 0.175, 0.483}, {0.229, 0.322, 0.546},
    {0.173, 0.449, 0.558}, {0.128, 0.567, 0.551}, {0.153, 0.683, 0.502},
    {0.369, 0.789, 0.383}, {0.678, 0.864, 0.190}, {0.993, 0.906, 0.144}};

void ic_plot_colormap(double t, double rgb[3])
{
    if (!(t >= 0))
        t = 0;
    if (t > 1)
        t = 1;
    const double x = t * 8;
    const int i = x >= 8 ? 7 : (int)x;
    const double f = x - i;
    for (int k = 0; k < 3; k++)
        rgb[k] = VIRIDIS[i][k] + f * (VIRIDIS[i + 1][k] - VIRIDIS[i][k]);
}

const double ic_plot_rgb_t[3] = {0.839, 0.153, 0.157}; /* red */
const double ic_plot_rgb_n[3] = {0.173, 0.627, 0.173}; /* green */
const double ic_plot_rgb_b[3] = {0.122, 0.467, 0.706}; /* blue */
const double ic_plot_rgb_surface[2][3] = {{0.55, 0.70, 0.85}, {0.93, 0.72, 0.50}};

void ic_plot_curve_color(int i, double rgb[3])
{
    static const double PALETTE[PLOT_CURVE_COLORS][3] = {
        {0.122, 0.467, 0.706}, {1.000, 0.498, 0.055}, {0.173, 0.627, 0.173},
        {0.839, 0.153, 0.157}, {0.580, 0.404, 0.741}, {0.549, 0.337, 0.294}};
    memcpy(rgb, PALETTE[i % PLOT_CURVE_COLORS], 3 * sizeof *rgb);
}

static void set_font(cairo_t *cr, double size, int bold)
{
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                           bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, size);
}

double ic_plot_text_width(cairo_t *cr, double size, int bold, const char *text)
{
    cairo_text_extents_t ext;
    set_font(cr, size, bold);
    cairo_text_extents(cr, text, &ext);
    return ext.x_advance;
}

void ic_plot_text(cairo_t *cr, double x, double y, double size, int bold, const char *text,
                  double align_x, double align_y)
{
    cairo_text_extents_t ext;
    set_font(cr, size, bold);
    cairo_text_extents(cr, text, &ext);
    /* align_x: 0 left, 0.5 centre, 1 right; align_y: 0 the top of the capitals
     * at y, 0.5 their middle, 1 the baseline */
    cairo_move_to(cr, x - align_x * ext.x_advance, y + (1 - align_y) * 0.72 * size);
    cairo_show_text(cr, text);
    cairo_new_path(cr); /* no current point left for the next path */
}

int ic_plot_ticks(double lo, double hi, int n, double *first, double *step)
{
    const double span = hi - lo;
    if (!(span > 0) || !isfinite(span)) {
        *first = lo, *step = 1;
        return 1;
    }
    const double raw = span / (n > 1 ? n : 1), mag = pow(10, floor(log10(raw)));
    const double f = raw / mag;
    *step = (f < 1.5 ? 1 : f < 3.5 ? 2 : f < 7.5 ? 5 : 10) * mag;
    *first = ceil(lo / *step - 1e-9) * *step;
    return (int)floor((hi - *first) / *step + 1e-9) + 1;
}

void ic_plot_tick_label(char *buf, size_t size, double v, double step)
{
    if (fabs(v) < 1e-9 * step)
        v = 0;
    const int digits = step >= 1 ? 0 : (int)ceil(-log10(step) - 1e-9);
    if (fabs(v) >= 1e5 || (v != 0 && fabs(v) < 1e-4))
        snprintf(buf, size, "%.3g", v);
    else
        snprintf(buf, size, "%.*f", digits, v);
}
