/* Surfaces: derivatives against sympy truth (tests/truth/surface_truth.txt),
 * primitives against their formula forms, principal curvatures in closed
 * form, degenerate points, callbacks and composition. */
#include <stdio.h>
#include <string.h>

#include "harness.h"
#include "intercurve/surface.h"
#include "surface/surface_jets.h"

#define ORDER 6

static double worst_deriv;

static void compare_derivs(const char *name, ic_surface *s, const double *at, int nout,
                           double want[][3], const ic_jet_space *sp)
{
    const int n = ic_jet_space_len(sp);
    double got[3 * 84];
    ic_error err;
    ic_status st = ic_surface_taylor(s, got, at, sp, &err);
    CHECK(st == IC_OK, "%s: taylor failed: %s", name, err.message);
    if (st != IC_OK)
        return;
    for (int d = 0; d <= ORDER; d++) {
        double scale = 1.0;
        for (int i = ic_jet_degree_start(sp, d); i < ic_jet_degree_start(sp, d + 1); i++)
            for (int k = 0; k < nout; k++)
                scale = fmax(scale, fabs(want[i][k]));
        for (int i = ic_jet_degree_start(sp, d); i < ic_jet_degree_start(sp, d + 1); i++)
            for (int k = 0; k < nout; k++) {
                const double g = got[k * n + i] * ic_jet_factorial(sp, i);
                const double e = fabs(g - want[i][k]) / scale;
                worst_deriv = fmax(worst_deriv, e / DBL_EPSILON);
                CHECK(e <= TIER_DERIVATIVE, "%s: derivative %d component %d: got %.17g want %.17g",
                      name, i, k, g, want[i][k]);
            }
    }
}

/* A malformed truth file: a failed check saying where; returns -1. */
static int bad_truth(const char *path, const char *case_name, const char *what)
{
    CHECK(0, "%s, case %s: %s", path, case_name, what);
    return -1;
}

/* One case of the truth file (kind and name read): its formula, point and
 * derivatives, compared with the surface's. 0, or -1 on a malformed case. */
static int truth_case(FILE *f, const char *path, const char *kind, const char *name,
                      const ic_jet_space *s2, const ic_jet_space *s3)
{
    char line[4096];
    const int parametric = strcmp(kind, "parametric") == 0;
    const ic_jet_space *sp = parametric ? s2 : s3;
    const int n = ic_jet_space_len(sp), nout = parametric ? 3 : 1;
    char formula[1024];
    if (!fgets(line, sizeof line, f) || strncmp(line, "formula ", 8) != 0)
        return bad_truth(path, name, "no formula line");
    snprintf(formula, sizeof formula, "%s", line + 8);
    formula[strcspn(formula, "\n")] = '\0';
    double at[3];
    if (!fgets(line, sizeof line, f) ||
        sscanf(line, "at %lf %lf %lf", &at[0], &at[1], &at[2]) < (parametric ? 2 : 3))
        return bad_truth(path, name, "no point line");
    double want[84][3];
    for (int i = 0; i < n; i++) {
        int e[3];
        if (!fgets(line, sizeof line, f))
            return bad_truth(path, name, "fewer derivatives than the space holds");
        if (parametric ? sscanf(line, "d %d %d %lf %lf %lf", &e[0], &e[1], &want[i][0],
                                &want[i][1], &want[i][2]) != 5
                       : sscanf(line, "d %d %d %d %lf", &e[0], &e[1], &e[2], &want[i][0]) != 4)
            return bad_truth(path, name, "a malformed derivative line");
        CHECK(ic_jet_index(sp, e) == i, "%s: monomial order of the truth file", name);
    }
    ic_surface *s = NULL;
    ic_error err;
    ic_status st;
    if (parametric) {
        char *parts[3], *save = NULL;
        parts[0] = strtok_r(formula, ";", &save);
        parts[1] = strtok_r(NULL, ";", &save);
        parts[2] = strtok_r(NULL, ";", &save);
        const char *xyz[3] = {parts[0], parts[1], parts[2]};
        st = ic_surface_new_parametric(&s, xyz, NULL, NULL, 0, NULL, &err);
    } else {
        st = ic_surface_new_implicit(&s, formula, NULL, 0, &err);
    }
    CHECK(st == IC_OK, "%s compiles: %s", name, err.message);
    if (st == IC_OK)
        compare_derivs(name, s, at, nout, want, sp);
    ic_surface_free(s);
    return 0;
}

