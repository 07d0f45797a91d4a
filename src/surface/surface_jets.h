/* The surface's Taylor polynomials for the layers above (the jet method
 * composes them with the curve one degree at a time). */
#ifndef IC_SURFACE_JETS_H
#define IC_SURFACE_JETS_H

#include "intercurve/surface.h"

/* The space of the surface's inputs at this order (cached; NULL with err set
 * when it cannot be made). */
const ic_jet_space *ic_surface_space(ic_surface *s, int order, ic_error *err);

/* A space of two variables at this order (cached like ic_surface_space):
 * the heights over a tangent plane are composed with an implicit surface
 * one order at a time in them. */
const ic_jet_space *ic_surface_plane_space(ic_surface *s, int order, ic_error *err);

/* ic_surface_taylor, but a NURBS on a knot line takes the piece that
 * heading[2] (a direction in (u, v), or NULL) goes into, as
 * ic_surface_compose does for a parameter jet heading that way. */
ic_status ic_surface_taylor_toward(ic_surface *s, double *out, const double *at,
                                   const double *heading, const ic_jet_space *sp, ic_error *err);

/* The total degree of the surface's function where it is a polynomial of a
 * known degree (an implicit primitive: 1 for a plane, 4 for a torus, 2 for
 * the others; a parametric plane: 1), else -1: its Taylor polynomials have
 * no terms above it, and need not be searched for them. */
int ic_surface_polynomial_degree(const ic_surface *s);

/* Whether the surface is a formula: its tape on the curve's one-variable
 * jets costs less than its Taylor polynomial in two or three variables
 * (docs/performance.md, "Jets"), so the jet method composes it directly. */
int ic_surface_is_formula(const ic_surface *s);

#endif
