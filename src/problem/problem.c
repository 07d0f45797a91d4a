/* Problem files: reading and validating (problem.h, docs/problem-files.md). */
#include "common/args.h"
#include "intercurve/problem.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "intercurve/expr.h"
#include "json/json_path.h"
#include "problem_cad.h"
#include "problem_nurbs.h"

#define MAX_SURFACES 2
#define MAX_CONSTANTS 64
#define NAME_LEN 64
/* Largest magnitude of a coordinate (box bounds, a primitive's center,
 * normal and lengths) or a parameter bound, in the problem's units: lengths
 * are squared and summed (norms, r^2 in the equations, the plot's
 * diagonal), which overflows above sqrt(DBL_MAX) ~ 1.3e154; 1e150 leaves
 * room for sums and products of a few such terms. A positive length must
 * also be at least 1/MAX_MAGNITUDE, so 1/r^2 (an ellipsoid's equation)
 * stays finite. */
#define MAX_MAGNITUDE 1e150

struct ic_problem {
    char title[200];
    int nsurfaces;
    ic_surface *surfaces[MAX_SURFACES];
    char names[MAX_SURFACES][NAME_LEN];
    int self;
    int has_box;
    double box[3][2];
    ic_constant consts[MAX_CONSTANTS];
    char const_names[MAX_CONSTANTS][NAME_LEN];
    int nconsts;
    char base_dir[4096]; /* files a problem names are relative to this ("": here) */
};

typedef struct {
    const char *name;
    ic_primitive_kind kind;
} primitive_name;

static const primitive_name PRIMITIVES[] = {
    {"plane", IC_PRIM_PLANE},   {"sphere", IC_PRIM_SPHERE}, {"cylinder", IC_PRIM_CYLINDER},
    {"cone", IC_PRIM_CONE},     {"torus", IC_PRIM_TORUS},   {"ellipsoid", IC_PRIM_ELLIPSOID},
};

static ic_status invalid(ic_error *err, const char *path, const char *msg)
{
    ic_error_set_path(err, "%s", path);
    return ic_error_set(err, IC_ERR_INVALID, 0, "%s", msg);
}

/* A value beyond MAX_MAGNITUDE: its square, or the width of its interval,
 * would overflow. */
static ic_status too_large(ic_error *err, const char *path, double v)
{
    ic_error_set_path(err, "%s", path);
    return ic_error_set(err, IC_ERR_INVALID, 0,
                        "%g is too large: values must lie within +-%g, where their squares "
                        "and differences stay finite",
                        v, MAX_MAGNITUDE);
}

/* An interval [lo, hi] of a box or a domain: bounds within MAX_MAGNITUDE,
 * so hi - lo (and the squares of coordinates in it) stay finite. */
static ic_status check_bounds(const double iv[2], const char *path, ic_error *err)
{
    char sub[IC_ERROR_PATH_LEN];
    for (int k = 0; k < 2; k++)
        if (fabs(iv[k]) > MAX_MAGNITUDE) {
            snprintf(sub, sizeof sub, "%s[%d]", path, k);
            return too_large(err, sub, iv[k]);
        }
    return IC_OK;
}

static ic_status read_constants(ic_problem *p, const cJSON *obj, ic_error *err)
{
    if (!obj)
        return IC_OK;
    if (!cJSON_IsObject(obj))
        return invalid(err, "constants", "expected an object of name: value");
    for (const cJSON *it = obj->child; it; it = it->next) {
        char path[IC_ERROR_PATH_LEN];
        snprintf(path, sizeof path, "constants.%s", it->string);
        if (p->nconsts == MAX_CONSTANTS)
            return invalid(err, path, "too many constants (at most 64)");
        if (strlen(it->string) >= NAME_LEN)
            return invalid(err, path, "constant name too long");
        double v;
        /* a constant may use the ones before it */
        ic_status st = ic_json_number(&v, it, path, p->consts, p->nconsts, err);
        if (st != IC_OK)
            return st;
        strcpy(p->const_names[p->nconsts], it->string);
        p->consts[p->nconsts].name = p->const_names[p->nconsts];
        p->consts[p->nconsts].value = v;
        p->nconsts++;
        /* validate the name now, so the error points at it */
        ic_expr *probe = NULL;
        const char *one = "0";
        st = ic_expr_compile(&probe, &one, 1, NULL, 0, p->consts, p->nconsts, NULL, err);
        ic_expr_free(probe);
        if (st != IC_OK) {
            ic_error_set_path(err, "%s", path);
            return st;
        }
    }
    return IC_OK;
}

