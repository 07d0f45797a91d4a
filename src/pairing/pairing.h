/*
 * The pairing of two surfaces (docs/architecture.md, "Pairings"): what
 * differs between implicit/implicit, parametric/implicit, two parametric
 * surfaces and a self-intersection, behind one interface built once per
 * pair, in the spirit of GSL's solver types: a table of operations per kind
 * and the state they share. The search for start points (trace/search.c)
 * works on the kind's search space through it alone.
 *
 * The search space: (x, y, z) over the box for two implicit surfaces,
 * (u, v) of the parametric sheet for a parametric/implicit pair, (u, v, p, q)
 * for two parametric sheets (A's (u, v), B's (p, q)).
 */
#ifndef IC_PAIRING_H
#define IC_PAIRING_H

#include "intercurve/expr.h"
#include "intercurve/jet.h"
#include "intercurve/surface.h"
#include "common/frame.h"

typedef struct ic_pairing ic_pairing;

typedef struct {
    const char *name; /* "implicit/implicit", ... */
    int dim;          /* the search space's dimension: 3, 2 or 4 */
    int nparams;      /* how many parameters give a point: 0, 2 or 4 */
    /* The search region (lo, hi, and which coordinates are periodic): the
     * box, or the parametric sheets' domains, which must be finite. */
    ic_status (*region)(const ic_pairing *p, const double box[3][2], int has_box, double *lo,
                        double *hi, int *periodic, ic_error *err);
    /* 1 when both surfaces can be enclosed over the cell (interval
     * evaluation exists for them). */
    int (*enclosable)(const ic_pairing *p, const double *lo, const double *hi);
    /* 1 when interval arithmetic proves that the cell holds no point of
     * both surfaces (an enclosure that failed excludes nothing). */
    int (*excluded)(const ic_pairing *p, const double *lo, const double *hi);
    /* 1 when an enclosure over the cell is unbounded (overflow, a pole). */
    int (*overflows)(const ic_pairing *p, const double *lo, const double *hi);
    /* Min-norm Newton onto the intersection from z (search coordinates,
     * updated); xyz receives the point. 0 when it converged with both
     * distances below accept (a length). */
    int (*newton)(const ic_pairing *p, double accept_rel, double L, double *z, double *xyz);
    /* The sheets' parameters of search coordinates z (implicit sheets'
     * entries untouched). */
    void (*unflatten)(const ic_pairing *p, const double *z, double params[2][2]);
    /* The search coordinates of a point: its parameters, or (x, y, z) for
     * two implicit surfaces. */
    void (*flatten)(const ic_pairing *p, const double xyz[3], const double params[2][2], double *z);
    /* The Newton system of a point on both surfaces in the plane through
     * X0 normal to t, over the search coordinates z: residuals F (lengths:
     * implicit equations divided by |grad f|), Jacobian J (dim columns),
     * the point X. */
    ic_status (*section)(const ic_pairing *p, const double *z, const double t[3],
                         const double X0[3], double F[4], double J[4][4], double X[3],
                         ic_error *err);
    /* z -= dz, periodic parameters brought back into their period. */
    void (*step)(const ic_pairing *p, double *z, const double *dz);
    /* The point of search coordinates z. */
    ic_status (*position)(const ic_pairing *p, const double *z, double xyz[3], ic_error *err);
    /* The residuals of a tangential point at search coordinates z: the
     * distances to the surfaces (over L: f / |grad f|, or R_A - R_B) and
     * the components of N_A x N_B; their number, or -1 where a surface is
     * singular (its normal undefined). */
    int (*contact_residuals)(const ic_pairing *p, const double *z, double L, double *F);
    /* The cell's place in space: its centre's point and parameters and a
     * radius covering the cell; radius 0 where it cannot be placed. */
    void (*place)(const ic_pairing *p, const double *lo, const double *hi, double xyz[3],
                  double params[2][2], double *radius);
    /* 1 when the cell, as given, is proven to hold no closed intersection
     * curve wholly inside it (the loop test, pairing_intervals.c). */
    int (*loop_free)(const ic_pairing *p, const double *lo, const double *hi);
    /* 1 when centred forms prove the cell holds no common point: they
     * separate surfaces closer than a cell's plain enclosure can tell. */
    int (*excluded_centred)(const ic_pairing *p, const double *lo, const double *hi);
    /* 1 when the normal R_u x R_v of a parametric sheet may vanish over the
     * cell (a pole, a pinch point: the loop test cannot succeed there). */
    int (*may_degenerate)(const ic_pairing *p, const double *lo, const double *hi);
    /* Self-intersections only (else NULL): 1 when the cell can hold no pair
     * of distinct preimages worth a start point (one sheet pair per curve,
     * and away from the trivial diagonal by `band`, a parameter width). */
    int (*skip)(const ic_pairing *p, const double *lo, const double *hi, int leaf,
                const double band[2]);
    /* Self-intersections only (else NULL): 1 when the preimages of z are
     * distinct (farther apart than `band`). */
    int (*distinct)(const ic_pairing *p, const double *z, const double band[2]);
} ic_pairing_kind;

