/* What the layers above the surface layer (trace, curve) may know of a
 * surface beyond the public API: accessor functions, not its layout
 * (surface_internal.h keeps that to the surface folder). */
#ifndef IC_SURFACE_ACCESS_H
#define IC_SURFACE_ACCESS_H

#include "intercurve/surface.h"
#include "net_shape.h"

/* A NURBS surface's recognised shape (net_shape.h; surface_net.c), found
 * on first use and kept, in *out: NULL for any other surface, a patch
 * restricted to part of its knots' domain, a patch not recognised. 0, or -1
 * out of memory (then tried again on the next call). */
int ic_surface_net_shape(ic_surface *s, const ic_net_shape **out);

/* A NURBS surface's point at uv, the same bits as the constant terms of
 * its Taylor coefficients there (ic_nurbs_point; a forced knot side
 * respected), without jets: 0, or -1 for any other surface. */
int ic_surface_nurbs_point(ic_surface *s, const double uv[2], double out[3]);

/* The primitive a primitive surface was made of (ic_surface_new_primitive),
 * NULL for any other surface (surface_access.c). */
const ic_primitive *ic_surface_primitive(const ic_surface *s);

/* A primitive surface's frame as ic_primitive_frame gives it (rows e1,
 * e2, e3; a plane's e3 its unit normal), kept since its creation: 0, or -1
 * for any other surface (frame untouched). */
int ic_surface_primitive_frame(const ic_surface *s, double frame[3][3]);

/* An enclosure of wA f_A + wB f_B over the box X, for two implicit formula
 * surfaces, with the terms their sums share enclosed once (surface_combined.c):
 * nearly coincident surfaces written alike, f_B = f_A + 1e-9, give 1e-9
 * itself where plain intervals give the terms' width. 1, or 0 where it is
 * not formed (another backend, a formula not defined over the whole box,
 * no term in common, out of memory): then it proves nothing. */
int ic_surface_combined_interval(ic_surface *A, ic_interval wA, ic_surface *B, ic_interval wB,
                                 const ic_interval *X, ic_interval *out);

#endif
