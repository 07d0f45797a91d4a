/* IGES records, global section, directory and parameters (iges_parse.h).
 * Every column is read through col(), which gives a blank past a record's
 * end, so short records and any bytes are safe. */
#include "iges_parse.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A record is 80 columns; 73 holds the section letter, the parameter data
 * of an entity is in columns 1-64 and the global section in 1-72. */
enum { RECORD = 80, SECTION_COLUMN = 73, PARAM_COLUMNS = 64, GLOBAL_COLUMNS = 72, FIELD = 8 };
enum { S_SEC, G_SEC, D_SEC, P_SEC, T_SEC };

static char col(const ic_iges_file *f, int line, int c)
{
    const ic_iges_line *l = &f->lines[line];
    return c >= 1 && c <= l->len ? f->text[l->at + (size_t)c - 1] : ' ';
}

static ic_status add_line(ic_iges_file *f, int *cap, size_t at, size_t len, ic_error *err)
{
    if (len > RECORD)
        return ic_error_set(err, IC_ERR_PARSE, 0, "line %d is longer than 80 columns",
                            f->nlines + 1);
    if (f->nlines == *cap) {
        const int grown = *cap ? 2 * *cap : 256;
        ic_iges_line *l = realloc(f->lines, (size_t)grown * sizeof *l);
        if (!l)
            return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory reading the IGES file");
        f->lines = l;
        *cap = grown;
    }
    f->lines[f->nlines++] = (ic_iges_line){.at = at, .len = (int)len};
    return IC_OK;
}

/* Records end at line ends ("\n" or "\r\n"); a file whose first 82 bytes
 * (a record and "\r\n") hold no line end is read as fixed 80-byte records.
 * Blank lines are passed over. */
static ic_status split_records(ic_iges_file *f, ic_error *err)
{
    const char *nl = memchr(f->text, '\n', f->len < RECORD + 2 ? f->len : RECORD + 2);
    int cap = 0;
    ic_status st = IC_OK;
    for (size_t at = 0; at < f->len && st == IC_OK;) {
        size_t end = nl ? at : (at + RECORD < f->len ? at + RECORD : f->len), next;
        if (nl) {
            while (end < f->len && f->text[end] != '\n')
                end++;
            next = end + 1;
            if (end > at && f->text[end - 1] == '\r')
                end--;
        } else {
            next = end;
        }
        int blank = 1;
        for (size_t k = at; k < end && blank; k++)
            blank = (unsigned char)f->text[k] <= ' ';
        if (!blank)
            st = add_line(f, &cap, at, end - at, err);
        at = next;
    }
    return st;
}

/* Each record's section from column 73, in the order S, G, D, P, T. */
static ic_status find_sections(ic_iges_file *f, ic_error *err)
{
    static const char LETTERS[] = "SGDPT";
    int last = 0;
    for (int k = 0; k < 4; k++)
        f->first[k] = f->count[k] = 0;
    for (int i = 0; i < f->nlines; i++) {
        const char c = col(f, i, SECTION_COLUMN);
        if (c == 'C' || c == 'B')
            return ic_error_set(err, IC_ERR_INVALID, 0,
                                "line %d: the compressed and binary IGES forms are not read", i + 1);
        const char *s = c ? strchr(LETTERS, c) : NULL;
        if (!s)
            return ic_error_set(err, IC_ERR_PARSE, 0,
                                "line %d: column 73 is '%c', not a section letter (S, G, D, P, T)",
                                i + 1, c >= ' ' && c < 127 ? c : '?');
        const int sec = (int)(s - LETTERS);
        if (sec < last)
            return ic_error_set(err, IC_ERR_PARSE, 0,
                                "line %d: a %c record after the %c section", i + 1, c,
                                LETTERS[last]);
        if (sec == T_SEC)
            break;
        if (f->count[sec]++ == 0)
            f->first[sec] = i;
        last = sec;
    }
    if (f->count[G_SEC] == 0 || f->count[D_SEC] == 0)
        return ic_error_set(err, IC_ERR_PARSE, 0, "the file has no %s section",
                            f->count[G_SEC] == 0 ? "global (G)" : "directory (D)");
    return IC_OK;
}

