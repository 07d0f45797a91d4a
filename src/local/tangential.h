/* Tangential points: heights over the tangent plane and the
 * height-difference method (src/local/height.c, src/local/tangential.c). */
#ifndef IC_TANGENTIAL_H
#define IC_TANGENTIAL_H

#include "local_internal.h"

typedef struct {
    double P[3], e1[3], e2[3], N[3]; /* the point and the frame of the tangent plane */
    const ic_jet_space *sp;          /* two variables (x, y) */
    double *psi[2];                  /* heights of A and B along N */
    double *g;                       /* psi_A - psi_B */
} ic_heights;

ic_status ic_heights_compute(ic_heights *h, const ic_sheet sh[2], const ic_jet_space *sp,
                             ic_error *err);
void ic_heights_free(ic_heights *h);

/* Classifies a tangential point and computes every branch through it to
 * `order` (res->type, discriminant, contact_order, branches). */
ic_status ic_height_difference(ic_local_result *res, const ic_sheet sh[2], int order,
                               const ic_local_options *opt, ic_error *err);

/* One step towards a degenerate tangential point of contact order m (3: a
 * cusp, 4: a tacnode, ...) from a nearby point P of the curve: the simple
 * root r of h^(m-1), h(r) = g(r, phi(r)) along dg/dw = 0 across the kernel,
 * nearest P within reach, lifted onto sheet A (X). IC_ERR_UNABLE where there
 * is none. */
ic_status ic_height_degenerate_step(const ic_sheet sh[2], int m, double reach,
                                    const ic_local_options *opt, double X[3], ic_error *err);

/* The perturbation method (Bendrici and Boumedien-Zidani (2022), section 3)
 * for the branches of a point already classified in res (branch point,
 * higher-order contact, tacnode: nearby points on small circles; tangential
 * curve: B shifted along N by epsilon); Richardson-extrapolated, with
 * res->error_estimate. */
ic_status ic_perturbation(ic_pair *pair, ic_local_result *res, const ic_sheet sh[2],
                          const ic_local_options *opt, ic_error *err);

/* Hassan and Badr (2016), section 4, at a tangential point of two
 * parametric sheets already classified in res (branch point or tangential
 * curve): the paper's coefficients and c', c'', c''' on each branch. */
ic_status ic_closed_hassan_badr_tangential(ic_local_result *res, const ic_sheet sh[2],
                                           const ic_local_options *opt, ic_error *err);

/* Abdel-All et al. (2012), section 4 (corrected), at a tangential point of
 * two implicit sheets classified in res: the paper's A, a11, a12, a13 and
 * c', c'', c''' on each branch (replacing the classification's branches). */
ic_status ic_closed_abdel_all_tangential(ic_local_result *res, const ic_sheet sh[2],
                                         const ic_local_options *opt, ic_error *err);

/* The papers' coefficients alone (reported at every tangential point of a
 * parametric/parametric or implicit/implicit pair, whatever the method). */
void ic_closed_abdel_all_coefficients(ic_local_result *res, const ic_sheet sh[2]);
void ic_closed_hassan_badr_coefficients(ic_local_result *res, const ic_sheet sh[2]);

#endif
