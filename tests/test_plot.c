/* Pictures (issue 6's tests): every bundled example plots without error to
 * SVG, PNG and PDF; the SVG parses as XML (libxml2) and holds one curve path
 * per curve segment and one arrow shaft per frame vector; the PNG has the
 * size asked for and is not blank; a problem with no intersection draws its
 * surfaces and no curve. */
#include <cairo.h>
#include <libxml/parser.h>
#include <libxml/tree.h>
#include <stdio.h>
#include <string.h>

#include "harness.h"
#include "intercurve.h"
#include "traced_example.h"

static const char *const EXAMPLES[] = {"viviani-implicit.json",
                                       "viviani.json",
                                       "ellipsoids.json",
                                       "enneper-self.json",
                                       "paraboloid-cubic.json",
                                       "sphere-cylinder-branch.json",
                                       "cusp.json",
                                       "torus-plane-tangential.json",
                                       "sphere-plane-contact.json",
                                       "torus-sphere.json",
                                       "cylinders.json",
                                       "cylinders-equal.json",
                                       "small-loop.json",
                                       "tacnode.json",
                                       "primitives.json"};

enum { WIDTH = 900, HEIGHT = 600, FRAMES = 5 };

/* Paths of the SVG whose style has the stroke width (the plot draws curve
 * segments with 3.5 and arrow shafts with 2.25, nothing else with those). */
static void count_paths(xmlNode *n, int *curves, int *arrows)
{
    for (; n; n = n->next) {
        if (n->type == XML_ELEMENT_NODE && strcmp((const char *)n->name, "path") == 0) {
            xmlChar *style = xmlGetProp(n, (const xmlChar *)"style");
            if (style) {
                *curves += strstr((const char *)style, "stroke-width:3.5;") != NULL;
                *arrows += strstr((const char *)style, "stroke-width:2.25;") != NULL;
                xmlFree(style);
            }
        }
        count_paths(n->children, curves, arrows);
    }
}

/* Pixel statistics of the PNG: size, the share of pixels that are not
 * white, and whether some are close to the colour rgb (0..255). */
static void check_png(const char *path, const char *name, const int rgb[3], int want_color)
{
    cairo_surface_t *s = cairo_image_surface_create_from_png(path);
    if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS) {
        CHECK(0, "%s: the PNG does not load", name);
        cairo_surface_destroy(s);
        return;
    }
    const int w = cairo_image_surface_get_width(s), h = cairo_image_surface_get_height(s);
    CHECK(w == WIDTH && h == HEIGHT, "%s: PNG of %d x %d, not %d x %d", name, w, h, WIDTH, HEIGHT);
    cairo_surface_flush(s);
    const unsigned char *data = cairo_image_surface_get_data(s);
    const int stride = cairo_image_surface_get_stride(s);
    long inked = 0, colored = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            const unsigned char *p = data + (size_t)y * stride + 4 * (size_t)x; /* B G R A */
            if (p[0] < 235 || p[1] < 235 || p[2] < 235)
                inked++;
            if (abs(p[2] - rgb[0]) < 20 && abs(p[1] - rgb[1]) < 20 && abs(p[0] - rgb[2]) < 20)
                colored++;
        }
    /* the surfaces alone cover far more than 3% of the picture */
    CHECK(inked > 0.03 * w * h, "%s: only %ld of %d pixels drawn", name, inked, w * h);
    if (want_color)
        CHECK(colored > 10, "%s: no pixel of the colour (%d, %d, %d)", name, rgb[0], rgb[1],
              rgb[2]);
    cairo_surface_destroy(s);
}

