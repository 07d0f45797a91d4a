/* ic_trace_write_iges: the fitted curves of traced examples written as
 * IGES and read back by a reader of the test's own (iges_readback.h): the
 * 80-column records and their sequence numbers, the global section's units
 * and scale, each entity 126's directory entry and parameters, its
 * B-spline bit for bit, weights 1, on both surfaces (docs/output-formats.md,
 * "IGES"). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fitted_cases.h"
#include "harness.h"
#include "iges_readback.h"
#include "intercurve.h"
#include "trace/trace_internal.h"

static int all_ones(const double *w, int n)
{
    for (int k = 0; k < n; k++)
        if (w[k] != 1)
            return 0;
    return 1;
}

/* Global fields (1-based as IGES 5.3 numbers them): delimiters, scale 1,
 * units flag 2 and "MM", version 11 (5.3). */
static void check_global(const fitted_case *c, const iges_file *g)
{
    char f[32][80];
    const int n = iges_global(g, f, 32);
    CHECK(n == 25, "%s: 25 global fields (%d)", c->name, n);
    if (n != 25)
        return;
    CHECK(strcmp(f[0], "1H,") == 0 && strcmp(f[1], "1H;") == 0, "%s: delimiters , and ;", c->name);
    CHECK(strtod(f[12], NULL) == 1 && strchr(f[12], '.'), "%s: model space scale 1. (%s)", c->name,
          f[12]);
    CHECK(strcmp(f[13], "2") == 0 && strcmp(f[14], "2HMM") == 0, "%s: units flag 2, MM (%s, %s)",
          c->name, f[13], f[14]);
    CHECK(strcmp(f[22], "11") == 0, "%s: IGES 5.3 (version flag 11, %s)", c->name, f[22]);
    CHECK(strlen(f[17]) == 18 && strncmp(f[17], "15H", 3) == 0 && f[17][11] == '.',
          "%s: the date 15HYYYYMMDD.HHNNSS (%s)", c->name, f[17]);
}

/* Entity k is curve i's fit, bit for bit, and lies on both surfaces. */
static void check_curve(const fitted_case *c, const fitted *t, const iges_curve *e, int i)
{
    const ic_bspline *b = &ic_trace_result_fit(t->res, i)->curve;
    CHECK(strcmp(e->label, "   CURVE") == 0 && e->subscript == i, "%s: label CURVE %d ('%s' %d)",
          c->name, i, e->label, e->subscript);
    CHECK(e->prop[0] == 0 && e->prop[1] == ic_trace_result_curve(t->res, i)->closed &&
              e->prop[2] == 1 && e->prop[3] == b->periodic,
          "%s curve %d: PROP1..4 = 0, closed, 1 (polynomial), periodic", c->name, i);
    CHECK(e->b.degree == b->degree && e->b.ncontrol == b->ncontrol,
          "%s curve %d: degree %d, %d points", c->name, i, e->b.degree, e->b.ncontrol);
    if (e->b.degree != b->degree || e->b.ncontrol != b->ncontrol)
        return;
    CHECK(same_doubles(e->b.knots, b->knots, e->nknots) &&
              same_doubles(e->b.control, b->control, 3 * b->ncontrol),
          "%s curve %d: knots and control points bit for bit", c->name, i);
    CHECK(all_ones(e->weights, b->ncontrol), "%s curve %d: weights 1", c->name, i);
    CHECK(e->reals_ok, "%s curve %d: every real with a decimal point", c->name, i);
    CHECK(e->range[0] == b->knots[b->degree] && e->range[1] == b->knots[b->ncontrol],
          "%s curve %d: V0, V1 the parameter range", c->name, i);
    const double tol = ic_trace_result_report(t->res)->fit_tol,
                 d = fitted_largest_distance(c, &e->b);
    CHECK(d <= tol,
          "%s curve %d: %d points of the curve read back within the fit tolerance %g "
          "of both surfaces (%g)",
          c->name, i, CASE_CHECKS, tol, d);
}

/* The directory entries, in order, are the fitted curves; the parameter
 * lines they point to follow each other without a gap. */
