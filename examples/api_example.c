/* The C API in a few lines: a surface from formulas, its geometry at a
 * point, a curve on it as a jet, and a whole intersection traced. Built and
 * run by `make test`. */
#include <stdio.h>

#include "intercurve.h"

int main(void)
{
    const char *xyz[3] = {"(R + r*cos(v))*cos(u)", "(R + r*cos(v))*sin(u)", "r*sin(v)"};
    const ic_constant consts[2] = {{"R", 2.0}, {"r", 0.5}};
    ic_surface *torus = NULL, *A = NULL, *B = NULL;
    ic_pair *pair = NULL;
    ic_trace_result *res = NULL;
    ic_jet_space *sp = NULL;
    ic_error err;
    int rc = 1;
    if (ic_surface_new_parametric(&torus, xyz, NULL, consts, 2, NULL, &err) != IC_OK)
        goto cleanup;

    /* normal, fundamental forms, principal curvatures at (u, v) = (0.3, 0.4) */
    ic_surface_geometry g;
    const double at[2] = {0.3, 0.4};
    if (ic_surface_geometry_at(torus, &g, at, &err) != IC_OK)
        goto cleanup;
    printf("point (%.6f, %.6f, %.6f), principal curvatures %.6f %.6f\n", g.point[0], g.point[1],
           g.point[2], g.principal_curvatures[0], g.principal_curvatures[1]);

    /* the curve R(u(s), v(s)) with u = 0.3 + s, v = 0.4 + 2 s, to order 4 */
    if (ic_jet_space_new(&sp, 1, 4, &err) != IC_OK)
        goto cleanup;
    double u[5], v[5], c[15];
    ic_jet_set_var(u, 0.3, 0, sp);
    ic_jet_set_var(v, 0.4, 0, sp);
    v[1] = 2.0;
    const double *in[2] = {u, v};
    if (ic_surface_compose(torus, c, in, sp, &err) != IC_OK)
        goto cleanup;
    printf("x(s) = %.6f + %.6f s + %.6f s^2 + ...\n", c[0], c[1], c[2]);

    /* the whole intersection of the sphere of radius 2 and the plane z = 1,
     * searched in the box [-3, 3]^3: one closed circle of radius sqrt 3 */
    if (ic_surface_new_implicit(&A, "x^2 + y^2 + z^2 - 4", NULL, 0, &err) != IC_OK ||
        ic_surface_new_implicit(&B, "z - 1", NULL, 0, &err) != IC_OK ||
        ic_pair_new(&pair, A, B, &err) != IC_OK)
        goto cleanup;
    ic_trace_options opt;
    ic_trace_defaults(&opt);
    opt.has_box = 1;
    for (int k = 0; k < 3; k++)
        opt.box[k][0] = -3, opt.box[k][1] = 3;
    if (ic_trace(&res, pair, &opt, &err) != IC_OK)
        goto cleanup;
    for (int i = 0; i < ic_trace_result_num_curves(res); i++) {
        const ic_trace_curve *cv = ic_trace_result_curve(res, i);
        printf("curve %d: %s, %s, length %.12f, %d points\n", i, cv->closed ? "closed" : "open",
               ic_shape_name(cv->shape), cv->length, cv->npoints);
    }
    rc = 0;
cleanup:
    if (rc)
        fprintf(stderr, "error: %s\n", err.message);
    ic_trace_result_free(res);
    ic_pair_free(pair);
    ic_surface_free(A);
    ic_surface_free(B);
    ic_jet_space_free(sp);
    ic_surface_free(torus);
    return rc;
}
