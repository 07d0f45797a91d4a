/* Pieces shared by the STEP and IGES readers (cad_surface.c, cad_nurbs.c),
 * below both: the readers call them and never the dispatcher (cad.c). */
#ifndef IC_CAD_INTERNAL_H
#define IC_CAD_INTERNAL_H

#include "cad_types.h"
#include "intercurve/common.h"

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

/* Appends a copy of *s (taking its arrays) to a growing list. */
ic_status ic_cad_list_append(ic_cad_surface **list, int *n, int *cap, ic_cad_surface *s,
                             ic_error *err);

#endif
