/*
 * Placement of primitives (surface.h, ic_primitive_frame): the local frame
 * (e1, e2, e3) from a primitive's axis and ref_direction (a plane's normal),
 * and the rotations between local coordinates and space on jets and on
 * intervals. Space x and local coordinates L are related by
 * x = center + sum_j L_j e_j, so L_j = e_j . (x - center).
 */
#include "common/args.h"
#include "surface_internal.h"

#include <float.h>
#include <math.h>

static int all_zero(const double v[3]) { return v[0] == 0.0 && v[1] == 0.0 && v[2] == 0.0; }

static int all_finite(const double v[3])
{
    return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]);
}

static double dot(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

/* u = v / |v| for a finite nonzero v. The plain sum of squares unless it
 * overflows or falls below DBL_MIN (where its rounding is coarse): then v
 * scaled by its largest component first. */
static void normalize(const double v[3], double u[3])
{
    const double len2 = dot(v, v);
    double w[3] = {v[0], v[1], v[2]};
    if (!(isfinite(len2) && len2 >= DBL_MIN)) {
        const double m = fmax(fabs(v[0]), fmax(fabs(v[1]), fabs(v[2])));
        for (int i = 0; i < 3; i++)
            w[i] = v[i] / m;
    }
    const double len = sqrt(dot(w, w));
    for (int i = 0; i < 3; i++)
        u[i] = w[i] / len;
}

/* The default e1: the coordinate axis least aligned with e3 (the first in a
 * tie), made normal to it; x for e3 = z. */
static void default_e1(const double e3[3], double e1[3])
{
    int k = 0;
    for (int i = 1; i < 3; i++)
        if (fabs(e3[i]) < fabs(e3[k]))
            k = i;
    double a[3] = {0, 0, 0};
    a[k] = 1.0;
    const double along = e3[k];
    double norm = 0.0;
    for (int i = 0; i < 3; i++) {
        e1[i] = a[i] - along * e3[i];
        norm += e1[i] * e1[i];
    }
    norm = sqrt(norm);
    for (int i = 0; i < 3; i++)
        e1[i] /= norm;
}

/* e1 from ref made normal to e3; 0 when ref is within
 * IC_PRIMITIVE_REF_MIN_ANGLE of +-e3. */
static int ref_e1(const double ref[3], const double e3[3], double e1[3])
{
    double r[3];
    normalize(ref, r);
    for (int pass = 0; pass < 2; pass++) {
        /* the second pass removes what rounding left along e3 */
        const double along = dot(r, e3);
        for (int i = 0; i < 3; i++)
            e1[i] = r[i] - along * e3[i];
        const double sine = sqrt(dot(e1, e1)); /* first pass: sin(angle(ref, e3)) */
        if (pass == 0 && !(sine > sin(IC_PRIMITIVE_REF_MIN_ANGLE)))
            return 0;
        for (int i = 0; i < 3; i++)
            r[i] = e1[i] = e1[i] / sine;
    }
    return 1;
}

static const char *kind_name(ic_primitive_kind kind)
{
    static const char *const names[] = {"plane", "sphere", "cylinder",
                                        "cone",  "torus",  "ellipsoid"};
    return (int)kind >= 0 && (int)kind < 6 ? names[kind] : "primitive";
}

/* e3 of the frame, or an error; *standard when the axis is absent. */
static ic_status frame_axis(const ic_primitive *p, double e3[3], int *standard, ic_error *err)
{
    const char *name = kind_name(p->kind);
    *standard = 0;
    if (p->kind == IC_PRIM_PLANE) {
        if (!all_zero(p->axis))
            return ic_error_set(err, IC_ERR_INVALID, 0,
                                "plane: a plane takes no axis, its normal places it");
        if (!all_finite(p->normal))
            return ic_error_set(err, IC_ERR_INVALID, 0, "plane: the normal is not finite");
        if (all_zero(p->normal))
            return ic_error_set(err, IC_ERR_INVALID, 0, "plane: the normal is zero");
        normalize(p->normal, e3);
        return IC_OK;
    }
    if (!all_finite(p->axis))
        return ic_error_set(err, IC_ERR_INVALID, 0, "%s: the axis is not finite", name);
    if (all_zero(p->axis)) {
        if (!all_zero(p->ref_direction))
            return ic_error_set(err, IC_ERR_INVALID, 0,
                                "%s: the axis is zero but a ref_direction is given (the axis "
                                "needs a direction; both zero is the standard position)",
                                name);
        *standard = 1;
        return IC_OK;
    }
    normalize(p->axis, e3);
    return IC_OK;
}

ic_status ic_primitive_frame(const ic_primitive *p, double frame[3][3], ic_error *err)
{
    IC_ARG_NOT_NULL(p, "prim");
    IC_ARG_NOT_NULL(frame, "frame");
    double *e1 = frame[0], *e2 = frame[1], *e3 = frame[2];
    if (!all_finite(p->ref_direction))
        return ic_error_set(err, IC_ERR_INVALID, 0, "%s: the ref_direction is not finite",
                            kind_name(p->kind));
    int standard;
    ic_status st = frame_axis(p, e3, &standard, err);
    if (st != IC_OK)
        return st;
    if (standard) {
        for (int j = 0; j < 3; j++)
            for (int k = 0; k < 3; k++)
                frame[j][k] = j == k ? 1.0 : 0.0;
        return IC_OK;
    }
    if (all_zero(p->ref_direction))
        default_e1(e3, e1);
    else if (!ref_e1(p->ref_direction, e3, e1))
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            "%s: the ref_direction is parallel to the %s (within %g radians); "
                            "it must point away from it",
                            kind_name(p->kind), p->kind == IC_PRIM_PLANE ? "normal" : "axis",
                            IC_PRIMITIVE_REF_MIN_ANGLE);
    cross(e3, e1, e2);
    return IC_OK;
}

void ic_placement_jets_to_space(const double f[3][3], double *xyz, int n)
{
    for (int i = 0; i < n; i++) {
        const double l[3] = {xyz[i], xyz[n + i], xyz[2 * n + i]};
        for (int k = 0; k < 3; k++)
            xyz[k * n + i] = f[0][k] * l[0] + f[1][k] * l[1] + f[2][k] * l[2];
    }
}

void ic_placement_jets_to_local(const double f[3][3], double *const d[3], int n)
{
    for (int i = 0; i < n; i++) {
        const double x[3] = {d[0][i], d[1][i], d[2][i]};
        for (int j = 0; j < 3; j++)
            d[j][i] = dot(f[j], x);
    }
}

/* sum_j c_j v_j in interval arithmetic (outward rounded). */
static ic_interval interval_dot(const double c[3], const ic_interval v[3])
{
    ic_interval sum = ic_interval_mul((ic_interval){c[0], c[0]}, v[0]);
    for (int j = 1; j < 3; j++)
        sum = ic_interval_add(sum, ic_interval_mul((ic_interval){c[j], c[j]}, v[j]));
    return sum;
}

void ic_placement_interval_to_local(const double f[3][3], ic_interval d[3])
{
    const ic_interval x[3] = {d[0], d[1], d[2]};
    for (int j = 0; j < 3; j++)
        d[j] = interval_dot(f[j], x);
}

void ic_placement_interval_to_space(const double f[3][3], ic_interval v[3])
{
    const ic_interval l[3] = {v[0], v[1], v[2]};
    for (int k = 0; k < 3; k++) {
        const double column[3] = {f[0][k], f[1][k], f[2][k]};
        v[k] = interval_dot(column, l);
    }
}
