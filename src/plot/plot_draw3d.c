/*
 * The 3D panel: surface meshes (flat-shaded, partly transparent), curve
 * segments coloured by curvature, and Frenet-frame arrows, all sorted by
 * depth and drawn far to near (the painter's algorithm); then the singular
 * points with their labels, the axes, the colour bar and the legend.
 */
#include "plot_internal.h"
#include "common/mathconst.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { PRIM_TRI, PRIM_SEG, PRIM_ARROW };

typedef struct {
    int kind, a, b, c; /* TRI: a; SEG: curve a, point b; ARROW: curve a, point b, vector c */
    double depth;
} prim;

typedef struct {
    cairo_t *cr;
    plot_camera cam;
    const ic_trace_result *trace;
    plot_mesh mesh;
    double box[3][2];
    double kmin, kmax; /* the colour range of the curvature */
    double *arrow;     /* per curve: the arrows' length in space */
    double light[3];
} ctx3d;

static int by_depth(const void *x, const void *y)
{
    const double a = ((const prim *)x)->depth, b = ((const prim *)y)->depth;
    return a < b ? 1 : a > b ? -1 : 0;
}

static double mean_depth(const ctx3d *c, const double (*p)[3], int n)
{
    double sum = 0;
    for (int i = 0; i < n; i++) {
        double x, y, d;
        ic_plot_camera_project(&c->cam, p[i], &x, &y, &d);
        sum += d;
    }
    return sum / n;
}

static void draw_tri(ctx3d *c, const plot_tri *t)
{
    double e1[3], e2[3], nrm[3];
    for (int k = 0; k < 3; k++)
        e1[k] = t->v[1][k] - t->v[0][k], e2[k] = t->v[2][k] - t->v[0][k];
    nrm[0] = e1[1] * e2[2] - e1[2] * e2[1];
    nrm[1] = e1[2] * e2[0] - e1[0] * e2[2];
    nrm[2] = e1[0] * e2[1] - e1[1] * e2[0];
    const double len = sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
    if (!(len > 0))
        return;
    /* two-sided Lambert shading with an ambient part */
    const double lam = fabs(nrm[0] * c->light[0] + nrm[1] * c->light[1] + nrm[2] * c->light[2]);
    const double shade = 0.45 + 0.55 * lam / len;
    const double *col = ic_plot_rgb_surface[t->surface & 1];
    cairo_set_source_rgba(c->cr, col[0] * shade, col[1] * shade, col[2] * shade, 0.55);
    for (int i = 0; i < 3; i++) {
        double x, y;
        ic_plot_camera_project(&c->cam, t->v[i], &x, &y, NULL);
        if (i == 0)
            cairo_move_to(c->cr, x, y);
        else
            cairo_line_to(c->cr, x, y);
    }
    cairo_close_path(c->cr);
    cairo_fill(c->cr);
}

static const ic_trace_point *curve_point(const ctx3d *c, int curve, int k)
{
    return &ic_trace_result_curve(c->trace, curve)->points[k];
}

static void draw_seg(ctx3d *c, int curve, int k)
{
    const ic_trace_point *p = curve_point(c, curve, k), *q = curve_point(c, curve, k + 1);
    double rgb[3];
    const double kap = 0.5 * (p->kappa + q->kappa);
    ic_plot_colormap(c->kmax > c->kmin ? (kap - c->kmin) / (c->kmax - c->kmin) : 0.5, rgb);
    cairo_set_source_rgb(c->cr, rgb[0], rgb[1], rgb[2]);
    cairo_set_line_width(c->cr, PLOT_CURVE_WIDTH);
    cairo_set_line_cap(c->cr, CAIRO_LINE_CAP_ROUND);
    ic_plot_curve_path(c->cr, &c->cam, c->trace, curve, k);
    cairo_stroke(c->cr);
}

