/**
 * @file local.h
 * The differential geometry of an intersection at one point (docs/local.md,
 * docs/tangential.md).
 *
 * A pair is two surfaces A and B (any mix of parametric and implicit), or one
 * parametric surface with itself (a self-intersection: A and B are the two
 * sheets R(u, v) and R(p, q) through the point). A point of the intersection
 * is located from coordinates or parameters and refined onto both surfaces;
 * at a transversal point the curve through it is oriented by
 * t = N_A x N_B / |N_A x N_B| and its Frenet apparatus and arc-length
 * derivatives c^(1..K) are computed by
 *  - the jet method (any order K <= IC_LOCAL_MAX_ORDER; Patrikalakis and
 *    Maekawa (2002), section 6.3.4; docs/references.md): order by
 *    order, three linear equations with the same matrix [t; N_A; N_B];
 *  - the closed-form method (orders <= 3): the papers' formulas, one function
 *    per paper and case (src/local/closed_*.c cite the equations).
 * At a tangential point (normals parallel within the angle option) the point
 * is classified and every branch through it computed (docs/tangential.md).
 */
#ifndef INTERCURVE_LOCAL_H
#define INTERCURVE_LOCAL_H

#include "intercurve/common.h"
#include "intercurve/defaults.h"
#include "intercurve/surface.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Highest derivative order of the local apparatus. */
#define IC_LOCAL_MAX_ORDER 16
/** Highest order of the closed-form method (the papers stop at c'''). */
#define IC_CLOSED_FORM_MAX_ORDER 3

/** Kinds of intersection points (named in docs/tangential.md and
 *  docs/output-formats.md). */
typedef enum {
    IC_POINT_TRANSVERSAL,
    IC_POINT_BRANCH,
    IC_POINT_TANGENTIAL_CURVE,
    IC_POINT_ISOLATED_CONTACT,
    IC_POINT_CUSP,
    IC_POINT_TACNODE,
    IC_POINT_HIGHER_ORDER_CONTACT,
    IC_POINT_TANGENTIAL, /**< tangential, not yet classified */
    /** a singular point of a surface itself (grad f = 0: a cone's apex),
     *  met by the traced curves (whole traces only; docs/tracing.md) */
    IC_POINT_SURFACE_SINGULAR
} ic_point_type;

/** "transversal", "branch-point", ... (the names of docs/output-formats.md): a
 *  static string. */
IC_API const char *ic_point_type_name(ic_point_type type);

typedef enum {
    IC_METHOD_AUTO,        /**< jet at transversal points, height-difference at tangential ones */
    IC_METHOD_JET,
    IC_METHOD_CLOSED_FORM,
    IC_METHOD_PERTURBATION,
    IC_METHOD_HEIGHT_DIFFERENCE /**< tangential points, any order (docs/tangential.md) */
} ic_method;

/** "auto", "jet", "closed-form", "perturbation", "height-difference" (a
 *  static string); and back (-1 if unknown or NULL). */
IC_API const char *ic_method_name(ic_method method);
IC_API int ic_method_from_name(const char *name);

