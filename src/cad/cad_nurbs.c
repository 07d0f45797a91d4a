/* NURBS patches read from CAD files: their arrays, checks and closure
 * (cad_internal.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cad_internal.h"

ic_status ic_cad_alloc_nurbs(ic_cad_surface *s, const int degree[2], const int count[2],
                             int rational, const char *who, ic_error *err)
{
    static const char *const dir[2] = {"u", "v"};
    for (int d = 0; d < 2; d++) {
        if (degree[d] < 1 || degree[d] > IC_NURBS_MAX_DEGREE)
            return ic_cad_fail(err, who, "%s degree %d is outside 1..%d, the degrees read", dir[d],
                               degree[d], IC_NURBS_MAX_DEGREE);
        if (count[d] <= degree[d] || count[d] > IC_CAD_MAX_COUNT)
            return ic_cad_fail(err, who,
                               "%d control points along %s: a patch of degree %d needs %d to %d",
                               count[d], dir[d], degree[d], degree[d] + 1, IC_CAD_MAX_COUNT);
    }
    const long npoints = (long)count[0] * count[1];
    if (npoints > IC_CAD_MAX_POINTS)
        return ic_cad_fail(err, who, "%ld control points: more than %d, the most read", npoints,
                           IC_CAD_MAX_POINTS);
    const size_t nknots = (size_t)(count[0] + degree[0] + 1 + count[1] + degree[1] + 1);
    s->knots_store = malloc(nknots * sizeof(double));
    s->points_store = malloc(3 * (size_t)npoints * sizeof(double));
    s->weights_store = rational ? malloc((size_t)npoints * sizeof(double)) : NULL;
    if (!s->knots_store || !s->points_store || (rational && !s->weights_store))
        return ic_error_set(err, IC_ERR_NOMEM, 0, "%s: out of memory", who);
    s->is_nurbs = 1;
    for (int d = 0; d < 2; d++) {
        s->nurbs.degree[d] = degree[d];
        s->nurbs.count[d] = count[d];
    }
    s->nurbs.knots[0] = s->knots_store;
    s->nurbs.knots[1] = s->knots_store + count[0] + degree[0] + 1;
    s->nurbs.points = s->points_store;
    s->nurbs.weights = s->weights_store;
    return IC_OK;
}

/* The knot span of x: s in [p, n - 1] with t[s] <= x < t[s + 1], the last
 * nonempty span for x = t[n] (the domain is not empty, so one exists). */
static int find_span(const double *t, int p, int n, double x)
{
    if (x >= t[n]) {
        int s = n - 1;
        while (s > p && !(t[s] < t[s + 1]))
            s--;
        return s;
    }
    int lo = p, hi = n - 1;
    while (lo < hi) { /* the last s with t[s] <= x */
        const int mid = lo + (hi - lo + 1) / 2;
        if (t[mid] <= x)
            lo = mid;
        else
            hi = mid - 1;
    }
    return lo;
}

/* The p + 1 B-spline basis functions of degree p that are nonzero on span s
 * at x (the triangle of Cox-de Boor recurrences). */
static void basis(const double *t, int p, int s, double x, double *N)
{
    double left[IC_NURBS_MAX_DEGREE + 1], right[IC_NURBS_MAX_DEGREE + 1];
    N[0] = 1;
    for (int j = 1; j <= p; j++) {
        left[j] = x - t[s + 1 - j];
        right[j] = t[s + j] - x;
        double saved = 0;
        for (int r = 0; r < j; r++) {
            const double tmp = N[r] / (right[r + 1] + left[j - r]);
            N[r] = saved + right[r + 1] * tmp;
            saved = left[j - r] * tmp;
        }
        N[j] = saved;
    }
}

/* The patch's point at (u, v). */
static void eval_point(const ic_nurbs *n, double u, double v, double out[3])
{
    double Nu[IC_NURBS_MAX_DEGREE + 1], Nv[IC_NURBS_MAX_DEGREE + 1], sum[4] = {0, 0, 0, 0};
    const int p = n->degree[0], q = n->degree[1];
    const int su = find_span(n->knots[0], p, n->count[0], u);
    const int sv = find_span(n->knots[1], q, n->count[1], v);
    basis(n->knots[0], p, su, u, Nu);
    basis(n->knots[1], q, sv, v, Nv);
    for (int a = 0; a <= p; a++)
        for (int b = 0; b <= q; b++) {
            const size_t k = (size_t)(su - p + a) * (size_t)n->count[1] + (size_t)(sv - q + b);
            const double w = (n->weights ? n->weights[k] : 1) * Nu[a] * Nv[b];
            for (int c = 0; c < 3; c++)
                sum[c] += w * n->points[3 * k + c];
            sum[3] += w;
        }
    for (int c = 0; c < 3; c++)
        out[c] = sum[c] / sum[3];
}

