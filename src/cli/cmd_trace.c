/* intercurve trace: the whole intersection as JSON (docs/output-formats.md). */
#include "cli/cli.h"
#include "cli/trace_options.h"
#include "api/api.h"

#include <math.h>
#include <string.h>

enum {
    OPT_FORMAT,
    OPT_OUTPUT,
    OPT_TOL,
    OPT_DEPTH,
    OPT_TIME_LIMIT,
    OPT_FIT_TOL,
    OPT_NO_EXACT,
    OPT_THREADS,
    OPT_CERTIFICATE,
    NOPTIONS
};

/* The formats, in the order of --format's choices. */
typedef enum {
    FORMAT_JSON,
    FORMAT_CSV,
    FORMAT_VTK,
    FORMAT_OBJ,
    FORMAT_TEXT,
    FORMAT_STEP,
    FORMAT_IGES
} out_format;

static const ic_cli_option TRACE_OPTIONS[NOPTIONS] = {
    [OPT_FORMAT] = {.name = "--format",
                    .metavar = "F",
                    .kind = IC_OPT_CHOICE,
                    .choices = "json|csv|vtk|obj|text|step|iges",
                    .fallback = "json",
                    .help = "json, csv (one row per point), vtk (legacy PolyData with\n"
                            "t, n, b, kappa, tau as point data, for ParaView), obj (polylines),\n"
                            "text (a summary table of the curves and points), or step or\n"
                            "iges (the curves' B-splines, for CAD systems);\n"
                            "docs/output-formats.md"},
    [OPT_OUTPUT] = {.name = "-o",
                    .metavar = "FILE",
                    .kind = IC_OPT_TEXT,
                    .help = "write to FILE (through a temporary file and a rename)"},
    [OPT_TOL] = IC_CLI_OPTION_TOL("truncation error allowed per step, a fraction of the problem's\n"
                                  "size (the diagonal of the region searched)"),
    [OPT_DEPTH] = IC_CLI_OPTION_DEPTH("subdivision depth of the start-point search"),
    [OPT_TIME_LIMIT] = {.name = "--time-limit",
                        .metavar = "SECONDS",
                        .kind = IC_OPT_REAL,
                        .lo = 0,
                        .hi = IC_TRACE_TIME_LIMIT_MAX,
                        .help = "stop after this wall time with what was found (complete:\n"
                                "false); without it the search's own cell budget bounds it"},
    [OPT_FIT_TOL] = {.name = "--fit-tol",
                     .metavar = "T",
                     .kind = IC_OPT_REAL,
                     .lo = 0,
                     .hi = IC_TRACE_REL_TOL_MAX,
                     .fallback = IC_CLI_TEXT_OF(IC_TRACE_FIT_TOL_DEFAULT),
                     .help = "the curves' B-splines in the json, vtk, step and iges outputs\n"
                             "(docs/bspline.md): what a pcurve's image may stray from the\n"
                             "curve, a fraction of the problem's size; the json report\n"
                             "gives the largest error found"},
    [OPT_NO_EXACT] =
        IC_CLI_OPTION_NO_EXACT("always search and march, even where a closed form applies\n"
                               "(coaxial surfaces of revolution, a plane's ellipse on a\n"
                               "quadric, two equal cylinders whose axes meet: docs/tracing.md,\n"
                               "\"Exact paths\")"),
    [OPT_THREADS] =
        IC_CLI_OPTION_THREADS("threads that search at once, 0 for all the machine's cores;\n"
                              "the output is the same whatever N (docs/tracing.md, \"Threads\")"),
    [OPT_CERTIFICATE] = {.name = "--certificate",
                         .metavar = "CERT.json",
                         .kind = IC_OPT_TEXT,
                         .help = "also writes the checker's cover of the search region, cell by\n"
                                 "cell, to CERT.json, for `intercurve verify --certificate`\n"
                                 "(docs/output-formats.md, \"The certificate file\"); where the\n"
                                 "checker did not run, a file that says why"},
};

static const ic_cli_command TRACE = {
    .name = "trace",
    .summary =
        "Finds the intersection curves of the problem's two surfaces and traces each, with\n"
        "t, n, b, curvature and torsion at every point, its length and its shape (line,\n"
        "circle, planar, circular-helix, helix, general), the tangential points met, and a\n"
        "report of what was proven (cells excluded by interval arithmetic), what was only\n"
        "sampled, and every failure. The report says \"complete\": true only when every part\n"
        "of the search was decided (docs/tracing.md, \"Completeness\").\n"
        "\n"
        "Two implicit surfaces are searched inside the problem's \"box\"; a parametric\n"
        "surface over its \"domain\" (both domains, or twice the one, for two parametric\n"
        "surfaces or a self-intersection). A curve ends where it leaves the box or a\n"
        "domain, closes, or meets a tangential point it cannot pass.",
    .options = TRACE_OPTIONS,
    .noptions = NOPTIONS,
    .notes = "example:\n"
             "  intercurve trace examples/viviani-implicit.json -o viviani.json\n"
             "  intercurve trace examples/viviani-implicit.json --format vtk -o viviani.vtk\n"
             "  intercurve trace examples/viviani-implicit.json --format step -o viviani.step\n",
};

