/* NURBS patches in problem files (problem_nurbs.h, docs/nurbs.md). */
#include "problem_nurbs.h"

#include <errno.h>
#include <stdio.h>
#include <sys/stat.h>
#include <stdlib.h>
#include <string.h>

#include "intercurve/problem.h"
#include "json/json_path.h"

/* Most control points one patch may have (a 1000 x 1000 net). */
#define MAX_NET_POINTS 1000000

/* A patch description and the arrays it points into. */
typedef struct {
    ic_nurbs d;
    double *knots[2], *points, *weights;
} owned_nurbs;

static void owned_free(owned_nurbs *o)
{
    free(o->knots[0]);
    free(o->knots[1]);
    free(o->points);
    free(o->weights);
}

static ic_status at_path(ic_error *err, const char *path, const char *what)
{
    ic_error_set_path(err, "%s", path);
    return ic_error_set(err, IC_ERR_INVALID, 0, "%s", what);
}

static ic_status no_memory(ic_error *err)
{
    return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory reading a NURBS patch");
}

/* n numbers of a JSON array (numbers, or formulas of the constants). */
static ic_status read_array(double *out, int n, const cJSON *a, const char *path,
                            const ic_constant *consts, int nconsts, ic_error *err)
{
    int i = 0;
    for (const cJSON *it = a->child; it && i < n; it = it->next, i++) {
        if (cJSON_IsNumber(it)) {
            out[i] = it->valuedouble;
            continue;
        }
        char sub[IC_ERROR_PATH_LEN];
        snprintf(sub, sizeof sub, "%s[%d]", path, i);
        const ic_status st = ic_json_number(&out[i], it, sub, consts, nconsts, err);
        if (st != IC_OK)
            return st;
    }
    return IC_OK;
}

/* An array of exactly n items (n < 0: any length >= 1, returned in *got). */
static ic_status need_array(const cJSON *a, int n, int *got, const char *path, ic_error *err)
{
    const int len = cJSON_IsArray(a) ? cJSON_GetArraySize(a) : -1;
    if (len < 0)
        return at_path(err, path, "expected an array");
    if (n >= 0 && len != n) {
        char what[64];
        snprintf(what, sizeof what, "expected %d items, got %d", n, len);
        return at_path(err, path, what);
    }
    if (len == 0)
        return at_path(err, path, "expected a non-empty array");
    if (got)
        *got = len;
    return IC_OK;
}

/* A knot vector of count + degree + 1 values. */
static ic_status read_knots(owned_nurbs *o, int k, const cJSON *a, const char *path,
                            const ic_constant *consts, int nconsts, ic_error *err)
{
    const int want = o->d.count[k] + o->d.degree[k] + 1;
    int got = 0;
    ic_status st = need_array(a, -1, &got, path, err);
    if (st != IC_OK)
        return st;
    if (got != want) {
        char what[128];
        snprintf(what, sizeof what,
                 "expected %d knots (control points + degree + 1 along this parameter), got %d",
                 want, got);
        return at_path(err, path, what);
    }
    if (!(o->knots[k] = malloc(sizeof(double) * (size_t)want)))
        return no_memory(err);
    o->d.knots[k] = o->knots[k];
    return read_array(o->knots[k], want, a, path, consts, nconsts, err);
}

/* The sizes and storage of an n_u x n_v net (weights too if asked). */
static ic_status alloc_net(owned_nurbs *o, int nu, int nv, int weights, const char *path,
                           ic_error *err)
{
    if ((long)nu * nv > MAX_NET_POINTS) {
        char what[96];
        snprintf(what, sizeof what, "%ld control points; at most %d are read", (long)nu * nv,
                 MAX_NET_POINTS);
        return at_path(err, path, what);
    }
    o->d.count[0] = nu, o->d.count[1] = nv;
    o->points = malloc(sizeof(double) * 3 * (size_t)nu * (size_t)nv);
    if (weights)
        o->weights = malloc(sizeof(double) * (size_t)nu * (size_t)nv);
    if (!o->points || (weights && !o->weights))
        return no_memory(err);
    o->d.points = o->points;
    o->d.weights = o->weights;
    return IC_OK;
}

