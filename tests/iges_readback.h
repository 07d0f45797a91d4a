/* A small reader of IGES's fixed-column form for the tests, written apart
 * from the writer (src/cad/curve_iges.c): the records checked column by
 * column, the global section's fields, and each entity 126 of the
 * directory with its parameter data. Any departure from the layout makes
 * it fail, never guess. */
#ifndef IC_TEST_IGES_READBACK_H
#define IC_TEST_IGES_READBACK_H

#include <ctype.h>
#include <stdlib.h>
#include <string.h>

#include "intercurve.h"

enum { IGES_MAX_LINES = 100000 };

typedef struct {
    char (*line)[82]; /* each 80 columns, no newline */
    int n;
    int count[5]; /* lines of S, G, D, P, T */
    int first[5]; /* index of each section's first line */
} iges_file;

static const char IGES_SECTIONS[] = "SGDPT";

/* Splits text into 80-column lines; 0 when every line is 80 characters and
 * a newline, the sections come in order S G D P T, each numbered 1, 2, ...
 * in columns 74-80, and the T record counts them. */
static inline int iges_read(iges_file *g, const char *text)
{
    memset(g, 0, sizeof *g);
    g->line = malloc(sizeof *g->line * IGES_MAX_LINES);
    int section = 0;
    for (const char *p = text; g->line && *p && g->n < IGES_MAX_LINES; p += 81) {
        const char *nl = strchr(p, '\n');
        if (!nl || nl - p != 80)
            return -1;
        memcpy(g->line[g->n], p, 80);
        g->line[g->n][80] = '\0';
        const char *at = strchr(IGES_SECTIONS, p[72]);
        if (!p[72] || !at || at - IGES_SECTIONS < section)
            return -1;
        if (at - IGES_SECTIONS > section || g->n == 0)
            g->first[at - IGES_SECTIONS] = g->n;
        section = (int)(at - IGES_SECTIONS);
        char seq[8];
        memcpy(seq, p + 73, 7);
        seq[7] = '\0';
        if (strspn(seq, " ") + strspn(seq + strspn(seq, " "), "0123456789") != 7 ||
            atoi(seq) != ++g->count[section])
            return -1;
        g->n++;
    }
    char want[33];
    snprintf(want, sizeof want, "S%7dG%7dD%7dP%7d", g->count[0], g->count[1], g->count[2],
             g->count[3]);
    return g->line && section == 4 && g->count[4] == 1 && strncmp(g->line[g->n - 1], want, 32) == 0
               ? 0
               : -1;
}

static inline void iges_free(iges_file *g) { free(g->line); }

/* Columns [from, from + width) of a line, as text, as a number. */
static inline int iges_column_int(const char *line, int from, int width)
{
    char f[16];
    memcpy(f, line + from, (size_t)width);
    f[width] = '\0';
    return atoi(f);
}

/* The free-format fields of `text` (delimited by ',' and ending in ';'),
 * Hollerith strings taken whole: field k into out[k] (NUL-terminated, at
 * most 79 characters); the count, or -1. */
static inline int iges_fields(const char *text, char out[][80], int max)
{
    int n = 0;
    for (const char *p = text; n < max;) {
        while (*p == ' ') /* the blanks that end a record's data */
            p++;
        const char *q = p;
        while (isdigit((unsigned char)*q))
            q++;
        size_t len = strcspn(p, ",;");
        if (q > p && *q == 'H') /* nHtext */
            len = (size_t)(q - p) + 1 + (size_t)atoi(p);
        if (len > 79 || strlen(p) < len + 1)
            return -1;
        memcpy(out[n], p, len);
        out[n++][len] = '\0';
        if (p[len] == ';')
            return n;
        if (p[len] != ',')
            return -1;
        p += len + 1;
    }
    return -1;
}

/* The global section's fields (columns 1-72 of its lines run together). */
static inline int iges_global(const iges_file *g, char out[][80], int max)
{
    char *text = calloc((size_t)g->count[1] * 72 + 1, 1);
    if (!text)
        return -1;
    for (int k = 0; k < g->count[1]; k++)
        strncat(text, g->line[g->first[1] + k], 72);
    const int n = iges_fields(text, out, max);
    free(text);
    return n;
}