static const cJSON *need(const cJSON *obj, const char *key, const char *path, ic_error *err)
{
    const cJSON *it = cJSON_GetObjectItemCaseSensitive(obj, key);
    if (!it) {
        ic_error_set_path(err, "%s", path);
        ic_error_set(err, IC_ERR_INVALID, 0, "missing key \"%s\"", key);
    }
    return it;
}

/* A formula field: a string, or a number (written as a formula). */
static const char *formula_text(const cJSON *item, char *buf, size_t size)
{
    if (cJSON_IsString(item))
        return item->valuestring;
    if (cJSON_IsNumber(item)) {
        snprintf(buf, size, "%.17g", item->valuedouble);
        return buf;
    }
    return NULL;
}

/* The optional "domain" and "periodic" keys of a parametric surface, over
 * its current ones (unbounded, or a primitive's natural domain). */
static ic_status read_domain(ic_problem *p, ic_surface *s, const cJSON *js, const char *path,
                             ic_error *err)
{
    const cJSON *jd = cJSON_GetObjectItemCaseSensitive(js, "domain");
    const cJSON *jper = cJSON_GetObjectItemCaseSensitive(js, "periodic");
    if (!jd && !jper)
        return IC_OK;
    char sub[IC_ERROR_PATH_LEN];
    double domain[2][2];
    int periodic[2];
    ic_surface_get_domain(s, domain, periodic);
    if (jd) {
        snprintf(sub, sizeof sub, "%s.domain", path);
        if (!cJSON_IsArray(jd) || cJSON_GetArraySize(jd) != 2)
            return invalid(err, sub, "expected [[u0, u1], [v0, v1]]");
        for (int i = 0; i < 2; i++) {
            snprintf(sub, sizeof sub, "%s.domain[%d]", path, i);
            ic_status st = ic_json_numbers(domain[i], 2, cJSON_GetArrayItem(jd, i), sub,
                                           p->consts, p->nconsts, err);
            if (st == IC_OK)
                st = check_bounds(domain[i], sub, err);
            if (st != IC_OK)
                return st;
        }
    }
    if (jper) {
        snprintf(sub, sizeof sub, "%s.periodic", path);
        if (!cJSON_IsArray(jper) || cJSON_GetArraySize(jper) != 2 ||
            !cJSON_IsBool(cJSON_GetArrayItem(jper, 0)) ||
            !cJSON_IsBool(cJSON_GetArrayItem(jper, 1)))
            return invalid(err, sub, "expected two booleans, e.g. [false, true]");
        periodic[0] = cJSON_IsTrue(cJSON_GetArrayItem(jper, 0));
        periodic[1] = cJSON_IsTrue(cJSON_GetArrayItem(jper, 1));
    }
    ic_status st = ic_surface_set_domain(s, (const double(*)[2])domain, periodic, err);
    if (st != IC_OK)
        ic_error_set_path(err, "%s.domain", path);
    return st;
}

