/*
 * The axes of the 3D panel (docs/plots.md, "Axes"): the box's edges, ticks
 * along one edge per axis, their labels and the axis names. Ticks, labels
 * and names are placed on the screen in pixels, not in space, so that a thin
 * or foreshortened axis keeps readable labels: the number of ticks follows
 * the axis' projected length and the labels' size, a label that would
 * overlap another is dropped, and the camera is fitted so that the box with
 * everything around it lies inside the panel.
 */
#include "plot_internal.h"

#include <math.h>
#include <string.h>

#define TICK_FONT 11.0     /* px, tick labels */
#define NAME_FONT 14.0     /* px, axis names (bold) */
#define TICK_PX 5.0        /* px, the length of a tick mark */
#define LABEL_GAP 3.0      /* px, from a tick's end to its label */
#define LABEL_SPACING 10.0 /* px, free space between neighbouring labels of an axis */
#define NAME_GAP 8.0       /* px, from an axis' labels to its name */
#define Z_NAME_RISE 18.0   /* px, the z name's centre above the top of its edge */
#define MIN_TICK_GAP 45.0  /* px, the least distance between neighbouring ticks */
#define MAX_TICKS_ASKED 5
#define PARALLEL_SIN                                                                               \
    0.35              /* sine of the angle below which ticks along the box would run               \
                         along the axis on the screen: they go perpendicular instead */
#define LEVEL_PX 1e-6 /* px, edges closer than this on the screen are level */
#define NAME_PUSH 6.0 /* px, the step that moves a name off another */
#define FIT_ROUNDS 6
#define MIN_FIT_PX 20.0 /* px, the smallest rectangle the box is fitted into */

/* The edge of one axis that carries its ticks, on the screen. */
typedef struct {
    double corner[3]; /* a point of the edge (its coordinate `axis` is the middle) */
    double ax, ay;    /* unit direction of the growing coordinate */
    double px;        /* projected length */
    double dx, dy;    /* unit direction from the edge towards its labels */
} axis_edge;

static void project(const plot_camera *cam, const double *p, double *x, double *y)
{
    ic_plot_camera_project(cam, p, x, y, NULL);
}

/* x and y: the bottom edge lowest on the screen; z: the vertical edge
 * farthest left; of edges level with each other (seen edge-on), the one
 * nearest the viewer, so that x and y meet at the near corner and their
 * labels do not pile up along one line. */
static void pick_edge(const plot_camera *cam, const double box[3][2], int ax, double corner[3])
{
    const int o1 = (ax + 1) % 3, o2 = (ax + 2) % 3;
    double best = -INFINITY, best_depth = INFINITY;
    for (int e = 0; e < 4; e++) {
        double p[3], sx, sy, depth;
        p[ax] = 0.5 * (box[ax][0] + box[ax][1]);
        p[o1] = box[o1][e & 1];
        p[o2] = box[o2][(e >> 1) & 1];
        if (ax < 2 && p[2] != box[2][0])
            continue;
        ic_plot_camera_project(cam, p, &sx, &sy, &depth);
        const double score = ax < 2 ? sy : -sx;
        if (score > best + LEVEL_PX || (score > best - LEVEL_PX && depth < best_depth))
            best = score, best_depth = depth, memcpy(corner, p, sizeof p);
    }
}

/* The screen displacement of moving from p outwards (away from the box)
 * along coordinate o by `len`. */
static void outward(const plot_camera *cam, const double box[3][2], const double *p, int o,
                    double len, double *dx, double *dy)
{
    double q[3], x0, y0, x1, y1;
    memcpy(q, p, sizeof q);
    q[o] += (p[o] == box[o][0] ? -1 : 1) * len;
    project(cam, p, &x0, &y0);
    project(cam, q, &x1, &y1);
    *dx = x1 - x0, *dy = y1 - y0;
}

