/* The point document (ic_local_write_json) and the point's text
 * (ic_local_write_text), called directly: each read back and compared with
 * what ic_local_apparatus returned, value by value and bit for bit, with
 * the keys of docs/output-formats.md in their order, and with closed forms
 * of Viviani's curve. */
#include "json_doc.h"

/* Viviani's curve x = 1 + cos t, y = sin t, z = 2 sin(t/2) at t = pi/3,
 * the point (1.5, sqrt 3 / 2, 1): |c' x c''| / |c'|^3 = sqrt(14.5) / 3.5^1.5 */
#define VIVIANI_KAPPA 0.5815431366846942
typedef struct {
    const ic_local_result *res;
    const ic_pair *pair;
    int order;
} point_doc;

static ic_status write_json(FILE *f, void *user, ic_error *err)
{
    const point_doc *d = user;
    return ic_local_write_json(f, d->res, d->pair, d->order, err);
}

static ic_status write_text(FILE *f, void *user, ic_error *err)
{
    const point_doc *d = user;
    return ic_local_write_text(f, d->res, err);
}

/* A pair of the problem file's surfaces (the problem keeps them). */
static ic_pair *problem_pair(ic_problem **p, const char *dir, const char *name)
{
    char path[512];
    snprintf(path, sizeof path, "%s/examples/%s", dir, name);
    ic_error err;
    ic_pair *pair = NULL;
    if (ic_problem_load(p, path, &err) == IC_OK &&
        ic_pair_new(&pair, ic_problem_surface(*p, 0),
                    ic_problem_is_self(*p) ? NULL : ic_problem_surface(*p, 1), &err) == IC_OK)
        return pair;
    CHECK(0, "%s: %s", name, err.message);
    return NULL;
}

static int analyse(ic_local_result *res, ic_pair *pair, const double xyz[3], int order,
                   ic_method method)
{
    ic_local_options opt;
    ic_local_defaults(&opt);
    ic_local_point pt;
    ic_error err;
    const int ok = ic_local_locate(pair, &pt, xyz, &opt, &err) == IC_OK &&
                   ic_local_apparatus(pair, res, &pt, order, method, &opt, &err) == IC_OK;
    CHECK(ok, "the point (%g, %g, %g) analysed: %s", xyz[0], xyz[1], xyz[2], err.message);
    return ok;
}

/* One branch's keys and values against the result's branch. */
static int branch_matches(const cJSON *b, const ic_branch *br, const int parametric[2])
{
    const char *keys[12];
    int n = 0;
    keys[n++] = "t";
    if (!br->regular)
        keys[n++] = "regular";
    const char *more[] = {"n", "b", "kappa", "tau", "kappa_prime", "tau_prime"};
    for (int i = 0; i < 6; i++)
        keys[n++] = more[i];
    if (!br->regular || (!br->frame_defined && br->order >= 2))
        keys[n++] = "undefined";
    keys[n++] = "derivatives";
    keys[n++] = "surfaces";
    keys[n] = NULL;
    const int fd = br->frame_defined;
    int ok =
        doc_keys_are(b, keys) && doc_vector_is(doc_get(b, "t"), br->t, 3) &&
        (fd ? doc_vector_is(doc_get(b, "n"), br->n, 3) : cJSON_IsNull(doc_get(b, "n"))) &&
        (fd ? doc_vector_is(doc_get(b, "b"), br->b, 3) : cJSON_IsNull(doc_get(b, "b"))) &&
        doc_number_is(doc_get(b, "kappa"), br->order >= 2 ? br->kappa : NAN) &&
        doc_number_is(doc_get(b, "tau"), br->tau_defined ? br->tau : NAN) &&
        doc_number_is(doc_get(b, "kappa_prime"), br->kappa_prime_defined ? br->kappa_prime : NAN) &&
        doc_number_is(doc_get(b, "tau_prime"), br->tau_prime_defined ? br->tau_prime : NAN);
    const cJSON *d = doc_get(b, "derivatives");
    ok = ok && cJSON_GetArraySize(d) == br->order;
    for (int k = 0; ok && k < br->order; k++)
        ok = doc_vector_is(cJSON_GetArrayItem(d, k), br->derivs[k], 3);
    const cJSON *surfaces = doc_get(b, "surfaces");
    ok = ok && cJSON_GetArraySize(surfaces) == 2;
    for (int s = 0; ok && s < 2; s++) {
        const cJSON *so = cJSON_GetArrayItem(surfaces, s);
        ok = doc_number_is(doc_get(so, "kappa_n"), br->surface[s].kappa_n) &&
             doc_number_is(doc_get(so, "kappa_g"), br->surface[s].kappa_g) &&
             doc_number_is(doc_get(so, "tau_g"), br->surface[s].tau_g);
        const cJSON *pd = doc_get(so, "parameter_derivatives");
        if (!parametric[s]) {
            ok = ok && !pd;
            continue;
        }
        const int m = br->param_order < br->order ? br->param_order : br->order;
        ok = ok && cJSON_GetArraySize(pd) == m;
        for (int k = 0; ok && k < m; k++)
            ok = doc_vector_is(cJSON_GetArrayItem(pd, k), br->param_derivs[s][k], 2);
    }
    return ok;
}

