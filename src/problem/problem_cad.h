/* Surfaces of problem files read from STEP and IGES files:
 * {"type": "step" | "iges", "file": ..., "entity": N, "form": ...}
 * (docs/cad-files.md, docs/problem-files.md). */
#ifndef IC_PROBLEM_CAD_H
#define IC_PROBLEM_CAD_H

#include <cjson/cJSON.h>

#include "intercurve/surface.h"

/* The surface object at JSON path `path`: "file" (relative to base_dir
 * unless absolute), "entity", optional "form" ("parametric", the default,
 * or "implicit" for a primitive). A NURBS patch gets the file's parameter
 * range; a primitive must follow the file's placement. Errors name the
 * path ("surfaces[0].entity", ".file"), the file and the entity. Other keys
 * are the caller's to check. */
ic_status ic_problem_read_cad(ic_surface **s, const cJSON *js, const char *path,
                              const char *base_dir, int iges, ic_error *err);

#endif
