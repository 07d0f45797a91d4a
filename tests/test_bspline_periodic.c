/* Closed curves as periodic B-splines (docs/bspline.md, "Closed curves"):
 * the form is the standard unclamped one (checked by an evaluator written
 * here from the Cox-de Boor recursion, not the library's), the curve is C^2
 * where it closes, and there it carries the traced point's exact x, t and
 * kappa n; a pcurve that closes in its plane is periodic too, one that goes
 * once round a periodic parameter stays clamped and ends a period on. */
#include "harness.h"

#include <float.h>
#include <math.h>
#include <string.h>

#include "traced_example.h"

/* relative: points of a B-spline of size ~1 from two evaluation orders
 * agree to a few ulps of the size */
#define EVAL_REL 1e-14
/* ulps: the d-th derivative from differenced control points (own_eval)
 * carries their rounding over h^d, h the shortest knot interval; the two
 * evaluations agree to this many ulps of size (size / h)^d */
#define DERIV_ULPS 64
/* relative to the size: the closing point's derivatives from both ends of
 * the parameter range, the second through the net over h^2 (h ~ 1e-2) */
#define SEAM_REL 1e-9
enum { SAMPLES = 400, MAXD = 3 };

static char source_dir[400];

/* N_{i,p}(t) by the Cox-de Boor recursion (de Boor 1972), on the span
 * u_i <= t < u_{i+1} (from_left: u_i < t <= u_{i+1}, the left limit). */
static double basis(const double *u, int i, int p, double t, int from_left)
{
    if (p == 0)
        return from_left ? (u[i] < t && t <= u[i + 1]) : (u[i] <= t && t < u[i + 1]);
    double v = 0;
    if (u[i + p] > u[i])
        v += (t - u[i]) / (u[i + p] - u[i]) * basis(u, i, p - 1, t, from_left);
    if (u[i + p + 1] > u[i + 1])
        v += (u[i + p + 1] - t) / (u[i + p + 1] - u[i + 1]) * basis(u, i + 1, p - 1, t, from_left);
    return v;
}

/* The point and derivatives 0..MAXD-1 of a B-spline at t, from the
 * derivative curves: Q_i = p (P_{i+1} - P_i) / (u_{i+p+1} - u_{i+1}) over
 * the knots u_1.. (Piegl and Tiller 1997, eq. 3.8). */
static void own_eval(const ic_bspline *c, double t, int from_left, double out[MAXD][3])
{
    const int dim = c->dim, n = c->ncontrol;
    double P[2048 * 3], Q[2048 * 3];
    memcpy(P, c->control, sizeof(double) * (size_t)(dim * n));
    for (int k = 0, p = c->degree, m = n; k < MAXD; k++, p--, m--) {
        const double *u = c->knots + k;
        for (int j = 0; j < dim; j++)
            out[k][j] = 0;
        for (int i = 0; i < m; i++) {
            const double N = basis(u, i, p, t, from_left);
            for (int j = 0; j < dim; j++)
                out[k][j] += N * P[dim * i + j];
        }
        for (int i = 0; i + 1 < m; i++)
            for (int j = 0; j < dim; j++)
                Q[dim * i + j] = p * (P[dim * (i + 1) + j] - P[dim * i + j]) /
                                 (u[i + p + 1] - u[i + 1]);
        memcpy(P, Q, sizeof(double) * (size_t)(dim * (m - 1)));
    }
}

/* The shape of the periodic form: u_{k+m} = u_k + L for the m distinct
 * points, and the first `degree` control points repeated at the end. */
static int periodic_shape(const ic_bspline *c)
{
    const int p = c->degree, n = c->ncontrol, m = n - p;
    const double L = c->knots[n] - c->knots[p];
    int ok = c->periodic && m >= 1 && L > 0 && c->knots[0] < c->knots[p];
    for (int k = 0; ok && k + m < n + p + 1; k++)
        ok = fabs(c->knots[k + m] - c->knots[k] - L) <= EVAL_REL * L;
    for (int i = 0; ok && i < p; i++)
        ok = memcmp(c->control + c->dim * i, c->control + c->dim * (m + i),
                    sizeof(double) * (size_t)c->dim) == 0;
    return ok;
}

/* the shortest nonzero knot interval */
static double shortest_interval(const ic_bspline *c)
{
    double h = INFINITY;
    for (int k = 0; k < c->ncontrol + c->degree; k++)
        if (c->knots[k + 1] > c->knots[k])
            h = fmin(h, c->knots[k + 1] - c->knots[k]);
    return h;
}

/* Largest difference of own_eval and ic_bspline_eval over the range, in
 * units of the bounds above (1: at the bound), and of the curve's
 * derivatives 0..2 at its two ends (from inside). */
