/* intercurve eval: local geometry and derivative tensor of one surface. */
#include "cli/cli.h"

enum { OPT_SURFACE, OPT_AT, OPT_ORDER, NOPTIONS };

static const ic_cli_option EVAL_OPTIONS[NOPTIONS] = {
    [OPT_SURFACE] = {.name = "--surface",
                     .metavar = "NAME",
                     .kind = IC_OPT_TEXT,
                     .help = "the surface's \"name\" in the problem (default: the first)"},
    [OPT_AT] = {.name = "--at",
                .metavar = "U,V|X,Y,Z",
                .kind = IC_OPT_LIST,
                .lo = 1,
                .hi = 3,
                .need = IC_OPT_REQUIRED,
                .help = "parameters U,V of a parametric surface, or X,Y,Z of an\n"
                        "implicit one; each value may be a formula such as pi/4"},
    [OPT_ORDER] = {.name = "--order",
                   .metavar = "K",
                   .kind = IC_OPT_INT,
                   .lo = 0,
                   .hi = IC_JET_MAX_ORDER,
                   .fallback = IC_CLI_TEXT_OF(IC_EVAL_ORDER_DEFAULT),
                   .help = "highest order of the partial derivatives"},
};

static const ic_cli_command EVAL = {
    .name = "eval",
    .summary = "Evaluates one surface of the problem at a point and prints, as JSON: the point\n"
               "(implicit: the value of f), the unit normal, the tangent basis, the first and\n"
               "second fundamental forms in that basis, the principal curvatures k1 >= k2 and\n"
               "directions, Gaussian and mean curvature, and every partial derivative up to\n"
               "order K. The problem file may hold one surface alone (no \"self\"): the surface\n"
               "to evaluate; point, trace and plot need two, or one with \"self\": true.",
    .options = EVAL_OPTIONS,
    .noptions = NOPTIONS,
    .notes = "At a degenerate point (zero normal, e.g. a sphere pole) the derivatives are\n"
             "printed and the undefined quantities are null, with \"degenerate\" explaining.\n"
             "\n"
             "example:\n"
             "  intercurve eval examples/viviani.json --surface sphere --at 0.3,0.4 --order 3\n",
};

/* The index of the surface --surface names (default the first); -1 after a
 * message listing the surfaces. */
static int chosen_surface(const ic_problem *p, const char *name, const char *file)
{
    const int idx = name ? ic_problem_find_surface(p, name) : 0;
    if (idx >= 0)
        return idx;
    fprintf(stderr, "intercurve eval: %s has no surface named '%s' (it has:", file, name);
    for (int i = 0; i < ic_problem_num_surfaces(p); i++)
        fprintf(stderr, " '%s'", ic_problem_surface_name(p, i));
    fprintf(stderr, ")\n");
    return -1;
}

/* --at holds as many values as the surface has inputs; else a message. */
static int check_at(const ic_problem *p, int idx, int count)
{
    ic_surface *s = ic_problem_surface(p, idx);
    if (count == ic_surface_num_inputs(s))
        return 0;
    const int parametric = ic_surface_get_kind(s) == IC_PARAMETRIC;
    fprintf(stderr, "intercurve eval: --at needs %s for the %s surface '%s', got %d value%s\n",
            parametric ? "two parameters U,V" : "three coordinates X,Y,Z",
            parametric ? "parametric" : "implicit", ic_problem_surface_name(p, idx), count,
            count == 1 ? "" : "s");
    return -1;
}

int ic_cmd_eval(int argc, char **argv)
{
    const char *file;
    ic_cli_value v[NOPTIONS];
    int rc = ic_cli_parse(&EVAL, argc, argv, &file, v);
    if (rc != 0)
        return rc == IC_CLI_HELP ? 0 : rc;
    ic_problem *p = NULL;
    if ((rc = ic_cli_load_problem(&p, file, IC_PROBLEM_ONE_SURFACE)) != 0)
        return rc;
    rc = EXIT_INPUT;
    const char *name = ic_cli_file_name(file);
    const int idx = chosen_surface(p, v[OPT_SURFACE].text, name);
    if (idx < 0 || check_at(p, idx, v[OPT_AT].count) < 0)
        goto cleanup;
    ic_error err;
    ic_error_clear(&err);
    const ic_status st =
        ic_surface_write_json(stdout, ic_problem_surface(p, idx), ic_problem_surface_name(p, idx),
                              v[OPT_AT].list, (int)v[OPT_ORDER].integer, &err);
    if (st == IC_OK && fflush(stdout) == 0) {
        rc = 0;
    } else if (st == IC_OK || st == IC_ERR_IO) {
        fprintf(stderr, "intercurve: cannot write the output (a write error)\n");
        rc = EXIT_COMPUTE;
    } else {
        ic_error_set_path(&err, "surfaces[%d] (\"%s\")", idx, ic_problem_surface_name(p, idx));
        ic_cli_print_error(name, &err);
        rc = EXIT_COMPUTE;
    }
cleanup:
    ic_problem_free(p);
    return rc;
}
