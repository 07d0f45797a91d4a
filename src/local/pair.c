/* Pairs of surfaces, options, names, and the sheets at a point. */
#include "common/args.h"
#include "local_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

const char *ic_point_type_name(ic_point_type type)
{
    switch (type) {
    case IC_POINT_TRANSVERSAL: return "transversal";
    case IC_POINT_BRANCH: return "branch-point";
    case IC_POINT_TANGENTIAL_CURVE: return "tangential-curve";
    case IC_POINT_ISOLATED_CONTACT: return "isolated-contact";
    case IC_POINT_CUSP: return "cusp";
    case IC_POINT_TACNODE: return "tacnode";
    case IC_POINT_HIGHER_ORDER_CONTACT: return "higher-order-contact";
    case IC_POINT_TANGENTIAL: return "tangential";
    case IC_POINT_SURFACE_SINGULAR: return "surface-singular";
    }
    return "unknown";
}

static const char *const METHOD_NAMES[] = {"auto", "jet", "closed-form", "perturbation",
                                           "height-difference"};

const char *ic_method_name(ic_method method)
{
    return method >= IC_METHOD_AUTO && method <= IC_METHOD_HEIGHT_DIFFERENCE
               ? METHOD_NAMES[method]
               : "unknown";
}

int ic_method_from_name(const char *name)
{
    if (!name)
        return -1;
    for (int i = 0; i < 5; i++)
        if (strcmp(name, METHOD_NAMES[i]) == 0)
            return i;
    return -1;
}

void ic_local_defaults(ic_local_options *opt)
{
    if (!opt)
        return;
    opt->point_tol = IC_LOCAL_POINT_TOL_DEFAULT; /* include/intercurve/defaults.h */
    opt->newton_tol = 1e-15;
    opt->max_newton = 60;
    opt->grid = 24;
    opt->tangential_angle = 1e-5; /* about eps^(1/3): docs/tangential.md */
    opt->distinct_params = 1e-6;
    opt->kappa_zero = 1e-12;
    opt->scale = 1.0;
    opt->contact_tol = 1e-8;
    opt->place_tol = 0.0;
}

ic_status ic_pair_new(ic_pair **out, ic_surface *A, ic_surface *B, ic_error *err)
{
    IC_ARG_NOT_NULL(out, "pair");
    *out = NULL;
    IC_ARG_NOT_NULL(A, "A");
    if (!B && ic_surface_get_kind(A) != IC_PARAMETRIC)
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            "a self-intersection needs a parametric surface");
    ic_pair *p = calloc(1, sizeof *p);
    if (!p)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory creating a pair");
    p->s[0] = A;
    p->s[1] = B ? B : A;
    p->self = B == NULL;
    ic_status st = IC_OK;
    for (int k = 0; k <= IC_LOCAL_MAX_ORDER && st == IC_OK; k++)
        st = ic_jet_space_new(&p->curve[k], 1, k, err);
    if (st == IC_OK)
        st = ic_pairing_init(&p->pairing, p->s[0], p->s[1], p->self, err);
    for (int k = 0; k < 2 && st == IC_OK; k++) {
        st = ic_jet_space_new(&p->tensor[k], 2 + k, 4, err);
        if (st == IC_OK)
            st = ic_jet_space_new(&p->near[k], 2 + k, 2, err);
    }
    if (st != IC_OK) {
        ic_pair_free(p);
        return st;
    }
    *out = p;
    return IC_OK;
}

void ic_pair_free(ic_pair *p)
{
    if (!p)
        return;
    for (int k = 0; k <= IC_LOCAL_MAX_ORDER; k++)
        ic_jet_space_free(p->curve[k]);
    for (int k = 0; k < 2; k++) {
        ic_jet_space_free(p->tensor[k]);
        ic_jet_space_free(p->near[k]);
    }
    ic_pairing_release(&p->pairing);
    free(p);
}

int ic_pair_is_self(const ic_pair *p) { return p ? p->self : 0; }
const ic_pairing *ic_pair_pairing(const ic_pair *p) { return &p->pairing; }
void ic_pair_set_frame(ic_pair *pair, const ic_frame *fr) { pair->pairing.frame = *fr; }
ic_surface *ic_pair_surface(const ic_pair *p, int which)
{
    return p && (which == 0 || which == 1) ? p->s[which] : NULL;
}

