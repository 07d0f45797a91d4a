/* Robustness of the whole-intersection tracer (issue 5): the same curves
 * across tolerances 1e-6 .. 1e-12, after reparametrising a surface
 * (u -> u^3 + u), and after shifting a periodic domain or the box. Truth:
 * Viviani's figure-eight (twice the Simpson lobe) and the Enneper double
 * curves (Simpson of |c'| between w = +-sqrt(22/3)), tests/curve_lengths.h. */
#include <stdio.h>
#include <string.h>

#include "curve_lengths.h"
#include "harness.h"
#include "intercurve.h"
#include "traced_pair.h"


static int total_points(const ic_trace_result *r)
{
    int n = 0;
    for (int i = 0; i < ic_trace_result_num_curves(r); i++)
        n += ic_trace_result_curve(r, i)->npoints;
    return n;
}

/* The relative bound on lengths (TIER_LENGTH), at every tolerance
 * from 1e-6 to 1e-12 (measured worst 8e-10: Enneper at tol 1e-6). */
static double length_bound(double L) { return TIER_LENGTH * L; }

/* Viviani's figure-eight, traced from an implicit cylinder and sphere in a
 * box, or with a parametric cylinder (z = zf(v1), v2 periodic on dom2). */
static ic_status viviani(traced *t, const char *zf, const double dom[2][2], const double box[3][2],
                         double tol)
{
    ic_trace_options opt;
    ic_trace_defaults(&opt);
    opt.tol = tol;
    ic_error err;
    memset(t, 0, sizeof *t);
    ic_status st;
    if (zf) {
        const char *cyl[3] = {"1 + sin(v)", "cos(v)", zf};
        const int per[2] = {0, 1};
        st = ic_surface_new_parametric(&t->A, cyl, NULL, NULL, 0, NULL, &err);
        if (st == IC_OK)
            st = ic_surface_set_domain(t->A, dom, per, &err);
    } else {
        st = ic_surface_new_implicit(&t->A, "(x - 1)^2 + y^2 - 1", NULL, 0, &err);
        opt.has_box = 1;
        memcpy(opt.box, box, sizeof opt.box);
    }
    if (st == IC_OK)
        st = ic_surface_new_implicit(&t->B, "x^2 + y^2 + z^2 - 4", NULL, 0, &err);
    if (st == IC_OK)
        st = ic_pair_new(&t->pair, t->A, t->B, &err);
    if (st == IC_OK)
        st = ic_trace(&t->res, t->pair, &opt, &err);
    CHECK(st == IC_OK, "Viviani: %s", err.message);
    return st;
}

/* One closed curve of the figure-eight's length, one branch point at (2, 0, 0). */
static void check_viviani(const traced *t, const char *what)
{
    const double L = 2 * viviani_lobe();
    const ic_trace_result *r = t->res;
    if (!r)
        return;
    const int one = ic_trace_result_num_curves(r) == 1 && ic_trace_result_num_specials(r) == 1;
    CHECK(one, "%s: %d curves, %d points (one figure-eight, one branch point)", what,
          ic_trace_result_num_curves(r), ic_trace_result_num_specials(r));
    if (!one)
        return;
    const ic_trace_curve *c = ic_trace_result_curve(r, 0);
    const ic_trace_special *sp = ic_trace_result_special(r, 0);
    const double err = fabs(c->length - L);
    CHECK(c->closed && err <= length_bound(L), "%s: length %.17g of %.17g", what, c->length, L);
    /* the branch point solves N_A x N_B = 0 to 1e-12 (linear in the offset) */
    CHECK(sp->type == IC_POINT_BRANCH &&
              hypot(hypot(sp->xyz[0] - 2, sp->xyz[1]), sp->xyz[2]) <= TIER_LOCATED,
          "%s: the branch point (2, 0, 0)", what);
    printf("%-44s %5d points, length error %.2g\n", what, c->npoints, err / L);
}

