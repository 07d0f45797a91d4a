/**
 * @file writers.h
 * Results as files: the JSON documents and text summaries
 * that `intercurve eval`, `point` and `trace` print, and traced
 * intersections as CSV, VTK PolyData (legacy ASCII) and OBJ polylines for
 * other tools, their fitted B-splines as STEP and IGES curves;
 * docs/output-formats.md describes every key, column and array. Each
 * writer writes to an open stream the caller owns (it is neither closed nor
 * flushed), reads its inputs without keeping them, and reports a failed
 * write (ferror) as IC_ERR_IO. ic_write_file_atomic puts any writer's
 * output into a file so that no reader ever sees half of it.
 */
#ifndef INTERCURVE_WRITERS_H
#define INTERCURVE_WRITERS_H

#include <stdio.h>

#include "intercurve/local.h"
#include "intercurve/surface.h"
#include "intercurve/trace.h"

#ifdef __cplusplus
extern "C" {
#endif

/** CSV, one row per curve point:
 *  curve,s,x,y,z,u,v,p,q,tx,ty,tz,nx,ny,nz,bx,by,bz,kappa,tau,type;
 *  then one row per special point with the curve and s columns empty. */
IC_API IC_NODISCARD ic_status ic_trace_write_csv(FILE *f, const ic_trace_result *res,
                                                 const ic_pair *pair, ic_error *err);

/** VTK legacy ASCII PolyData: one polyline per curve, one vertex per special
 *  point, point data t, n, b (vectors), kappa, tau, s, curve, traced
 *  (scalars). Where a curve has its B-spline (ic_trace_fit), a stretch
 *  turning more than 0.02 rad gets points of the B-spline between its
 *  traced points, with the B-spline's apparatus there and traced = 0
 *  (docs/output-formats.md). */
IC_API IC_NODISCARD ic_status ic_trace_write_vtk(FILE *f, const ic_trace_result *res,
                                                 ic_error *err);

/** Wavefront OBJ: the points as vertices, one polyline (l) per curve, one
 *  point element (p) per special point. */
IC_API IC_NODISCARD ic_status ic_trace_write_obj(FILE *f, const ic_trace_result *res,
                                                 ic_error *err);

/** The point document (`intercurve point`, docs/output-formats.md): res,
 *  a result of ic_local_apparatus at a point of `pair`, as one JSON object
 *  and a newline. `order` is the K asked of ic_local_apparatus, written as
 *  "order" (a point with no branch has no other record of it); the pair
 *  tells which surfaces are parametric ("params" and
 *  "parameter_derivatives" only for those). Numbers round-trip to the same
 *  doubles; undefined values (non-finite, or flagged undefined) are null.
 *  The document is written as it is made (nothing is allocated): IC_ERR_IO
 *  when f reports a write error. */
IC_API IC_NODISCARD ic_status ic_local_write_json(FILE *f, const ic_local_result *res,
                                           const ic_pair *pair, int order, ic_error *err);

/** The same point for people (`intercurve point --format text`): 15
 *  significant digits, one value per line. IC_ERR_IO on a write error. */
IC_API IC_NODISCARD ic_status ic_local_write_text(FILE *f, const ic_local_result *res, ic_error *err);

/** A certificate's summary as the JSON object {"certificate": {...}} with
 *  the keys of the trace document's report.certificate
 *  (docs/output-formats.md) and a newline: IC_ERR_IO on a write error. */
IC_API IC_NODISCARD ic_status ic_certificate_write_json(FILE *f, const ic_trace_certificate *c,
                                                        ic_error *err);

/** The trace document (`intercurve trace`,
 *  docs/output-formats.md): {"curves", "points", "report"} of a result of
 *  ic_trace on `pair`, as one JSON object and a newline. Numbers round-trip
 *  to the same doubles; undefined values are null. The document is written
 *  as it is made (nothing is allocated): IC_ERR_IO on a write error. */
IC_API IC_NODISCARD ic_status ic_trace_write_json(FILE *f, const ic_trace_result *res,
                                           const ic_pair *pair, ic_error *err);

/** A summary table of a trace for people (`intercurve trace --format
 *  text`): the title (NULL or "" for none), one row per curve and per
 *  special point, the verdict and the report. IC_ERR_IO on a write error. */
IC_API IC_NODISCARD ic_status ic_trace_write_text(FILE *f, const ic_trace_result *res, const char *title,
                                           ic_error *err);

/** The surface document (`intercurve eval`, docs/output-formats.md): the
 *  surface s (called `name` in the document) at `at` (u, v for a
 *  parametric surface, x, y, z for an implicit one): the point or the
 *  value of f, the normal, the tangent basis, both fundamental forms, the
 *  principal curvatures and directions, Gaussian and mean curvature, and
 *  every partial derivative of order 0..`order`. At a degenerate point
 *  (IC_ERR_DOMAIN of ic_surface_geometry_at) the document says why under
 *  "degenerate" and the quantities that need the normal are null.
 *  IC_ERR_INVALID for an order outside 0..IC_JET_MAX_ORDER; the status and
 *  message of the evaluation when the derivatives or the geometry cannot
 *  be computed, IC_ERR_NOMEM when they do not fit in memory (nothing is
 *  written then); IC_ERR_IO as above. s is not const: evaluation grows its workspace. */
IC_API IC_NODISCARD ic_status ic_surface_write_json(FILE *f, ic_surface *s, const char *name,
                                             const double *at, int order, ic_error *err);

/** The fitted curves of res (ic_trace_fit; ic_trace_result_fit) as an
 *  ISO 10303-21 file of AP214 (docs/output-formats.md, "STEP"): each a
 *  B_SPLINE_CURVE_WITH_KNOTS named "curve I" (I its index in res) in a
 *  GEOMETRIC_CURVE_SET, the shape of one product, lengths in millimetres
 *  (the problem's numbers unchanged). title (NULL or "" for none) names the
 *  file and the product. Curves without a fit are left out; IC_ERR_INVALID
 *  when no curve has one (fit first), IC_ERR_IO on a write error. */
IC_API IC_NODISCARD ic_status ic_trace_write_step(FILE *f, const ic_trace_result *res,
                                                  const char *title, ic_error *err);

/** The same curves as an IGES 5.3 file (docs/output-formats.md, "IGES"):
 *  each a rational B-spline curve (entity 126) with PROP3 = 1 (polynomial,
 *  weights 1), labelled CURVE with subscript I; units flag 2 (millimetres),
 *  model space scale 1; title in the start section. Errors as
 *  ic_trace_write_step. */
IC_API IC_NODISCARD ic_status ic_trace_write_iges(FILE *f, const ic_trace_result *res,
                                                  const char *title, ic_error *err);

/** A writer for ic_write_file_atomic: prints its document into f and
 *  returns IC_OK, or an error status with err filled. */
typedef ic_status (*ic_file_writer)(FILE *f, void *user, ic_error *err);

/**
 * Writes what writer(f, user, err) prints into the file `path`, whole or
 * not at all (docs/output-formats.md, "How files are written"). The output
 * is gathered in memory first, so that a write error is seen where it
 * happens. Then a missing or regular file is replaced by a temporary
 * created beside it with O_CREAT | O_EXCL under a hidden name (a link
 * planted at that name is never followed), synced and renamed over it,
 * keeping the replaced file's permission bits; a symbolic link stays and
 * what it resolves to is written the same way (a dangling link is
 * refused); a device, FIFO or socket is written in place, never replaced;
 * a directory is refused. On any failure the target is left as it was and
 * no temporary remains.
 * Returns the writer's status and message when it fails (nothing is
 * written; an IC_ERR_IO of the writer, which writes to memory, means that
 * memory ran out and is returned as IC_ERR_NOMEM), IC_ERR_NOMEM when
 * memory runs out, IC_ERR_IO ("cannot write PATH: reason", the system's
 * reason) when the file cannot be written. path and user are not kept.
 */
IC_API IC_NODISCARD ic_status ic_write_file_atomic(const char *path, ic_file_writer writer, void *user,
                                            ic_error *err);


#ifdef __cplusplus
}
#endif
#endif
