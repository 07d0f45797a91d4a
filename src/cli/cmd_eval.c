/* intercurve eval: local geometry and derivative tensor of one surface. */
#include "cli.h"

#include <stdlib.h>
#include <string.h>

static const char EVAL_HELP[] =
    "usage: intercurve eval PROBLEM.json [--surface NAME] --at U,V|X,Y,Z [--order K]\n"
    "\n"
    "Evaluates one surface of the problem at a point and prints, as JSON: the point\n"
    "(implicit: the value of f), the unit normal, the tangent basis, the first and\n"
    "second fundamental forms in that basis, the principal curvatures k1 >= k2 and\n"
    "directions, Gaussian and mean curvature, and every partial derivative up to\n"
    "order K (default 4, at most 24).\n"
    "\n"
    "  --surface NAME  the surface's \"name\" in the problem (default: the first)\n"
    "  --at LIST       parameters U,V of a parametric surface, or X,Y,Z of an\n"
    "                  implicit one; each value may be a formula such as pi/4\n"
    "  --order K       highest derivative order\n"
    "\n"
    "At a degenerate point (zero normal, e.g. a sphere pole) the derivatives are\n"
    "printed and the undefined quantities are null, with \"degenerate\" explaining.\n"
    "\n"
    "example:\n"
    "  intercurve eval examples/viviani.json --surface sphere --at 0.3,0.4 --order 3\n";

static cJSON *derivative_tensor(ic_surface *s, const double *at, int order, ic_error *err)
{
    ic_jet_space *sp = NULL;
    double *t = NULL;
    cJSON *list = NULL;
    if (ic_jet_space_new(&sp, ic_surface_num_vars(s), order, err) != IC_OK)
        goto cleanup;
    const int n = ic_jet_space_len(sp), nout = ic_surface_num_outputs(s);
    t = malloc((size_t)nout * n * sizeof *t);
    if (!t) {
        ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory");
        goto cleanup;
    }
    if (ic_surface_taylor(s, t, at, sp, err) != IC_OK)
        goto cleanup;
    list = cJSON_CreateArray();
    for (int i = 0; i < n; i++) {
        int alpha[3];
        ic_jet_exponents(sp, i, alpha);
        const double f = ic_jet_factorial(sp, i);
        cJSON *item = cJSON_CreateObject();
        cJSON_AddItemToObject(item, "order", cJSON_CreateIntArray(alpha, ic_surface_num_vars(s)));
        if (nout == 1) {
            cJSON_AddItemToObject(item, "value", ic_json_number_or_null(t[i] * f));
        } else {
            double v[3] = {t[i] * f, t[n + i] * f, t[2 * n + i] * f};
            cJSON_AddItemToObject(item, "value", ic_json_vector(v, 3));
        }
        cJSON_AddItemToArray(list, item);
    }
cleanup:
    free(t);
    ic_jet_space_free(sp);
    return list;
}

static void add_geometry(cJSON *doc, const ic_surface_geometry *g, int parametric)
{
    cJSON_AddItemToObject(doc, "normal", ic_json_vector(g->normal, 3));
    cJSON *basis = cJSON_CreateArray();
    cJSON_AddItemToArray(basis, ic_json_vector(g->basis[0], 3));
    cJSON_AddItemToArray(basis, ic_json_vector(g->basis[1], 3));
    cJSON_AddItemToObject(doc, parametric ? "tangent_basis_Ru_Rv" : "tangent_basis_orthonormal",
                          basis);
    cJSON *first = cJSON_CreateObject();
    cJSON_AddItemToObject(first, "E", ic_json_number_or_null(g->first[0]));
    cJSON_AddItemToObject(first, "F", ic_json_number_or_null(g->first[1]));
    cJSON_AddItemToObject(first, "G", ic_json_number_or_null(g->first[2]));
    cJSON_AddItemToObject(doc, "first_fundamental_form", first);
    cJSON *second = cJSON_CreateObject();
    cJSON_AddItemToObject(second, "L", ic_json_number_or_null(g->second[0]));
    cJSON_AddItemToObject(second, "M", ic_json_number_or_null(g->second[1]));
    cJSON_AddItemToObject(second, "N", ic_json_number_or_null(g->second[2]));
    cJSON_AddItemToObject(doc, "second_fundamental_form", second);
    cJSON_AddItemToObject(doc, "principal_curvatures", ic_json_vector(g->principal_curvatures, 2));
    cJSON *dirs = cJSON_CreateArray();
    cJSON_AddItemToArray(dirs, ic_json_vector(g->principal_directions[0], 3));
    cJSON_AddItemToArray(dirs, ic_json_vector(g->principal_directions[1], 3));
    cJSON_AddItemToObject(doc, "principal_directions", dirs);
    cJSON_AddItemToObject(doc, "gaussian_curvature", ic_json_number_or_null(g->gauss));
    cJSON_AddItemToObject(doc, "mean_curvature", ic_json_number_or_null(g->mean));
}

