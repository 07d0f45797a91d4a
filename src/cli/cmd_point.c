/* intercurve point: the intersection's Frenet apparatus at one point. */
#include "cli/cli.h"

#include <math.h>
#include <string.h>

enum { OPT_AT, OPT_PARAMS, OPT_ORDER, OPT_METHOD, OPT_FORMAT, OPT_POINT_TOL, NOPTIONS };

/* The formats, in the order of --format's choices. */
enum { FORMAT_JSON, FORMAT_TEXT };

static const ic_cli_option POINT_OPTIONS[NOPTIONS] = {
    [OPT_AT] = {.name = "--at",
                .metavar = "X,Y,Z",
                .kind = IC_OPT_LIST,
                .lo = 1,
                .hi = 3,
                .need = IC_OPT_ONE_OF,
                .help = "the point by coordinates (values may be formulas: sqrt(2)/2)"},
    [OPT_PARAMS] = {.name = "--params",
                    .metavar = "U,V[,P,Q]",
                    .kind = IC_OPT_LIST,
                    .lo = 1,
                    .hi = 4,
                    .need = IC_OPT_ONE_OF,
                    .help = "the parameters of the parametric surfaces in problem order;\n"
                            "for a self-intersection both preimages U,V,P,Q"},
    [OPT_ORDER] = {.name = "--order",
                   .metavar = "K",
                   .kind = IC_OPT_INT,
                   .lo = 1,
                   .hi = IC_LOCAL_MAX_ORDER,
                   .fallback = IC_CLI_TEXT_OF(IC_POINT_ORDER_DEFAULT),
                   .help = "highest derivative c^(K) (closed-form: up to 3, and 3 when not\n"
                           "given)"},
    [OPT_METHOD] = {.name = "--method",
                    .metavar = "M",
                    .kind = IC_OPT_CHOICE,
                    .choices = "auto|jet|closed-form|perturbation|height-difference",
                    .fallback = "auto",
                    .help = "jet (transversal points, any order), closed-form (the\n"
                            "papers' formulas, order <= 3: at transversal points Hassan\n"
                            "and Badr (2016), Abdel-All et al. (2012), Bendrici and\n"
                            "Boumedien-Zidani (2022) with Patrikalakis and Maekawa (2002);\n"
                            "at tangential ones section 4 of the first two;\n"
                            "docs/references.md),\n"
                            "perturbation (tangential points: t, n, kappa as limits of\n"
                            "nearby transversal values, with an error estimate),\n"
                            "height-difference (tangential points, any order); auto: jet\n"
                            "at transversal points, height-difference at tangential ones"},
    [OPT_FORMAT] = {.name = "--format",
                    .metavar = "F",
                    .kind = IC_OPT_CHOICE,
                    .choices = "json|text",
                    .fallback = "json",
                    .help = "the document (docs/output-formats.md) or a text for people"},
    [OPT_POINT_TOL] = {.name = "--point-tol",
                       .metavar = "T",
                       .kind = IC_OPT_REAL,
                       .lo = 0,
                       .hi = INFINITY,
                       .fallback = IC_CLI_TEXT_OF(IC_LOCAL_POINT_TOL_DEFAULT),
                       .help = "how far from either surface the search for the point may\n"
                               "start (a length); farther is an error saying how far. It\n"
                               "widens the search only: the point found must pass the\n"
                               "surfaces' residual test, at most " IC_CLI_TEXT_OF(
                                   IC_LOCAL_ON_SURFACE_REL) " (1 + |X|) from both"},
};

static const ic_cli_command POINT = {
    .name = "point",
    .summary = "Locates the point on the intersection of the problem's two surfaces (or the\n"
               "self-intersection of its one surface), refines it onto both, and prints its type\n"
               "and, on the branch through it, t, n, b, curvature, torsion, their derivatives,\n"
               "the derivatives c', ..., c^(K) with respect to arc length, and the normal\n"
               "curvature, geodesic curvature and geodesic torsion on each surface.",
    .options = POINT_OPTIONS,
    .noptions = NOPTIONS,
    .notes =
        "The curve is oriented by t = N_A x N_B. At a tangential point (normals parallel)\n"
        "the point is classified (branch-point, tangential-curve, isolated-contact, cusp,\n"
        "tacnode, higher-order-contact) and every branch through it is given, with the\n"
        "discriminant and the papers' coefficients. Undefined values (n, b, torsion where\n"
        "the curvature is 0) are null. Exit status 2 when the point is not on the\n"
        "intersection; the first message then says \"not on the surfaces: residual ...\".\n"
        "\n"
        "examples:\n"
        "  intercurve point examples/viviani.json --at 1.5,0.8660254037844386,1 --order 3\n"
        "  intercurve point examples/viviani.json --at 2,0,0 --format text   (a branch point)\n",
};

