/* The tracer's constants pinned (issue 10, item 4; docs/testing.md,
 * "Constants pinned"): each case here fails when the constant it names is
 * changed tenfold (tests/mutation/mutate_constants.sh builds every such
 * mutant) and passes with the real value. Truth is closed-form: circles,
 * lines, a Viviani-like curve through a cone's apex, contacts placed by
 * construction, surfaces that do not meet; never the tracer's output. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "curve_lengths.h"
#include "harness.h"
#include "intercurve.h"
#include "trace/trace_internal.h"
#include "traced_pair.h"

#define PI 3.14159265358979323846

/* The docs' promise for lengths (docs/tracing.md). */
#define LENGTH_REL 1e-9

/* Two implicit formulas traced in the box with the default options at the
 * search depth given. */
static int trace_implicit(traced *t, const char *fa, const char *fb, const double box[3][2],
                          int depth)
{
    memset(t, 0, sizeof *t);
    ic_error err;
    ic_trace_options opt;
    ic_trace_defaults(&opt);
    opt.has_box = 1;
    memcpy(opt.box, box, sizeof opt.box);
    opt.depth = depth;
    ic_status st = ic_surface_new_implicit(&t->A, fa, NULL, 0, &err);
    if (st == IC_OK)
        st = ic_surface_new_implicit(&t->B, fb, NULL, 0, &err);
    if (st == IC_OK)
        st = ic_pair_new(&t->pair, t->A, t->B, &err);
    if (st == IC_OK)
        st = ic_trace(&t->res, t->pair, &opt, &err);
    if (st != IC_OK)
        fprintf(stderr, "trace %s / %s: %s\n", fa, fb, err.message);
    return st == IC_OK;
}

static int ncurves(const traced *t) { return ic_trace_result_num_curves(t->res); }
static int npoints(const traced *t) { return ic_trace_result_num_specials(t->res); }
static int complete(const traced *t) { return ic_trace_result_report(t->res)->complete; }
static const char *first_failure(const traced *t)
{
    const ic_trace_report *r = ic_trace_result_report(t->res);
    return r->nfailures ? r->failures[0] : "";
}

/* ---- the search's budgets ---- */

/* IC_TRACE_MAX_CELLS: the planes z = 0 and z = 1e-9 do not meet. At the
 * deepest search a user can ask for (depth 9) proving that takes about
 * 7e5 cells (every leaf along the planes down to 2^-9 of the box); the
 * budget must allow it (a tenth of it stops the search, not complete). */
static void test_cell_budget(void)
{
    static const double box[3][2] = {{-1, 1}, {-1, 1}, {-0.6, 1.4}};
    traced t;
    if (!trace_implicit(&t, "z", "z - 1e-9", box, 9)) {
        CHECK(0, "near planes at depth 9: traced");
        return;
    }
    CHECK(ncurves(&t) == 0 && npoints(&t) == 0 && complete(&t),
          "near planes at depth 9: %d curves, %d points, complete %d (want 0, 0, 1: %s)",
          ncurves(&t), npoints(&t), complete(&t), first_failure(&t));
    release(&t);
}

/* One closed curve: a circle of radius rho about (cx, cy) in the plane z = h,
 * its length to length_rel and every point within point_tol of it. */
static void expect_circle(const char *what, const traced *t, double cx, double cy, double h,
                          double rho, double length_rel, double point_tol)
{
    CHECK(ncurves(t) == 1, "%s: %d curves (want 1)", what, ncurves(t));
    if (ncurves(t) != 1)
        return;
    const ic_trace_curve *c = ic_trace_result_curve(t->res, 0);
    const double L = 2 * PI * rho;
    CHECK(c->closed && fabs(c->length - L) <= length_rel * L,
          "%s: closed %d, length %.17g (want %.17g)", what, c->closed, c->length, L);
    double worst = 0;
    for (int i = 0; i < c->npoints; i++) {
        const double *x = c->points[i].xyz;
        worst = fmax(worst, fabs(hypot(x[0] - cx, x[1] - cy) - rho));
        worst = fmax(worst, fabs(x[2] - h));
    }
    CHECK(worst <= point_tol, "%s: a point %.3g off the circle (tolerance %.3g)", what, worst,
          point_tol);
}

/* IC_TRACE_MAX_REFINE_LEVELS: the bump z = 0.5 exp(-(x^2 + y^2)/s^2), s =
 * 1e-6, meets z = 0.25 in the circle of radius s sqrt(ln 2). Newton finds
 * it only from cells of about its size: 2^-14 of a first-search cell of
 * the box [-1, 1]^3, found within 16 levels, not within 12. */
