/**
 * @file surface.h
 * One type for every surface: parametric R(u, v) or implicit f(x, y, z) = 0,
 * given as formulas, as a C callback, or as a primitive.
 *
 * Conventions (docs/conventions.md):
 *  - unit normal: parametric N = (R_u x R_v) / |R_u x R_v|, implicit
 *    N = grad f / |grad f|;
 *  - second fundamental form L = R_uu . N, M = R_uv . N, N = R_vv . N
 *    (implicit: II(X, Y) = -X^T Hess(f) Y / |grad f| on an orthonormal
 *    tangent basis), so the normal curvature of a curve c on the surface is
 *    c'' . N and a sphere with its outward normal has principal curvatures
 *    -1/r;
 *  - principal curvatures are ordered k1 >= k2.
 *
 * A surface owns a workspace that grows on first use of a new order, so
 * evaluation does not allocate in steady state (up to order 4 in its own
 * variables it is made with the surface: those evaluations never allocate);
 * one surface object must not be evaluated from two threads at once.
 */
#ifndef INTERCURVE_SURFACE_H
#define INTERCURVE_SURFACE_H

#include "intercurve/common.h"
#include "intercurve/expr.h"
#include "intercurve/jet.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
    IC_SURFACE_NONE = -1, /**< no surface: what ic_surface_get_kind(NULL) returns */
    IC_PARAMETRIC = 0,
    IC_IMPLICIT = 1
} ic_surface_kind;

typedef enum {
    IC_PRIM_PLANE,
    IC_PRIM_SPHERE,
    IC_PRIM_CYLINDER,
    IC_PRIM_CONE,
    IC_PRIM_TORUS,
    IC_PRIM_ELLIPSOID
} ic_primitive_kind;

/**
 * A primitive, given in its standard position (axis along z) and placed by
 * `center`, `axis` and `ref_direction` (docs/surfaces.md gives both forms of
 * each): with the local frame (e1, e2, e3) of ic_primitive_frame and Q the
 * matrix of columns e1, e2, e3, the placed surface is R = center +
 * Q R_local(u, v) and f(x) = f_local(Q^T (x - center)), where R_local and
 * f_local are the forms below with c = 0 (all placement fields zero: Q = I):
 *  - plane:     point `center`, normal `normal`;
 *               R = center + u e1 + v e2 with (e1, e2, normal/|normal|) a
 *               right-handed orthonormal frame; f = normal . (x - center);
 *  - sphere:    R = c + r (cos u cos v, sin u cos v, sin v); f = |x-c|^2 - r^2;
 *  - cylinder:  R = c + (r cos u, r sin u, v); f = (x-cx)^2 + (y-cy)^2 - r^2;
 *  - cone:      apex c, half-angle a: R = c + (v tan a cos u, v tan a sin u, v);
 *               f = (x-cx)^2 + (y-cy)^2 - tan^2(a) (z-cz)^2;
 *  - torus:     R = c + ((R + r cos v) cos u, (R + r cos v) sin u, r sin v);
 *               f = (|x-c|^2 + R^2 - r^2)^2 - 4 R^2 ((x-cx)^2 + (y-cy)^2);
 *  - ellipsoid: R = c + (a cos u cos v, b sin u cos v, c sin v);
 *               f = (x-cx)^2/a^2 + (y-cy)^2/b^2 + (z-cz)^2/c^2 - 1.
 */
typedef struct {
    ic_primitive_kind kind;
    double center[3];
    double normal[3];     /**< plane */
    double radius;        /**< sphere, cylinder; torus: tube radius r */
    double major_radius;  /**< torus: R */
    double half_angle;    /**< cone, radians, in (0, pi/2) */
    double axes[3];       /**< ellipsoid semi-axes */
    /** Placement (the plane has no axis, its `normal` places it, but it
     *  takes a ref_direction for its e1): the local z axis and the local x
     *  direction (the parametrisation's u = 0 seam), both in space, any
     *  length. All zero: z and x, the standard position above; an axis with
     *  a zero ref_direction gets the default e1 of ic_primitive_frame. A
     *  ref_direction not normal to the axis is made normal to it (its
     *  component along the axis removed); parallel to it is an error. */
    double axis[3];
    double ref_direction[3];
} ic_primitive;

