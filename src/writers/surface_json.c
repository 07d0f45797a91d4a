/* The document of `intercurve eval` (docs/output-formats.md, "The surface
 * document"): one surface's local geometry and derivative tensor. */
#include "common/args.h"
#include "intercurve/writers.h"

#include <stdlib.h>

#include "intercurve/jet.h"
#include "json/json_out.h"

/* The Taylor coefficients of s at `at` up to `order`, computed before
 * anything is written: *sp and *taylor (the caller frees both). */
static ic_status taylor_at(ic_jet_space **sp, double **taylor, ic_surface *s, const double *at,
                           int order, ic_error *err)
{
    *sp = NULL;
    *taylor = NULL;
    ic_status st = ic_jet_space_new(sp, ic_surface_num_inputs(s), order, err);
    if (st != IC_OK)
        return st;
    *taylor = malloc((size_t)ic_surface_num_outputs(s) * ic_jet_space_len(*sp) * sizeof **taylor);
    if (!*taylor)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory");
    return ic_surface_taylor(s, *taylor, at, *sp, err);
}

/* Every partial derivative up to the jet space's order, each
 * {"order": [exponents], "value": number or [x, y, z]}. */
static void derivative_tensor(json_out *j, const ic_jet_space *sp, const double *taylor,
                              int ninputs, int nout)
{
    const int n = ic_jet_space_len(sp);
    ic_json_out_array(j);
    for (int i = 0; i < n; i++) {
        int alpha[3];
        ic_jet_exponents(sp, i, alpha);
        const double factorial = ic_jet_factorial(sp, i);
        ic_json_out_object(j);
        ic_json_out_key(j, "order");
        ic_json_out_ints(j, alpha, ninputs);
        ic_json_out_key(j, "value");
        if (nout == 1) {
            ic_json_out_number(j, taylor[i] * factorial);
        } else {
            const double v[3] = {taylor[i] * factorial, taylor[n + i] * factorial,
                                 taylor[2 * n + i] * factorial};
            ic_json_out_vector(j, v, 3);
        }
        ic_json_out_end_object(j);
    }
    ic_json_out_end_array(j);
}

static void pair_of_vectors(json_out *j, const char *key, const double a[3], const double b[3])
{
    ic_json_out_key(j, key);
    ic_json_out_array(j);
    ic_json_out_vector(j, a, 3);
    ic_json_out_vector(j, b, 3);
    ic_json_out_end_array(j);
}

static void form_json(json_out *j, const char *key, const char *const names[3], const double v[3])
{
    ic_json_out_key(j, key);
    ic_json_out_object(j);
    for (int i = 0; i < 3; i++) {
        ic_json_out_key(j, names[i]);
        ic_json_out_number(j, v[i]);
    }
    ic_json_out_end_object(j);
}

static void add_geometry(json_out *j, const ic_surface_geometry *g, int parametric)
{
    static const char *const first[3] = {"E", "F", "G"}, *const second[3] = {"L", "M", "N"};
    ic_json_out_key(j, "normal");
    ic_json_out_vector(j, g->normal, 3);
    pair_of_vectors(j, parametric ? "tangent_basis_Ru_Rv" : "tangent_basis_orthonormal",
                    g->basis[0], g->basis[1]);
    form_json(j, "first_fundamental_form", first, g->first);
    form_json(j, "second_fundamental_form", second, g->second);
    ic_json_out_key(j, "principal_curvatures");
    ic_json_out_vector(j, g->principal_curvatures, 2);
    pair_of_vectors(j, "principal_directions", g->principal_directions[0],
                    g->principal_directions[1]);
    ic_json_out_key(j, "gaussian_curvature");
    ic_json_out_number(j, g->gauss);
    ic_json_out_key(j, "mean_curvature");
    ic_json_out_number(j, g->mean);
}

/* At a degenerate point: the quantities that need the normal are null. */
static void add_nulls(json_out *j)
{
    static const char *const keys[] = {"normal",
                                       "first_fundamental_form",
                                       "second_fundamental_form",
                                       "principal_curvatures",
                                       "principal_directions",
                                       "gaussian_curvature",
                                       "mean_curvature"};
    for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++) {
        ic_json_out_key(j, keys[i]);
        ic_json_out_null(j);
    }
}

/* The document, once everything in it is computed; st is the geometry's
 * status (IC_OK, or IC_ERR_DOMAIN with the reason in why). */
static ic_status write_document(FILE *f, ic_surface *s, const char *name, const double *at,
                                int order, const ic_surface_geometry *g, ic_status st,
                                const ic_error *why, const ic_jet_space *sp,
                                const double *taylor, ic_error *err)
{
    const int parametric = ic_surface_get_kind(s) == IC_PARAMETRIC;
    json_out j;
    ic_json_out_start(&j, f);
    ic_json_out_object(&j);
    ic_json_out_key(&j, "surface");
    ic_json_out_string(&j, name);
    ic_json_out_key(&j, "type");
    ic_json_out_string(&j, parametric ? "parametric" : "implicit");
    ic_json_out_key(&j, "at");
    ic_json_out_vector(&j, at, ic_surface_num_inputs(s));
    ic_json_out_key(&j, parametric ? "point" : "value");
    if (parametric)
        ic_json_out_vector(&j, g->point, 3);
    else
        ic_json_out_number(&j, g->value);
    ic_json_out_key(&j, "degenerate");
    if (st == IC_OK) {
        ic_json_out_null(&j);
        add_geometry(&j, g, parametric);
    } else {
        ic_json_out_string(&j, why->message);
        add_nulls(&j);
    }
    ic_json_out_key(&j, "order");
    ic_json_out_int(&j, order);
    ic_json_out_key(&j, "derivatives");
    derivative_tensor(&j, sp, taylor, ic_surface_num_inputs(s), ic_surface_num_outputs(s));
    ic_json_out_end_object(&j);
    return ic_json_out_finish(&j, "surface JSON", err);
}

ic_status ic_surface_write_json(FILE *f, ic_surface *s, const char *name, const double *at,
                                int order, ic_error *err)
{
    IC_ARG_NOT_NULL(f, "f");
    IC_ARG_NOT_NULL(s, "s");
    IC_ARG_NOT_NULL(name, "name");
    IC_ARG_NOT_NULL(at, "at");
    if (order < 0 || order > IC_JET_MAX_ORDER)
        return ic_error_set(err, IC_ERR_INVALID, 0, "the order %d is outside 0..%d", order,
                            IC_JET_MAX_ORDER);
    ic_jet_space *sp;
    double *taylor;
    ic_status st = taylor_at(&sp, &taylor, s, at, order, err);
    if (st == IC_OK) {
        ic_surface_geometry g;
        ic_error why; /* the reason of a degenerate point, printed in the document */
        ic_error_clear(&why);
        st = ic_surface_geometry_at(s, &g, at, &why);
        if (st == IC_OK || st == IC_ERR_DOMAIN)
            st = write_document(f, s, name, at, order, &g, st, &why, sp, taylor, err);
        else
            st = ic_error_set(err, st, why.column, "%s", why.message);
    }
    free(taylor);
    ic_jet_space_free(sp);
    return st;
}