static ic_status read_parametric(ic_problem *p, ic_surface **s, const cJSON *js,
                                 const char *path, ic_error *err)
{
    static const char *const keys[] = {"name", "type", "params", "xyz", "domain", "periodic",
                                       NULL};
    char sub[IC_ERROR_PATH_LEN];
    ic_status st = ic_json_check_keys(js, path, keys, err);
    if (st != IC_OK)
        return st;
    const char *params[2] = {"u", "v"};
    const cJSON *jp = cJSON_GetObjectItemCaseSensitive(js, "params");
    if (jp) {
        snprintf(sub, sizeof sub, "%s.params", path);
        if (!cJSON_IsArray(jp) || cJSON_GetArraySize(jp) != 2 ||
            !cJSON_IsString(cJSON_GetArrayItem(jp, 0)) ||
            !cJSON_IsString(cJSON_GetArrayItem(jp, 1)))
            return invalid(err, sub, "expected two parameter names, e.g. [\"u\", \"v\"]");
        params[0] = cJSON_GetArrayItem(jp, 0)->valuestring;
        params[1] = cJSON_GetArrayItem(jp, 1)->valuestring;
    }
    const cJSON *jx = need(js, "xyz", path, err);
    if (!jx)
        return IC_ERR_INVALID;
    snprintf(sub, sizeof sub, "%s.xyz", path);
    if (!cJSON_IsArray(jx) || cJSON_GetArraySize(jx) != 3)
        return invalid(err, sub, "expected three formulas [x, y, z]");
    const char *xyz[3];
    char numbuf[3][40];
    for (int i = 0; i < 3; i++) {
        xyz[i] = formula_text(cJSON_GetArrayItem(jx, i), numbuf[i], sizeof numbuf[i]);
        if (!xyz[i]) {
            snprintf(sub, sizeof sub, "%s.xyz[%d]", path, i);
            return invalid(err, sub, "expected a formula string");
        }
    }
    int which = -1;
    st = ic_surface_new_parametric(s, xyz, params, p->consts, p->nconsts, &which, err);
    if (st != IC_OK) {
        if (which >= 0) {
            snprintf(sub, sizeof sub, "%s.xyz[%d]", path, which);
            return ic_json_formula_error(err, sub, xyz[which]);
        }
        snprintf(sub, sizeof sub, "%s.params", path);
        ic_error_set_path(err, "%s", sub);
        return st;
    }
    return read_domain(p, *s, js, path, err); /* absent: unbounded */
}

static ic_status read_implicit(ic_problem *p, ic_surface **s, const cJSON *js, const char *path,
                               ic_error *err)
{
    static const char *const keys[] = {"name", "type", "f", NULL};
    char sub[IC_ERROR_PATH_LEN], numbuf[40];
    ic_status st = ic_json_check_keys(js, path, keys, err);
    if (st != IC_OK)
        return st;
    const cJSON *jf = need(js, "f", path, err);
    if (!jf)
        return IC_ERR_INVALID;
    snprintf(sub, sizeof sub, "%s.f", path);
    const char *f = formula_text(jf, numbuf, sizeof numbuf);
    if (!f)
        return invalid(err, sub, "expected a formula string in x, y, z");
    st = ic_surface_new_implicit(s, f, p->consts, p->nconsts, err);
    if (st != IC_OK)
        return ic_json_formula_error(err, sub, f);
    return IC_OK;
}

/* The magnitude rule of a primitive's numbers: every one within
 * MAX_MAGNITUDE, a positive length (radii, axes) also at least its inverse.
 * Lengths that are not positive are left to the primitive's own message. */
static ic_status check_magnitudes(const double *v, int count, int is_length, const char *path,
                                  ic_error *err)
{
    char sub[IC_ERROR_PATH_LEN];
    for (int k = 0; k < count; k++) {
        if (count > 1)
            snprintf(sub, sizeof sub, "%s[%d]", path, k);
        else
            snprintf(sub, sizeof sub, "%s", path);
        if (fabs(v[k]) > MAX_MAGNITUDE)
            return too_large(err, sub, v[k]);
        if (is_length && v[k] > 0 && v[k] < 1 / MAX_MAGNITUDE) {
            ic_error_set_path(err, "%s", sub);
            return ic_error_set(err, IC_ERR_INVALID, 0,
                                "%g is too small: a length must be at least %g, where its "
                                "square and inverse square stay finite",
                                v[k], 1 / MAX_MAGNITUDE);
        }
    }
    return IC_OK;
}

/* A field of a primitive: one number (count 1) or an array of `count`;
 * is_length: radii and axes (see check_magnitudes). */
