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

/* AddressSanitizer (make sanitize) runs the traces about 5 times slower: a
 * time limit grows with it (as in test_torture). */
#ifdef __SANITIZE_ADDRESS__
#define SLOWDOWN 5.0
#else
#define SLOWDOWN 1.0
#endif

/* The default options in the box at the search depth given. */
static ic_trace_options box_options(const double box[3][2], int depth)
{
    ic_trace_options opt;
    ic_trace_defaults(&opt);
    opt.has_box = 1;
    memcpy(opt.box, box, sizeof opt.box);
    opt.depth = depth;
    return opt;
}

/* Two implicit formulas traced with the options. */
static int trace_with(traced *t, const char *fa, const char *fb, const ic_trace_options *opt)
{
    memset(t, 0, sizeof *t);
    ic_error err;
    ic_status st = ic_surface_new_implicit(&t->A, fa, NULL, 0, &err);
    if (st == IC_OK)
        st = ic_surface_new_implicit(&t->B, fb, NULL, 0, &err);
    if (st == IC_OK)
        st = ic_pair_new(&t->pair, t->A, t->B, &err);
    if (st == IC_OK)
        st = ic_trace(&t->res, t->pair, opt, &err);
    if (st != IC_OK)
        fprintf(stderr, "trace %s / %s: %s\n", fa, fb, err.message);
    return st == IC_OK;
}

/* Two implicit formulas traced in the box with the default options at the
 * search depth given. */
static int trace_implicit(traced *t, const char *fa, const char *fb, const double box[3][2],
                          int depth)
{
    const ic_trace_options opt = box_options(box, depth);
    return trace_with(t, fa, fb, &opt);
}

static int ncurves(const traced *t) { return ic_trace_result_num_curves(t->res); }
static int npoints(const traced *t) { return ic_trace_result_num_specials(t->res); }
static int complete(const traced *t) { return ic_trace_result_report(t->res)->tracer_complete; }
static const char *first_failure(const traced *t)
{
    const ic_trace_report *r = ic_trace_result_report(t->res);
    return r->nfailures ? r->failures[0] : "";
}