/* Locates the point of --at or --params (ic_local_find: "not on the
 * surfaces" first when it is off them); 0, or the exit code after the
 * message. */
static int locate_point(const char *file, ic_pair *pair, ic_local_point *pt, const double *values,
                        int count, int by_params, const ic_local_options *opt)
{
    ic_error err;
    ic_error_clear(&err);
    const ic_status st = ic_local_find(pair, pt, values, count, by_params, opt, &err);
    if (st == IC_OK)
        return 0;
    ic_cli_print_error(file, &err);
    return st == IC_ERR_INVALID ? EXIT_INPUT : EXIT_COMPUTE;
}

/* The point's apparatus, printed as the document or as text; 0 or the
 * exit code after the message. */
static int print_point(const char *name, ic_pair *pair, const ic_local_point *pt,
                       const ic_cli_value *v, const ic_local_options *opt)
{
    ic_error err;
    ic_error_clear(&err);
    const ic_method method = (ic_method)ic_method_from_name(v[OPT_METHOD].text);
    /* the closed forms stop at the third derivative: their default order */
    const int order = method == IC_METHOD_CLOSED_FORM && !v[OPT_ORDER].given
                          ? IC_POINT_CLOSED_FORM_ORDER_DEFAULT
                          : (int)v[OPT_ORDER].integer;
    ic_local_result res;
    ic_status st = ic_local_apparatus(pair, &res, pt, order, method, opt, &err);
    if (st != IC_OK) {
        ic_cli_print_error(name, &err);
        return st == IC_ERR_INVALID ? EXIT_INPUT : EXIT_COMPUTE;
    }
    st = v[OPT_FORMAT].choice == FORMAT_TEXT ? ic_local_write_text(stdout, &res, &err)
                                             : ic_local_write_json(stdout, &res, pair, order, &err);
    if (st == IC_OK && fflush(stdout) == 0)
        return 0;
    fprintf(stderr, "intercurve: cannot write the output (%s)\n",
            st == IC_ERR_NOMEM ? "out of memory" : "a write error");
    return EXIT_COMPUTE;
}

int ic_cmd_point(int argc, char **argv)
{
    const char *file;
    ic_cli_value v[NOPTIONS];
    int rc = ic_cli_parse(&POINT, argc, argv, &file, v);
    if (rc != 0)
        return rc == IC_CLI_HELP ? 0 : rc;
    const int by_params = v[OPT_PARAMS].given;
    if (!by_params && v[OPT_AT].count != 3) {
        fprintf(stderr, "intercurve point: --at needs three coordinates X,Y,Z, got %d\n",
                v[OPT_AT].count);
        return EXIT_INPUT;
    }
    ic_local_options opt;
    ic_local_defaults(&opt);
    opt.point_tol = v[OPT_POINT_TOL].real;
    ic_problem *p = NULL;
    ic_pair *pair = NULL;
    if ((rc = ic_cli_load_problem(&p, file, 0)) != 0)
        return rc;
    const char *name = ic_cli_file_name(file);
    ic_error err;
    ic_error_clear(&err);
    const int self = ic_problem_is_self(p);
    if (ic_pair_new(&pair, ic_problem_surface(p, 0), self ? NULL : ic_problem_surface(p, 1),
                    &err) != IC_OK) {
        ic_cli_print_error(name, &err);
        rc = EXIT_INPUT;
        goto cleanup;
    }
    const ic_cli_value *where = &v[by_params ? OPT_PARAMS : OPT_AT];
    ic_local_point pt;
    rc = locate_point(name, pair, &pt, where->list, where->count, by_params, &opt);
    if (rc == 0)
        rc = print_point(name, pair, &pt, v, &opt);
cleanup:
    ic_pair_free(pair);
    ic_problem_free(p);
    return rc;
}
