/* The tape: building it (constant folding, sharing of identical
 * instructions), compiling formulas into it, freeing it. */
#include "common/args.h"
#include "expr_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

int ic_expr_is_reserved_name(const char *name); /* parser.c */

const char *ic_op_name(ic_opcode op)
{
    static const char *const names[OP_COUNT] = {
        "constant", "variable", "+", "-", "*", "/", "unary -", "^", "^", "^", "sqrt", "exp",
        "log", "sin", "cos", "tan", "asin", "acos", "atan", "atan2", "sinh", "cosh", "tanh",
        "abs"};
    return op >= 0 && op < OP_COUNT ? names[op] : "?";
}

double ic_op_eval_double(ic_opcode op, double a, double b, long n, double c)
{
    switch (op) {
    case OP_CONST: return c;
    case OP_VAR: return a;
    case OP_ADD: return a + b;
    case OP_SUB: return a - b;
    case OP_MUL: return a * b;
    case OP_DIV: return b == 0.0 ? NAN : a / b;
    case OP_NEG: return -a;
    case OP_POWI:
        if (n < 0 && a == 0.0)
            return NAN;
        return pow(a, (double)n);
    case OP_POWR: return a < 0.0 ? NAN : pow(a, c);
    case OP_POW: return a > 0.0 ? pow(a, b) : NAN;
    case OP_SQRT: return a < 0.0 ? NAN : sqrt(a);
    case OP_EXP: return exp(a);
    case OP_LOG: return a > 0.0 ? log(a) : NAN;
    case OP_SIN: return sin(a);
    case OP_COS: return cos(a);
    case OP_TAN: return tan(a);
    case OP_ASIN: return fabs(a) <= 1.0 ? asin(a) : NAN;
    case OP_ACOS: return fabs(a) <= 1.0 ? acos(a) : NAN;
    case OP_ATAN: return atan(a);
    case OP_ATAN2: return (a == 0.0 && b == 0.0) ? NAN : atan2(a, b);
    case OP_SINH: return sinh(a);
    case OP_COSH: return cosh(a);
    case OP_TANH: return tanh(a);
    case OP_ABS: return fabs(a);
    case OP_COUNT: break;
    }
    return NAN;
}

static unsigned long instr_hash(const ic_instr *x)
{
    unsigned long h = (unsigned long)x->op * 1000003ul;
    h = (h ^ (unsigned long)(x->a + 2)) * 1000003ul;
    h = (h ^ (unsigned long)(x->b + 2)) * 1000003ul;
    h = (h ^ (unsigned long)x->n) * 1000003ul;
    unsigned long long bits;
    memcpy(&bits, &x->c, sizeof bits);
    h ^= (unsigned long)(bits ^ (bits >> 32));
    return h;
}

static int instr_equal(const ic_instr *x, const ic_instr *y)
{
    return x->op == y->op && x->a == y->a && x->b == y->b && x->n == y->n &&
           memcmp(&x->c, &y->c, sizeof x->c) == 0;
}

static int grow(ic_expr *e)
{
    if (e->len < e->cap)
        return 0;
    int cap = e->cap ? 2 * e->cap : 32;
    ic_instr *code = realloc(e->code, (size_t)cap * sizeof *code);
    if (!code)
        return -1;
    e->code = code;
    e->cap = cap;
    /* keep the hash table at most half full */
    free(e->hash);
    e->hash_cap = 2 * cap;
    e->hash = malloc((size_t)e->hash_cap * sizeof *e->hash);
    if (!e->hash)
        return -1;
    for (int i = 0; i < e->hash_cap; i++)
        e->hash[i] = -1;
    for (int i = 0; i < e->len; i++) {
        unsigned long h = instr_hash(&e->code[i]) % (unsigned long)e->hash_cap;
        while (e->hash[h] >= 0)
            h = (h + 1) % (unsigned long)e->hash_cap;
        e->hash[h] = i;
    }
    return 0;
}

static int is_unary(ic_opcode op) { return op != OP_CONST && op != OP_VAR && op != OP_ADD &&
        op != OP_SUB && op != OP_MUL && op != OP_DIV && op != OP_POW && op != OP_ATAN2; }

