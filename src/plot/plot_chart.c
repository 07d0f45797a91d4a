/*
 * The chart: curvature (top) and torsion (bottom) against arc length, one
 * line per curve in the curve palette, the singular points on each curve
 * marked by a dashed vertical line. Torsion blows up near tangential points
 * and where kappa -> 0, so its range is that of the 2nd to 98th percentile
 * (widened by a fifth) when the extremes lie far outside it; the plot is
 * clipped to its frame and says so.
 */
#include "plot_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define LEGEND_FONT 11.0 /* px */
#define LEGEND_MORE "\xe2\x80\xa6 and %d more"

static int cmp_qsort(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y ? 1 : 0;
}

/* The value range of kappa (which 0) or tau (1); *clipped when the
 * percentile range was used. 0, or -1 out of memory (before: a chart of the
 * range [-1, 1], found by tests/test_nomem.c, "writers"). */
static int value_range(const ic_trace_result *tr, int which, double scale, double *lo, double *hi,
                       int *clipped)
{
    *clipped = 0;
    int n = 0;
    for (int c = 0; c < ic_trace_result_num_curves(tr); c++)
        n += ic_trace_result_curve(tr, c)->npoints;
    double *v = malloc(((size_t)n + 1) * sizeof *v);
    if (!v)
        return -1;
    int m = 0;
    for (int c = 0; c < ic_trace_result_num_curves(tr); c++) {
        const ic_trace_curve *cv = ic_trace_result_curve(tr, c);
        for (int k = 0; k < cv->npoints; k++) {
            const ic_trace_point *p = &cv->points[k];
            const double x = which ? (p->frame_defined ? p->tau : NAN) : p->kappa;
            if (isfinite(x))
                v[m++] = x;
        }
    }
    if (m == 0) {
        *lo = -1, *hi = 1;
        free(v);
        return 0;
    }
    qsort(v, (size_t)m, sizeof *v, cmp_qsort);
    *lo = v[0], *hi = v[m - 1];
    /* constant to rounding (relative to the curvature's scale for torsion) */
    if (*hi - *lo <= 1e-9 * fmax(fmax(fabs(*lo), fabs(*hi)), scale)) {
        const double mid = 0.5 * (*lo + *hi), pad = fmax(0.1 * fabs(mid), 0.1 * scale);
        *lo = mid - (pad > 0 ? pad : 0.1), *hi = mid + (pad > 0 ? pad : 0.1);
        free(v);
        return 0;
    }
    const double p2 = v[(int)(0.02 * (m - 1))], p98 = v[(int)(0.98 * (m - 1))];
    const double core = p98 - p2;
    if (core > 0 && (*hi - *lo) > 3 * core) {
        *lo = p2 - 0.2 * core, *hi = p98 + 0.2 * core;
        *clipped = 1;
    }
    if (which == 0 && *lo > 0 && *lo < 0.25 * *hi)
        *lo = 0; /* curvature from 0 when that costs little */
    /* a margin, so that extremes do not run along the frame */
    const double pad = 0.06 * (*hi - *lo);
    *hi += pad;
    if (!(which == 0 && *lo == 0))
        *lo -= pad;
    free(v);
    return 0;
}

/* One panel: frame, ticks, the lines, the singular points; -1 out of memory. */
static int panel(cairo_t *cr, const ic_trace_result *tr, int which, double x, double y, double w,
                  double h, double smax, double scale)
{
    double lo, hi;
    int clipped;
    if (value_range(tr, which, scale, &lo, &hi, &clipped) != 0)
        return -1;
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_rectangle(cr, x, y, w, h);
    cairo_fill(cr);
    /* grid and ticks */
    double first, step;
    int n = ic_plot_ticks(lo, hi, 4, &first, &step);
    cairo_set_line_width(cr, 0.6);
    for (int i = 0; i < n; i++) {
        const double v = first + i * step, yy = y + h - (v - lo) / (hi - lo) * h;
        cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
        cairo_move_to(cr, x, yy);
        cairo_line_to(cr, x + w, yy);
        cairo_stroke(cr);
        char buf[32];
        ic_plot_tick_label(buf, sizeof buf, v, step);
        cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
        ic_plot_text(cr, x - 5, yy, 11, 0, buf, 1, 0.5);
    }
    n = ic_plot_ticks(0, smax, 5, &first, &step);
    for (int i = 0; i < n; i++) {
        const double v = first + i * step, xx = x + v / smax * w;
        cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
        cairo_move_to(cr, xx, y);
        cairo_line_to(cr, xx, y + h);
        cairo_stroke(cr);
        char buf[32];
        ic_plot_tick_label(buf, sizeof buf, v, step);
        cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
        ic_plot_text(cr, xx, y + h + 5, 11, 0, buf, 0.5, 0);
    }
    cairo_save(cr);
    cairo_rectangle(cr, x, y, w, h);
    cairo_clip(cr);
    for (int c = 0; c < ic_trace_result_num_curves(tr); c++) {
        const ic_trace_curve *cv = ic_trace_result_curve(tr, c);
        double rgb[3];
        ic_plot_curve_color(c, rgb);
        cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
        cairo_set_line_width(cr, 1.6);
        int pen = 0;
        for (int k = 0; k < cv->npoints; k++) {
            const ic_trace_point *p = &cv->points[k];
            const double v = which ? (p->frame_defined ? p->tau : NAN) : p->kappa;
            if (!isfinite(v)) { /* undefined here: the line breaks */
                pen = 0;
                continue;
            }
            const double xx = x + (p->s - cv->points[0].s) / smax * w;
            const double yy = y + h - (v - lo) / (hi - lo) * h;
            if (pen)
                cairo_line_to(cr, xx, yy);
            else
                cairo_move_to(cr, xx, yy);
            pen = 1;
        }
        cairo_stroke(cr);
        /* the singular points on this curve */
        const double dash[2] = {4, 3};
        cairo_set_dash(cr, dash, 2, 0);
        cairo_set_line_width(cr, 1);
        cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
        for (int k = 0; k < cv->npoints; k++) {
            const ic_point_type ty = ic_trace_point_type(tr, cv, &cv->points[k]);
            if (ty != IC_POINT_TRANSVERSAL && ty != IC_POINT_TANGENTIAL_CURVE) {
                const double xx = x + (cv->points[k].s - cv->points[0].s) / smax * w;
                cairo_move_to(cr, xx, y);
                cairo_line_to(cr, xx, y + h);
                cairo_stroke(cr);
            }
        }
        cairo_set_dash(cr, NULL, 0, 0);
    }
    cairo_restore(cr);
    cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
    cairo_set_line_width(cr, 1);
    cairo_rectangle(cr, x, y, w, h);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    ic_plot_text(cr, x, y - 8, 13, 1,
              which
                  ? (clipped ? "torsion \xcf\x84 (clipped to the 2-98% range)" : "torsion \xcf\x84")
                  : (clipped ? "curvature \xce\xba (clipped)" : "curvature \xce\xba"),
              0, 1);
    return 0;
}

