/* intercurve point: the intersection's Frenet apparatus at one point. */
#include "cli.h"
#include "common/vec3.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The surfaces' own residual test for a point the command reports: its
 * largest distance to either surface (a length) at most ON_SURFACE_REL
 * times the problem's length scale at the point, 1 + |X| (the unit keeps
 * points near the origin from asking for zero). The same test the tracer
 * uses for a point on both surfaces (src/trace/search.c); the locator's
 * refinement stops near 1e-15 of that scale, so 1e-10 leaves five digits
 * for ill-conditioned sheets. --point-tol never loosens it: it only lets
 * the search start that far from the surfaces. */
#define ON_SURFACE_REL 1e-10
#define STRINGIFY_(x) #x
#define STRINGIFY(x) STRINGIFY_(x) /* the constant's value in the help text */

static const char POINT_HELP[] =
    "usage: intercurve point PROBLEM.json (--at X,Y,Z | --params U,V[,P,Q]) [--order K]\n"
    "                        [--method auto|jet|closed-form] [--format json|text]\n"
    "                        [--point-tol T]\n"
    "\n"
    "Locates the point on the intersection of the problem's two surfaces (or the\n"
    "self-intersection of its one surface), refines it onto both, and prints its type\n"
    "and, on the branch through it, t, n, b, curvature, torsion, their derivatives,\n"
    "the derivatives c', ..., c^(K) with respect to arc length, and the normal\n"
    "curvature, geodesic curvature and geodesic torsion on each surface.\n"
    "\n"
    "  --at X,Y,Z      the point by coordinates (values may be formulas: sqrt(2)/2)\n"
    "  --params LIST   the parameters of the parametric surfaces in problem order;\n"
    "                  for a self-intersection both preimages U,V,P,Q\n"
    "  --order K       highest derivative (default 4; jet: up to 16, closed-form: 3)\n"
    "  --method M      auto, jet (transversal, any order), closed-form (the papers'\n"
    "                  formulas, order <= 3: at transversal points Hassan and Badr\n"
    "                  (2016), Abdel-All et al. (2012), Bendrici and Boumedien-Zidani\n"
    "                  (2022) with Patrikalakis and Maekawa (2002); at tangential\n"
    "                  ones section 4 of the first two; docs/references.md),\n"
    "                  height-difference (tangential points, any order), perturbation\n"
    "                  (tangential points: t, n, kappa as limits of nearby transversal\n"
    "                  values, with an error estimate)\n"
    "  --format F      json (default) or text\n"
    "  --point-tol T   how far from either surface the search for the point may\n"
    "                  start (a length, default 1e-6); farther is an error saying how\n"
    "                  far. It widens the search only: the point found must pass the\n"
    "                  surfaces' residual test, at most " STRINGIFY(ON_SURFACE_REL) " (1 + |X|) from both\n"
    "\n"
    "The curve is oriented by t = N_A x N_B. At a tangential point (normals parallel)\n"
    "the point is classified (branch-point, tangential-curve, isolated-contact, cusp,\n"
    "tacnode, higher-order-contact) and every branch through it is given, with the\n"
    "discriminant and the papers' coefficients. Undefined values (n, b, torsion where\n"
    "the curvature is 0) are null. Exit status 2 when the point is not on the\n"
    "intersection; the first message then says \"not on the surfaces: residual ...\".\n"
    "\n"
    "examples:\n"
    "  intercurve point examples/viviani.json --at 1.5,0.8660254037844386,1 --order 3\n"
    "  intercurve point examples/viviani.json --at 2,0,0 --format text   (a branch point)\n";

