/* The layout rules of the pictures (docs/plots.md), through the internal
 * functions that make them: the region drawn without a box, the length of
 * the Frenet arrows, the axes (labels inside the panel and apart, for thin
 * boxes and many views) and the chart's curve legend. */
#include <cairo.h>
#include <math.h>
#include <string.h>

#include "harness.h"
#include "intercurve.h"
#include "plot/plot_internal.h"

/* A circle of radius r about c in the plane z = c[2], n points (the first
 * four at 0, 90, 180 and 270 degrees when n is a multiple of 4). */
static ic_trace_curve circle(ic_trace_point *p, int n, const double c[3], double r)
{
    memset(p, 0, (size_t)n * sizeof *p);
    for (int i = 0; i < n; i++) {
        const double a = 2 * 3.141592653589793 * i / n;
        p[i].xyz[0] = c[0] + r * cos(a), p[i].xyz[1] = c[1] + r * sin(a), p[i].xyz[2] = c[2];
        p[i].s = r * a;
    }
    ic_trace_curve cv;
    memset(&cv, 0, sizeof cv);
    cv.npoints = n, cv.points = p, cv.closed = 1, cv.length = 2 * 3.141592653589793 * r;
    return cv;
}

/* Arrows: 8% of the box's diagonal, but at most a fifth of the diagonal of
 * the curve's bounding box (docs/plots.md, "Frenet frames"). */
static void test_arrow_length(void)
{
    enum { N = 64 };
    ic_trace_point p[N];
    const double c[3] = {0.3, 0.2, 0.105};
    /* a loop of radius 0.01 in a box of side 2 (examples/small-loop.json):
     * its bounding box has the diagonal 2 sqrt(2) r (the points at 0, 90,
     * 180, 270 degrees are on it) */
    const double r = 0.01, box_diag = 2 * sqrt(3.0);
    ic_trace_curve cv = circle(p, N, c, r);
    const double small = ic_plot_arrow_length(&cv, box_diag), extent = 2 * sqrt(2.0) * r;
    CHECK(small > 0 && small <= extent / 5 * (1 + 1e-12),
          "a loop of radius %g: arrows %g long, more than a fifth of its extent %g", r, small,
          extent);
    CHECK(small >= 0.99 * extent / 5, "a loop of radius %g: arrows %g, far below a fifth of %g", r,
          small, extent);
    /* a large circle: the box's share */
    cv = circle(p, N, c, 0.9);
    CHECK_CLOSE(ic_plot_arrow_length(&cv, box_diag), 0.08 * box_diag, 1e-12,
                "arrows on a curve as large as the box");
}

/* A scene of the cylinder (x - 1)^2 + y^2 = 1, |z| <= 3, given
 * parametrically, and the implicit surface `implicit`, without a box. */
static int region_of(double box[3][2], const char *implicit)
{
    const char *xyz[3] = {"1 + sin(v)", "cos(v)", "u"};
    const double dom[2][2] = {{-3, 3}, {0, 2 * 3.141592653589793}};
    const int periodic[2] = {0, 1};
    ic_surface *cyl = NULL, *imp = NULL;
    ic_error err;
    int ok = ic_surface_new_parametric(&cyl, xyz, NULL, NULL, 0, NULL, &err) == IC_OK &&
             ic_surface_set_domain(cyl, dom, periodic, &err) == IC_OK &&
             ic_surface_new_implicit(&imp, implicit, NULL, 0, &err) == IC_OK;
    plot_mesh mesh = {NULL, 0, 0};
    if (ok) {
        ic_plot_scene scene;
        memset(&scene, 0, sizeof scene);
        scene.nsurfaces = 2;
        scene.surfaces[0] = cyl, scene.surfaces[1] = imp;
        ok = ic_plot_mesh_surface(&mesh, cyl, 0, NULL, 36, &err) == IC_OK &&
             ic_plot_region(box, &scene, &mesh, 18, &err) == IC_OK;
    }
    CHECK(ok, "region with %s: %s", implicit, err.message);
    free(mesh.t);
    ic_surface_free(cyl);
    ic_surface_free(imp);
    return ok;
}

