/* NURBS patches: validation, spans, and exact Taylor coefficients from the
 * B-spline basis derivatives and the quotient rule (Piegl and Tiller 1997,
 * eqs. 2.5 and 2.9 for the basis and its derivatives, eq. 4.8 for the
 * rational derivatives, here carried out by jet division). */
#include "nurbs.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* length: largest |w x| (and weight) a patch may hold, so that products of
 * the homogeneous coordinates by basis values and their derivatives (which
 * grow by at most degree! / (shortest span)^order) stay far from overflow */
#define NURBS_MAX_MAGNITUDE 1e150

/* An invalid field: the message, and the field's path relative to the patch. */
static ic_status field_error(ic_error *err, const char *path, const char *what)
{
    ic_error_set(err, IC_ERR_INVALID, 0, "%s", what);
    if (err)
        snprintf(err->path, sizeof err->path, "%s", path);
    return IC_ERR_INVALID;
}

/* Most control points a patch may have (a 1000 x 1000 net). */
#define NURBS_MAX_POINTS 1000000

static ic_status check_sizes(const ic_nurbs *d, ic_error *err)
{
    char what[160], path[32];
    for (int k = 0; k < 2; k++) {
        snprintf(path, sizeof path, "degree[%d]", k);
        if (d->degree[k] < 1 || d->degree[k] > IC_NURBS_MAX_DEGREE) {
            snprintf(what, sizeof what, "degree %d outside 1..%d", d->degree[k],
                     IC_NURBS_MAX_DEGREE);
            return field_error(err, path, what);
        }
        if (d->count[k] < d->degree[k] + 1 || d->count[k] > NURBS_MAX_POINTS) {
            snprintf(what, sizeof what,
                     "%d control points along parameter %d; degree %d needs at least %d",
                     d->count[k], k + 1, d->degree[k], d->degree[k] + 1);
            return field_error(err, "control_points", what);
        }
        if (!d->knots[k])
            return field_error(err, "knots", "no knot vector");
    }
    if ((long long)d->count[0] * d->count[1] > NURBS_MAX_POINTS) {
        snprintf(what, sizeof what, "%d x %d control points; at most %d in all", d->count[0],
                 d->count[1], NURBS_MAX_POINTS);
        return field_error(err, "control_points", what);
    }
    if (!d->points)
        return field_error(err, "control_points", "no control points");
    return IC_OK;
}

/* Knots finite, nondecreasing, a nonempty domain, and no interior knot of
 * multiplicity above the degree (the patch would be discontinuous there). */
static ic_status check_knots(const double *t, int n, int p, int k, ic_error *err)
{
    char path[48], what[160];
    for (int i = 0; i < n + p + 1; i++) {
        snprintf(path, sizeof path, "knots[%d][%d]", k, i);
        if (!isfinite(t[i]) || fabs(t[i]) > NURBS_MAX_MAGNITUDE) {
            snprintf(what, sizeof what, "knot %g is not a finite number within %g", t[i],
                     NURBS_MAX_MAGNITUDE);
            return field_error(err, path, what);
        }
        if (i > 0 && t[i] < t[i - 1]) {
            snprintf(what, sizeof what, "knots decrease: %.10g after %.10g", t[i], t[i - 1]);
            return field_error(err, path, what);
        }
    }
    snprintf(path, sizeof path, "knots[%d]", k);
    if (!(t[p] < t[n])) {
        snprintf(what, sizeof what,
                 "empty domain [%g, %g]: knot %d (the degree) must lie below knot %d (the number "
                 "of control points)", t[p], t[n], p, n);
        return field_error(err, path, what);
    }
    for (int i = p + 1; i < n; i++) {
        int mult = 1;
        while (i + mult < n && t[i + mult] == t[i])
            mult++;
        if (t[i] > t[p] && t[i] < t[n] && mult > p) {
            snprintf(path, sizeof path, "knots[%d][%d]", k, i);
            snprintf(what, sizeof what,
                     "interior knot %g has multiplicity %d, above the degree %d: the patch is "
                     "discontinuous there", t[i], mult, p);
            return field_error(err, path, what);
        }
    }
    return IC_OK;
}

