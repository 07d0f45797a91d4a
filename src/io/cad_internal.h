/* Pieces shared by the STEP and IGES readers (cad.h). */
#ifndef IC_CAD_INTERNAL_H
#define IC_CAD_INTERNAL_H

#include "cad.h"
#include "intercurve/common.h"
#include "iges_parse.h"
#include "step_parse.h"

/* A patch closes on itself along a direction when its points at the two
 * ends of the domain agree to this much relative to the control net's size
 * (max(1, largest coordinate), in the file's length unit). Writers give
 * 10 to 15 significant digits; 1e-9 allows for 10. */
#define IC_CAD_CLOSURE_TOL 1e-9

/* IC_ERR_INVALID with "WHO: message", WHO naming the entity ("#42
 * (CYLINDRICAL_SURFACE)", "DE 7 (entity 128)"). */
ic_status ic_cad_fail(ic_error *err, const char *who, const char *fmt, ...) IC_PRINTF(3, 4);

/* Allocates the patch's arrays (knots: count + degree + 1 along each
 * direction; weights when `rational`) and points s->nurbs at them, after
 * checking the degrees (1..IC_NURBS_MAX_DEGREE) and counts (above the
 * degree, within IC_CAD_MAX_COUNT and IC_CAD_MAX_POINTS). */
ic_status ic_cad_alloc_nurbs(ic_cad_surface *s, const int degree[2], const int count[2],
                             int rational, const char *who, ic_error *err);
/* Checks the filled patch (finite numbers, nondecreasing knots, positive
 * weights, a domain of positive width), sets s->domain, and sets
 * s->periodic where `closed` says so and the patch truly closes on itself
 * (its boundary curves at the two ends of the domain coincide). */
ic_status ic_cad_finish_nurbs(ic_cad_surface *s, const int closed[2], const char *who,
                              ic_error *err);

/* The readers of each format, on a parsed file. `unit`/`metres` are the
 * file's length unit. ic_*_read: the surface `entity` (or what it leads
 * to); ic_*_list: every surface. */
ic_status ic_step_read(const ic_step_file *f, int entity, ic_cad_surface *out, ic_error *err);
ic_status ic_step_list(const ic_step_file *f, ic_cad_surface **list, int *n, ic_cad_info *info,
                       ic_error *err);
void ic_iges_length_unit(const ic_iges_file *f, char *unit, size_t size, double *metres);
ic_status ic_iges_read(const ic_iges_file *f, int entity, ic_cad_surface *out, ic_error *err);
ic_status ic_iges_list(const ic_iges_file *f, ic_cad_surface **list, int *n, ic_cad_info *info,
                       ic_error *err);

/* Appends a copy of *s (taking its arrays) to a growing list. */
ic_status ic_cad_list_append(ic_cad_surface **list, int *n, int *cap, ic_cad_surface *s,
                             ic_error *err);

#endif