static void make_edge(axis_edge *e, const plot_camera *cam, const double box[3][2], int ax)
{
    double side = 0;
    for (int k = 0; k < 3; k++)
        side = fmax(side, box[k][1] - box[k][0]);
    pick_edge(cam, box, ax, e->corner);
    /* the labels go outwards along the other horizontal coordinate for x
     * and y; for z along x or y, whichever moves left */
    double dx, dy;
    outward(cam, box, e->corner, ax == 0 ? 1 : 0, side, &dx, &dy);
    if (ax == 2) {
        double ex, ey;
        outward(cam, box, e->corner, 1, side, &ex, &ey);
        if (ex < dx)
            dx = ex, dy = ey;
    }
    double p0[3], p1[3], x0, y0, x1, y1;
    memcpy(p0, e->corner, sizeof p0);
    memcpy(p1, e->corner, sizeof p1);
    p0[ax] = box[ax][0], p1[ax] = box[ax][1];
    project(cam, p0, &x0, &y0);
    project(cam, p1, &x1, &y1);
    e->px = hypot(x1 - x0, y1 - y0);
    const double dl = hypot(dx, dy);
    if (e->px > 1e-9)
        e->ax = (x1 - x0) / e->px, e->ay = (y1 - y0) / e->px;
    else /* the axis points at the viewer: any direction across the labels */
        e->ax = dl > 0 ? dy / dl : 1, e->ay = dl > 0 ? -dx / dl : 0;
    e->dx = dl > 0 ? dx / dl : 0, e->dy = dl > 0 ? dy / dl : 0;
    if (fabs(e->ax * e->dy - e->ay * e->dx) < PARALLEL_SIN) {
        /* perpendicular to the axis, away from the box's centre */
        double c[3], cx, cy, mx, my;
        for (int k = 0; k < 3; k++)
            c[k] = 0.5 * (box[k][0] + box[k][1]);
        project(cam, c, &cx, &cy);
        project(cam, e->corner, &mx, &my);
        const double s = (mx - cx) * -e->ay + (my - cy) * e->ax >= 0 ? 1 : -1;
        e->dx = -s * e->ay, e->dy = s * e->ax;
    }
}

/* Half the extent of a w x h rectangle along the unit direction (ux, uy). */
static double support(double w, double h, double ux, double uy)
{
    return 0.5 * (fabs(ux) * w + fabs(uy) * h);
}

/* The ticks of about `asked` nice values in range, with their labels;
 * their number, or 0 when there are more than PLOT_AXIS_TICKS. */
static int fill_ticks(cairo_t *cr, const double range[2], int asked, plot_tick *t)
{
    double first, step;
    const int n = ic_plot_ticks(range[0], range[1], asked, &first, &step);
    if (n > PLOT_AXIS_TICKS)
        return 0;
    for (int i = 0; i < n; i++) {
        t[i].value = first + i * step;
        ic_plot_tick_label(t[i].text, sizeof t[i].text, t[i].value, step);
        t[i].width = ic_plot_text_width(cr, TICK_FONT, 0, t[i].text);
    }
    return n;
}

/* Whether neighbouring ticks are MIN_TICK_GAP apart and their labels leave
 * LABEL_SPACING between them along the axis. */
static int labels_fit(const plot_tick *t, int n, const axis_edge *e, const double range[2])
{
    for (int i = 0; i + 1 < n; i++) {
        const double gap = (t[i + 1].value - t[i].value) / (range[1] - range[0]) * e->px;
        const double need = support(t[i].width, TICK_FONT, e->ax, e->ay) +
                            support(t[i + 1].width, TICK_FONT, e->ax, e->ay);
        if (gap < MIN_TICK_GAP || gap < need + LABEL_SPACING)
            return 0;
    }
    return 1;
}

/* As many ticks as the projected length holds (about MAX_TICKS_ASKED at
 * most, MIN_TICK_GAP apart, labels that do not run together); when not even
 * two fit, the one nearest the middle. */
static int choose_ticks(cairo_t *cr, const double range[2], const axis_edge *e, plot_tick *t)
{
    for (int asked = MAX_TICKS_ASKED; asked >= 1; asked--) {
        const int n = fill_ticks(cr, range, asked, t);
        if (n >= 1 && labels_fit(t, n, e, range))
            return n;
    }
    const int n = fill_ticks(cr, range, 2, t);
    const double mid = 0.5 * (range[0] + range[1]);
    int best = 0;
    for (int i = 1; i < n; i++)
        if (fabs(t[i].value - mid) < fabs(t[best].value - mid))
            best = i;
    if (n > 0)
        t[0] = t[best];
    return n > 0;
}

static plot_rect centred(double cx, double cy, double w, double h)
{
    return (plot_rect){cx - 0.5 * w, cy - 0.5 * h, cx + 0.5 * w, cy + 0.5 * h};
}

static int overlap(const plot_rect *a, const plot_rect *b)
{
    return a->x0 < b->x1 && b->x0 < a->x1 && a->y0 < b->y1 && b->y0 < a->y1;
}

static int overlaps_any(const plot_rect *a, const plot_rect *placed, int n)
{
    for (int i = 0; i < n; i++)
        if (overlap(a, &placed[i]))
            return 1;
    return 0;
}

/* The ticks of axis ax on its edge: marks, labels beyond them; returns the
 * largest label's extent from the edge. */
