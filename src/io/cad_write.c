/* The listing of `intercurve surfaces` (docs/cad-files.md, "Listing a
 * file"): every surface of a CAD file as text lines or as JSON. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cad.h"
#include "cad_write.h"
#include "io/json_out.h"

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

static cJSON *range_json(json_out *j, const double r[2])
{
    if (isinf(r[0]) || isinf(r[1]))
        return cJSON_CreateNull();
    return ic_json_out_vector(j, r, 2);
}

static void add_primitive(json_out *j, cJSON *o, const ic_primitive *p)
{
    ic_json_out_add(j, o, p->kind == IC_PRIM_CONE ? "apex" : "center",
                    ic_json_out_vector(j, p->center, 3));
    ic_json_out_add(j, o, "axis", ic_json_out_vector(j, p->axis, 3));
    ic_json_out_add(j, o, "ref_direction", ic_json_out_vector(j, p->ref_direction, 3));
    if (p->kind == IC_PRIM_SPHERE || p->kind == IC_PRIM_CYLINDER)
        ic_json_out_add(j, o, "radius", ic_json_out_number(j, p->radius));
    if (p->kind == IC_PRIM_TORUS) {
        ic_json_out_add(j, o, "major_radius", ic_json_out_number(j, p->major_radius));
        ic_json_out_add(j, o, "minor_radius", ic_json_out_number(j, p->radius));
    }
    if (p->kind == IC_PRIM_CONE)
        ic_json_out_add(j, o, "half_angle", ic_json_out_number(j, p->half_angle));
}

static cJSON *surface_json(json_out *j, const ic_cad_surface *s)
{
    cJSON *o = cJSON_CreateObject();
    ic_json_out_add(j, o, "entity", cJSON_CreateNumber(s->entity));
    ic_json_out_add(j, o, "type", cJSON_CreateString(s->type));
    ic_json_out_add(j, o, "name", cJSON_CreateString(s->name));
    ic_json_out_add(j, o, "supported", cJSON_CreateBool(s->supported));
    ic_json_out_add(j, o, "kind", cJSON_CreateString(kind_name(s)));
    if (!s->supported) {
        ic_json_out_add(j, o, "problem", cJSON_CreateString(s->problem));
        return o;
    }
    cJSON *domain = cJSON_CreateArray();
    for (int d = 0; d < 2; d++)
        ic_json_out_append(j, domain, range_json(j, s->domain[d]));
    ic_json_out_add(j, o, "domain", domain);
    cJSON *periodic = cJSON_CreateArray();
    for (int d = 0; d < 2; d++)
        ic_json_out_append(j, periodic, cJSON_CreateBool(s->periodic[d]));
    ic_json_out_add(j, o, "periodic", periodic);
    if (s->is_nurbs) {
        ic_json_out_add(j, o, "degree", cJSON_CreateIntArray(s->nurbs.degree, 2));
        ic_json_out_add(j, o, "count", cJSON_CreateIntArray(s->nurbs.count, 2));
        ic_json_out_add(j, o, "rational", cJSON_CreateBool(s->nurbs.weights != NULL));
    } else if (s->prim.kind == IC_PRIM_PLANE) {
        ic_json_out_add(j, o, "point", ic_json_out_vector(j, s->prim.center, 3));
        ic_json_out_add(j, o, "normal", ic_json_out_vector(j, s->prim.normal, 3));
        ic_json_out_add(j, o, "ref_direction", ic_json_out_vector(j, s->prim.ref_direction, 3));
    } else {
        add_primitive(j, o, &s->prim);
    }
    return o;
}

static ic_status write_json(FILE *f, const char *file, const ic_cad_info *info,
                            const ic_cad_surface *list, int n, ic_error *err)
{
    json_out j = {0};
    cJSON *doc = cJSON_CreateObject();
    ic_json_out_add(&j, doc, "file", cJSON_CreateString(file));
    ic_json_out_add(&j, doc, "format", cJSON_CreateString(ic_cad_format_name(info->format)));
    ic_json_out_add(&j, doc, "unit",
                    info->unit[0] ? cJSON_CreateString(info->unit) : cJSON_CreateNull());
    ic_json_out_add(&j, doc, "unit_in_metres",
                    info->unit_metres > 0 ? ic_json_out_number(&j, info->unit_metres)
                                          : cJSON_CreateNull());
    cJSON *surfaces = cJSON_CreateArray();
    for (int k = 0; k < n; k++)
        ic_json_out_append(&j, surfaces, surface_json(&j, &list[k]));
    ic_json_out_add(&j, doc, "surfaces", surfaces);
    return ic_json_out_write(f, doc, &j, "surfaces", err);
}

ic_status ic_cad_write_list(FILE *f, const char *file, const ic_cad_info *info,
                            const ic_cad_surface *list, int n, int json, ic_error *err)
{
    return json ? write_json(f, file, info, list, n, err) : write_text(f, file, info, list, n, err);
}