/* "control_points": n_u rows of n_v points [x, y, z], all rows alike. */
static ic_status read_net(owned_nurbs *o, const cJSON *net, const cJSON *w, const char *path,
                          const ic_constant *consts, int nconsts, ic_error *err)
{
    char sub[IC_ERROR_PATH_LEN];
    snprintf(sub, sizeof sub, "%s.control_points", path);
    int nu = 0, nv = 0;
    ic_status st = need_array(net, -1, &nu, sub, err);
    if (st == IC_OK) {
        snprintf(sub, sizeof sub, "%s.control_points[0]", path);
        st = need_array(net->child, -1, &nv, sub, err);
    }
    if (st == IC_OK)
        st = alloc_net(o, nu, nv, w != NULL, path, err);
    if (st == IC_OK && w) {
        snprintf(sub, sizeof sub, "%s.weights", path);
        st = need_array(w, nu, NULL, sub, err);
    }
    const cJSON *row = net->child, *wrow = w ? w->child : NULL;
    for (int i = 0; st == IC_OK && i < nu; i++, row = row->next) {
        snprintf(sub, sizeof sub, "%s.control_points[%d]", path, i);
        st = need_array(row, nv, NULL, sub, err);
        const cJSON *pt = row->child;
        for (int j = 0; st == IC_OK && j < nv; j++, pt = pt->next) {
            snprintf(sub, sizeof sub, "%s.control_points[%d][%d]", path, i, j);
            st = need_array(pt, 3, NULL, sub, err);
            if (st == IC_OK)
                st = read_array(o->points + 3 * ((size_t)i * nv + j), 3, pt, sub, consts,
                                nconsts, err);
        }
        if (st == IC_OK && wrow) {
            snprintf(sub, sizeof sub, "%s.weights[%d]", path, i);
            st = need_array(wrow, nv, NULL, sub, err);
            if (st == IC_OK)
                st = read_array(o->weights + (size_t)i * nv, nv, wrow, sub, consts, nconsts,
                                err);
            wrow = wrow->next;
        }
    }
    return st;
}

/* "periodic": [bool, bool] (optional). */
static ic_status read_periodic(owned_nurbs *o, const cJSON *a, const char *path, ic_error *err)
{
    if (!a)
        return IC_OK;
    ic_status st = need_array(a, 2, NULL, path, err);
    const cJSON *it = a->child;
    for (int k = 0; st == IC_OK && k < 2; k++, it = it->next) {
        if (!cJSON_IsBool(it)) {
            char sub[IC_ERROR_PATH_LEN];
            snprintf(sub, sizeof sub, "%s[%d]", path, k);
            return at_path(err, sub, "expected true or false");
        }
        o->d.periodic[k] = cJSON_IsTrue(it);
    }
    return st;
}

/* The constructor's checks name a field relative to the patch. */
static ic_status make_surface(ic_surface **s, const owned_nurbs *o, const char *path,
                              ic_error *err)
{
    ic_error local;
    ic_error_clear(&local);
    const ic_status st = ic_surface_new_nurbs(s, &o->d, &local);
    if (st == IC_OK)
        return IC_OK;
    if (err) {
        *err = local;
        ic_error_set_path(err, "%s.%s", path, local.path[0] ? local.path : "control_points");
    }
    return st;
}

ic_status ic_problem_read_nurbs(ic_surface **s, const cJSON *js, const char *path,
                                const ic_constant *consts, int nconsts, ic_error *err)
{
    *s = NULL;
    owned_nurbs o;
    memset(&o, 0, sizeof o);
    char sub[IC_ERROR_PATH_LEN];
    double deg[2];
    snprintf(sub, sizeof sub, "%s.degree", path);
    const cJSON *jd = cJSON_GetObjectItemCaseSensitive(js, "degree");
    ic_status st = jd ? ic_json_numbers(deg, 2, jd, sub, consts, nconsts, err)
                      : at_path(err, path, "missing key \"degree\"");
    for (int k = 0; st == IC_OK && k < 2; k++) {
        if (!(deg[k] >= 1 && deg[k] <= IC_NURBS_MAX_DEGREE && deg[k] == (int)deg[k])) {
            snprintf(sub, sizeof sub, "%s.degree[%d]", path, k);
            st = at_path(err, sub, "expected a whole number from 1 to 9 (IC_NURBS_MAX_DEGREE)");
        }
        o.d.degree[k] = (int)deg[k];
    }
    const cJSON *net = cJSON_GetObjectItemCaseSensitive(js, "control_points");
    if (st == IC_OK && !net)
        st = at_path(err, path, "missing key \"control_points\"");
    if (st == IC_OK)
        st = read_net(&o, net, cJSON_GetObjectItemCaseSensitive(js, "weights"), path, consts,
                      nconsts, err);
    const cJSON *jk = cJSON_GetObjectItemCaseSensitive(js, "knots");
    snprintf(sub, sizeof sub, "%s.knots", path);
    if (st == IC_OK)
        st = jk ? need_array(jk, 2, NULL, sub, err)
                : at_path(err, path, "missing key \"knots\"");
    for (int k = 0; st == IC_OK && k < 2; k++) {
        snprintf(sub, sizeof sub, "%s.knots[%d]", path, k);
        st = read_knots(&o, k, cJSON_GetArrayItem(jk, k), sub, consts, nconsts, err);
    }
    snprintf(sub, sizeof sub, "%s.periodic", path);
    if (st == IC_OK)
        st = read_periodic(&o, cJSON_GetObjectItemCaseSensitive(js, "periodic"), sub, err);
    if (st == IC_OK)
        st = make_surface(s, &o, path, err);
    owned_free(&o);
    return st;
}