/** Smallest angle, in radians, between a primitive's ref_direction (or a
 *  plane's) and its axis (or the plane's normal), either way round: closer
 *  to parallel is an error, as the seam would be set by rounding rather
 *  than by the direction given. */
#define IC_PRIMITIVE_REF_MIN_ANGLE 1e-6

/**
 * The local frame of a primitive as its surface uses it: frame[0..2] = e1,
 * e2, e3, a right-handed orthonormal frame. e3 is the normalised axis (the
 * plane's normal; z when the axis is zero); e1 is the normalised
 * ref_direction with its component along e3 removed, or, when ref_direction
 * is zero, the coordinate axis least aligned with e3 (the first in a tie)
 * made normal to it, which is x for the axis z; e2 = e3 x e1.
 * IC_ERR_INVALID, saying what, on non-finite placement numbers, an axis
 * that is zero while ref_direction is not, a ref_direction within
 * IC_PRIMITIVE_REF_MIN_ANGLE of the axis, a plane given an axis (its normal
 * places it), or a plane's zero normal.
 */
IC_API IC_NODISCARD ic_status ic_primitive_frame(const ic_primitive *prim, double frame[3][3],
                                                 ic_error *err);

/** Largest degree of a NURBS patch in either parameter. */
#define IC_NURBS_MAX_DEGREE 9

/**
 * A NURBS patch (docs/nurbs.md): R(u, v) = sum N_i,p(u) N_j,q(v) w_ij P_ij /
 * sum N_i,p(u) N_j,q(v) w_ij over the domain [knots[0][p], knots[0][n_u]] x
 * [knots[1][q], knots[1][n_v]], p = degree[0], n_u = count[0] (likewise q, n_v
 * along v). Nothing is owned: the surface copies what it needs.
 */
typedef struct {
    int degree[2];          /**< 1..IC_NURBS_MAX_DEGREE */
    int count[2];           /**< control points along u and along v, each > degree */
    const double *knots[2]; /**< count[d] + degree[d] + 1 nondecreasing values */
    const double *points;   /**< point (i, j) at points[3 * (i * count[1] + j)] */
    const double *weights;  /**< count[0] * count[1] positive values, or NULL: all 1 */
    int periodic[2];        /**< the patch closes on itself along u (v): checked */
} ic_nurbs;

/**
 * A surface given by code. It fills `derivs` with the partial derivatives
 * (not divided by factorials) of the surface at `at`, up to the order of
 * `sp`, in the monomial order of `sp` (jet.h): for a parametric surface
 * three consecutive arrays (x, y, z) of ic_jet_space_len(sp) doubles over
 * (u, v); for an implicit one a single array over (x, y, z). It returns 0,
 * or nonzero where the surface is not defined at `at`.
 */
typedef int (*ic_surface_callback)(void *user, double *derivs, const double *at,
                                   const ic_jet_space *sp);

/** Sine-like threshold below which a parametric point counts as degenerate:
 *  |R_u x R_v| <= IC_SURFACE_DEGENERATE * max(|R_u|, |R_v|)^2. */
#define IC_SURFACE_DEGENERATE 1e-10

typedef struct ic_surface ic_surface;

/** Parametric surface from formulas x, y, z over the parameters
 *  params[2] (NULL: "u", "v"). On a parse error, *which (if not NULL) is the
 *  index of the formula at fault and err->column its column. */
IC_API IC_NODISCARD ic_status ic_surface_new_parametric(ic_surface **s, const char *const xyz[3],
                                                        const char *const params[2],
                                                        const ic_constant *consts, int nconsts,
                                                        int *which, ic_error *err);
/** Implicit surface f(x, y, z) = 0 from a formula. */
IC_API IC_NODISCARD ic_status ic_surface_new_implicit(ic_surface **s, const char *f,
                                                      const ic_constant *consts, int nconsts,
                                                      ic_error *err);
IC_API IC_NODISCARD ic_status ic_surface_new_callback(ic_surface **s, ic_surface_kind kind,
                                                      ic_surface_callback fn, void *user,
                                                      ic_error *err);