ic_status ic_sheet_at(ic_pair *pair, ic_sheet *sh, int which, const ic_local_point *pt,
                      ic_error *err)
{
    memset(sh, 0, sizeof *sh);
    sh->s = pair->s[which];
    sh->parametric = ic_surface_get_kind(sh->s) == IC_PARAMETRIC;
    if (sh->parametric) {
        sh->at[0] = pt->params[which][0];
        sh->at[1] = pt->params[which][1];
    } else {
        memcpy(sh->at, pt->xyz, sizeof pt->xyz);
    }
    ic_status st = ic_surface_geometry_at(sh->s, &sh->geo, sh->at, err);
    if (st != IC_OK)
        return st;
    return ic_surface_taylor(sh->s, sh->taylor, sh->at, pair->tensor[sh->parametric ? 0 : 1],
                             err);
}

ic_status ic_pair_nomem_check(ic_pair *pair, long before, ic_status st, ic_error *err)
{
    if (st == IC_ERR_NOMEM)
        pair->nomem++;
    else if (pair->nomem != before)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory");
    return st;
}

long ic_pair_nomem_count(const ic_pair *pair) { return pair->nomem; }
void ic_pair_nomem_restore(ic_pair *pair, long before) { pair->nomem = before; }

void ic_pair_nomem_take(ic_pair *pair, ic_pair *copy)
{
    pair->nomem += copy->nomem;
    copy->nomem = 0;
}

const ic_jet_space *ic_pair_near_space(const ic_pair *pair, int nvars)
{
    return pair->near[nvars - 2];
}

ic_status ic_sheet_singular(ic_error *err, ic_status st, int which)
{
    if (st == IC_ERR_DOMAIN && err) {
        char msg[IC_ERROR_MESSAGE_LEN];
        memcpy(msg, err->message, sizeof msg);
        ic_error_set(err, st, 0, "surface %c is singular at the point: %.200s", 'A' + which, msg);
    }
    return st;
}

static const double FACT[5] = {1, 1, 2, 6, 24};

void ic_sheet_partial(const ic_sheet *sh, int i, int j, double *out)
{
    static const int start[5] = {0, 1, 3, 6, 10};
    const int idx = start[i + j] + j; /* degree i+j, v-exponent j */
    for (int k = 0; k < 3; k++)
        out[k] = sh->taylor[15 * k + idx] * FACT[i] * FACT[j];
}

double ic_sheet_fpartial(const ic_sheet *sh, int a, int b, int c)
{
    static const int start[5] = {0, 1, 4, 10, 20};
    const int d = a + b + c;
    int pos = 0;
    for (int a2 = a + 1; a2 <= d; a2++)
        pos += d - a2 + 1; /* monomials of degree d with a larger x-exponent */
    pos += d - a - b;
    return sh->taylor[start[d] + pos] * FACT[a] * FACT[b] * FACT[c];
}

void ic_param_data_load(ic_param_data *p, const ic_sheet *sh)
{
    ic_sheet_partial(sh, 1, 0, p->d1[0]);
    ic_sheet_partial(sh, 0, 1, p->d1[1]);
    ic_sheet_partial(sh, 2, 0, p->d2[0][0]);
    ic_sheet_partial(sh, 1, 1, p->d2[0][1]);
    memcpy(p->d2[1][0], p->d2[0][1], sizeof p->d2[0][1]);
    ic_sheet_partial(sh, 0, 2, p->d2[1][1]);
    for (int k = 0; k < 4; k++)
        ic_sheet_partial(sh, 3 - k, k, p->d3[k]);
    for (int k = 0; k < 5; k++)
        ic_sheet_partial(sh, 4 - k, k, p->d4[k]);
    p->N = sh->geo.normal;
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++) {
            p->L[i][j] = p->d2[i][j][0] * p->N[0] + p->d2[i][j][1] * p->N[1] + p->d2[i][j][2] * p->N[2];
            p->g[i][j] = p->d1[i][0] * p->d1[j][0] + p->d1[i][1] * p->d1[j][1] + p->d1[i][2] * p->d1[j][2];
        }
    const double *a = p->d1[0], *b = p->d1[1];
    const double c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    p->area = sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
}