/* Every case of the truth file; returns the number read, -1 (a failed
 * check) when the file cannot be read. */
static int test_truth_file(const char *path)
{
    FILE *f = fopen(path, "r");
    if (!REQUIRE(f != NULL, "cannot open %s", path))
        return -1;
    ic_jet_space *s2 = NULL, *s3 = NULL;
    char line[4096], kind[32], name[64];
    int cases = 0;
    if (!REQUIRE(ic_jet_space_new(&s2, 2, ORDER, NULL) == IC_OK &&
                     ic_jet_space_new(&s3, 3, ORDER, NULL) == IC_OK,
                 "the jet spaces of order %d", ORDER))
        cases = -1;
    else if (!fgets(line, sizeof line, f))
        cases = bad_truth(path, "(header)", "empty file");
    while (cases >= 0 && fgets(line, sizeof line, f) && strncmp(line, "end", 3) != 0) {
        if (sscanf(line, "%31s %63s", kind, name) != 2)
            cases = bad_truth(path, "(next)", "no 'kind name' line");
        else if (truth_case(f, path, kind, name, s2, s3) != 0)
            cases = -1;
        else
            cases++;
    }
    fclose(f);
    ic_jet_space_free(s2);
    ic_jet_space_free(s3);
    return cases;
}

/* The enclosures of a parametric primitive p over random (u, v) boxes hold
 * its values and first derivatives at points sampled in the box (beyond a
 * slack of 8 eps of the magnitude: the samples are rounded, the enclosure
 * is of the exact values), and are no wider than twice those of the same
 * surface written as formulas, q (same operations, so the same widths up to
 * the order of the products). */
static void check_param_intervals(int i, ic_surface *p, ic_surface *q, const ic_jet_space *s1,
                                  harness_rng *rng)
{
    int outside = 0, wide = 0;
    for (int trial = 0; trial < 40; trial++) {
        const double w = pow(10.0, harness_uniform(rng, -4, 0));
        ic_interval box[2];
        for (int k = 0; k < 2; k++) {
            const double lo = harness_uniform(rng, -3.0, 3.0);
            box[k] = (ic_interval){lo, lo + w};
        }
        ic_interval_grad gp[3], gq[3];
        if (ic_surface_eval_interval_grad(p, gp, box, NULL) != IC_OK ||
            ic_surface_eval_interval_grad(q, gq, box, NULL) != IC_OK) {
            outside++;
            continue;
        }
        for (int k = 0; k < 3; k++)
            for (int d = -1; d < 2; d++) {
                const ic_interval a = d < 0 ? gp[k].v : gp[k].d[d];
                const ic_interval b = d < 0 ? gq[k].v : gq[k].d[d];
                if (a.hi - a.lo > 2 * (b.hi - b.lo) + 1e-15)
                    wide++;
            }
        for (int sample = 0; sample < 20; sample++) {
            const double at[2] = {harness_uniform(rng, box[0].lo, box[0].hi),
                                  harness_uniform(rng, box[1].lo, box[1].hi)};
            double t[3 * 3]; /* value, d/du, d/dv of x, y, z */
            if (ic_surface_taylor(p, t, at, s1, NULL) != IC_OK) {
                outside++;
                continue;
            }
            for (int k = 0; k < 3; k++)
                for (int d = 0; d < 3; d++) {
                    const double x = t[3 * k + d];
                    const ic_interval a = d == 0 ? gp[k].v : gp[k].d[d - 1];
                    const double slack = 8 * DBL_EPSILON * (1 + fabs(x));
                    if (x < a.lo - slack || x > a.hi + slack)
                        outside++;
                }
        }
    }
    CHECK(outside == 0, "parametric primitive %d: %d samples outside its enclosures", i, outside);
    CHECK(wide == 0, "parametric primitive %d: %d enclosures wider than the formula's", i, wide);
}

