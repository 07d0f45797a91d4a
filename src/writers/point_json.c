/* The document of `intercurve point` (docs/output-formats.md, "The point
 * document"): one point of an intersection with every branch through it. */
#include "common/args.h"
#include "intercurve/writers.h"
#include "parametric.h"

#include "json/json_out.h"

static void number_member(json_out *j, const char *key, double x)
{
    ic_json_out_key(j, key);
    ic_json_out_number(j, x);
}

static void value_or_null(json_out *j, const char *key, int defined, double x)
{
    ic_json_out_key(j, key);
    if (defined)
        ic_json_out_number(j, x);
    else
        ic_json_out_null(j);
}

static void vector_or_null(json_out *j, const char *key, int defined, const double *v)
{
    ic_json_out_key(j, key);
    if (defined)
        ic_json_out_vector(j, v, 3);
    else
        ic_json_out_null(j);
}

/* One entry of "surfaces" of a branch: the Darboux quantities (from order
 * 2) and, on a parametric sheet, the derivatives of the parameter curve. */
static void branch_surface(json_out *j, const ic_branch *br, int s, int parametric)
{
    ic_json_out_object(j);
    if (br->order >= 2) {
        number_member(j, "kappa_n", br->surface[s].kappa_n);
        number_member(j, "kappa_g", br->surface[s].kappa_g);
        number_member(j, "tau_g", br->surface[s].tau_g);
    }
    if (parametric) {
        ic_json_out_key(j, "parameter_derivatives");
        ic_json_out_array(j);
        for (int k = 0; k < br->param_order && k < br->order; k++)
            ic_json_out_vector(j, br->param_derivs[s][k], 2);
        ic_json_out_end_array(j);
    }
    ic_json_out_end_object(j);
}

/* Why some values of the branch are null, or NULL when all are defined. */
static const char *undefined_reason(const ic_branch *br)
{
    if (!br->regular)
        return "a cusp: t, n, b are one-sided limits along this half-branch; the curvature is "
               "infinite";
    if (!br->frame_defined && br->order >= 2)
        return "the curvature is 0: n, b and the torsion are undefined";
    return NULL;
}

static void branch_json(json_out *j, const ic_branch *br, const int parametric[2])
{
    ic_json_out_object(j);
    ic_json_out_key(j, "t");
    ic_json_out_vector(j, br->t, 3);
    if (!br->regular) {
        ic_json_out_key(j, "regular");
        ic_json_out_bool(j, 0);
    }
    vector_or_null(j, "n", br->frame_defined, br->n);
    vector_or_null(j, "b", br->frame_defined, br->b);
    value_or_null(j, "kappa", br->order >= 2, br->kappa);
    value_or_null(j, "tau", br->tau_defined, br->tau);
    value_or_null(j, "kappa_prime", br->kappa_prime_defined, br->kappa_prime);
    value_or_null(j, "tau_prime", br->tau_prime_defined, br->tau_prime);
    const char *why = undefined_reason(br);
    if (why) {
        ic_json_out_key(j, "undefined");
        ic_json_out_string(j, why);
    }
    ic_json_out_key(j, "derivatives");
    ic_json_out_array(j);
    for (int k = 0; k < br->order; k++)
        ic_json_out_vector(j, br->derivs[k], 3);
    ic_json_out_end_array(j);
    ic_json_out_key(j, "surfaces");
    ic_json_out_array(j);
    for (int s = 0; s < 2; s++)
        branch_surface(j, br, s, parametric[s]);
    ic_json_out_end_array(j);
    ic_json_out_end_object(j);
}

/* The keys that only some points have: the contact order, the papers'
 * coefficients, the perturbation method's error estimate. */
static void add_optional(json_out *j, const ic_local_result *res)
{
    if (res->contact_order) {
        ic_json_out_key(j, "contact_order");
        ic_json_out_int(j, res->contact_order);
    }
    ic_json_out_key(j, "method");
    ic_json_out_string(j, ic_method_name(res->method));
    if (res->npaper) {
        ic_json_out_key(j, "paper_coefficients");
        ic_json_out_object(j);
        for (int i = 0; i < res->npaper; i++)
            number_member(j, res->paper_names[i], res->paper_values[i]);
        ic_json_out_end_object(j);
    }
    if (res->method == IC_METHOD_PERTURBATION)
        number_member(j, "error_estimate", res->error_estimate);
}

ic_status ic_local_write_json(FILE *f, const ic_local_result *res, const ic_pair *pair, int order,
                              ic_error *err)
{
    IC_ARG_NOT_NULL(f, "f");
    IC_ARG_NOT_NULL(res, "res");
    IC_ARG_NOT_NULL(pair, "pair");
    int parametric[2];
    ic_writer_parametric(pair, parametric);
    json_out j;
    ic_json_out_start(&j, f);
    ic_json_out_object(&j);
    ic_json_out_key(&j, "point");
    ic_json_out_vector(&j, res->point.xyz, 3);
    number_member(&j, "residual", res->point.residual);
    ic_json_out_key(&j, "params");
    ic_json_out_array(&j);
    for (int s = 0; s < 2; s++) {
        if (parametric[s])
            ic_json_out_vector(&j, res->point.params[s], 2);
        else
            ic_json_out_null(&j);
    }
    ic_json_out_end_array(&j);
    ic_json_out_key(&j, "normals");
    ic_json_out_array(&j);
    for (int s = 0; s < 2; s++)
        ic_json_out_vector(&j, res->normals[s], 3);
    ic_json_out_end_array(&j);
    number_member(&j, "angle", res->angle);
    ic_json_out_key(&j, "type");
    ic_json_out_string(&j, ic_point_type_name(res->type));
    number_member(&j, "discriminant", res->discriminant);
    add_optional(&j, res);
    ic_json_out_key(&j, "order");
    ic_json_out_int(&j, order);
    ic_json_out_key(&j, "branches");
    ic_json_out_array(&j);
    for (int i = 0; i < res->nbranches; i++)
        branch_json(&j, &res->branches[i], parametric);
    ic_json_out_end_array(&j);
    ic_json_out_end_object(&j);
    return ic_json_out_finish(&j, "point JSON", err);
}
