/**
 * @file expr.h
 * The formula language (docs/formulas.md): parse, report errors with the
 * column, compile to a flat tape, evaluate on doubles, intervals and jets.
 *
 * Grammar (lowest precedence first):
 *   sum     = product { ("+" | "-") product }
 *   product = unary { ("*" | "/") unary }
 *   unary   = ("-" | "+") unary | power
 *   power   = primary [ "^" unary ]          (right-associative; -x^2 = -(x^2))
 *   primary = number | name | name "(" sum { "," sum } ")" | "(" sum ")"
 * Numbers: 1, 2.5, .5, 1e-3 (read without regard to the C locale).
 * Names: the variables, the constants given at compile time, pi, e.
 * Functions: sqrt exp log sin cos tan asin acos atan atan2 sinh cosh tanh
 * abs pow. pow(a, b) is a^b. A non-constant exponent needs a positive base.
 *
 * One ::ic_expr holds several formulas over the same variables (the x, y, z
 * of a parametric surface) in one tape: shared subexpressions are computed
 * once, constants are folded at compile time.
 *
 * An ::ic_expr is immutable after compilation and may be shared between
 * threads; evaluation takes caller-owned work memory.
 */
#ifndef INTERCURVE_EXPR_H
#define INTERCURVE_EXPR_H

#include "intercurve/common.h"
#include "intercurve/jet.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Longest formula accepted, in bytes, and deepest nesting of the grammar. */
#define IC_EXPR_MAX_LEN 65536
#define IC_EXPR_MAX_DEPTH 200

typedef struct ic_expr ic_expr;

/** A closed interval [lo, hi]. lo > hi (both NaN) is the empty interval. */
typedef struct {
    double lo, hi;
} ic_interval;

/**
 * Compiles `nformulas` formulas over the variables `vars[nvars]` with the
 * named constants `consts[nconsts]` (may be NULL when nconsts = 0).
 * On a parse error returns IC_ERR_PARSE and fills `err` with the 1-based
 * column of the offending token and a message; `*which` (if not NULL)
 * receives the index of the formula at fault. Names of variables and
 * constants must be identifiers distinct from each other, from pi and e
 * and from the function names (IC_ERR_INVALID otherwise).
 */
IC_API IC_NODISCARD ic_status ic_expr_compile(ic_expr **out, const char *const *formulas,
                                              int nformulas, const char *const *vars, int nvars,
                                              const ic_constant *consts, int nconsts, int *which,
                                              ic_error *err);
/** Frees a compiled expression; NULL is allowed. */
IC_API void ic_expr_free(ic_expr *e);

/* The getters and work lengths below are 0 for a NULL expression. */
IC_API int ic_expr_num_outputs(const ic_expr *e);
IC_API int ic_expr_num_vars(const ic_expr *e);
/** Number of instructions of the tape (after folding and sharing). */
IC_API int ic_expr_tape_len(const ic_expr *e);

/**
 * Evaluates a formula made only of numbers, pi, e and the given constants
 * (used for numbers written as formulas in problem files, "2*pi").
 * IC_ERR_PARSE with the column on a malformed or non-constant formula,
 * IC_ERR_DOMAIN if the value is not finite.
 */
IC_API IC_NODISCARD ic_status ic_expr_eval_constant(double *value, const char *formula,
                                                    const ic_constant *consts, int nconsts,
                                                    ic_error *err);

/** Doubles of work memory for ic_expr_eval. */
IC_API size_t ic_expr_work_len(const ic_expr *e);
/**
 * out[i] = formula i at the point x[nvars]. Returns IC_ERR_DOMAIN (with the
 * column of the operation in `err`) if an intermediate value is not finite
 * or an argument is outside its function's domain.
 */
IC_API IC_NODISCARD ic_status ic_expr_eval(const ic_expr *e, double *out, const double *x,
                                           double *work, ic_error *err);

/** ic_interval elements of work memory for ic_expr_eval_interval. */
IC_API size_t ic_expr_interval_work_len(const ic_expr *e);
/**
 * out[i] encloses the values of formula i over the box x[nvars], at the
 * points of the box where it is defined (rounding is outward). An empty
 * result means the formula is defined nowhere in the box; an infinite bound
 * means no finite bound was found (a division by an interval holding 0).
 */
IC_API void ic_expr_eval_interval(const ic_expr *e, ic_interval *out, const ic_interval *x,
                                  ic_interval *work);

/** Most directions of differentiation of an interval gradient. */
#define IC_INTERVAL_GRAD_MAX 3

/** An enclosure of a value and of its derivatives along the directions of differentiation. */
typedef struct {
    ic_interval v;
    ic_interval d[IC_INTERVAL_GRAD_MAX];
} ic_interval_grad;

