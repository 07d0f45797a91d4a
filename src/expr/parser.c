/* Recursive-descent parser of the formula language (grammar in expr.h).
 * It emits tape instructions directly; the builder folds constants and
 * shares repeated subexpressions. */
#include "expr_internal.h"
#include "common/mathconst.h"

#include <math.h>
#include <string.h>

typedef struct {
    ic_expr *e;
    const char *src;
    ic_token tok;
    const char *const *vars;
    int nvars;
    const ic_constant *consts;
    int nconsts;
    int depth;
    ic_error *err;
} parser;

typedef struct {
    const char *name;
    int nargs;
    ic_opcode op; /* OP_POW for pow (special-cased) */
} function_info;

static const function_info FUNCTIONS[] = {
    {"sqrt", 1, OP_SQRT}, {"exp", 1, OP_EXP},   {"log", 1, OP_LOG},     {"sin", 1, OP_SIN},
    {"cos", 1, OP_COS},   {"tan", 1, OP_TAN},   {"asin", 1, OP_ASIN},   {"acos", 1, OP_ACOS},
    {"atan", 1, OP_ATAN}, {"atan2", 2, OP_ATAN2}, {"sinh", 1, OP_SINH}, {"cosh", 1, OP_COSH},
    {"tanh", 1, OP_TANH}, {"abs", 1, OP_ABS},   {"pow", 2, OP_POW},
};
#define NFUNCTIONS ((int)(sizeof FUNCTIONS / sizeof FUNCTIONS[0]))

static const function_info *find_function(const char *s, int len)
{
    for (int i = 0; i < NFUNCTIONS; i++)
        if ((int)strlen(FUNCTIONS[i].name) == len && strncmp(FUNCTIONS[i].name, s, len) == 0)
            return &FUNCTIONS[i];
    return NULL;
}

int ic_expr_is_reserved_name(const char *name);
int ic_expr_is_reserved_name(const char *name)
{
    if (strcmp(name, "pi") == 0 || strcmp(name, "e") == 0)
        return 1;
    return find_function(name, (int)strlen(name)) != NULL;
}

static int column(const parser *p) { return p->tok.start + 1; }

static int advance(parser *p)
{
    p->tok = ic_lex(p->src, p->tok.start + p->tok.length, p->err);
    return p->tok.kind == TOK_ERROR ? -1 : 0;
}

static int fail(parser *p, const char *what)
{
    if (p->tok.kind == TOK_END)
        ic_error_set(p->err, IC_ERR_PARSE, column(p), "unexpected end of formula: %s", what);
    else
        ic_error_set(p->err, IC_ERR_PARSE, column(p), "unexpected '%.*s': %s", p->tok.length,
                     p->src + p->tok.start, what);
    return -1;
}

/* Whole exponents up to 2^53 are stored as integers (every double of that
 * size is exact in a long); beyond it every double is an even integer. */
#define WHOLE_POWER_MAX 9007199254740992.0

/* A power whose exponent is a constant becomes POWI or POWR. A whole
 * exponent is a whole power for every base, negative ones included: above
 * 2^53 it is even, so x^c = |x|^c. */
static int emit_power(parser *p, int base, int expo, int col)
{
    const ic_instr *x = &p->e->code[expo];
    if (x->op == OP_CONST) {
        double c = x->c;
        if (c == floor(c) && fabs(c) <= WHOLE_POWER_MAX)
            return ic_tape_emit(p->e, OP_POWI, base, -1, (long)c, 0.0, col, p->err);
        if (c == floor(c)) {
            const int a = ic_tape_emit(p->e, OP_ABS, base, -1, 0, 0.0, col, p->err);
            return a < 0 ? a : ic_tape_emit(p->e, OP_POWR, a, -1, 0, c, col, p->err);
        }
        return ic_tape_emit(p->e, OP_POWR, base, -1, 0, c, col, p->err);
    }
    return ic_tape_emit(p->e, OP_POW, base, expo, 0, 0.0, col, p->err);
}

static int parse_sum(parser *p);