/** A primitive in its parametric or implicit form. IC_ERR_INVALID on
 *  non-positive radii or axes, a zero plane normal, a cone angle outside
 *  (0, pi/2), a bad placement (ic_primitive_frame). Parametric
 *  primitives get their natural domain (docs). */
IC_API IC_NODISCARD ic_status ic_surface_new_primitive(ic_surface **s, const ic_primitive *prim,
                                                       ic_surface_kind form, ic_error *err);
/** A NURBS patch (copied). IC_ERR_INVALID names the field at fault in
 *  err->path, relative to the patch ("knots[1][4]", "weights[2][0]"): a
 *  degree outside 1..IC_NURBS_MAX_DEGREE, too few points, a knot that is not
 *  finite or decreases, an empty domain, a weight that is not positive, a
 *  coordinate that is not finite, a periodic flag the points do not close. */
IC_API IC_NODISCARD ic_status ic_surface_new_nurbs(ic_surface **s, const ic_nurbs *nurbs,
                                                   ic_error *err);
/** Frees a surface; NULL is allowed. */
IC_API void ic_surface_free(ic_surface *s);

/**
 * Knot lines of a NURBS patch, where its derivatives may jump (docs/nurbs.md):
 * 1 and *knot if going from parameter value `from` to `to` along parameter
 * `dir` (0: u, 1: v) meets one (from excluded, to included; the first met),
 * else 0. Always 0 for other surfaces and NULL.
 */
IC_API int ic_surface_knot_crossed(const ic_surface *s, int dir, double from, double to,
                                   double *knot);

/** 1 if parameter dir of a NURBS patch wraps (periodic) at a seam, where its
 *  derivatives may jump as on a knot line: the two ends of the domain are
 *  one line, the tracer puts a point on it like on a knot line. Else 0. */
IC_API int ic_surface_knot_seam(const ic_surface *s, int dir);

/**
 * Which polynomial piece of a NURBS patch gives the derivatives at a point on
 * a knot line: side[d] = -1 the piece below the knot along parameter d, +1
 * the piece above, 0 (the default; also side = NULL) the piece a composed
 * parameter jet heads into (ic_surface_taylor alone takes the piece above).
 * A tracer sets it where a curve crosses a knot line, so the apparatus there
 * is that of the side the curve goes to. No effect on other surfaces.
 */
IC_API void ic_surface_set_knot_side(ic_surface *s, const int side[2]);

IC_API ic_surface_kind ic_surface_get_kind(const ic_surface *s);
/** Number of variables: 2 for parametric (u, v), 3 for implicit (x, y, z);
 *  0 for NULL (as ic_surface_num_outputs). */
IC_API int ic_surface_num_vars(const ic_surface *s);
/* The spelling before 0.1.0 (deprecated; docs/packaging.md). */
#define ic_surface_num_inputs ic_surface_num_vars
/** 3 for parametric (x, y, z), 1 for implicit (f). */
IC_API int ic_surface_num_outputs(const ic_surface *s);

/** Parameter domain [[u0, u1], [v0, v1]] and periodic flags of a parametric
 *  surface. IC_ERR_INVALID for an implicit surface or u0 >= u1. */
IC_API IC_NODISCARD ic_status ic_surface_set_domain(ic_surface *s, const double domain[2][2],
                                                    const int periodic[2], ic_error *err);
IC_API void ic_surface_get_domain(const ic_surface *s, double domain[2][2], int periodic[2]);

/**
 * Taylor coefficients of the surface at `at` (u, v or x, y, z): `sp` must
 * have ic_surface_num_vars(s) variables; `out` receives
 * ic_surface_num_outputs(s) consecutive jets of sp. The partial derivative
 * d^alpha is out[i] * ic_jet_factorial(sp, i). IC_ERR_DOMAIN where the
 * surface is undefined at `at` (err says which operation), IC_ERR_INVALID on
 * a space of the wrong number of variables.
 */
IC_API IC_NODISCARD ic_status ic_surface_taylor(ic_surface *s, double *out, const double *at,
                                                const ic_jet_space *sp, ic_error *err);