int ic_tape_emit(ic_expr *e, ic_opcode op, int a, int b, long n, double c, int column,
                 ic_error *err)
{
    /* Fold an operation whose arguments are all constants. */
    const int has_a = op != OP_CONST && op != OP_VAR;
    const int has_b = has_a && !is_unary(op);
    if (has_a && e->code[a].op == OP_CONST && (!has_b || e->code[b].op == OP_CONST)) {
        double v = ic_op_eval_double(op, e->code[a].c, has_b ? e->code[b].c : 0.0, n, c);
        if (!isfinite(v))
            return ic_error_set(err, IC_ERR_PARSE, column,
                                "non-finite constant: '%s' of constant arguments is undefined "
                                "or overflows",
                                ic_op_name(op)),
                   -1;
        op = OP_CONST;
        a = b = -1;
        n = 0;
        c = v;
    }
    if (op == OP_CONST && c == 0.0)
        c = 0.0; /* one representation of zero, so -0 and 0 share a register */
    ic_instr x = {op, has_a ? a : -1, has_b ? b : -1, n, c, column};
    if (op == OP_CONST || op == OP_VAR)
        x.a = x.b = -1;
    if (e->hash_cap > 0) {
        unsigned long h = instr_hash(&x) % (unsigned long)e->hash_cap;
        for (; e->hash[h] >= 0; h = (h + 1) % (unsigned long)e->hash_cap)
            if (instr_equal(&e->code[e->hash[h]], &x))
                return e->hash[h];
    }
    if (grow(e) < 0)
        return ic_error_set(err, IC_ERR_NOMEM, column, "out of memory compiling a formula"), -1;
    e->code[e->len] = x;
    unsigned long h = instr_hash(&x) % (unsigned long)e->hash_cap;
    while (e->hash[h] >= 0)
        h = (h + 1) % (unsigned long)e->hash_cap;
    e->hash[h] = e->len;
    return e->len++;
}

static int valid_identifier(const char *s)
{
    if (!s || !(*s == '_' || (*s >= 'a' && *s <= 'z') || (*s >= 'A' && *s <= 'Z')))
        return 0;
    for (; *s; s++)
        if (!(*s == '_' || (*s >= 'a' && *s <= 'z') || (*s >= 'A' && *s <= 'Z') ||
              (*s >= '0' && *s <= '9')))
            return 0;
    return 1;
}

/* Names of variables and constants: identifiers, not reserved, distinct. */
static ic_status check_names(const char *const *vars, int nvars, const ic_constant *consts,
                             int nconsts, ic_error *err)
{
    for (int i = 0; i < nvars + nconsts; i++) {
        const char *name = i < nvars ? vars[i] : consts[i - nvars].name;
        const char *kind = i < nvars ? "variable" : "constant";
        if (!valid_identifier(name))
            return ic_error_set(err, IC_ERR_INVALID, 0, "%s name '%s' is not an identifier",
                                kind, name ? name : "(null)");
        if (ic_expr_is_reserved_name(name))
            return ic_error_set(err, IC_ERR_INVALID, 0,
                                "%s name '%s' is reserved (pi, e or a function)", kind, name);
        if (i >= nvars && !isfinite(consts[i - nvars].value))
            return ic_error_set(err, IC_ERR_INVALID, 0, "constant '%s' is not finite", name);
        for (int j = 0; j < i; j++) {
            const char *other = j < nvars ? vars[j] : consts[j - nvars].name;
            if (strcmp(name, other) == 0)
                return ic_error_set(err, IC_ERR_INVALID, 0, "name '%s' is defined twice", name);
        }
    }
    return IC_OK;
}

/* Drops instructions no output depends on (the intermediate constants left
 * by folding) and renumbers the rest; the sharing table is no longer needed.
 * -1 out of memory: the tape is then not the one it should be (a picture of
 * its surface came out different; tests/test_nomem.c, "writers"). */
static int remove_dead_code(ic_expr *e)
{
    int *live = calloc((size_t)e->len + 1, sizeof *live);
    if (!live)
        return -1;
    for (int k = 0; k < e->noutputs; k++)
        live[e->outputs[k]] = 1;
    for (int i = e->len - 1; i >= 0; i--)
        if (live[i]) {
            if (e->code[i].a >= 0)
                live[e->code[i].a] = 1;
            if (e->code[i].b >= 0)
                live[e->code[i].b] = 1;
        }
    int next = 0;
    for (int i = 0; i < e->len; i++) {
        if (!live[i])
            continue;
        ic_instr x = e->code[i];
        if (x.a >= 0)
            x.a = live[x.a] - 1;
        if (x.b >= 0)
            x.b = live[x.b] - 1;
        e->code[next] = x;
        live[i] = ++next; /* new index + 1 */
    }
    for (int k = 0; k < e->noutputs; k++)
        e->outputs[k] = live[e->outputs[k]] - 1;
    e->len = next;
    free(live);
    free(e->hash);
    e->hash = NULL;
    e->hash_cap = 0;
    return 0;
}