static ic_status prim_field(ic_problem *p, double *out, int count, int is_length, const cJSON *js,
                           const char *key, const char *path, int required, ic_error *err)
{
    char sub[IC_ERROR_PATH_LEN];
    const cJSON *it = cJSON_GetObjectItemCaseSensitive(js, key);
    if (!it) {
        if (!required)
            return IC_OK;
        ic_error_set_path(err, "%s", path);
        return ic_error_set(err, IC_ERR_INVALID, 0, "missing key \"%s\"", key);
    }
    snprintf(sub, sizeof sub, "%s.%s", path, key);
    ic_status st = count == 1 ? ic_json_number(out, it, sub, p->consts, p->nconsts, err)
                              : ic_json_numbers(out, count, it, sub, p->consts, p->nconsts, err);
    if (st != IC_OK)
        return st;
    return check_magnitudes(out, count, is_length, sub, err);
}

static int all_zero(const double v[3]) { return v[0] == 0.0 && v[1] == 0.0 && v[2] == 0.0; }

/* The optional placement keys "axis" and "ref_direction" (after the kind's
 * own keys: a plane's ref_direction is checked against its normal). An
 * absent axis is z; an absent ref_direction gets the default of
 * ic_primitive_frame. */
static ic_status read_placement(ic_problem *p, ic_primitive *prim, const cJSON *js,
                                const char *path, ic_error *err)
{
    char sub[IC_ERROR_PATH_LEN];
    const int has_axis = cJSON_GetObjectItemCaseSensitive(js, "axis") != NULL;
    const int has_ref = cJSON_GetObjectItemCaseSensitive(js, "ref_direction") != NULL;
    snprintf(sub, sizeof sub, "%s.axis", path);
    if (has_axis && prim->kind == IC_PRIM_PLANE)
        return invalid(err, sub, "a plane takes no axis: its \"normal\" places it");
    ic_status st = prim_field(p, prim->axis, 3, 0, js, "axis", path, 0, err);
    if (st != IC_OK)
        return st;
    if (has_axis && all_zero(prim->axis))
        return invalid(err, sub, "the axis is zero: give a direction, or leave \"axis\" out for z");
    snprintf(sub, sizeof sub, "%s.ref_direction", path);
    if ((st = prim_field(p, prim->ref_direction, 3, 0, js, "ref_direction", path, 0, err)))
        return st;
    if (!has_ref)
        return IC_OK;
    if (all_zero(prim->ref_direction))
        return invalid(err, sub,
                       "the ref_direction is zero: give a direction, or leave the key out for "
                       "the default");
    if (!has_axis && prim->kind != IC_PRIM_PLANE)
        prim->axis[2] = 1.0;
    if (prim->kind == IC_PRIM_PLANE && all_zero(prim->normal))
        return IC_OK; /* the plane's own message */
    double frame[3][3];
    st = ic_primitive_frame(prim, frame, err); /* the axis is valid: the ref is at fault */
    if (st != IC_OK)
        ic_error_set_path(err, "%s", sub);
    return st;
}

