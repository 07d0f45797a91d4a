/* Surfaces of a STEP file (cad_readers.h): the elementary surfaces with their
 * AXIS2_PLACEMENT_3D become placed primitives, B_SPLINE_SURFACE_WITH_KNOTS
 * (simple, or the complex rational form) a NURBS patch (step_bspline.c). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cad_internal.h"
#include "cad_readers.h"
#include "common/mathconst.h"
#include "step_surface.h"

/* The surface types of ISO 10303-42 a file may hold; the first five and
 * the B-spline with knots are read. */
static const char *const SURFACE_TYPES[] = {
    "PLANE", "CYLINDRICAL_SURFACE", "CONICAL_SURFACE", "SPHERICAL_SURFACE", "TOROIDAL_SURFACE",
    "B_SPLINE_SURFACE_WITH_KNOTS", "B_SPLINE_SURFACE", "RATIONAL_B_SPLINE_SURFACE",
    "BEZIER_SURFACE", "UNIFORM_SURFACE", "QUASI_UNIFORM_SURFACE", "DEGENERATE_TOROIDAL_SURFACE",
    "SURFACE_OF_REVOLUTION", "SURFACE_OF_LINEAR_EXTRUSION", "OFFSET_SURFACE",
    "RECTANGULAR_TRIMMED_SURFACE", "CURVE_BOUNDED_SURFACE", "RECTANGULAR_COMPOSITE_SURFACE",
    "ORIENTED_SURFACE", "SURFACE_REPLICA", NULL};

/* The simple instance's type (its only part). */
static void simple_type(const ic_step_file *f, const ic_step_instance *in, char *out, size_t size)
{
    ic_step_text(f, in->part, out, size);
}

int ic_step_surface_type(const ic_step_file *f, const ic_step_instance *in, char *type,
                         size_t size)
{
    if (in->complex) {
        if (ic_step_part(f, in, "B_SPLINE_SURFACE") >= 0) {
            snprintf(type, size, "%s",
                     ic_step_part(f, in, "RATIONAL_B_SPLINE_SURFACE") >= 0
                         ? "RATIONAL_B_SPLINE_SURFACE"
                         : ic_step_part(f, in, "B_SPLINE_SURFACE_WITH_KNOTS") >= 0
                             ? "B_SPLINE_SURFACE_WITH_KNOTS"
                             : "B_SPLINE_SURFACE");
            return 1;
        }
        for (int k = 0; SURFACE_TYPES[k]; k++)
            if (ic_step_part(f, in, SURFACE_TYPES[k]) >= 0) {
                snprintf(type, size, "%s", SURFACE_TYPES[k]);
                return 1;
            }
        return 0;
    }
    for (int k = 0; SURFACE_TYPES[k]; k++)
        if (ic_step_is(f, in->part, SURFACE_TYPES[k])) {
            simple_type(f, in, type, size);
            return 1;
        }
    return 0;
}

/* A positive length parameter k. */
static ic_status length(const ic_step_file *f, int part, int k, double *out, const char *what,
                        const char *who, ic_error *err)
{
    if (ic_step_number(f, ic_step_param(f, part, k), out) < 0)
        return ic_cad_fail(err, who, "its %s is not a number", what);
    if (!(*out > 0))
        return ic_cad_fail(err, who, "its %s %g is not positive", what, *out);
    return IC_OK;
}

static void full_turn(double domain[2], int *periodic)
{
    domain[0] = 0;
    domain[1] = 2 * IC_PI;
    *periodic = 1;
}

static void unbounded(double domain[2])
{
    domain[0] = -HUGE_VAL;
    domain[1] = HUGE_VAL;
}

/* CONICAL_SURFACE(name, position, radius, semi_angle) is
 * C + (r + v tan a)(cos u x + sin u y) + v z: radius r in the plane of the
 * placement, apex at v = -r / tan a. ic_primitive's cone has its apex at
 * `center`: center = C - (r / tan a) z, and its v is STEP's v + r / tan a. */