static void check_entities(const fitted_case *c, const fitted *t, const iges_file *g,
                           const int *which, int n)
{
    CHECK(g->count[2] == 2 * n, "%s: %d directory lines for %d curves", c->name, g->count[2], n);
    int next_p = 1;
    for (int k = 0; k < n && 2 * k + 1 < g->count[2]; k++) {
        const char *d1 = g->line[g->first[2] + 2 * k], *d2 = g->line[g->first[2] + 2 * k + 1];
        CHECK(iges_column_int(d1, 8, 8) == next_p && strncmp(d1 + 64, "00000000", 8) == 0,
              "%s: entity %d's parameters start at P%d, status 00000000", c->name, k, next_p);
        next_p += iges_column_int(d2, 24, 8);
        iges_curve e;
        if (REQUIRE(iges_curve_read(g, k, &e), "%s: entity %d reads as a 126", c->name, k))
            check_curve(c, t, &e, which[k]);
        iges_curve_free(&e);
    }
    CHECK(next_p == g->count[3] + 1, "%s: the parameter lines are the entities' (%d of %d)",
          c->name, next_p - 1, g->count[3]);
}

/* The start section's text (columns 1-72 run together) is `start`. */
static void check_start(const fitted_case *c, const iges_file *g, const char *start)
{
    char text[512] = "";
    for (int k = 0; k < g->count[0] && (k + 1) * 72 < (int)sizeof text; k++)
        strncat(text, g->line[k], 72);
    size_t n = strlen(text);
    while (n > 0 && text[n - 1] == ' ')
        n--;
    text[n] = '\0';
    CHECK(strcmp(text, start) == 0, "%s: the start section is '%.60s' (%d lines)", c->name, text,
          g->count[0]);
}

static void check_file(const fitted_case *c, const fitted *t, const char *title, const char *start)
{
    ic_error err;
    ic_status st = IC_OK;
    char *buf = fitted_write(ic_trace_write_iges, t, title, &st, &err);
    iges_file g;
    if (REQUIRE(buf, "%s: IGES written: %s", c->name, err.message) &&
        REQUIRE(iges_read(&g, buf) == 0,
                "%s: 80 columns a line, sections S G D P T numbered, counted in T", c->name)) {
        check_start(c, &g, start);
        check_global(c, &g);
        int which[8], n = 0;
        for (int i = 0; i < ic_trace_result_num_curves(t->res) && n < 8; i++)
            if (ic_trace_result_fit(t->res, i))
                which[n++] = i;
        check_entities(c, t, &g, which, n);
    }
    if (buf)
        iges_free(&g);
    free(buf);
}

static void check_case(const fitted_case *c, const char *dir)
{
    fitted t;
    if (fitted_trace(&t, c, dir) != 0)
        return;
    check_file(c, &t, "Viviani's curve", "Viviani's curve");
    check_file(c, &t, NULL, "intersection curves as B-splines");
    fitted_release(&t);
}

/* A curve without a fit is left out; with none, the writer says to fit. */
static void check_unfitted(const char *dir)
{
    const fitted_case *c = &FITTED_CASES[2];
    fitted t;
    if (fitted_trace(&t, c, dir) != 0)
        return;
    ic_curve_fit *const kept[2] = {t.res->fits[0], t.res->fits[1]};
    t.res->fits[0] = NULL;
    check_file(c, &t, "one of two", "one of two");
    t.res->fits[1] = NULL;
    ic_error err;
    ic_status st = IC_OK;
    char *buf = fitted_write(ic_trace_write_iges, &t, NULL, &st, &err);
    CHECK(!buf && st == IC_ERR_INVALID && strstr(err.message, "ic_trace_fit"),
          "no fit: IC_ERR_INVALID saying to fit first (%s)", err.message);
    free(buf);
    t.res->fits[0] = kept[0];
    t.res->fits[1] = kept[1];
    fitted_release(&t);
}

/* A long title fills several start lines; a stream that refuses writes is
 * IC_ERR_IO. */
static void check_title_and_error(const char *dir)
{
    const fitted_case *c = &FITTED_CASES[1];
    fitted t;
    if (fitted_trace(&t, c, dir) != 0)
        return;
    char title[200];
    for (int k = 0; k < 199; k++)
        title[k] = (char)('a' + k % 26);
    title[199] = '\0';
    check_file(c, &t, title, title);
    FILE *ro = fopen("/dev/null", "r");
    ic_error err;
    if (REQUIRE(ro, "/dev/null opens"))
        CHECK(ic_trace_write_iges(ro, t.res, "x", &err) == IC_ERR_IO,
              "a write error is IC_ERR_IO (%s)", err.message);
    if (ro)
        fclose(ro);
    fitted_release(&t);
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : ".";
    for (int k = 0; k < NFITTED_CASES; k++)
        check_case(&FITTED_CASES[k], dir);
    check_unfitted(dir);
    check_title_and_error(dir);
    return harness_finish("test_curve_iges");
}
