/* The surface document of `intercurve eval` (ic_surface_write_json),
 * called directly and read back against ic_surface_geometry_at and the
 * sphere's closed form; and problem files of one surface (ic_problem_read
 * with IC_PROBLEM_ONE_SURFACE). */
#include "json_doc.h"

/* the sphere of radius 2 with its outward normal: principal curvatures
 * -1/2 (docs/conventions.md); the geometry's rounding is a few ulps */
#define SPHERE_K (-0.5)
#define GEOMETRY_TOL (16 * DBL_EPSILON)

typedef struct {
    ic_surface *s;
    const char *name;
    const double *at;
    int order;
} surface_doc;

static ic_status write_json(FILE *f, void *user, ic_error *err)
{
    const surface_doc *d = user;
    return ic_surface_write_json(f, d->s, d->name, d->at, d->order, err);
}

static ic_problem *read_text(const char *json, unsigned flags, ic_status *st, ic_error *err)
{
    ic_problem *p = NULL;
    FILE *f = fmemopen((void *)json, strlen(json), "r");
    *st = f ? ic_problem_read(&p, f, "the text", flags, err) : IC_ERR_IO;
    if (f)
        fclose(f);
    return p;
}

/* The "value" of the derivative of order alpha[n] in the list, or NULL. */
static const cJSON *derivative(const cJSON *list, const int *alpha, int n)
{
    for (const cJSON *item = list ? list->child : NULL; item; item = item->next) {
        const cJSON *o = doc_get(item, "order");
        int same = cJSON_GetArraySize(o) == n;
        for (int k = 0; same && k < n; k++)
            same = cJSON_GetArrayItem(o, k)->valuedouble == alpha[k];
        if (same)
            return doc_get(item, "value");
    }
    return NULL;
}

/* A fundamental form {"E": .., "F": .., "G": ..} holds v under names[0..2]. */
static int form_is(const cJSON *form, const char names[3], const double v[3])
{
    const char *const keys[4] = {(char[2]){names[0], 0}, (char[2]){names[1], 0},
                                 (char[2]){names[2], 0}, NULL};
    int ok = doc_keys_are(form, keys);
    for (int i = 0; ok && i < 3; i++)
        ok = doc_number_is(doc_get(form, keys[i]), v[i]);
    return ok;
}

/* The sphere of viviani.json, a parametric surface, at (0.3, 0.4). */
static void test_sphere(ic_surface *s)
{
    const double at[2] = {0.3, 0.4};
    ic_surface_geometry g;
    if (ic_surface_geometry_at(s, &g, at, NULL) != IC_OK) {
        CHECK(0, "the sphere's geometry");
        return;
    }
    surface_doc d = {s, "sphere", at, 3};
    cJSON *doc = doc_parse(write_json, &d, "sphere");
    if (!doc)
        return;
    static const char *const keys[] = {"surface",
                                       "type",
                                       "at",
                                       "point",
                                       "degenerate",
                                       "normal",
                                       "tangent_basis_Ru_Rv",
                                       "first_fundamental_form",
                                       "second_fundamental_form",
                                       "principal_curvatures",
                                       "principal_directions",
                                       "gaussian_curvature",
                                       "mean_curvature",
                                       "order",
                                       "derivatives",
                                       NULL};
    CHECK(doc_keys_are(doc, keys), "sphere: the documented keys in order");
    const cJSON *first = doc_get(doc, "first_fundamental_form");
    const cJSON *basis = doc_get(doc, "tangent_basis_Ru_Rv");
    const cJSON *directions = doc_get(doc, "principal_directions");
    CHECK(doc_string_is(doc_get(doc, "surface"), "sphere") &&
              doc_string_is(doc_get(doc, "type"), "parametric") &&
              doc_vector_is(doc_get(doc, "at"), at, 2) &&
              doc_vector_is(doc_get(doc, "point"), g.point, 3) &&
              cJSON_IsNull(doc_get(doc, "degenerate")) &&
              doc_vector_is(doc_get(doc, "normal"), g.normal, 3) &&
              doc_vector_is(cJSON_GetArrayItem(basis, 0), g.basis[0], 3) &&
              doc_vector_is(cJSON_GetArrayItem(basis, 1), g.basis[1], 3) &&
              form_is(first, "EFG", g.first) &&
              form_is(doc_get(doc, "second_fundamental_form"), "LMN", g.second) &&
              doc_vector_is(cJSON_GetArrayItem(directions, 0), g.principal_directions[0], 3) &&
              doc_vector_is(cJSON_GetArrayItem(directions, 1), g.principal_directions[1], 3) &&
              doc_number_is(doc_get(doc, "gaussian_curvature"), g.gauss) &&
              doc_vector_is(doc_get(doc, "principal_curvatures"), g.principal_curvatures, 2) &&
              doc_number_is(doc_get(doc, "mean_curvature"), g.mean),
          "sphere: the geometry read back bit for bit");
    const cJSON *k = doc_get(doc, "principal_curvatures");
    CHECK(harness_close(cJSON_GetArrayItem(k, 0)->valuedouble, SPHERE_K, GEOMETRY_TOL, 0) &&
              harness_close(cJSON_GetArrayItem(k, 1)->valuedouble, SPHERE_K, GEOMETRY_TOL, 0) &&
              harness_close(doc_get(doc, "gaussian_curvature")->valuedouble, 0.25, GEOMETRY_TOL, 0),
          "sphere of radius 2: principal curvatures -1/2, Gaussian curvature 1/4");
    /* (K + 1)(K + 2)/2 partial derivatives of a function of two variables;
     * the one of order (0, 0) is the point, (0, 1) is R_v */
    const int o00[2] = {0, 0}, o01[2] = {0, 1};
    const cJSON *der = doc_get(doc, "derivatives");
    const cJSON *x = derivative(der, o00, 2), *rv = derivative(der, o01, 2);
    int ok = cJSON_GetArraySize(der) == 10 && x && rv;
    for (int j = 0; ok && j < 3; j++)
        ok = harness_close(cJSON_GetArrayItem(x, j)->valuedouble, g.point[j], GEOMETRY_TOL, 1) &&
             harness_close(cJSON_GetArrayItem(rv, j)->valuedouble, g.basis[1][j], GEOMETRY_TOL, 1);
    CHECK(ok, "sphere: 10 derivatives up to order 3, the point and R_v among them");
    cJSON_Delete(doc);
}