/* The operations of a kind's table, each bound to the kind file's static
 * function of the same name: every kind file defines them all, so its table
 * names only what differs (name, dim, nparams, and skip and distinct). */
#define IC_PAIRING_OPERATIONS                                                                      \
    .region = region, .enclosable = enclosable, .excluded = excluded, .overflows = overflows,      \
    .newton = newton, .unflatten = unflatten, .flatten = flatten, .place = place,                  \
    .contact_residuals = contact_residuals, .section = section, .step = step,                      \
    .position = position, .loop_free = loop_free, .excluded_centred = excluded_centred,            \
    .may_degenerate = may_degenerate

/* A self-intersection sheet's glued edges (pairing_glue.c): the edges
 * z[axis] = e0 and e0 + T of a parameter not marked periodic are one curve
 * of the surface, R(u, w) = R(u + T, g(w)) with g(w) = c - w (flip) or
 * w + c; axis -1: none. */
typedef struct {
    int axis, flip;
    double T, c;
} ic_pairing_glue;

struct ic_pairing {
    const ic_pairing_kind *kind;
    ic_surface *S[2];
    int par[2];              /* which sheets are parametric (the loop tests' interface) */
    int P, I;                /* parametric/implicit: the parametric and the implicit sheet */
    ic_jet_space *sp2, *sp3; /* first-order jets over (u, v) and (x, y, z) */
    /* where the problem was moved from (trace/frame.c): its messages give
     * points as xyz + frame.xyz; all zeros when nothing moved */
    ic_frame frame;
    ic_pairing_glue glue; /* self-intersections only; axis -1 elsewhere */
};

/* Looks for glued edges of a self-intersection's sheet (pairing_glue.c). */
void ic_pairing_find_glue(ic_pairing *p);
/* The preimage b = (p, q) on the far edge's side carried back across the
 * glue: G^-1(b) = (p - T, g^-1(q)) along its axis (p->glue.axis >= 0). */
void ic_pairing_glue_back(const ic_pairing *p, const double b[2], double out[2]);
/* A self-intersection's two preimages z = (u, v, p, q) apart: the sum of
 * |u - p| and |v - q| modulo the periods, the least of that and the same
 * with (p, q) carried back across the glue (pairing_self.c). */
double ic_pairing_self_gap(const ic_pairing *p, const double *z);

/* 1 when a parametric sheet's normal may vanish within `rel` of its
 * domain's widths around the point's parameters (a pole, a pinch point). */
int ic_pairing_point_may_degenerate(const ic_pairing *p, const double xyz[3],
                                    const double params[2][2], double rel);

/* 1 when a parametric sheet's normal may vanish over the hull of two
 * points' parameters grown by its size each way (a gap through a pole, a
 * pinch point). */
int ic_pairing_gap_may_degenerate(const ic_pairing *p, const double xyz_a[3],
                                  const double params_a[2][2], const double xyz_b[3],
                                  const double params_b[2][2]);

/* Builds the pairing of A and B (self: B is A, a self-intersection). */
ic_status ic_pairing_init(ic_pairing *p, ic_surface *A, ic_surface *B, int self, ic_error *err);
void ic_pairing_release(ic_pairing *p);

/* The kinds (pairing_implicit.c, pairing_mixed.c, pairing_params.c,
 * pairing_self.c). */