static ic_status cone(const ic_step_file *f, int part, double radians, ic_primitive *prim,
                      const char *who, ic_error *err)
{
    double r, a;
    if (ic_step_number(f, ic_step_param(f, part, 2), &r) < 0 || !(r >= 0))
        return ic_cad_fail(err, who, "its radius is not a number >= 0");
    if (ic_step_number(f, ic_step_param(f, part, 3), &a) < 0)
        return ic_cad_fail(err, who, "its semi_angle is not a number");
    a *= radians;
    if (!(a > 0 && a < IC_PI / 2))
        return ic_cad_fail(err, who, "its semi_angle %g rad is outside (0, pi/2)", a);
    prim->half_angle = a;
    const double offset = r / tan(a);
    for (int k = 0; k < 3; k++)
        prim->center[k] -= offset * prim->axis[k];
    return IC_OK;
}

/* The elementary surfaces: placement, then the kind's own numbers. */
static ic_status elementary(const ic_step_file *f, const ic_step_instance *in, double radians,
                            ic_cad_surface *out, const char *who, ic_error *err)
{
    const int part = in->part;
    ic_primitive *prim = &out->prim;
    ic_status st = ic_step_placement(f, ic_step_param(f, part, 1), prim, who, err);
    if (st != IC_OK)
        return st;
    if (ic_step_is(f, part, "PLANE")) {
        prim->kind = IC_PRIM_PLANE;
        memcpy(prim->normal, prim->axis, sizeof prim->normal);
        unbounded(out->domain[0]);
        unbounded(out->domain[1]);
    } else if (ic_step_is(f, part, "CYLINDRICAL_SURFACE")) {
        prim->kind = IC_PRIM_CYLINDER;
        st = length(f, part, 2, &prim->radius, "radius", who, err);
        full_turn(out->domain[0], &out->periodic[0]);
        unbounded(out->domain[1]);
    } else if (ic_step_is(f, part, "CONICAL_SURFACE")) {
        prim->kind = IC_PRIM_CONE;
        st = cone(f, part, radians, prim, who, err);
        full_turn(out->domain[0], &out->periodic[0]);
        unbounded(out->domain[1]);
    } else if (ic_step_is(f, part, "SPHERICAL_SURFACE")) {
        prim->kind = IC_PRIM_SPHERE;
        st = length(f, part, 2, &prim->radius, "radius", who, err);
        full_turn(out->domain[0], &out->periodic[0]);
        out->domain[1][0] = -IC_PI / 2;
        out->domain[1][1] = IC_PI / 2;
    } else { /* TOROIDAL_SURFACE(name, position, major_radius, minor_radius) */
        prim->kind = IC_PRIM_TORUS;
        st = length(f, part, 2, &prim->major_radius, "major_radius", who, err);
        if (st == IC_OK)
            st = length(f, part, 3, &prim->radius, "minor_radius", who, err);
        full_turn(out->domain[0], &out->periodic[0]);
        full_turn(out->domain[1], &out->periodic[1]);
    }
    return st;
}

static int is_elementary(const ic_step_file *f, const ic_step_instance *in)
{
    static const char *const kinds[] = {"PLANE", "CYLINDRICAL_SURFACE", "CONICAL_SURFACE",
                                        "SPHERICAL_SURFACE", "TOROIDAL_SURFACE"};
    for (size_t k = 0; k < sizeof kinds / sizeof kinds[0]; k++)
        if (!in->complex && ic_step_is(f, in->part, kinds[k]))
            return 1;
    return 0;
}

/* A face (ADVANCED_FACE, FACE_SURFACE: name, bounds, face_geometry,
 * same_sense) leads to its surface; its bounds are not read. */
static int face_surface(const ic_step_file *f, const ic_step_instance *in)
{
    if (in->complex ||
        !(ic_step_is(f, in->part, "ADVANCED_FACE") || ic_step_is(f, in->part, "FACE_SURFACE")))
        return -1;
    const int v = ic_step_param(f, in->part, 2);
    return v >= 0 && f->values[v].kind == IC_STEP_REF ? (int)f->values[v].u.ref : 0;
}

