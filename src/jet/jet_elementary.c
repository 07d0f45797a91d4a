/*
 * Elementary functions of jets by Taylor recurrences on homogeneous parts.
 *
 * With E the Euler operator (E multiplies the degree-d part by d), the chain
 * rule E f(a) = f'(a) E a holds for every function f, and the degree-d part
 * of E(u) * v is sum_j j u_j v_{d-j}. Each function below reads its
 * recurrence off such an identity (docs/jets.md lists them): part d of the
 * result depends only on parts < d, so one pass over the degrees suffices.
 */
#include "common/args.h"
#include "jet_internal.h"

#include <math.h>

/* b = exp(a):  E b = b E a  =>  d b_d = sum_{j=1..d} j a_j b_{d-j}. */
void ic_jet_exp(double *b, const double *a, const ic_jet_space *sp)
{
    if (!b || !a || !sp)
        return;
    b[0] = exp(a[0]);
    for (int d = 1; d <= sp->K; d++) {
        ic_jet_part_zero(sp, b, d);
        for (int j = 1; j <= d; j++)
            ic_jet_hacc(sp, b, a, j, b, d - j, (double)j / d);
    }
}

/* b = log(a):  a E b = E a  =>  d a_0 b_d = d a_d - sum_{j=1..d-1} (d-j) a_j b_{d-j}. */
ic_status ic_jet_log(double *b, const double *a, const ic_jet_space *sp, ic_error *err)
{
    IC_ARG_NOT_NULL(b, "b");
    IC_ARG_NOT_NULL(a, "a");
    IC_ARG_NOT_NULL(sp, "sp");
    if (!(a[0] > 0.0))
        return ic_error_set(err, IC_ERR_DOMAIN, 0, "log of %g (needs a positive value)", a[0]);
    b[0] = log(a[0]);
    for (int d = 1; d <= sp->K; d++) {
        ic_jet_part_zero(sp, b, d);
        ic_jet_part_axpy(sp, b, d, 1.0, a);
        for (int j = 1; j < d; j++)
            ic_jet_hacc(sp, b, a, j, b, d - j, -(double)(d - j) / d);
        ic_jet_part_scale(sp, b, d, 1.0 / a[0]);
    }
    return IC_OK;
}

/* b = sqrt(a):  b b = a  =>  2 b_0 b_d = a_d - sum_{j=1..d-1} b_j b_{d-j}. */
ic_status ic_jet_sqrt(double *b, const double *a, const ic_jet_space *sp, ic_error *err)
{
    IC_ARG_NOT_NULL(b, "b");
    IC_ARG_NOT_NULL(a, "a");
    IC_ARG_NOT_NULL(sp, "sp");
    if (a[0] < 0.0 || (a[0] == 0.0 && sp->K > 0) || !isfinite(a[0]))
        return ic_error_set(err, IC_ERR_DOMAIN, 0,
                            "sqrt of %g (needs a positive value to be differentiable)", a[0]);
    b[0] = sqrt(a[0]);
    for (int d = 1; d <= sp->K; d++) {
        ic_jet_part_zero(sp, b, d);
        ic_jet_part_axpy(sp, b, d, 1.0, a);
        for (int j = 1; j < d; j++)
            ic_jet_hacc(sp, b, b, j, b, d - j, -1.0);
        ic_jet_part_scale(sp, b, d, 0.5 / b[0]);
    }
    return IC_OK;
}

/* b = a^n by binary powering: exact in the sense of the ring of jets, and
 * well conditioned where a(0) is small (the recurrence below divides by it). */
