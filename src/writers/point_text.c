/* `intercurve point --format text`: one point of an intersection for
 * people, 15 significant digits (docs/output-formats.md). */
#include "common/args.h"
#include "intercurve/writers.h"

#include <math.h>

static void text_vector(FILE *f, const char *name, const double *v, int defined)
{
    if (defined)
        fprintf(f, "  %-12s (% .15g, % .15g, % .15g)\n", name, v[0] + 0.0, v[1] + 0.0, v[2] + 0.0);
    else
        fprintf(f, "  %-12s undefined\n", name);
}

static void text_branch(FILE *f, const ic_branch *br, int index)
{
    fprintf(f, "branch %d%s\n", index + 1,
            br->regular ? "" : " (cusp half-branch: one-sided limits)");
    text_vector(f, "t", br->t, 1);
    text_vector(f, "n", br->n, br->frame_defined);
    text_vector(f, "b", br->b, br->frame_defined);
    if (br->order >= 2)
        fprintf(f, "  %-12s %.15g\n", "kappa", br->kappa);
    else if (!br->regular)
        fprintf(f, "  %-12s infinite (a cusp)\n", "kappa");
    if (br->tau_defined)
        fprintf(f, "  %-12s %.15g\n", "tau", br->tau + 0.0);
    if (br->kappa_prime_defined)
        fprintf(f, "  %-12s %.15g\n", "kappa'", br->kappa_prime);
    if (br->tau_prime_defined)
        fprintf(f, "  %-12s %.15g\n", "tau'", br->tau_prime);
    for (int k = 0; k < br->order; k++) {
        char name[16];
        snprintf(name, sizeof name, "c^(%d)", k + 1);
        text_vector(f, name, br->derivs[k], 1);
    }
    for (int s = 0; s < 2 && br->order >= 2; s++)
        fprintf(f, "  surface %c    kappa_n %.15g  kappa_g %.15g  tau_g %.15g\n", 'A' + s,
                br->surface[s].kappa_n, br->surface[s].kappa_g, br->surface[s].tau_g);
}

ic_status ic_local_write_text(FILE *f, const ic_local_result *res, ic_error *err)
{
    IC_ARG_NOT_NULL(f, "f");
    IC_ARG_NOT_NULL(res, "res");
    fprintf(f, "point        (%.15g, %.15g, %.15g)  residual %.3g\n", res->point.xyz[0],
            res->point.xyz[1], res->point.xyz[2], res->point.residual);
    fprintf(f, "type         %s (angle between the normals %.6g rad), method %s\n",
            ic_point_type_name(res->type), res->angle, ic_method_name(res->method));
    if (!isnan(res->discriminant))
        fprintf(f, "discriminant %.15g%s\n", res->discriminant,
                res->nbranches ? "" : "  (no branch: an isolated point)");
    for (int i = 0; i < res->nbranches; i++)
        text_branch(f, &res->branches[i], i);
    return ferror(f) ? ic_error_set(err, IC_ERR_IO, 0, "writing the point's text output failed")
                     : IC_OK;
}
