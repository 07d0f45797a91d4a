/* The residuals of a tangential point (N_A x N_B = 0 on both surfaces) over
 * the unknowns of a pairing, shared by the tangential locator and the
 * estimate of how well its place is known (locate_tangential.c,
 * tangential_place.c). */
#ifndef IC_TANGENTIAL_RESIDUALS_H
#define IC_TANGENTIAL_RESIDUALS_H

#include "local_internal.h"

typedef struct {
    ic_pair *pair;
    int params;     /* the unknowns are parameters (else a position) */
    int two_sheets; /* two parametric sheets: (u, v, p, q) */
    int n;          /* unknowns: the pairing's search coordinates */
    ic_local_point base;
    double L; /* the problem's size: length residuals are divided by it */
    /* two parametric sheets with the unknowns (u, v) of A alone, B's (p, q)
     * the projection of R_A(u, v) on B from base: near a multiple root the
     * flat direction moves (u, v) and (p, q) together, which no damping
     * per unknown reaches; over (u, v) alone it is along the unknowns */
    int reduced;
    const ic_local_options *opt;
} ic_tres;


/* Sets up the unknowns z from `near` (opt may be NULL: no reduction). */
void ic_tres_setup(ic_tres *c, ic_pair *pair, const ic_local_point *near,
                   const ic_local_options *opt, double *z);
/* The reduced context of two parametric sheets at the unknowns z. */
void ic_tres_reduce(const ic_tres *c, const double *z, ic_tres *r);
/* Builds the point from the unknowns (a reduced context leaves B's
 * parameters at the base's; ic_tres_residuals_at fills them). */
void ic_tres_unpack(const ic_tres *c, const double *z, ic_local_point *pt);
/* The point in space of the unknowns z. */
ic_status ic_tres_position(const ic_tres *c, const double *z, double xyz[3], ic_error *err);
/* The residuals at z: their number, or -1 where a surface is singular. */
int ic_tres_residuals(const ic_tres *c, const double *z, double *F);
/* The reduced residuals at pt (B's parameters projected into pt). */
int ic_tres_reduced_at(const ic_tres *c, ic_local_point *pt, double *F);
/* The largest residual at z (infinite where a surface is singular or the
 * count differs from m). */
double ic_tres_worst(const ic_tres *c, const double *z, int m, double *F);

#endif