ic_status ic_jet_pow_int(double *b, const double *a, long n, const ic_jet_space *sp,
                         double *scratch, ic_error *err)
{
    IC_ARG_NOT_NULL(b, "b");
    IC_ARG_NOT_NULL(a, "a");
    IC_ARG_NOT_NULL(sp, "sp");
    IC_ARG_NOT_NULL(scratch, "scratch");
    if (n < 0 && a[0] == 0.0)
        return ic_error_set(err, IC_ERR_DOMAIN, 0, "negative power %ld of a jet whose value is 0",
                            n);
    unsigned long e = n < 0 ? (unsigned long)(-(n + 1)) + 1u : (unsigned long)n;
    double *base = scratch, *tmp = scratch + sp->n, *acc = scratch + 2 * sp->n;
    ic_jet_copy(base, a, sp);
    ic_jet_set_const(acc, 1.0, sp);
    while (e) {
        if (e & 1u) {
            ic_jet_mul(tmp, acc, base, sp);
            ic_jet_copy(acc, tmp, sp);
        }
        e >>= 1;
        if (e) {
            ic_jet_mul(tmp, base, base, sp);
            ic_jet_copy(base, tmp, sp);
        }
    }
    if (n >= 0) {
        ic_jet_copy(b, acc, sp);
        return IC_OK;
    }
    ic_jet_set_const(tmp, 1.0, sp);
    return ic_jet_div(b, tmp, acc, sp, err);
}

/* b = a^p:  a E b = p b E a  =>  d a_0 b_d = sum_{j=1..d} (p j - (d - j)) a_j b_{d-j}. */
ic_status ic_jet_pow_real(double *b, const double *a, double p, const ic_jet_space *sp,
                          double *scratch, ic_error *err)
{
    IC_ARG_NOT_NULL(b, "b");
    IC_ARG_NOT_NULL(a, "a");
    IC_ARG_NOT_NULL(sp, "sp");
    IC_ARG_NOT_NULL(scratch, "scratch");
    if (p == floor(p) && fabs(p) <= 1e9)
        return ic_jet_pow_int(b, a, (long)p, sp, scratch, err);
    if (a[0] == 0.0 && p > 0.0 && sp->K == 0) {
        b[0] = 0.0;
        return IC_OK;
    }
    if (!(a[0] > 0.0))
        return ic_error_set(err, IC_ERR_DOMAIN, 0,
                            "power %g of %g (a non-integer power needs a positive base)", p, a[0]);
    b[0] = pow(a[0], p);
    for (int d = 1; d <= sp->K; d++) {
        ic_jet_part_zero(sp, b, d);
        for (int j = 1; j <= d; j++)
            ic_jet_hacc(sp, b, a, j, b, d - j, (p * j - (d - j)) / d);
        ic_jet_part_scale(sp, b, d, 1.0 / a[0]);
    }
    return IC_OK;
}

/* sin and cos together:  E s = c E a,  E c = -s E a. sgn = -1 gives
 * sinh/cosh with sgn = +1 (E c = s E a). */
static void sin_cos_like(double *s, double *c, const double *a, double sgn,
                         const ic_jet_space *sp)
{
    for (int d = 1; d <= sp->K; d++) {
        ic_jet_part_zero(sp, s, d);
        ic_jet_part_zero(sp, c, d);
        for (int j = 1; j <= d; j++) {
            ic_jet_hacc(sp, s, a, j, c, d - j, (double)j / d);
            ic_jet_hacc(sp, c, a, j, s, d - j, sgn * j / d);
        }
    }
}

void ic_jet_sin_cos(double *s, double *c, const double *a, const ic_jet_space *sp)
{
    if (!s || !c || !a || !sp)
        return;
    s[0] = sin(a[0]);
    c[0] = cos(a[0]);
    sin_cos_like(s, c, a, -1.0, sp);
}

void ic_jet_sin(double *s, const double *a, const ic_jet_space *sp, double *scratch)
{
    if (!s || !a || !sp || !scratch)
        return;
    ic_jet_sin_cos(s, scratch, a, sp);
}

void ic_jet_cos(double *c, const double *a, const ic_jet_space *sp, double *scratch)
{
    if (!c || !a || !sp || !scratch)
        return;
    ic_jet_sin_cos(scratch, c, a, sp);
}