/* An entity 126 read back. */
typedef struct {
    int de; /* its directory entry's first line */
    char label[9];
    int subscript;
    int prop[4];
    int nknots;
    ic_bspline b; /* knots and points as the file gives them */
    double *weights;
    double range[2]; /* V0, V1 */
    int reals_ok;    /* every real field has a decimal point */
} iges_curve;

static inline void iges_curve_free(iges_curve *c)
{
    free(c->b.knots);
    free(c->b.control);
    free(c->weights);
}

/* A real field of a parameter entry: its value; flags one without a point. */
static inline double iges_real(const char *field, int *ok)
{
    char *end;
    const double v = strtod(field, &end);
    if (*end != '\0' || end == field || !strchr(field, '.'))
        *ok = 0;
    return v;
}

/* Parameter data of lines [from, from + n) of P, which must point back to
 * directory line `de`: columns 1-64 run together. */
static inline char *iges_parameters(const iges_file *g, int from, int n, int de)
{
    char *text = calloc((size_t)n * 64 + 1, 1);
    for (int k = 0; text && k < n; k++) {
        const char *line = g->line[g->first[3] + from - 1 + k];
        if (from - 1 + k >= g->count[3] || line[64] != ' ' || iges_column_int(line, 65, 7) != de) {
            free(text);
            return NULL;
        }
        strncat(text, line, 64);
    }
    return text;
}

/* Splits the parameter text into fields at ',' and ';' (126 has no
 * strings); the count, or -1. */
static inline int iges_split(char *text, char **fields, int max)
{
    int n = 0;
    for (char *p = text; n < max;) {
        while (*p == ' ')
            p++;
        fields[n++] = p;
        p += strcspn(p, ",;");
        const char delim = *p;
        char *end = p;
        while (end > fields[n - 1] && end[-1] == ' ')
            end--;
        *end = '\0';
        if (delim == ';')
            return n;
        if (delim != ',')
            return -1;
        p++;
    }
    return -1;
}

/* The entity 126 of directory entry k (0, 1, ...); 1 when it reads. */
static inline int iges_curve_read(const iges_file *g, int k, iges_curve *c)
{
    memset(c, 0, sizeof *c);
    const char *d1 = g->line[g->first[2] + 2 * k], *d2 = g->line[g->first[2] + 2 * k + 1];
    c->de = 2 * k + 1;
    if (iges_column_int(d1, 0, 8) != 126 || iges_column_int(d2, 0, 8) != 126)
        return 0;
    memcpy(c->label, d2 + 56, 8);
    c->subscript = iges_column_int(d2, 64, 8);
    char *text = iges_parameters(g, iges_column_int(d1, 8, 8), iges_column_int(d2, 24, 8), c->de);
    int max = 1;
    for (const char *q = text; q && *q; q++)
        max += *q == ',';
    char **f = text ? malloc(sizeof *f * (size_t)max) : NULL;
    const int n = f ? iges_split(text, f, max) : -1;
    const int K = n > 7 ? atoi(f[1]) : -1, M = n > 7 ? atoi(f[2]) : 0;
    c->nknots = K + M + 2;
    const int want = 7 + c->nknots + 4 * (K + 1) + 5;
    int ok = n == want && atoi(f[0]) == 126 && K >= M && M >= 1;
    c->reals_ok = 1;
    c->b = (ic_bspline){.dim = 3, .degree = M, .ncontrol = K + 1};
    c->b.knots = ok ? malloc(sizeof(double) * (size_t)c->nknots) : NULL;
    c->b.control = ok ? malloc(sizeof(double) * 3 * (size_t)(K + 1)) : NULL;
    c->weights = ok ? malloc(sizeof(double) * (size_t)(K + 1)) : NULL;
    ok = ok && c->b.knots && c->b.control && c->weights;
    for (int j = 0; ok && j < 4; j++)
        c->prop[j] = atoi(f[3 + j]);
    for (int j = 0; ok && j < c->nknots; j++)
        c->b.knots[j] = iges_real(f[7 + j], &c->reals_ok);
    for (int j = 0; ok && j <= K; j++)
        c->weights[j] = iges_real(f[7 + c->nknots + j], &c->reals_ok);
    for (int j = 0; ok && j < 3 * (K + 1); j++)
        c->b.control[j] = iges_real(f[7 + c->nknots + K + 1 + j], &c->reals_ok);
    for (int j = 0; ok && j < 2; j++)
        c->range[j] = iges_real(f[want - 5 + j], &c->reals_ok);
    free(f);
    free(text);
    return ok;
}

#endif
