/* The document of `intercurve point` (docs/output-formats.md, "The point
 * document"): one point of an intersection with every branch through it. */
#include "intercurve/writers.h"

#include "io/json_out.h"

static cJSON *value_or_null(json_out *j, int defined, double x)
{
    return defined ? ic_json_out_number(j, x) : cJSON_CreateNull();
}

static cJSON *vector_or_null(json_out *j, int defined, const double *v)
{
    return defined ? ic_json_out_vector(j, v, 3) : cJSON_CreateNull();
}

/* One entry of "surfaces" of a branch: the Darboux quantities (from order
 * 2) and, on a parametric sheet, the derivatives of the parameter curve. */
static cJSON *branch_surface(json_out *j, const ic_branch *br, int s, int parametric)
{
    cJSON *so = cJSON_CreateObject();
    if (br->order >= 2) {
        ic_json_out_add(j, so, "kappa_n", ic_json_out_number(j, br->surface[s].kappa_n));
        ic_json_out_add(j, so, "kappa_g", ic_json_out_number(j, br->surface[s].kappa_g));
        ic_json_out_add(j, so, "tau_g", ic_json_out_number(j, br->surface[s].tau_g));
    }
    if (parametric) {
        cJSON *pd = cJSON_CreateArray();
        for (int k = 0; k < br->param_order && k < br->order; k++)
            ic_json_out_append(j, pd, ic_json_out_vector(j, br->param_derivs[s][k], 2));
        ic_json_out_add(j, so, "parameter_derivatives", pd);
    }
    return so;
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

static cJSON *branch_json(json_out *j, const ic_branch *br, const int parametric[2])
{
    cJSON *o = cJSON_CreateObject();
    ic_json_out_add(j, o, "t", ic_json_out_vector(j, br->t, 3));
    if (!br->regular)
        ic_json_out_add(j, o, "regular", cJSON_CreateFalse());
    ic_json_out_add(j, o, "n", vector_or_null(j, br->frame_defined, br->n));
    ic_json_out_add(j, o, "b", vector_or_null(j, br->frame_defined, br->b));
    ic_json_out_add(j, o, "kappa", value_or_null(j, br->order >= 2, br->kappa));
    ic_json_out_add(j, o, "tau", value_or_null(j, br->tau_defined, br->tau));
    ic_json_out_add(j, o, "kappa_prime", value_or_null(j, br->kappa_prime_defined, br->kappa_prime));
    ic_json_out_add(j, o, "tau_prime", value_or_null(j, br->tau_prime_defined, br->tau_prime));
    const char *why = undefined_reason(br);
    if (why)
        ic_json_out_add(j, o, "undefined", cJSON_CreateString(why));
    cJSON *d = cJSON_CreateArray();
    for (int k = 0; k < br->order; k++)
        ic_json_out_append(j, d, ic_json_out_vector(j, br->derivs[k], 3));
    ic_json_out_add(j, o, "derivatives", d);
    cJSON *surfaces = cJSON_CreateArray();
    for (int s = 0; s < 2; s++)
        ic_json_out_append(j, surfaces, branch_surface(j, br, s, parametric[s]));
    ic_json_out_add(j, o, "surfaces", surfaces);
    return o;
}

/* The keys that only some points have: the contact order, the papers'
 * coefficients, the perturbation method's error estimate. */
static void add_optional(json_out *j, cJSON *doc, const ic_local_result *res)
{
    if (res->contact_order)
        ic_json_out_add(j, doc, "contact_order", cJSON_CreateNumber(res->contact_order));
    ic_json_out_add(j, doc, "method", cJSON_CreateString(ic_method_name(res->method)));
    if (res->npaper) {
        cJSON *pc = cJSON_CreateObject();
        for (int i = 0; i < res->npaper; i++)
            ic_json_out_add(j, pc, res->paper_names[i], ic_json_out_number(j, res->paper_values[i]));
        ic_json_out_add(j, doc, "paper_coefficients", pc);
    }
    if (res->method == IC_METHOD_PERTURBATION)
        ic_json_out_add(j, doc, "error_estimate", ic_json_out_number(j, res->error_estimate));
}

ic_status ic_local_write_json(FILE *f, const ic_local_result *res, const ic_pair *pair, int order,
                              ic_error *err)
{
    json_out j = {0};
    int parametric[2];
    for (int s = 0; s < 2; s++)
        parametric[s] = ic_surface_get_kind(ic_pair_surface(pair, s)) == IC_PARAMETRIC;
    cJSON *doc = cJSON_CreateObject();
    ic_json_out_add(&j, doc, "point", ic_json_out_vector(&j, res->point.xyz, 3));
    ic_json_out_add(&j, doc, "residual", ic_json_out_number(&j, res->point.residual));
    cJSON *params = cJSON_CreateArray();
    for (int s = 0; s < 2; s++)
        ic_json_out_append(&j, params,
                        parametric[s] ? ic_json_out_vector(&j, res->point.params[s], 2)
                                      : cJSON_CreateNull());
    ic_json_out_add(&j, doc, "params", params);
    cJSON *normals = cJSON_CreateArray();
    for (int s = 0; s < 2; s++)
        ic_json_out_append(&j, normals, ic_json_out_vector(&j, res->normals[s], 3));
    ic_json_out_add(&j, doc, "normals", normals);
    ic_json_out_add(&j, doc, "angle", ic_json_out_number(&j, res->angle));
    ic_json_out_add(&j, doc, "type", cJSON_CreateString(ic_point_type_name(res->type)));
    ic_json_out_add(&j, doc, "discriminant", ic_json_out_number(&j, res->discriminant));
    add_optional(&j, doc, res);
    ic_json_out_add(&j, doc, "order", cJSON_CreateNumber(order));
    cJSON *branches = cJSON_CreateArray();
    for (int i = 0; i < res->nbranches; i++)
        ic_json_out_append(&j, branches, branch_json(&j, &res->branches[i], parametric));
    ic_json_out_add(&j, doc, "branches", branches);
    return ic_json_out_write(f, doc, &j, "point JSON", err);
}