/* Whether some failure of the report contains the words. */
static int failure_says(const traced *t, const char *words)
{
    const ic_trace_report *r = ic_trace_result_report(t->res);
    for (int i = 0; i < r->nfailures; i++)
        if (strstr(r->failures[i], words))
            return 1;
    return 0;
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

/* ---- the undecided regions ---- */

/* IC_TRACE_MAX_REGIONS: y + 1e-300 exp(800 sin(8 pi x)) overflows double
 * precision where sin(8 pi x) > log(DBL_MAX)/800 = 0.8872, in eight bands
 * of width 0.038 about x = 1/16 + n/4, n = -4..3. Each band is undecided
 * (the formula cannot be evaluated there) and is listed as its own region,
 * no wider in x than the band and a first-search cell (1/32) each side:
 * with six regions at most the last would reach across three bands. */
static void test_undecided_regions(void)
{
    static const double box[3][2] = {{-1, 1}, {-1, 1}, {-1, 1}};
    traced t;
    if (!trace_implicit(&t, "y + 1e-300*exp(800*sin(8*pi*x))", "z", box, 6)) {
        CHECK(0, "overflow bands: traced");
        return;
    }
    CHECK(!complete(&t), "overflow bands: complete");
    const ic_trace_report *r = ic_trace_result_report(t.res);
    int found[8] = {0};
    for (int i = 0; i < r->nfailures; i++) {
        const char *box_text = strchr(r->failures[i], '[');
        double lo, hi;
        if (strncmp(r->failures[i], "undecided:", 10) != 0 || !box_text ||
            sscanf(box_text, "[%lf, %lf]", &lo, &hi) != 2)
            continue;
        CHECK(hi - lo <= 0.038 + 2.0 / 32, "an undecided region [%g, %g] in x: wider than a band",
              lo, hi);
        for (int n = -4; n <= 3; n++)
            found[n + 4] += lo <= 0.0625 + n / 4.0 && 0.0625 + n / 4.0 <= hi;
    }
    for (int n = 0; n < 8; n++)
        CHECK(found[n] == 1, "the band about x = %g: in %d regions (want 1)", 0.0625 + (n - 4) / 4.0,
              found[n]);
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

/* ---- singular points ---- */

/* The cone x^2 + y^2 = z^2 cut by the cylinder (x - 1/2)^2 + y^2 = 1/4
 * through its apex: the closed curve c(th) = ((1 + cos 2th)/2,
 * (sin 2th)/2, cos th), through the apex twice (th = pi/2, 3 pi/2), of
 * speed sqrt(1 + sin^2 th). */
static long double apex_curve_speed(long double th)
{
    const long double s = sinl(th);
    return sqrtl(1 + s * s);
}

/* Its torsion at th: (c1 x c2) . c3 / |c1 x c2|^2, ck the k-th derivative. */
static double apex_curve_torsion(double th)
{
    const double d1[3] = {-sin(2 * th), cos(2 * th), -sin(th)};
    const double d2[3] = {-2 * cos(2 * th), -2 * sin(2 * th), -cos(th)};
    const double d3[3] = {4 * sin(2 * th), -4 * cos(2 * th), sin(th)};
    const double c[3] = {d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2],
                         d1[0] * d2[1] - d1[1] * d2[0]};
    return (c[0] * d3[0] + c[1] * d3[1] + c[2] * d3[2]) / (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
}

/* The largest relative error of the torsion over the curve's points (the
 * apex itself, where the frame is a limit, left out): th from cos th = z,
 * sin th = y / z. */
static double apex_torsion_error(const ic_trace_curve *c)
{
    double worst = 0;
    for (int i = 0; i < c->npoints; i++) {
        const ic_trace_point *p = &c->points[i];
        const double *x = p->xyz;
        if (!p->frame_defined || fabs(x[2]) < 1e-12)
            continue;
        const double tau = apex_curve_torsion(atan2(x[1] / x[2], x[2]));
        worst = fmax(worst, fabs(p->tau - tau) / fmax(1.0, fabs(tau)));
    }
    return worst;
}

/* IC_TRACE_SINGULAR_CLEARANCE: the curve points nearer the apex than the
 * clearance are dropped and the curve runs straight to the apex. At the
 * cone's apex the normal vanishes: the torsion of a point at d from it errs
 * by about eps (L/d)^3 (measured 1.4e-5 relative at d = 4e-4, 0.1 at
 * 4e-5), so 1e-3 admits no point nearer than about 1e-4 L; a straight cut
 * of a curve of curvature kappa over d shortens it by about kappa^2 d^3 / 24
 * at each of the four ends: 1.5e-3 L already costs 1e-7 of the length. */
static void test_cone_apex(void)
{
    static const double box[3][2] = {{-0.2, 1.2}, {-0.7, 0.7}, {-1.2, 1.2}};
    traced t;
    if (!trace_implicit(&t, "x^2 + y^2 - z^2", "(x - 0.5)^2 + y^2 - 0.25", box, 6)) {
        CHECK(0, "cone and cylinder: traced");
        return;
    }
    const double L = simpson_length(apex_curve_speed, 0, 2 * PI);
    const ic_trace_curve *c = ncurves(&t) == 1 ? ic_trace_result_curve(t.res, 0) : NULL;
    CHECK(c && c->closed && fabs(c->length - L) <= LENGTH_REL * L,
          "cone and cylinder: %d curves, the first closed %d of length %.17g (want one closed "
          "of %.17g)",
          ncurves(&t), c ? c->closed : -1, c ? c->length : 0.0, L);
    CHECK(npoints(&t) == 1 && ic_trace_result_special(t.res, 0)->type == IC_POINT_SURFACE_SINGULAR,
          "cone and cylinder: %d points (want the apex, surface-singular)", npoints(&t));
    if (c) {
        /* relative: see above */
        const double err = apex_torsion_error(c);
        CHECK(err <= 1e-3, "cone and cylinder: torsion off by %.3g relative near the apex", err);
    }
    CHECK(complete(&t), "cone and cylinder: complete (%s)", first_failure(&t));
    release(&t);
}

/* IC_TRACE_END_REACH: the saddle z = k (x^2 - y^2), k = 0.05, meets z = 0
 * in the lines y = x and y = -x, crossing at a branch point at the origin.
 * The normals' angle there grows as 2 k d with the distance d, so the
 * march stops about 1e-4 (3e-5 L) before the point; its locator must reach
 * that far (1e-4 L does, 1e-5 L does not: four ends left approximate). */
static void test_flat_branch_point(void)
{
    static const double box[3][2] = {{-1, 1}, {-1, 1}, {-1, 1}};
    traced t;
    if (!trace_implicit(&t, "z - 0.05*(x^2 - y^2)", "z", box, 6)) {
        CHECK(0, "flat saddle: traced");
        return;
    }
    CHECK(ncurves(&t) == 2, "flat saddle: %d curves (want the two diagonals)", ncurves(&t));
    for (int i = 0; i < ncurves(&t); i++) {
        const ic_trace_curve *c = ic_trace_result_curve(t.res, i);
        CHECK(fabs(c->length - 2 * sqrt(2.0)) <= LENGTH_REL * 2 * sqrt(2.0),
              "flat saddle: curve %d of length %.17g (want 2 sqrt 2)", i, c->length);
    }
    const ic_trace_special *p = npoints(&t) == 1 ? ic_trace_result_special(t.res, 0) : NULL;
    CHECK(p && p->type == IC_POINT_BRANCH && !p->approximate &&
              fmax(fmax(fabs(p->xyz[0]), fabs(p->xyz[1])), fabs(p->xyz[2])) <= 1e-12,
          "flat saddle: %d points (want the branch point at the origin, exact)", npoints(&t));
    CHECK(complete(&t), "flat saddle: complete (%s)", first_failure(&t));
    release(&t);
}

/* ---- poles and domain edges ---- */

/* A parametric patch over the domain given; NULL on failure. */
static ic_surface *patch(const char *const xyz[3], const double domain[2][2], const int per[2])
{
    ic_surface *s = NULL;
    if (ic_surface_new_parametric(&s, xyz, NULL, NULL, 0, NULL, NULL) != IC_OK)
        return NULL;
    if (ic_surface_set_domain(s, domain, per, NULL) != IC_OK) {
        ic_surface_free(s);
        return NULL;
    }
    return s;
}

/* The unit sphere as a patch, u the longitude (wrapping) and v the
 * latitude: the parametrization degenerates at its poles (0, 0, +-1). */
static ic_surface *unit_sphere(void)
{
    static const char *const xyz[3] = {"cos(u)*cos(v)", "sin(u)*cos(v)", "sin(v)"};
    static const double domain[2][2] = {{0, 2 * PI}, {-PI / 2, PI / 2}};
    static const int per[2] = {1, 0};
    return patch(xyz, domain, per);
}

/* A parametric surface A and the implicit formula fb traced with the
 * default options (the search over A's domain). */
static int trace_on_patch(traced *t, ic_surface *A, const char *fb)
{
    memset(t, 0, sizeof *t);
    t->A = A;
    ic_trace_options opt;
    ic_trace_defaults(&opt);
    ic_error err;
    ic_status st = A ? ic_surface_new_implicit(&t->B, fb, NULL, 0, &err) : IC_ERR_INVALID;
    if (st == IC_OK)
        st = ic_pair_new(&t->pair, t->A, t->B, &err);
    if (st == IC_OK)
        st = ic_trace(&t->res, t->pair, &opt, &err);
    if (st != IC_OK)
        fprintf(stderr, "trace on a patch / %s: %s\n", fb, A ? err.message : "no patch");
    return st == IC_OK;
}

/* IC_TRACE_APPROX_TANGENTIAL_ANGLE /10: the bead x^2 + y^2 + (z - 1.01)^2
 * = 0.01^2 rests on the unit sphere's pole: the centres are 1.01 apart,
 * the sum of the radii, so the two touch at (0, 0, 1) only, an isolated
 * contact (written (z - 1 - 0.01)^2 - 0.01^2, so that they touch in
 * doubles too: 1.01 rounded parts them by 1e-18). The locator refuses the
 * pole (no normal there): the point is classified pi 1e-6 beside it (1e-6
 * of the latitude's range), where the normals, tilting apart by
 * d (1 + 1/0.01) at a distance d, are 3.2e-4 apart: a contact within 1e-3,
 * a crossing beyond 1e-4. Its place is the search's Newton point, at most
 * 1e-10 (L + |x|) from the bead, which lies 50 d^2 from the sphere there:
 * d < 1e-5. */
static void test_contact_at_pole(void)
{
    traced t;
    if (!trace_on_patch(&t, unit_sphere(), "x^2 + y^2 + (z - 1 - 0.01)^2 - 0.01^2")) {
        CHECK(0, "a bead on the pole: traced");
        release(&t);
        return;
    }
    const ic_trace_special *p = npoints(&t) == 1 ? ic_trace_result_special(t.res, 0) : NULL;
    CHECK(ncurves(&t) == 0 && p && p->type == IC_POINT_ISOLATED_CONTACT &&
              hypot(hypot(p->xyz[0], p->xyz[1]), p->xyz[2] - 1) <= 1e-5,
          "a bead on the pole: %d curves, %d points (want the contact at the pole: %s)",
          ncurves(&t), npoints(&t), p ? ic_point_type_name(p->type) : "none");
    CHECK(complete(&t), "a bead on the pole: complete (%s)", first_failure(&t));
    release(&t);
}

/* IC_TRACE_APPROX_TANGENTIAL_ANGLE x10: the plane z = 1 + th x, th = 3e-3,
 * through the unit sphere's pole cuts it in the circle of radius
 * sin(atan th) = th / sqrt(1 + th^2) through the pole, crossing the sphere
 * at the constant angle atan th (cos of it: the plane's distance from the
 * centre) between the normals: no tangential point anywhere. The pole is
 * classified from beside it at about that angle: a crossing above 1e-3, a
 * contact (a point on the curve) below 1e-2. */
static void test_crossing_at_pole(void)
{
    const double th = 3e-3;
    traced t;
    if (!trace_on_patch(&t, unit_sphere(), "z - 1 - 3e-3*x")) {
        CHECK(0, "a plane through the pole: traced");
        release(&t);
        return;
    }
    const double rho = th / sqrt(1 + th * th);
    CHECK(ncurves(&t) == 1 && npoints(&t) == 0 && complete(&t),
          "a plane through the pole: %d curves, %d points, complete %d (want 1, 0, 1)", ncurves(&t),
          npoints(&t), complete(&t));
    if (ncurves(&t) == 1) {
        const ic_trace_curve *c = ic_trace_result_curve(t.res, 0);
        const double L = 2 * PI * rho;
        CHECK(c->closed && fabs(c->length - L) <= LENGTH_REL * L,
              "a plane through the pole: closed %d, length %.17g (want %.17g)", c->closed,
              c->length, L);
        double worst = 0;
        for (int i = 0; i < c->npoints; i++) {
            const double *x = c->points[i].xyz;
            worst = fmax(worst, fabs(sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) - 1));
            worst = fmax(worst, fabs(x[2] - 1 - th * x[0]));
        }
        CHECK(worst <= 1e-12, "a plane through the pole: a point %.3g off the surfaces", worst);
    }
    release(&t);
}

/* IC_TRACE_POLE_GAP_CHORDS x10: the sheet z = 0 over [-1, 1]^2 against
 * y ((x + 0.97)^2 + (y - 0.02)^2 - 0.005^2): the line y = 0 across the
 * sheet (length 2) and the circle of radius 0.005 about (-0.97, 0.02)
 * (length 0.01 pi), 0.031 to 0.041 from the line's end at (-1, 0, 0),
 * where it left the domain. A start point within the gap that the joining
 * bridges at a pole of such an end starts no curve: 50 chord heights
 * (0.010, L = 2.04 where the first search left the intersection) leave the
 * circle's start points, 500 (0.10) would drop them all. */
static void test_loop_beside_edge(void)
{
    static const char *const xyz[3] = {"u", "v", "0"};
    static const double domain[2][2] = {{-1, 1}, {-1, 1}};
    static const int per[2] = {0, 0};
    traced t;
    if (!trace_on_patch(&t, patch(xyz, domain, per), "y*((x + 0.97)^2 + (y - 0.02)^2 - 2.5e-5)")) {
        CHECK(0, "a loop beside an edge: traced");
        release(&t);
        return;
    }
    CHECK(ncurves(&t) == 2 && npoints(&t) == 0 && complete(&t),
          "a loop beside an edge: %d curves, %d points, complete %d (want 2, 0, 1)", ncurves(&t),
          npoints(&t), complete(&t));
    int line = 0, loop = 0;
    for (int i = 0; i < ncurves(&t); i++) {
        const ic_trace_curve *c = ic_trace_result_curve(t.res, i);
        line += !c->closed && fabs(c->length - 2) <= LENGTH_REL * 2;
        loop += c->closed && fabs(c->length - 0.01 * PI) <= LENGTH_REL * 0.01 * PI;
    }
    CHECK(line == 1 && loop == 1,
          "a loop beside an edge: %d lines of length 2, %d circles of length 0.01 pi (want 1, 1)",
          line, loop);
    release(&t);
}

/* ---- coincidence ---- */

/* IC_TRACE_COINCIDENT_TOL: z = a (x^2 + y^2) and z = 0 touch at the origin
 * (an isolated contact); at L/8 from it they are a L^2/64 apart, here
 * 10^-9.5 L with L = 1: a Morse contact, not a coincidence. The same plane
 * twice coincides. */
static void test_coincidence_tolerance(void)
{
    ic_surface *A = NULL, *B = NULL, *P = NULL;
    ic_pair *flat = NULL, *same = NULL;
    const double a = 64 * pow(10.0, -9.5);
    char f[80];
    snprintf(f, sizeof f, "z - %.17g*(x^2 + y^2)", a);
    const int ok = ic_surface_new_implicit(&A, f, NULL, 0, NULL) == IC_OK &&
                   ic_surface_new_implicit(&B, "z", NULL, 0, NULL) == IC_OK &&
                   ic_surface_new_implicit(&P, "z", NULL, 0, NULL) == IC_OK &&
                   ic_pair_new(&flat, A, B, NULL) == IC_OK && ic_pair_new(&same, P, B, NULL) == IC_OK;
    CHECK(ok, "coincidence: surfaces made");
    if (ok) {
        ic_local_point origin;
        memset(&origin, 0, sizeof origin);
        CHECK(!ic_trace_coincident_at(flat, &origin, 1.0),
              "z = %g (x^2 + y^2) against z = 0: taken for coincident", a);
        CHECK(ic_trace_coincident_at(same, &origin, 1.0), "the plane twice: not coincident");
    }
    ic_pair_free(flat);
    ic_pair_free(same);
    ic_surface_free(A);
    ic_surface_free(B);
    ic_surface_free(P);
}

/* IC_TRACE_COINCIDENT_REACH: the plane z = 0.25 given twice. The cells
 * within the reach of a point where the surfaces were found to coincide
 * are the coincident region, not refined: the trace takes 0.7 s (Debug).
 * With a tenth of the reach the cells between the coincident points are
 * refined and each new start point tested again: 380 s. Within a time
 * limit of 10 s (50 under AddressSanitizer, where it takes 2.6 s) the
 * region must be reported as such, not cut short. */
static void test_coincident_region(void)
{
    static const double box[3][2] = {{-1, 1}, {-1, 1}, {-1, 1}};
    ic_trace_options opt = box_options(box, 6);
    opt.time_limit = 10 * SLOWDOWN;
    traced t;
    if (!trace_with(&t, "z - 0.25", "z - 0.25", &opt)) {
        CHECK(0, "coincident planes: traced");
        return;
    }
    CHECK(ncurves(&t) == 0 && npoints(&t) == 0 && !complete(&t),
          "coincident planes: %d curves, %d points, complete %d (want 0, 0, 0)", ncurves(&t),
          npoints(&t), complete(&t));
    CHECK(failure_says(&t, "coincide") && !failure_says(&t, "time limit"),
          "coincident planes: the report says \"%s\" (want the coincident region, in time)",
          first_failure(&t));
    release(&t);
}

/* ---- the tangential locator and its place ---- */

/* The contact of order m of the graph z = H + (x - X0)^m + (y - Y0)^m with
 * the plane z = H, at (X0, Y0, H) by construction, in three pairings:
 * implicit/implicit, a parametric graph on an implicit plane, and two
 * parametric sheets (over (u, v) = (x, y)). */
#define X0 0.3
#define Y0 (-0.2)
#define H 0.1

static const double GRAPH_DOMAIN[2][2] = {{-2, 2}, {-2, 2}};

static ic_surface *parametric(const char *z)
{
    const char *xyz[3] = {"u", "v", z};
    const int per[2] = {0, 0};
    ic_surface *s = NULL;
    if (ic_surface_new_parametric(&s, xyz, NULL, NULL, 0, NULL, NULL) != IC_OK)
        return NULL;
    if (ic_surface_set_domain(s, GRAPH_DOMAIN, per, NULL) != IC_OK) {
        ic_surface_free(s);
        return NULL;
    }
    return s;
}

static ic_surface *implicit(const char *f)
{
    ic_surface *s = NULL;
    return ic_surface_new_implicit(&s, f, NULL, 0, NULL) == IC_OK ? s : NULL;
}

/* Surfaces A (the graph) and B (the plane) in the pairing; 0 on failure. */
static int contact_surfaces(int m, int pairing, ic_surface **A, ic_surface **B)
{
    char g[160];
    if (pairing == 0) {
        snprintf(g, sizeof g, "z - %g - (x - %g)^%d - (y - %g)^%d", H, X0, m, Y0, m);
        *A = implicit(g);
    } else {
        snprintf(g, sizeof g, "%g + (u - %g)^%d + (v - %g)^%d", H, X0, m, Y0, m);
        *A = parametric(g);
    }
    snprintf(g, sizeof g, pairing == 2 ? "%g" : "z - %g", H);
    *B = pairing == 2 ? parametric(g) : implicit(g);
    return *A && *B;
}

typedef struct {
    ic_status status;
    double dist;  /* from the true contact */
    double place; /* ic_local_tangential_place */
} located;

/* Locates from the point of the graph at (X0, Y0) + off dir (L = 1). */
static located locate_contact(ic_pair *pair, int m, double off, const double *dir)
{
    ic_local_options o;
    ic_local_defaults(&o);
    o.scale = 1.0;
    const double x = X0 + off * dir[0], y = Y0 + off * dir[1];
    ic_local_point near, pt;
    memset(&near, 0, sizeof near);
    near.xyz[0] = x, near.xyz[1] = y, near.xyz[2] = H + pow(x - X0, m) + pow(y - Y0, m);
    for (int s = 0; s < 2; s++)
        near.params[s][0] = x, near.params[s][1] = y;
    located r = {ic_local_locate_tangential(pair, &pt, &near, 1.0, &o, NULL), INFINITY, NAN};
    if (r.status != IC_OK)
        return r;
    r.dist = sqrt(pow(pt.xyz[0] - X0, 2) + pow(pt.xyz[1] - Y0, 2) + pow(pt.xyz[2] - H, 2));
    if (ic_local_tangential_place(pair, &pt, &o, &r.place, NULL) != IC_OK)
        r.place = NAN;
    return r;
}

/* relative (L = 1): where the located contact must be. The locator ends at
 * steps of 1e-15 of the unknowns (measured 8e-15 up to order 14); at order
 * 16, the highest the analysis reaches, the residual is flat (16 d^15 <
 * 1e-12 up to d = 0.13) and it ends within 1e-11 (measured 5.6e-12). */
static double locate_tol(int m) { return m <= 14 ? 1e-12 : 1e-10; }

/* The place radius is an estimate by decades of L, within a factor of
 * about 4 of the true distance (docs/tracing.md); it is at most 1e-4 L,
 * which says "not known". A simple point is known to a few units in the
 * last place of L (IC_TRACE_PLACE_ULPS assumes 16). */
#define PLACE_FACTOR 8.0
#define PLACE_UNKNOWN 1e-4
#define PLACE_SIMPLE_ULPS 16

static void check_place(const char *what, const located *r, int m)
{
    CHECK(r->place >= fmin(r->dist / PLACE_FACTOR, 0.99 * PLACE_UNKNOWN) - 16 * DBL_EPSILON,
          "%s: the place radius %.3g, but the point is %.3g from the contact", what, r->place,
          r->dist);
    if (m <= 4 && r->dist <= 1e-13)
        CHECK(r->place <= PLACE_SIMPLE_ULPS * DBL_EPSILON,
              "%s: a point located to %.3g, its place radius %.3g", what, r->dist, r->place);
}

/* Whether the start `off` away must end at the contact: its residual
 * (about m off^(m-1)) well above the locator's acceptance. */
static int must_converge(int m, double off)
{
    return m <= 4 ? off >= 1e-3 : m <= 8 ? off >= 1e-2 : off >= 0.075;
}

/* The contacts of order 2 to 16 in the three pairings, from four sides at
 * each distance: located (LOCATE_*), and their place honest and useful
 * (PLACE_*). At order 16 the locator may say it cannot converge. */
static void test_locator_contacts(void)
{
    static const double dirs[4][2] = {{1, 0.5}, {-0.3, 1}, {-1, -0.7}, {0.6, -1}};
    static const double near_offs[3] = {1e-2, 1e-3, 1e-4}, far_offs[3] = {0.3, 0.15, 0.075};
    for (int m = 2; m <= 16; m += 2)
        for (int pairing = 0; pairing < 3; pairing++) {
            ic_surface *A = NULL, *B = NULL;
            ic_pair *pair = NULL;
            const int ok = contact_surfaces(m, pairing, &A, &B) &&
                           ic_pair_new(&pair, A, B, NULL) == IC_OK;
            CHECK(ok, "contact of order %d, pairing %d: made", m, pairing);
            for (int i = 0; ok && i < 3; i++)
                for (int d = 0; d < 4; d++) {
                    const double off = m <= 8 ? near_offs[i] : far_offs[i];
                    char what[96];
                    snprintf(what, sizeof what, "order %d, pairing %d, from %g side %d", m,
                             pairing, off, d);
                    const located r = locate_contact(pair, m, off, dirs[d]);
                    if (must_converge(m, off))
                        CHECK((m == 16 && r.status == IC_ERR_UNABLE) || r.dist <= locate_tol(m),
                              "%s: located %.3g from the contact (status %d)", what, r.dist,
                              r.status);
                    if (r.status == IC_OK)
                        check_place(what, &r, m);
                }
            ic_pair_free(pair);
            ic_surface_free(A);
            ic_surface_free(B);
        }
}

/* LOCATE_ACCEPT: the sphere of radius 1/2 above the plane z = 0 with a gap
 * g: no common point (every residual vector has a component of at least
 * g/2: the distances to the two surfaces add up to g at best), so none is
 * located at g = 6e-12 (L = 1); at g = 0 the contact is. */
static void test_locator_hovering(void)
{
    static const char *const spheres[2] = {"x^2 + y^2 + (z - 0.500000000006)^2 - 0.25",
                                           "x^2 + y^2 + (z - 0.5)^2 - 0.25"};
    for (int touching = 0; touching < 2; touching++) {
        ic_surface *A = implicit(spheres[touching]), *B = implicit("z");
        ic_pair *pair = NULL;
        ic_local_options o;
        ic_local_defaults(&o);
        ic_local_point near, pt;
        memset(&near, 0, sizeof near);
        memset(&pt, 0, sizeof pt);
        near.xyz[0] = 1e-3, near.xyz[1] = 2e-3;
        ic_status st = IC_ERR_INVALID;
        if (A && B && ic_pair_new(&pair, A, B, NULL) == IC_OK)
            st = ic_local_locate_tangential(pair, &pt, &near, 1.0, &o, NULL);
        if (touching)
            CHECK(st == IC_OK && fabs(pt.xyz[0]) + fabs(pt.xyz[1]) + fabs(pt.xyz[2]) <= 1e-15,
                  "the touching sphere: status %d", st);
        else
            CHECK(st == IC_ERR_UNABLE, "a sphere 6e-12 above the plane: status %d, at (%g, %g, %g)",
                  st, pt.xyz[0], pt.xyz[1], pt.xyz[2]);
        ic_pair_free(pair);
        ic_surface_free(A);
        ic_surface_free(B);
    }
}

/* The graph z = h + (x - X0)^m touches the plane z = h along the line
 * x = X0 (a tangential curve, of contact order m): located from beside it,
 * the point is on the line and not carried along it (the locator does not
 * follow a tangential curve). LOCATE_MAX_ITERATIONS: at order 8 and h = 0
 * the lengthened steps need 16 to 20 iterations (10 leave it 9e-6 off). */
static void check_line(int m, int pairing, double h)
{
    static const double offs[3] = {1e-2, 3e-2, 1e-1};
    char g[120], p[40];
    if (pairing == 0)
        snprintf(g, sizeof g, "z - %g - (x - %g)^%d", h, X0, m);
    else
        snprintf(g, sizeof g, "%g + (u - %g)^%d", h, X0, m);
    snprintf(p, sizeof p, pairing == 2 ? "%g" : "z - %g", h);
    ic_surface *A = pairing == 0 ? implicit(g) : parametric(g);
    ic_surface *B = pairing == 2 ? parametric(p) : implicit(p);
    ic_pair *pair = NULL;
    const int ok = A && B && ic_pair_new(&pair, A, B, NULL) == IC_OK;
    CHECK(ok, "line of order %d, pairing %d: made", m, pairing);
    for (int i = 0; ok && i < 3; i++) {
        ic_local_options o;
        ic_local_defaults(&o);
        ic_local_point near, pt;
        memset(&near, 0, sizeof near);
        memset(&pt, 0, sizeof pt);
        const double x = X0 + offs[i], y = Y0;
        near.xyz[0] = x, near.xyz[1] = y, near.xyz[2] = h + pow(offs[i], m);
        for (int s = 0; s < 2; s++)
            near.params[s][0] = x, near.params[s][1] = y;
        const ic_status st = ic_local_locate_tangential(pair, &pt, &near, 1.0, &o, NULL);
        /* on the line to the locator's 1e-12; along it, not moved farther
         * than the start was from it */
        CHECK(st == IC_OK && hypot(pt.xyz[0] - X0, pt.xyz[2] - h) <= 1e-12 &&
                  fabs(pt.xyz[1] - y) <= offs[i],
              "line of order %d at height %g, pairing %d, from %g: status %d at (%.17g, %.17g, "
              "%.17g)",
              m, h, pairing, offs[i], st, pt.xyz[0], pt.xyz[1], pt.xyz[2]);
    }
    ic_pair_free(pair);
    ic_surface_free(A);
    ic_surface_free(B);
}

static void test_locator_lines(void)
{
    for (int m = 2; m <= 8; m += 2)
        for (int pairing = 0; pairing < 3; pairing++) {
            check_line(m, pairing, 0.0);
            check_line(m, pairing, H);
        }
}

/* LOCATE_PLAIN_ITERATIONS: the sphere of radius 1/2 on the plane z = 0,
 * located from its points up to 0.45 from the contact (plain Gauss-Newton
 * needs more than 4 steps from there). */
static void test_locator_far(void)
{
    ic_surface *A = implicit("x^2 + y^2 + (z - 0.5)^2 - 0.25"), *B = implicit("z");
    ic_pair *pair = NULL;
    const int ok = A && B && ic_pair_new(&pair, A, B, NULL) == IC_OK;
    CHECK(ok, "sphere on a plane: made");
    static const double offs[4] = {0.1, 0.2, 0.3, 0.45};
    for (int i = 0; ok && i < 4; i++) {
        ic_local_options o;
        ic_local_defaults(&o);
        ic_local_point near, pt;
        memset(&near, 0, sizeof near);
        memset(&pt, 0, sizeof pt);
        const double x = 0.8 * offs[i], y = 0.6 * offs[i];
        near.xyz[0] = x, near.xyz[1] = y, near.xyz[2] = 0.5 - sqrt(0.25 - x * x - y * y);
        const ic_status st = ic_local_locate_tangential(pair, &pt, &near, 1.0, &o, NULL);
        CHECK(st == IC_OK && fabs(pt.xyz[0]) + fabs(pt.xyz[1]) + fabs(pt.xyz[2]) <= 1e-15,
              "sphere on a plane from %g: status %d at (%g, %g, %g)", offs[i], st, pt.xyz[0],
              pt.xyz[1], pt.xyz[2]);
    }
    ic_pair_free(pair);
    ic_surface_free(A);
    ic_surface_free(B);
}

int main(void)
{
    test_cell_budget();
    test_refinement_depth();
    test_loop_beside_contact();
    test_undecided_regions();
    test_close_branches();
    test_cone_apex();
    test_flat_branch_point();
    test_contact_at_pole();
    test_crossing_at_pole();
    test_loop_beside_edge();
    test_coincidence_tolerance();
    test_coincident_region();
    test_locator_contacts();
    test_locator_hovering();
    test_locator_lines();
    test_locator_far();
    return harness_finish("constants");
}
