/* A small reader of ISO 10303-21 for the tests, written apart from the
 * writer (src/cad/curve_step.c): the DATA section's instances by number, and
 * each B_SPLINE_CURVE_WITH_KNOTS with its CARTESIAN_POINTs followed by
 * reference and its knots expanded from the multiplicities. Any departure
 * from the syntax it expects makes it fail (ok = 0), never guess. */
#ifndef IC_TEST_STEP_READBACK_H
#define IC_TEST_STEP_READBACK_H

#include <ctype.h>
#include <stdlib.h>
#include <string.h>

#include "intercurve.h"

typedef struct {
    int id;
    char *text; /* after "#id=", without the ';' */
} p21_instance;

typedef struct {
    char *header; /* HEADER section, its ';' kept */
    p21_instance *inst;
    int n;
} p21_file;

/* A cursor through an instance's text; ok drops to 0 at the first surprise.
 * Blanks may come before any token (p21_expect's text is one token). */
typedef struct {
    const char *p;
    int ok;
} p21_cursor;

static inline void p21_skip(p21_cursor *c)
{
    while (isspace((unsigned char)*c->p))
        c->p++;
}

static inline void p21_expect(p21_cursor *c, const char *token)
{
    p21_skip(c);
    if (c->ok && strncmp(c->p, token, strlen(token)) == 0)
        c->p += strlen(token);
    else
        c->ok = 0;
}

/* Consumes ch when it comes next. */
static inline int p21_next_is(p21_cursor *c, char ch)
{
    p21_skip(c);
    if (*c->p != ch)
        return 0;
    c->p++;
    return 1;
}

static inline long p21_integer(p21_cursor *c)
{
    p21_skip(c);
    char *end;
    const long v = strtol(c->p, &end, 10);
    if (end == c->p || *end == '.' || *end == 'E')
        c->ok = 0;
    c->p = end;
    return v;
}

/* A REAL: digits, a decimal point (required), digits, an optional exponent. */
static inline double p21_real(p21_cursor *c)
{
    p21_skip(c);
    const char *s = c->p + (*c->p == '-' || *c->p == '+');
    size_t digits = strspn(s, "0123456789");
    if (digits == 0 || s[digits] != '.')
        c->ok = 0;
    char *end;
    const double v = strtod(c->p, &end);
    if (end == c->p)
        c->ok = 0;
    c->p = end;
    return v;
}

static inline int p21_reference(p21_cursor *c)
{
    p21_expect(c, "#");
    return (int)p21_integer(c);
}

/* A string '...' ('' is a quote) into out. */
static inline void p21_string(p21_cursor *c, char *out, size_t size)
{
    size_t n = 0;
    p21_expect(c, "'");
    while (c->ok && *c->p) {
        if (*c->p == '\'' && c->p[1] != '\'')
            break;
        c->p += *c->p == '\'' ? 2 : 1;
        if (n + 1 < size)
            out[n++] = c->p[-1];
    }
    out[n] = '\0';
    p21_expect(c, "'");
}

/* The end of text after an instance's last character, skipping strings. */
static inline char *p21_instance_end(char *p)
{
    for (int quoted = 0; *p; p++) {
        if (*p == '\'')
            quoted = !quoted; /* '' toggles twice */
        else if (*p == ';' && !quoted)
            return p;
    }
    return NULL;
}

/* Splits buf (kept and modified) into the header and the DATA instances;
 * 0 on success. */
static inline int p21_read(p21_file *pf, char *buf)
{
    memset(pf, 0, sizeof *pf);
    char *data = strstr(buf, "\nDATA;\n");
    if (strncmp(buf, "ISO-10303-21;\nHEADER;\n", 22) != 0 || !data)
        return -1;
    *data = '\0';
    pf->header = buf + 22;
    char *p = data + 7;
    for (;;) {
        while (isspace((unsigned char)*p))
            p++;
        if (strcmp(p, "ENDSEC;\nEND-ISO-10303-21;\n") == 0)
            return 0;
        char *end = p21_instance_end(p), *eq;
        const long id = strtol(p + 1, &eq, 10);
        if (*p != '#' || !end || *eq != '=' || id <= 0)
            return -1;
        p21_instance *grown = realloc(pf->inst, (size_t)(pf->n + 1) * sizeof *grown);
        if (!grown)
            return -1;
        pf->inst = grown;
        *end = '\0';
        pf->inst[pf->n++] = (p21_instance){(int)id, eq + 1};
        p = end + 1;
    }
}

static inline void p21_free(p21_file *pf) { free(pf->inst); }