/* Along d the patch closes on itself: its points at the two ends of the
 * domain along d agree at the start and middle of every knot span of the
 * other direction and at its end. Evaluated rather than read off the
 * control rows, as a periodic knot vector written out unclamped repeats
 * fewer rows than its degree. */
static int wraps(const ic_nurbs *n, int d, const double domain[2][2], double scale)
{
    const int e = 1 - d;
    const double *t = n->knots[e];
    for (int s = n->degree[e]; s <= n->count[e]; s++) {
        if (s < n->count[e] && !(t[s] < t[s + 1]))
            continue;
        const int last = s == n->count[e];
        for (int half = 0; half < (last ? 1 : 2); half++) {
            const double w = last ? domain[e][1] : t[s] + 0.5 * half * (t[s + 1] - t[s]);
            double a[3], b[3], at_a[2], at_b[2];
            at_a[d] = domain[d][0];
            at_b[d] = domain[d][1];
            at_a[e] = at_b[e] = w;
            eval_point(n, at_a[0], at_a[1], a);
            eval_point(n, at_b[0], at_b[1], b);
            for (int k = 0; k < 3; k++)
                if (!(fabs(a[k] - b[k]) <= IC_CAD_CLOSURE_TOL * scale))
                    return 0;
        }
    }
    return 1;
}

static ic_status check_values(const ic_nurbs *n, const char *who, ic_error *err)
{
    static const char *const dir[2] = {"u", "v"};
    const size_t npoints = (size_t)n->count[0] * (size_t)n->count[1];
    for (size_t k = 0; k < 3 * npoints; k++)
        if (!isfinite(n->points[k]))
            return ic_cad_fail(err, who, "control point %zu has a coordinate that is not finite",
                               k / 3);
    for (size_t k = 0; n->weights && k < npoints; k++)
        if (!(n->weights[k] > 0) || !isfinite(n->weights[k]))
            return ic_cad_fail(err, who, "weight %zu is %g: weights must be positive", k,
                               n->weights[k]);
    for (int d = 0; d < 2; d++) {
        const int len = n->count[d] + n->degree[d] + 1;
        for (int k = 0; k < len; k++) {
            if (!isfinite(n->knots[d][k]))
                return ic_cad_fail(err, who, "%s knot %d is not finite", dir[d], k);
            if (k > 0 && n->knots[d][k] < n->knots[d][k - 1])
                return ic_cad_fail(err, who, "%s knots decrease at knot %d (%g after %g)", dir[d],
                                   k, n->knots[d][k], n->knots[d][k - 1]);
        }
        if (!(n->knots[d][n->degree[d]] < n->knots[d][n->count[d]]))
            return ic_cad_fail(err, who, "the %s parameter range [%g, %g] is empty", dir[d],
                               n->knots[d][n->degree[d]], n->knots[d][n->count[d]]);
    }
    return IC_OK;
}

ic_status ic_cad_finish_nurbs(ic_cad_surface *s, const int closed[2], const char *who,
                              ic_error *err)
{
    const ic_nurbs *n = &s->nurbs;
    const ic_status st = check_values(n, who, err);
    if (st != IC_OK)
        return st;
    double scale = 1;
    const size_t npoints = (size_t)n->count[0] * (size_t)n->count[1];
    for (size_t k = 0; k < 3 * npoints; k++)
        scale = fmax(scale, fabs(n->points[k]));
    for (int d = 0; d < 2; d++) {
        s->domain[d][0] = n->knots[d][n->degree[d]];
        s->domain[d][1] = n->knots[d][n->count[d]];
    }
    for (int d = 0; d < 2; d++)
        s->periodic[d] = s->nurbs.periodic[d] = closed[d] && wraps(n, d, s->domain, scale);
    return IC_OK;
}
