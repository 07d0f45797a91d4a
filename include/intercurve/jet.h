/**
 * @file jet.h
 * Truncated multivariate Taylor polynomials ("jets"): the automatic
 * differentiation engine of intercurve.
 *
 * A jet space fixes the number of variables m (1..IC_JET_MAX_VARS) and the
 * total degree K (0..IC_JET_MAX_ORDER). A jet in it is a plain array of
 * ic_jet_space_len() doubles: the Taylor coefficients
 *     c[idx(alpha)] = (d^alpha f)(x0) / alpha!
 * of monomials x^alpha, |alpha| <= K, ordered by total degree, and within one
 * degree by decreasing exponent of the first variable, then the second, ...
 * (m = 2: 1, x, y, x^2, xy, y^2, x^3, ...).
 *
 * The elementary functions use the standard Taylor recurrences, applied to
 * homogeneous parts: with E the Euler operator (multiply the degree-d part
 * by d), E f(a) = f'(a) E a turns every function into a convolution
 * recurrence over degrees (docs/jets.md). No symbolic algebra, no finite
 * differences.
 *
 * Rules for every function below:
 *  - all jets belong to the space `sp`;
 *  - outputs may not alias inputs, except for ic_jet_add, ic_jet_sub,
 *    ic_jet_neg, ic_jet_scale and ic_jet_add_const, which work in place;
 *  - `scratch` is caller-owned memory of ic_jet_scratch_len(sp) doubles
 *    (contents ignored on entry and undefined on return), so no function
 *    allocates;
 *  - a function that returns IC_ERR_DOMAIN leaves its output undefined and
 *    fills `err` (if not NULL) with the reason: the jet of the function does
 *    not exist at that point (log of a jet whose constant term is <= 0,
 *    sqrt at 0, division by 0, ...). NaN is never produced silently.
 */
#ifndef INTERCURVE_JET_H
#define INTERCURVE_JET_H

#include "intercurve/common.h"