static cJSON *branch_json(const ic_branch *br, const ic_pair *pair)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddItemToObject(o, "t", ic_json_vector(br->t, 3));
    if (!br->regular)
        cJSON_AddFalseToObject(o, "regular");
    cJSON_AddItemToObject(o, "n",
                          br->frame_defined ? ic_json_vector(br->n, 3) : cJSON_CreateNull());
    cJSON_AddItemToObject(o, "b",
                          br->frame_defined ? ic_json_vector(br->b, 3) : cJSON_CreateNull());
    cJSON_AddItemToObject(o, "kappa",
                          br->order >= 2 ? ic_json_number_or_null(br->kappa) : cJSON_CreateNull());
    cJSON_AddItemToObject(o, "tau",
                          br->tau_defined ? ic_json_number_or_null(br->tau) : cJSON_CreateNull());
    cJSON_AddItemToObject(o, "kappa_prime",
                          br->kappa_prime_defined ? ic_json_number_or_null(br->kappa_prime)
                                                  : cJSON_CreateNull());
    cJSON_AddItemToObject(o, "tau_prime",
                          br->tau_prime_defined ? ic_json_number_or_null(br->tau_prime)
                                                : cJSON_CreateNull());
    if (!br->regular)
        cJSON_AddStringToObject(o, "undefined",
                                "a cusp: t, n, b are one-sided limits along "
                                "this half-branch; the curvature is infinite");
    else if (!br->frame_defined && br->order >= 2)
        cJSON_AddStringToObject(o, "undefined",
                                "the curvature is 0: n, b and the torsion are undefined");
    cJSON *d = cJSON_CreateArray();
    for (int k = 0; k < br->order; k++)
        cJSON_AddItemToArray(d, ic_json_vector(br->derivs[k], 3));
    cJSON_AddItemToObject(o, "derivatives", d);
    cJSON *surfaces = cJSON_CreateArray();
    for (int s = 0; s < 2; s++) {
        cJSON *so = cJSON_CreateObject();
        if (br->order >= 2) {
            cJSON_AddItemToObject(so, "kappa_n", ic_json_number_or_null(br->surface[s].kappa_n));
            cJSON_AddItemToObject(so, "kappa_g", ic_json_number_or_null(br->surface[s].kappa_g));
            cJSON_AddItemToObject(so, "tau_g", ic_json_number_or_null(br->surface[s].tau_g));
        }
        if (ic_surface_get_kind(ic_pair_surface(pair, s)) == IC_PARAMETRIC) {
            cJSON *pd = cJSON_CreateArray();
            for (int k = 0; k < br->param_order && k < br->order; k++)
                cJSON_AddItemToArray(pd, ic_json_vector(br->param_derivs[s][k], 2));
            cJSON_AddItemToObject(so, "parameter_derivatives", pd);
        }
        cJSON_AddItemToArray(surfaces, so);
    }
    cJSON_AddItemToObject(o, "surfaces", surfaces);
    return o;
}

static cJSON *result_json(const ic_local_result *res, const ic_pair *pair, int order)
{
    cJSON *doc = cJSON_CreateObject();
    cJSON_AddItemToObject(doc, "point", ic_json_vector(res->point.xyz, 3));
    cJSON_AddItemToObject(doc, "residual", ic_json_number_or_null(res->point.residual));
    cJSON *params = cJSON_CreateArray();
    for (int s = 0; s < 2; s++)
        cJSON_AddItemToArray(params, ic_surface_get_kind(ic_pair_surface(pair, s)) == IC_PARAMETRIC
                                         ? ic_json_vector(res->point.params[s], 2)
                                         : cJSON_CreateNull());
    cJSON_AddItemToObject(doc, "params", params);
    cJSON *normals = cJSON_CreateArray();
    cJSON_AddItemToArray(normals, ic_json_vector(res->normals[0], 3));
    cJSON_AddItemToArray(normals, ic_json_vector(res->normals[1], 3));
    cJSON_AddItemToObject(doc, "normals", normals);
    cJSON_AddItemToObject(doc, "angle", ic_json_number_or_null(res->angle));
    cJSON_AddStringToObject(doc, "type", ic_point_type_name(res->type));
    cJSON_AddItemToObject(doc, "discriminant", ic_json_number_or_null(res->discriminant));
    if (res->contact_order)
        cJSON_AddNumberToObject(doc, "contact_order", res->contact_order);
    cJSON_AddStringToObject(doc, "method", ic_method_name(res->method));
    if (res->npaper) {
        cJSON *pc = cJSON_CreateObject();
        for (int i = 0; i < res->npaper; i++)
            cJSON_AddItemToObject(pc, res->paper_names[i],
                                  ic_json_number_or_null(res->paper_values[i]));
        cJSON_AddItemToObject(doc, "paper_coefficients", pc);
    }
    if (res->method == IC_METHOD_PERTURBATION)
        cJSON_AddItemToObject(doc, "error_estimate", ic_json_number_or_null(res->error_estimate));
    cJSON_AddNumberToObject(doc, "order", order);
    cJSON *branches = cJSON_CreateArray();
    for (int i = 0; i < res->nbranches; i++)
        cJSON_AddItemToArray(branches, branch_json(&res->branches[i], pair));
    cJSON_AddItemToObject(doc, "branches", branches);
    return doc;
}

