/*
 * The pairing's equations over a cell of its search space, as the checker
 * sees them: F (m = dim - 1 components, zero exactly on the intersection)
 * and its Jacobian J (m x dim), enclosed with interval arithmetic over a box,
 * from the surfaces' own enclosures alone (docs/tracing.md, "The
 * certificate"):
 *   implicit/implicit (x, y, z):      F = (f_A(X), f_B(X));
 *   parametric/implicit (u, v):       F = f_I(R_P(u, v)), J by the chain rule;
 *   two parametric sheets (u,v,p,q):  F = R_A(u, v) - R_B(p, q) (also a
 *                                     self-intersection, B = A).
 */
#ifndef IC_CERTIFY_SYSTEM_H
#define IC_CERTIFY_SYSTEM_H

#include "pairing/pairing.h"

typedef struct {
    ic_interval F[3];
    ic_interval J[3][4];
} ic_certify_eval;

/* The equations' count m of a pairing (its dimension less one). */
int ic_certify_equations(const ic_pairing *pg);

/* Encloses F and J over the box X (dim intervals); 0 when a surface has no
 * enclosure there (a callback, a formula undefined somewhere in the box, an
 * overflow): the box then proves nothing. */
int ic_certify_enclose(const ic_pairing *pg, const ic_interval *X, ic_certify_eval *out);

/* F and J at the point z (midpoints of the enclosures at z itself); 0 where
 * they cannot be evaluated. */
int ic_certify_at(const ic_pairing *pg, const double *z, double F[3], double J[3][4]);

/* 1 when the values alone (no derivatives) of some component of F exclude
 * 0 over X: the cells where a formula's derivatives are unbounded (sqrt
 * of x^2 + y^2 on the axis) but its values keep away from 0. */
int ic_certify_values_exclude(const ic_pairing *pg, const ic_interval *X);

/* 1 when some component of F excludes 0 over X. */
int ic_certify_excludes(const ic_certify_eval *e, int m);

/* The midpoint of X (per coordinate) and the enclosure at it: 0 where it
 * has none. */
int ic_certify_centre(const ic_pairing *pg, const ic_interval *X, double *c,
                      ic_certify_eval *at);

/* 1 when the mean value form of some combination of F's components
 * excludes 0 over X (exclude.c), from `over`, the enclosure over X, and
 * `at`, the one at X's midpoint c (ic_certify_centre): it proves empty the
 * cells close to where the surfaces touch. */
int ic_certify_excludes_centred(const ic_pairing *pg, const ic_interval *X,
                                const ic_certify_eval *over, const double *c,
                                const ic_certify_eval *at);

/* Coordinate k of the image point (the parametric sheet's, A's for two
 * sheets) over X, and its gradient over the search coordinates: 0 when it
 * has no enclosure. */
int ic_certify_image_grad(const ic_pairing *pg, const ic_interval *X, int k, ic_interval *v,
                          ic_interval g[4]);

/* The box of parametric sheet `sheet`'s image over X (two parametric kinds
 * and the mixed one; the implicit pairing's X is the point itself). 0 when
 * it has no enclosure. */
int ic_certify_image(const ic_pairing *pg, const ic_interval *X, ic_interval xyz[3]);

#endif