/* The region drawn without a box (docs/plots.md, "The region drawn"). */
static void test_region(void)
{
    double box[3][2];
    /* the README's problem: the sphere of radius 2 closes within reach, so
     * it is drawn whole: the box holds [-2, 2]^3 and the cylinder's
     * [0, 2] x [-1, 1] x [-3, 3], with a margin of 5% of the largest side
     * (6): 0.3, give or take the sphere mesh's interpolation (a tenth) */
    if (region_of(box, "x^2 + y^2 + z^2 - 4")) {
        const double want[3][2] = {{-2.3, 2.3}, {-2.3, 2.3}, {-3.3, 3.3}};
        for (int k = 0; k < 3; k++)
            for (int e = 0; e < 2; e++)
                CHECK_ABS(box[k][e], want[k][e], 0.1, "sphere and cylinder: the region's bound");
    }
    /* a plane is unbounded: it does not stretch x and y beyond the
     * cylinder; z = 3.5 lies beyond the cylinder's top and is taken in */
    if (region_of(box, "z - 3.5")) {
        const double want[3][2] = {{-0.325, 2.325}, {-1.325, 1.325}, {-3.325, 3.825}};
        for (int k = 0; k < 3; k++)
            for (int e = 0; e < 2; e++)
                CHECK_ABS(box[k][e], want[k][e], 0.05, "plane z = 3.5 and cylinder: the bound");
    }
}

/* Whether a label of axis ax lies across the box's edge its ticks are on
 * (the ticks start on it: their marks' first ends). */
static int label_on_edge(const plot_axes *a, int ax, const plot_rect *r)
{
    const int n = a->nticks[ax];
    if (n < 2)
        return 0;
    const plot_tick *t0 = &a->tick[ax][0], *t1 = &a->tick[ax][n - 1];
    /* the line through the ticks' feet, sampled beyond them by a tick gap */
    enum { SAMPLES = 400 };
    for (int i = 0; i <= SAMPLES; i++) {
        const double u = -0.5 + 2.0 * i / SAMPLES;
        const double x = t0->x0 + u * (t1->x0 - t0->x0), y = t0->y0 + u * (t1->y0 - t0->y0);
        if (x > r->x0 && x < r->x1 && y > r->y0 && y < r->y1)
            return 1;
    }
    return 0;
}

/* Everything the axes show, inside the area and apart from each other. */
static void check_axes(const plot_axes *a, const plot_rect *area, const char *what)
{
    plot_rect shown[3 + 3 * PLOT_AXIS_TICKS];
    int n = 0;
    for (int ax = 0; ax < 3; ax++) {
        if (a->name_shown[ax])
            shown[n++] = a->name[ax];
        for (int k = 0; k < a->nticks[ax]; k++)
            if (a->tick[ax][k].shown)
                shown[n++] = a->tick[ax][k].label;
    }
    int outside = 0, overlapping = 0;
    for (int i = 0; i < n; i++) {
        outside += shown[i].x0 < area->x0 || shown[i].x1 > area->x1 || shown[i].y0 < area->y0 ||
                   shown[i].y1 > area->y1;
        for (int j = 0; j < i; j++)
            overlapping += shown[i].x0 < shown[j].x1 && shown[j].x0 < shown[i].x1 &&
                           shown[i].y0 < shown[j].y1 && shown[j].y0 < shown[i].y1;
    }
    /* the ticks of an axis are chosen so that their labels do not run
     * together: none of them is dropped for a neighbour on the same axis */
    int crowded = 0;
    for (int ax = 0; ax < 3; ax++)
        for (int k = 1; k < a->nticks[ax]; k++) {
            const plot_rect *p = &a->tick[ax][k - 1].label, *q = &a->tick[ax][k].label;
            crowded += p->x0 < q->x1 && q->x0 < p->x1 && p->y0 < q->y1 && q->y0 < p->y1;
        }
    CHECK(crowded == 0, "%s: %d neighbouring labels of an axis overlap", what, crowded);
    int across = 0;
    for (int ax = 0; ax < 3; ax++)
        for (int k = 0; k < a->nticks[ax]; k++)
            across += a->tick[ax][k].shown && label_on_edge(a, ax, &a->tick[ax][k].label);
    CHECK(across == 0, "%s: %d labels lie across their own axis", what, across);
    CHECK(outside == 0, "%s: %d labels outside the panel", what, outside);
    CHECK(overlapping == 0, "%s: %d pairs of labels overlap", what, overlapping);
}

/* The projected length of the box's edge along axis ax through corner 0. */
static double edge_px(const plot_camera *cam, const double box[3][2], int ax)
{
    double a[3] = {box[0][0], box[1][0], box[2][0]}, b[3], xa, ya, xb, yb;
    memcpy(b, a, sizeof b);
    b[ax] = box[ax][1];
    ic_plot_camera_project(cam, a, &xa, &ya, NULL);
    ic_plot_camera_project(cam, b, &xb, &yb, NULL);
    return hypot(xb - xa, yb - ya);
}