static void print_vec(const char *name, const double *v, int defined)
{
    if (defined)
        printf("  %-12s (% .15g, % .15g, % .15g)\n", name, v[0] + 0.0, v[1] + 0.0, v[2] + 0.0);
    else
        printf("  %-12s undefined\n", name);
}

static void print_text(const ic_local_result *res)
{
    printf("point        (%.15g, %.15g, %.15g)  residual %.3g\n", res->point.xyz[0],
           res->point.xyz[1], res->point.xyz[2], res->point.residual);
    printf("type         %s (angle between the normals %.6g rad), method %s\n",
           ic_point_type_name(res->type), res->angle, ic_method_name(res->method));
    if (!isnan(res->discriminant))
        printf("discriminant %.15g%s\n", res->discriminant,
               res->nbranches ? "" : "  (no branch: an isolated point)");
    for (int i = 0; i < res->nbranches; i++) {
        const ic_branch *br = &res->branches[i];
        printf("branch %d%s\n", i + 1, br->regular ? "" : " (cusp half-branch: one-sided limits)");
        print_vec("t", br->t, 1);
        print_vec("n", br->n, br->frame_defined);
        print_vec("b", br->b, br->frame_defined);
        if (br->order >= 2)
            printf("  %-12s %.15g\n", "kappa", br->kappa);
        else if (!br->regular)
            printf("  %-12s infinite (a cusp)\n", "kappa");
        if (br->tau_defined)
            printf("  %-12s %.15g\n", "tau", br->tau + 0.0);
        if (br->kappa_prime_defined)
            printf("  %-12s %.15g\n", "kappa'", br->kappa_prime);
        if (br->tau_prime_defined)
            printf("  %-12s %.15g\n", "tau'", br->tau_prime);
        for (int k = 0; k < br->order; k++) {
            char name[16];
            snprintf(name, sizeof name, "c^(%d)", k + 1);
            print_vec(name, br->derivs[k], 1);
        }
        for (int s = 0; s < 2 && br->order >= 2; s++)
            printf("  surface %c    kappa_n %.15g  kappa_g %.15g  tau_g %.15g\n", 'A' + s,
                   br->surface[s].kappa_n, br->surface[s].kappa_g, br->surface[s].tau_g);
    }
}

/* The largest residual (a length) the command accepts at X. */
static double accepted_residual(const double X[3])
{
    return ON_SURFACE_REL * (1.0 + hypot(hypot(X[0], X[1]), X[2]));
}

/* 1 when the sheets' normals at the point are parallel within the
 * tangential angle: the locator then has no plane normal to the curve to
 * refine in, so the point is where the search left it. */