/* What the writers need, handed through ic_write_file_atomic. */
typedef struct {
    out_format fmt;
    const ic_trace_result *res;
    const ic_pair *pair;
    const char *title;
} trace_output;

/* The formats that carry or draw on the curves' B-splines (ic_trace_fit
 * first). */
static int has_bsplines(out_format fmt)
{
    return fmt == FORMAT_JSON || fmt == FORMAT_STEP || fmt == FORMAT_IGES || fmt == FORMAT_VTK;
}

/* Writes the result in its format to an open stream (an ic_file_writer). */
static ic_status write_result(FILE *f, void *user, ic_error *err)
{
    const trace_output *o = user;
    switch (o->fmt) {
    case FORMAT_CSV:
        return ic_trace_write_csv(f, o->res, o->pair, err);
    case FORMAT_VTK:
        return ic_trace_write_vtk(f, o->res, err);
    case FORMAT_OBJ:
        return ic_trace_write_obj(f, o->res, err);
    case FORMAT_TEXT:
        return ic_trace_write_text(f, o->res, o->title, err);
    case FORMAT_STEP:
        return ic_trace_write_step(f, o->res, o->title, err);
    case FORMAT_IGES:
        return ic_trace_write_iges(f, o->res, o->title, err);
    case FORMAT_JSON:
        break;
    }
    return ic_trace_write_json(f, o->res, o->pair, err);
}

/* The certificate file, when asked for: 0, or EXIT_COMPUTE after the
 * reason. */
static int write_certificate(const char *path, ic_trace_result *res)
{
    if (!path)
        return 0;
    ic_error err;
    ic_error_clear(&err);
    if (ic_write_file_atomic(path, ic_api_write_certificate, res, &err) != IC_OK) {
        fprintf(stderr, "intercurve trace: %s\n", err.message);
        return EXIT_COMPUTE;
    }
    if (!ic_trace_result_certificate(res))
        fprintf(stderr, "intercurve trace: %s holds no cover: %s\n", path,
                ic_api_unchecked_reason(res));
    return 0;
}

/* The result to -o's file (whole or not at all) or to standard output;
 * 0, or EXIT_COMPUTE after the reason. */
static int write_output(const char *path, trace_output *o)
{
    ic_error err;
    ic_error_clear(&err);
    if (path) {
        if (ic_write_file_atomic(path, write_result, o, &err) == IC_OK)
            return 0;
        fprintf(stderr, "intercurve trace: %s\n", err.message);
        return EXIT_COMPUTE;
    }
    if (write_result(stdout, o, &err) == IC_OK && fflush(stdout) == 0)
        return 0;
    fprintf(stderr, "intercurve trace: writing the output failed\n");
    return EXIT_COMPUTE;
}

int ic_cmd_trace(int argc, char **argv)
{
    const char *file;
    ic_cli_value v[NOPTIONS];
    int rc = ic_cli_parse(&TRACE, argc, argv, &file, v);
    if (rc != 0)
        return rc == IC_CLI_HELP ? 0 : rc;
    const char *out_path = v[OPT_OUTPUT].text, *cert_path = v[OPT_CERTIFICATE].text;
    if (out_path && cert_path && strcmp(out_path, cert_path) == 0) {
        fprintf(stderr, "intercurve trace: -o and --certificate name the same file %s: the "
                        "certificate would replace the trace\n",
                cert_path);
        return EXIT_INPUT;
    }
    ic_trace_options opt;
    ic_trace_defaults(&opt);
    opt.tol = v[OPT_TOL].real;
    opt.depth = (int)v[OPT_DEPTH].integer;
    opt.exact_paths = !v[OPT_NO_EXACT].given;
    opt.threads = (int)v[OPT_THREADS].integer;
    if (v[OPT_TIME_LIMIT].given)
        opt.time_limit = v[OPT_TIME_LIMIT].real;
    opt.keep_certificate = v[OPT_CERTIFICATE].given;
    const double fit_tol = has_bsplines((out_format)v[OPT_FORMAT].choice) ? v[OPT_FIT_TOL].real : 0;
    ic_cli_traced t;
    if ((rc = ic_cli_trace_file(file, &opt, fit_tol, "trace", &t)) != 0)
        return rc;
    trace_output o = {(out_format)v[OPT_FORMAT].choice, t.res, t.pair, ic_problem_title(t.problem)};
    rc = write_output(v[OPT_OUTPUT].text, &o);
    if (rc == 0)
        rc = write_certificate(v[OPT_CERTIFICATE].text, t.res);
    ic_cli_traced_free(&t);
    return rc;
}
