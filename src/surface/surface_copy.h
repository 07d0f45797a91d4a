/* A surface's copy for another thread (surface_copy.c). */
#ifndef IC_SURFACE_COPY_H
#define IC_SURFACE_COPY_H

#include "intercurve/surface.h"

/* A deep copy of s with workspaces of its own, which evaluates exactly as s
 * does and may be used by another thread while s is in use. IC_ERR_UNABLE
 * for a callback surface (the caller's code need not be reentrant),
 * IC_ERR_NOMEM out of memory. */
ic_status ic_surface_copy(ic_surface **out, const ic_surface *s, ic_error *err);

#endif
