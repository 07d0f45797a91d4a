/* ic_trace_write_step: the fitted curves of traced examples written as
 * STEP and read back by a reader of the test's own (step_readback.h). The
 * B-splines must come back bit for bit (17 significant digits round-trip a
 * double), lie on both surfaces, and the file must hold the entities a CAD
 * system needs to open it (docs/output-formats.md, "STEP"). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fitted_cases.h"
#include "harness.h"
#include "intercurve.h"
#include "step_readback.h"
#include "trace/trace_internal.h"

/* The curve read back is the fit's B-spline, bit for bit, and lies on both
 * surfaces within the fit tolerance. */
static void check_curve(const fitted_case *c, const fitted *t, const p21_curve *k, int i)
{
    const ic_bspline *b = &ic_trace_result_fit(t->res, i)->curve;
    char want[64];
    snprintf(want, sizeof want, "curve %d", i);
    CHECK(strcmp(k->name, want) == 0, "%s: the curve is named '%s', not '%s'", c->name, k->name,
          want);
    CHECK(k->b.degree == b->degree && k->b.ncontrol == b->ncontrol &&
              k->nknots == b->ncontrol + b->degree + 1,
          "%s curve %d: degree %d, %d points, %d knots", c->name, i, k->b.degree, k->b.ncontrol,
          k->nknots);
    if (k->b.degree != b->degree || k->b.ncontrol != b->ncontrol ||
        k->nknots != b->ncontrol + b->degree + 1)
        return;
    CHECK(same_doubles(k->b.control, b->control, 3 * b->ncontrol),
          "%s curve %d: the control points bit for bit", c->name, i);
    CHECK(same_doubles(k->b.knots, b->knots, k->nknots), "%s curve %d: the knots bit for bit",
          c->name, i);
    CHECK(k->closed == ic_trace_result_curve(t->res, i)->closed, "%s curve %d: closed flag",
          c->name, i);
    const double tol = ic_trace_result_report(t->res)->fit_tol,
                 d = fitted_largest_distance(c, &k->b);
    CHECK(d <= tol,
          "%s curve %d: %d points of the curve read back within the fit tolerance %g "
          "of both surfaces (%g)",
          c->name, i, CASE_CHECKS, tol, d);
}

/* Every #n a DATA instance mentions is an instance of the file. */
static int references_resolve(const p21_file *pf)
{
    for (int k = 0; k < pf->n; k++)
        for (const char *p = strchr(pf->inst[k].text, '#'); p; p = strchr(p + 1, '#'))
            if (!p21_find(pf, atoi(p + 1)))
                return 0;
    return 1;
}

/* The header, the context a CAD system needs, the counts. */
static void check_file(const fitted_case *c, const fitted *t, const p21_file *pf)
{
    CHECK(strstr(pf->header, "FILE_DESCRIPTION((") && strstr(pf->header, "FILE_NAME('") &&
              strstr(pf->header,
                     "FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));\nENDSEC;"),
          "%s: the header's three entities, AP214", c->name);
    CHECK(references_resolve(pf), "%s: every reference is an instance", c->name);
    static const char *const needed[] = {"APPLICATION_PROTOCOL_DEFINITION",
                                         "PRODUCT",
                                         "PRODUCT_DEFINITION",
                                         "PRODUCT_DEFINITION_SHAPE",
                                         "SHAPE_DEFINITION_REPRESENTATION",
                                         "GEOMETRICALLY_BOUNDED_WIREFRAME_SHAPE_REPRESENTATION",
                                         "GEOMETRIC_CURVE_SET"};
    for (size_t k = 0; k < sizeof needed / sizeof *needed; k++)
        CHECK(p21_count(pf, needed[k]) == 1, "%s: one %s", c->name, needed[k]);
    int points = 0;
    for (int i = 0; i < ic_trace_result_num_curves(t->res); i++)
        points += ic_trace_result_fit(t->res, i)->curve.ncontrol;
    CHECK(p21_count(pf, "B_SPLINE_CURVE_WITH_KNOTS") == c->ncurves &&
              p21_count(pf, "CARTESIAN_POINT") == points,
          "%s: %d curves and %d points, no other", c->name, c->ncurves, points);
    int mm = 0;
    for (int k = 0; k < pf->n; k++)
        mm += strcmp(pf->inst[k].text, "(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MILLI.,.METRE.))") == 0;
    CHECK(mm == 1, "%s: the length unit is the millimetre", c->name);
}

