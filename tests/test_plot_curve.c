/* The curves of the pictures as smooth paths (src/plot/plot_curve.c,
 * docs/plots.md): a circle and an ellipse, traced finely and coarsely,
 * drawn from above with a known camera. Every cubic piece of the path,
 * mapped back into the plane, lies on the true curve: within 1.8e-5 a^6 of
 * the circle's radius for a stretch turning by a (one cubic per stretch
 * without the B-spline), and within the fit tolerance of both with the
 * B-spline (pieces from it), where the chords between the traced points
 * are far off. */
#include "harness.h"

#include <math.h>
#include <string.h>

#include "plot/plot_internal.h"
#include "traced_example.h"

/* the circle of tests/data/periodic-plane-sphere.json: the unit sphere
 * cut by z = 0.6; the ellipse of tests/data/plane-elliptic-cylinder.json,
 * x^2/4 + y^2 = 1 in z = 0 */
#define RADIUS 0.8
#define SEMI_A 2.0
/* relative to the size: with the B-spline, the cubic pieces' ends are the
 * B-spline's, within the fit tolerance the trace's report gives, and the
 * pieces are to stay this close to the curve between them: 100 times
 * finer than cairo keeps a path (1/256 of a unit, 3e-6 of a picture 1400
 * units wide) */
#define CUBIC_FIT_PIECE 3e-8
/* without the B-spline: one cubic per traced stretch, turning by the
 * stretch's angle a, is within 1.8e-5 a^6 of the radius (the cubic's
 * handles are the arc's), checked per stretch with a factor 2 of margin */
#define CUBIC_ARC_COEFF (2 * 1.8e-5)
/* relative to the radius: the rounding of screen coordinates ~1e3 scaled
 * back and of hypot, a few tens of ulps */
#define SCREEN_ROUNDING 1e-14
enum { SCALE = 1000, PROBES = 8 };

static double cubic_at(const double *b, int j, double u)
{
    const double v = 1 - u;
    return v * v * v * b[j] + 3 * v * v * u * b[2 + j] + 3 * v * u * u * b[4 + j] +
           u * u * u * b[6 + j];
}

/* The distance of (x, y) from the circle (relative to its radius) or the
 * ellipse (first order, |f| / |grad f|, relative to the semi-axis 1). */
static double off_curve(int ellipse, double x, double y)
{
    if (!ellipse)
        return fabs(hypot(x, y) - RADIUS) / RADIUS;
    return fabs(x * x / (SEMI_A * SEMI_A) + y * y - 1) /
           hypot(2 * x / (SEMI_A * SEMI_A), 2 * y);
}

/* The largest distance from the curve of n cubic pieces; *gaps counts
 * pieces that do not start where the last ended. */
static double pieces_off(int ellipse, double (*b)[8], int n, int *gaps)
{
    double worst = 0;
    for (int i = 0; i < n; i++) {
        *gaps += i > 0 && (b[i][0] != b[i - 1][6] || b[i][1] != b[i - 1][7]);
        for (int k = 0; k <= PROBES; k++) {
            const double u = (double)k / PROBES;
            /* the camera below: screen (x, y) = SCALE (x, -y) */
            const double x = cubic_at(b[i], 0, u) / SCALE, y = -cubic_at(b[i], 1, u) / SCALE;
            worst = fmax(worst, off_curve(ellipse, x, y));
        }
    }
    return worst;
}

/* cairo's path of one stretch: a move_to and n curve_to's */
static int cairo_path_ok(cairo_t *cr, const plot_camera *cam, const traced *t, int k, int n)
{
    cairo_new_path(cr);
    ic_plot_curve_path(cr, cam, t->res, 0, k);
    cairo_path_t *path = cairo_copy_path(cr);
    int moves = 0, curves = 0, other = 0;
    for (int i = 0; i < path->num_data; i += path->data[i].header.length) {
        const cairo_path_data_type_t type = path->data[i].header.type;
        moves += type == CAIRO_PATH_MOVE_TO, curves += type == CAIRO_PATH_CURVE_TO;
        other += type != CAIRO_PATH_MOVE_TO && type != CAIRO_PATH_CURVE_TO;
    }
    cairo_path_destroy(path);
    return moves == 1 && curves == n && other == 0;
}

