/* STEP Part 21 tokens and instance table (step_parse.h). The text is read
 * by position with its length checked before every byte, so any bytes are
 * safe; nesting and the number of values are bounded. */
#include "step_parse.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    const char *s;
    size_t n, pos;
    int line;
    int depth;
    ic_status status; /* the first failure */
    ic_step_file *f;
    ic_error *err;
} parser;

static ic_status fail(parser *p, const char *what)
{
    p->status = IC_ERR_PARSE;
    return ic_error_set(p->err, IC_ERR_PARSE, 0, "line %d: %s", p->line, what);
}

static int at(const parser *p, size_t k) { return p->pos + k < p->n ? (unsigned char)p->s[p->pos + k] : -1; }

/* Blanks, line ends and comments. An unclosed comment is an error. */
static ic_status skip(parser *p)
{
    for (;;) {
        const int c = at(p, 0);
        if (c == '\n')
            p->line++;
        if (c >= 0 && c <= ' ') {
            p->pos++;
        } else if (c == '/' && at(p, 1) == '*') {
            p->pos += 2;
            while (p->pos < p->n && !(at(p, 0) == '*' && at(p, 1) == '/'))
                p->line += p->s[p->pos++] == '\n';
            if (p->pos >= p->n)
                return fail(p, "the file ends inside a comment");
            p->pos += 2;
        } else {
            return IC_OK;
        }
    }
}

static int is_word(int c, int first)
{
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_' || c == '!' ||
           (!first && ((c >= '0' && c <= '9') || c == '-'));
}

/* A new value of `kind`; -1 (err set) when the limit is reached or memory is out. */
static int new_value(parser *p, ic_step_kind kind)
{
    ic_step_file *f = p->f;
    if (f->nvalues == f->cap_values) {
        if (f->nvalues >= IC_STEP_MAX_VALUES) {
            p->status = ic_error_set(p->err, IC_ERR_INVALID, 0,
                                     "line %d: more than %d values: too large", p->line,
                                     IC_STEP_MAX_VALUES);
            return -1;
        }
        const int cap = f->cap_values ? 2 * f->cap_values : 1024;
        ic_step_value *v = realloc(f->values, (size_t)cap * sizeof *v);
        if (!v) {
            p->status = ic_error_set(p->err, IC_ERR_NOMEM, 0, "out of memory reading the STEP file");
            return -1;
        }
        f->values = v;
        f->cap_values = cap;
    }
    ic_step_value *v = &f->values[f->nvalues];
    memset(v, 0, sizeof *v);
    v->kind = (uint8_t)kind;
    v->next = v->child = -1;
    return f->nvalues++;
}

/* A value whose text is s[start, end). */
static int text_value(parser *p, ic_step_kind kind, size_t start, size_t end)
{
    const int v = new_value(p, kind);
    if (v >= 0) {
        p->f->values[v].u.s.text = (uint32_t)start;
        p->f->values[v].u.s.len = (uint32_t)(end - start);
    }
    return v;
}

static size_t word_end(const parser *p)
{
    size_t k = 0;
    while (is_word(at(p, k), k == 0))
        k++;
    return p->pos + k;
}

static int parse_list(parser *p);

/* 'text' with '' for a quote; the value holds what is between the quotes. */
static int parse_string(parser *p)
{
    const size_t start = ++p->pos;
    for (;;) {
        const int c = at(p, 0);
        if (c < 0) {
            fail(p, "the file ends inside a string");
            return -1;
        }
        p->line += c == '\n';
        p->pos++;
        if (c == '\'' && at(p, 0) == '\'')
            p->pos++;
        else if (c == '\'')
            return text_value(p, IC_STEP_STRING, start, p->pos - 1);
    }
}

/* .NAME. or "hex": text up to the closing mark, which must come first. */
static int parse_delimited(parser *p, ic_step_kind kind, char close)
{
    const size_t start = ++p->pos;
    while (at(p, 0) >= 0 && at(p, 0) != close && at(p, 0) > ' ' && at(p, 0) != ',' &&
           at(p, 0) != ')')
        p->pos++;
    if (at(p, 0) != close) {
        fail(p, kind == IC_STEP_ENUM ? "an enumeration not closed by '.'"
                                     : "a binary value not closed by '\"'");
        return -1;
    }
    p->pos++;
    return text_value(p, kind, start, p->pos - 1);
}

