/* Marching along a tangential intersection curve (the surfaces touch along
 * it: a torus on a sphere): the corrector and the branch orientation. */
#ifndef IC_TRACE_TANGENTIAL_CURVE_H
#define IC_TRACE_TANGENTIAL_CURVE_H

#include "intercurve/trace.h"

/* The point of the tangential curve nearest the predicted point X: each
 * parametric sheet's parameters projected from X (starting at params), then
 * Gauss-Newton on "on both surfaces, normals parallel" within reach. */
ic_status ic_tcurve_correct(ic_pair *pair, const int par[2], const double X[3],
                            const double params[2][2], double reach, const ic_local_options *opt,
                            ic_local_point *next);


#endif
