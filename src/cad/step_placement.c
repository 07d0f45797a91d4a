/* The points, directions and placements of a STEP file (step_surface.h):
 * CARTESIAN_POINT, DIRECTION and AXIS2_PLACEMENT_3D, which the elementary
 * surfaces (step_surface.c) and the B-spline patches (step_bspline.c) are
 * built on. */
#include <math.h>
#include <string.h>

#include "step_surface.h"

/* The instance a REF value names, checked to be of `type`; NULL after an
 * error saying what `what` of `who` should have been. */
static const ic_step_instance *follow(const ic_step_file *f, int v, const char *type,
                                      const char *what, const char *who, ic_error *err)
{
    const ic_step_instance *in = NULL;
    if (v >= 0 && f->values[v].kind == IC_STEP_REF)
        in = ic_step_find(f, f->values[v].u.ref);
    if (!in || in->complex || !ic_step_is(f, in->part, type)) {
        if (v >= 0 && f->values[v].kind == IC_STEP_REF)
            ic_cad_fail(err, who, "its %s #%d is %s, not a %s", what, (int)f->values[v].u.ref,
                        in ? "of another type" : "missing from the file", type);
        else
            ic_cad_fail(err, who, "its %s is not a reference to a %s", what, type);
        return NULL;
    }
    return in;
}

/* Three numbers from a list (CARTESIAN_POINT, DIRECTION). */
static ic_status triple(const ic_step_file *f, const ic_step_instance *in, double out[3],
                        const char *who, ic_error *err)
{
    const int list = ic_step_param(f, in->part, 1);
    if (list < 0 || f->values[list].kind != IC_STEP_LIST || f->values[list].count != 3)
        return ic_cad_fail(err, who, "#%d does not have three coordinates", (int)in->id);
    for (int k = 0; k < 3; k++)
        if (ic_step_number(f, ic_step_item(f, list, k), &out[k]) < 0)
            return ic_cad_fail(err, who, "#%d has a coordinate that is not a number", (int)in->id);
    return IC_OK;
}

ic_status ic_step_point(const ic_step_file *f, int v, double out[3], const char *who, ic_error *err)
{
    const ic_step_instance *in = follow(f, v, "CARTESIAN_POINT", "point", who, err);
    return in ? triple(f, in, out, who, err) : IC_ERR_INVALID;
}

/* A DIRECTION made unit; `fallback` when the value is $. */
static ic_status direction(const ic_step_file *f, int v, const double fallback[3], double out[3],
                           const char *what, const char *who, ic_error *err)
{
    if (v >= 0 && f->values[v].kind == IC_STEP_NULL) {
        memcpy(out, fallback, 3 * sizeof(double));
        return IC_OK;
    }
    const ic_step_instance *in = follow(f, v, "DIRECTION", what, who, err);
    if (!in || triple(f, in, out, who, err) != IC_OK)
        return IC_ERR_INVALID;
    const double len = sqrt(out[0] * out[0] + out[1] * out[1] + out[2] * out[2]);
    if (!(len > 0) || !isfinite(len))
        return ic_cad_fail(err, who, "its %s #%d has zero (or no finite) length", what,
                           (int)in->id);
    for (int k = 0; k < 3; k++)
        out[k] /= len;
    return IC_OK;
}

ic_status ic_step_placement(const ic_step_file *f, int v, ic_primitive *prim, const char *who,
                            ic_error *err)
{
    static const double Z[3] = {0, 0, 1}, X[3] = {1, 0, 0}, Y[3] = {0, 1, 0};
    const ic_step_instance *in = follow(f, v, "AXIS2_PLACEMENT_3D", "position", who, err);
    if (!in)
        return IC_ERR_INVALID;
    ic_status st = ic_step_point(f, ic_step_param(f, in->part, 1), prim->center, who, err);
    if (st == IC_OK)
        st = direction(f, ic_step_param(f, in->part, 2), Z, prim->axis, "axis", who, err);
    const double *z = prim->axis;
    const int along_x = fabs(fabs(z[0]) - 1) == 0;
    if (st == IC_OK)
        st = direction(f, ic_step_param(f, in->part, 3), along_x ? Y : X, prim->ref_direction,
                       "ref_direction", who, err);
    if (st != IC_OK)
        return st;
    double *x = prim->ref_direction;
    const double dot = x[0] * z[0] + x[1] * z[1] + x[2] * z[2];
    for (int k = 0; k < 3; k++)
        x[k] -= dot * z[k];
    const double len = sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    if (!(len > IC_STEP_PARALLEL_TOL))
        return ic_cad_fail(err, who, "its placement #%d has ref_direction along its axis",
                           (int)in->id);
    for (int k = 0; k < 3; k++)
        x[k] = x[k] / len + 0.0; /* + 0: no -0 */
    return IC_OK;
}