static void check_paths(const traced *t, int ellipse, int fitted)
{
    const plot_camera cam = {.right = {1, 0, 0}, .up = {0, 1, 0}, .toward = {0, 0, 1},
                             .scale = SCALE};
    cairo_surface_t *surf = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 16, 16);
    cairo_t *cr = cairo_create(surf);
    const ic_trace_curve *c = ic_trace_result_curve(t->res, 0);
    double worst = 0, worst_bound = 0, worst_chord = 0, b[PLOT_MAX_PIECES][8];
    int pieces = 0, gaps = 0, over = 0, bad_paths = 0;
    for (int k = 0; k + 1 < c->npoints; k++) {
        const int n = ic_plot_curve_pieces(&cam, t->res, 0, k, b);
        const double off = pieces_off(ellipse, b, n, &gaps);
        pieces += n;
        bad_paths += !cairo_path_ok(cr, &cam, t, k, n);
        const double a = (c->points[k + 1].s - c->points[k].s) / RADIUS;
        const double bound = CUBIC_ARC_COEFF * pow(a, 6);
        over += !ellipse && !fitted && off > bound + SCREEN_ROUNDING;
        worst = fmax(worst, off);
        worst_bound = fmax(worst_bound, bound);
        worst_chord = fmax(worst_chord, 1 - cos(a / 2)); /* a chord's sagitta over r */
    }
    cairo_destroy(cr);
    cairo_surface_destroy(surf);
    const char *name = fitted ? "B-spline" : "traced points";
    CHECK(gaps == 0 && bad_paths == 0 && pieces >= c->npoints - 1,
          "%s: joined cubic pieces, drawn as such (%d for %d stretches, %d gaps, %d paths wrong)",
          name, pieces, c->npoints - 1, gaps, bad_paths);
    const double fit_bound = ic_trace_result_report(t->res)->fit_tol / (ellipse ? 1 : RADIUS) +
                             CUBIC_FIT_PIECE;
    if (fitted)
        CHECK(worst <= fit_bound, "B-spline: the drawn curve is %g of the radius off (bound %g)",
              worst, fit_bound);
    else if (!ellipse)
        CHECK(over == 0, "traced points: %d stretches beyond 1.8e-5 a^6 (worst %g, bound %g)",
              over, worst, worst_bound);
    printf("%-14s %d pieces for %d stretches, off the curve %.2g (chords: %.2g; bound %.2g)\n",
           name, pieces, c->npoints - 1, worst, worst_chord, fitted ? fit_bound : worst_bound);
}

/* The circle or the ellipse traced with the default steps, or coarsely
 * (chord heights of 1e-2, steps up to 0.2: stretches turning up to 0.25
 * rad). */
static int trace_curve(traced *t, const char *dir, int ellipse, int coarse)
{
    char path[600];
    snprintf(path, sizeof path, "%s/tests/data/%s", dir,
             ellipse ? "plane-elliptic-cylinder.json" : "periodic-plane-sphere.json");
    ic_trace_options opt = coarse_trace_options();
    if (!coarse)
        ic_trace_defaults(&opt);
    return trace_file_with(t, path, opt) == 0 &&
           REQUIRE(ic_trace_result_num_curves(t->res) == 1, "%s: one curve", path);
}

int main(int argc, char **argv)
{
    if (!REQUIRE(argc > 1, "usage: test_plot_curve SOURCE_DIR"))
        return harness_finish("plot_curve");
    for (int ellipse = 0; ellipse < 2; ellipse++)
        for (int coarse = 0; coarse < 2; coarse++) {
            traced t;
            printf("%s, %s trace:\n", ellipse ? "ellipse" : "circle", coarse ? "coarse" : "default");
            if (trace_curve(&t, argv[1], ellipse, coarse)) {
                check_paths(&t, ellipse, 0);
                ic_error err;
                if (REQUIRE(ic_trace_fit(t.res, t.pair, 1e-9, &err) == IC_OK, "fit: %s",
                            err.message))
                    check_paths(&t, ellipse, 1);
            }
            release(&t);
        }
    return harness_finish("plot_curve");
}