static int parse_call(parser *p, const function_info *f, int name_col)
{
    int args[2], nargs = 0;
    const int open_col = column(p);
    if (advance(p) < 0) /* past '(' */
        return -1;
    if (p->tok.kind != TOK_RPAREN) {
        for (;;) {
            int r = parse_sum(p);
            if (r < 0)
                return -1;
            if (nargs < 2)
                args[nargs] = r;
            nargs++;
            if (p->tok.kind != TOK_COMMA)
                break;
            if (advance(p) < 0)
                return -1;
        }
    }
    if (p->tok.kind == TOK_END) /* as for a parenthesis of parse_primary */
        return ic_error_set(p->err, IC_ERR_PARSE, open_col,
                            "unbalanced parentheses: this '(' is never closed"),
               -1;
    if (p->tok.kind != TOK_RPAREN)
        return fail(p, "expected ',' or ')' in the arguments of a function");
    if (nargs != f->nargs)
        return ic_error_set(p->err, IC_ERR_PARSE, name_col,
                            "function '%s' takes %d argument%s, got %d", f->name, f->nargs,
                            f->nargs == 1 ? "" : "s", nargs),
               -1;
    if (advance(p) < 0)
        return -1;
    if (f->op == OP_POW)
        return emit_power(p, args[0], args[1], name_col);
    return ic_tape_emit(p->e, f->op, args[0], nargs > 1 ? args[1] : -1, 0, 0.0, name_col,
                        p->err);
}

static int parse_name(parser *p)
{
    const char *s = p->src + p->tok.start;
    const int len = p->tok.length, col = column(p);
    if (advance(p) < 0)
        return -1;
    const int call = p->tok.kind == TOK_LPAREN;
    const function_info *f = find_function(s, len);
    if (f) {
        if (!call)
            return ic_error_set(p->err, IC_ERR_PARSE, col,
                                "function '%s' needs its arguments in parentheses", f->name),
                   -1;
        return parse_call(p, f, col);
    }
    if (call)
        return ic_error_set(p->err, IC_ERR_PARSE, col, "unknown function '%.*s'", len, s), -1;
    for (int i = 0; i < p->nvars; i++)
        if ((int)strlen(p->vars[i]) == len && strncmp(p->vars[i], s, len) == 0)
            return ic_tape_emit(p->e, OP_VAR, -1, -1, i, 0.0, col, p->err);
    for (int i = 0; i < p->nconsts; i++)
        if ((int)strlen(p->consts[i].name) == len && strncmp(p->consts[i].name, s, len) == 0)
            return ic_tape_emit(p->e, OP_CONST, -1, -1, 0, p->consts[i].value, col, p->err);
    if (len == 2 && strncmp(s, "pi", 2) == 0)
        return ic_tape_emit(p->e, OP_CONST, -1, -1, 0, IC_PI, col, p->err);
    if (len == 1 && s[0] == 'e')
        return ic_tape_emit(p->e, OP_CONST, -1, -1, 0, IC_E, col, p->err);
    return ic_error_set(p->err, IC_ERR_PARSE, col, "unknown identifier '%.*s'", len, s), -1;
}

static int parse_primary(parser *p)
{
    const int col = column(p);
    switch (p->tok.kind) {
    case TOK_NUMBER: {
        const double v = p->tok.value;
        if (!isfinite(v))
            return ic_error_set(p->err, IC_ERR_PARSE, col, "number '%.*s' is not finite",
                                p->tok.length, p->src + p->tok.start),
                   -1;
        if (advance(p) < 0)
            return -1;
        return ic_tape_emit(p->e, OP_CONST, -1, -1, 0, v, col, p->err);
    }
    case TOK_NAME:
        return parse_name(p);
    case TOK_LPAREN: {
        if (advance(p) < 0)
            return -1;
        int r = parse_sum(p);
        if (r < 0)
            return -1;
        if (p->tok.kind != TOK_RPAREN) {
            if (p->tok.kind == TOK_END)
                return ic_error_set(p->err, IC_ERR_PARSE, col,
                                    "unbalanced parentheses: this '(' is never closed"),
                       -1;
            return fail(p, "expected ')'");
        }
        if (advance(p) < 0)
            return -1;
        return r;
    }
    default:
        return fail(p, "expected a number, a name or '('");
    }
}