static inline const char *p21_find(const p21_file *pf, int id)
{
    for (int k = 0; k < pf->n; k++)
        if (pf->inst[k].id == id)
            return pf->inst[k].text;
    return NULL;
}

/* How many instances are of the type (their text begins "TYPE("). */
static inline int p21_count(const p21_file *pf, const char *type)
{
    int n = 0;
    for (int k = 0; k < pf->n; k++)
        n += strncmp(pf->inst[k].text, type, strlen(type)) == 0 &&
             pf->inst[k].text[strlen(type)] == '(';
    return n;
}

/* CARTESIAN_POINT('',(x,y,z)) of instance id into x. */
static inline int p21_point(const p21_file *pf, int id, double x[3])
{
    const char *text = p21_find(pf, id);
    p21_cursor c = {text ? text : "", text != NULL};
    char name[64];
    p21_expect(&c, "CARTESIAN_POINT(");
    p21_string(&c, name, sizeof name);
    p21_expect(&c, ",");
    p21_expect(&c, "(");
    for (int j = 0; j < 3; j++) {
        if (j)
            p21_expect(&c, ",");
        x[j] = p21_real(&c);
    }
    p21_expect(&c, ")");
    p21_expect(&c, ")");
    p21_skip(&c);
    return c.ok && *c.p == '\0';
}

/* A curve read back: the B-spline (knots expanded), its name and flags. */
typedef struct {
    char name[64];
    int closed;
    int nknots; /* expanded */
    ic_bspline b;
} p21_curve;

static inline void p21_curve_free(p21_curve *k)
{
    free(k->b.knots);
    free(k->b.control);
}

/* Appends x to a growing array of doubles (*n of them). */
static inline int p21_push(double **a, int *n, double x)
{
    double *grown = realloc(*a, (size_t)(*n + 1) * sizeof *grown);
    if (!grown)
        return 0;
    grown[(*n)++] = x;
    *a = grown;
    return 1;
}

/* The control points: "(#a,#b,...)" */
static inline void p21_curve_points(p21_cursor *c, const p21_file *pf, p21_curve *k)
{
    p21_expect(c, "(");
    int ncoords = 0;
    do {
        double x[3];
        if (!p21_point(pf, p21_reference(c), x))
            c->ok = 0;
        for (int j = 0; j < 3 && c->ok; j++)
            c->ok = p21_push(&k->b.control, &ncoords, x[j]);
    } while (c->ok && p21_next_is(c, ','));
    p21_expect(c, ")");
    k->b.ncontrol = ncoords / 3;
}

/* "(m1,...),(k1,...)": each distinct knot repeated by its multiplicity. */
static inline void p21_curve_knots(p21_cursor *c, p21_curve *k)
{
    long mult[4096];
    int nmult = 0, nknots = 0;
    p21_expect(c, "(");
    do
        mult[nmult++] = p21_integer(c);
    while (c->ok && nmult < 4096 && p21_next_is(c, ','));
    p21_expect(c, ")");
    p21_expect(c, ",");
    p21_expect(c, "(");
    for (int d = 0; c->ok; d++) {
        const double knot = p21_real(c);
        for (long r = 0; d < nmult && r < mult[d] && c->ok; r++)
            c->ok = p21_push(&k->b.knots, &nknots, knot);
        if (d >= nmult || !p21_next_is(c, ',')) {
            c->ok = c->ok && d == nmult - 1;
            break;
        }
    }
    p21_expect(c, ")");
    k->nknots = nknots;
}

/* Instance `text`, a B_SPLINE_CURVE_WITH_KNOTS, into k; 1 when it reads. */
static inline int p21_curve_read(const p21_file *pf, const char *text, p21_curve *k)
{
    memset(k, 0, sizeof *k);
    k->b.dim = 3;
    p21_cursor c = {text, 1};
    p21_expect(&c, "B_SPLINE_CURVE_WITH_KNOTS(");
    p21_string(&c, k->name, sizeof k->name);
    p21_expect(&c, ",");
    k->b.degree = (int)p21_integer(&c);
    p21_expect(&c, ",");
    p21_curve_points(&c, pf, k);
    p21_expect(&c, ",");
    p21_expect(&c, ".UNSPECIFIED.");
    p21_expect(&c, ",");
    k->closed = p21_next_is(&c, '.') && *c.p == 'T';
    p21_expect(&c, k->closed ? "T." : "F.");
    p21_expect(&c, ",");
    p21_expect(&c, ".F.");
    p21_expect(&c, ",");
    p21_curve_knots(&c, k);
    p21_expect(&c, ",");
    p21_expect(&c, ".UNSPECIFIED.");
    p21_expect(&c, ")");
    p21_skip(&c);
    return c.ok && *c.p == '\0';
}

#endif