/**
 * The surface composed with jets: `in` holds ic_surface_num_vars(s) jets of
 * `sp` (a parameter curve (u(s), v(s)) or a space curve (x(s), y(s), z(s)),
 * or jets in more variables); `out` receives ic_surface_num_outputs(s)
 * consecutive jets of sp: R(u(s), v(s)) or f(x(s), y(s), z(s)).
 */
IC_API IC_NODISCARD ic_status ic_surface_compose(ic_surface *s, double *out,
                                                 const double *const *in, const ic_jet_space *sp,
                                                 ic_error *err);

/** Point R(at) (parametric, out[3]) or value f(at) (implicit, out[1]). */
IC_API IC_NODISCARD ic_status ic_surface_eval(ic_surface *s, double *out, const double *at,
                                              ic_error *err);

/**
 * Encloses the surface over a box of its inputs: out[3] (parametric: x, y, z
 * over the parameter box) or out[1] (implicit: f over the space box), with
 * outward rounding (expr.h). Formula surfaces and primitives: IC_ERR_UNABLE
 * for callbacks (the caller then samples instead of proving).
 */
IC_API IC_NODISCARD ic_status ic_surface_eval_interval(ic_surface *s, ic_interval *out,
                                                       const ic_interval *in, ic_error *err);

/**
 * The same with the derivatives: out[3] for a parametric surface (out[i].d[0]
 * and d[1] enclose dx_i/du and dx_i/dv over the box), out[1] for an implicit
 * one (out->d[0..2] enclose grad f). Formula surfaces and implicit
 * primitives; IC_ERR_UNABLE otherwise; IC_ERR_DOMAIN when the formula is
 * not defined over the whole box (then the enclosures prove nothing about
 * the box as a whole).
 */
IC_API IC_NODISCARD ic_status ic_surface_eval_interval_grad(ic_surface *s, ic_interval_grad *out,
                                                            const ic_interval *in, ic_error *err);

/**
 * The same to second order (expr.h, ic_interval_hess): out[3] or out[1] as
 * above, h enclosing the second derivatives over the box. Formula surfaces
 * and implicit quadric primitives (IC_ERR_UNABLE otherwise: tori, parametric
 * primitives, NURBS, callbacks); IC_ERR_DOMAIN where the formula or its
 * first two derivatives are not defined over the whole box.
 */
IC_API IC_NODISCARD ic_status ic_surface_eval_interval_hess(ic_surface *s, ic_interval_hess *out,
                                                            const ic_interval *in, ic_error *err);

/** Local geometry of a surface at a point (see the conventions above). */
typedef struct {
    double point[3];       /**< R(u, v); implicit: the given point */
    double value;          /**< implicit: f there (0 on the surface); parametric: 0 */
    double normal[3];      /**< unit normal */
    double basis[2][3];    /**< tangent basis: R_u, R_v; implicit: orthonormal e1, e2 */
    double first[3];       /**< E, F, G in that basis */
    double second[3];      /**< L, M, N in that basis */
    double principal_curvatures[2];          /**< k1 >= k2 */
    double principal_directions[2][3];       /**< unit vectors in space */
    double principal_directions_basis[2][2]; /**< the same in basis coordinates */
    double gauss, mean;    /**< K = k1 k2, H = (k1 + k2) / 2 */
    double normal_length;  /**< |R_u x R_v| or |grad f| */
} ic_surface_geometry;

/**
 * Geometry at `at`. IC_ERR_DOMAIN at a degenerate point (parametric:
 * |R_u x R_v| <= IC_SURFACE_DEGENERATE max(|R_u|, |R_v|)^2, e.g. a sphere
 * pole; implicit: grad f = 0), with err saying so.
 */
IC_API IC_NODISCARD ic_status ic_surface_geometry_at(ic_surface *s, ic_surface_geometry *g,
                                                     const double *at, ic_error *err);
/** The first-order part of ic_surface_geometry_at, several times cheaper:
 *  point, value, normal, normal_length (and, parametric, the basis R_u,
 *  R_v); the other fields are zero. Same errors at degenerate points. */
IC_API IC_NODISCARD ic_status ic_surface_normal_at(ic_surface *s, ic_surface_geometry *g,
                                                   const double *at, ic_error *err);

#ifdef __cplusplus
}
#endif
#endif
