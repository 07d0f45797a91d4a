/* The listing of `intercurve surfaces` (docs/cad-files.md, "Listing a
 * file"): every surface of a CAD file as text lines or as JSON. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cad.h"
#include "cad_write.h"
#include "json/json_out.h"

static const char *kind_name(const ic_cad_surface *s)
{
    static const char *const prims[] = {"plane", "sphere", "cylinder", "cone", "torus",
                                        "ellipsoid"};
    if (!s->supported)
        return "not read";
    if (s->is_nurbs)
        return s->nurbs.weights ? "rational nurbs" : "nurbs";
    return prims[s->prim.kind];
}

/* "[0, 1]", "[0, 6.28319) periodic", "unbounded" */
static void range_text(char *out, size_t size, const double r[2], int periodic)
{
    if (isinf(r[0]) || isinf(r[1]))
        snprintf(out, size, "unbounded");
    else
        snprintf(out, size, "[%.10g, %.10g]%s", r[0], r[1], periodic ? " periodic" : "");
}

/* What the kind's numbers are, for a text line. */
static void detail_text(char *out, size_t size, const ic_cad_surface *s)
{
    const ic_primitive *p = &s->prim;
    if (!s->supported)
        snprintf(out, size, "not read: %s", s->problem);
    else if (s->is_nurbs)
        snprintf(out, size, "degree %d x %d, %d x %d control points", s->nurbs.degree[0],
                 s->nurbs.degree[1], s->nurbs.count[0], s->nurbs.count[1]);
    else if (p->kind == IC_PRIM_PLANE)
        snprintf(out, size, "point (%.10g, %.10g, %.10g), normal (%.10g, %.10g, %.10g)",
                 p->center[0], p->center[1], p->center[2], p->normal[0], p->normal[1],
                 p->normal[2]);
    else
        snprintf(out, size, "%s (%.10g, %.10g, %.10g), axis (%.10g, %.10g, %.10g)%s%.10g",
                 p->kind == IC_PRIM_CONE ? "apex" : "center", p->center[0], p->center[1],
                 p->center[2], p->axis[0], p->axis[1], p->axis[2],
                 p->kind == IC_PRIM_CONE ? ", half-angle " : ", radius ",
                 p->kind == IC_PRIM_CONE ? p->half_angle : p->radius);
    if (s->supported && !s->is_nurbs && p->kind == IC_PRIM_TORUS) {
        const size_t used = strlen(out);
        snprintf(out + used, size - used, ", major radius %.10g", p->major_radius);
    }
}

static ic_status write_text(FILE *f, const char *file, const ic_cad_info *info,
                            const ic_cad_surface *list, int n, ic_error *err)
{
    const char *format = ic_cad_format_name(info->format);
    char unit[64] = "not stated";
    if (info->unit[0] && info->unit_metres > 0)
        snprintf(unit, sizeof unit, "%s (%.10g m)", info->unit, info->unit_metres);
    else if (info->unit[0])
        snprintf(unit, sizeof unit, "%s (size unknown)", info->unit);
    int readable = 0;
    for (int k = 0; k < n; k++)
        readable += list[k].supported;
    fprintf(f, "%s: %s file, length unit %s, %d surface%s (%d readable)\n", file, format, unit, n,
            n == 1 ? "" : "s", readable);
    for (int k = 0; k < n; k++) {
        const ic_cad_surface *s = &list[k];
        char u[80] = "", v[80] = "", detail[400];
        if (s->supported) {
            range_text(u, sizeof u, s->domain[0], s->periodic[0]);
            range_text(v, sizeof v, s->domain[1], s->periodic[1]);
        }
        detail_text(detail, sizeof detail, s);
        fprintf(f, "%s%d  %s  \"%s\"", info->format == IC_CAD_STEP ? "#" : "DE ", s->entity,
                s->type, s->name);
        if (s->supported)
            fprintf(f, "  %s  u %s  v %s", kind_name(s), u, v);
        fprintf(f, "  %s\n", detail);
    }
    if (ferror(f))
        return ic_error_set(err, IC_ERR_IO, 0, "writing the surfaces listing failed");
    return IC_OK;
}

static void range_json(json_out *j, const double r[2])
{
    if (isinf(r[0]) || isinf(r[1]))
        ic_json_out_null(j);
    else
        ic_json_out_vector(j, r, 2);
}