/* ---- geomdl (NURBS-Python) JSON: {"shape": {"type": "surface", "data":
 * [{"degree_u", "degree_v", "knotvector_u", "knotvector_v", "size_u",
 * "size_v", "control_points": {"points": [[x, y, z], ...] (v fastest),
 * "weights": [...]}}]}} ---- */

/* A whole number item of a geomdl surface. */
static ic_status geomdl_int(int *out, const cJSON *obj, const char *key, int lo, int hi,
                            const char *path, ic_error *err)
{
    char sub[IC_ERROR_PATH_LEN], what[96];
    snprintf(sub, sizeof sub, "%s.%s", path, key);
    const cJSON *it = cJSON_GetObjectItemCaseSensitive(obj, key);
    const double v = cJSON_IsNumber(it) ? it->valuedouble : -1;
    if (!(v >= lo && v <= hi && v == (int)v)) {
        snprintf(what, sizeof what, "expected a whole number from %d to %d", lo, hi);
        return at_path(err, sub, what);
    }
    *out = (int)v;
    return IC_OK;
}

/* The flat point (and weight) lists of a geomdl surface. */
static ic_status geomdl_net(owned_nurbs *o, const cJSON *cp, const char *path, ic_error *err)
{
    char sub[IC_ERROR_PATH_LEN];
    const int nu = o->d.count[0], nv = o->d.count[1];
    const cJSON *pts = cJSON_GetObjectItemCaseSensitive(cp, "points");
    const cJSON *w = cJSON_GetObjectItemCaseSensitive(cp, "weights");
    snprintf(sub, sizeof sub, "%s.control_points.points", path);
    ic_status st = need_array(pts, nu * nv, NULL, sub, err);
    if (st == IC_OK)
        st = alloc_net(o, nu, nv, w != NULL, sub, err);
    const cJSON *pt = pts ? pts->child : NULL;
    for (int k = 0; st == IC_OK && k < nu * nv; k++, pt = pt->next) {
        snprintf(sub, sizeof sub, "%s.control_points.points[%d]", path, k);
        st = need_array(pt, 3, NULL, sub, err);
        if (st == IC_OK)
            st = read_array(o->points + 3 * (size_t)k, 3, pt, sub, NULL, 0, err);
    }
    snprintf(sub, sizeof sub, "%s.control_points.weights", path);
    if (st == IC_OK && w && (st = need_array(w, nu * nv, NULL, sub, err)) == IC_OK)
        st = read_array(o->weights, nu * nv, w, sub, NULL, 0, err);
    return st;
}

/* One geomdl surface object at `path` of the file. */
static ic_status geomdl_surface(owned_nurbs *o, const cJSON *js, const char *path, ic_error *err)
{
    char sub[IC_ERROR_PATH_LEN];
    if (!cJSON_IsObject(js))
        return at_path(err, path, "expected a geomdl surface object");
    ic_status st = geomdl_int(&o->d.degree[0], js, "degree_u", 1, IC_NURBS_MAX_DEGREE, path, err);
    if (st == IC_OK)
        st = geomdl_int(&o->d.degree[1], js, "degree_v", 1, IC_NURBS_MAX_DEGREE, path, err);
    if (st == IC_OK)
        st = geomdl_int(&o->d.count[0], js, "size_u", 2, MAX_NET_POINTS, path, err);
    if (st == IC_OK)
        st = geomdl_int(&o->d.count[1], js, "size_v", 2, MAX_NET_POINTS, path, err);
    if (st == IC_OK && (long)o->d.count[0] * o->d.count[1] > MAX_NET_POINTS)
        st = at_path(err, path, "size_u x size_v exceeds the 1000000 control points read");
    const cJSON *cp = cJSON_GetObjectItemCaseSensitive(js, "control_points");
    snprintf(sub, sizeof sub, "%s.control_points", path);
    if (st == IC_OK && !cJSON_IsObject(cp))
        st = at_path(err, sub, "expected an object with \"points\" (and \"weights\")");
    if (st == IC_OK)
        st = geomdl_net(o, cp, path, err);
    static const char *const knot_keys[2] = {"knotvector_u", "knotvector_v"};
    for (int k = 0; st == IC_OK && k < 2; k++) {
        snprintf(sub, sizeof sub, "%s.%s", path, knot_keys[k]);
        st = read_knots(o, k, cJSON_GetObjectItemCaseSensitive(js, knot_keys[k]), sub, NULL, 0,
                        err);
    }
    return st;
}

