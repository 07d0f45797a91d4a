/**
 * @file writers.h
 * Traced intersections as files for other tools: CSV, VTK
 * PolyData (legacy ASCII) and OBJ polylines. Each writes to an open stream and
 * reports a failed write as IC_ERR_IO; docs/output-formats.md describes the
 * columns and arrays.
 */
#ifndef INTERCURVE_WRITERS_H
#define INTERCURVE_WRITERS_H

#include <stdio.h>

#include "intercurve/trace.h"

#ifdef __cplusplus
extern "C" {
#endif

/** The classification of a point of curve c: a recorded special point's type
 *  where the point is one (a tangential curve end), tangential-curve along a
 *  tangential curve, transversal otherwise. */
IC_API ic_point_type ic_trace_point_type(const ic_trace_result *res, const ic_trace_curve *c,
                                         const ic_trace_point *p);

/** CSV, one row per curve point:
 *  curve,s,x,y,z,u,v,p,q,tx,ty,tz,nx,ny,nz,bx,by,bz,kappa,tau,type;
 *  then one row per special point with the curve and s columns empty. */
IC_API IC_NODISCARD ic_status ic_trace_write_csv(FILE *f, const ic_trace_result *res,
                                                 const ic_pair *pair, ic_error *err);

/** VTK legacy ASCII PolyData: one polyline per curve, one vertex per special
 *  point, point data t, n, b (vectors), kappa, tau, s, curve (scalars). */
IC_API IC_NODISCARD ic_status ic_trace_write_vtk(FILE *f, const ic_trace_result *res,
                                                 ic_error *err);

/** Wavefront OBJ: the points as vertices, one polyline (l) per curve, one
 *  point element (p) per special point. */
IC_API IC_NODISCARD ic_status ic_trace_write_obj(FILE *f, const ic_trace_result *res,
                                                 ic_error *err);

#ifdef __cplusplus
}
#endif
#endif