static ic_status copy_net(ic_nurbs_patch *pt, const ic_nurbs *d, ic_error *err)
{
    const int nu = d->count[0], nv = d->count[1];
    const double w0 = d->weights ? d->weights[0] : 1.0;
    char path[64], what[160];
    for (int i = 0; i < nu; i++)
        for (int j = 0; j < nv; j++) {
            const int at = i * nv + j;
            const double w = d->weights ? d->weights[at] : 1.0;
            if (!(w > 0) || !(w <= NURBS_MAX_MAGNITUDE)) {
                snprintf(path, sizeof path, "weights[%d][%d]", i, j);
                snprintf(what, sizeof what, "weight %g is not a positive number within %g", w,
                         NURBS_MAX_MAGNITUDE);
                return field_error(err, path, what);
            }
            pt->rational |= w != w0;
            for (int c = 0; c < 3; c++) {
                const double x = d->points[3 * at + c];
                if (!isfinite(x) || !(fabs(x * w) <= NURBS_MAX_MAGNITUDE)) {
                    snprintf(path, sizeof path, "control_points[%d][%d][%d]", i, j, c);
                    snprintf(what, sizeof what,
                             "coordinate %g (weight %g) is not finite or its product with the "
                             "weight exceeds %g", x, w, NURBS_MAX_MAGNITUDE);
                    return field_error(err, path, what);
                }
                pt->hom[4 * at + c] = w * x;
            }
            pt->hom[4 * at + 3] = w;
        }
    return IC_OK;
}

/* Hodograph of the homogeneous net along dir: Q_i = p (P_i+1 - P_i) /
 * (t_i+p+1 - t_i+1) (Piegl and Tiller 1997, eq. 3.8 per row), over the
 * knots without their first and last. Zero where that knot span is empty. */
static void make_hodograph(ic_nurbs_patch *pt, int dir)
{
    const int p = pt->p[dir], nu = pt->n[0], nv = pt->n[1];
    const double *t = pt->knots[dir];
    const int mu = dir == 0 ? nu - 1 : nu, mv = dir == 0 ? nv : nv - 1;
    for (int i = 0; i < mu; i++)
        for (int j = 0; j < mv; j++) {
            const int a = i * nv + j, b = dir == 0 ? a + nv : a + 1, k = dir == 0 ? i : j;
            const double h = t[k + p + 1] - t[k + 1];
            for (int c = 0; c < 4; c++)
                pt->hodo[dir][4 * (i * mv + j) + c] =
                    h > 0 ? p * (pt->hom[4 * b + c] - pt->hom[4 * a + c]) / h : 0.0;
        }
}

ic_status ic_nurbs_patch_new(ic_nurbs_patch **out, const ic_nurbs *d, ic_error *err)
{
    *out = NULL;
    if (!d)
        return ic_error_set(err, IC_ERR_INVALID, 0, "NURBS patch: no description");
    ic_status st = check_sizes(d, err);
    for (int k = 0; st == IC_OK && k < 2; k++)
        st = check_knots(d->knots[k], d->count[k], d->degree[k], k, err);
    if (st != IC_OK)
        return st;
    ic_nurbs_patch *pt = calloc(1, sizeof *pt);
    const size_t cells = (size_t)d->count[0] * (size_t)d->count[1];
    if (pt) {
        for (int k = 0; k < 2; k++) {
            pt->p[k] = d->degree[k];
            pt->n[k] = d->count[k];
            pt->periodic[k] = d->periodic[k] != 0;
            pt->knots[k] = malloc(sizeof(double) * (size_t)(d->count[k] + d->degree[k] + 1));
            pt->hodo[k] = malloc(sizeof(double) * 4 * cells);
        }
        pt->hom = malloc(sizeof(double) * 4 * cells);
    }
    if (!pt || !pt->hom || !pt->knots[0] || !pt->knots[1] || !pt->hodo[0] || !pt->hodo[1]) {
        ic_nurbs_patch_free(pt);
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory creating a NURBS patch");
    }
    for (int k = 0; k < 2; k++) {
        memcpy(pt->knots[k], d->knots[k], sizeof(double) * (size_t)(pt->n[k] + pt->p[k] + 1));
        pt->domain[k][0] = pt->knots[k][pt->p[k]];
        pt->domain[k][1] = pt->knots[k][pt->n[k]];
    }
    if ((st = copy_net(pt, d, err)) != IC_OK) {
        ic_nurbs_patch_free(pt);
        return st;
    }
    make_hodograph(pt, 0);
    make_hodograph(pt, 1);
    *out = pt;
    return IC_OK;
}

/* A copy of n doubles, or NULL out of memory. */
static double *copy_doubles(const double *a, size_t n)
{
    double *c = malloc(n * sizeof *c);
    if (c)
        memcpy(c, a, n * sizeof *c);
    return c;
}

