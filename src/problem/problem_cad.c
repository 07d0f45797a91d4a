/* Surfaces of problem files read from CAD files (problem_cad.h,
 * docs/cad-files.md): {"type": "step" | "iges", "file", "entity", "form"}. */
#include "problem_cad.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cad/cad.h"

/* A primitive made from a file must give the file's points: at sample
 * parameters its point (parametric) or its distance |f| / |grad f|
 * (implicit) agrees with the file's parametrisation to this much relative
 * to the primitive's size (max(1, |center| + radii), the file's length
 * unit). The two compute the same sines and cosines: 1e-9 leaves room for
 * rounding at any size and catches any misplacement. */
#define CAD_PLACEMENT_TOL 1e-9

static ic_status at_path(ic_error *err, const char *path, ic_status code, const char *msg)
{
    ic_error_set_path(err, "%s", path);
    return ic_error_set(err, code, 0, "%s", msg);
}

/* "file" joined to base_dir (unless absolute), "entity" a whole number. */
static ic_status file_and_entity(char *file, size_t size, int *entity, const cJSON *js,
                                 const char *path, const char *base_dir, ic_error *err)
{
    char sub[IC_ERROR_PATH_LEN];
    snprintf(sub, sizeof sub, "%s.file", path);
    const cJSON *jf = cJSON_GetObjectItemCaseSensitive(js, "file");
    if (!cJSON_IsString(jf) || !jf->valuestring[0])
        return at_path(err, sub, IC_ERR_INVALID, "expected the name of a STEP or IGES file");
    const char *name = jf->valuestring;
    const int joined = name[0] == '/' || !base_dir || !base_dir[0]
                           ? snprintf(file, size, "%s", name)
                           : snprintf(file, size, "%s/%s", base_dir, name);
    if (joined < 0 || (size_t)joined >= size)
        return at_path(err, sub, IC_ERR_INVALID, "the file's path is too long");
    snprintf(sub, sizeof sub, "%s.entity", path);
    const cJSON *je = cJSON_GetObjectItemCaseSensitive(js, "entity");
    if (!cJSON_IsNumber(je) || je->valuedouble != floor(je->valuedouble) ||
        je->valuedouble < 1 || je->valuedouble > 2147483647.0)
        return at_path(err, sub, IC_ERR_INVALID,
                       "expected the entity's number: a STEP instance #N or an IGES "
                       "directory entry DE N (intercurve surfaces FILE lists them)");
    *entity = (int)je->valuedouble;
    return IC_OK;
}

/* The file's point at the primitive's parameters (u, v): its frame x =
 * ref_direction, y = axis x ref_direction, z = axis; the cone's v measured
 * from the apex (ic_primitive's). */
static void file_point(const ic_primitive *p, double u, double v, double X[3])
{
    const double *z = p->axis, *x = p->ref_direction;
    const double y[3] = {z[1] * x[2] - z[2] * x[1], z[2] * x[0] - z[0] * x[2],
                         z[0] * x[1] - z[1] * x[0]};
    double radial, height;
    switch (p->kind) {
    case IC_PRIM_SPHERE:
        radial = p->radius * cos(v), height = p->radius * sin(v);
        break;
    case IC_PRIM_CONE:
        radial = v * tan(p->half_angle), height = v;
        break;
    case IC_PRIM_TORUS:
        radial = p->major_radius + p->radius * cos(v), height = p->radius * sin(v);
        break;
    default: /* cylinder */
        radial = p->radius, height = v;
        break;
    }
    for (int k = 0; k < 3; k++)
        X[k] = p->center[k] + radial * (cos(u) * x[k] + sin(u) * y[k]) + height * z[k];
}

/* The surface follows the file's placement (see CAD_PLACEMENT_TOL). */
static int follows_placement(ic_surface *s, const ic_primitive *p, ic_surface_kind form)
{
    static const double at[3][2] = {{0.3, 0.2}, {2.1, -0.7}, {4.4, 1.1}};
    const double size = fmax(1, fabs(p->center[0]) + fabs(p->center[1]) + fabs(p->center[2]) +
                                    p->radius + p->major_radius + 2);
    for (int k = 0; k < 3; k++) {
        double X[3], got[3];
        file_point(p, at[k][0], at[k][1], X);
        double off;
        if (form == IC_PARAMETRIC) {
            if (ic_surface_eval(s, got, at[k], NULL) != IC_OK)
                return 0;
            off = fabs(got[0] - X[0]) + fabs(got[1] - X[1]) + fabs(got[2] - X[2]);
        } else {
            ic_surface_geometry g;
            if (ic_surface_normal_at(s, &g, X, NULL) != IC_OK)
                return 0;
            off = fabs(g.value) / g.normal_length;
        }
        if (!(off <= CAD_PLACEMENT_TOL * size))
            return 0;
    }
    return 1;
}