int ic_expr_finish(ic_expr *e) { return remove_dead_code(e); }

ic_status ic_expr_compile(ic_expr **out, const char *const *formulas, int nformulas,
                          const char *const *vars, int nvars, const ic_constant *consts,
                          int nconsts, int *which, ic_error *err)
{
    IC_ARG_NOT_NULL(out, "out");
    *out = NULL;
    if (which)
        *which = -1;
    IC_ARG_NOT_NULL(formulas, "formulas");
    IC_ARG_CHECK(nformulas >= 1, "nformulas", "must be at least 1");
    IC_ARG_CHECK(nvars >= 0, "nvars", "must not be negative");
    IC_ARG_CHECK(nconsts >= 0, "nconsts", "must not be negative");
    IC_ARG_CHECK(nvars == 0 || vars, "vars", "is NULL");
    IC_ARG_CHECK(nconsts == 0 || consts, "consts", "is NULL");
    ic_status st = check_names(vars, nvars, consts, nconsts, err);
    if (st != IC_OK)
        return st;
    ic_expr *e = calloc(1, sizeof *e);
    if (!e || !(e->outputs = malloc((size_t)nformulas * sizeof *e->outputs))) {
        ic_expr_free(e);
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory compiling formulas");
    }
    e->nvars = nvars;
    e->noutputs = nformulas;
    for (int i = 0; i < nformulas; i++) {
        if (!formulas[i]) {
            ic_expr_free(e);
            return ic_error_set(err, IC_ERR_INVALID, 0, "formula %d is NULL", i);
        }
        int r = ic_parse_formula(e, formulas[i], vars, nvars, consts, nconsts, err);
        if (r < 0) {
            if (which)
                *which = i;
            ic_expr_free(e);
            return err ? err->code : IC_ERR_PARSE;
        }
        e->outputs[i] = r;
    }
    if (remove_dead_code(e) != 0) {
        ic_expr_free(e);
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory compiling a formula");
    }
    *out = e;
    return IC_OK;
}

void ic_expr_free(ic_expr *e)
{
    if (!e)
        return;
    free(e->code);
    free(e->outputs);
    free(e->hash);
    free(e);
}

/* A copy of n elements of `size` bytes (NULL for none or out of memory). */
static void *copy_array(const void *a, size_t n, size_t size)
{
    if (!a || n == 0)
        return NULL;
    void *c = malloc(n * size);
    if (c)
        memcpy(c, a, n * size);
    return c;
}

ic_status ic_expr_copy(ic_expr **out, const ic_expr *e, ic_error *err)
{
    *out = NULL;
    ic_expr *c = calloc(1, sizeof *c);
    if (!c)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory copying formulas");
    *c = *e;
    c->cap = e->len; /* the tape is complete: no room to grow */
    c->code = copy_array(e->code, (size_t)e->len, sizeof *e->code);
    c->outputs = copy_array(e->outputs, (size_t)e->noutputs, sizeof *e->outputs);
    c->hash = copy_array(e->hash, (size_t)e->hash_cap, sizeof *e->hash);
    if ((e->code && !c->code) || (e->outputs && !c->outputs) || (e->hash && !c->hash)) {
        ic_expr_free(c);
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory copying formulas");
    }
    *out = c;
    return IC_OK;
}

int ic_expr_num_outputs(const ic_expr *e) { return e ? e->noutputs : 0; }
int ic_expr_num_vars(const ic_expr *e) { return e ? e->nvars : 0; }
int ic_expr_tape_len(const ic_expr *e) { return e ? e->len : 0; }

ic_status ic_expr_eval_constant(double *value, const char *formula, const ic_constant *consts,
                                int nconsts, ic_error *err)
{
    IC_ARG_NOT_NULL(value, "value");
    IC_ARG_NOT_NULL(formula, "formula");
    ic_expr *e = NULL;
    ic_status st = ic_expr_compile(&e, &formula, 1, NULL, 0, consts, nconsts, NULL, err);
    if (st != IC_OK)
        return st;
    /* With no variables every instruction folds into one constant. */
    *value = e->code[e->outputs[0]].c;
    ic_expr_free(e);
    return IC_OK;
}