/* The top level: keys in the documented order, every value. */
static void check_document(const cJSON *doc, const ic_local_result *res, const ic_pair *pair,
                           int order, const char *what)
{
    int parametric[2];
    for (int s = 0; s < 2; s++)
        parametric[s] = ic_surface_get_kind(ic_pair_surface(pair, s)) == IC_PARAMETRIC;
    const char *keys[16] = {"point", "residual", "params",      "normals",
                            "angle", "type",     "discriminant"};
    int n = 7;
    if (res->contact_order)
        keys[n++] = "contact_order";
    keys[n++] = "method";
    if (res->npaper)
        keys[n++] = "paper_coefficients";
    if (res->method == IC_METHOD_PERTURBATION)
        keys[n++] = "error_estimate";
    keys[n++] = "order";
    keys[n++] = "branches";
    keys[n] = NULL;
    CHECK(doc_keys_are(doc, keys), "%s: the documented keys in order", what);
    const cJSON *params = doc_get(doc, "params"), *normals = doc_get(doc, "normals");
    int ok = doc_vector_is(doc_get(doc, "point"), res->point.xyz, 3) &&
             doc_number_is(doc_get(doc, "residual"), res->point.residual) &&
             cJSON_GetArraySize(params) == 2 && cJSON_GetArraySize(normals) == 2 &&
             doc_number_is(doc_get(doc, "angle"), res->angle) &&
             doc_string_is(doc_get(doc, "type"), ic_point_type_name(res->type)) &&
             doc_number_is(doc_get(doc, "discriminant"), res->discriminant) &&
             doc_string_is(doc_get(doc, "method"), ic_method_name(res->method)) &&
             doc_number_is(doc_get(doc, "order"), order);
    for (int s = 0; ok && s < 2; s++)
        ok = (parametric[s] ? doc_vector_is(cJSON_GetArrayItem(params, s), res->point.params[s], 2)
                            : cJSON_IsNull(cJSON_GetArrayItem(params, s))) &&
             doc_vector_is(cJSON_GetArrayItem(normals, s), res->normals[s], 3);
    for (int i = 0; ok && i < res->npaper; i++)
        ok = doc_number_is(doc_get(doc_get(doc, "paper_coefficients"), res->paper_names[i]),
                           res->paper_values[i]);
    if (res->contact_order)
        ok = ok && doc_number_is(doc_get(doc, "contact_order"), res->contact_order);
    if (res->method == IC_METHOD_PERTURBATION)
        ok = ok && doc_number_is(doc_get(doc, "error_estimate"), res->error_estimate);
    CHECK(ok, "%s: the point's values read back bit for bit", what);
    const cJSON *branches = doc_get(doc, "branches");
    CHECK(cJSON_GetArraySize(branches) == res->nbranches, "%s: %d branches", what, res->nbranches);
    for (int i = 0; i < res->nbranches && i < cJSON_GetArraySize(branches); i++)
        CHECK(branch_matches(cJSON_GetArrayItem(branches, i), &res->branches[i], parametric),
              "%s: branch %d read back bit for bit", what, i + 1);
}

/* The document of one analysed point, checked, then returned (delete it). */
static cJSON *point_document(const ic_local_result *res, const ic_pair *pair, int order,
                             const char *what)
{
    point_doc d = {res, pair, order};
    cJSON *doc = doc_parse(write_json, &d, what);
    if (doc)
        check_document(doc, res, pair, order, what);
    return doc;
}

/* A transversal point of Viviani's curve (two parametric surfaces). */
static void test_transversal(const char *dir)
{
    ic_problem *p = NULL;
    ic_pair *pair = problem_pair(&p, dir, "viviani.json");
    const double at[3] = {1.5, 0.8660254037844386, 1};
    ic_local_result res;
    if (pair && analyse(&res, pair, at, 5, IC_METHOD_AUTO)) {
        cJSON *doc = point_document(&res, pair, 5, "Viviani, transversal");
        const cJSON *br = cJSON_GetArrayItem(doc_get(doc, "branches"), 0);
        CHECK(doc_string_is(doc_get(doc, "type"), "transversal") &&
                  cJSON_IsNull(doc_get(doc, "discriminant")),
              "Viviani: a transversal point, no discriminant (null)");
        CHECK(br && harness_close(doc_get(br, "kappa")->valuedouble, VIVIANI_KAPPA, 1e-13, 1),
              "Viviani: kappa = sqrt(14.5)/3.5^1.5 in the document");
        CHECK(cJSON_GetArraySize(doc_get(br, "derivatives")) == 5, "order 5: c' .. c^(5)");
        cJSON_Delete(doc);
        /* the text: the same kappa to 15 digits */
        point_doc d = {&res, pair, 5};
        ic_error err;
        ic_status st;
        char *text = doc_text(write_text, &d, &st, &err);
        const char *k = text ? strstr(text, "\n  kappa        ") : NULL;
        CHECK(st == IC_OK && text && strncmp(text, "point        (1.5, ", 19) == 0 &&
                  strstr(text, "\ntype         transversal") && k &&
                  harness_close(strtod(k + 16, NULL), res.branches[0].kappa, 1e-14, 1),
              "the point's text: its point, type and kappa to 15 digits");
        free(text);
    }
    ic_pair_free(pair);
    ic_problem_free(p);
}