static void plot_example(const char *dir, const char *tmpdir, const char *name)
{
    traced t;
    if (trace_example(&t, dir, name) != 0) {
        release(&t);
        return;
    }
    ic_plot_scene scene;
    ic_plot_scene_of_problem(&scene, t.problem, t.res);
    ic_plot_options opt;
    ic_plot_defaults(&opt);
    opt.width = WIDTH, opt.height = HEIGHT, opt.frames = FRAMES;
    /* what the figure must hold, from the trace */
    int segments = 0, framed = 1;
    for (int c = 0; c < ic_trace_result_num_curves(t.res); c++) {
        const ic_trace_curve *cv = ic_trace_result_curve(t.res, c);
        segments += cv->npoints - 1;
        for (int k = 0; k < cv->npoints; k++)
            framed &= cv->points[k].frame_defined;
    }
    const int ncurves = ic_trace_result_num_curves(t.res);
    static const char *const EXT[3] = {"svg", "png", "pdf"};
    for (int f = 0; f < 3; f++) {
        char path[512];
        snprintf(path, sizeof path, "%s/%s.%s", tmpdir, name, EXT[f]);
        ic_error err;
        const ic_status st = ic_plot_write(path, &scene, &opt, &err);
        CHECK(st == IC_OK, "%s: plot to %s: %s", name, EXT[f], err.message);
        if (st != IC_OK)
            continue;
        if (f == 0) {
            xmlDoc *doc = xmlReadFile(path, NULL, XML_PARSE_NONET | XML_PARSE_HUGE);
            CHECK(doc != NULL, "%s: the SVG is not well-formed XML", name);
            if (!doc)
                continue;
            int curves = 0, arrows = 0;
            count_paths(xmlDocGetRootElement(doc), &curves, &arrows);
            CHECK(curves == segments, "%s: %d curve paths, the trace has %d segments", name, curves,
                  segments);
            /* FRAMES frames of three arrows (t only where kappa = 0) */
            const int want = ncurves == 0 ? 0 : framed ? 3 * FRAMES : -1;
            CHECK(want < 0 ? arrows >= FRAMES && arrows <= 3 * FRAMES : arrows == want,
                  "%s: %d frame arrows, not %d", name, arrows, want);
            xmlFreeDoc(doc);
        } else if (f == 1) {
            static const int RED[3] = {214, 39, 40}; /* t arrows: ic_plot_rgb_t */
            check_png(path, name, RED, ncurves > 0);
        } else {
            FILE *fp = fopen(path, "rb");
            char head[5] = {0};
            CHECK(fp && fread(head, 1, 4, fp) == 4 && memcmp(head, "%PDF", 4) == 0,
                  "%s: the PDF starts with %%PDF", name);
            if (fp)
                fclose(fp);
        }
    }
    release(&t);
}

/* Two spheres apart: no curve, no point; the surfaces are drawn, and the
 * message in the no-intersection colour (0.6, 0.1, 0.1). */
static void test_no_intersection(const char *tmpdir)
{
    ic_surface *A = NULL, *B = NULL;
    ic_pair *pair = NULL;
    ic_trace_result *res = NULL;
    ic_trace_options to;
    ic_trace_defaults(&to);
    to.has_box = 1;
    for (int k = 0; k < 3; k++)
        to.box[k][0] = -2, to.box[k][1] = 2;
    to.box[0][1] = 4;
    if (ic_surface_new_implicit(&A, "x^2 + y^2 + z^2 - 1", NULL, 0, NULL) != IC_OK ||
        ic_surface_new_implicit(&B, "(x - 2.5)^2 + y^2 + z^2 - 1", NULL, 0, NULL) != IC_OK ||
        ic_pair_new(&pair, A, B, NULL) != IC_OK || ic_trace(&res, pair, &to, NULL) != IC_OK) {
        CHECK(0, "two spheres apart: trace");
    } else {
        CHECK(ic_trace_result_num_curves(res) == 0 && ic_trace_result_num_specials(res) == 0,
              "two spheres apart: nothing traced");
        ic_plot_scene scene;
        memset(&scene, 0, sizeof scene);
        scene.title = "Two spheres apart";
        scene.has_box = 1;
        memcpy(scene.box, to.box, sizeof scene.box);
        scene.nsurfaces = 2;
        scene.surfaces[0] = A, scene.surfaces[1] = B;
        scene.names[0] = "left", scene.names[1] = "right";
        scene.trace = res;
        ic_plot_options opt;
        ic_plot_defaults(&opt);
        opt.width = WIDTH, opt.height = HEIGHT;
        char path[512];
        snprintf(path, sizeof path, "%s/apart.png", tmpdir);
        CHECK(ic_plot_write(path, &scene, &opt, NULL) == IC_OK, "two spheres apart: plot");
        static const int MESSAGE[3] = {153, 26, 26};
        check_png(path, "two spheres apart", MESSAGE, 1);
    }
    ic_trace_result_free(res);
    ic_pair_free(pair);
    ic_surface_free(A);
    ic_surface_free(B);
}