/* A sphere pole: degenerate, the reason given, the normal's quantities
 * null; an order outside 0..IC_JET_MAX_ORDER writes nothing. */
static void test_pole_and_order(ic_surface *s)
{
    const double pole[2] = {0.3, 1.5707963267948966};
    surface_doc d = {s, "sphere", pole, 2};
    cJSON *doc = doc_parse(write_json, &d, "sphere pole");
    CHECK(doc && cJSON_IsString(doc_get(doc, "degenerate")) &&
              cJSON_IsNull(doc_get(doc, "normal")) &&
              cJSON_IsNull(doc_get(doc, "principal_curvatures")) &&
              cJSON_GetArraySize(doc_get(doc, "derivatives")) == 6,
          "sphere pole: degenerate, normal null, the 6 derivatives still there");
    cJSON_Delete(doc);
    d.order = IC_JET_MAX_ORDER + 1;
    ic_error err;
    ic_status st;
    char *text = doc_text(write_json, &d, &st, &err);
    CHECK(st == IC_ERR_INVALID && text && text[0] == '\0', "order %d: IC_ERR_INVALID (%s)", d.order,
          err.message);
    free(text);
}

/* One surface alone: an error for an intersection, a surface with
 * IC_PROBLEM_ONE_SURFACE; two surfaces and self-intersections as before. */
static void test_one_surface(void)
{
    ic_error err;
    ic_status st;
    const char *one = "{\"surfaces\": [{\"type\": \"implicit\", \"f\": \"z - x*y\"}]}";
    ic_problem *p = read_text(one, 0, &st, &err);
    CHECK(st == IC_ERR_INVALID && !p && strcmp(err.path, "surfaces") == 0,
          "one surface without the flag: IC_ERR_INVALID at surfaces (%s)", err.message);
    p = read_text(one, IC_PROBLEM_ONE_SURFACE, &st, &err);
    CHECK(st == IC_OK && p && ic_problem_num_surfaces(p) == 1 && !ic_problem_is_self(p) &&
              strcmp(ic_problem_surface_name(p, 0), "A") == 0 && !ic_problem_surface(p, 1),
          "one surface with the flag: one surface named A, no self-intersection (%s)", err.message);
    if (p) {
        const double at[3] = {1.5, 2, 0.25};
        surface_doc d = {ic_problem_surface(p, 0), "A", at, 1};
        cJSON *doc = doc_parse(write_json, &d, "z - x y");
        /* f = z - x y = 0.25 - 3 at the point, grad f = (-y, -x, 1) */
        const double grad[3] = {-2, -1.5, 1};
        int ok = doc && doc_number_is(doc_get(doc, "value"), 0.25 - 3) &&
                 cJSON_GetArraySize(doc_get(doc, "derivatives")) == 4;
        for (int i = 0; ok && i < 3; i++) {
            int alpha[3] = {0, 0, 0};
            alpha[i] = 1;
            ok = doc_number_is(derivative(doc_get(doc, "derivatives"), alpha, 3), grad[i]);
        }
        CHECK(ok, "z - x y at (1.5, 2, 0.25): f = -2.75, grad f = (-2, -1.5, 1)");
        cJSON_Delete(doc);
    }
    ic_problem_free(p);
    const char *two = "{\"surfaces\": [{\"type\": \"implicit\", \"f\": \"z\"}, "
                      "{\"type\": \"implicit\", \"f\": \"y\"}]}";
    p = read_text(two, IC_PROBLEM_ONE_SURFACE, &st, &err);
    CHECK(st == IC_OK && p && ic_problem_num_surfaces(p) == 2, "two surfaces with the flag (%s)",
          err.message);
    ic_problem_free(p);
    const char *three = "{\"surfaces\": [{\"type\": \"implicit\", \"f\": \"z\"}, "
                        "{\"type\": \"implicit\", \"f\": \"y\"}, "
                        "{\"type\": \"implicit\", \"f\": \"x\"}]}";
    p = read_text(three, IC_PROBLEM_ONE_SURFACE, &st, &err);
    CHECK(st == IC_ERR_INVALID && !p && strstr(err.message, "one or two surfaces"),
          "three surfaces: IC_ERR_INVALID, one or two wanted (%s)", err.message);
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : ".";
    char path[512];
    snprintf(path, sizeof path, "%s/examples/viviani.json", dir);
    ic_problem *p = NULL;
    ic_error err;
    if (ic_problem_load(&p, path, &err) == IC_OK) {
        ic_surface *sphere = ic_problem_surface(p, ic_problem_find_surface(p, "sphere"));
        test_sphere(sphere);
        test_pole_and_order(sphere);
    } else {
        CHECK(0, "%s: %s", path, err.message);
    }
    ic_problem_free(p);
    test_one_surface();
    return harness_finish("test_surface_document");
}
