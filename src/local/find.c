/*
 * The point `intercurve point` and the bindings report: located from
 * coordinates or parameters, then held to the surfaces' own residual test
 * (docs/local.md, "Locating the point"), whatever opt->point_tol let the
 * search start from. A tangential point, where the refinement has no plane
 * normal to the curve to work in, is moved onto the nearest tangential
 * point instead.
 */
#include "common/args.h"
#include "local_internal.h"
#include "common/vec3.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* IC_LOCAL_ON_SURFACE_REL (local.h): the unit keeps points near the origin
 * from asking for zero. */
static double accepted_residual(const double X[3])
{
    return IC_LOCAL_ON_SURFACE_REL * (1.0 + hypot(hypot(X[0], X[1]), X[2]));
}

/* 1 when the sheets' normals at the point are parallel within the
 * tangential angle. */
static int normals_parallel(ic_pair *pair, const ic_local_point *pt, const ic_local_options *opt)
{
    double N[2][3];
    for (int s = 0; s < 2; s++) {
        ic_surface *srf = ic_pair_surface(pair, s);
        const int par = ic_surface_get_kind(srf) == IC_PARAMETRIC;
        ic_surface_geometry g;
        if (ic_surface_normal_at(srf, &g, par ? pt->params[s] : pt->xyz, NULL) != IC_OK)
            return 0;
        memcpy(N[s], g.normal, sizeof N[s]);
    }
    double c[3];
    ic_cross3(c, N[0], N[1]);
    return ic_norm3(c) < sin(opt->tangential_angle);
}

/* A located point off the surfaces at a tangential place (unrefined) is
 * moved onto the nearest tangential point within point_tol; 1 if moved. */
static int snap_tangential(ic_pair *pair, ic_local_point *pt, const ic_local_options *opt)
{
    ic_local_point on;
    if (!normals_parallel(pair, pt, opt) ||
        ic_local_locate_tangential(pair, &on, pt, opt->point_tol, opt, NULL) != IC_OK ||
        !(on.residual <= accepted_residual(on.xyz)))
        return 0;
    *pt = on;
    return 1;
}

/* "not on the surfaces: residual R at WHERE" and, on the next line, why. */
static ic_status not_on_surfaces(ic_error *err, ic_status code, double residual,
                                 const char *where, const char *why)
{
    char first[IC_ERROR_MESSAGE_LEN];
    if (isinf(residual))
        snprintf(first, sizeof first,
                 "not on the surfaces: residual unknown: %s is off a surface whose gradient "
                 "vanishes there", where);
    else
        snprintf(first, sizeof first, "not on the surfaces: residual %.3g at %s", residual,
                 where);
    return ic_error_set(err, code, 0, "%s\n%s", first, why);
}

ic_status ic_local_find(ic_pair *pair, ic_local_point *pt, const double *values, int count,
                        int by_params, const ic_local_options *opt, ic_error *err)
{
    IC_ARG_NOT_NULL(pair, "pair");
    IC_ARG_NOT_NULL(pt, "pt");
    IC_ARG_NOT_NULL(values, "values");
    IC_ARG_NOT_NULL(opt, "opt");
    if (!by_params && count != 3)
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            "the point needs three coordinates X,Y,Z, got %d", count);
    ic_error why;
    ic_error_clear(&why);
    const ic_status st = by_params ? ic_local_locate_params(pair, pt, values, count, opt, &why)
                                   : ic_local_locate(pair, pt, values, opt, &why);
    if (st != IC_OK) {
        /* pt->residual: how far the given point is, as far as measured */
        const double *X = by_params ? pt->xyz : values;
        if (!(pt->residual > accepted_residual(X))) {
            if (err)
                *err = why;
            return st;
        }
        return not_on_surfaces(err, st, pt->residual,
                               by_params ? "the point of the given parameters" : "the given point",
                               why.message);
    }
    if (pt->residual <= accepted_residual(pt->xyz) || snap_tangential(pair, pt, opt))
        return IC_OK;
    char where[160], why_text[IC_ERROR_MESSAGE_LEN];
    snprintf(where, sizeof where, "the nearest point found (%.17g, %.17g, %.17g)", pt->xyz[0],
             pt->xyz[1], pt->xyz[2]);
    snprintf(why_text, sizeof why_text,
             "the surfaces' residual test allows %.3g there (%g of 1 + |X|); the point "
             "tolerance %g only widens the search for the point",
             accepted_residual(pt->xyz), IC_LOCAL_ON_SURFACE_REL, opt->point_tol);
    return not_on_surfaces(err, IC_ERR_UNABLE, pt->residual, where, why_text);
}