/* Boxes of every shape seen from every side: the labels stay inside the
 * panel and apart, the box too, and an axis long on the screen keeps at
 * least two labels. */
static void test_axes(cairo_t *cr)
{
    static const double BOXES[][3][2] = {
        {{-1, 1}, {-1, 1}, {-1, 1}},                     /* a cube */
        {{-0.01, 0.01}, {-1.5, 1.5}, {-1.5, 1.5}},       /* thin in x */
        {{-1.5, 1.5}, {-1.5, 1.5}, {-0.01, 0.01}},       /* thin in z */
        {{-3.5, 3.5}, {-3.5, 3.5}, {-1.5, 1.5}},         /* examples/torus-sphere.json */
        {{0, 1e-4}, {1000, 1001}, {-50, 50}},            /* three scales */
        {{0.00101, 0.00109}, {12345, 12346}, {-1, 1}},   /* long labels */
        {{-0.0012345, -0.001234}, {0, 5e-7}, {0, 5e-7}}, /* longer labels */
    };
    const plot_rect area = {8, 48, 858 - 110, 800 - 36};
    int cases = 0, long_axes = 0;
    for (size_t b = 0; b < sizeof BOXES / sizeof BOXES[0]; b++)
        for (int az = 0; az < 360; az += 20)
            for (int el = -80; el <= 90; el += 10) {
                plot_camera cam;
                plot_axes axes;
                ic_plot_camera_init(&cam, az, el);
                ic_plot_axes_fit(&axes, cr, &cam, BOXES[b], area, NULL, 0);
                char what[96];
                snprintf(what, sizeof what, "box %zu, view %d,%d", b, az, el);
                check_axes(&axes, &area, what);
                for (int c = 0; c < 8; c++) {
                    const double p[3] = {BOXES[b][0][c & 1], BOXES[b][1][(c >> 1) & 1],
                                         BOXES[b][2][(c >> 2) & 1]};
                    double x, y;
                    ic_plot_camera_project(&cam, p, &x, &y, NULL);
                    CHECK(x >= area.x0 - 1e-9 && x <= area.x1 + 1e-9 && y >= area.y0 - 1e-9 &&
                              y <= area.y1 + 1e-9,
                          "%s: a corner of the box at (%g, %g), outside the panel", what, x, y);
                }
                for (int ax = 0; ax < 3; ax++) {
                    if (edge_px(&cam, BOXES[b], ax) < 300)
                        continue;
                    int shown = 0;
                    for (int k = 0; k < axes.nticks[ax]; k++)
                        shown += axes.tick[ax][k].shown;
                    long_axes++;
                    CHECK(shown >= 2, "%s: axis %c, %.0f px long, has %d labels", what, 'x' + ax,
                          edge_px(&cam, BOXES[b], ax), shown);
                }
                cases++;
            }
    /* a panel too small for the labels: what is shown is still inside it */
    const plot_rect tiny = {100, 100, 140, 130};
    for (int az = 0; az < 360; az += 45) {
        plot_camera cam;
        plot_axes axes;
        ic_plot_camera_init(&cam, az, 25);
        ic_plot_axes_fit(&axes, cr, &cam, BOXES[0], tiny, NULL, 0);
        check_axes(&axes, &tiny, "a panel of 40 x 30 px");
    }
    CHECK(cases > 1000 && long_axes > 1000, "axes: %d views, %d long axes checked", cases,
          long_axes);
}

/* The chart's curve legend: at most six entries (the palette), fewer
 * where they do not fit, none where not even one does. */
static void test_legend(cairo_t *cr)
{
    CHECK(ic_plot_legend_entries(cr, 3, 1000) == 3, "three curves, wide: all three");
    CHECK(ic_plot_legend_entries(cr, 18, 1000) == 6, "18 curves, wide: six, one per colour");
    const int narrow = ic_plot_legend_entries(cr, 18, 250);
    CHECK(narrow >= 1 && narrow < 6, "18 curves in 250 px: %d entries", narrow);
    CHECK(ic_plot_legend_entries(cr, 18, 20) == 0, "18 curves in 20 px: no entry");
}

int main(void)
{
    cairo_surface_t *surf = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 16, 16);
    cairo_t *cr = cairo_create(surf);
    test_arrow_length();
    test_region();
    test_axes(cr);
    test_legend(cr);
    cairo_destroy(cr);
    cairo_surface_destroy(surf);
    return harness_finish("test_plot_layout");
}