extern const ic_pairing_kind ic_pairing_implicit;
extern const ic_pairing_kind ic_pairing_mixed;
extern const ic_pairing_kind ic_pairing_params;
extern const ic_pairing_kind ic_pairing_self;

/* Shared by the kinds (pairing.c). */
int ic_pairing_excludes_zero(ic_interval a);
int ic_pairing_unbounded(ic_interval a);
/* f and grad f of an implicit surface, both divided by the largest
 * component of grad f (the same zero set; squares of gradients near
 * overflow stay finite). 0, or -1 where it cannot be evaluated. */
int ic_pairing_value_grad(ic_surface *s, const ic_jet_space *sp, const double *x, double *f,
                          double *g);
/* The domain of parametric sheet s as a box, which must be finite. */
ic_status ic_pairing_domain_box(const ic_pairing *p, int s, double lo[2], double hi[2],
                                int periodic[2], ic_error *err);
/* A parametric sheet's point and covering radius over a (u, v) cell. */
void ic_pairing_place_sheet(const ic_pairing *p, int s, const double *lo, const double *hi,
                            double xyz[3], double *radius);
/* Both sheets' enclosures over a cell of the full space (each sheet's own
 * coordinates at offset); 1 when both exist. */
int ic_pairing_enclose_sheet(const ic_pairing *p, int s, const ic_interval *in, ic_interval *out);

/* A parametric sheet's point and first derivatives at (u, v). */
ic_status ic_pairing_sheet_eval1(const ic_pairing *p, int s, const double *uv, double R[3],
                                 double Ru[3], double Rv[3], ic_error *err);
/* An implicit sheet's value and gradient at x, and |grad f| (an error where
 * it vanishes). */
ic_status ic_pairing_implicit_eval1(const ic_pairing *p, int s, const double *x, double *f,
                                    double grad[3], double *gnorm, ic_error *err);
/* uv -= duv on parametric sheet s, periodic parameters wrapped. */
void ic_pairing_step_sheet(const ic_pairing *p, int s, double *uv, const double *duv);

/* Interval pieces of the proofs (pairing_intervals.c). */
ic_interval ic_pairing_point(double x);
ic_interval ic_pairing_mid(ic_interval a);
void ic_pairing_cross(ic_interval *c, const ic_interval *a, const ic_interval *b);
/* Does T . v keep one sign over the cell for some fixed v? */
int ic_pairing_one_sided(const ic_interval *T);
/* The normal R_u x R_v of a parametric sheet over a (u, v) box; 0 where it
 * has no enclosure. */
int ic_pairing_param_normal(ic_surface *s, const double *lo, const double *hi, ic_interval *N);
/* 1 when a parametric sheet's R_u x R_v may vanish over the (u, v) box. */
int ic_pairing_sheet_may_degenerate(ic_surface *s, const double *lo, const double *hi);
/* h(c) + sum_k G[k] (X_k - c_k) excludes 0 over the n-dimensional cell? */
int ic_pairing_centred_excludes(ic_interval hc, const ic_interval *G, const double *lo,
                                const double *hi, int n);

/* The second-order Taylor form: h(c) + gc . (X - c) + (X - c)^T H (X - c) / 2
 * excludes 0 over the n-dimensional cell X (n <= 3; Taylor's theorem with
 * the Lagrange remainder, H enclosing h's Hessian over the convex cell, its
 * entries placed by ic_interval_hess_index; hc and gc enclosing h and its
 * gradient at the point c of X)? It separates surfaces that
 * are nearly the same over a cell (concentric spheres 1e-9 apart), where
 * first-order forms shrink the cell to the square root of the gap. */
int ic_pairing_taylor2_excludes(ic_interval hc, const ic_interval *gc, const ic_interval *H,
                                const ic_interval *X, const double *c, int n);

/* 1 when |h(c)| exceeds |grad h(c)| . |X - c| over the cell: only then can
 * a tighter enclosure of h than the first-order one exclude 0 (h changes
 * by about that much across the cell), so the second-order and common-term
 * forms, which cost a Hessian or a second evaluation, are tried only then
 * (the cells that hold the curve, most of those examined, fail it). */
int ic_pairing_gap_beyond_slope(ic_interval hc, const ic_interval *gc, const ic_interval *X,
                                const double *c, int n);

#endif