static int normals_parallel(ic_pair *pair, const ic_local_point *pt, const ic_local_options *opt)
{
    double N[2][3];
    for (int s = 0; s < 2; s++) {
        ic_surface *srf = ic_pair_surface(pair, s);
        const int par = ic_surface_get_kind(srf) == IC_PARAMETRIC;
        ic_surface_geometry g;
        if (ic_surface_normal_at(srf, &g, par ? pt->params[s] : pt->xyz, NULL) != IC_OK)
            return 0;
        memcpy(N[s], g.normal, sizeof N[s]);
    }
    double c[3];
    ic_cross3(c, N[0], N[1]);
    return ic_norm3(c) < sin(opt->tangential_angle);
}

/* "not on the surfaces", the first message whenever the point is off them:
 * before the locator's reasons (a singular sheet, no convergence). */
static void say_not_on_surfaces(const char *file, double residual, const char *where)
{
    if (isinf(residual))
        fprintf(stderr,
                "intercurve: %s: not on the surfaces: residual unknown: %s is off a surface "
                "whose gradient vanishes there\n",
                file, where);
    else
        fprintf(stderr, "intercurve: %s: not on the surfaces: residual %.3g at %s\n", file,
                residual, where);
}

/* A located point off the surfaces at a tangential place (unrefined) is
 * moved onto the nearest tangential point within --point-tol; 1 if moved. */
static int snap_tangential(ic_pair *pair, ic_local_point *pt, const ic_local_options *opt)
{
    ic_local_point on;
    if (!normals_parallel(pair, pt, opt) ||
        ic_local_locate_tangential(pair, &on, pt, opt->point_tol, opt, NULL) != IC_OK ||
        !(on.residual <= accepted_residual(on.xyz)))
        return 0;
    *pt = on;
    return 1;
}

/* Locates the point of --at or --params; 0, or the exit code after the
 * messages. The point must pass the surfaces' residual test
 * (ON_SURFACE_REL) whatever --point-tol allowed the search. */
static int locate_point(const char *file, ic_pair *pair, ic_local_point *pt, const double *values,
                        int count, int by_params, const ic_local_options *opt)
{
    ic_error err;
    ic_error_clear(&err);
    ic_status st = by_params ? ic_local_locate_params(pair, pt, values, count, opt, &err)
                             : ic_local_locate(pair, pt, values, opt, &err);
    if (st != IC_OK) {
        /* pt->residual: how far the given point is, as far as measured */
        const double *X = by_params ? pt->xyz : values;
        if (pt->residual > accepted_residual(X))
            say_not_on_surfaces(file, pt->residual,
                                by_params ? "the point of the given parameters"
                                          : "the given point");
        ic_cli_print_error(file, &err);
        return st == IC_ERR_INVALID ? EXIT_INPUT : EXIT_COMPUTE;
    }
    if (pt->residual <= accepted_residual(pt->xyz) || snap_tangential(pair, pt, opt))
        return 0;
    char where[160];
    snprintf(where, sizeof where, "the nearest point found (%.17g, %.17g, %.17g)", pt->xyz[0],
             pt->xyz[1], pt->xyz[2]);
    say_not_on_surfaces(file, pt->residual, where);
    fprintf(stderr,
            "intercurve: %s: the surfaces' residual test allows %.3g there (%g of 1 + |X|); "
            "--point-tol %g only widens the search for the point\n",
            file, accepted_residual(pt->xyz), ON_SURFACE_REL, opt->point_tol);
    return EXIT_COMPUTE;
}