static ic_status read_primitive(ic_problem *p, ic_surface **s, const cJSON *js,
                                ic_primitive_kind kind, const char *path, ic_error *err)
{
    static const char *const keys[] = {
        "name",   "type",         "form",         "center",        "normal",
        "radius", "major_radius", "minor_radius", "half_angle",    "axes",
        "domain", "periodic",     "axis",         "ref_direction", NULL};
    ic_status st = ic_json_check_keys(js, path, keys, err);
    if (st != IC_OK)
        return st;
    ic_primitive prim;
    memset(&prim, 0, sizeof prim);
    prim.kind = kind;
    ic_surface_kind form = IC_IMPLICIT;
    char sub[IC_ERROR_PATH_LEN];
    const cJSON *jform = cJSON_GetObjectItemCaseSensitive(js, "form");
    if (jform) {
        snprintf(sub, sizeof sub, "%s.form", path);
        if (cJSON_IsString(jform) && strcmp(jform->valuestring, "parametric") == 0)
            form = IC_PARAMETRIC;
        else if (!(cJSON_IsString(jform) && strcmp(jform->valuestring, "implicit") == 0))
            return invalid(err, sub, "expected \"implicit\" or \"parametric\"");
    }
    if ((st = prim_field(p, prim.center, 3, 0, js, "center", path, 0, err)) != IC_OK)
        return st;
    switch (kind) {
    case IC_PRIM_PLANE:
        st = prim_field(p, prim.normal, 3, 0, js, "normal", path, 1, err);
        break;
    case IC_PRIM_SPHERE:
    case IC_PRIM_CYLINDER:
        st = prim_field(p, &prim.radius, 1, 1, js, "radius", path, 1, err);
        break;
    case IC_PRIM_CONE:
        st = prim_field(p, &prim.half_angle, 1, 0, js, "half_angle", path, 1, err);
        break;
    case IC_PRIM_TORUS:
        st = prim_field(p, &prim.major_radius, 1, 1, js, "major_radius", path, 1, err);
        if (st == IC_OK)
            st = prim_field(p, &prim.radius, 1, 1, js, "minor_radius", path, 1, err);
        break;
    case IC_PRIM_ELLIPSOID:
        st = prim_field(p, prim.axes, 3, 1, js, "axes", path, 1, err);
        break;
    }
    if (st == IC_OK)
        st = read_placement(p, &prim, js, path, err);
    if (st != IC_OK)
        return st;
    st = ic_surface_new_primitive(s, &prim, form, err);
    if (st != IC_OK) {
        ic_error_set_path(err, "%s", path);
        return st;
    }
    const int wants_domain = cJSON_GetObjectItemCaseSensitive(js, "domain") ||
                             cJSON_GetObjectItemCaseSensitive(js, "periodic");
    if (wants_domain && form != IC_PARAMETRIC)
        return invalid(err, path, "\"domain\" and \"periodic\" need \"form\": \"parametric\"");
    return read_domain(p, *s, js, path, err);
}

/* "type": "nurbs" (inline) or "geomdl" (from a NURBS-Python file), each
 * with an optional sub-"domain" (docs/nurbs.md). */
static ic_status read_nurbs(ic_problem *p, ic_surface **s, const cJSON *js, int geomdl,
                            const char *path, ic_error *err)
{
    static const char *const inline_keys[] = {"name",    "type",     "degree", "knots",
                                              "control_points", "weights", "periodic",
                                              "domain",  NULL};
    static const char *const file_keys[] = {"name", "type", "file", "index", "periodic",
                                            "domain", NULL};
    ic_status st = ic_json_check_keys(js, path, geomdl ? file_keys : inline_keys, err);
    if (st != IC_OK)
        return st;
    st = geomdl ? ic_problem_read_geomdl(s, js, path, p->base_dir, err)
                : ic_problem_read_nurbs(s, js, path, p->consts, p->nconsts, err);
    if (st != IC_OK)
        return st;
    return read_domain(p, *s, js, path, err);
}

/* "type": "step" or "iges": a surface of a CAD file (docs/cad-files.md),
 * with an optional "domain" and "periodic" as the other parametric ones. */
static ic_status read_cad(ic_problem *p, ic_surface **s, const cJSON *js, int iges,
                          const char *path, ic_error *err)
{
    static const char *const keys[] = {"name", "type", "file", "entity", "form",
                                       "domain", "periodic", NULL};
    ic_status st = ic_json_check_keys(js, path, keys, err);
    if (st == IC_OK)
        st = ic_problem_read_cad(s, js, path, p->base_dir, iges, err);
    if (st == IC_OK && ic_surface_get_kind(*s) != IC_PARAMETRIC &&
        (cJSON_GetObjectItemCaseSensitive(js, "domain") ||
         cJSON_GetObjectItemCaseSensitive(js, "periodic")))
        return invalid(err, path, "\"domain\" and \"periodic\" need the parametric form");
    return st == IC_OK ? read_domain(p, *s, js, path, err) : st;
}

