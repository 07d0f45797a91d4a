/* intercurve plot: the picture of a problem (docs/plots.md). */
#include "cli/cli.h"
#include "cli/trace_options.h"

enum {
    OPT_OUTPUT,
    OPT_VIEW,
    OPT_FRAMES,
    OPT_SIZE,
    OPT_MESH,
    OPT_NO_CHART,
    OPT_TOL,
    OPT_DEPTH,
    OPT_NO_EXACT,
    OPT_THREADS,
    NOPTIONS
};

static const ic_cli_option PLOT_OPTIONS[NOPTIONS] = {
    [OPT_OUTPUT] = {.name = "-o",
                    .metavar = "FIGURE",
                    .kind = IC_OPT_TEXT,
                    .need = IC_OPT_REQUIRED,
                    .help = "the picture to write, .svg, .png or .pdf, or .html for the\n"
                            "interactive page (through a temporary file and a rename)"},
    [OPT_VIEW] = {.name = "--view",
                  .metavar = "AZ,EL",
                  .kind = IC_OPT_LIST,
                  .lo = 2,
                  .hi = 2,
                  .fallback = IC_CLI_TEXT_OF(IC_PLOT_AZIMUTH_DEFAULT) "," IC_CLI_TEXT_OF(
                      IC_PLOT_ELEVATION_DEFAULT),
                  .help = "azimuth and elevation of the view in degrees"},
    [OPT_FRAMES] = {.name = "--frames",
                    .metavar = "N",
                    .kind = IC_OPT_INT,
                    .lo = 0,
                    .hi = IC_PLOT_FRAMES_MAX,
                    .fallback = IC_CLI_TEXT_OF(IC_PLOT_FRAMES_DEFAULT),
                    .help = "Frenet frames drawn along the curves"},
    [OPT_SIZE] = {.name = "--size",
                  .metavar = "WxH",
                  .kind = IC_OPT_SIZE,
                  .lo = IC_PLOT_WIDTH_MIN,
                  .hi = IC_PLOT_SIZE_MAX,
                  .lo2 = IC_PLOT_HEIGHT_MIN,
                  .fallback = IC_CLI_TEXT_OF(IC_PLOT_WIDTH_DEFAULT) "x" IC_CLI_TEXT_OF(
                      IC_PLOT_HEIGHT_DEFAULT),
                  .help = "width and height in pixels (PNG) or points (SVG, PDF); the page\n"
                          "fills its window"},
    [OPT_MESH] = {.name = "--mesh",
                  .metavar = "N",
                  .kind = IC_OPT_INT,
                  .lo = IC_PLOT_MESH_MIN,
                  .hi = IC_PLOT_MESH_MAX,
                  .fallback = IC_CLI_TEXT_OF(IC_PLOT_MESH_DEFAULT),
                  .help = "mesh cells per parameter or box axis"},
    [OPT_NO_CHART] = {.name = "--no-chart", .kind = IC_OPT_FLAG, .help = "the 3D view only"},
    [OPT_TOL] = IC_CLI_OPTION_TOL("as for 'intercurve trace'"),
    [OPT_DEPTH] = IC_CLI_OPTION_DEPTH("as for 'intercurve trace'"),
    [OPT_NO_EXACT] = IC_CLI_OPTION_NO_EXACT("as for 'intercurve trace'"),
    [OPT_THREADS] = IC_CLI_OPTION_THREADS("as for 'intercurve trace'"),
};

static const ic_cli_command PLOT = {
    .name = "plot",
    .summary = "Traces the intersection (as 'intercurve trace') and draws it: both surfaces as\n"
               "shaded, partly transparent meshes, the curves coloured by curvature with a colour\n"
               "bar, Frenet frames (t red, n green, b blue) along them, the singular points\n"
               "labelled by type, axes with ticks; and beside it a chart of curvature and torsion\n"
               "against arc length. The format follows the extension of FIGURE.",
    .options = PLOT_OPTIONS,
    .noptions = NOPTIONS,
    .notes = "example:\n"
             "  intercurve plot examples/viviani-implicit.json -o viviani.png\n"
             "  intercurve plot examples/torus-sphere.json -o torus.svg --view 20,40 --frames 12\n"
             "  intercurve plot examples/viviani-implicit.json -o viviani.html\n",
};

int ic_cmd_plot(int argc, char **argv)
{
    const char *file;
    ic_cli_value v[NOPTIONS];
    int rc = ic_cli_parse(&PLOT, argc, argv, &file, v);
    if (rc != 0)
        return rc == IC_CLI_HELP ? 0 : rc;
    ic_plot_options po;
    ic_plot_defaults(&po);
    po.azimuth = v[OPT_VIEW].list[0], po.elevation = v[OPT_VIEW].list[1];
    po.frames = (int)v[OPT_FRAMES].integer;
    po.width = v[OPT_SIZE].width, po.height = v[OPT_SIZE].height;
    po.mesh = (int)v[OPT_MESH].integer;
    po.chart = !v[OPT_NO_CHART].given;
    ic_trace_options to;
    ic_trace_defaults(&to);
    to.tol = v[OPT_TOL].real;
    to.depth = (int)v[OPT_DEPTH].integer;
    to.exact_paths = !v[OPT_NO_EXACT].given;
    to.threads = (int)v[OPT_THREADS].integer;
    ic_cli_traced t;
    /* the curves are drawn through their B-splines (docs/plots.md) */
    if ((rc = ic_cli_trace_file(file, &to, IC_TRACE_FIT_TOL_DEFAULT, "plot", &t)) != 0)
        return rc;
    ic_plot_scene scene;
    ic_plot_scene_of_problem(&scene, t.problem, t.res);
    ic_error err;
    ic_error_clear(&err);
    const ic_status st = ic_plot_write(v[OPT_OUTPUT].text, &scene, &po, &err);
    if (st != IC_OK)
        fprintf(stderr, "intercurve plot: %s\n", err.message);
    ic_cli_traced_free(&t);
    return st == IC_OK ? 0 : st == IC_ERR_INVALID ? EXIT_INPUT : EXIT_COMPUTE;
}
