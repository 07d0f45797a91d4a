/* The C API in a few lines: a surface from formulas, its geometry at a
 * point, and a curve on it as a jet. Built and run by `make test`. */
#include <stdio.h>

#include "intercurve.h"

int main(void)
{
    const char *xyz[3] = {"(R + r*cos(v))*cos(u)", "(R + r*cos(v))*sin(u)", "r*sin(v)"};
    const ic_constant consts[2] = {{"R", 2.0}, {"r", 0.5}};
    ic_surface *torus = NULL;
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
    rc = 0;
cleanup:
    if (rc)
        fprintf(stderr, "error: %s\n", err.message);
    ic_jet_space_free(sp);
    ic_surface_free(torus);
    return rc;
}