/* [+-]digits[.digits][E[+-]digits] */
static int parse_number(parser *p)
{
    char buf[64];
    size_t k = 0;
    for (int c; (c = at(p, (size_t)k)) >= 0 && k + 1 < sizeof buf; k++) {
        const int prev = k ? buf[k - 1] : 0;
        const int ok = (c >= '0' && c <= '9') || c == '.' || c == 'E' || c == 'e' ||
                       ((c == '+' || c == '-') && (k == 0 || prev == 'E' || prev == 'e'));
        if (!ok)
            break;
        buf[k] = (char)c;
    }
    buf[k] = '\0';
    char *end = NULL;
    const double x = strtod(buf, &end);
    if (k == 0 || end != buf + k || !isfinite(x)) {
        fail(p, "a malformed or out-of-range number");
        return -1;
    }
    p->pos += k;
    const int v = new_value(p, IC_STEP_NUMBER);
    if (v >= 0)
        p->f->values[v].u.number = x;
    return v;
}

/* #digits, as an id within int range; -1 after a message. */
static int read_id(parser *p, int32_t *id)
{
    p->pos++;
    long long x = 0;
    size_t k = 0;
    for (int c; (c = at(p, k)) >= '0' && c <= '9'; k++) {
        x = 10 * x + (c - '0');
        if (x > INT_MAX) {
            fail(p, "an instance number above 2147483647");
            return -1;
        }
    }
    if (k == 0) {
        fail(p, "'#' not followed by an instance number");
        return -1;
    }
    p->pos += k;
    *id = (int32_t)x;
    return 0;
}

/* NAME( ... ): a TYPED value. */
static int parse_typed(parser *p)
{
    const size_t start = p->pos, end = word_end(p);
    p->pos = end;
    const int v = text_value(p, IC_STEP_TYPED, start, end);
    if (v < 0 || skip(p) != IC_OK)
        return -1;
    if (at(p, 0) != '(') {
        fail(p, "a type name not followed by '('");
        return -1;
    }
    const int list = parse_list(p);
    if (list < 0)
        return -1;
    p->f->values[v].child = list;
    return v;
}

static int parse_value(parser *p)
{
    const int c = at(p, 0);
    int v = -1;
    if (c == '$' || c == '*') {
        p->pos++;
        v = new_value(p, c == '$' ? IC_STEP_NULL : IC_STEP_DERIVED);
    } else if (c == '#') {
        int32_t id;
        if (read_id(p, &id) == 0 && (v = new_value(p, IC_STEP_REF)) >= 0)
            p->f->values[v].u.ref = id;
    } else if (c == '\'') {
        v = parse_string(p);
    } else if (c == '.') {
        v = parse_delimited(p, IC_STEP_ENUM, '.');
    } else if (c == '"') {
        v = parse_delimited(p, IC_STEP_BINARY, '"');
    } else if ((c >= '0' && c <= '9') || c == '+' || c == '-') {
        v = parse_number(p);
    } else if (c == '(') {
        v = parse_list(p);
    } else if (is_word(c, 1)) {
        v = parse_typed(p);
    } else {
        fail(p, c < 0 ? "the file ends inside a record" : "an unexpected character in a value");
    }
    return v;
}

/* ( value, value, ... ) */
static int parse_list(parser *p)
{
    if (++p->depth > IC_STEP_MAX_DEPTH) {
        fail(p, "lists nested too deeply");
        return -1;
    }
    p->pos++; /* ( */
    const int list = new_value(p, IC_STEP_LIST);
    if (list < 0 || skip(p) != IC_OK)
        return -1;
    int last = -1;
    if (at(p, 0) == ')') {
        p->pos++;
        p->depth--;
        return list;
    }
    for (;;) {
        const int v = parse_value(p);
        if (v < 0 || skip(p) != IC_OK)
            return -1;
        if (last < 0)
            p->f->values[list].child = v;
        else
            p->f->values[last].next = v;
        last = v;
        p->f->values[list].count++;
        const int c = at(p, 0);
        p->pos++;
        if (c == ')')
            break;
        if (c != ',') {
            p->pos--;
            fail(p, c < 0 ? "the file ends inside a record" : "expected ',' or ')' in a list");
            return -1;
        }
        if (skip(p) != IC_OK)
            return -1;
    }
    p->depth--;
    return list;
}