/* The file's text (at most IC_PROBLEM_MAX_FILE bytes), NUL-terminated. */
static ic_status slurp(char **text, size_t *len, const char *file, ic_error *err)
{
    *text = NULL;
    struct stat info;
    if (stat(file, &info) != 0)
        return ic_error_set(err, IC_ERR_IO, 0, "cannot open %s: %s", file, strerror(errno));
    if (!S_ISREG(info.st_mode)) /* a pipe or a device could block or never end */
        return ic_error_set(err, IC_ERR_IO, 0, "%s is not a regular file", file);
    FILE *f = fopen(file, "rb");
    if (!f)
        return ic_error_set(err, IC_ERR_IO, 0, "cannot open %s: %s", file, strerror(errno));
    char *buf = malloc(IC_PROBLEM_MAX_FILE + 1);
    ic_status st = IC_OK;
    if (!buf)
        st = no_memory(err);
    else if ((*len = fread(buf, 1, IC_PROBLEM_MAX_FILE + 1, f)), ferror(f))
        st = ic_error_set(err, IC_ERR_IO, 0, "cannot read %s", file);
    else if (*len > IC_PROBLEM_MAX_FILE)
        st = ic_error_set(err, IC_ERR_INVALID, 0, "%s is larger than %d bytes", file,
                          IC_PROBLEM_MAX_FILE);
    fclose(f);
    if (st != IC_OK) {
        free(buf);
        return st;
    }
    buf[*len] = '\0';
    *text = buf;
    return IC_OK;
}

/* "file" joined to base_dir (unless absolute) into out. */
static ic_status file_path(char *out, size_t size, const cJSON *js, const char *path,
                           const char *base_dir, ic_error *err)
{
    char sub[IC_ERROR_PATH_LEN];
    snprintf(sub, sizeof sub, "%s.file", path);
    const cJSON *jf = cJSON_GetObjectItemCaseSensitive(js, "file");
    if (!cJSON_IsString(jf) || !jf->valuestring[0])
        return at_path(err, sub, "expected the name of a geomdl JSON file");
    const char *name = jf->valuestring;
    const int joined = name[0] == '/' || !base_dir || !base_dir[0]
                           ? snprintf(out, size, "%s", name)
                           : snprintf(out, size, "%s/%s", base_dir, name);
    if (joined < 0 || (size_t)joined >= size)
        return at_path(err, sub, "the file's path is too long");
    return IC_OK;
}

ic_status ic_problem_read_geomdl(ic_surface **s, const cJSON *js, const char *path,
                                 const char *base_dir, ic_error *err)
{
    *s = NULL;
    char file[4096], sub[IC_ERROR_PATH_LEN];
    int index = 0;
    ic_status st = file_path(file, sizeof file, js, path, base_dir, err);
    if (st == IC_OK && cJSON_GetObjectItemCaseSensitive(js, "index"))
        st = geomdl_int(&index, js, "index", 0, MAX_NET_POINTS, path, err);
    char *text = NULL;
    size_t len = 0;
    if (st == IC_OK && (st = slurp(&text, &len, file, err)) != IC_OK)
        ic_error_set_path(err, "%s.file", path);
    cJSON *root = st == IC_OK ? cJSON_ParseWithLength(text, len) : NULL;
    free(text);
    if (st == IC_OK && !root)
        st = at_path(err, path, "the geomdl file is not valid JSON");
    const cJSON *shape = cJSON_GetObjectItemCaseSensitive(root, "shape");
    const cJSON *type = cJSON_GetObjectItemCaseSensitive(shape, "type");
    const cJSON *data = cJSON_GetObjectItemCaseSensitive(shape, "data");
    if (st == IC_OK && !(cJSON_IsString(type) && strcmp(type->valuestring, "surface") == 0 &&
                         cJSON_IsArray(data)))
        st = at_path(err, path, "the geomdl file has no \"shape\" of type \"surface\" with "
                                "\"data\"");
    if (st == IC_OK && index >= cJSON_GetArraySize(data))
        st = at_path(err, path, "\"index\" is past the last surface of the geomdl file");
    owned_nurbs o;
    memset(&o, 0, sizeof o);
    snprintf(sub, sizeof sub, "%s (%s: shape.data[%d])", path, file, index);
    if (st == IC_OK)
        st = geomdl_surface(&o, cJSON_GetArrayItem(data, index), sub, err);
    if (st == IC_OK)
        st = make_surface(s, &o, sub, err);
    owned_free(&o);
    cJSON_Delete(root);
    return st;
}
