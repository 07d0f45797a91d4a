/* The apparatus at a located point: sheets, classification by the angle
 * between the normals, the chosen method, the Frenet frame. */
#include "common/args.h"
#include "tangential.h"
#include "common/vec3.h"

#include <math.h>
#include <string.h>

static ic_status apparatus(ic_pair *pair, ic_local_result *res, const ic_local_point *pt,
                           int order, ic_method method, const ic_local_options *opt,
                           ic_error *err)
{
    memset(res, 0, sizeof *res);
    res->point = *pt;
    res->discriminant = NAN;
    res->method = method == IC_METHOD_AUTO ? IC_METHOD_JET : method;
    if (order < 1 || order > IC_LOCAL_MAX_ORDER)
        return ic_error_set(err, IC_ERR_INVALID, 0, "order %d outside 1..%d", order,
                            IC_LOCAL_MAX_ORDER);
    if (res->method == IC_METHOD_CLOSED_FORM && order > IC_CLOSED_FORM_MAX_ORDER)
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            "the closed-form method gives derivatives up to order %d (the "
                            "papers stop at c'''); use the jet method for order %d",
                            IC_CLOSED_FORM_MAX_ORDER, order);
    ic_sheet sh[2];
    for (int s = 0; s < 2; s++) {
        ic_status st = ic_sheet_at(pair, &sh[s], s, pt, err);
        if (st != IC_OK)
            return ic_sheet_singular(err, st, s);
        memcpy(res->normals[s], sh[s].geo.normal, sizeof sh[s].geo.normal);
    }
    double cr[3];
    ic_cross3(cr, sh[0].geo.normal, sh[1].geo.normal);
    res->angle = atan2(ic_norm3(cr), fabs(ic_dot3(sh[0].geo.normal, sh[1].geo.normal)));
    if (res->angle < opt->tangential_angle) {
        res->type = IC_POINT_TANGENTIAL;
        const int closed = res->method == IC_METHOD_CLOSED_FORM;
        if (closed && sh[0].parametric != sh[1].parametric)
            return ic_error_set(err, IC_ERR_INVALID, 0,
                                "tangential point (normals %.3g rad from parallel): the "
                                "closed forms there cover two parametric surfaces (Hassan and "
                                "Badr (2016), section 4) or two implicit ones (Abdel-All et "
                                "al. (2012), section 4); use height-difference",
                                res->angle);
        const int perturb = res->method == IC_METHOD_PERTURBATION;
        if (!perturb && !closed)
            res->method = IC_METHOD_HEIGHT_DIFFERENCE;
        /* the classification is the height-difference method's */
        ic_status st = ic_height_difference(res, sh, perturb ? 2 : closed ? 3 : order, opt, err);
        if (st != IC_OK)
            return st;
        /* the papers' coefficients, whatever the method */
        if (sh[0].parametric && sh[1].parametric)
            ic_closed_hassan_badr_coefficients(res, sh);
        else if (!sh[0].parametric && !sh[1].parametric)
            ic_closed_abdel_all_coefficients(res, sh);
        if (perturb)
            return ic_perturbation(pair, res, sh, opt, err);
        if (closed) {
            st = sh[0].parametric ? ic_closed_hassan_badr_tangential(res, sh, opt, err)
                                  : ic_closed_abdel_all_tangential(res, sh, opt, err);
            for (int i = 0; st == IC_OK && i < res->nbranches; i++)
                ic_branch_finish(&res->branches[i], sh, opt);
            return st;
        }
        for (int i = 0; i < res->nbranches; i++)
            if (res->branches[i].regular)
                ic_branch_finish(&res->branches[i], sh, opt);
        return IC_OK;
    }
    if (res->method == IC_METHOD_PERTURBATION)
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            "the perturbation method is for tangential points; this one is "
                            "transversal (normals %.3g rad apart)",
                            res->angle);
    if (res->method == IC_METHOD_HEIGHT_DIFFERENCE)
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            "the height-difference method is for tangential points; this one "
                            "is transversal (normals %.3g rad apart)",
                            res->angle);
    res->type = IC_POINT_TRANSVERSAL;
    res->nbranches = 1;
    ic_branch *br = &res->branches[0];
    br->regular = 1;
    ic_status st = res->method == IC_METHOD_CLOSED_FORM
                       ? ic_closed_form_method(br, sh, order, err)
                       : ic_jet_method(pair, br, sh, order, err);
    if (st != IC_OK)
        return st;
    br->regular = 1;
    ic_branch_finish(br, sh, opt);
    return IC_OK;
}

/* (the perturbation method tries the apparatus at nearby points, and passes
 * over those where it fails: out of memory there is the pair's to tell;
 * tests/test_nomem.c, "apparatus, tangential") */
ic_status ic_local_apparatus(ic_pair *pair, ic_local_result *res, const ic_local_point *pt,
                             int order, ic_method method, const ic_local_options *opt,
                             ic_error *err)
{
    IC_ARG_NOT_NULL(pair, "pair");
    IC_ARG_NOT_NULL(res, "res");
    IC_ARG_NOT_NULL(pt, "pt");
    IC_ARG_NOT_NULL(opt, "opt");
    const long before = pair->nomem;
    const ic_status st = apparatus(pair, res, pt, order, method, opt, err);
    return ic_pair_nomem_check(pair, before, st, err);
}