/** Tolerances of the local computations, with their units. */
typedef struct {
    /** length: a given point farther than this from either surface is an
     *  error that says how far (IC_LOCAL_POINT_TOL_DEFAULT) */
    double point_tol;
    /** dimensionless: refinement stops when the residual is below
     *  newton_tol * (1 + |point|) (default 1e-15) */
    double newton_tol;
    /** iterations of each Newton solve (default 60) */
    int max_newton;
    /** grid cells per parameter for the closest-point search (default 24) */
    int grid;
    /** radians: normals closer than this to parallel make the point
     *  tangential (default 1e-5, about eps^(1/3), where the transversal
     *  errors eps/angle^2 meet the O(angle) distance to the tangential
     *  values; docs/tangential.md measures it) */
    double tangential_angle;
    /** parameter distance: two preimages of a self-intersection closer
     *  than this are the same sheet (default 1e-6) */
    double distinct_params;
    /** 1/length: a curvature at or below this is zero: n, b, tau are then
     *  undefined (default 1e-12) */
    double kappa_zero;
    /** dimensionless: at a tangential point, a coefficient of the height
     *  difference counts as zero when it is below contact_tol times the
     *  scale of its degree (default 1e-8; docs/tangential.md) */
    double contact_tol;
    /** length: the problem's size L. Residuals that are lengths are
     *  measured in units of it where they meet dimensionless ones (the
     *  tangential locator), and its difference steps are fractions of it
     *  (default 1; the tracer sets its problem scale, docs/tracing.md) */
    double scale;
    /** length: how well the point's place is known (default 0: exactly,
     *  as given). At a tangential point, a coefficient of the height
     *  difference that moving the point this far could make or remove is
     *  zero; the tracer sets it from ic_local_tangential_place
     *  (docs/tangential.md) */
    double place_tol;
} ic_local_options;

/** Fills the defaults above. */
IC_API void ic_local_defaults(ic_local_options *opt);

typedef struct ic_pair ic_pair;

/** A pair of surfaces (not owned; they must outlive the pair). B = NULL
 *  makes a self-intersection pair of A, which must be parametric. */
IC_API IC_NODISCARD ic_status ic_pair_new(ic_pair **pair, ic_surface *A, ic_surface *B,
                                          ic_error *err);
/** Frees a pair; NULL is allowed. */
IC_API void ic_pair_free(ic_pair *pair);
/** 1 for a self-intersection pair. */
IC_API int ic_pair_is_self(const ic_pair *pair);
/** Surface 0 (A) or 1 (B; A again for a self-intersection): the caller's
 *  surface given to ic_pair_new, not owned by the pair; NULL for a NULL pair
 *  or another `which`. */
IC_API ic_surface *ic_pair_surface(const ic_pair *pair, int which);

/** A point of the intersection: coordinates and the parameters on each
 *  parametric sheet (unused entries of implicit surfaces are 0). */
typedef struct {
    double xyz[3];
    double params[2][2];
    double residual; /**< length: largest distance to either surface */
} ic_local_point;

/**
 * Locates the point of the intersection nearest to xyz: parameters of the
 * parametric surfaces by a closest-point search (a grid, then Newton), two
 * distinct preimages for a self-intersection, then a Newton refinement onto
 * both surfaces in the plane through the point normal to the curve.
 * IC_ERR_UNABLE with the distance in the message when xyz is farther than
 * opt->point_tol from either surface (or from the intersection).
 */
IC_API IC_NODISCARD ic_status ic_local_locate(ic_pair *pair, ic_local_point *pt,
                                              const double xyz[3], const ic_local_options *opt,
                                              ic_error *err);

/**
 * The same from parameters: params lists the parameters of the parametric
 * surfaces in problem order (u, v for A if parametric, then those of B; for a
 * self-intersection u, v, p, q). nparams must match (IC_ERR_INVALID).
 */
IC_API IC_NODISCARD ic_status ic_local_locate_params(ic_pair *pair, ic_local_point *pt,
                                                     const double *params, int nparams,
                                                     const ic_local_options *opt, ic_error *err);

/**
 * Locates a point of the intersection from a guess with its position and
 * its parameters on the parametric surfaces (the others' entries ignored):
 * ic_local_locate_params from the parameters where the pair has any, else
 * ic_local_locate from the position.
 */
IC_API IC_NODISCARD ic_status ic_local_locate_guess(ic_pair *pair, ic_local_point *pt,
                                             const double xyz[3], const double params[2][2],
                                             const ic_local_options *opt, ic_error *err);