static void test_tolerances(void)
{
    const double box[3][2] = {{-2.5, 2.5}, {-2.5, 2.5}, {-2.5, 2.5}};
    const double tols[4] = {1e-10, 1e-11, 1e-12, 1e-13};
    for (int k = 0; k < 4; k++) {
        traced t;
        char what[64];
        snprintf(what, sizeof what, "Viviani implicit, tol %g", tols[k]);
        if (viviani(&t, NULL, NULL, box, tols[k]) == IC_OK)
            check_viviani(&t, what);
        release(&t);
    }
    /* Enneper's two double curves at every tolerance */
    const char *enn[3] = {"u - u^3/3 + u*v^2", "-v - u^2*v + v^3/3", "u^2 - v^2"};
    const double dom[2][2] = {{-5, 5}, {-5, 5}};
    const double a = sqrt(22.0 / 3), L = enneper_arc(-a, a);
    for (int k = 0; k < 4; k++) {
        traced t;
        memset(&t, 0, sizeof t);
        ic_trace_options opt;
        ic_trace_defaults(&opt);
        opt.tol = tols[k];
        ic_error err;
        if (!REQUIRE(ic_surface_new_parametric(&t.A, enn, NULL, NULL, 0, NULL, &err) == IC_OK &&
                         ic_surface_set_domain(t.A, dom, NULL, &err) == IC_OK &&
                         ic_pair_new(&t.pair, t.A, NULL, &err) == IC_OK &&
                         ic_trace(&t.res, t.pair, &opt, &err) == IC_OK,
                     "Enneper at tol %g traced: %s", tols[k], err.message)) {
            release(&t);
            continue;
        }
        CHECK(ic_trace_result_num_curves(t.res) == 2, "Enneper at tol %g: two curves", tols[k]);
        double worst = 0;
        for (int i = 0; i < ic_trace_result_num_curves(t.res); i++) {
            const ic_trace_curve *c = ic_trace_result_curve(t.res, i);
            worst = fmax(worst, fabs(c->length - L));
            CHECK(fabs(c->length - L) <= length_bound(L),
                  "Enneper at tol %g: length %.17g of %.17g", tols[k], c->length, L);
        }
        printf("Enneper self-intersection, tol %-14g %5d points, length error %.2g\n", tols[k],
               total_points(t.res), worst / L);
        release(&t);
    }
}

static void test_reparametrised_and_shifted(void)
{
    const double pi = 3.141592653589793;
    const double box[3][2] = {{-2.5, 2.5}, {-2.5, 2.5}, {-2.5, 2.5}};
    const double shifted[3][2] = {{-2.3, 2.7}, {-2.4, 2.6}, {-2.2, 2.8}};
    /* u -> u^3 + u stretches the height unevenly: z in [-2.5, 2.5] needs
     * u in about [-1.19, 1.19] */
    const double plain[2][2] = {{-2.5, 2.5}, {0, 2 * pi}};
    const double cubic[2][2] = {{-1.3, 1.3}, {0, 2 * pi}};
    const double turned[2][2] = {{-2.5, 2.5}, {1, 1 + 2 * pi}};
    const double both[2][2] = {{-1.4, 1.2}, {-2, 2 * pi - 2}};
    struct {
        const char *what, *zf;
        const double (*dom)[2], (*box)[2];
    } cases[] = {
        {"Viviani, parametric cylinder", "u", plain, NULL},
        {"Viviani, cylinder height u^3 + u", "u^3 + u", cubic, NULL},
        {"Viviani, periodic domain shifted by 1", "u", turned, NULL},
        {"Viviani, u^3 + u and both domains shifted", "u^3 + u", both, NULL},
        {"Viviani implicit, box shifted", NULL, NULL, shifted},
        {"Viviani implicit, box centred", NULL, NULL, box},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        traced t;
        if (viviani(&t, cases[i].zf, cases[i].dom, cases[i].box, 1e-10) == IC_OK)
            check_viviani(&t, cases[i].what);
        release(&t);
    }
}

/* A step budget hit ends the curve with "budget" and says so in the report. */
static void test_budget(void)
{
    traced t;
    memset(&t, 0, sizeof t);
    ic_trace_options opt;
    ic_trace_defaults(&opt);
    opt.max_points = 20;
    opt.has_box = 1;
    for (int k = 0; k < 3; k++)
        opt.box[k][0] = -3, opt.box[k][1] = 3;
    ic_error err;
    if (!REQUIRE(ic_surface_new_implicit(&t.A, "x^2 + y^2 + z^2 - 4", NULL, 0, &err) == IC_OK &&
                     ic_surface_new_implicit(&t.B, "z - 1", NULL, 0, &err) == IC_OK &&
                     ic_pair_new(&t.pair, t.A, t.B, &err) == IC_OK &&
                     ic_trace(&t.res, t.pair, &opt, &err) == IC_OK,
                 "budget case traced: %s", err.message)) {
        release(&t);
        return;
    }
    const ic_trace_report *rep = ic_trace_result_report(t.res);
    const ic_trace_curve *c =
        ic_trace_result_num_curves(t.res) >= 1 ? ic_trace_result_curve(t.res, 0) : NULL;
    CHECK(c && !c->closed && c->ends[0] == IC_TRACE_BUDGET && c->ends[1] == IC_TRACE_BUDGET &&
              rep->nfailures > 0 && strstr(rep->failures[0], "budget of 20 points"),
          "the budget is visible: %s", rep->nfailures ? rep->failures[0] : "no failure listed");
    release(&t);
}

int main(void)
{
    test_budget();
    test_tolerances();
    test_reparametrised_and_shifted();
    return harness_finish("test_trace_robust");
}