/* No ink within MARGIN_PX of the PNG's left and right edges: nothing was
 * drawn across them (a label or legend clipped by the picture's edge). */
enum { MARGIN_PX = 4 };
static void check_margins(const char *path, const char *name)
{
    cairo_surface_t *s = cairo_image_surface_create_from_png(path);
    if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS) {
        CHECK(0, "%s: the PNG does not load", name);
        cairo_surface_destroy(s);
        return;
    }
    cairo_surface_flush(s);
    const int w = cairo_image_surface_get_width(s), h = cairo_image_surface_get_height(s);
    const unsigned char *data = cairo_image_surface_get_data(s);
    const int stride = cairo_image_surface_get_stride(s);
    int left = 0, right = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < MARGIN_PX; x++) {
            const unsigned char *p = data + (size_t)y * stride + 4 * (size_t)x;
            const unsigned char *q = data + (size_t)y * stride + 4 * (size_t)(w - 1 - x);
            left += p[0] < 235 || p[1] < 235 || p[2] < 235;
            right += q[0] < 235 || q[1] < 235 || q[2] < 235;
        }
    CHECK(left == 0 && right == 0, "%s: %d pixels drawn in the left margin, %d in the right", name,
          left, right);
    cairo_surface_destroy(s);
}

/* Two implicit surfaces in a box, both called surface_name, traced and
 * drawn from the view az, el into tmpdir/name.png at the default size; the
 * margins checked. */
static void plot_margins(const char *tmpdir, const char *name, const char *fa, const char *fb,
                         const double box[3][2], double az, double el, const char *surface_name)
{
    ic_surface *A = NULL, *B = NULL;
    ic_pair *pair = NULL;
    ic_trace_result *res = NULL;
    ic_trace_options to;
    ic_trace_defaults(&to);
    to.has_box = 1;
    memcpy(to.box, box, sizeof to.box);
    ic_error err;
    if (ic_surface_new_implicit(&A, fa, NULL, 0, &err) != IC_OK ||
        ic_surface_new_implicit(&B, fb, NULL, 0, &err) != IC_OK ||
        ic_pair_new(&pair, A, B, &err) != IC_OK || ic_trace(&res, pair, &to, &err) != IC_OK) {
        CHECK(0, "%s: trace: %s", name, err.message);
    } else {
        ic_plot_scene scene;
        memset(&scene, 0, sizeof scene);
        scene.title = name;
        scene.has_box = 1;
        memcpy(scene.box, box, sizeof scene.box);
        scene.nsurfaces = 2;
        scene.surfaces[0] = A, scene.surfaces[1] = B;
        scene.names[0] = scene.names[1] = surface_name;
        scene.trace = res;
        ic_plot_options opt;
        ic_plot_defaults(&opt);
        opt.azimuth = az, opt.elevation = el; /* the default size, 1400 x 800 */
        char path[512];
        snprintf(path, sizeof path, "%s/%s.png", tmpdir, name);
        CHECK(ic_plot_write(path, &scene, &opt, &err) == IC_OK, "%s: plot: %s", name, err.message);
        check_margins(path, name);
    }
    ic_trace_result_free(res);
    ic_pair_free(pair);
    ic_surface_free(A);
    ic_surface_free(B);
}

