/* NURBS patches in problem files: inline ("type": "nurbs") and from a
 * geomdl (NURBS-Python) JSON file ("type": "geomdl"). docs/nurbs.md. */
#ifndef IC_PROBLEM_NURBS_H
#define IC_PROBLEM_NURBS_H

#include <cjson/cJSON.h>

#include "intercurve/surface.h"

/* The surface object at JSON path `path` holding degree, knots,
 * control_points, optional weights and periodic. Errors name their path
 * under `path`. Other keys are the caller's to check. */
ic_status ic_problem_read_nurbs(ic_surface **s, const cJSON *js, const char *path,
                                const ic_constant *consts, int nconsts, ic_error *err);

/* The surface object naming a geomdl JSON file ("file", relative to
 * base_dir unless absolute) and optionally which of its surfaces ("index",
 * default 0). Errors name the problem's path and the file's own path. */
ic_status ic_problem_read_geomdl(ic_surface **s, const cJSON *js, const char *path,
                                 const char *base_dir, ic_error *err);

#endif