int ic_cmd_point(int argc, char **argv)
{
    const char *file = NULL, *at_text = NULL, *params_text = NULL, *format = "json";
    int order = 4, method = IC_METHOD_AUTO;
    ic_local_options opt;
    ic_local_defaults(&opt);
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            fputs(POINT_HELP, stdout);
            return 0;
        }
        const int has_value = i + 1 < argc;
        if (strcmp(argv[i], "--at") == 0 && has_value)
            at_text = argv[++i];
        else if (strcmp(argv[i], "--params") == 0 && has_value)
            params_text = argv[++i];
        else if (strcmp(argv[i], "--order") == 0 && has_value) {
            if (ic_cli_parse_int(&order, argv[++i], 1, IC_LOCAL_MAX_ORDER, "--order") < 0)
                return EXIT_INPUT;
        } else if (strcmp(argv[i], "--method") == 0 && has_value) {
            method = ic_method_from_name(argv[++i]);
            if (method < 0) {
                fprintf(stderr,
                        "intercurve point: --method expects auto, jet, closed-form or "
                        "perturbation, got '%s'\n",
                        argv[i]);
                return EXIT_INPUT;
            }
        } else if (strcmp(argv[i], "--format") == 0 && has_value) {
            format = argv[++i];
            if (strcmp(format, "json") != 0 && strcmp(format, "text") != 0) {
                fprintf(stderr, "intercurve point: --format expects json or text, got '%s'\n",
                        format);
                return EXIT_INPUT;
            }
        } else if (strcmp(argv[i], "--point-tol") == 0 && has_value) {
            double v;
            if (ic_cli_parse_list(&v, 1, argv[++i], "--point-tol") != 1 || !(v > 0)) {
                fprintf(stderr, "intercurve point: --point-tol expects a positive length\n");
                return EXIT_INPUT;
            }
            opt.point_tol = v;
        } else if (argv[i][0] == '-' && argv[i][1] != '\0') {
            fprintf(stderr,
                    "intercurve point: unknown option or missing value: %s\n"
                    "try 'intercurve point --help'\n",
                    argv[i]);
            return EXIT_INPUT;
        } else if (!file)
            file = argv[i];
        else {
            fprintf(stderr, "intercurve point: unexpected argument '%s'\n", argv[i]);
            return EXIT_INPUT;
        }
    }
    if (!file || (!at_text == !params_text)) {
        fprintf(stderr, "intercurve point: needs PROBLEM.json and one of --at or --params\n%s",
                POINT_HELP);
        return EXIT_INPUT;
    }
    ic_error err;
    ic_error_clear(&err);
    ic_problem *p = NULL;
    ic_pair *pair = NULL;
    if (ic_problem_load(&p, file, &err) != IC_OK) {
        ic_cli_print_error(file, &err);
        return EXIT_INPUT;
    }
    int rc = EXIT_INPUT;
    double values[4];
    const int count = ic_cli_parse_list(values, at_text ? 3 : 4, at_text ? at_text : params_text,
                                        at_text ? "--at" : "--params");
    if (count < 0)
        goto cleanup;
    if (at_text && count != 3) {
        fprintf(stderr, "intercurve point: --at needs three coordinates X,Y,Z, got %d\n", count);
        goto cleanup;
    }
    const int self = ic_problem_is_self(p);
    if (ic_pair_new(&pair, ic_problem_surface(p, 0), self ? NULL : ic_problem_surface(p, 1),
                    &err) != IC_OK) {
        ic_cli_print_error(file, &err);
        goto cleanup;
    }
    ic_local_point pt;
    rc = locate_point(file, pair, &pt, values, count, !at_text, &opt);
    if (rc != 0)
        goto cleanup;
    rc = EXIT_INPUT;
    ic_local_result res;
    ic_status st = ic_local_apparatus(pair, &res, &pt, order, (ic_method)method, &opt, &err);
    if (st != IC_OK) {
        ic_cli_print_error(file, &err);
        rc = st == IC_ERR_INVALID ? EXIT_INPUT : EXIT_COMPUTE;
        goto cleanup;
    }
    if (strcmp(format, "text") == 0) {
        print_text(&res);
        rc = fflush(stdout) == 0 ? 0 : EXIT_COMPUTE;
    } else {
        rc = ic_json_print(result_json(&res, pair, order)) == 0 ? 0 : EXIT_COMPUTE;
    }
cleanup:
    ic_pair_free(pair);
    ic_problem_free(p);
    return rc;
}