/* Viviani's branch point (2, 0, 0): two branches, kappa 1/2, tau +-3/8,
 * Delta = 1/16; the closed form adds the paper's coefficients, the
 * perturbation method its error estimate. */
static void test_branch_point(const char *dir)
{
    ic_problem *p = NULL;
    ic_pair *pair = problem_pair(&p, dir, "viviani.json");
    const double at[3] = {2, 0, 0};
    const ic_method methods[3] = {IC_METHOD_AUTO, IC_METHOD_CLOSED_FORM, IC_METHOD_PERTURBATION};
    for (int m = 0; pair && m < 3; m++) {
        ic_local_result res;
        const int order = methods[m] == IC_METHOD_CLOSED_FORM ? 3 : 4;
        if (!analyse(&res, pair, at, order, methods[m]))
            continue;
        char what[64];
        snprintf(what, sizeof what, "branch point, %s", ic_method_name(methods[m]));
        cJSON *doc = point_document(&res, pair, order, what);
        const cJSON *branches = doc_get(doc, "branches");
        int ok = doc_string_is(doc_get(doc, "type"), "branch-point") &&
                 cJSON_GetArraySize(branches) == 2 &&
                 harness_close(doc_get(doc, "discriminant")->valuedouble, 1.0 / 16, 1e-12, 0);
        /* the perturbation method extrapolates t, n, kappa only */
        for (int i = 0; ok && i < 2 && methods[m] != IC_METHOD_PERTURBATION; i++) {
            const cJSON *b = cJSON_GetArrayItem(branches, i);
            ok = harness_close(doc_get(b, "kappa")->valuedouble, 0.5, 1e-12, 0) &&
                 harness_close(fabs(doc_get(b, "tau")->valuedouble), 0.375, 1e-9, 0);
        }
        CHECK(ok, "%s: two branches, kappa 1/2, |tau| 3/8, discriminant 1/16", what);
        if (methods[m] == IC_METHOD_CLOSED_FORM)
            CHECK(cJSON_GetArraySize(doc_get(doc, "paper_coefficients")) == res.npaper &&
                      res.npaper > 0,
                  "closed form at the branch point: the paper's coefficients");
        cJSON_Delete(doc);
    }
    ic_pair_free(pair);
    ic_problem_free(p);
}

/* Two planes meet in a line: kappa 0, so n, b and tau are null with the
 * reason; implicit surfaces have no parameters (null). */
static void test_straight_line(void)
{
    ic_surface *A = NULL, *B = NULL;
    ic_pair *pair = NULL;
    ic_local_result res;
    const double at[3] = {0.3, 0, 0};
    if (ic_surface_new_implicit(&A, "z", NULL, 0, NULL) == IC_OK &&
        ic_surface_new_implicit(&B, "y", NULL, 0, NULL) == IC_OK &&
        ic_pair_new(&pair, A, B, NULL) == IC_OK && analyse(&res, pair, at, 3, IC_METHOD_JET)) {
        cJSON *doc = point_document(&res, pair, 3, "two planes");
        const cJSON *b = cJSON_GetArrayItem(doc_get(doc, "branches"), 0);
        const cJSON *params = doc_get(doc, "params");
        CHECK(cJSON_IsNull(cJSON_GetArrayItem(params, 0)) &&
                  cJSON_IsNull(cJSON_GetArrayItem(params, 1)),
              "two planes: params [null, null]");
        CHECK(b && cJSON_IsNull(doc_get(b, "n")) && cJSON_IsNull(doc_get(b, "b")) &&
                  cJSON_IsNull(doc_get(b, "tau")) && doc_number_is(doc_get(b, "kappa"), 0) &&
                  strstr(cJSON_GetStringValue(doc_get(b, "undefined")), "curvature is 0"),
              "two planes: kappa 0; n, b, tau null and why");
        cJSON_Delete(doc);
        /* a full disk: the failed write is reported, not success */
        FILE *full = fopen("/dev/full", "w");
        if (full) {
            setvbuf(full, NULL, _IONBF, 0);
            ic_error err;
            CHECK(ic_local_write_json(full, &res, pair, 3, &err) == IC_ERR_IO &&
                      ic_local_write_text(full, &res, &err) == IC_ERR_IO,
                  "the point's writers report a failed write");
            fclose(full);
        }
    }
    ic_pair_free(pair);
    ic_surface_free(A);
    ic_surface_free(B);
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : ".";
    test_transversal(dir);
    test_branch_point(dir);
    test_straight_line();
    return harness_finish("test_point_document");
}