/* Each primitive against the same surface written as formulas. */
static void test_primitives_match_formulas(harness_rng *rng)
{
    ic_primitive prims[6];
    memset(prims, 0, sizeof prims);
    const double c[3] = {0.3, -1.2, 0.7};
    for (int i = 0; i < 6; i++)
        memcpy(prims[i].center, c, sizeof c);
    prims[0].kind = IC_PRIM_PLANE;
    prims[0].normal[0] = 0.0, prims[0].normal[1] = 0.0, prims[0].normal[2] = 2.0;
    prims[1].kind = IC_PRIM_SPHERE, prims[1].radius = 2.5;
    prims[2].kind = IC_PRIM_CYLINDER, prims[2].radius = 1.5;
    prims[3].kind = IC_PRIM_CONE, prims[3].half_angle = 0.4;
    prims[4].kind = IC_PRIM_TORUS, prims[4].major_radius = 2.0, prims[4].radius = 0.5;
    prims[5].kind = IC_PRIM_ELLIPSOID;
    prims[5].axes[0] = 1.5, prims[5].axes[1] = 0.8, prims[5].axes[2] = 1.1;
    const char *par[6][3] = {
        {"0.3 + u", "-1.2 + v", "0.7"}, /* plane with normal +z: e1 = x, e2 = y */
        {"0.3 + 2.5*cos(u)*cos(v)", "-1.2 + 2.5*sin(u)*cos(v)", "0.7 + 2.5*sin(v)"},
        {"0.3 + 1.5*cos(u)", "-1.2 + 1.5*sin(u)", "0.7 + v"},
        {"0.3 + v*tan(0.4)*cos(u)", "-1.2 + v*tan(0.4)*sin(u)", "0.7 + v"},
        {"0.3 + (2 + 0.5*cos(v))*cos(u)", "-1.2 + (2 + 0.5*cos(v))*sin(u)", "0.7 + 0.5*sin(v)"},
        {"0.3 + 1.5*cos(u)*cos(v)", "-1.2 + 0.8*sin(u)*cos(v)", "0.7 + 1.1*sin(v)"},
    };
    const char *imp[6] = {
        "2*(z - 0.7)",
        "(x-0.3)^2 + (y+1.2)^2 + (z-0.7)^2 - 6.25",
        "(x-0.3)^2 + (y+1.2)^2 - 2.25",
        "(x-0.3)^2 + (y+1.2)^2 - tan(0.4)^2*(z-0.7)^2",
        "((x-0.3)^2 + (y+1.2)^2 + (z-0.7)^2 + 3.75)^2 - 16*((x-0.3)^2 + (y+1.2)^2)",
        "(x-0.3)^2/2.25 + (y+1.2)^2/0.64 + (z-0.7)^2/1.21 - 1",
    };
    ic_jet_space *s2 = NULL, *s3 = NULL, *s1 = NULL, *first = NULL;
    if (!REQUIRE(ic_jet_space_new(&s2, 2, ORDER, NULL) == IC_OK &&
                     ic_jet_space_new(&s3, 3, ORDER, NULL) == IC_OK &&
                     ic_jet_space_new(&s1, 1, 12, NULL) == IC_OK &&
                     ic_jet_space_new(&first, 2, 1, NULL) == IC_OK,
                 "the jet spaces of the primitives' test"))
        goto done;
    for (int i = 0; i < 6; i++) {
        for (int form = 0; form < 2; form++) {
            ic_surface *p = NULL, *q = NULL;
            ic_error err;
            CHECK(ic_surface_new_primitive(&p, &prims[i], form ? IC_IMPLICIT : IC_PARAMETRIC,
                                           &err) == IC_OK,
                  "primitive %d: %s", i, err.message);
            if (form)
                CHECK(ic_surface_new_implicit(&q, imp[i], NULL, 0, &err) == IC_OK, "%s", err.message);
            else
                CHECK(ic_surface_new_parametric(&q, par[i], NULL, NULL, 0, NULL, &err) == IC_OK,
                      "%s", err.message);
            if (!p || !q) {
                ic_surface_free(p);
                ic_surface_free(q);
                continue;
            }
            const ic_jet_space *sp = form ? s3 : s2;
            const int n = ic_jet_space_len(sp), nout = form ? 1 : 3;
            if (!form)
                check_param_intervals(i, p, q, first, rng);
            for (int trial = 0; trial < 10; trial++) {
                double at[3], a[3 * 84], b[3 * 84];
                for (int k = 0; k < 3; k++)
                    at[k] = harness_uniform(rng, -1.4, 1.4);
                CHECK(ic_surface_taylor(p, a, at, sp, NULL) == IC_OK &&
                          ic_surface_taylor(q, b, at, sp, NULL) == IC_OK,
                      "taylor of primitive %d", i);
                double worst = 0.0, scale = 1.0;
                for (int k = 0; k < nout * n; k++)
                    scale = fmax(scale, fabs(b[k]));
                for (int k = 0; k < nout * n; k++)
                    worst = fmax(worst, fabs(a[k] - b[k]));
                /* closed form vs recurrences: both within a few ulps of
                 * the coefficients' scale */
                CHECK(worst <= TIER_DERIVATIVE * scale, "primitive %d form %d vs formula: %g",
                      i, form, worst / scale);
            }
            /* composition with a curve jet: primitives use jet arithmetic */
            {
                double curve[3][13] = {{0}}, a[39], b[39];
                for (int k = 0; k < 3; k++) {
                    curve[k][0] = harness_uniform(rng, -1.4, 1.4);
                    curve[k][1] = harness_uniform(rng, -1.0, 1.0);
                    curve[k][2] = harness_uniform(rng, -0.5, 0.5);
                }
                const double *in[3] = {curve[0], curve[1], curve[2]};
                CHECK(ic_surface_compose(p, a, in, s1, NULL) == IC_OK &&
                          ic_surface_compose(q, b, in, s1, NULL) == IC_OK,
                      "compose primitive %d", i);
                double worst = 0.0, scale = 1.0;
                for (int k = 0; k < 13 * nout; k++) {
                    worst = fmax(worst, fabs(a[k] - b[k]));
                    scale = fmax(scale, fabs(b[k]));
                }
                CHECK(worst <= TIER_DERIVATIVE * scale,
                      "primitive %d form %d composed vs formula: %g", i, form, worst / scale);
            }
            ic_surface_free(p);
            ic_surface_free(q);
        }
    }
done:
    ic_jet_space_free(s1);
    ic_jet_space_free(first);
    ic_jet_space_free(s2);
    ic_jet_space_free(s3);
}