static ic_status read_surface(ic_problem *p, int i, const cJSON *js, ic_error *err)
{
    char path[IC_ERROR_PATH_LEN];
    snprintf(path, sizeof path, "surfaces[%d]", i);
    if (!cJSON_IsObject(js))
        return invalid(err, path, "expected an object");
    const cJSON *jn = cJSON_GetObjectItemCaseSensitive(js, "name");
    if (jn) {
        if (!cJSON_IsString(jn) || jn->valuestring[0] == '\0' ||
            strlen(jn->valuestring) >= NAME_LEN) {
            snprintf(path, sizeof path, "surfaces[%d].name", i);
            return invalid(err, path, "expected a non-empty name of at most 63 characters");
        }
        strcpy(p->names[i], jn->valuestring);
    } else {
        strcpy(p->names[i], i == 0 ? "A" : "B");
    }
    for (int j = 0; j < i; j++)
        if (strcmp(p->names[j], p->names[i]) == 0) {
            snprintf(path, sizeof path, "surfaces[%d].name", i);
            return invalid(err, path, "two surfaces have the same name");
        }
    const cJSON *jt = need(js, "type", path, err);
    if (!jt)
        return IC_ERR_INVALID;
    const char *type = cJSON_IsString(jt) ? jt->valuestring : "";
    if (strcmp(type, "parametric") == 0)
        return read_parametric(p, &p->surfaces[i], js, path, err);
    if (strcmp(type, "implicit") == 0)
        return read_implicit(p, &p->surfaces[i], js, path, err);
    if (strcmp(type, "nurbs") == 0 || strcmp(type, "geomdl") == 0)
        return read_nurbs(p, &p->surfaces[i], js, type[0] == 'g', path, err);
    if (strcmp(type, "step") == 0 || strcmp(type, "iges") == 0)
        return read_cad(p, &p->surfaces[i], js, type[0] == 'i', path, err);
    for (size_t k = 0; k < sizeof PRIMITIVES / sizeof PRIMITIVES[0]; k++)
        if (strcmp(type, PRIMITIVES[k].name) == 0)
            return read_primitive(p, &p->surfaces[i], js, PRIMITIVES[k].kind, path, err);
    snprintf(path, sizeof path, "surfaces[%d].type", i);
    return invalid(err, path,
                   "expected \"parametric\", \"implicit\", \"nurbs\", \"geomdl\", "
                   "\"step\", \"iges\", \"plane\", \"sphere\", \"cylinder\", \"cone\", "
                   "\"torus\" or \"ellipsoid\"");
}

/* The "surfaces" array: two, or one for a self-intersection, or one
 * alone where the flags allow it (a surface to evaluate). */
static ic_status read_surfaces(ic_problem *p, const cJSON *js, unsigned flags, ic_error *err)
{
    const int n = cJSON_IsArray(js) ? cJSON_GetArraySize(js) : 0;
    const int one_alone = (flags & IC_PROBLEM_ONE_SURFACE) && !p->self && n == 1;
    const int want = p->self || one_alone ? 1 : 2;
    if (!cJSON_IsArray(js) || n != want)
        return invalid(err, "surfaces",
                       p->self ? "a self-intersection problem (\"self\": true) has exactly one "
                                 "surface"
                       : (flags & IC_PROBLEM_ONE_SURFACE)
                           ? "expected an array of one or two surfaces"
                           : "expected an array of exactly two surfaces (or one with "
                             "\"self\": true)");
    for (int i = 0; i < want; i++) {
        const ic_status st = read_surface(p, i, cJSON_GetArrayItem(js, i), err);
        if (st != IC_OK)
            return st;
        p->nsurfaces++;
    }
    if (p->self && ic_surface_get_kind(p->surfaces[0]) != IC_PARAMETRIC)
        return invalid(err, "surfaces[0]", "a self-intersection needs a parametric surface");
    return IC_OK;
}