static void draw_arrow(ctx3d *c, int curve, int k, int which)
{
    const ic_trace_point *p = curve_point(c, curve, k);
    const double *v = which == 0 ? p->t : which == 1 ? p->n : p->b;
    const double *col = which == 0 ? ic_plot_rgb_t : which == 1 ? ic_plot_rgb_n : ic_plot_rgb_b;
    double tip[3], x0, y0, x1, y1;
    for (int i = 0; i < 3; i++)
        tip[i] = p->xyz[i] + c->arrow[curve] * v[i];
    ic_plot_camera_project(&c->cam, p->xyz, &x0, &y0, NULL);
    ic_plot_camera_project(&c->cam, tip, &x1, &y1, NULL);
    cairo_set_source_rgb(c->cr, col[0], col[1], col[2]);
    cairo_set_line_width(c->cr, PLOT_ARROW_WIDTH);
    cairo_set_line_cap(c->cr, CAIRO_LINE_CAP_BUTT);
    cairo_move_to(c->cr, x0, y0);
    cairo_line_to(c->cr, x1, y1);
    cairo_stroke(c->cr);
    const double dx = x1 - x0, dy = y1 - y0, l = hypot(dx, dy);
    if (l < 1e-9)
        return;
    const double ux = dx / l, uy = dy / l, hl = fmin(10.0, 0.45 * l), hw = 0.45 * hl;
    cairo_move_to(c->cr, x1, y1);
    cairo_line_to(c->cr, x1 - hl * ux - hw * uy, y1 - hl * uy + hw * ux);
    cairo_line_to(c->cr, x1 - hl * ux + hw * uy, y1 - hl * uy - hw * ux);
    cairo_close_path(c->cr);
    cairo_fill(c->cr);
}

/* The vertical colour bar of the curvature at (x, y), height h. */
static void draw_colorbar(ctx3d *c, double x, double y, double h)
{
    cairo_t *cr = c->cr;
    enum { STEPS = 48 };
    for (int i = 0; i < STEPS; i++) {
        double rgb[3];
        ic_plot_colormap(c->kmax > c->kmin ? (i + 0.5) / STEPS : 0.5, rgb);
        cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
        cairo_rectangle(cr, x, y + h - (i + 1) * h / STEPS, 16, h / STEPS + 0.5);
        cairo_fill(cr);
    }
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
    if (!(c->kmax > c->kmin)) { /* constant curvature: its value, mid-bar */
        char buf[48];
        snprintf(buf, sizeof buf, "%.6g (constant)", c->kmin);
        ic_plot_text(cr, x + 20, y + 0.5 * h, 11, 0, buf, 0, 0.5);
    } else {
        double first, step;
        const double lo = c->kmin, hi = c->kmax;
        const int n = ic_plot_ticks(lo, hi, 4, &first, &step);
        for (int i = 0; i < n; i++) {
            const double v = first + i * step, yy = y + h - (v - lo) / (hi - lo) * h;
            char buf[32];
            ic_plot_tick_label(buf, sizeof buf, v, step);
            ic_plot_text(cr, x + 20, yy, 11, 0, buf, 0, 0.5);
        }
    }
    ic_plot_text(cr, x + 8, y - 12, 12, 1, "curvature \xce\xba", 0.5, 1);
}

/* The legend's label of surface s: "A: name", the name cut to at most
 * `keep` bytes (at a character boundary) and "..." when it is cut. */
static void surface_label(char *buf, size_t size, const ic_plot_scene *scene, int s, size_t keep)
{
    const char *name = scene->names[s] ? scene->names[s] : "";
    size_t n = strlen(name);
    if (n <= keep) {
        snprintf(buf, size, "%c: %s", 'A' + s, name);
        return;
    }
    while (keep > 0 && ((unsigned char)name[keep] & 0xC0) == 0x80)
        keep--; /* not inside a UTF-8 sequence */
    snprintf(buf, size, "%c: %.*s\xe2\x80\xa6", 'A' + s, (int)keep, name);
}