static ic_surface *primitive(ic_primitive_kind kind, ic_surface_kind form, double r, double R)
{
    ic_primitive p;
    memset(&p, 0, sizeof p);
    p.kind = kind;
    p.radius = r;
    p.major_radius = R;
    p.half_angle = 0.5;
    ic_surface *s = NULL;
    ic_error err;
    return REQUIRE(ic_surface_new_primitive(&s, &p, form, &err) == IC_OK, "primitive %d: %s",
                   (int)kind, err.message)
               ? s
               : NULL;
}

/* Principal curvatures in closed form (outward normals: -1/r on a sphere). */
static void test_principal_curvatures(void)
{
    const double tier = TIER_ROUNDING; /* a few roundings of O(1) values */
    ic_surface_geometry g;
    ic_surface *s = primitive(IC_PRIM_SPHERE, IC_PARAMETRIC, 2.5, 0);
    if (!s)
        return;
    const double uv[2] = {0.3, 0.4};
    CHECK(ic_surface_geometry_at(s, &g, uv, NULL) == IC_OK, "sphere geometry");
    CHECK_ABS(g.principal_curvatures[0], -0.4, tier, "sphere k1");
    CHECK_ABS(g.principal_curvatures[1], -0.4, tier, "sphere k2");
    CHECK_ABS(g.gauss, 0.16, tier, "sphere K");
    const double pole[2] = {0.3, 1.5707963267948966};
    ic_error err;
    CHECK(ic_surface_geometry_at(s, &g, pole, &err) == IC_ERR_DOMAIN &&
              strstr(err.message, "degenerate"),
          "sphere pole is degenerate: %s", err.message);
    ic_surface_free(s);

    s = primitive(IC_PRIM_SPHERE, IC_IMPLICIT, 2.5, 0);
    if (!s)
        return;
    const double p[3] = {1.5, 2.0, 0.0};
    CHECK(ic_surface_geometry_at(s, &g, p, NULL) == IC_OK, "implicit sphere");
    CHECK_ABS(g.principal_curvatures[0], -0.4, tier, "implicit sphere k1");
    CHECK_ABS(g.principal_curvatures[1], -0.4, tier, "implicit sphere k2");
    CHECK_ABS(g.normal[0], 0.6, tier, "outward normal");
    ic_surface_free(s);

    s = primitive(IC_PRIM_CYLINDER, IC_PARAMETRIC, 1.5, 0);
    if (!s)
        return;
    CHECK(ic_surface_geometry_at(s, &g, uv, NULL) == IC_OK, "cylinder");
    CHECK_ABS(g.principal_curvatures[0], 0.0, tier, "cylinder k1");
    CHECK_ABS(g.principal_curvatures[1], -1.0 / 1.5, tier, "cylinder k2");
    CHECK_ABS(fabs(g.principal_directions[0][2]), 1.0, tier, "cylinder: k1 along the axis");
    ic_surface_free(s);

    s = primitive(IC_PRIM_CYLINDER, IC_IMPLICIT, 1.5, 0);
    if (!s)
        return;
    const double q[3] = {0.9, 1.2, 7.0};
    CHECK(ic_surface_geometry_at(s, &g, q, NULL) == IC_OK, "implicit cylinder");
    CHECK_ABS(g.principal_curvatures[0], 0.0, tier, "implicit cylinder k1");
    CHECK_ABS(g.principal_curvatures[1], -1.0 / 1.5, tier, "implicit cylinder k2");
    ic_surface_free(s);

    /* torus R = 2, r = 0.5 at v: -1/r along meridians, -cos v/(R + r cos v) */
    for (int form = 0; form < 2; form++) {
        s = primitive(IC_PRIM_TORUS, form ? IC_IMPLICIT : IC_PARAMETRIC, 0.5, 2.0);
        if (!s)
            return;
        const double u = 0.7, v = 2.3;
        const double at_uv[2] = {u, v};
        const double w = 2.0 + 0.5 * cos(v);
        const double at_xyz[3] = {w * cos(u), w * sin(u), 0.5 * sin(v)};
        CHECK(ic_surface_geometry_at(s, &g, form ? at_xyz : at_uv, NULL) == IC_OK, "torus");
        const double ka = -2.0, kb = -cos(v) / w;
        /* twice the tier: -cos v/(R + r cos v) takes more operations than
         * the sphere's and the cylinder's curvatures */
        CHECK_ABS(g.principal_curvatures[0], fmax(ka, kb), 2 * TIER_ROUNDING, "torus k1");
        CHECK_ABS(g.principal_curvatures[1], fmin(ka, kb), 2 * TIER_ROUNDING, "torus k2");
        ic_surface_free(s);
    }
    /* cone apex (implicit): grad f = 0 */
    s = primitive(IC_PRIM_CONE, IC_IMPLICIT, 0, 0);
    if (!s)
        return;
    const double apex[3] = {0, 0, 0};
    CHECK(ic_surface_geometry_at(s, &g, apex, &err) == IC_ERR_DOMAIN, "cone apex degenerate");
    ic_surface_free(s);
}