static ic_status read_problem(ic_problem *p, const cJSON *root, unsigned flags, ic_error *err)
{
    static const char *const keys[] = {"title", "constants", "surfaces", "self", "box", NULL};
    if (!cJSON_IsObject(root))
        return invalid(err, "(root)", "expected a JSON object");
    ic_status st = ic_json_check_keys(root, "(root)", keys, err);
    if (st != IC_OK)
        return st;
    const cJSON *jt = cJSON_GetObjectItemCaseSensitive(root, "title");
    if (jt) {
        if (!cJSON_IsString(jt))
            return invalid(err, "title", "expected a string");
        snprintf(p->title, sizeof p->title, "%s", jt->valuestring);
    }
    if ((st = read_constants(p, cJSON_GetObjectItemCaseSensitive(root, "constants"), err)))
        return st;
    const cJSON *jself = cJSON_GetObjectItemCaseSensitive(root, "self");
    if (jself && !cJSON_IsBool(jself))
        return invalid(err, "self", "expected true or false");
    p->self = jself && cJSON_IsTrue(jself);
    const cJSON *js = need(root, "surfaces", "(root)", err);
    if (!js)
        return IC_ERR_INVALID;
    if ((st = read_surfaces(p, js, flags, err)) != IC_OK)
        return st;
    const cJSON *jb = cJSON_GetObjectItemCaseSensitive(root, "box");
    if (jb) {
        if (!cJSON_IsArray(jb) || cJSON_GetArraySize(jb) != 3)
            return invalid(err, "box", "expected [[x0, x1], [y0, y1], [z0, z1]]");
        for (int i = 0; i < 3; i++) {
            char path[IC_ERROR_PATH_LEN];
            snprintf(path, sizeof path, "box[%d]", i);
            st = ic_json_numbers(p->box[i], 2, cJSON_GetArrayItem(jb, i), path, p->consts,
                                 p->nconsts, err);
            if (st == IC_OK)
                st = check_bounds(p->box[i], path, err);
            if (st != IC_OK)
                return st;
            if (!(p->box[i][0] < p->box[i][1]))
                return invalid(err, path, "empty interval: the lower bound must be smaller");
        }
        p->has_box = 1;
    }
    return IC_OK;
}

/* A parse error at byte `at` of the text, by line and column. */
static ic_status json_error(ic_error *err, const char *json, size_t at, const char *what)
{
    int line = 1, col = 1;
    ic_json_line_col(json, at, &line, &col);
    ic_error_set_path(err, "(line %d, column %d)", line, col);
    return ic_error_set(err, IC_ERR_PARSE, 0, "%s near line %d, column %d", what, line, col);
}

/* JSON's white space (cJSON also skips control characters and NUL). */
static int json_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

/* The JSON text into a tree that keeps the document rules
 * (ic_json_check_document); after the document only whitespace may follow
 * (cJSON stops at the end of the first value and ignores the rest). */
static ic_status parse_document(cJSON **root, const char *json, size_t len, ic_error *err)
{
    const char *end = NULL;
    *root = json ? cJSON_ParseWithLengthOpts(json, len, &end, 0) : NULL;
    if (!*root) {
        const size_t at = end && end >= json && end <= json + len ? (size_t)(end - json) : 0;
        return json_error(err, json ? json : "", json ? at : 0, "invalid JSON");
    }
    const size_t used = (size_t)(end - json);
    ic_status st = IC_OK;
    for (size_t i = used; i < len && st == IC_OK; i++)
        if (!json_space(json[i]))
            st = json_error(err, json, i,
                            json[i] == '\0' ? "a NUL byte after the JSON document"
                                            : "invalid JSON: text after the end of the document");
    if (st == IC_OK)
        st = ic_json_check_document(*root, json, used, err);
    if (st != IC_OK) {
        cJSON_Delete(*root);
        *root = NULL;
    }
    return st;
}

