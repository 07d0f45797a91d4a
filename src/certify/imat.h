/*
 * Small interval matrices for the checker's proofs (at most 4 x 4): the
 * midpoint inverse, products with a point matrix, and the two tests every
 * proof rests on. Every bound is rounded outward (expr/interval.c).
 */
#ifndef IC_CERTIFY_IMAT_H
#define IC_CERTIFY_IMAT_H

#include "intercurve/expr.h"

#define IC_CERTIFY_MAX_DIM 4

/* The inverse of the point matrix A (m x m, row-major in a[4][4]) by
 * Gaussian elimination with partial pivoting; 0 when a pivot vanishes. Only
 * an approximation is needed: the tests below are valid for any Y. */
int ic_imat_point_inverse(const double a[4][4], int m, double y[4][4]);

/* The midpoints of an interval matrix. */
void ic_imat_mid(const ic_interval M[4][4], int m, double a[4][4]);

/* 1 when every real matrix in M (m x m) is regular: with Y the inverse of
 * M's midpoint, the row sums of |I - Y M| are all below 1, so for every A
 * in M the matrix Y A = I - (I - Y A) is invertible, and so is A. */
int ic_imat_regular(const ic_interval M[4][4], int m);

/* The Krawczyk operator (Krawczyk 1969; Moore 1977) of a square system
 * over the box X (m unknowns): K = c - Y F(c) + (I - Y M)(X - c), with c X's
 * midpoint, Fc an enclosure of F(c), M an enclosure of the Jacobian over X
 * and Y the midpoint inverse of M. 0 when Y cannot be formed. */
int ic_imat_krawczyk(const ic_interval *X, const ic_interval *Fc, const ic_interval M[4][4], int m,
                     ic_interval *K);

/* K inside the interior of X, coordinate by coordinate. */
int ic_imat_strictly_inside(const ic_interval *K, const ic_interval *X, int m);
/* K and X share no point. */
int ic_imat_disjoint(const ic_interval *K, const ic_interval *X, int m);

#endif