static double place_ticks(plot_axes *a, cairo_t *cr, const plot_camera *cam, const double box[3][2],
                          const axis_edge *e, int ax)
{
    plot_tick *t = a->tick[ax];
    a->nticks[ax] = choose_ticks(cr, box[ax], e, t);
    double reach = TICK_PX;
    for (int i = 0; i < a->nticks[ax]; i++) {
        double p[3];
        memcpy(p, e->corner, sizeof p);
        p[ax] = t[i].value;
        project(cam, p, &t[i].x0, &t[i].y0);
        t[i].x1 = t[i].x0 + TICK_PX * e->dx, t[i].y1 = t[i].y0 + TICK_PX * e->dy;
        /* beyond the tick's end, and clear of the axis' line on the screen
         * (the labels go off at a slant where d is not perpendicular) */
        const double w = t[i].width, slant = fabs(e->dx * -e->ay + e->dy * e->ax);
        const double off =
            fmax(LABEL_GAP + support(w, TICK_FONT, e->dx, e->dy),
                 (LABEL_GAP + support(w, TICK_FONT, -e->ay, e->ax)) / slant - TICK_PX);
        t[i].label = centred(t[i].x1 + off * e->dx, t[i].y1 + off * e->dy, w, TICK_FONT);
        t[i].shown = 1;
        reach = fmax(reach, TICK_PX + off + support(w, TICK_FONT, e->dx, e->dy));
    }
    return reach;
}

/* The name of axis ax: x and y beyond the labels at the middle of the edge,
 * z above the top of its edge; moved on while it overlaps an earlier name. */
static void place_name(plot_axes *a, cairo_t *cr, const plot_camera *cam, const double box[3][2],
                       const axis_edge *e, int ax, double reach)
{
    static const char *const NAMES[3] = {"x", "y", "z"};
    const double w = ic_plot_text_width(cr, NAME_FONT, 1, NAMES[ax]);
    double p[3], x, y, ux = e->dx, uy = e->dy;
    memcpy(p, e->corner, sizeof p);
    if (ax == 2) {
        p[2] = box[2][1];
        project(cam, p, &x, &y);
        y -= Z_NAME_RISE, ux = 0, uy = -1;
    } else {
        project(cam, p, &x, &y);
        const double off = reach + NAME_GAP + support(w, NAME_FONT, ux, uy);
        x += off * ux, y += off * uy;
    }
    a->name[ax] = centred(x, y, w, NAME_FONT);
    for (int k = 0; k < 10 && overlaps_any(&a->name[ax], a->name, ax); k++) {
        x += NAME_PUSH * ux, y += NAME_PUSH * uy;
        a->name[ax] = centred(x, y, w, NAME_FONT);
    }
    a->name_shown[ax] = 1;
}

void ic_plot_axes_layout(plot_axes *axes, cairo_t *cr, const plot_camera *cam, const double box[3][2])
{
    axis_edge e[3];
    for (int ax = 0; ax < 3; ax++) {
        make_edge(&e[ax], cam, box, ax);
        place_name(axes, cr, cam, box, &e[ax], ax, place_ticks(axes, cr, cam, box, &e[ax], ax));
    }
    /* the names first, then the labels of the longest axis on the screen
     * first: a label that overlaps one placed before is dropped */
    plot_rect placed[3 + 3 * PLOT_AXIS_TICKS];
    int np = 0;
    for (int ax = 0; ax < 3; ax++)
        placed[np++] = axes->name[ax];
    int order[3] = {0, 1, 2};
    for (int i = 0; i < 3; i++)
        for (int j = i + 1; j < 3; j++)
            if (e[order[j]].px > e[order[i]].px) {
                const int k = order[i];
                order[i] = order[j], order[j] = k;
            }
    for (int i = 0; i < 3; i++) {
        plot_tick *t = axes->tick[order[i]];
        for (int k = 0; k < axes->nticks[order[i]]; k++) {
            t[k].shown = !overlaps_any(&t[k].label, placed, np);
            if (t[k].shown)
                placed[np++] = t[k].label;
        }
    }
}

static void add_point(plot_rect *r, double x, double y)
{
    r->x0 = fmin(r->x0, x), r->y0 = fmin(r->y0, y);
    r->x1 = fmax(r->x1, x), r->y1 = fmax(r->y1, y);
}

static void add_rect(plot_rect *r, const plot_rect *a)
{
    add_point(r, a->x0, a->y0);
    add_point(r, a->x1, a->y1);
}

/* The screen bounds of the box's corners (*b) and of everything drawn
 * around it (*u). */
static void bounds(plot_rect *b, plot_rect *u, const plot_axes *a, const plot_camera *cam,
                   const double box[3][2], const double (*extra)[3], int nextra)
{
    *b = (plot_rect){INFINITY, INFINITY, -INFINITY, -INFINITY};
    for (int c = 0; c < 8; c++) {
        const double p[3] = {box[0][c & 1], box[1][(c >> 1) & 1], box[2][(c >> 2) & 1]};
        double x, y;
        project(cam, p, &x, &y);
        add_point(b, x, y);
    }
    *u = *b;
    for (int i = 0; i < nextra; i++) {
        double x, y;
        project(cam, extra[i], &x, &y);
        add_point(u, x, y);
    }
    for (int ax = 0; ax < 3; ax++) {
        add_rect(u, &a->name[ax]);
        for (int k = 0; k < a->nticks[ax]; k++) {
            add_point(u, a->tick[ax][k].x1, a->tick[ax][k].y1);
            if (a->tick[ax][k].shown)
                add_rect(u, &a->tick[ax][k].label);
        }
    }
}