ic_status ic_nurbs_patch_copy(ic_nurbs_patch **out, const ic_nurbs_patch *pt, ic_error *err)
{
    *out = NULL;
    ic_nurbs_patch *c = calloc(1, sizeof *c);
    if (!c)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory copying a NURBS patch");
    *c = *pt;
    const size_t cells = (size_t)pt->n[0] * (size_t)pt->n[1];
    c->hom = copy_doubles(pt->hom, 4 * cells);
    for (int k = 0; k < 2; k++) {
        c->knots[k] = copy_doubles(pt->knots[k], (size_t)(pt->n[k] + pt->p[k] + 1));
        c->hodo[k] = copy_doubles(pt->hodo[k], 4 * cells);
    }
    if (!c->hom || !c->knots[0] || !c->knots[1] || !c->hodo[0] || !c->hodo[1]) {
        ic_nurbs_patch_free(c);
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory copying a NURBS patch");
    }
    *out = c;
    return IC_OK;
}

void ic_nurbs_patch_free(ic_nurbs_patch *pt)
{
    if (!pt)
        return;
    for (int k = 0; k < 2; k++) {
        free(pt->knots[k]);
        free(pt->hodo[k]);
    }
    free(pt->hom);
    free(pt);
}

double ic_nurbs_wrap(const ic_nurbs_patch *pt, int dir, double t)
{
    if (!pt->periodic[dir])
        return t;
    const double a = pt->domain[dir][0], period = pt->domain[dir][1] - a;
    if (t >= a && t < a + period)
        return t;
    const double r = fmod(t - a, period);
    return a + (r < 0 ? r + period : r);
}

int ic_nurbs_find_span(const ic_nurbs_patch *pt, int dir, double t, ic_nurbs_side side)
{
    return ic_knot_span(pt->knots[dir], pt->p[dir], pt->n[dir], t, side);
}

int ic_knot_span(const double *k, int p, int n, double t, ic_nurbs_side side)
{
    /* the first and last nonempty spans of the domain */
    int first = p, last = n - 1;
    while (k[first + 1] == k[first])
        first++;
    while (k[last] == k[last + 1])
        last--;
    if (t <= k[first + 1] && !(side == IC_NURBS_RIGHT && t == k[first + 1] && first < last))
        return first;
    if (t >= k[last] && !(side == IC_NURBS_LEFT && t == k[last] && first < last))
        return last;
    int lo = first, hi = last; /* k[lo] <= t < k[hi + 1] */
    while (hi > lo) {
        const int mid = (lo + hi + 1) / 2;
        const int right_of = side == IC_NURBS_RIGHT ? t >= k[mid] : t > k[mid];
        if (right_of)
            lo = mid;
        else
            hi = mid - 1;
    }
    return lo; /* nonempty: k[lo] <= t < k[lo + 1] (LEFT: k[lo] < t <= k[lo + 1]) */
}

int ic_nurbs_knot_crossed(const ic_nurbs_patch *pt, int dir, double from, double to,
                          double *knot)
{
    if (!(from != to) || !isfinite(from) || !isfinite(to))
        return 0;
    const double d0 = pt->domain[dir][0], d1 = pt->domain[dir][1];
    const int up = to > from;
    const double a = ic_nurbs_wrap(pt, dir, from);
    const double shift = from - a, b = to - shift;
    /* the nearest knot beyond a that way: the end of a's span that way */
    const int s = ic_nurbs_find_span(pt, dir, a, up ? IC_NURBS_RIGHT : IC_NURBS_LEFT);
    const double c = pt->knots[dir][up ? s + 1 : s];
    const int met = up ? c <= b : c >= b;
    /* an interior knot (the seam of a wrapping parameter is not one) */
    if (!met || !(c > d0 && c < d1))
        return 0;
    *knot = c + shift;
    return 1;
}

double ic_nurbs_wrap_side(const ic_nurbs_patch *pt, int dir, double t, ic_nurbs_side side)
{
    const double w = ic_nurbs_wrap(pt, dir, t);
    /* on the seam, the piece below it is the domain's last */
    return pt->periodic[dir] && side == IC_NURBS_LEFT && w == pt->domain[dir][0]
               ? pt->domain[dir][1]
               : w;
}

int ic_nurbs_seam(const ic_nurbs_patch *pt, int dir) { return pt->periodic[dir]; }
