/* intercurve point: the intersection's Frenet apparatus at one point. */
#include "cli/cli.h"
#include "common/vec3.h"

#include <math.h>
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
                   .fallback = "4",
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
                       .fallback = "1e-6",
                       .help = "how far from either surface the search for the point may\n"
                               "start (a length); farther is an error saying how far. It\n"
                               "widens the search only: the point found must pass the\n"
                               "surfaces' residual test, at most " STRINGIFY(
                                   ON_SURFACE_REL) " (1 + |X|) from both"},
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
                          ? IC_CLOSED_FORM_MAX_ORDER
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