/* z = x^2 + 3xy as a callback (derivatives supplied by hand). */
static int paraboloid(void *user, double *d, const double *at, const ic_jet_space *sp)
{
    (void)user;
    const int n = ic_jet_space_len(sp), K = ic_jet_space_order(sp);
    memset(d, 0, 3 * (size_t)n * sizeof *d);
    const double u = at[0], v = at[1];
    d[0] = u, d[n] = v, d[2 * n] = u * u + 3 * u * v;
    if (K >= 1) {
        d[1] = 1.0, d[n + 2] = 1.0;
        d[2 * n + 1] = 2 * u + 3 * v, d[2 * n + 2] = 3 * u;
    }
    if (K >= 2)
        d[2 * n + 3] = 2.0, d[2 * n + 4] = 3.0; /* d_uu, d_uv */
    return 0;
}

static int failing(void *user, double *d, const double *at, const ic_jet_space *sp)
{
    (void)user, (void)d, (void)at, (void)sp;
    return 1;
}

static void test_callback_and_compose(void)
{
    ic_surface *cb = NULL, *fm = NULL;
    const char *xyz[3] = {"u", "v", "u^2 + 3*u*v"};
    CHECK(ic_surface_new_callback(&cb, IC_PARAMETRIC, paraboloid, NULL, NULL) == IC_OK, "cb");
    CHECK(ic_surface_new_parametric(&fm, xyz, NULL, NULL, 0, NULL, NULL) == IC_OK, "formula");
    ic_jet_space *s1 = NULL;
    if (!cb || !fm || !REQUIRE(ic_jet_space_new(&s1, 1, 8, NULL) == IC_OK, "jet space of order 8")) {
        ic_surface_free(cb);
        ic_surface_free(fm);
        return;
    }
    /* a parameter curve u = 0.4 + s - s^2, v = -0.3 + 2 s */
    double u[9] = {0.4, 1.0, -1.0}, v[9] = {-0.3, 2.0}, a[27], b[27];
    for (int i = 3; i < 9; i++)
        u[i] = 0.0;
    for (int i = 2; i < 9; i++)
        v[i] = 0.0;
    const double *in[2] = {u, v};
    CHECK(ic_surface_compose(cb, a, in, s1, NULL) == IC_OK, "compose callback");
    CHECK(ic_surface_compose(fm, b, in, s1, NULL) == IC_OK, "compose formula");
    double worst = 0.0;
    for (int i = 0; i < 27; i++)
        worst = fmax(worst, fabs(a[i] - b[i]));
    CHECK(worst <= TIER_ROUNDING, "callback and formula compose alike: %g", worst);
    /* z(s) = u^2 + 3uv, exact polynomial: s^4 coefficient = 1 (from (-s^2)^2) */
    CHECK_ABS(b[18 + 4], 1.0, TIER_ROUNDING, "s^4 coefficient of z");
    ic_surface_geometry g;
    const double at[2] = {0.4, -0.3};
    CHECK(ic_surface_geometry_at(cb, &g, at, NULL) == IC_OK, "callback geometry");
    ic_surface *bad = NULL;
    ic_error err;
    CHECK(ic_surface_new_callback(&bad, IC_PARAMETRIC, failing, NULL, NULL) == IC_OK, "cb");
    CHECK(ic_surface_geometry_at(bad, &g, at, &err) == IC_ERR_DOMAIN, "failing callback reported");
    ic_surface_free(bad);
    ic_surface_free(cb);
    ic_surface_free(fm);
    ic_jet_space_free(s1);
}