static int parse_unary(parser *p);

static int parse_power(parser *p)
{
    int base = parse_primary(p);
    if (base < 0 || p->tok.kind != TOK_CARET)
        return base;
    const int col = column(p);
    if (advance(p) < 0)
        return -1;
    int expo = parse_unary(p); /* right-associative, may carry a sign */
    if (expo < 0)
        return -1;
    return emit_power(p, base, expo, col);
}

static int parse_unary(parser *p)
{
    if (++p->depth > IC_EXPR_MAX_DEPTH)
        return ic_error_set(p->err, IC_ERR_PARSE, column(p),
                            "formula nested too deeply (more than %d levels)", IC_EXPR_MAX_DEPTH),
               -1;
    int r;
    if (p->tok.kind == TOK_MINUS || p->tok.kind == TOK_PLUS) {
        const int neg = p->tok.kind == TOK_MINUS, col = column(p);
        if (advance(p) < 0)
            return -1;
        r = parse_unary(p);
        if (r >= 0 && neg)
            r = ic_tape_emit(p->e, OP_NEG, r, -1, 0, 0.0, col, p->err);
    } else {
        r = parse_power(p);
    }
    p->depth--;
    return r;
}

static int parse_product(parser *p)
{
    int left = parse_unary(p);
    while (left >= 0 && (p->tok.kind == TOK_STAR || p->tok.kind == TOK_SLASH)) {
        const ic_opcode op = p->tok.kind == TOK_STAR ? OP_MUL : OP_DIV;
        const int col = column(p);
        if (advance(p) < 0)
            return -1;
        int right = parse_unary(p);
        if (right < 0)
            return -1;
        left = ic_tape_emit(p->e, op, left, right, 0, 0.0, col, p->err);
    }
    return left;
}

static int parse_sum(parser *p)
{
    if (++p->depth > IC_EXPR_MAX_DEPTH)
        return ic_error_set(p->err, IC_ERR_PARSE, column(p),
                            "formula nested too deeply (more than %d levels)", IC_EXPR_MAX_DEPTH),
               -1;
    int left = parse_product(p);
    while (left >= 0 && (p->tok.kind == TOK_PLUS || p->tok.kind == TOK_MINUS)) {
        const ic_opcode op = p->tok.kind == TOK_PLUS ? OP_ADD : OP_SUB;
        const int col = column(p);
        if (advance(p) < 0)
            return -1;
        int right = parse_product(p);
        if (right < 0)
            return -1;
        left = ic_tape_emit(p->e, op, left, right, 0, 0.0, col, p->err);
    }
    p->depth--;
    return left;
}

int ic_parse_formula(ic_expr *e, const char *src, const char *const *vars, int nvars,
                     const ic_constant *consts, int nconsts, ic_error *err)
{
    parser p = {.e = e, .src = src, .vars = vars, .nvars = nvars, .consts = consts,
                .nconsts = nconsts, .err = err};
    const size_t len = strlen(src);
    if (len > IC_EXPR_MAX_LEN)
        return ic_error_set(err, IC_ERR_PARSE, 1, "formula too long (%zu bytes, at most %d)",
                            len, IC_EXPR_MAX_LEN),
               -1;
    p.tok = ic_lex(src, 0, err);
    if (p.tok.kind == TOK_ERROR)
        return -1;
    if (p.tok.kind == TOK_END)
        return ic_error_set(err, IC_ERR_PARSE, 1, "empty formula"), -1;
    int r = parse_sum(&p);
    if (r < 0)
        return -1;
    if (p.tok.kind == TOK_RPAREN)
        return ic_error_set(err, IC_ERR_PARSE, column(&p),
                            "unbalanced parentheses: ')' without a matching '('"),
               -1;
    if (p.tok.kind != TOK_END)
        return fail(&p, "expected an operator or the end of the formula");
    return r;
}
