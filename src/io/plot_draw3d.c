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
    double arrow;      /* arrow length in space */
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
    double rgb[3], x0, y0, x1, y1;
    const double kap = 0.5 * (p->kappa + q->kappa);
    ic_plot_colormap(c->kmax > c->kmin ? (kap - c->kmin) / (c->kmax - c->kmin) : 0.5, rgb);
    ic_plot_camera_project(&c->cam, p->xyz, &x0, &y0, NULL);
    ic_plot_camera_project(&c->cam, q->xyz, &x1, &y1, NULL);
    cairo_set_source_rgb(c->cr, rgb[0], rgb[1], rgb[2]);
    cairo_set_line_width(c->cr, PLOT_CURVE_WIDTH);
    cairo_set_line_cap(c->cr, CAIRO_LINE_CAP_ROUND);
    cairo_move_to(c->cr, x0, y0);
    cairo_line_to(c->cr, x1, y1);
    cairo_stroke(c->cr);
}

static void draw_arrow(ctx3d *c, int curve, int k, int which)
{
    const ic_trace_point *p = curve_point(c, curve, k);
    const double *v = which == 0 ? p->t : which == 1 ? p->n : p->b;
    const double *col = which == 0 ? ic_plot_rgb_t : which == 1 ? ic_plot_rgb_n : ic_plot_rgb_b;
    double tip[3], x0, y0, x1, y1;
    for (int i = 0; i < 3; i++)
        tip[i] = p->xyz[i] + c->arrow * v[i];
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

/* The box's edges, and ticks along the three edges from its lowest corner. */
static void draw_axes(ctx3d *c)
{
    cairo_t *cr = c->cr;
    cairo_set_source_rgb(cr, 0.75, 0.75, 0.75);
    cairo_set_line_width(cr, 0.8);
    for (int e = 0; e < 12; e++) { /* edges: axis e / 4, the other two bits e % 4 */
        const int ax = e / 4, o1 = (ax + 1) % 3, o2 = (ax + 2) % 3;
        double a[3], b[3], x0, y0, x1, y1;
        a[ax] = c->box[ax][0], b[ax] = c->box[ax][1];
        a[o1] = b[o1] = c->box[o1][e & 1];
        a[o2] = b[o2] = c->box[o2][(e >> 1) & 1];
        ic_plot_camera_project(&c->cam, a, &x0, &y0, NULL);
        ic_plot_camera_project(&c->cam, b, &x1, &y1, NULL);
        cairo_move_to(cr, x0, y0);
        cairo_line_to(cr, x1, y1);
        cairo_stroke(cr);
    }
    static const char *const NAMES[3] = {"x", "y", "z"};
    double size = 0;
    for (int k = 0; k < 3; k++)
        size = fmax(size, c->box[k][1] - c->box[k][0]);
    for (int ax = 0; ax < 3; ax++) {
        /* the edge to label: x and y along the bottom, the one lowest on the
         * screen; z the vertical edge farthest left. Ticks point away from
         * the box along the coordinate `off`. */
        const int o1 = (ax + 1) % 3, o2 = (ax + 2) % 3;
        double best = -INFINITY, corner[3] = {0, 0, 0};
        int off = o1;
        double sign = -1;
        for (int e = 0; e < 4; e++) {
            double p[3];
            p[ax] = 0.5 * (c->box[ax][0] + c->box[ax][1]);
            p[o1] = c->box[o1][e & 1];
            p[o2] = c->box[o2][(e >> 1) & 1];
            if (ax < 2 && p[2] != c->box[2][0])
                continue;
            double sx, sy;
            ic_plot_camera_project(&c->cam, p, &sx, &sy, NULL);
            const double score = ax < 2 ? sy : -sx;
            if (score > best) {
                best = score;
                memcpy(corner, p, sizeof p);
                /* x, y: away along the other horizontal axis; z: along x or
                 * y, whichever moves left on the screen */
                const int o = ax < 2 ? (ax == 0 ? 1 : 0) : 0;
                off = o;
                sign = p[o] == c->box[o][0] ? -1 : 1;
                if (ax == 2) {
                    const int o3 = 1;
                    double q[3], r[3], x0, y0, x1, y1, x2, y2;
                    memcpy(q, p, sizeof p);
                    memcpy(r, p, sizeof p);
                    q[0] += (p[0] == c->box[0][0] ? -1 : 1) * size;
                    r[o3] += (p[o3] == c->box[o3][0] ? -1 : 1) * size;
                    ic_plot_camera_project(&c->cam, p, &x0, &y0, NULL);
                    ic_plot_camera_project(&c->cam, q, &x1, &y1, NULL);
                    ic_plot_camera_project(&c->cam, r, &x2, &y2, NULL);
                    if (x2 < x1) {
                        off = o3;
                        sign = p[o3] == c->box[o3][0] ? -1 : 1;
                    }
                }
            }
        }
        double first, step;
        /* about one tick per 70 px of the axis on the screen (2 to 5), so
         * that the labels of a foreshortened axis do not run together */
        double e0[3], e1[3], sx0, sy0, sx1, sy1;
        memcpy(e0, corner, sizeof e0);
        memcpy(e1, corner, sizeof e1);
        e0[ax] = c->box[ax][0], e1[ax] = c->box[ax][1];
        ic_plot_camera_project(&c->cam, e0, &sx0, &sy0, NULL);
        ic_plot_camera_project(&c->cam, e1, &sx1, &sy1, NULL);
        const double px = hypot(sx1 - sx0, sy1 - sy0);
        const int want = px < 140 ? 2 : px > 350 ? 5 : (int)(px / 70);
        const int n = ic_plot_ticks(c->box[ax][0], c->box[ax][1], want, &first, &step);
        cairo_set_source_rgb(cr, 0.25, 0.25, 0.25);
        cairo_set_line_width(cr, 1.0);
        for (int i = 0; i < n; i++) {
            const double v = first + i * step;
            double a[3], b[3], l[3];
            memcpy(a, corner, sizeof a);
            a[ax] = v;
            memcpy(b, a, sizeof a);
            memcpy(l, a, sizeof a);
            b[off] += sign * 0.02 * size;
            l[off] += sign * 0.07 * size;
            double x0, y0, x1, y1, xl, yl;
            ic_plot_camera_project(&c->cam, a, &x0, &y0, NULL);
            ic_plot_camera_project(&c->cam, b, &x1, &y1, NULL);
            ic_plot_camera_project(&c->cam, l, &xl, &yl, NULL);
            cairo_move_to(cr, x0, y0);
            cairo_line_to(cr, x1, y1);
            cairo_stroke(cr);
            char buf[32];
            ic_plot_tick_label(buf, sizeof buf, v, step);
            ic_plot_text(cr, xl, yl, 11, 0, buf, 0.5, 0.5);
        }
        /* the axis name beyond the tick labels of the axis' middle, 26 px
         * further along the screen direction from the axis to the labels */
        double a[3], l[3], xa, ya, xl, yl;
        memcpy(a, corner, sizeof a);
        a[ax] = 0.5 * (c->box[ax][0] + c->box[ax][1]);
        memcpy(l, a, sizeof a);
        l[off] += sign * 0.07 * size;
        ic_plot_camera_project(&c->cam, a, &xa, &ya, NULL);
        ic_plot_camera_project(&c->cam, l, &xl, &yl, NULL);
        const double dx = xl - xa, dy = yl - ya, dl = hypot(dx, dy);
        if (dl > 1e-9)
            xl += 26 * dx / dl, yl += 26 * dy / dl;
        if (ax == 2) { /* z: above the top of its edge */
            a[2] = c->box[2][1];
            ic_plot_camera_project(&c->cam, a, &xl, &yl, NULL);
            yl -= 18;
        }
        ic_plot_text(cr, xl, yl, 14, 1, NAMES[ax], 0.5, 0.5);
    }
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

static void draw_legend(ctx3d *c, const ic_plot_scene *scene, double x, double y, int frames)
{
    cairo_t *cr = c->cr;
    for (int s = 0; s < scene->nsurfaces; s++) {
        const double *col = ic_plot_rgb_surface[s];
        cairo_set_source_rgba(cr, col[0], col[1], col[2], 0.8);
        cairo_rectangle(cr, x, y - 6, 14, 12);
        cairo_fill(cr);
        cairo_set_source_rgb(cr, 0.15, 0.15, 0.15);
        char buf[160];
        snprintf(buf, sizeof buf, "%c: %s", 'A' + s, scene->names[s] ? scene->names[s] : "");
        ic_plot_text(cr, x + 20, y, 12, 0, buf, 0, 0.5);
        x += 30 + ic_plot_text_width(cr, 12, 0, buf);
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

/* Label boxes placed so far, so that labels do not overlap. */
typedef struct {
    double x0, y0, x1, y1;
} rect;

static int overlaps(const rect *a, const rect *r, int n)
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
    rect *placed = calloc((size_t)n + 1, sizeof *placed);
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
        rect r = {0, 0, 0, 0};
        for (int k = 0; k < 8; k++) {
            const double lx = DX[k] >= 0 ? x + DX[k] : x + DX[k] - w;
            const double ly = DY[k] > 0 ? y + DY[k] : DY[k] < 0 ? y + DY[k] - h : y - h / 2;
            r = (rect){lx - 2, ly - 2, lx + w + 2, ly + h + 2};
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

/* The box of the picture: the scene's, else around the parametric meshes
 * and the curves (an implicit surface is then meshed inside it). */
static void picture_box(ctx3d *c, const ic_plot_scene *scene)
{
    if (scene->has_box) {
        memcpy(c->box, scene->box, sizeof c->box);
        return;
    }
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int i = 0; i < c->mesh.n; i++)
        for (int v = 0; v < 3; v++)
            for (int k = 0; k < 3; k++)
                lo[k] = fmin(lo[k], c->mesh.t[i].v[v][k]),
                hi[k] = fmax(hi[k], c->mesh.t[i].v[v][k]);
    for (int ci = 0; c->trace && ci < ic_trace_result_num_curves(c->trace); ci++) {
        const ic_trace_curve *cv = ic_trace_result_curve(c->trace, ci);
        for (int p = 0; p < cv->npoints; p++)
            for (int k = 0; k < 3; k++)
                lo[k] = fmin(lo[k], cv->points[p].xyz[k]),
                hi[k] = fmax(hi[k], cv->points[p].xyz[k]);
    }
    for (int k = 0; k < 3; k++) {
        if (!(hi[k] >= lo[k]))
            lo[k] = -1, hi[k] = 1;
        const double m = 0.05 * fmax(hi[k] - lo[k], 1e-3);
        c->box[k][0] = lo[k] - m, c->box[k][1] = hi[k] + m;
    }
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

ic_status ic_plot_draw_3d(cairo_t *cr, const ic_plot_scene *scene, const ic_plot_options *opt,
                          double x, double y, double w, double h, ic_error *err)
{
    ctx3d c;
    memset(&c, 0, sizeof c);
    c.cr = cr;
    c.trace = scene->trace;
    ic_status st = IC_OK;
    /* parametric surfaces first: without a box they set the picture's */
    for (int pass = 0; pass < 2 && st == IC_OK; pass++) {
        if (pass == 1)
            picture_box(&c, scene);
        for (int s = 0; s < scene->nsurfaces && st == IC_OK; s++) {
            const int par = ic_surface_get_kind(scene->surfaces[s]) == IC_PARAMETRIC;
            if (par == (pass == 0))
                st = ic_plot_mesh_surface(&c.mesh, scene->surfaces[s], s,
                                          pass == 0 ? (scene->has_box ? scene->box : NULL) : c.box,
                                          par ? opt->mesh : opt->mesh / 2, err);
        }
    }
    if (st != IC_OK) {
        free(c.mesh.t);
        return st;
    }
    ic_plot_camera_init(&c.cam, opt->azimuth, opt->elevation);
    ic_plot_camera_fit(&c.cam, c.box, x + 40, y + 30, w - 150, h - 90);
    /* light from the viewer, raised and to the left */
    for (int k = 0; k < 3; k++)
        c.light[k] = 0.8 * c.cam.toward[k] + 0.45 * c.cam.up[k] - 0.3 * c.cam.right[k];
    double diag = 0;
    for (int k = 0; k < 3; k++)
        diag += (c.box[k][1] - c.box[k][0]) * (c.box[k][1] - c.box[k][0]);
    c.arrow = 0.08 * sqrt(diag);
    /* the curves lie on the surfaces: drawn after the triangles at their own
     * depth (1% of the diagonal nearer), so a surface hides them only where
     * it passes in front */
    const double bias = 0.01 * sqrt(diag);
    /* the curvature range over every curve point */
    const int nc = c.trace ? ic_trace_result_num_curves(c.trace) : 0;
    c.kmin = INFINITY, c.kmax = -INFINITY;
    int nseg = 0;
    for (int i = 0; i < nc; i++) {
        const ic_trace_curve *cv = ic_trace_result_curve(c.trace, i);
        nseg += cv->npoints - 1;
        for (int k = 0; k < cv->npoints; k++)
            if (isfinite(cv->points[k].kappa)) {
                c.kmin = fmin(c.kmin, cv->points[k].kappa);
                c.kmax = fmax(c.kmax, cv->points[k].kappa);
            }
    }
    if (!(c.kmax >= c.kmin))
        c.kmin = c.kmax = 0;
    if (c.kmax - c.kmin <= 1e-9 * fmax(fabs(c.kmax), 1e-300))
        c.kmax = c.kmin; /* constant: one colour */
    int(*frames)[2] = malloc(((size_t)opt->frames + 1) * sizeof *frames);
    const int nf = frames ? frame_points(c.trace, opt->frames, frames) : 0;
    prim *pr = malloc(((size_t)c.mesh.n + (size_t)nseg + 3 * (size_t)nf + 1) * sizeof *pr);
    if (!pr || !frames) {
        free(pr);
        free(frames);
        free(c.mesh.t);
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory drawing");
    }
    int np = 0;
    for (int i = 0; i < c.mesh.n; i++)
        pr[np++] = (prim){PRIM_TRI, i, 0, 0, mean_depth(&c, (const double(*)[3])c.mesh.t[i].v, 3)};
    for (int i = 0; i < nc; i++) {
        const ic_trace_curve *cv = ic_trace_result_curve(c.trace, i);
        for (int k = 0; k + 1 < cv->npoints; k++) {
            const double p[2][3] = {
                {cv->points[k].xyz[0], cv->points[k].xyz[1], cv->points[k].xyz[2]},
                {cv->points[k + 1].xyz[0], cv->points[k + 1].xyz[1], cv->points[k + 1].xyz[2]}};
            pr[np++] = (prim){PRIM_SEG, i, k, 0, mean_depth(&c, p, 2) - bias};
        }
    }
    for (int f = 0; f < nf; f++) {
        const ic_trace_point *p = curve_point(&c, frames[f][0], frames[f][1]);
        for (int v = 0; v < (p->frame_defined ? 3 : 1); v++)
            pr[np++] = (prim){PRIM_ARROW, frames[f][0], frames[f][1], v,
                              mean_depth(&c, (const double(*)[3])p->xyz, 1) - bias};
    }
    qsort(pr, (size_t)np, sizeof *pr, by_depth);
    draw_axes(&c);
    for (int i = 0; i < np; i++) {
        if (pr[i].kind == PRIM_TRI)
            draw_tri(&c, &c.mesh.t[pr[i].a]);
        else if (pr[i].kind == PRIM_SEG)
            draw_seg(&c, pr[i].a, pr[i].b);
        else
            draw_arrow(&c, pr[i].a, pr[i].b, pr[i].c);
    }
    if (c.trace && draw_specials(&c) != 0) {
        free(pr);
        free(frames);
        free(c.mesh.t);
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory drawing");
    }
    if (nc > 0)
        draw_colorbar(&c, x + w - 95, y + 60, fmin(260, h - 160));
    draw_legend(&c, scene, x + 20, y + h - 18, nf);
    if (c.trace && nc == 0 && ic_trace_result_num_specials(c.trace) == 0) {
        /* "no intersection" only where the search proved it; else what was
         * not proven */
        const ic_trace_report *rep = ic_trace_result_report(c.trace);
        cairo_set_source_rgb(cr, 0.6, 0.1, 0.1);
        ic_plot_text(cr, x + 0.5 * w, y + 0.5 * h, 28, 1, "no intersection", 0.5, 0.5);
        if (!rep->proven || rep->uncovered_cells > 0 || rep->unproven_cells > 0) {
            char buf[160];
            snprintf(buf, sizeof buf, "found: not proven (%s%d cells uncovered, %d unproven)",
                     rep->proven ? "" : "sampled only, ", rep->uncovered_cells,
                     rep->unproven_cells);
            ic_plot_text(cr, x + 0.5 * w, y + 0.5 * h + 28, 14, 0, buf, 0.5, 0.5);
        }
    }
    free(pr);
    free(frames);
    free(c.mesh.t);
    return IC_OK;
}