/* Columns 1..width of `count` records from `first` joined into a new text. */
static char *join_columns(const ic_iges_file *f, int first, int count, int width, size_t *len)
{
    char *t = malloc((size_t)count * (size_t)width + 1);
    if (!t)
        return NULL;
    size_t n = 0;
    for (int i = first; i < first + count; i++)
        for (int c = 1; c <= width; c++)
            t[n++] = col(f, i, c);
    t[n] = '\0';
    *len = n;
    return t;
}

static ic_status add_param(ic_iges_params *p, int *cap, ic_iges_param v, ic_error *err)
{
    if (p->n == *cap) {
        if (p->n >= IC_IGES_MAX_PARAMS)
            return ic_error_set(err, IC_ERR_INVALID, 0, "more than %d parameters: too large",
                                IC_IGES_MAX_PARAMS);
        const int grown = *cap ? 2 * *cap : 64;
        ic_iges_param *q = realloc(p->p, (size_t)grown * sizeof *q);
        if (!q)
            return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory reading the IGES file");
        p->p = q;
        *cap = grown;
    }
    p->p[p->n++] = v;
    return IC_OK;
}

/* A number field t[a, b): blanks ignored, D as E for the exponent.
 * 1 with *x, 0 for an empty field, -1 when it is not a number. */
static int read_number(const char *t, size_t a, size_t b, double *x)
{
    char buf[64];
    size_t n = 0;
    for (size_t k = a; k < b; k++) {
        const char c = t[k];
        if (c == ' ')
            continue;
        if (n + 1 >= sizeof buf)
            return -1;
        buf[n++] = c == 'D' || c == 'd' ? 'E' : c;
    }
    buf[n] = '\0';
    if (n == 0)
        return 0;
    char *end = NULL;
    *x = strtod(buf, &end);
    return end != buf + n || !isfinite(*x) ? -1 : 1;
}

/* nH followed by n characters at t[*k]: 1 (and *k past it), 0 when the
 * field is not a Hollerith string, -1 when it runs past the text. */
static int hollerith(const char *t, size_t len, size_t *k, ic_iges_param *v)
{
    size_t j = *k, n = 0;
    while (j < len && t[j] >= '0' && t[j] <= '9' && n <= len)
        n = 10 * n + (size_t)(t[j++] - '0');
    if (j == *k || j >= len || (t[j] != 'H' && t[j] != 'h'))
        return 0;
    if (n > len - j - 1)
        return -1;
    *v = (ic_iges_param){.kind = IC_IGES_STRING, .at = j + 1, .len = n};
    *k = j + 1 + n;
    return 1;
}

/* Free-format fields of t[k, len) up to the record delimiter, appended to p. */
static ic_status parse_fields(ic_iges_params *p, int *cap, size_t k, size_t len, char pd, char rd,
                              const char *where, ic_error *err)
{
    const char *t = p->text;
    for (;;) {
        while (k < len && t[k] == ' ')
            k++;
        if (k >= len)
            return IC_OK; /* no record delimiter: the text ends the record */
        ic_iges_param v = {.kind = IC_IGES_EMPTY};
        const int h = hollerith(t, len, &k, &v);
        if (h < 0)
            return ic_error_set(err, IC_ERR_PARSE, 0, "%s: a string (nH...) runs past the end",
                                where);
        if (h == 0) {
            const size_t a = k;
            while (k < len && t[k] != pd && t[k] != rd)
                k++;
            const int got = read_number(t, a, k, &v.number);
            if (got < 0)
                return ic_error_set(err, IC_ERR_PARSE, 0, "%s: parameter %d ('%.*s') is not a number",
                                    where, p->n + 1, (int)(k - a < 40 ? k - a : 40), t + a);
            v.kind = got ? IC_IGES_NUMBER : IC_IGES_EMPTY;
        }
        while (k < len && t[k] == ' ')
            k++;
        const ic_status st = add_param(p, cap, v, err);
        if (st != IC_OK)
            return st;
        if (k >= len || t[k] == rd)
            return IC_OK;
        if (t[k] != pd)
            return ic_error_set(err, IC_ERR_PARSE, 0,
                                "%s: parameter %d is followed by '%c', not a delimiter", where,
                                p->n, t[k] >= ' ' && t[k] < 127 ? t[k] : '?');
        k++;
    }
}