/* One legend entry: a swatch and "curve k"; its width with the space after. */
static double legend_entry(cairo_t *cr, int c, double x, double y, int draw)
{
    char buf[32];
    snprintf(buf, sizeof buf, "curve %d", c + 1);
    if (draw) {
        double rgb[3];
        ic_plot_curve_color(c, rgb);
        cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
        cairo_set_line_width(cr, 3);
        cairo_move_to(cr, x, y);
        cairo_line_to(cr, x + 16, y);
        cairo_stroke(cr);
        cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
        ic_plot_text(cr, x + 20, y, LEGEND_FONT, 0, buf, 0, 0.5);
    }
    return 30 + ic_plot_text_width(cr, LEGEND_FONT, 0, buf);
}

int ic_plot_legend_entries(cairo_t *cr, int ncurves, double width)
{
    int shown = ncurves < PLOT_CURVE_COLORS ? ncurves : PLOT_CURVE_COLORS;
    for (; shown > 0; shown--) {
        double used = 0;
        for (int c = 0; c < shown; c++)
            used += legend_entry(cr, c, 0, 0, 0);
        if (shown < ncurves) {
            char buf[48];
            snprintf(buf, sizeof buf, LEGEND_MORE, ncurves - shown);
            used += ic_plot_text_width(cr, LEGEND_FONT, 0, buf);
        }
        if (used <= width)
            break;
    }
    return shown;
}

/* The curve legend from (x, y), at most `width` long: the first curves
 * while they fit, then how many more there are (or only how many). */
static void draw_curve_legend(cairo_t *cr, int nc, double x, double y, double width)
{
    const int shown = ic_plot_legend_entries(cr, nc, width);
    for (int c = 0; c < shown; c++)
        x += legend_entry(cr, c, x, y, 1);
    if (shown == nc)
        return;
    char buf[48];
    snprintf(buf, sizeof buf, shown ? LEGEND_MORE : "%d curves", shown ? nc - shown : nc);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    if (ic_plot_text_width(cr, LEGEND_FONT, 0, buf) <= width)
        ic_plot_text(cr, x, y, LEGEND_FONT, 0, buf, 0, 0.5);
}

int ic_plot_draw_chart(cairo_t *cr, const ic_trace_result *tr, double x, double y, double w,
                       double h)
{
    double smax = 0;
    const int nc = tr ? ic_trace_result_num_curves(tr) : 0;
    for (int c = 0; c < nc; c++)
        smax = fmax(smax, ic_trace_result_curve(tr, c)->length);
    if (nc == 0 || !(smax > 0)) {
        cairo_set_source_rgb(cr, 0.4, 0.4, 0.4);
        ic_plot_text(cr, x + 0.5 * w, y + 0.5 * h, 13, 0, "no curve: no curvature to chart", 0.5, 0.5);
        return 0;
    }
    /* two panels, each with its s ticks below it; the axis title and the
     * curve legend at the bottom */
    const double left = 55, ph = 0.5 * (h - 140); /* the scale of both: the largest curvature */
    double kscale = 0;
    for (int c = 0; c < nc; c++) {
        const ic_trace_curve *cv = ic_trace_result_curve(tr, c);
        for (int k = 0; k < cv->npoints; k++)
            if (isfinite(cv->points[k].kappa))
                kscale = fmax(kscale, cv->points[k].kappa);
    }
    if (panel(cr, tr, 0, x + left, y + 30, w - left - 15, ph, smax, kscale) != 0 ||
        panel(cr, tr, 1, x + left, y + 30 + ph + 50, w - left - 15, ph, smax, kscale) != 0)
        return -1;
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    ic_plot_text(cr, x + left + 0.5 * (w - left - 15), y + h - 28, 12, 0, "arc length s", 0.5, 0.5);
    draw_curve_legend(cr, nc, x + left, y + h - 5, w - left - 15);
    return 0;
}