/**
 * The tangential point nearest to a point close to it: on both surfaces with
 * parallel normals (N_A x N_B = 0), by Gauss-Newton on the residuals of the
 * pairing (distances to the surfaces, the components of N_A x N_B) from
 * `near`. IC_ERR_UNABLE if it does not converge (residual above 1e-12) or
 * moves farther than `reach` (a length).
 */
IC_API IC_NODISCARD ic_status ic_local_locate_tangential(ic_pair *pair, ic_local_point *pt,
                                                         const ic_local_point *near, double reach,
                                                         const ic_local_options *opt,
                                                         ic_error *err);

/**
 * How well the place of a located tangential point `pt` is known: the
 * radius (a length) inside which the residuals of ic_local_locate_tangential
 * no longer grow steadily away from it but sit at their rounding noise. A
 * simple tangential point gives a few units in the last place of the
 * problem's size; a contact of order m whose formula cancels gives about
 * (noise)^(1/(m-1)); at most 1e-4 of the problem's size (then the place is
 * not known at all). IC_ERR_UNABLE where a surface is singular near it.
 */
IC_API IC_NODISCARD ic_status ic_local_tangential_place(ic_pair *pair, const ic_local_point *pt,
                                                        const ic_local_options *opt, double *radius,
                                                        ic_error *err);

/**
 * Locates a degenerate tangential point (a cusp, a tacnode or a higher one,
 * contact order 3..8 along the kernel) from `near`, a nearby point of the
 * curve, where ic_local_locate_tangential is ill-conditioned: the point is
 * a simple root of the (m-1)-th derivative of the height difference along
 * the kernel curve (docs/tracing.md). IC_ERR_UNABLE when no point within
 * `reach` (a length) classifies with the contact order it was solved for.
 */
IC_API IC_NODISCARD ic_status ic_local_locate_degenerate(ic_pair *pair, ic_local_point *pt,
                                                         const ic_local_point *near, double reach,
                                                         const ic_local_options *opt,
                                                         ic_error *err);

/** Dimensionless: a point ic_local_find reports is at most this times
 *  (1 + |X|) (a length) from either surface: the tracer's test for a point on
 *  both surfaces; the refinement stops near 1e-15 of that scale, so it
 *  leaves five digits for ill-conditioned sheets. */
#define IC_LOCAL_ON_SURFACE_REL 1e-10
/**
 * The point `intercurve point` reports (docs/local.md, "Locating the point"): located
 * from values (count 3 coordinates, or with by_params the parameters as
 * ic_local_locate_params takes them), then held to the surfaces' residual
 * test: at most IC_LOCAL_ON_SURFACE_REL (1 + |X|) from either surface, whatever
 * opt->point_tol let the search start from; a tangential point that fails
 * it is moved onto the nearest tangential point within point_tol. A point
 * off the surfaces is IC_ERR_UNABLE (or the locator's status) with a
 * message whose first line is "not on the surfaces: residual R at ..." and
 * whose second line says why; IC_ERR_INVALID for a wrong count.
 */
IC_API IC_NODISCARD ic_status ic_local_find(ic_pair *pair, ic_local_point *pt,
                                            const double *values, int count, int by_params,
                                            const ic_local_options *opt, ic_error *err);
/** Darboux quantities of the curve on one surface (docs/local.md, "Outputs"). */
typedef struct {
    double kappa_n; /**< normal curvature c'' . N */
    double kappa_g; /**< geodesic curvature c'' . (N x t) */
    double tau_g;   /**< geodesic torsion -N' . (N x t) = II(t, N x t) */
} ic_darboux;