/* ic_problem_parse with flags. */
static ic_status parse_problem(ic_problem **out, const char *json, size_t len, unsigned flags,
                               const char *base_dir, ic_error *err)
{
    *out = NULL;
    ic_error_clear(err);
    cJSON *root = NULL;
    ic_status st = parse_document(&root, json, len, err);
    if (st != IC_OK)
        return st;
    ic_problem *p = calloc(1, sizeof *p);
    if (!p) {
        cJSON_Delete(root);
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory reading a problem");
    }
    snprintf(p->base_dir, sizeof p->base_dir, "%s", base_dir);
    st = read_problem(p, root, flags, err);
    cJSON_Delete(root);
    if (st != IC_OK) {
        ic_problem_free(p);
        return st;
    }
    *out = p;
    return IC_OK;
}

ic_status ic_problem_parse(ic_problem **out, const char *json, size_t len, ic_error *err)
{
    IC_ARG_NOT_NULL(out, "p");
    *out = NULL;
    IC_ARG_NOT_NULL(json, "json");
    return parse_problem(out, json, len, 0, "", err);
}

ic_status ic_problem_read(ic_problem **out, FILE *f, const char *name, unsigned flags,
                          ic_error *err)
{
    IC_ARG_NOT_NULL(out, "p");
    *out = NULL;
    IC_ARG_NOT_NULL(f, "f");
    IC_ARG_NOT_NULL(name, "name");
    ic_error_clear(err);
    char *buf = malloc(IC_PROBLEM_MAX_FILE + 1);
    if (!buf)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory reading %s", name);
    /* the directory of a file name: what the problem's own files are relative to */
    char dir[4096] = "";
    const char *slash = name ? strrchr(name, '/') : NULL;
    if (slash && (size_t)(slash - name) < sizeof dir)
        snprintf(dir, sizeof dir, "%.*s", slash == name ? 1 : (int)(slash - name), name);
    /* one byte more than allowed tells a file that is too large */
    size_t len = fread(buf, 1, IC_PROBLEM_MAX_FILE + 1, f);
    ic_status st;
    if (ferror(f))
        st = ic_error_set(err, IC_ERR_INVALID, 0, "cannot read %s", name);
    else if (len > IC_PROBLEM_MAX_FILE)
        st = ic_error_set(err, IC_ERR_INVALID, 0, "%s is larger than %d bytes", name,
                          IC_PROBLEM_MAX_FILE);
    else
        st = parse_problem(out, buf, len, flags, dir, err);
    free(buf);
    return st;
}

ic_status ic_problem_load(ic_problem **out, const char *filename, ic_error *err)
{
    IC_ARG_NOT_NULL(out, "p");
    *out = NULL;
    IC_ARG_NOT_NULL(filename, "filename");
    ic_error_clear(err);
    FILE *f = fopen(filename, "rb");
    if (!f)
        return ic_error_set(err, IC_ERR_INVALID, 0, "cannot open %s: %s", filename,
                            strerror(errno));
    const ic_status st = ic_problem_read(out, f, filename, 0, err);
    fclose(f);
    return st;
}

void ic_problem_free(ic_problem *p)
{
    if (!p)
        return;
    for (int i = 0; i < MAX_SURFACES; i++)
        ic_surface_free(p->surfaces[i]);
    free(p);
}

const char *ic_problem_title(const ic_problem *p) { return p ? p->title : NULL; }
int ic_problem_num_surfaces(const ic_problem *p) { return p ? p->nsurfaces : 0; }
ic_surface *ic_problem_surface(const ic_problem *p, int i)
{
    return p && i >= 0 && i < p->nsurfaces ? p->surfaces[i] : NULL;
}
const char *ic_problem_surface_name(const ic_problem *p, int i)
{
    return p && i >= 0 && i < p->nsurfaces ? p->names[i] : NULL;
}
int ic_problem_find_surface(const ic_problem *p, const char *name)
{
    if (!p || !name)
        return -1;
    for (int i = 0; i < p->nsurfaces; i++)
        if (strcmp(p->names[i], name) == 0)
            return i;
    return -1;
}
int ic_problem_is_self(const ic_problem *p) { return p ? p->self : 0; }
int ic_problem_box(const ic_problem *p, double box[3][2])
{
    if (!p)
        return 0;
    if (p->has_box && box)
        memcpy(box, p->box, sizeof p->box);
    return p->has_box;
}
