/* Internal representation of compiled formulas: the tape. */
#ifndef IC_EXPR_INTERNAL_H
#define IC_EXPR_INTERNAL_H

#include "intercurve/expr.h"
#include "expr_access.h"

typedef enum {
    OP_CONST, OP_VAR,
    OP_ADD, OP_SUB, OP_MUL, OP_DIV, OP_NEG,
    OP_POWI,  /* a ^ n, n integer constant */
    OP_POWR,  /* a ^ c, c real constant */
    OP_POW,   /* a ^ b, both variable: exp(b log a), a > 0 */
    OP_SQRT, OP_EXP, OP_LOG, OP_SIN, OP_COS, OP_TAN, OP_ASIN, OP_ACOS, OP_ATAN,
    OP_ATAN2, /* atan2(a, b) = atan2(y, x) */
    OP_SINH, OP_COSH, OP_TANH, OP_ABS,
    OP_COUNT
} ic_opcode;

/* One instruction; its result is register `index`. a, b are earlier
 * registers; n the integer exponent (POWI) or variable index (VAR); c the
 * constant (CONST) or real exponent (POWR). */
typedef struct {
    ic_opcode op;
    int a, b;
    long n;
    double c;
    int column; /* 1-based column in its formula, for error messages */
} ic_instr;

struct ic_expr {
    ic_instr *code;
    int len, cap;
    int *outputs;  /* register of each formula's result */
    int noutputs;
    int nvars;
    int *hash;     /* open addressing table of instruction indices, -1 empty */
    int hash_cap;
};

/* Builder: appends an instruction (or returns an identical earlier one),
 * folding constants. Returns the register index, or -1 with err filled. */
int ic_tape_emit(ic_expr *e, ic_opcode op, int a, int b, long n, double c, int column,
                 ic_error *err);

/* Ends a tape built by ic_tape_emit: registers no output needs removed,
 * the sharing table dropped. -1 out of memory. */
int ic_expr_finish(ic_expr *e);

/* Evaluates one operation on doubles; used by folding and by ic_expr_eval.
 * Returns a non-finite value where the operation is undefined. */
double ic_op_eval_double(ic_opcode op, double a, double b, long n, double c);

/* One instruction on intervals (src/expr/interval.c): the enclosure of
 * op(a, b) where it is defined. */
ic_interval ic_interval_op(const ic_instr *in, ic_interval a, ic_interval b);
/* 1 when the operation is defined at every point of the enclosures a, b. */
int ic_interval_op_defined(const ic_instr *in, ic_interval a, ic_interval b);

/* The factor f'(a) of the chain rule d op(a) = f'(a) da of a one-argument
 * operation over the enclosure a, given v = op(a) (interval_grad.c). */
ic_interval ic_interval_unary_factor(const ic_instr *in, ic_interval a, ic_interval v);

/* Name of the operation as written in formulas ("sin", "+", ...). */
const char *ic_op_name(ic_opcode op);

/* Lexer */
typedef enum {
    TOK_END, TOK_NUMBER, TOK_NAME, TOK_PLUS, TOK_MINUS, TOK_STAR, TOK_SLASH, TOK_CARET,
    TOK_LPAREN, TOK_RPAREN, TOK_COMMA, TOK_ERROR
} ic_token_kind;

typedef struct {
    ic_token_kind kind;
    int start;     /* byte offset in the formula */
    int length;
    double value;  /* TOK_NUMBER */
} ic_token;

/* Reads the token at byte offset pos (after blanks). On a malformed token
 * returns TOK_ERROR with err filled (column set). */
ic_token ic_lex(const char *src, int pos, ic_error *err);

/* Parses formula `src` into e's tape; returns the result register or -1. */
int ic_parse_formula(ic_expr *e, const char *src, const char *const *vars, int nvars,
                     const ic_constant *consts, int nconsts, ic_error *err);

#endif