/** The apparatus of one branch through the point. */
typedef struct {
    int order;                  /**< K: derivatives c^(1..K) are filled */
    double t[3], n[3], b[3];
    double kappa, tau;
    double kappa_prime;         /**< d kappa / ds (needs K >= 3) */
    double tau_prime;           /**< d tau / ds (needs K >= 4) */
    int regular;                /**< 0 at a cusp: t, n, b are one-sided limits, kappa infinite */
    int frame_defined;          /**< 0 where kappa = 0: n, b, tau, tau' undefined */
    int tau_defined;            /**< needs the frame and K >= 3 */
    int kappa_prime_defined, tau_prime_defined;
    double derivs[IC_LOCAL_MAX_ORDER][3];        /**< derivs[k-1] = c^(k) */
    /** derivatives of the parameter curves on each parametric sheet:
     *  param_derivs[s][k-1] = (u^(k), v^(k)) */
    double param_derivs[2][IC_LOCAL_MAX_ORDER][2];
    int param_order;            /**< orders of param_derivs filled (closed forms: 2) */
    ic_darboux surface[2];
} ic_branch;

/**
 * Reverses the orientation of a branch in place (s -> -s, the one
 * orientation map of the library): c^(k) and the parameter curves'
 * derivatives are multiplied by (-1)^k, so t, b, kappa', tau' and the
 * geodesic curvatures kappa_g change sign; n, kappa, tau, the normal
 * curvatures and the geodesic torsions do not.
 */
IC_API void ic_branch_reverse(ic_branch *br);


#define IC_LOCAL_MAX_BRANCHES 8

/** Everything known at one point. */
typedef struct {
    ic_local_point point;
    double normals[2][3];
    double angle;         /**< radians in [0, pi/2]: between the normal lines */
    ic_point_type type;
    ic_method method;     /**< the method that produced the branches */
    /** tangential points: the discriminant Delta = (g_xy/2)^2 - g_xx g_yy / 4 of
     *  the quadratic part of the height difference (> 0 branch point, < 0
     *  isolated contact, 0 degenerate), in 1/length^2; NaN when transversal */
    double discriminant;
    /** tangential points: the order of contact along the kernel (cusp,
     *  tacnode) or of the leading form (higher-order contact); 0 otherwise */
    int contact_order;
    /** closed-form method at tangential points: the paper's coefficients
     *  (Hassan and Badr (2016), eq. (4.8): a11, a12, a22 and the discriminant
     *  a12^2 - a11 a22; Abdel-All et al. (2012), eqs. (4.1), (4.10): A, a11,
     *  a12, a13) */
    int npaper;
    const char *paper_names[4]; /**< static strings */
    double paper_values[4];
    /** perturbation method: the change of the extrapolated t, n, kappa
     *  between the last two Richardson levels (an error estimate); 0 otherwise */
    double error_estimate;
    int nbranches;
    ic_branch branches[IC_LOCAL_MAX_BRANCHES];
} ic_local_result;

/**
 * The apparatus at a located point, to order K (1..IC_LOCAL_MAX_ORDER; the
 * closed-form method to IC_CLOSED_FORM_MAX_ORDER). At a tangential point
 * (angle below opt->tangential_angle) the point is classified and every
 * branch through it computed: by the height-difference method (auto, jet or
 * height-difference), the perturbation method (to order 2) or the papers'
 * closed forms (two parametric or two implicit surfaces; a mixed pair is
 * IC_ERR_INVALID). Perturbation and height-difference at a transversal
 * point are IC_ERR_INVALID, as is an order out of range;
 * IC_ERR_UNABLE where the classification cannot decide (it says why).
 */
IC_API IC_NODISCARD ic_status ic_local_apparatus(ic_pair *pair, ic_local_result *res,
                                                 const ic_local_point *pt, int order,
                                                 ic_method method, const ic_local_options *opt,
                                                 ic_error *err);

/** Local straight-line and plane-curve conditions (Abdel-All et al. (2012),
 *  corollaries 3.1, 3.2) at a branch: kappa <= tol (1/length), and tau = 0
 *  within tol (1/length); a branch with undefined torsion is no plane curve witness. */
IC_API int ic_branch_is_line(const ic_branch *br, double tol);
IC_API int ic_branch_is_planar(const ic_branch *br, double tol);

#ifdef __cplusplus
}
#endif
#endif