static void add_nulls(cJSON *doc, int parametric)
{
    static const char *const keys[] = {"normal",
                                       "first_fundamental_form",
                                       "second_fundamental_form",
                                       "principal_curvatures",
                                       "principal_directions",
                                       "gaussian_curvature",
                                       "mean_curvature"};
    for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++)
        cJSON_AddNullToObject(doc, keys[i]);
    (void)parametric;
}

int ic_cmd_eval(int argc, char **argv)
{
    const char *file = NULL, *name = NULL, *at_text = NULL;
    int order = 4;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            fputs(EVAL_HELP, stdout);
            return 0;
        }
        const int has_value = i + 1 < argc;
        if (strcmp(argv[i], "--surface") == 0 && has_value)
            name = argv[++i];
        else if (strcmp(argv[i], "--at") == 0 && has_value)
            at_text = argv[++i];
        else if (strcmp(argv[i], "--order") == 0 && has_value) {
            if (ic_cli_parse_int(&order, argv[++i], 0, IC_JET_MAX_ORDER, "--order") < 0)
                return EXIT_INPUT;
        } else if (argv[i][0] == '-' && argv[i][1] != '\0') {
            fprintf(stderr, "intercurve eval: unknown option or missing value: %s\n%s", argv[i],
                    "try 'intercurve eval --help'\n");
            return EXIT_INPUT;
        } else if (!file)
            file = argv[i];
        else {
            fprintf(stderr, "intercurve eval: unexpected argument '%s'\n", argv[i]);
            return EXIT_INPUT;
        }
    }
    if (!file || !at_text) {
        fprintf(stderr, "intercurve eval: needs PROBLEM.json and --at\n%s", EVAL_HELP);
        return EXIT_INPUT;
    }
    ic_error err;
    ic_problem *p = NULL;
    if (ic_problem_load(&p, file, &err) != IC_OK) {
        ic_cli_print_error(file, &err);
        return EXIT_INPUT;
    }
    int rc = EXIT_INPUT;
    const int idx = name ? ic_problem_find_surface(p, name) : 0;
    if (idx < 0) {
        fprintf(stderr, "intercurve eval: %s has no surface named '%s' (it has:", file, name);
        for (int i = 0; i < ic_problem_num_surfaces(p); i++)
            fprintf(stderr, " '%s'", ic_problem_surface_name(p, i));
        fprintf(stderr, ")\n");
        goto cleanup;
    }
    ic_surface *s = ic_problem_surface(p, idx);
    const int parametric = ic_surface_get_kind(s) == IC_PARAMETRIC;
    const int nin = ic_surface_num_vars(s);
    double at[3];
    const int count = ic_cli_parse_list(at, 3, at_text, "--at");
    if (count < 0)
        goto cleanup;
    if (count != nin) {
        fprintf(stderr, "intercurve eval: --at needs %s for the %s surface '%s', got %d value%s\n",
                parametric ? "two parameters U,V" : "three coordinates X,Y,Z",
                parametric ? "parametric" : "implicit", ic_problem_surface_name(p, idx), count,
                count == 1 ? "" : "s");
        goto cleanup;
    }
    cJSON *doc = cJSON_CreateObject();
    cJSON_AddStringToObject(doc, "surface", ic_problem_surface_name(p, idx));
    cJSON_AddStringToObject(doc, "type", parametric ? "parametric" : "implicit");
    cJSON_AddItemToObject(doc, "at", ic_json_vector(at, nin));
    cJSON *tensor = derivative_tensor(s, at, order, &err);
    if (!tensor) {
        cJSON_Delete(doc);
        ic_error_set_path(&err, "surfaces[%d] (\"%s\")", idx, ic_problem_surface_name(p, idx));
        ic_cli_print_error(file, &err);
        rc = EXIT_COMPUTE;
        goto cleanup;
    }
    ic_surface_geometry g;
    ic_status st = ic_surface_geometry_at(s, &g, at, &err);
    if (st != IC_OK && st != IC_ERR_DOMAIN) {
        cJSON_Delete(doc);
        cJSON_Delete(tensor);
        ic_error_set_path(&err, "surfaces[%d] (\"%s\")", idx, ic_problem_surface_name(p, idx));
        ic_cli_print_error(file, &err);
        rc = EXIT_COMPUTE;
        goto cleanup;
    }
    if (parametric)
        cJSON_AddItemToObject(doc, "point", ic_json_vector(g.point, 3));
    else
        cJSON_AddItemToObject(doc, "value", ic_json_number_or_null(g.value));
    if (st == IC_OK) {
        cJSON_AddNullToObject(doc, "degenerate");
        add_geometry(doc, &g, parametric);
    } else {
        cJSON_AddStringToObject(doc, "degenerate", err.message);
        add_nulls(doc, parametric);
    }
    cJSON_AddNumberToObject(doc, "order", order);
    cJSON_AddItemToObject(doc, "derivatives", tensor);
    rc = ic_json_print(doc) == 0 ? 0 : EXIT_COMPUTE;
cleanup:
    ic_problem_free(p);
    return rc;
}