/* The surfaces' names (cut until the legend fits in `width`) and the frame
 * colours, from (x, y). */
static void draw_legend(ctx3d *c, const ic_plot_scene *scene, double x, double y, double width,
                        int frames)
{
    cairo_t *cr = c->cr;
    const double frame_part = frames ? 3 * 40 : 0;
    char buf[2][160];
    for (size_t keep = sizeof buf[0];; keep = keep * 3 / 4) {
        double used = frame_part;
        for (int s = 0; s < scene->nsurfaces; s++) {
            surface_label(buf[s], sizeof buf[s], scene, s, keep);
            used += 30 + ic_plot_text_width(cr, 12, 0, buf[s]);
        }
        if (used <= width || keep == 0)
            break;
    }
    for (int s = 0; s < scene->nsurfaces; s++) {
        const double *col = ic_plot_rgb_surface[s];
        cairo_set_source_rgba(cr, col[0], col[1], col[2], 0.8);
        cairo_rectangle(cr, x, y - 6, 14, 12);
        cairo_fill(cr);
        cairo_set_source_rgb(cr, 0.15, 0.15, 0.15);
        ic_plot_text(cr, x + 20, y, 12, 0, buf[s], 0, 0.5);
        x += 30 + ic_plot_text_width(cr, 12, 0, buf[s]);
    }
    static const char *const FRAME[3] = {"t", "n", "b"};
    const double *cols[3] = {ic_plot_rgb_t, ic_plot_rgb_n, ic_plot_rgb_b};
    for (int k = 0; k < (frames ? 3 : 0); k++) {
        cairo_set_source_rgb(cr, cols[k][0], cols[k][1], cols[k][2]);
        cairo_set_line_width(cr, 3);
        cairo_move_to(cr, x, y);
        cairo_line_to(cr, x + 18, y);
        cairo_stroke(cr);
        cairo_set_source_rgb(cr, 0.15, 0.15, 0.15);
        ic_plot_text(cr, x + 22, y, 12, 1, FRAME[k], 0, 0.5);
        x += 40;
    }
}

/* Whether a overlaps one of the n label boxes placed so far. */
static int overlaps(const plot_rect *a, const plot_rect *r, int n)
{
    for (int i = 0; i < n; i++)
        if (a->x0 < r[i].x1 && r[i].x0 < a->x1 && a->y0 < r[i].y1 && r[i].y0 < a->y1)
            return 1;
    return 0;
}

/* The special points, labelled by type; -1 out of memory (before: drawn
 * without them; tests/test_nomem.c, "writers"). */
static int draw_specials(ctx3d *c)
{
    const int n = ic_trace_result_num_specials(c->trace);
    plot_rect *placed = calloc((size_t)n + 1, sizeof *placed);
    if (!placed)
        return -1;
    int np = 0;
    for (int i = 0; i < n; i++) {
        const ic_trace_special *sp = ic_trace_result_special(c->trace, i);
        double x, y;
        ic_plot_camera_project(&c->cam, sp->xyz, &x, &y, NULL);
        cairo_new_path(c->cr); /* the text before leaves a current point */
        cairo_arc(c->cr, x, y, 5.5, 0, 2 * IC_PI);
        cairo_set_source_rgb(c->cr, 1, 1, 1);
        cairo_fill_preserve(c->cr);
        cairo_set_source_rgb(c->cr, 0, 0, 0);
        cairo_set_line_width(c->cr, 1.6);
        cairo_stroke(c->cr);
        char label[64];
        snprintf(label, sizeof label, "%s%s", ic_point_type_name(sp->type),
                 sp->approximate ? " (approximate)" : "");
        const double w = ic_plot_text_width(c->cr, 12, 0, label), h = 12;
        /* the first of eight places around the marker that is free */
        static const double DX[8] = {10, 10, -10, -10, 10, -10, 0, 0};
        static const double DY[8] = {-10, 10, -10, 10, 0, 0, -16, 16};
        plot_rect r = {0, 0, 0, 0};
        for (int k = 0; k < 8; k++) {
            const double lx = DX[k] >= 0 ? x + DX[k] : x + DX[k] - w;
            const double ly = DY[k] > 0 ? y + DY[k] : DY[k] < 0 ? y + DY[k] - h : y - h / 2;
            r = (plot_rect){lx - 2, ly - 2, lx + w + 2, ly + h + 2};
            if (!overlaps(&r, placed, np))
                break;
        }
        placed[np++] = r;
        cairo_set_source_rgba(c->cr, 1, 1, 1, 0.8);
        cairo_rectangle(c->cr, r.x0, r.y0, r.x1 - r.x0, r.y1 - r.y0);
        cairo_fill(c->cr);
        cairo_set_source_rgb(c->cr, 0, 0, 0);
        ic_plot_text(c->cr, r.x0 + 2, r.y0 + 2, 12, 0, label, 0, 0);
    }
    free(placed);
    return 0;
}

