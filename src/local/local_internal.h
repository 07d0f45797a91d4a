/* Internal pieces of the local layer. */
#ifndef IC_LOCAL_INTERNAL_H
#define IC_LOCAL_INTERNAL_H

#include "intercurve/jet.h"
#include "intercurve/local.h"
#include "pairing/pairing.h"
#include "pair_access.h"

struct ic_pair {
    ic_surface *s[2];      /* A, B (B = A for a self-intersection) */
    int self;
    /* one-variable spaces of order 0..IC_LOCAL_MAX_ORDER (curve jets), the
     * spaces of order 4 for the sheets' derivative tensors (the tangential
     * closed forms need fourth derivatives) and of order 2 for locating */
    ic_jet_space *curve[IC_LOCAL_MAX_ORDER + 1];
    ic_jet_space *tensor[2]; /* [0]: 2 variables, [1]: 3 variables */
    ic_jet_space *near[2];
    ic_pairing pairing; /* what differs between the kinds of pair */
    long nomem;         /* its operations that ran out of memory (ic_pair_nomem_check) */
};

/* One sheet of the pair at the point: its geometry and derivatives to
 * order 4 (parametric: 3 jets of 15 coefficients over (u, v); implicit: one
 * jet of 35 over (x, y, z)). */
typedef struct {
    ic_surface *s;
    int parametric;
    double at[3];          /* (u, v) or (x, y, z) */
    ic_surface_geometry geo;
    double taylor[45];
} ic_sheet;

/* Fills sheet `which` (0 = A, 1 = B) at the point. */
ic_status ic_sheet_at(ic_pair *pair, ic_sheet *sh, int which, const ic_local_point *pt,
                      ic_error *err);

/* The partial derivatives of a parametric sheet to order 4, in the papers'
 * notation: P_i, P_ij, P_ijk (111, 112, 122, 222), P_ijkl (1111 .. 2222), the
 * second form L_ij = P_ij . N, the first form g_ij, and |P_1 x P_2|. */
typedef struct {
    double d1[2][3];
    double d2[2][2][3];
    double d3[4][3];
    double d4[5][3];
    double L[2][2];
    double g[2][2];
    const double *N;
    double area;
} ic_param_data;

void ic_param_data_load(ic_param_data *p, const ic_sheet *sh);

/* Rewrites a domain error of sheet `which` as "surface A/B is singular at
 * the point: ..."; returns st. */
ic_status ic_sheet_singular(ic_error *err, ic_status st, int which);

/* II(X, Y) of a sheet for tangent vectors X, Y in space (relative to the
 * sheet's own normal). */
double ic_sheet_second_form(const ic_sheet *sh, const double *X, const double *Y);

/* Partial derivative of a parametric sheet: d^(i+j) R / du^i dv^j (i+j <= 4). */
void ic_sheet_partial(const ic_sheet *sh, int i, int j, double *out);
/* Partial derivative of an implicit sheet: d^alpha f for alpha in N^3, |alpha| <= 4. */
double ic_sheet_fpartial(const ic_sheet *sh, int ax, int ay, int az);

/* Methods: fill the branch derivatives c^(1..K) (and parameter curves) at
 * a transversal point of the two sheets. */
ic_status ic_jet_method(ic_pair *pair, ic_branch *br, const ic_sheet sh[2], int order,
                        ic_error *err);
ic_status ic_closed_form_method(ic_branch *br, const ic_sheet sh[2], int order, ic_error *err);

/* The closed forms, one per paper (src/local/closed_*.c). Each fills
 * c', c'', c''' (br->derivs[0..2], br->order = 3) oriented by
 * t = N_A x N_B, and, where the paper gives them separately, its own
 * curvature and torsion formulas in `paper` (NULL allowed). */
typedef struct {
    double kappa, tau;
} ic_paper_values;
ic_status ic_closed_hassan_badr(ic_branch *br, const ic_sheet sh[2], ic_paper_values *paper,
                                ic_error *err);
ic_status ic_closed_abdel_all(ic_branch *br, const ic_sheet sh[2], ic_paper_values *paper,
                              ic_error *err);
ic_status ic_closed_patrikalakis_maekawa(ic_branch *br, const ic_sheet sh[2],
                                         ic_paper_values *paper, ic_error *err);

/* x with t . x = r[0], N_A . x = r[1], N_B . x = r[2] (unit t normal to
 * both): x = (r0 N_A x N_B + r1 N_B x t + r2 t x N_A) / det[t; N_A; N_B]. */
void ic_solve_frame(double *x, const double *t, const double *NA, const double *NB,
                    const double *r);

/* The same solve with its cross products and determinant made once: the
 * jet method solves with the same t, N_A, N_B at every order. */
typedef struct {
    double ab[3], bt[3], ta[3]; /* N_A x N_B, N_B x t, t x N_A */
    double det;                 /* det[t; N_A; N_B] */
} ic_frame_solver;

void ic_frame_solver_init(ic_frame_solver *fs, const double *t, const double *NA,
                          const double *NB);

static inline void ic_frame_solve(const ic_frame_solver *fs, double *x, const double *r)
{
    for (int c = 0; c < 3; c++)
        x[c] = (r[0] * fs->ab[c] + r[1] * fs->bt[c] + r[2] * fs->ta[c]) / fs->det;
}
/* c', c'', c''' (arc length) of a curve from its derivatives b1, b2, b3 with
 * respect to any regular parameter (the chain rule for d/ds = |b1|^-1 d/dp). */
void ic_arc_length_derivs(double c[3][3], const double *b1, const double *b2, const double *b3);
/* Flips c', c'', c''' to the orientation t = N_A x N_B if needed. */
void ic_orient_closed(ic_branch *br, const double *NA, const double *NB);

/* From c^(1..K) in br->derivs: t, n, b, kappa, tau, kappa', tau' and the
 * Darboux quantities on both sheets. */
void ic_branch_finish(ic_branch *br, const ic_sheet sh[2], const ic_local_options *opt);


#endif