static void test_invalid(void)
{
    ic_primitive p;
    memset(&p, 0, sizeof p);
    ic_surface *s = NULL;
    ic_error err;
    p.kind = IC_PRIM_SPHERE, p.radius = -1.0;
    CHECK(ic_surface_new_primitive(&s, &p, IC_IMPLICIT, &err) == IC_ERR_INVALID && !s, "radius");
    p.kind = IC_PRIM_CONE, p.half_angle = 2.0;
    CHECK(ic_surface_new_primitive(&s, &p, IC_IMPLICIT, &err) == IC_ERR_INVALID, "cone angle");
    p.kind = IC_PRIM_PLANE;
    CHECK(ic_surface_new_primitive(&s, &p, IC_IMPLICIT, &err) == IC_ERR_INVALID, "zero normal");
    const char *xyz[3] = {"u", "v", "w"};
    int which = -1;
    CHECK(ic_surface_new_parametric(&s, xyz, NULL, NULL, 0, &which, &err) == IC_ERR_PARSE &&
              which == 2,
          "unknown identifier in z: which = %d", which);
    const char *ok[3] = {"u", "v", "0"};
    if (!REQUIRE(ic_surface_new_parametric(&s, ok, NULL, NULL, 0, NULL, NULL) == IC_OK, "plane"))
        return;
    const double empty[2][2] = {{1, 0}, {0, 1}};
    CHECK(ic_surface_set_domain(s, empty, NULL, &err) == IC_ERR_INVALID, "empty domain");
    ic_jet_space *s3 = NULL;
    if (REQUIRE(ic_jet_space_new(&s3, 3, 2, NULL) == IC_OK, "jet space of 3 variables")) {
        double out[30];
        const double at[3] = {0, 0, 0};
        CHECK(ic_surface_taylor(s, out, at, s3, &err) == IC_ERR_INVALID, "wrong space");
    }
    ic_jet_space_free(s3);
    ic_surface_free(s);
}

/* A primitive along a curve one order at a time (ic_primitive_along, the
 * jet method's) against ic_surface_compose on the same curve: every kind,
 * parametric along a parameter curve and implicit along a space curve, in
 * standard position and placed. At each order the first step, with the
 * curve's order-k coefficients 0, must give the order-k coefficient of the
 * surface composed with the curve cut there, the second, with them, the
 * full one's. */