/* The points of the frames: n positions equally spaced in arc length over
 * all curves, each the nearest curve point. */
static int frame_points(const ic_trace_result *tr, int n, int (*at)[2])
{
    double total = 0;
    const int nc = tr ? ic_trace_result_num_curves(tr) : 0;
    for (int c = 0; c < nc; c++)
        total += ic_trace_result_curve(tr, c)->length;
    if (!(total > 0) || n <= 0)
        return 0;
    int count = 0;
    for (int j = 0; j < n; j++) {
        double target = (j + 0.5) * total / n;
        for (int c = 0; c < nc; c++) {
            const ic_trace_curve *cv = ic_trace_result_curve(tr, c);
            if (target > cv->length && c + 1 < nc) {
                target -= cv->length;
                continue;
            }
            const double s = cv->points[0].s + target;
            int best = 0;
            for (int k = 1; k < cv->npoints; k++)
                if (fabs(cv->points[k].s - s) < fabs(cv->points[best].s - s))
                    best = k;
            at[count][0] = c, at[count][1] = best;
            count++;
            break;
        }
    }
    return count;
}

/* The meshes: the parametric surfaces first (cut to the scene's box, or
 * whole), then the region drawn, then the implicit surfaces inside it. */
static ic_status make_meshes(ctx3d *c, const ic_plot_scene *scene, const ic_plot_options *opt,
                             ic_error *err)
{
    const int implicit_cells = opt->mesh / 2;
    ic_status st = IC_OK;
    for (int s = 0; s < scene->nsurfaces && st == IC_OK; s++)
        if (ic_surface_get_kind(scene->surfaces[s]) == IC_PARAMETRIC)
            st = ic_plot_mesh_surface(&c->mesh, scene->surfaces[s], s,
                                   scene->has_box ? scene->box : NULL, opt->mesh, err);
    if (st == IC_OK)
        st = ic_plot_region(c->box, scene, &c->mesh, implicit_cells > 4 ? implicit_cells : 4, err);
    for (int s = 0; s < scene->nsurfaces && st == IC_OK; s++)
        if (ic_surface_get_kind(scene->surfaces[s]) != IC_PARAMETRIC)
            st = ic_plot_mesh_surface(&c->mesh, scene->surfaces[s], s, (const double(*)[2])c->box,
                                   implicit_cells, err);
    return st;
}

/* The colour range of the curvature over every curve point. */
static void curvature_range(ctx3d *c, int nc)
{
    c->kmin = INFINITY, c->kmax = -INFINITY;
    for (int i = 0; i < nc; i++) {
        const ic_trace_curve *cv = ic_trace_result_curve(c->trace, i);
        for (int k = 0; k < cv->npoints; k++)
            if (isfinite(cv->points[k].kappa)) {
                c->kmin = fmin(c->kmin, cv->points[k].kappa);
                c->kmax = fmax(c->kmax, cv->points[k].kappa);
            }
    }
    if (!(c->kmax >= c->kmin))
        c->kmin = c->kmax = 0;
    if (c->kmax - c->kmin <= 1e-9 * fmax(fabs(c->kmax), 1e-300))
        c->kmax = c->kmin; /* constant: one colour */
}

