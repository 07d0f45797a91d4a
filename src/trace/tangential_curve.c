/* The corrector and orientation for marching along tangential curves
 * (tangential_curve.h, docs/tracing.md). */
#include "tangential_curve.h"
#include "local/pair_access.h"

#include <string.h>

ic_status ic_tcurve_correct(ic_pair *pair, const int par[2], const double X[3],
                            const double params[2][2], double reach, const ic_local_options *opt,
                            ic_local_point *next)
{
    ic_local_point near;
    memset(&near, 0, sizeof near);
    memcpy(near.xyz, X, sizeof near.xyz);
    memcpy(near.params, params, sizeof near.params);
    for (int s = 0; s < 2; s++) {
        double dist;
        /* the predictor's parameters are only first-order here: the
         * projection of X gives parameters as good as X itself */
        if (par[s] && ic_local_project(pair, s, near.params[s], X, opt, &dist) != IC_OK)
            return IC_ERR_UNABLE;
    }
    return ic_local_locate_tangential(pair, next, &near, reach, opt, NULL);
}
