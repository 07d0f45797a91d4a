/* A program outside the project, built against an installed intercurve by
 * tests/test_install.sh: it loads a problem file (cJSON inside the library),
 * computes the curvature of Viviani's curve at a point and draws the problem
 * (cairo inside the library).
 * usage: consumer examples/viviani.json OUT.svg */
#include <math.h>
#include <stdio.h>

#include <intercurve.h>

/* Viviani's curve (1 + cos t, sin t, 2 sin(t/2)) at t = pi/3, the point
 * (1.5, sqrt(3)/2, 1): kappa = |r' x r''| / |r'|^3 from its derivatives. */
static double viviani_kappa(void)
{
    const double t = acos(-1.0) / 3;
    const double d1[3] = {-sin(t), cos(t), cos(t / 2)};
    const double d2[3] = {-cos(t), -sin(t), -0.5 * sin(t / 2)};
    const double c[3] = {d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2],
                         d1[0] * d2[1] - d1[1] * d2[0]};
    const double speed = sqrt(d1[0] * d1[0] + d1[1] * d1[1] + d1[2] * d1[2]);
    return sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) / (speed * speed * speed);
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: consumer PROBLEM.json OUT.svg\n");
        return 2;
    }
    ic_problem *p = NULL;
    ic_pair *pair = NULL;
    ic_error err;
    int rc = 1;
    ic_error_clear(&err);
    if (ic_problem_load(&p, argv[1], &err) != IC_OK ||
        ic_pair_new(&pair, ic_problem_surface(p, 0), ic_problem_surface(p, 1), &err) != IC_OK)
        goto done;
    ic_local_options opt;
    ic_local_defaults(&opt);
    ic_local_point pt;
    ic_local_result res;
    const double at[3] = {1.5, sqrt(3.0) / 2, 1};
    if (ic_local_locate(pair, &pt, at, &opt, &err) != IC_OK ||
        ic_local_apparatus(pair, &res, &pt, 3, IC_METHOD_AUTO, &opt, &err) != IC_OK)
        goto done;
    const double want = viviani_kappa();
    printf("%s: kappa %.15g (want %.15g)\n", ic_problem_title(p), res.branches[0].kappa, want);
    /* the jet method's kappa agrees to rounding (docs/local.md) */
    if (!(fabs(res.branches[0].kappa - want) <= 1e-12)) {
        fprintf(stderr, "consumer: wrong curvature\n");
        goto done;
    }
    ic_plot_scene scene;
    ic_plot_options popt;
    ic_plot_scene_of_problem(&scene, p, NULL);
    ic_plot_defaults(&popt);
    popt.mesh = 8;
    if (ic_plot_write(argv[2], &scene, &popt, &err) != IC_OK)
        goto done;
    rc = 0;
done:
    if (rc && err.message[0])
        fprintf(stderr, "consumer: %s\n", err.message);
    ic_pair_free(pair);
    ic_problem_free(p);
    return rc;
}