static int inside(const plot_rect *a, const plot_rect *area)
{
    return a->x0 >= area->x0 && a->y0 >= area->y0 && a->x1 <= area->x1 && a->y1 <= area->y1;
}

/* The rectangle f shrunk about its centre to at least MIN_FIT_PX a side. */
static void keep_size(plot_rect *f)
{
    const double cx = 0.5 * (f->x0 + f->x1), cy = 0.5 * (f->y0 + f->y1);
    if (f->x1 - f->x0 < MIN_FIT_PX)
        f->x0 = cx - 0.5 * MIN_FIT_PX, f->x1 = cx + 0.5 * MIN_FIT_PX;
    if (f->y1 - f->y0 < MIN_FIT_PX)
        f->y0 = cy - 0.5 * MIN_FIT_PX, f->y1 = cy + 0.5 * MIN_FIT_PX;
}

void ic_plot_axes_fit(plot_axes *axes, cairo_t *cr, plot_camera *cam, const double box[3][2],
                   plot_rect area, const double (*extra)[3], int nextra)
{
    /* the box goes into the area less what sticks out around it (labels in
     * pixels, which do not scale with the box); a few rounds, as the ticks
     * chosen depend on the scale */
    plot_rect f = area, b, u;
    for (int round = 0; round < FIT_ROUNDS; round++) {
        ic_plot_camera_fit(cam, box, f.x0, f.y0, f.x1 - f.x0, f.y1 - f.y0);
        ic_plot_axes_layout(axes, cr, cam, box);
        bounds(&b, &u, axes, cam, box, extra, nextra);
        if (inside(&u, &area))
            return;
        f.x0 = area.x0 + (b.x0 - u.x0) + 1, f.x1 = area.x1 - (u.x1 - b.x1) - 1;
        f.y0 = area.y0 + (b.y0 - u.y0) + 1, f.y1 = area.y1 - (u.y1 - b.y1) - 1;
        keep_size(&f);
    }
    for (int ax = 0; ax < 3; ax++) { /* what still does not fit is left out */
        axes->name_shown[ax] = inside(&axes->name[ax], &area);
        for (int k = 0; k < axes->nticks[ax]; k++)
            axes->tick[ax][k].shown &= inside(&axes->tick[ax][k].label, &area);
    }
}

void ic_plot_axes_draw(cairo_t *cr, const plot_camera *cam, const double box[3][2],
                    const plot_axes *axes)
{
    cairo_set_source_rgb(cr, 0.75, 0.75, 0.75);
    cairo_set_line_width(cr, 0.8);
    for (int e = 0; e < 12; e++) { /* edges: axis e / 4, the other two bits e % 4 */
        const int ax = e / 4, o1 = (ax + 1) % 3, o2 = (ax + 2) % 3;
        double a[3], b[3], x0, y0, x1, y1;
        a[ax] = box[ax][0], b[ax] = box[ax][1];
        a[o1] = b[o1] = box[o1][e & 1];
        a[o2] = b[o2] = box[o2][(e >> 1) & 1];
        project(cam, a, &x0, &y0);
        project(cam, b, &x1, &y1);
        cairo_move_to(cr, x0, y0);
        cairo_line_to(cr, x1, y1);
        cairo_stroke(cr);
    }
    static const char *const NAMES[3] = {"x", "y", "z"};
    cairo_set_source_rgb(cr, 0.25, 0.25, 0.25);
    cairo_set_line_width(cr, 1.0);
    for (int ax = 0; ax < 3; ax++) {
        for (int k = 0; k < axes->nticks[ax]; k++) {
            const plot_tick *t = &axes->tick[ax][k];
            cairo_move_to(cr, t->x0, t->y0);
            cairo_line_to(cr, t->x1, t->y1);
            cairo_stroke(cr);
            if (t->shown)
                ic_plot_text(cr, 0.5 * (t->label.x0 + t->label.x1), 0.5 * (t->label.y0 + t->label.y1),
                          TICK_FONT, 0, t->text, 0.5, 0.5);
        }
        const plot_rect *n = &axes->name[ax];
        if (axes->name_shown[ax])
            ic_plot_text(cr, 0.5 * (n->x0 + n->x1), 0.5 * (n->y0 + n->y1), NAME_FONT, 1, NAMES[ax],
                      0.5, 0.5);
    }
}