/* The global section: its first two fields give the delimiters (1H, and
 * 1H; by default), the rest are free-format with them. */
static ic_status parse_global(ic_iges_file *f, ic_error *err)
{
    ic_iges_params *g = &f->global;
    size_t len;
    if (!(g->text = join_columns(f, f->first[G_SEC], f->count[G_SEC], GLOBAL_COLUMNS, &len)))
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory reading the IGES file");
    const char *t = g->text;
    size_t k = 0;
    char delim[2] = {',', ';'};
    for (int d = 0; d < 2; d++) {
        while (k < len && t[k] == ' ')
            k++;
        if (k + 2 < len && t[k] == '1' && (t[k + 1] == 'H' || t[k + 1] == 'h')) {
            delim[d] = t[k + 2];
            k += 3;
            while (k < len && t[k] == ' ')
                k++;
        }
        if (d == 0 && (delim[0] == ' ' || (delim[0] >= '0' && delim[0] <= '9')))
            break; /* reported below */
        if (k >= len || (t[k] != delim[0] && !(d == 1 && t[k] == delim[1])))
            return ic_error_set(err, IC_ERR_PARSE, 0,
                                "global section: field %d (the %s delimiter) is not 1Hx followed "
                                "by the parameter delimiter",
                                d + 1, d == 0 ? "parameter" : "record");
        k++;
    }
    if (delim[0] == delim[1] || delim[0] == ' ' || delim[1] == ' ' ||
        (delim[0] >= '0' && delim[0] <= '9') || (delim[1] >= '0' && delim[1] <= '9'))
        return ic_error_set(err, IC_ERR_PARSE, 0, "global section: unusable delimiters");
    f->pdelim = delim[0];
    f->rdelim = delim[1];
    int cap = 0;
    ic_status st = IC_OK;
    for (int d = 0; d < 2 && st == IC_OK; d++)
        st = add_param(g, &cap, (ic_iges_param){.kind = IC_IGES_EMPTY}, err);
    if (st != IC_OK || t[k - 1] == f->rdelim)
        return st;
    return parse_fields(g, &cap, k, len, f->pdelim, f->rdelim, "global section", err);
}

/* Columns of one 8-column field of a directory record as a whole number. */
static int field(const ic_iges_file *f, int line, int index, int *out)
{
    char buf[FIELD + 1];
    int n = 0;
    for (int c = (index - 1) * FIELD + 1; c <= index * FIELD; c++)
        if (col(f, line, c) != ' ')
            buf[n++] = col(f, line, c);
    buf[n] = '\0';
    char *end = NULL;
    const long x = n ? strtol(buf, &end, 10) : 0;
    *out = (int)x;
    return n && end != buf + n ? -1 : 0;
}

static ic_status parse_directory(ic_iges_file *f, ic_error *err)
{
    if (f->count[D_SEC] % 2)
        return ic_error_set(err, IC_ERR_PARSE, 0,
                            "the directory has %d records: an odd number, the last entry is cut",
                            f->count[D_SEC]);
    f->nentries = f->count[D_SEC] / 2;
    if (!(f->entries = calloc((size_t)f->nentries, sizeof *f->entries)))
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory reading the IGES file");
    for (int k = 0; k < f->nentries; k++) {
        ic_iges_entry *e = &f->entries[k];
        const int a = f->first[D_SEC] + 2 * k, b = a + 1;
        e->de = 2 * k + 1;
        if (field(f, a, 1, &e->type) < 0 || field(f, a, 2, &e->pointer) < 0 ||
            field(f, a, 7, &e->matrix) < 0 || field(f, b, 4, &e->nlines) < 0 ||
            field(f, b, 5, &e->form) < 0 || field(f, b, 9, &e->subscript) < 0)
            return ic_error_set(err, IC_ERR_PARSE, 0,
                                "DE %d: a field of the directory entry is not a whole number",
                                e->de);
        int n = 0;
        for (int c = 7 * FIELD + 1; c <= 8 * FIELD; c++)
            if (n > 0 || col(f, b, c) != ' ')
                e->label[n++] = (unsigned char)col(f, b, c) < ' ' ? ' ' : col(f, b, c);
        while (n > 0 && e->label[n - 1] == ' ')
            n--;
        e->label[n] = '\0';
    }
    return IC_OK;
}