/* The tips of the frame arrows, which the camera's fit keeps in the panel;
 * their number. */
static int arrow_tips(const ctx3d *c, const int (*frames)[2], int nf, double (*tips)[3])
{
    int n = 0;
    for (int f = 0; f < nf; f++) {
        const ic_trace_point *p = curve_point(c, frames[f][0], frames[f][1]);
        for (int v = 0; v < (p->frame_defined ? 3 : 1); v++, n++) {
            const double *dir = v == 0 ? p->t : v == 1 ? p->n : p->b;
            for (int k = 0; k < 3; k++)
                tips[n][k] = p->xyz[k] + c->arrow[frames[f][0]] * dir[k];
        }
    }
    return n;
}

/* Triangles, curve segments and arrows with their depths; their number.
 * The curves lie on the surfaces: drawn after the triangles at their own
 * depth less `bias`, so a surface hides them only where it passes in front. */
static int collect_prims(const ctx3d *c, int nc, const int (*frames)[2], int nf, double bias,
                         prim *pr)
{
    int np = 0;
    for (int i = 0; i < c->mesh.n; i++)
        pr[np++] = (prim){PRIM_TRI, i, 0, 0, mean_depth(c, (const double(*)[3])c->mesh.t[i].v, 3)};
    for (int i = 0; i < nc; i++) {
        const ic_trace_curve *cv = ic_trace_result_curve(c->trace, i);
        for (int k = 0; k + 1 < cv->npoints; k++) {
            double p[2][3];
            memcpy(p[0], cv->points[k].xyz, sizeof p[0]);
            memcpy(p[1], cv->points[k + 1].xyz, sizeof p[1]);
            pr[np++] = (prim){PRIM_SEG, i, k, 0, mean_depth(c, (const double(*)[3])p, 2) - bias};
        }
    }
    for (int f = 0; f < nf; f++) {
        const ic_trace_point *p = curve_point(c, frames[f][0], frames[f][1]);
        for (int v = 0; v < (p->frame_defined ? 3 : 1); v++)
            pr[np++] = (prim){PRIM_ARROW, frames[f][0], frames[f][1], v,
                              mean_depth(c, (const double(*)[3])p->xyz, 1) - bias};
    }
    qsort(pr, (size_t)np, sizeof *pr, by_depth);
    return np;
}

/* "no intersection" only where the search proved it; else what was not
 * proven. */
static void draw_no_intersection(cairo_t *cr, const ic_trace_result *trace, double x, double y)
{
    const ic_trace_report *rep = ic_trace_result_report(trace);
    cairo_set_source_rgb(cr, 0.6, 0.1, 0.1);
    ic_plot_text(cr, x, y, 28, 1, "no intersection", 0.5, 0.5);
    if (!rep->proven || rep->uncovered_cells > 0 || rep->unproven_cells > 0) {
        char buf[160];
        snprintf(buf, sizeof buf, "found: not proven (%s%d cells uncovered, %d unproven)",
                 rep->proven ? "" : "sampled only, ", rep->uncovered_cells, rep->unproven_cells);
        ic_plot_text(cr, x, y + 28, 14, 0, buf, 0.5, 0.5);
    }
}

/* The depth-sorted scene, the axes, the singular points, colour bar and
 * legend, once the meshes and the box are made. */