static ic_status read_surface(const ic_step_file *f, const ic_step_instance *in,
                              const ic_step_units *units, ic_cad_surface *out, ic_error *err)
{
    char who[96];
    ic_step_surface_type(f, in, out->type, sizeof out->type);
    snprintf(who, sizeof who, "#%d (%s)", (int)in->id, out->type);
    out->entity = in->id;
    const int name_part = in->complex ? ic_step_part(f, in, "REPRESENTATION_ITEM") : in->part;
    ic_step_text(f, ic_step_param(f, name_part, 0), out->name, sizeof out->name);
    snprintf(out->unit, sizeof out->unit, "%s", units->length);
    out->unit_metres = units->metres;
    if (is_elementary(f, in))
        return elementary(f, in, units->radians, out, who, err);
    if (in->complex ? ic_step_part(f, in, "B_SPLINE_SURFACE_WITH_KNOTS") >= 0
                    : ic_step_is(f, in->part, "B_SPLINE_SURFACE_WITH_KNOTS"))
        return ic_step_bspline(f, in, out, who, err);
    return ic_cad_fail(err, who,
                       "this surface type is not supported (read are PLANE, "
                       "CYLINDRICAL_SURFACE, CONICAL_SURFACE, SPHERICAL_SURFACE, "
                       "TOROIDAL_SURFACE and B_SPLINE_SURFACE_WITH_KNOTS, rational or not)");
}

static ic_status read_entity(const ic_step_file *f, int entity, const ic_step_units *units,
                             ic_cad_surface *out, ic_error *err)
{
    memset(out, 0, sizeof *out);
    const ic_step_instance *in = ic_step_find(f, entity);
    if (!in)
        return ic_error_set(err, IC_ERR_INVALID, 0, "#%d: no such instance in the file", entity);
    const int target = face_surface(f, in);
    if (target == 0)
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            "#%d: the face's face_geometry is not a reference", entity);
    if (target > 0 && !(in = ic_step_find(f, target)))
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            "#%d: the face's surface #%d is missing from the file", entity, target);
    char type[48];
    if (!ic_step_surface_type(f, in, type, sizeof type)) {
        ic_step_text(f, in->part, type, sizeof type);
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            "#%d is %s%s, not a surface (nor a face of one)", (int)in->id,
                            in->complex ? "a complex instance beginning " : "a ", type);
    }
    const ic_status st = read_surface(f, in, units, out, err);
    if (st != IC_OK)
        ic_cad_surface_clear(out);
    out->supported = st == IC_OK;
    return st;
}

ic_status ic_step_read(const ic_step_file *f, int entity, ic_cad_surface *out, ic_error *err)
{
    ic_step_units units;
    ic_step_find_units(f, &units);
    return read_entity(f, entity, &units, out, err);
}

ic_status ic_step_list(const ic_step_file *f, ic_cad_surface **list, int *n, ic_cad_info *info,
                       ic_error *err)
{
    int cap = 0;
    char type[48];
    ic_step_units units;
    ic_step_find_units(f, &units);
    snprintf(info->unit, sizeof info->unit, "%s", units.length);
    info->unit_metres = units.metres;
    for (int k = 0; k < f->ninst; k++) {
        if (!ic_step_surface_type(f, &f->inst[k], type, sizeof type))
            continue;
        ic_cad_surface s;
        ic_error why;
        ic_error_clear(&why);
        ic_status st = read_entity(f, f->inst[k].id, &units, &s, &why);
        if (st == IC_ERR_NOMEM)
            return ic_error_set(err, st, 0, "%s", why.message);
        if (st != IC_OK) { /* listed with the reason it cannot be read */
            s.entity = f->inst[k].id;
            snprintf(s.type, sizeof s.type, "%s", type);
            snprintf(s.problem, sizeof s.problem, "%s", why.message);
            const int name_part = f->inst[k].complex
                                      ? ic_step_part(f, &f->inst[k], "REPRESENTATION_ITEM")
                                      : f->inst[k].part;
            ic_step_text(f, ic_step_param(f, name_part, 0), s.name, sizeof s.name);
            snprintf(s.unit, sizeof s.unit, "%s", units.length);
            s.unit_metres = units.metres;
        }
        if ((st = ic_cad_list_append(list, n, &cap, &s, err)) != IC_OK)
            return st;
    }
    return IC_OK;
}