#ifdef __cplusplus
extern "C" {
#endif

#define IC_JET_MAX_VARS 4
#define IC_JET_MAX_ORDER 24

typedef struct ic_jet_space ic_jet_space;

/** Creates the space of jets in `nvars` variables of total degree `order`.
 *  Returns IC_ERR_INVALID for nvars outside 1..IC_JET_MAX_VARS or order
 *  outside 0..IC_JET_MAX_ORDER, IC_ERR_NOMEM when the tables do not fit. */
IC_API IC_NODISCARD ic_status ic_jet_space_new(ic_jet_space **sp, int nvars, int order,
                                               ic_error *err);
/** Frees a space; NULL is allowed. */
IC_API void ic_jet_space_free(ic_jet_space *sp);

/* The getters below return 0 for a NULL space (ic_jet_index -1). */
/** Number of variables m. */
IC_API int ic_jet_space_num_vars(const ic_jet_space *sp);
/* The spelling before 0.1.0 (deprecated; docs/packaging.md). */
#define ic_jet_space_nvars ic_jet_space_num_vars
IC_API int ic_jet_space_order(const ic_jet_space *sp);
/** Number of coefficients, C(m + K, m). */
IC_API int ic_jet_space_len(const ic_jet_space *sp);
/** Number of doubles of scratch every function of this space may need. */
IC_API size_t ic_jet_scratch_len(const ic_jet_space *sp);
/** Index of the first coefficient of total degree d (0 <= d <= K + 1). */
IC_API int ic_jet_degree_start(const ic_jet_space *sp, int d);
/** Index of monomial x^alpha (alpha has nvars entries), or -1 if |alpha| > K
 *  or an entry is negative. */
IC_API int ic_jet_index(const ic_jet_space *sp, const int *alpha);
/** Exponents of the monomial at `index` into alpha[nvars]; alpha is left as
 *  it was for an index out of range. */
IC_API void ic_jet_exponents(const ic_jet_space *sp, int index, int *alpha);
/** alpha! = alpha_1! ... alpha_m! of the monomial at `index`: the factor
 *  between a Taylor coefficient and the partial derivative (0 for an index
 *  out of range). */
IC_API double ic_jet_factorial(const ic_jet_space *sp, int index);

/* ---- construction and linear operations (in place allowed) ---- */

/** c = 0. */
IC_API void ic_jet_zero(double *c, const ic_jet_space *sp);
/** c = value (a constant). */
IC_API void ic_jet_set_const(double *c, double value, const ic_jet_space *sp);
/** c = value + x_var: the jet of the coordinate function x_var at value. */
IC_API void ic_jet_set_var(double *c, double value, int var, const ic_jet_space *sp);
IC_API void ic_jet_copy(double *c, const double *a, const ic_jet_space *sp);
IC_API void ic_jet_add(double *c, const double *a, const double *b, const ic_jet_space *sp);
IC_API void ic_jet_sub(double *c, const double *a, const double *b, const ic_jet_space *sp);
IC_API void ic_jet_neg(double *c, const double *a, const ic_jet_space *sp);
/** c = s * a. */
IC_API void ic_jet_scale(double *c, const double *a, double s, const ic_jet_space *sp);
/** c = a + s (the constant term only). */
IC_API void ic_jet_add_const(double *c, const double *a, double s, const ic_jet_space *sp);

/* ---- products and functions (no aliasing of output and inputs) ---- */

/** c = a * b truncated at degree K. */
IC_API void ic_jet_mul(double *c, const double *a, const double *b, const ic_jet_space *sp);
/** q = a / b. IC_ERR_DOMAIN if b(0) = 0. */
IC_API IC_NODISCARD ic_status ic_jet_div(double *q, const double *a, const double *b,
                                         const ic_jet_space *sp, ic_error *err);
/** b = sqrt(a). IC_ERR_DOMAIN if a(0) < 0, or a(0) = 0 and K > 0. */
IC_API IC_NODISCARD ic_status ic_jet_sqrt(double *b, const double *a, const ic_jet_space *sp,
                                          ic_error *err);
/** b = a^n for an integer n (binary powering; a(0) may be 0 when n >= 0).
 *  IC_ERR_DOMAIN if n < 0 and a(0) = 0. */
IC_API IC_NODISCARD ic_status ic_jet_pow_int(double *b, const double *a, long n,
                                             const ic_jet_space *sp, double *scratch,
                                             ic_error *err);
/** b = a^p for a real p. Integral p goes to ic_jet_pow_int; otherwise
 *  IC_ERR_DOMAIN unless a(0) > 0 (or a(0) = 0, p > 0, K = 0). */
IC_API IC_NODISCARD ic_status ic_jet_pow_real(double *b, const double *a, double p,
                                              const ic_jet_space *sp, double *scratch,
                                              ic_error *err);
IC_API void ic_jet_exp(double *b, const double *a, const ic_jet_space *sp);
/** IC_ERR_DOMAIN if a(0) <= 0. */
IC_API IC_NODISCARD ic_status ic_jet_log(double *b, const double *a, const ic_jet_space *sp,
                                         ic_error *err);
/** s = sin(a) and c = cos(a) together (s, c distinct). */
IC_API void ic_jet_sin_cos(double *s, double *c, const double *a, const ic_jet_space *sp);
IC_API void ic_jet_sin(double *s, const double *a, const ic_jet_space *sp, double *scratch);
IC_API void ic_jet_cos(double *c, const double *a, const ic_jet_space *sp, double *scratch);
/** IC_ERR_DOMAIN where cos(a(0)) = 0. */
IC_API IC_NODISCARD ic_status ic_jet_tan(double *t, const double *a, const ic_jet_space *sp,
                                         double *scratch, ic_error *err);
/** IC_ERR_DOMAIN unless |a(0)| < 1 (|a(0)| = 1 allowed only when K = 0). */
IC_API IC_NODISCARD ic_status ic_jet_asin(double *b, const double *a, const ic_jet_space *sp,
                                          double *scratch, ic_error *err);
IC_API IC_NODISCARD ic_status ic_jet_acos(double *b, const double *a, const ic_jet_space *sp,
                                          double *scratch, ic_error *err);
IC_API void ic_jet_atan(double *b, const double *a, const ic_jet_space *sp, double *scratch);
/** b = atan2(y, x), continuous branch through (y(0), x(0)).
 *  IC_ERR_DOMAIN if x(0) = y(0) = 0. */
IC_API IC_NODISCARD ic_status ic_jet_atan2(double *b, const double *y, const double *x,
                                           const ic_jet_space *sp, double *scratch, ic_error *err);
/** s = sinh(a), c = cosh(a) together (s, c distinct). */
IC_API void ic_jet_sinh_cosh(double *s, double *c, const double *a, const ic_jet_space *sp);
IC_API void ic_jet_sinh(double *s, const double *a, const ic_jet_space *sp, double *scratch);
IC_API void ic_jet_cosh(double *c, const double *a, const ic_jet_space *sp, double *scratch);
IC_API void ic_jet_tanh(double *t, const double *a, const ic_jet_space *sp, double *scratch);
/** b = |a|. IC_ERR_DOMAIN if a(0) = 0 and K > 0 (not differentiable). */
IC_API IC_NODISCARD ic_status ic_jet_abs(double *b, const double *a, const ic_jet_space *sp,
                                         ic_error *err);

/* ---- composition and reversion ---- */

/**
 * out = P(g_1 - g_1(0), ..., g_p - g_p(0)).
 *
 * P is a jet in `sp_p` (p = nvars of sp_p variables): the Taylor polynomial of
 * some function about the point (g_1(0), ..., g_p(0)). g[i] are p jets of
 * `sp`; out is in `sp`. The constant terms of g are the expansion point and
 * do not enter otherwise. Degrees above min(K_p, K) are dropped. This is the
 * chain rule to all orders: if P is the order-K Taylor polynomial of F at
 * g(0), out is the order-K jet of F(g).
 */
IC_API void ic_jet_compose(double *out, const double *P, const ic_jet_space *sp_p,
                           const double *const *g, const ic_jet_space *sp, double *scratch);

/**
 * Univariate series reversion: given f (sp has one variable) with
 * f'(0) = f[1] != 0, computes g with g(0) = 0 and f(g(y)) = f(0) + y to
 * order K. IC_ERR_UNABLE if f[1] = 0.
 */
IC_API IC_NODISCARD ic_status ic_jet_revert(double *g, const double *f, const ic_jet_space *sp,
                                            double *scratch, ic_error *err);

/**
 * Bivariate reversion: given a map F = (f[0], f[1]) : R^2 -> R^2 as two jets
 * of a two-variable space with invertible linear part, computes
 * G = (g[0], g[1]) with G(0) = 0 and F(G(y)) = F(0) + y to order K.
 * IC_ERR_UNABLE if the Jacobian of F at 0 is singular (relative determinant
 * below 1e-14).
 */
IC_API IC_NODISCARD ic_status ic_jet_revert2(double *const g[2], const double *const f[2],
                                             const ic_jet_space *sp, double *scratch,
                                             ic_error *err);

#ifdef __cplusplus
}
#endif
#endif