static void number_member(json_out *j, const char *key, double x)
{
    ic_json_out_key(j, key);
    ic_json_out_number(j, x);
}

static void vector_member(json_out *j, const char *key, const double v[3])
{
    ic_json_out_key(j, key);
    ic_json_out_vector(j, v, 3);
}

static void string_member(json_out *j, const char *key, const char *text)
{
    ic_json_out_key(j, key);
    ic_json_out_string(j, text);
}

static void add_primitive(json_out *j, const ic_primitive *p)
{
    vector_member(j, p->kind == IC_PRIM_CONE ? "apex" : "center", p->center);
    vector_member(j, "axis", p->axis);
    vector_member(j, "ref_direction", p->ref_direction);
    if (p->kind == IC_PRIM_SPHERE || p->kind == IC_PRIM_CYLINDER)
        number_member(j, "radius", p->radius);
    if (p->kind == IC_PRIM_TORUS) {
        number_member(j, "major_radius", p->major_radius);
        number_member(j, "minor_radius", p->radius);
    }
    if (p->kind == IC_PRIM_CONE)
        number_member(j, "half_angle", p->half_angle);
}

/* What a readable surface is: its domain, periodicity and form. */
static void add_supported(json_out *j, const ic_cad_surface *s)
{
    ic_json_out_key(j, "domain");
    ic_json_out_array(j);
    for (int d = 0; d < 2; d++)
        range_json(j, s->domain[d]);
    ic_json_out_end_array(j);
    ic_json_out_key(j, "periodic");
    ic_json_out_array(j);
    for (int d = 0; d < 2; d++)
        ic_json_out_bool(j, s->periodic[d]);
    ic_json_out_end_array(j);
    if (s->is_nurbs) {
        ic_json_out_key(j, "degree");
        ic_json_out_ints(j, s->nurbs.degree, 2);
        ic_json_out_key(j, "count");
        ic_json_out_ints(j, s->nurbs.count, 2);
        ic_json_out_key(j, "rational");
        ic_json_out_bool(j, s->nurbs.weights != NULL);
    } else if (s->prim.kind == IC_PRIM_PLANE) {
        vector_member(j, "point", s->prim.center);
        vector_member(j, "normal", s->prim.normal);
        vector_member(j, "ref_direction", s->prim.ref_direction);
    } else {
        add_primitive(j, &s->prim);
    }
}

static void surface_json(json_out *j, const ic_cad_surface *s)
{
    ic_json_out_object(j);
    ic_json_out_key(j, "entity");
    ic_json_out_int(j, s->entity);
    string_member(j, "type", s->type);
    string_member(j, "name", s->name);
    ic_json_out_key(j, "supported");
    ic_json_out_bool(j, s->supported);
    string_member(j, "kind", kind_name(s));
    if (s->supported)
        add_supported(j, s);
    else
        string_member(j, "problem", s->problem);
    ic_json_out_end_object(j);
}

static ic_status write_json(FILE *f, const char *file, const ic_cad_info *info,
                            const ic_cad_surface *list, int n, ic_error *err)
{
    json_out j;
    ic_json_out_start(&j, f);
    ic_json_out_object(&j);
    string_member(&j, "file", file);
    string_member(&j, "format", ic_cad_format_name(info->format));
    ic_json_out_key(&j, "unit");
    if (info->unit[0])
        ic_json_out_string(&j, info->unit);
    else
        ic_json_out_null(&j);
    ic_json_out_key(&j, "unit_in_metres");
    if (info->unit_metres > 0)
        ic_json_out_number(&j, info->unit_metres);
    else
        ic_json_out_null(&j);
    ic_json_out_key(&j, "surfaces");
    ic_json_out_array(&j);
    for (int k = 0; k < n; k++)
        surface_json(&j, &list[k]);
    ic_json_out_end_array(&j);
    ic_json_out_end_object(&j);
    return ic_json_out_finish(&j, "surfaces", err);
}

ic_status ic_cad_write_list(FILE *f, const char *file, const ic_cad_info *info,
                            const ic_cad_surface *list, int n, int json, ic_error *err)
{
    return json ? write_json(f, file, info, list, n, err) : write_text(f, file, info, list, n, err);
}