static ic_status make_primitive(ic_surface **s, const ic_cad_surface *d, ic_surface_kind form,
                                const char *who, ic_error *err)
{
    ic_status st = ic_surface_new_primitive(s, &d->prim, form, err);
    if (st != IC_OK) {
        char msg[IC_ERROR_MESSAGE_LEN];
        snprintf(msg, sizeof msg, "%s", err ? err->message : "");
        return ic_error_set(err, st, 0, "%s: %s", who, msg);
    }
    /* a plane is placed by its point and normal; the others must give the
     * file's own points (a check of the mapping of the file's placement) */
    if (d->prim.kind == IC_PRIM_PLANE || follows_placement(*s, &d->prim, form))
        return IC_OK;
    ic_surface_free(*s);
    *s = NULL;
    const double *a = d->prim.axis, *r = d->prim.ref_direction;
    return ic_error_set(err, IC_ERR_INVALID, 0,
                        "%s: placed with axis (%g, %g, %g) and ref_direction (%g, %g, %g), "
                        "the primitive made from it does not give the file's points (an "
                        "internal error: please report it with the file)",
                        who, a[0], a[1], a[2], r[0], r[1], r[2]);
}

static ic_status make_nurbs(ic_surface **s, const ic_cad_surface *d, const char *who,
                            ic_error *err)
{
    ic_status st = ic_surface_new_nurbs(s, &d->nurbs, err);
    if (st != IC_OK) {
        char msg[IC_ERROR_MESSAGE_LEN];
        snprintf(msg, sizeof msg, "%s%s%s", err && err->path[0] ? err->path : "",
                 err && err->path[0] ? ": " : "", err ? err->message : "");
        return ic_error_set(err, st, 0, "%s: %s", who, msg);
    }
    double domain[2][2];
    int periodic[2];
    ic_surface_get_domain(*s, domain, periodic);
    if (memcmp(domain, d->domain, sizeof domain) == 0)
        return IC_OK;
    /* IGES's U0..U1 x V0..V1 within the knots' range */
    return ic_surface_set_domain(*s, d->domain, d->periodic, err);
}

ic_status ic_problem_read_cad(ic_surface **s, const cJSON *js, const char *path,
                              const char *base_dir, int iges, ic_error *err)
{
    *s = NULL;
    char file[4096], sub[IC_ERROR_PATH_LEN];
    int entity = 0;
    ic_status st = file_and_entity(file, sizeof file, &entity, js, path, base_dir, err);
    if (st != IC_OK)
        return st;
    ic_surface_kind form = IC_PARAMETRIC;
    const cJSON *jform = cJSON_GetObjectItemCaseSensitive(js, "form");
    if (jform) {
        snprintf(sub, sizeof sub, "%s.form", path);
        if (cJSON_IsString(jform) && strcmp(jform->valuestring, "implicit") == 0)
            form = IC_IMPLICIT;
        else if (!(cJSON_IsString(jform) && strcmp(jform->valuestring, "parametric") == 0))
            return at_path(err, sub, IC_ERR_INVALID, "expected \"parametric\" or \"implicit\"");
    }
    ic_cad_surface d;
    int entity_fault;
    st = ic_cad_read_entity(file, iges ? IC_CAD_IGES : IC_CAD_STEP, entity, &d, &entity_fault,
                            err);
    if (st != IC_OK) {
        ic_error_set_path(err, "%s.%s", path, entity_fault ? "entity" : "file");
        return st;
    }
    char who[IC_ERROR_MESSAGE_LEN / 2];
    snprintf(who, sizeof who, "%s %s%d (%s)", file, iges ? "DE " : "#", d.entity, d.type);
    if (d.is_nurbs)
        st = form == IC_PARAMETRIC
                 ? make_nurbs(s, &d, who, err)
                 : ic_error_set(err, IC_ERR_INVALID, 0, "%s: a NURBS patch has no implicit form",
                                who);
    else
        st = make_primitive(s, &d, form, who, err);
    if (st != IC_OK)
        ic_error_set_path(err, "%s.entity", path);
    ic_cad_surface_clear(&d);
    return st;
}