static void check_case(const fitted_case *c, const char *dir)
{
    fitted t;
    if (fitted_trace(&t, c, dir) != 0)
        return;
    ic_error err;
    ic_status st = IC_OK;
    char *buf = fitted_write(ic_trace_write_step, &t, "Viviani's \\ curve", &st, &err);
    p21_file pf;
    if (REQUIRE(buf, "%s: STEP written: %s", c->name, err.message) &&
        REQUIRE(p21_read(&pf, buf) == 0, "%s: the file splits into header and instances",
                c->name)) {
        CHECK(strstr(pf.header, "FILE_NAME('Viviani''s \\\\ curve'"),
              "%s: the title as a Part 21 string", c->name);
        check_file(c, &t, &pf);
        for (int k = 0, i = 0; k < pf.n; k++) {
            if (strncmp(pf.inst[k].text, "B_SPLINE_CURVE_WITH_KNOTS(", 26) != 0)
                continue;
            p21_curve curve;
            if (REQUIRE(p21_curve_read(&pf, pf.inst[k].text, &curve), "%s: curve #%d reads",
                        c->name, pf.inst[k].id))
                check_curve(c, &t, &curve, i++);
            p21_curve_free(&curve);
        }
        p21_free(&pf);
    }
    free(buf);
    fitted_release(&t);
}

/* A curve without a fit is left out; with none, the writer says to fit. */
static void check_unfitted(const char *dir)
{
    fitted t;
    if (fitted_trace(&t, &FITTED_CASES[2], dir) != 0)
        return;
    ic_error err;
    ic_status st = IC_OK;
    ic_curve_fit *const kept[2] = {t.res->fits[0], t.res->fits[1]};
    t.res->fits[0] = NULL;
    char *buf = fitted_write(ic_trace_write_step, &t, NULL, &st, &err);
    p21_file pf;
    if (REQUIRE(buf && p21_read(&pf, buf) == 0, "one fit of two: written")) {
        CHECK(p21_count(&pf, "B_SPLINE_CURVE_WITH_KNOTS") == 1 &&
                  p21_count(&pf, "CARTESIAN_POINT") == kept[1]->curve.ncontrol,
              "one fit of two: one curve, its points");
        int curve1 = 0;
        for (int k = 0; k < pf.n; k++)
            curve1 += strncmp(pf.inst[k].text, "B_SPLINE_CURVE_WITH_KNOTS('curve 1',", 36) == 0;
        CHECK(curve1 == 1, "it is curve 1");
        p21_free(&pf);
    }
    free(buf);
    t.res->fits[1] = NULL;
    buf = fitted_write(ic_trace_write_step, &t, NULL, &st, &err);
    CHECK(!buf && st == IC_ERR_INVALID && strstr(err.message, "ic_trace_fit"),
          "no fit: IC_ERR_INVALID saying to fit first (%s)", err.message);
    free(buf);
    t.res->fits[0] = kept[0];
    t.res->fits[1] = kept[1];
    fitted_release(&t);
}

/* A stream that refuses writes: IC_ERR_IO. */
static void check_write_error(const char *dir)
{
    fitted t;
    if (fitted_trace(&t, &FITTED_CASES[1], dir) != 0)
        return;
    FILE *ro = fopen("/dev/null", "r");
    ic_error err;
    if (REQUIRE(ro, "/dev/null opens"))
        CHECK(ic_trace_write_step(ro, t.res, "x", &err) == IC_ERR_IO,
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
    check_write_error(dir);
    return harness_finish("test_curve_step");
}
