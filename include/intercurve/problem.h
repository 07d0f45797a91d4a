/**
 * @file problem.h
 * Problem files (docs/problem-files.md lists every key).
 *
 * Every error names the file, the JSON path ("surfaces[1].xyz[2]") in
 * err->path and, for a formula, the column in err->column; the message then
 * ends with a caret picture of the formula.
 */
#ifndef INTERCURVE_PROBLEM_H
#define INTERCURVE_PROBLEM_H

#include <stdio.h>

#include "intercurve/common.h"
#include "intercurve/surface.h"

#ifdef __cplusplus
extern "C" {
#endif

#define IC_PROBLEM_MAX_FILE (16 * 1024 * 1024)

typedef struct ic_problem ic_problem;

/** Reads and validates a problem file. IC_ERR_PARSE for malformed JSON or
 *  formulas, IC_ERR_INVALID for wrong values, with path and message. */
IC_API IC_NODISCARD ic_status ic_problem_load(ic_problem **p, const char *filename, ic_error *err);
/** The same from a JSON text in memory. */
IC_API IC_NODISCARD ic_status ic_problem_parse(ic_problem **p, const char *json, size_t len,
                                               ic_error *err);
/** Flags of ic_problem_read. IC_PROBLEM_ONE_SURFACE: a file whose
 *  "surfaces" holds one surface without "self" is accepted too, a surface
 *  to evaluate rather than an intersection (ic_problem_num_surfaces is 1,
 *  ic_problem_is_self 0); without it such a file is IC_ERR_INVALID. */
#define IC_PROBLEM_ONE_SURFACE 1u
/** Reads and validates a problem from an open stream, to its end (the
 *  stream is not closed); `name` stands for it in messages. IC_ERR_INVALID
 *  when the stream cannot be read or holds more than IC_PROBLEM_MAX_FILE
 *  bytes; otherwise as ic_problem_parse. ic_problem_load is fopen and this
 *  without flags. */
IC_API IC_NODISCARD ic_status ic_problem_read(ic_problem **p, FILE *f, const char *name, unsigned flags,
                                       ic_error *err);
/** Frees a problem and its surfaces; NULL is allowed. */
IC_API void ic_problem_free(ic_problem *p);

/* The accessors' pointers (NULL for a NULL problem or an index out of range)
 * point into the problem: valid until ic_problem_free. The counts and flags
 * are 0 for a NULL problem. */
/** The title ("" when the file has none). */
IC_API const char *ic_problem_title(const ic_problem *p);
IC_API int ic_problem_num_surfaces(const ic_problem *p);
/** The i-th surface (owned by the problem). */
IC_API ic_surface *ic_problem_surface(const ic_problem *p, int i);
IC_API const char *ic_problem_surface_name(const ic_problem *p, int i);
/** Index of the surface called `name`, or -1 (also for NULL arguments). */
IC_API int ic_problem_find_surface(const ic_problem *p, const char *name);
/** 1 for a self-intersection problem. */
IC_API int ic_problem_is_self(const ic_problem *p);
/** 1 if the problem has a box; then box[3][2] receives it. */
IC_API int ic_problem_box(const ic_problem *p, double box[3][2]);

#ifdef __cplusplus
}
#endif
#endif