static void check_along(ic_surface *srf, const char *what, harness_rng *rng)
{
    enum { K = 12 };
    ic_jet_space *s1 = NULL;
    if (!REQUIRE(ic_jet_space_new(&s1, 1, K, NULL) == IC_OK, "space"))
        return;
    const int nin = ic_surface_num_vars(srf), nout = ic_surface_num_outputs(srf);
    double in[3][K + 1], cut[3][K + 1], out[3 * (K + 1)], first[3], final[3], at[3];
    for (int i = 0; i < nin; i++) {
        for (int k = 0; k <= K; k++)
            in[i][k] = harness_uniform(rng, -0.5, 0.5);
        in[i][0] += 1.0;
        at[i] = in[i][0];
    }
    ic_primitive_along pa;
    CHECK(ic_primitive_along_serves(srf), "%s: a primitive is served", what);
    ic_primitive_along_start(&pa, srf, at);
    double worst = 0.0, scale = 1.0;
    for (int k = 1; k <= K; k++) {
        ic_primitive_along_step(&pa, k, first);
        for (int i = 0; i < nin; i++)
            pa.in[i][k] = in[i][k];
        ic_primitive_along done = pa; /* the next order starts from the finished one */
        ic_primitive_along_step(&done, k, final);
        ic_primitive_along_finish(&pa, k);
        for (int pass = 0; pass < 2; pass++) {
            for (int i = 0; i < nin; i++)
                for (int j = 0; j <= K; j++)
                    cut[i][j] = j < k || (pass && j == k) ? in[i][j] : 0.0;
            const double *ins[3] = {cut[0], cut[1], cut[2]};
            if (!REQUIRE(ic_surface_compose(srf, out, ins, s1, NULL) == IC_OK, "compose"))
                break;
            for (int c = 0; c < nout; c++) {
                const double want = out[c * (K + 1) + k], got = pass ? final[c] : first[c];
                worst = fmax(worst, fabs(got - want));
                scale = fmax(scale, fabs(want));
            }
        }
    }
    CHECK(worst <= 1e-13 * scale, "%s along a curve: %g (scale %g)", what, worst, scale);
    ic_jet_space_free(s1);
}

static void test_primitive_along(harness_rng *rng)
{
    const ic_primitive_kind kinds[6] = {IC_PRIM_PLANE, IC_PRIM_SPHERE, IC_PRIM_CYLINDER,
                                        IC_PRIM_CONE, IC_PRIM_TORUS, IC_PRIM_ELLIPSOID};
    for (int i = 0; i < 24; i++) {
        ic_primitive p;
        memset(&p, 0, sizeof p);
        p.kind = kinds[i % 6];
        const int placed = i % 12 >= 6, form = i >= 12 ? IC_IMPLICIT : IC_PARAMETRIC;
        p.center[0] = 0.3, p.center[1] = -1.2, p.center[2] = 0.7;
        p.radius = p.kind == IC_PRIM_TORUS ? 0.5 : 1.5;
        p.major_radius = 2.0, p.half_angle = 0.4;
        p.axes[0] = 1.5, p.axes[1] = 0.8, p.axes[2] = 1.1;
        p.normal[0] = 0.2, p.normal[1] = -0.4, p.normal[2] = 1.0;
        if (placed && p.kind != IC_PRIM_PLANE) /* (the plane is placed by its normal) */
            p.axis[0] = 0.3, p.axis[1] = -0.5, p.axis[2] = 0.8;
        ic_surface *srf = NULL;
        char what[64];
        snprintf(what, sizeof what, "primitive kind %d, %s%s", (int)p.kind,
                 form == IC_IMPLICIT ? "implicit" : "parametric", placed ? ", placed" : "");
        if (REQUIRE(ic_surface_new_primitive(&srf, &p, form, NULL) == IC_OK, "%s", what))
            check_along(srf, what, rng);
        ic_surface_free(srf);
    }
}

/* ic_primitive_along_advance, the jet method's one call per order, against
 * the general path it stands for (ic_primitive_along_finish of order k, then
 * ic_primitive_along_step of order k + 1 with the curve's coefficients of
 * that order still zero), at every order up to the jet method's highest,
 * on random primitives, placed at random or not: an implicit quadric's
 * step is summed there apart, in registers (quadric_next), the others go
 * through the general path. */
enum { ADVANCE_K = 16 }; /* IC_LOCAL_MAX_ORDER */

/* The sum of the magnitudes of the terms of a quadric's order-k
 * coefficient, sum_i |A_i| sum_j |d_ij d_i(k-j)|. Two evaluations of the
 * same terms in any order differ by at most 2 (k + 5) DBL_EPSILON times it
 * (recursive summation of the k + 1 products, each weighted by A_i, and the
 * sum over i): the specialised sum adds the same terms in the same order
 * and agrees to the bit, unless a compiler fuses multiplications and
 * additions differently in the two; a wrong term is a whole term off. */