/** ic_interval_grad elements of work memory for ic_expr_eval_interval_grad. */
IC_API size_t ic_expr_interval_grad_work_len(const ic_expr *e);
/**
 * Forward mode on intervals: x[i].v is variable i's interval and x[i].d[k]
 * its derivative along direction k (k < ngrad <= IC_INTERVAL_GRAD_MAX;
 * the identity for a gradient). out[i].d[k] then encloses the derivative of
 * formula i along direction k at every point of the box where the formula
 * is differentiable (abs contributes [-1, 1] where its argument holds 0).
 * Returns 1 when every operation is defined over the whole enclosure of its
 * arguments (no sqrt or log of a negative part, no division by an interval
 * holding 0, ...) and no enclosure is empty; 0 otherwise (and for a NULL
 * argument, which computes nothing). Arguments that
 * need the formula on the whole box (the mean value theorem of centred
 * forms, the normal cones of the loop test) must decide nothing on 0.
 */
IC_API int ic_expr_eval_interval_grad(const ic_expr *e, ic_interval_grad *out,
                                      const ic_interval_grad *x, int ngrad, ic_interval_grad *work);

/** Entries of a symmetric Hessian over IC_INTERVAL_GRAD_MAX directions,
 * (0,0) (0,1) (0,2) (1,1) (1,2) (2,2): see ic_interval_hess_index. */
#define IC_INTERVAL_HESS_LEN 6

/** An enclosure of a value, of its first and of its second derivatives. */
typedef struct {
    ic_interval v;
    ic_interval d[IC_INTERVAL_GRAD_MAX];
    ic_interval h[IC_INTERVAL_HESS_LEN];
} ic_interval_hess;

/** The place of the second derivative along directions j and k in h. */
IC_API int ic_interval_hess_index(int j, int k);
/** ic_interval_hess elements of work memory for ic_expr_eval_interval_hess. */
IC_API size_t ic_expr_interval_hess_work_len(const ic_expr *e);
/**
 * Second-order forward mode on intervals, as ic_expr_eval_interval_grad:
 * x[i] holds variable i's interval, its derivatives (the identity for a
 * Hessian) and its second derivatives (0). out[i].h then encloses formula
 * i's second derivatives at every point of the box. Returns 1 when every
 * operation and its first two derivatives are defined over the whole box;
 * 0 otherwise, also where abs's argument holds 0 and for atan2, whose
 * second derivatives are not written: the result then proves nothing.
 */
IC_API int ic_expr_eval_interval_hess(const ic_expr *e, ic_interval_hess *out,
                                      const ic_interval_hess *x, int ngrad, ic_interval_hess *work);

/** Doubles of work memory for ic_expr_eval_jet in space sp. */
IC_API size_t ic_expr_jet_work_len(const ic_expr *e, const ic_jet_space *sp);
/**
 * out[i] (jet i of ic_jet_space_len(sp) doubles, consecutive) = formula i
 * composed with the jets x[0..nvars-1] of sp. IC_ERR_DOMAIN (with the
 * column in `err`) where a function's jet does not exist.
 */
IC_API IC_NODISCARD ic_status ic_expr_eval_jet(const ic_expr *e, double *out,
                                               const double *const *x, const ic_jet_space *sp,
                                               double *work, ic_error *err);

/**
 * Writes a two-line picture of an error position into buf:
 *   "  <formula>\n  <spaces>^\n". Formulas longer than fits are cut around
 * the column. Returns buf (an empty string for a NULL formula).
 */
IC_API char *ic_expr_caret(char *buf, size_t size, const char *formula, int column);

/* Interval arithmetic used by the evaluator, exposed for the subdivision
 * code and for tests. Every result encloses the exact image. */
IC_API ic_interval ic_interval_add(ic_interval a, ic_interval b);
IC_API ic_interval ic_interval_sub(ic_interval a, ic_interval b);
IC_API ic_interval ic_interval_mul(ic_interval a, ic_interval b);
IC_API ic_interval ic_interval_div(ic_interval a, ic_interval b);
IC_API ic_interval ic_interval_neg(ic_interval a);
IC_API ic_interval ic_interval_sqrt(ic_interval a);
IC_API ic_interval ic_interval_exp(ic_interval a);
IC_API ic_interval ic_interval_log(ic_interval a);
IC_API ic_interval ic_interval_pow_int(ic_interval a, long n);
IC_API ic_interval ic_interval_pow_real(ic_interval a, double p);
IC_API ic_interval ic_interval_pow(ic_interval a, ic_interval b);
IC_API ic_interval ic_interval_sin(ic_interval a);
IC_API ic_interval ic_interval_cos(ic_interval a);
IC_API ic_interval ic_interval_tan(ic_interval a);
IC_API ic_interval ic_interval_asin(ic_interval a);
IC_API ic_interval ic_interval_acos(ic_interval a);
IC_API ic_interval ic_interval_atan(ic_interval a);
IC_API ic_interval ic_interval_atan2(ic_interval y, ic_interval x);
IC_API ic_interval ic_interval_sinh(ic_interval a);
IC_API ic_interval ic_interval_cosh(ic_interval a);
IC_API ic_interval ic_interval_tanh(ic_interval a);
IC_API ic_interval ic_interval_abs(ic_interval a);
/** 1 if the interval is empty (lo > hi or NaN). */
IC_API int ic_interval_is_empty(ic_interval a);

#ifdef __cplusplus
}
#endif
#endif