ic_status ic_iges_parse(ic_iges_file *f, const char *text, size_t len, ic_error *err)
{
    memset(f, 0, sizeof *f);
    f->text = text;
    f->len = len;
    ic_status st = split_records(f, err);
    if (st == IC_OK)
        st = find_sections(f, err);
    if (st == IC_OK)
        st = parse_global(f, err);
    if (st == IC_OK)
        st = parse_directory(f, err);
    if (st != IC_OK)
        ic_iges_free(f);
    return st;
}

void ic_iges_free(ic_iges_file *f)
{
    free(f->lines);
    ic_iges_params_free(&f->global);
    free(f->entries);
    memset(f, 0, sizeof *f);
}

const ic_iges_entry *ic_iges_entry_at(const ic_iges_file *f, int de)
{
    if (de < 1 || de % 2 == 0 || (de - 1) / 2 >= f->nentries)
        return NULL;
    return &f->entries[(de - 1) / 2];
}

ic_status ic_iges_entity_params(const ic_iges_file *f, const ic_iges_entry *e, ic_iges_params *out,
                                ic_error *err)
{
    memset(out, 0, sizeof *out);
    if (e->pointer < 1 || e->nlines < 1 || e->pointer > f->count[P_SEC] ||
        e->nlines > f->count[P_SEC] - e->pointer + 1)
        return ic_error_set(err, IC_ERR_PARSE, 0,
                            "DE %d: its parameter data (%d lines from line %d) is not within the "
                            "%d lines of the P section",
                            e->de, e->nlines, e->pointer, f->count[P_SEC]);
    size_t len;
    out->text = join_columns(f, f->first[P_SEC] + e->pointer - 1, e->nlines, PARAM_COLUMNS, &len);
    if (!out->text)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory reading the IGES file");
    char where[48];
    snprintf(where, sizeof where, "DE %d, parameter data", e->de);
    int cap = 0;
    ic_status st = parse_fields(out, &cap, 0, len, f->pdelim, f->rdelim, where, err);
    double type;
    if (st == IC_OK && (ic_iges_number(out, 0, &type) < 0 || type != e->type))
        st = ic_error_set(err, IC_ERR_PARSE, 0,
                          "DE %d: its parameter data does not begin with its type %d", e->de,
                          e->type);
    if (st != IC_OK)
        ic_iges_params_free(out);
    return st;
}

void ic_iges_params_free(ic_iges_params *p)
{
    free(p->text);
    free(p->p);
    memset(p, 0, sizeof *p);
}

int ic_iges_number(const ic_iges_params *p, int k, double *x)
{
    if (k < 0 || k >= p->n || p->p[k].kind == IC_IGES_STRING)
        return -1;
    *x = p->p[k].kind == IC_IGES_NUMBER ? p->p[k].number : 0;
    return 0;
}

void ic_iges_string(const ic_iges_params *p, int k, char *out, size_t size)
{
    size_t n = 0;
    if (k >= 0 && k < p->n && p->p[k].kind == IC_IGES_STRING)
        for (size_t j = 0; j < p->p[k].len && n + 1 < size; j++) {
            const char c = p->text[p->p[k].at + j];
            out[n++] = (unsigned char)c < ' ' ? ' ' : c;
        }
    if (size > 0)
        out[n] = '\0';
}