static ic_status add_instance(parser *p, int32_t id, int part, int complex)
{
    ic_step_file *f = p->f;
    if (f->ninst == f->cap_inst) {
        const int cap = f->cap_inst ? 2 * f->cap_inst : 256;
        ic_step_instance *in = realloc(f->inst, (size_t)cap * sizeof *in);
        if (!in)
            return ic_error_set(p->err, IC_ERR_NOMEM, 0, "out of memory reading the STEP file");
        f->inst = in;
        f->cap_inst = cap;
    }
    f->inst[f->ninst++] = (ic_step_instance){.id = id, .part = part, .complex = complex};
    return IC_OK;
}

static ic_status expect_end(parser *p)
{
    if (skip(p) != IC_OK)
        return IC_ERR_PARSE;
    if (at(p, 0) != ';')
        return fail(p, at(p, 0) < 0 ? "the file ends inside a record" : "expected ';' after a record");
    p->pos++;
    return IC_OK;
}

/* #id = NAME(...); or #id = (NAME(...) NAME(...) ...); */
static ic_status parse_instance(parser *p)
{
    int32_t id;
    if (read_id(p, &id) < 0 || skip(p) != IC_OK)
        return IC_ERR_PARSE;
    if (at(p, 0) != '=')
        return fail(p, "expected '=' after an instance number");
    p->pos++;
    if (skip(p) != IC_OK)
        return IC_ERR_PARSE;
    int first = -1, complex = at(p, 0) == '(';
    if (!complex) {
        if (!is_word(at(p, 0), 1))
            return fail(p, "expected an entity name after '='");
        if ((first = parse_typed(p)) < 0)
            return p->status;
    } else {
        p->pos++;
        for (int last = -1;;) {
            if (skip(p) != IC_OK)
                return IC_ERR_PARSE;
            if (at(p, 0) == ')' && first >= 0)
                break;
            if (!is_word(at(p, 0), 1))
                return fail(p, "expected an entity name in a complex instance");
            const int v = parse_typed(p);
            if (v < 0)
                return p->status;
            if (last < 0)
                first = v;
            else
                p->f->values[last].next = v;
            last = v;
        }
        p->pos++;
    }
    const ic_status st = expect_end(p);
    return st != IC_OK ? st : add_instance(p, id, first, complex);
}

static int by_id(const void *a, const void *b)
{
    const int32_t x = ((const ic_step_instance *)a)->id, y = ((const ic_step_instance *)b)->id;
    return (x > y) - (x < y);
}

/* Section keywords (HEADER; ...) and header records NAME(...); are read
 * and passed over; reading stops at END-ISO-10303-21;. */
static ic_status parse_records(parser *p)
{
    for (;;) {
        if (skip(p) != IC_OK)
            return IC_ERR_PARSE;
        const int c = at(p, 0);
        if (c < 0)
            return fail(p, "the file ends before END-ISO-10303-21;");
        if (c == '#') {
            const ic_status st = parse_instance(p);
            if (st != IC_OK)
                return st;
            continue;
        }
        if (!is_word(c, 1))
            return fail(p, "an unexpected character between records");
        const size_t start = p->pos, end = word_end(p);
        const int is_end = end - start == 16 && memcmp(p->s + start, "END-ISO-10303-21", 16) == 0;
        p->pos = end;
        if (skip(p) != IC_OK)
            return IC_ERR_PARSE;
        if (at(p, 0) == '(') {
            const int saved = p->f->nvalues;
            if (parse_list(p) < 0)
                return p->status;
            p->f->nvalues = saved; /* a header record's values are not kept */
        }
        const ic_status st = expect_end(p);
        if (st != IC_OK || is_end)
            return st;
    }
}