void ic_jet_sinh_cosh(double *s, double *c, const double *a, const ic_jet_space *sp)
{
    if (!s || !c || !a || !sp)
        return;
    s[0] = sinh(a[0]);
    c[0] = cosh(a[0]);
    sin_cos_like(s, c, a, 1.0, sp);
}

void ic_jet_sinh(double *s, const double *a, const ic_jet_space *sp, double *scratch)
{
    if (!s || !a || !sp || !scratch)
        return;
    ic_jet_sinh_cosh(s, scratch, a, sp);
}

void ic_jet_cosh(double *c, const double *a, const ic_jet_space *sp, double *scratch)
{
    if (!c || !a || !sp || !scratch)
        return;
    ic_jet_sinh_cosh(scratch, c, a, sp);
}

/* t = tan(a) (sgn = +1) or tanh(a) (sgn = -1):  E t = w E a with
 * w = 1 + sgn t^2, whose part d needs t only up to part d. */
static void tan_like(double *t, const double *a, double t0, double sgn, const ic_jet_space *sp,
                     double *w)
{
    t[0] = t0;
    w[0] = 1.0 + sgn * t0 * t0;
    for (int d = 1; d <= sp->K; d++) {
        ic_jet_part_zero(sp, t, d);
        for (int j = 1; j <= d; j++)
            ic_jet_hacc(sp, t, a, j, w, d - j, (double)j / d);
        ic_jet_part_zero(sp, w, d);
        for (int j = 0; j <= d; j++)
            ic_jet_hacc(sp, w, t, j, t, d - j, sgn);
    }
}

ic_status ic_jet_tan(double *t, const double *a, const ic_jet_space *sp, double *scratch,
                     ic_error *err)
{
    IC_ARG_NOT_NULL(t, "t");
    IC_ARG_NOT_NULL(a, "a");
    IC_ARG_NOT_NULL(sp, "sp");
    IC_ARG_NOT_NULL(scratch, "scratch");
    if (cos(a[0]) == 0.0 || !isfinite(a[0]))
        return ic_error_set(err, IC_ERR_DOMAIN, 0, "tan at %g (a pole)", a[0]);
    tan_like(t, a, tan(a[0]), 1.0, sp, scratch);
    return IC_OK;
}

void ic_jet_tanh(double *t, const double *a, const ic_jet_space *sp, double *scratch)
{
    if (!t || !a || !sp || !scratch)
        return;
    tan_like(t, a, tanh(a[0]), -1.0, sp, scratch);
}

/* b with w E b = r, where r_d is the degree-d part of a known series
 * (r_d = d a_d for atan/asin; the atan2 numerator below):
 * d w_0 b_d = r_d - sum_{j=1..d-1} (d-j) w_j b_{d-j}. b[0] is set by the caller. */
static void solve_euler(double *b, const double *w, const double *r, const ic_jet_space *sp)
{
    for (int d = 1; d <= sp->K; d++) {
        ic_jet_part_zero(sp, b, d);
        ic_jet_part_axpy(sp, b, d, 1.0 / d, r);
        for (int j = 1; j < d; j++)
            ic_jet_hacc(sp, b, w, j, b, d - j, -(double)(d - j) / d);
        ic_jet_part_scale(sp, b, d, 1.0 / w[0]);
    }
}

/* r = E a (part d times d). */
static void euler(double *r, const double *a, const ic_jet_space *sp)
{
    for (int d = 0; d <= sp->K; d++)
        for (int i = sp->deg_start[d]; i < sp->deg_start[d + 1]; i++)
            r[i] = d * a[i];
}

/* atan:  (1 + a^2) E b = E a. */
void ic_jet_atan(double *b, const double *a, const ic_jet_space *sp, double *scratch)
{
    if (!b || !a || !sp || !scratch)
        return;
    double *w = scratch, *r = scratch + sp->n;
    ic_jet_mul(w, a, a, sp);
    w[0] += 1.0;
    euler(r, a, sp);
    b[0] = atan(a[0]);
    solve_euler(b, w, r, sp);
}