static ic_status draw_scene(ctx3d *c, const ic_plot_scene *scene, const ic_plot_options *opt,
                            const plot_rect *panel, ic_error *err)
{
    const double x = panel->x0, y = panel->y0, w = panel->x1 - x, h = panel->y1 - y;
    const int nc = c->trace ? ic_trace_result_num_curves(c->trace) : 0;
    double diag = 0;
    for (int k = 0; k < 3; k++)
        diag += (c->box[k][1] - c->box[k][0]) * (c->box[k][1] - c->box[k][0]);
    diag = sqrt(diag);
    int nseg = 0;
    for (int i = 0; i < nc; i++)
        nseg += ic_trace_result_curve(c->trace, i)->npoints - 1;
    int(*frames)[2] = malloc(((size_t)opt->frames + 1) * sizeof *frames);
    double(*tips)[3] = malloc((3 * (size_t)opt->frames + 1) * sizeof *tips);
    prim *pr =
        malloc(((size_t)c->mesh.n + (size_t)nseg + 3 * (size_t)opt->frames + 1) * sizeof *pr);
    plot_axes *axes = malloc(sizeof *axes);
    c->arrow = malloc(((size_t)nc + 1) * sizeof *c->arrow);
    ic_status st = IC_OK;
    if (!frames || !tips || !pr || !axes || !c->arrow) {
        st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory drawing");
    } else {
        for (int i = 0; i < nc; i++)
            c->arrow[i] = ic_plot_arrow_length(ic_trace_result_curve(c->trace, i), diag);
        curvature_range(c, nc);
        const int nf = frame_points(c->trace, opt->frames, frames);
        /* the box with its labels left of the colour bar and above the legend */
        const plot_rect area = {x + 8, y + 8, x + w - 110, y + h - 36};
        ic_plot_camera_init(&c->cam, opt->azimuth, opt->elevation);
        ic_plot_axes_fit(axes, c->cr, &c->cam, (const double(*)[2])c->box, area,
                      (const double(*)[3])tips, arrow_tips(c, (const int(*)[2])frames, nf, tips));
        /* light from the viewer, raised and to the left */
        for (int k = 0; k < 3; k++)
            c->light[k] = 0.8 * c->cam.toward[k] + 0.45 * c->cam.up[k] - 0.3 * c->cam.right[k];
        const int np = collect_prims(c, nc, (const int(*)[2])frames, nf, 0.01 * diag, pr);
        ic_plot_axes_draw(c->cr, &c->cam, (const double(*)[2])c->box, axes);
        for (int i = 0; i < np; i++) {
            if (pr[i].kind == PRIM_TRI)
                draw_tri(c, &c->mesh.t[pr[i].a]);
            else if (pr[i].kind == PRIM_SEG)
                draw_seg(c, pr[i].a, pr[i].b);
            else
                draw_arrow(c, pr[i].a, pr[i].b, pr[i].c);
        }
        if (c->trace && draw_specials(c) != 0)
            st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory drawing the special points");
        if (nc > 0)
            draw_colorbar(c, x + w - 95, y + 60, fmin(260, h - 160));
        draw_legend(c, scene, x + 20, y + h - 18, w - 30, nf);
        if (c->trace && nc == 0 && ic_trace_result_num_specials(c->trace) == 0)
            draw_no_intersection(c->cr, c->trace, x + 0.5 * w, y + 0.5 * h);
    }
    free(frames);
    free(tips);
    free(pr);
    free(axes);
    free(c->arrow);
    return st;
}

ic_status ic_plot_draw_3d(cairo_t *cr, const ic_plot_scene *scene, const ic_plot_options *opt,
                       double x, double y, double w, double h, ic_error *err)
{
    ctx3d c;
    memset(&c, 0, sizeof c);
    c.cr = cr;
    c.trace = scene->trace;
    ic_status st = make_meshes(&c, scene, opt, err);
    if (st == IC_OK) {
        const plot_rect panel = {x, y, x + w, y + h};
        st = draw_scene(&c, scene, opt, &panel, err);
    }
    free(c.mesh.t);
    return st;
}
