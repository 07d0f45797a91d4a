/* intercurve plot: the picture of a problem (docs/plots.md). */
#include "cli.h"

#include <stdlib.h>
#include <string.h>

static const char PLOT_HELP[] =
    "usage: intercurve plot PROBLEM.json -o FIGURE.svg|.png|.pdf [--view AZ,EL] [--frames N]\n"
    "                       [--size WxH] [--mesh N] [--no-chart] [--tol T] [--depth D]\n"
    "\n"
    "Traces the intersection (as 'intercurve trace') and draws it: both surfaces as\n"
    "shaded, partly transparent meshes, the curves coloured by curvature with a colour\n"
    "bar, Frenet frames (t red, n green, b blue) along them, the singular points\n"
    "labelled by type, axes with ticks; and beside it a chart of curvature and torsion\n"
    "against arc length. The format follows the extension of FIGURE.\n"
    "\n"
    "  -o FIGURE     the picture to write (through a temporary file and a rename)\n"
    "  --view AZ,EL  azimuth and elevation of the view in degrees (default 35,25)\n"
    "  --frames N    Frenet frames drawn along the curves, 0..200 (default 8)\n"
    "  --size WxH    width and height in pixels or points (default 1400x800)\n"
    "  --mesh N      mesh cells per parameter or box axis, 4..200 (default 36)\n"
    "  --no-chart    the 3D view only\n"
    "  --tol T, --depth D  as for 'intercurve trace'\n"
    "\n"
    "example:\n"
    "  intercurve plot examples/viviani-implicit.json -o viviani.png\n"
    "  intercurve plot examples/torus-sphere.json -o torus.svg --view 20,40 --frames 12\n";

static int parse_size(ic_plot_options *o, const char *text)
{
    int w, h;
    char tail;
    if (sscanf(text, "%dx%d%c", &w, &h, &tail) != 2 || w < 200 || h < 150 || w > 10000 ||
        h > 10000) {
        fprintf(stderr, "intercurve plot: --size expects WxH, each in 200..10000 (got '%s')\n",
                text);
        return -1;
    }
    o->width = w, o->height = h;
    return 0;
}

/* Options; 0, or an exit code. `file` and `out` receive the paths. */
static int parse_args(int argc, char **argv, const char **file, const char **out,
                      ic_plot_options *po, ic_trace_options *to)
{
    for (int i = 1; i < argc; i++) {
        const int has_value = i + 1 < argc;
        if (strcmp(argv[i], "-o") == 0 && has_value)
            *out = argv[++i];
        else if (strcmp(argv[i], "--view") == 0 && has_value) {
            double v[2];
            if (ic_cli_parse_list(v, 2, argv[++i], "--view") != 2) {
                fprintf(stderr, "intercurve plot: --view expects AZIMUTH,ELEVATION in degrees\n");
                return EXIT_INPUT;
            }
            po->azimuth = v[0], po->elevation = v[1];
        } else if (strcmp(argv[i], "--frames") == 0 && has_value) {
            if (ic_cli_parse_int(&po->frames, argv[++i], 0, 200, "--frames") < 0)
                return EXIT_INPUT;
        } else if (strcmp(argv[i], "--mesh") == 0 && has_value) {
            if (ic_cli_parse_int(&po->mesh, argv[++i], 4, 200, "--mesh") < 0)
                return EXIT_INPUT;
        } else if (strcmp(argv[i], "--size") == 0 && has_value) {
            if (parse_size(po, argv[++i]) < 0)
                return EXIT_INPUT;
        } else if (strcmp(argv[i], "--no-chart") == 0) {
            po->chart = 0;
        } else if (strcmp(argv[i], "--tol") == 0 && has_value) {
            double v;
            if (ic_cli_parse_list(&v, 1, argv[++i], "--tol") != 1 || !(v > 0) || v > 1e-2) {
                fprintf(stderr, "intercurve plot: --tol expects a fraction of the problem's size in (0, 1e-2]\n");
                return EXIT_INPUT;
            }
            to->tol = v;
        } else if (strcmp(argv[i], "--depth") == 0 && has_value) {
            if (ic_cli_parse_int(&to->depth, argv[++i], 1, 9, "--depth") < 0)
                return EXIT_INPUT;
        } else if (argv[i][0] == '-' && argv[i][1] != '\0') {
            fprintf(stderr,
                    "intercurve plot: unknown option or missing value: %s\n"
                    "try 'intercurve plot --help'\n",
                    argv[i]);
            return EXIT_INPUT;
        } else if (!*file) {
            *file = argv[i];
        } else {
            fprintf(stderr, "intercurve plot: unexpected argument '%s'\n", argv[i]);
            return EXIT_INPUT;
        }
    }
    if (!*file || !*out) {
        fprintf(stderr, "intercurve plot: needs PROBLEM.json and -o FIGURE\n%s", PLOT_HELP);
        return EXIT_INPUT;
    }
    return 0;
}

int ic_cmd_plot(int argc, char **argv)
{
    for (int i = 1; i < argc; i++)
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            fputs(PLOT_HELP, stdout);
            return 0;
        }
    const char *file = NULL, *out = NULL;
    ic_plot_options po;
    ic_trace_options to;
    ic_plot_defaults(&po);
    ic_trace_defaults(&to);
    int rc = parse_args(argc, argv, &file, &out, &po, &to);
    if (rc != 0)
        return rc;
    ic_cli_traced t;
    rc = ic_cli_trace_file(file, &to, &t);
    if (rc != 0)
        return rc;
    ic_plot_scene scene;
    ic_plot_scene_of_problem(&scene, t.problem, t.res);
    ic_error err;
    const ic_status st = ic_plot_write(out, &scene, &po, &err);
    if (st != IC_OK)
        fprintf(stderr, "intercurve plot: %s\n", err.message);
    ic_cli_traced_free(&t);
    return st == IC_OK ? 0 : st == IC_ERR_INVALID ? EXIT_INPUT : EXIT_COMPUTE;
}
