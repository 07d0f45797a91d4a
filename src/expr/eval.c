/* Evaluation of the tape on doubles and on jets. */
#include "common/args.h"
#include "expr_internal.h"

#include <math.h>

size_t ic_expr_work_len(const ic_expr *e) { return e ? (size_t)e->len : 0; }

static ic_status domain_error(const ic_instr *x, double a, ic_error *err)
{
    return ic_error_set(err, IC_ERR_DOMAIN, x->column,
                        "'%s' is undefined or overflows at argument %.17g", ic_op_name(x->op), a);
}

ic_status ic_expr_eval(const ic_expr *e, double *out, const double *x, double *work,
                       ic_error *err)
{
    IC_ARG_NOT_NULL(e, "e");
    IC_ARG_NOT_NULL(out, "out");
    IC_ARG_NOT_NULL(x, "x");
    IC_ARG_NOT_NULL(work, "work");
    double *r = work;
    for (int i = 0; i < e->len; i++) {
        const ic_instr *in = &e->code[i];
        if (in->op == OP_VAR) {
            r[i] = x[in->n];
            continue;
        }
        const double a = in->a >= 0 ? r[in->a] : 0.0;
        const double b = in->b >= 0 ? r[in->b] : 0.0;
        r[i] = ic_op_eval_double(in->op, a, b, in->n, in->c);
        if (!isfinite(r[i]))
            return domain_error(in, a, err);
    }
    for (int k = 0; k < e->noutputs; k++)
        out[k] = r[e->outputs[k]];
    return IC_OK;
}

size_t ic_expr_jet_work_len(const ic_expr *e, const ic_jet_space *sp)
{
    if (!e || !sp)
        return 0;
    return (size_t)e->len * (size_t)ic_jet_space_len(sp) + ic_jet_scratch_len(sp);
}

/* One instruction on jets: reg = op(A, B). */
static ic_status jet_op(const ic_expr *e, const ic_instr *in, double *reg, const double *A,
                        const double *B, const ic_jet_space *sp, double *scratch, ic_error *err)
{
    switch (in->op) {
    case OP_CONST: ic_jet_set_const(reg, in->c, sp); return IC_OK;
    case OP_VAR: return IC_OK; /* handled by the caller */
    case OP_ADD:
        if (e->code[in->b].op == OP_CONST)
            ic_jet_add_const(reg, A, B[0], sp);
        else
            ic_jet_add(reg, A, B, sp);
        return IC_OK;
    case OP_SUB: ic_jet_sub(reg, A, B, sp); return IC_OK;
    case OP_MUL:
        if (e->code[in->a].op == OP_CONST)
            ic_jet_scale(reg, B, A[0], sp);
        else if (e->code[in->b].op == OP_CONST)
            ic_jet_scale(reg, A, B[0], sp);
        else
            ic_jet_mul(reg, A, B, sp);
        return IC_OK;
    case OP_DIV:
        if (e->code[in->b].op == OP_CONST && B[0] != 0.0) {
            ic_jet_scale(reg, A, 1.0 / B[0], sp);
            return IC_OK;
        }
        return ic_jet_div(reg, A, B, sp, err);
    case OP_NEG: ic_jet_neg(reg, A, sp); return IC_OK;
    case OP_POWI:
        if (in->n == 2) {
            ic_jet_mul(reg, A, A, sp);
            return IC_OK;
        }
        return ic_jet_pow_int(reg, A, in->n, sp, scratch, err);
    case OP_POWR: return ic_jet_pow_real(reg, A, in->c, sp, scratch, err);
    case OP_POW: {
        /* a^b = exp(b log a) */
        double *lg = scratch, *prod = scratch + ic_jet_space_len(sp);
        ic_status st = ic_jet_log(lg, A, sp, err);
        if (st != IC_OK)
            return st;
        ic_jet_mul(prod, lg, B, sp);
        ic_jet_exp(reg, prod, sp);
        return IC_OK;
    }
    case OP_SQRT: return ic_jet_sqrt(reg, A, sp, err);
    case OP_EXP: ic_jet_exp(reg, A, sp); return IC_OK;
    case OP_LOG: return ic_jet_log(reg, A, sp, err);
    case OP_SIN: ic_jet_sin(reg, A, sp, scratch); return IC_OK;
    case OP_COS: ic_jet_cos(reg, A, sp, scratch); return IC_OK;
    case OP_TAN: return ic_jet_tan(reg, A, sp, scratch, err);
    case OP_ASIN: return ic_jet_asin(reg, A, sp, scratch, err);
    case OP_ACOS: return ic_jet_acos(reg, A, sp, scratch, err);
    case OP_ATAN: ic_jet_atan(reg, A, sp, scratch); return IC_OK;
    case OP_ATAN2: return ic_jet_atan2(reg, A, B, sp, scratch, err);
    case OP_SINH: ic_jet_sinh(reg, A, sp, scratch); return IC_OK;
    case OP_COSH: ic_jet_cosh(reg, A, sp, scratch); return IC_OK;
    case OP_TANH: ic_jet_tanh(reg, A, sp, scratch); return IC_OK;
    case OP_ABS: return ic_jet_abs(reg, A, sp, err);
    case OP_COUNT: break;
    }
    return ic_error_set(err, IC_ERR_INVALID, in->column, "corrupt tape");
}

ic_status ic_expr_eval_jet(const ic_expr *e, double *out, const double *const *x,
                           const ic_jet_space *sp, double *work, ic_error *err)
{
    IC_ARG_NOT_NULL(e, "e");
    IC_ARG_NOT_NULL(out, "out");
    IC_ARG_NOT_NULL(x, "x");
    IC_ARG_NOT_NULL(sp, "sp");
    IC_ARG_NOT_NULL(work, "work");
    const int n = ic_jet_space_len(sp);
    double *scratch = work + (size_t)e->len * (size_t)n;
    for (int i = 0; i < e->len; i++) {
        const ic_instr *in = &e->code[i];
        double *reg = work + (size_t)i * (size_t)n;
        if (in->op == OP_VAR) {
            ic_jet_copy(reg, x[in->n], sp);
            continue;
        }
        const double *A = in->a >= 0 ? work + (size_t)in->a * (size_t)n : NULL;
        const double *B = in->b >= 0 ? work + (size_t)in->b * (size_t)n : NULL;
        ic_status st = jet_op(e, in, reg, A, B, sp, scratch, err);
        if (st == IC_OK && !isfinite(reg[0]))
            st = domain_error(in, A ? A[0] : 0.0, err);
        if (st != IC_OK) {
            if (err)
                err->column = in->column;
            return st;
        }
    }
    for (int k = 0; k < e->noutputs; k++)
        ic_jet_copy(out + (size_t)k * (size_t)n, work + (size_t)e->outputs[k] * (size_t)n, sp);
    return IC_OK;
}