static double quadric_terms(const ic_primitive_along *pa, int k)
{
    double sum = 0.0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j <= k; j++)
            sum += fabs(pa->A[i]) * fabs(pa->d[i][j] * pa->d[i][k - j]);
    return sum;
}

static void check_advance(ic_surface *srf, const char *what, harness_rng *rng)
{
    const int nin = ic_surface_num_vars(srf), nout = ic_surface_num_outputs(srf);
    double in[3][ADVANCE_K + 1] = {{0.0}};
    for (int i = 0; i < nin; i++)
        for (int k = 0; k <= ADVANCE_K; k++)
            in[i][k] = harness_uniform(rng, -0.5, 0.5) + (k == 0 ? 1.0 : 0.0);
    const double at[3] = {in[0][0], in[1][0], in[2][0]};
    ic_primitive_along general, fast;
    ic_primitive_along_start(&general, srf, at);
    ic_primitive_along_start(&fast, srf, at);
    int bad = 0, bad_order = 0;
    double bad_got = 0.0, bad_want = 0.0;
    for (int k = 1; k < ADVANCE_K; k++) {
        double want[3], got[3];
        for (int i = 0; i < nin; i++)
            general.in[i][k] = in[i][k];
        ic_primitive_along_finish(&general, k);
        ic_primitive_along next = general; /* its order-(k+1) coefficients zero */
        ic_primitive_along_step(&next, k + 1, want);
        ic_primitive_along_advance(&fast, k, in[0][k], in[1][k], in[2][k], got);
        const double bound =
            next.quadric ? 2.0 * (k + 6) * DBL_EPSILON * quadric_terms(&next, k + 1) : 0.0;
        for (int c = 0; c < nout; c++)
            if (!(fabs(got[c] - want[c]) <= bound) && bad++ == 0)
                bad_order = k + 1, bad_got = got[c], bad_want = want[c];
    }
    CHECK(bad == 0, "%s: the advance's step differs %d times, first at order %d: %.17g, want %.17g",
          what, bad, bad_order, bad_got, bad_want);
}

static void test_primitive_advance(harness_rng *rng)
{
    const ic_primitive_kind kinds[6] = {IC_PRIM_CYLINDER, IC_PRIM_SPHERE, IC_PRIM_CONE,
                                        IC_PRIM_ELLIPSOID, IC_PRIM_PLANE, IC_PRIM_TORUS};
    const int trials = 48 * harness_multiplier();
    for (int t = 0; t < trials; t++) {
        ic_primitive p;
        memset(&p, 0, sizeof p);
        p.kind = kinds[t % 6];
        const int placed = t / 6 % 2, form = t / 12 % 4 == 3 ? IC_PARAMETRIC : IC_IMPLICIT;
        for (int i = 0; i < 3; i++) {
            p.center[i] = harness_uniform(rng, -2.0, 2.0);
            p.axes[i] = harness_uniform(rng, 0.3, 2.0);
            p.normal[i] = harness_uniform(rng, -1.0, 1.0);
            if (placed && p.kind != IC_PRIM_PLANE) /* (the plane is placed by its normal) */
                p.axis[i] = harness_uniform(rng, -1.0, 1.0);
        }
        p.radius = harness_uniform(rng, 0.3, 2.0);
        p.major_radius = p.radius + harness_uniform(rng, 0.5, 2.0);
        p.half_angle = harness_uniform(rng, 0.1, 1.2);
        ic_surface *srf = NULL;
        char what[64];
        snprintf(what, sizeof what, "random primitive %d (kind %d, %s%s)", t, (int)p.kind,
                 form == IC_IMPLICIT ? "implicit" : "parametric", placed ? ", placed" : "");
        if (REQUIRE(ic_surface_new_primitive(&srf, &p, form, NULL) == IC_OK, "%s", what))
            check_advance(srf, what, rng);
        ic_surface_free(srf);
    }
}

int main(int argc, char **argv)
{
    harness_rng rng = {0xD1B54A32D192ED03ull};
    const int cases = test_truth_file(argc > 1 ? argv[1] : "tests/truth/surface_truth.txt");
    CHECK(cases == 13, "truth cases read: %d", cases);
    printf("worst derivative error: %.1f ulps of the order's largest derivative (tier 32)\n",
           worst_deriv);
    test_primitives_match_formulas(&rng);
    test_principal_curvatures();
    test_callback_and_compose();
    test_invalid();
    test_primitive_along(&rng);
    test_primitive_advance(&rng);
    return harness_finish("test_surface");
}
