/* The document of `intercurve eval` (docs/output-formats.md, "The surface
 * document"): one surface's local geometry and derivative tensor. */
#include "intercurve/writers.h"

#include <stdlib.h>

#include "intercurve/jet.h"
#include "io/json_out.h"

/* Every partial derivative up to `order` at `at` into *list, each
 * {"order": [exponents], "value": number or [x, y, z]}. */
static ic_status derivative_tensor(cJSON **list, json_out *j, ic_surface *s, const double *at,
                                   int order, ic_error *err)
{
    ic_jet_space *sp = NULL;
    double *taylor = NULL;
    *list = NULL;
    ic_status st = ic_jet_space_new(&sp, ic_surface_num_inputs(s), order, err);
    if (st != IC_OK)
        goto cleanup;
    const int n = ic_jet_space_len(sp), nout = ic_surface_num_outputs(s);
    taylor = malloc((size_t)nout * n * sizeof *taylor);
    if (!taylor) {
        st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory");
        goto cleanup;
    }
    if ((st = ic_surface_taylor(s, taylor, at, sp, err)) != IC_OK)
        goto cleanup;
    *list = cJSON_CreateArray();
    for (int i = 0; i < n; i++) {
        int alpha[3];
        ic_jet_exponents(sp, i, alpha);
        const double factorial = ic_jet_factorial(sp, i);
        cJSON *item = cJSON_CreateObject();
        ic_json_out_add(j, item, "order", cJSON_CreateIntArray(alpha, ic_surface_num_inputs(s)));
        if (nout == 1) {
            ic_json_out_add(j, item, "value", ic_json_out_number(j, taylor[i] * factorial));
        } else {
            const double v[3] = {taylor[i] * factorial, taylor[n + i] * factorial,
                                 taylor[2 * n + i] * factorial};
            ic_json_out_add(j, item, "value", ic_json_out_vector(j, v, 3));
        }
        ic_json_out_append(j, *list, item);
    }
cleanup:
    free(taylor);
    ic_jet_space_free(sp);
    return st;
}

static cJSON *pair_of_vectors(json_out *j, const double a[3], const double b[3])
{
    cJSON *pair = cJSON_CreateArray();
    ic_json_out_append(j, pair, ic_json_out_vector(j, a, 3));
    ic_json_out_append(j, pair, ic_json_out_vector(j, b, 3));
    return pair;
}

static cJSON *form_json(json_out *j, const char *const names[3], const double v[3])
{
    cJSON *form = cJSON_CreateObject();
    for (int i = 0; i < 3; i++)
        ic_json_out_add(j, form, names[i], ic_json_out_number(j, v[i]));
    return form;
}

static void add_geometry(json_out *j, cJSON *doc, const ic_surface_geometry *g, int parametric)
{
    static const char *const first[3] = {"E", "F", "G"}, *const second[3] = {"L", "M", "N"};
    ic_json_out_add(j, doc, "normal", ic_json_out_vector(j, g->normal, 3));
    ic_json_out_add(j, doc, parametric ? "tangent_basis_Ru_Rv" : "tangent_basis_orthonormal",
                 pair_of_vectors(j, g->basis[0], g->basis[1]));
    ic_json_out_add(j, doc, "first_fundamental_form", form_json(j, first, g->first));
    ic_json_out_add(j, doc, "second_fundamental_form", form_json(j, second, g->second));
    ic_json_out_add(j, doc, "principal_curvatures", ic_json_out_vector(j, g->principal_curvatures, 2));
    ic_json_out_add(j, doc, "principal_directions",
                 pair_of_vectors(j, g->principal_directions[0], g->principal_directions[1]));
    ic_json_out_add(j, doc, "gaussian_curvature", ic_json_out_number(j, g->gauss));
    ic_json_out_add(j, doc, "mean_curvature", ic_json_out_number(j, g->mean));
}

/* At a degenerate point: the quantities that need the normal are null. */
static void add_nulls(json_out *j, cJSON *doc)
{
    static const char *const keys[] = {"normal",
                                       "first_fundamental_form",
                                       "second_fundamental_form",
                                       "principal_curvatures",
                                       "principal_directions",
                                       "gaussian_curvature",
                                       "mean_curvature"};
    for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++)
        ic_json_out_add(j, doc, keys[i], cJSON_CreateNull());
}

ic_status ic_surface_write_json(FILE *f, ic_surface *s, const char *name, const double *at,
                                int order, ic_error *err)
{
    if (order < 0 || order > IC_JET_MAX_ORDER)
        return ic_error_set(err, IC_ERR_INVALID, 0, "the order %d is outside 0..%d", order,
                            IC_JET_MAX_ORDER);
    json_out j = {0};
    const int parametric = ic_surface_get_kind(s) == IC_PARAMETRIC;
    cJSON *tensor;
    ic_status st = derivative_tensor(&tensor, &j, s, at, order, err);
    if (st != IC_OK)
        return st;
    ic_surface_geometry g;
    ic_error why; /* the reason of a degenerate point, printed in the document */
    ic_error_clear(&why);
    st = ic_surface_geometry_at(s, &g, at, &why);
    if (st != IC_OK && st != IC_ERR_DOMAIN) {
        cJSON_Delete(tensor);
        return ic_error_set(err, st, why.column, "%s", why.message);
    }
    cJSON *doc = cJSON_CreateObject();
    ic_json_out_add(&j, doc, "surface", cJSON_CreateString(name));
    ic_json_out_add(&j, doc, "type", cJSON_CreateString(parametric ? "parametric" : "implicit"));
    ic_json_out_add(&j, doc, "at", ic_json_out_vector(&j, at, ic_surface_num_inputs(s)));
    if (parametric)
        ic_json_out_add(&j, doc, "point", ic_json_out_vector(&j, g.point, 3));
    else
        ic_json_out_add(&j, doc, "value", ic_json_out_number(&j, g.value));
    if (st == IC_OK) {
        ic_json_out_add(&j, doc, "degenerate", cJSON_CreateNull());
        add_geometry(&j, doc, &g, parametric);
    } else {
        ic_json_out_add(&j, doc, "degenerate", cJSON_CreateString(why.message));
        add_nulls(&j, doc);
    }
    ic_json_out_add(&j, doc, "order", cJSON_CreateNumber(order));
    ic_json_out_add(&j, doc, "derivatives", tensor);
    return ic_json_out_write(f, doc, &j, "surface JSON", err);
}