/* Pictures whose labels or legend ran across the picture's edge (issue 11):
 * the torus and sphere seen from 20, 40 (z labels at the left edge), thin
 * boxes (their labels at the left edge), eighteen curves (the chart's
 * legend across the right edge) on surfaces with long names (the 3D
 * legend). */
static void test_margins(const char *tmpdir)
{
    const double torus_box[3][2] = {{-3.5, 3.5}, {-3.5, 3.5}, {-1.5, 1.5}};
    plot_margins(tmpdir, "torus-sphere-20-40", "(x^2 + y^2 + z^2 + 3)^2 - 16*(x^2 + y^2)",
                 "x^2 + y^2 + z^2 - 1", torus_box, 20, 40, "torus");
    const double thin_z[3][2] = {{-1.5, 1.5}, {-1.5, 1.5}, {-0.01, 0.01}};
    plot_margins(tmpdir, "thin-z", "x^2 + y^2 + z^2 - 1", "z - 0.001", thin_z, 35, 25, "sphere");
    const double thin_x[3][2] = {{-0.01, 0.01}, {-1.5, 1.5}, {-1.5, 1.5}};
    plot_margins(tmpdir, "thin-x", "x^2 + y^2 + z^2 - 1", "x - 0.001", thin_x, 35, 25, "sphere");
    const double egg_box[3][2] = {{-4, 4}, {-4, 4}, {-1, 1}};
    /* and names that make the 3D legend longer than the picture is wide */
    plot_margins(tmpdir, "eighteen-loops", "z", "z - sin(2*x)*sin(2*y) + 0.5", egg_box, 35, 25,
                 "a surface whose name is long enough that the legend with two of it and "
                 "the frame colours would run wider than the picture, 1400 pixels");
}

/* Bad requests: an unknown extension, a size out of range, a directory
 * that does not exist (IC_ERR_IO, and no file left behind). */
static void test_errors(const char *tmpdir)
{
    ic_plot_scene scene;
    memset(&scene, 0, sizeof scene);
    ic_surface *A = NULL;
    CHECK(ic_surface_new_implicit(&A, "x^2 + y^2 + z^2 - 1", NULL, 0, NULL) == IC_OK, "sphere");
    scene.surfaces[0] = A;
    scene.nsurfaces = 1;
    scene.has_box = 1;
    for (int k = 0; k < 3; k++)
        scene.box[k][0] = -1.5, scene.box[k][1] = 1.5;
    ic_plot_options opt;
    ic_plot_defaults(&opt);
    ic_error err;
    char path[512];
    snprintf(path, sizeof path, "%s/figure.gif", tmpdir);
    CHECK(ic_plot_write(path, &scene, &opt, &err) == IC_ERR_INVALID &&
              strstr(err.message, ".svg, .png, .pdf or .html"),
          "unknown extension: %s", err.message);
    opt.width = 50;
    snprintf(path, sizeof path, "%s/small.png", tmpdir);
    CHECK(ic_plot_write(path, &scene, &opt, &err) == IC_ERR_INVALID, "too small: %s", err.message);
    ic_plot_defaults(&opt);
    snprintf(path, sizeof path, "%s/no/such/dir/figure.png", tmpdir);
    CHECK(ic_plot_write(path, &scene, &opt, &err) == IC_ERR_IO, "unwritable: %s", err.message);
    /* surfaces alone (no trace): drawn, no chart */
    snprintf(path, sizeof path, "%s/sphere.svg", tmpdir);
    CHECK(ic_plot_write(path, &scene, &opt, &err) == IC_OK, "surface only: %s", err.message);
    ic_surface_free(A);
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : ".";
    const char *tmpdir = argc > 2 ? argv[2] : ".";
    for (size_t i = 0; i < sizeof EXAMPLES / sizeof EXAMPLES[0]; i++)
        plot_example(dir, tmpdir, EXAMPLES[i]);
    test_no_intersection(tmpdir);
    test_margins(tmpdir);
    test_errors(tmpdir);
    xmlCleanupParser();
    return harness_finish("test_plot");
}