static void test_refinement_depth(void)
{
    static const double box[3][2] = {{-1, 1}, {-1, 1}, {-1, 1}};
    const double s = 1e-6;
    traced t;
    if (!trace_implicit(&t, "z - 0.5*exp(-(x^2 + y^2)/1e-12)", "z - 0.25", box, 6)) {
        CHECK(0, "bump: traced");
        return;
    }
    /* the length: the tracer's step tolerance, 1e-11 L, is 1e-5 of this
     * circle's radius (measured 1.3e-8 relative); 1e-6 tells it from any
     * other circle. Its points lie on both surfaces to rounding. */
    expect_circle("a bump of width 1e-6", &t, 0, 0, 0.25, s * sqrt(log(2.0)), 1e-6, 1e-14);
    CHECK(complete(&t), "a bump of width 1e-6: complete (%s)", first_failure(&t));
    release(&t);
}

/* IC_TRACE_EXPLAIN_LEVELS: z = (x^2 + y^2)(1 - 2 exp(-((x - 0.02)^2 + y^2)/s^2)),
 * s = 1e-4, against z = 0: an isolated contact at the origin (the height is
 * (x^2 + y^2)(1 - 2 e^-40000) there, positive definite) and the circle of
 * radius s sqrt(ln 2) about (0.02, 0), 0.02 from it. Newton finds the
 * circle only from cells of about its size. Explained at the first
 * search's level (cells of 1/32), the contact's cells would hide it; at
 * 1/8 of that (3 levels) the cells around the circle are searched. */
static void test_loop_beside_contact(void)
{
    static const double box[3][2] = {{-1, 1}, {-1, 1}, {-1, 1}};
    const double s = 1e-4;
    traced t;
    if (!trace_implicit(&t, "z - (x^2 + y^2)*(1 - 2*exp(-((x - 0.02)^2 + y^2)/1e-8))", "z", box,
                        6)) {
        CHECK(0, "loop beside a contact: traced");
        return;
    }
    expect_circle("a loop 0.02 from a contact", &t, 0.02, 0, 0, s * sqrt(log(2.0)), LENGTH_REL,
                  1e-14);
    CHECK(npoints(&t) == 1, "a loop 0.02 from a contact: %d points (want 1)", npoints(&t));
    if (npoints(&t) == 1) {
        const ic_trace_special *p = ic_trace_result_special(t.res, 0);
        CHECK(p->type == IC_POINT_ISOLATED_CONTACT && !p->approximate &&
                  fmax(fmax(fabs(p->xyz[0]), fabs(p->xyz[1])), fabs(p->xyz[2])) <= 1e-12,
              "the contact: %s, approximate %d, at (%g, %g, %g)", ic_point_type_name(p->type),
              p->approximate, p->xyz[0], p->xyz[1], p->xyz[2]);
    }
    CHECK(complete(&t), "a loop 0.02 from a contact: complete (%s)", first_failure(&t));
    release(&t);
}

/* ---- curves told apart ---- */

/* IC_TRACE_ON_CURVE: z = k (x^2 - r^2 + r^2 y / 2), k = 3e7, r^2 = 1.1e-15,
 * against z = 0: the two branches x = +-sqrt(r^2 (1 - y/2)) of a parabola
 * that closes beyond the box, 4.7e-8 to 8.1e-8 apart over y in [-1, 1]
 * (2.4 to 4 times 1e-8 L; L = 2, the diagonal of what the search left),
 * each of length 2 (the slope r^2/(4x) adds 1e-16). N_A x N_B has x
 * component k r^2 / 2 everywhere: every cell is loop-free. */
static void test_close_branches(void)
{
    static const double box[3][2] = {{-1, 1}, {-1, 1}, {-1, 1}};
    traced t;
    if (!trace_implicit(&t, "z - 3e7*(x^2 - 1.1e-15 + 5.5e-16*y)", "z", box, 6)) {
        CHECK(0, "close branches: traced");
        return;
    }
    CHECK(ncurves(&t) == 2 && complete(&t), "branches 5e-8 apart: %d curves (want 2), complete %d",
          ncurves(&t), complete(&t));
    double sides = 0;
    for (int i = 0; i < ncurves(&t); i++) {
        const ic_trace_curve *c = ic_trace_result_curve(t.res, i);
        CHECK(fabs(c->length - 2) <= LENGTH_REL * 2, "branch %d: length %.17g (want 2)", i,
              c->length);
        double worst = 0;
        for (int k = 0; k < c->npoints; k++) {
            const double *x = c->points[k].xyz;
            const double want = copysign(sqrt(1.1e-15 - 5.5e-16 * x[1]), x[0]);
            worst = fmax(worst, fabs(x[0] - want));
        }
        /* on both surfaces to rounding (1e-15), 5e7 times nearer its own
         * branch than the other */
        CHECK(worst <= 1e-15, "branch %d: a point %.3g off its branch", i, worst);
        sides += copysign(1.0, c->points[0].xyz[0]);
    }
    CHECK(sides == 0, "the two curves are the two branches (sides sum %g)", sides);
    release(&t);
}

int main(void)
{
    test_cell_budget();
    test_refinement_depth();
    test_loop_beside_contact();
    test_close_branches();
    return harness_finish("constants");
}