static void compare(const ic_bspline *c, double size, double *worst_eval, double *worst_seam)
{
    const double lo = c->knots[c->degree], hi = c->knots[c->ncontrol];
    const double h = shortest_interval(c);
    for (int k = 0; k <= SAMPLES; k++) {
        const double t = lo + (hi - lo) * k / SAMPLES;
        double own[MAXD][3], lib[MAXD * 3];
        own_eval(c, t, k == SAMPLES, own);
        if (ic_bspline_eval(c, t, MAXD - 1, lib, NULL) != IC_OK) {
            *worst_eval = INFINITY;
            continue;
        }
        for (int j = 0; j < c->dim; j++) /* the library wraps hi to lo: compare the point */
            *worst_eval = fmax(*worst_eval, fabs(own[0][j] - lib[j]) / (EVAL_REL * size));
        for (int d = 1; d < MAXD && k < SAMPLES; d++)
            for (int j = 0; j < c->dim; j++)
                *worst_eval = fmax(*worst_eval, fabs(own[d][j] - lib[d * c->dim + j]) /
                                                    (DERIV_ULPS * DBL_EPSILON * pow(size / h, d)));
    }
    double a[MAXD][3], z[MAXD][3];
    own_eval(c, lo, 0, a);
    own_eval(c, hi, 1, z);
    for (int d = 0; d < MAXD; d++)
        for (int j = 0; j < c->dim; j++)
            *worst_seam = fmax(*worst_seam, fabs(a[d][j] - z[d][j]) * pow(size, d - 1.0));
}

/* Every closed curve of a problem: periodic, standard, C^2 at the seam,
 * with x, t and kappa n of its first point there; pcurves as the header
 * says. period[s]: sheet s's period in its first parameter (0: none). */
static void check_file(const char *file, double size, int ncurves, const double period[2])
{
    char path[600];
    snprintf(path, sizeof path, "%s/%s", source_dir, file);
    traced t;
    if (trace_file(&t, path) != 0)
        return;
    ic_error err;
    if (!REQUIRE(ic_trace_fit(t.res, t.pair, 1e-9, &err) == IC_OK, "%s: fit: %s", file,
                 err.message)) {
        release(&t);
        return;
    }
    const int n = ic_trace_result_num_curves(t.res);
    CHECK(n == ncurves, "%s: %d closed curves (%d)", file, ncurves, n);
    double worst_eval = 0, worst_seam = 0, worst_point = 0;
    for (int i = 0; i < n; i++) {
        const ic_trace_curve *tc = ic_trace_result_curve(t.res, i);
        const ic_curve_fit *f = ic_trace_result_fit(t.res, i);
        if (!REQUIRE(tc->closed && f && periodic_shape(&f->curve), "%s: curve %d periodic", file, i))
            continue;
        compare(&f->curve, size, &worst_eval, &worst_seam);
        double at[MAXD][3];
        own_eval(&f->curve, f->curve.knots[f->curve.degree], 0, at);
        const ic_trace_point *p0 = &tc->points[0];
        for (int j = 0; j < 3; j++)
            worst_point = fmax(worst_point, fmax(fabs(at[0][j] - p0->xyz[j]) / size,
                                                 fmax(fabs(at[1][j] - p0->t[j]),
                                                      fabs(at[2][j] - p0->kappa * p0->n[j]) * size)));
        for (int s = 0; s < 2; s++) {
            const ic_bspline *pc = &f->pcurves[s];
            if (!pc->ncontrol)
                continue;
            if (period[s] == 0) {
                CHECK(periodic_shape(pc), "%s: curve %d's pcurve %d closes: periodic", file, i, s);
                compare(pc, size, &worst_eval, &worst_seam);
                continue;
            }
            double a[MAXD][3], z[MAXD][3];
            own_eval(pc, pc->knots[pc->degree], 0, a);
            own_eval(pc, pc->knots[pc->ncontrol], 1, z);
            CHECK(!pc->periodic && fabs(fabs(z[0][0] - a[0][0]) - period[s]) <= EVAL_REL &&
                      fabs(z[0][1] - a[0][1]) <= EVAL_REL,
                  "%s: curve %d's pcurve %d clamped, once round its period (%g to %g)", file, i, s,
                  a[0][0], z[0][0]);
        }
    }
    CHECK(worst_eval <= 1, "%s: own and library evaluation differ by %g of their bounds", file,
          worst_eval);
    CHECK(worst_seam <= SEAM_REL, "%s: C^2 where it closes: %g", file, worst_seam);
    CHECK(worst_point <= SEAM_REL, "%s: the first point's x, t, kappa n there: %g", file,
          worst_point);
    printf("%-50s eval %.2g, seam %.2g, start %.2g\n", file, worst_eval, worst_seam, worst_point);
    release(&t);
}

int main(int argc, char **argv)
{
    if (!REQUIRE(argc > 1, "usage: test_bspline_periodic SOURCE_DIR"))
        return harness_finish("bspline_periodic");
    snprintf(source_dir, sizeof source_dir, "%s", argv[1]);
    /* a circle, closed in the plane's parameters too */
    check_file("tests/data/periodic-plane-sphere.json", 1, 1, (double[2]){0, 0});
    /* two circles going once round the NURBS cylinder's periodic u in [0, 1] */
    check_file("tests/data/nurbs/problem-cylinder-sphere.json", 2, 2, (double[2]){1, 0});
    /* the two loops of two cylinders (implicit: no pcurves) */
    check_file("examples/cylinders.json", 1, 2, (double[2]){0, 0});
    return harness_finish("bspline_periodic");
}
