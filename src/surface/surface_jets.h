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

/* A primitive along a curve, one order at a time: a parametric one along
 * a parameter curve (u(s), v(s)), an implicit one along a space curve
 * (x(s), y(s), z(s)). Its formula's one-variable series (cos u, sin u,
 * cos v, sin v, the local coordinates, their squares and products) each gain
 * their order-k coefficient from the curve's coefficients up to order k
 * (the on-line sin/cos recurrence
 *     k s_k = sum_{j=1..k} j u_j c_{k-j},  k c_k = -sum_{j=1..k} j u_j s_{k-j}
 * and the Cauchy product), so the whole curve to order K costs O(K^2),
 * without the primitive's Taylor polynomial in two or three variables. */
typedef struct {
    const ic_surface *s;
    double in[3][IC_JET_MAX_ORDER + 1]; /* the curve: u, v or x, y, z (caller's, k >= 1) */
    double cu[IC_JET_MAX_ORDER + 1], su[IC_JET_MAX_ORDER + 1];
    double cv[IC_JET_MAX_ORDER + 1], sv[IC_JET_MAX_ORDER + 1];
    double w[IC_JET_MAX_ORDER + 1];    /* parametric torus: R + r cos v */
    double d[3][IC_JET_MAX_ORDER + 1]; /* implicit: local coordinates */
    double rho[IC_JET_MAX_ORDER + 1];  /* implicit torus: d_x^2 + d_y^2 */
    double sum[IC_JET_MAX_ORDER + 1];  /* implicit torus: |d|^2 + R^2 - r^2 */
    double A[3], B[3], C;              /* implicit quadric: sum A_i d_i^2 + B_i d_i + C */
    int quadric;                       /* implicit, not a torus: the series are d alone */
} ic_primitive_along;

/* Whether ic_primitive_along serves the surface (a primitive). */
int ic_primitive_along_serves(const ic_surface *s);

/* Starts at the point `at` ((u, v) or (x, y, z)); the caller then sets
 * in[i][k] for k >= 1 (zero until known). */
void ic_primitive_along_start(ic_primitive_along *pa, const ic_surface *s, const double *at);

/* The order-k coefficient of R(u(s), v(s)) (out[3]) or f(x(s), y(s), z(s))
 * (out[0]), k >= 1, from the curve's coefficients up to order k as they are
 * now. Steps go k = 1, 2, ...; a step may be repeated (after in[.][k]
 * change), and the series must be completed with the final in[.][k]
 * (ic_primitive_along_finish, or another step) before the next order. */
void ic_primitive_along_step(ic_primitive_along *pa, int k, double *out);

/* Completes the series at order k once the curve's order-k coefficients are
 * final: a step without its output. */
void ic_primitive_along_finish(ic_primitive_along *pa, int k);

/* ic_primitive_along_finish and ic_primitive_along_step of order k + 1 in
 * one call, for the jet method, which finds the curve's coefficients of
 * each order from the step of that order: sets the curve's final order-k
 * coefficients (in0, in1, in2: u, v and one ignored, or x, y, z), completes
 * the series at order k and writes the step of order k + 1 (k >= 1,
 * k + 1 <= IC_JET_MAX_ORDER) into next, the curve's coefficients above
 * order k being still zero (as ic_primitive_along_start leaves them). The
 * same result to the bit; an implicit quadric's step is made from the
 * order-k coefficients kept in registers (they come by value): read back
 * from memory just after they were written, a wide load the compiler may
 * make of two of them waits for the writes to reach the cache, and the
 * whole step waits on them. */
void ic_primitive_along_advance(ic_primitive_along *pa, int k, double in0, double in1, double in2,
                                double *next);

#endif