/* asin:  sqrt(1 - a^2) E b = E a. */
ic_status ic_jet_asin(double *b, const double *a, const ic_jet_space *sp, double *scratch,
                      ic_error *err)
{
    IC_ARG_NOT_NULL(b, "b");
    IC_ARG_NOT_NULL(a, "a");
    IC_ARG_NOT_NULL(sp, "sp");
    IC_ARG_NOT_NULL(scratch, "scratch");
    if (!(fabs(a[0]) < 1.0) && !(fabs(a[0]) == 1.0 && sp->K == 0))
        return ic_error_set(err, IC_ERR_DOMAIN, 0,
                            "asin/acos of %g (needs |value| < 1 to be differentiable)", a[0]);
    b[0] = asin(a[0]);
    if (sp->K == 0)
        return IC_OK;
    double *w = scratch, *r = scratch + sp->n, *tmp = scratch + 2 * sp->n;
    ic_jet_mul(tmp, a, a, sp);
    ic_jet_neg(tmp, tmp, sp);
    tmp[0] += 1.0;
    ic_status st = ic_jet_sqrt(w, tmp, sp, err);
    if (st != IC_OK)
        return st;
    euler(r, a, sp);
    solve_euler(b, w, r, sp);
    return IC_OK;
}

/* acos = pi/2 - asin. */
ic_status ic_jet_acos(double *b, const double *a, const ic_jet_space *sp, double *scratch,
                      ic_error *err)
{
    IC_ARG_NOT_NULL(b, "b");
    IC_ARG_NOT_NULL(a, "a");
    IC_ARG_NOT_NULL(sp, "sp");
    IC_ARG_NOT_NULL(scratch, "scratch");
    ic_status st = ic_jet_asin(b, a, sp, scratch, err);
    if (st != IC_OK)
        return st;
    ic_jet_neg(b, b, sp);
    b[0] = acos(a[0]);
    return IC_OK;
}

/* atan2:  (x^2 + y^2) E b = x E y - y E x. */
ic_status ic_jet_atan2(double *b, const double *y, const double *x, const ic_jet_space *sp,
                       double *scratch, ic_error *err)
{
    IC_ARG_NOT_NULL(b, "b");
    IC_ARG_NOT_NULL(y, "y");
    IC_ARG_NOT_NULL(x, "x");
    IC_ARG_NOT_NULL(sp, "sp");
    IC_ARG_NOT_NULL(scratch, "scratch");
    if (x[0] == 0.0 && y[0] == 0.0)
        return ic_error_set(err, IC_ERR_DOMAIN, 0, "atan2 at the origin (0, 0)");
    const int n = sp->n;
    double *w = scratch, *r = scratch + n, *e = scratch + 2 * n, *tmp = scratch + 3 * n;
    ic_jet_mul(w, x, x, sp);
    ic_jet_mul(tmp, y, y, sp);
    ic_jet_add(w, w, tmp, sp);
    euler(e, y, sp);
    ic_jet_mul(r, x, e, sp);
    euler(e, x, sp);
    ic_jet_mul(tmp, y, e, sp);
    ic_jet_sub(r, r, tmp, sp);
    b[0] = atan2(y[0], x[0]);
    solve_euler(b, w, r, sp);
    return IC_OK;
}

ic_status ic_jet_abs(double *b, const double *a, const ic_jet_space *sp, ic_error *err)
{
    IC_ARG_NOT_NULL(b, "b");
    IC_ARG_NOT_NULL(a, "a");
    IC_ARG_NOT_NULL(sp, "sp");
    if (a[0] == 0.0 && sp->K > 0)
        return ic_error_set(err, IC_ERR_DOMAIN, 0, "abs at 0 (not differentiable)");
    if (a[0] < 0.0)
        ic_jet_neg(b, a, sp);
    else
        ic_jet_copy(b, a, sp);
    return IC_OK;
}