ic_status ic_step_parse(ic_step_file *f, const char *text, size_t len, ic_error *err)
{
    memset(f, 0, sizeof *f);
    f->text = text;
    f->len = len;
    if (len > UINT32_MAX)
        return ic_error_set(err, IC_ERR_INVALID, 0, "the STEP file is too large");
    parser p = {.s = text, .n = len, .line = 1, .f = f, .err = err};
    ic_status st = parse_records(&p);
    if (st == IC_OK && f->ninst > 1) {
        qsort(f->inst, (size_t)f->ninst, sizeof *f->inst, by_id);
        for (int k = 1; k < f->ninst && st == IC_OK; k++)
            if (f->inst[k].id == f->inst[k - 1].id)
                st = ic_error_set(err, IC_ERR_PARSE, 0, "#%d is defined twice", (int)f->inst[k].id);
    }
    if (st != IC_OK) {
        ic_step_free(f);
    }
    return st;
}

void ic_step_free(ic_step_file *f)
{
    free(f->values);
    free(f->inst);
    memset(f, 0, sizeof *f);
}

const ic_step_instance *ic_step_find(const ic_step_file *f, int id)
{
    int lo = 0, hi = f->ninst - 1;
    while (lo <= hi) {
        const int mid = lo + (hi - lo) / 2;
        if (f->inst[mid].id == id)
            return &f->inst[mid];
        if (f->inst[mid].id < id)
            lo = mid + 1;
        else
            hi = mid - 1;
    }
    return NULL;
}

/* STEP names are upper case; lower case is read as the same name. */
static int same_word(const char *a, const char *b, size_t n)
{
    for (size_t k = 0; k < n; k++) {
        const char x = a[k] >= 'a' && a[k] <= 'z' ? (char)(a[k] - 32) : a[k];
        if (x != b[k])
            return 0;
    }
    return 1;
}

int ic_step_is(const ic_step_file *f, int v, const char *name)
{
    if (v < 0)
        return 0;
    const ic_step_value *x = &f->values[v];
    const size_t n = strlen(name);
    return (x->kind == IC_STEP_TYPED || x->kind == IC_STEP_ENUM) && x->u.s.len == n &&
           same_word(f->text + x->u.s.text, name, n);
}

int ic_step_part(const ic_step_file *f, const ic_step_instance *in, const char *type)
{
    for (int v = in->part; v >= 0; v = f->values[v].next)
        if (ic_step_is(f, v, type))
            return v;
    return -1;
}

int ic_step_item(const ic_step_file *f, int list, int k)
{
    if (list < 0 || f->values[list].kind != IC_STEP_LIST || k < 0 || k >= f->values[list].count)
        return -1;
    int v = f->values[list].child;
    while (k-- > 0 && v >= 0)
        v = f->values[v].next;
    return v;
}

int ic_step_param(const ic_step_file *f, int typed, int k)
{
    if (typed < 0 || f->values[typed].kind != IC_STEP_TYPED)
        return -1;
    return ic_step_item(f, f->values[typed].child, k);
}

void ic_step_text(const ic_step_file *f, int v, char *out, size_t size)
{
    size_t used = 0;
    if (v >= 0 && size > 0) {
        const ic_step_value *x = &f->values[v];
        const int has_text =
            x->kind == IC_STEP_STRING || x->kind == IC_STEP_ENUM || x->kind == IC_STEP_TYPED;
        for (uint32_t k = 0; has_text && k < x->u.s.len && used + 1 < size; k++) {
            const char c = f->text[x->u.s.text + k];
            if (c == '\'' && x->kind == IC_STEP_STRING)
                k++; /* '' stands for one quote */
            out[used++] = (unsigned char)c < ' ' ? ' ' : c;
        }
    }
    if (size > 0)
        out[used] = '\0';
}

int ic_step_number(const ic_step_file *f, int v, double *x)
{
    /* a measure may be written typed, as LENGTH_MEASURE(2.5) */
    for (int depth = 0; v >= 0 && f->values[v].kind == IC_STEP_TYPED && depth < 4; depth++)
        v = ic_step_param(f, v, 0);
    if (v < 0 || f->values[v].kind != IC_STEP_NUMBER)
        return -1;
    *x = f->values[v].u.number;
    return 0;
}
