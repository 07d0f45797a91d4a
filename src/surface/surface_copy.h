/* A surface's copy for another thread (surface_copy.c). */
#ifndef IC_SURFACE_COPY_H
#define IC_SURFACE_COPY_H

#include "intercurve/surface.h"

/* A deep copy of s with workspaces of its own, which evaluates exactly as s
 * does and may be used by another thread while s is in use. IC_ERR_UNABLE
 * for a callback surface (the caller's code need not be reentrant),
 * IC_ERR_NOMEM out of memory. */
ic_status ic_surface_copy(ic_surface **out, const ic_surface *s, ic_error *err);

/* The same surface moved to a new origin (surface_shift.c): coordinates
 * x' = x - origin and, if parametric, parameters u' = u - param_at, with
 * nothing rounded. IC_ERR_UNABLE where that cannot be exact (a NURBS patch,
 * a callback, a primitive's centre or a domain bound that does not subtract
 * exactly, a parametric primitive's angles moved), IC_ERR_NOMEM. */
ic_status ic_surface_shifted(ic_surface **out, const ic_surface *s, const double origin[3],
                             const double param_at[2], ic_error *err);

#endif
