/* B_SPLINE_SURFACE_WITH_KNOTS of a STEP file (step_surface.h), simple:
 *   B_SPLINE_SURFACE_WITH_KNOTS(name, u_degree, v_degree, control_points_list,
 *     surface_form, u_closed, v_closed, self_intersect, u_multiplicities,
 *     v_multiplicities, u_knots, v_knots, knot_spec)
 * or complex, each part holding its own attributes:
 *   (B_SPLINE_SURFACE(u_degree, v_degree, control_points_list, surface_form,
 *     u_closed, v_closed, self_intersect)
 *    B_SPLINE_SURFACE_WITH_KNOTS(u_mult, v_mult, u_knots, v_knots, knot_spec)
 *    RATIONAL_B_SPLINE_SURFACE(weights_data) REPRESENTATION_ITEM(name) ...).
 * control_points_list[i][j] is the point i along u and j along v, as
 * ic_nurbs has it; the knots are written once each with their
 * multiplicities and are expanded here. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "step_surface.h"

/* The attributes, as value indices (-1 when absent). */
typedef struct {
    int degree[2], points, closed[2], mult[2], knots[2], weights;
} bspline_attrs;

static void attributes(const ic_step_file *f, const ic_step_instance *in, bspline_attrs *a)
{
    int base, with_knots;
    if (in->complex) {
        base = ic_step_part(f, in, "B_SPLINE_SURFACE");
        with_knots = ic_step_part(f, in, "B_SPLINE_SURFACE_WITH_KNOTS");
        a->weights = ic_step_param(f, ic_step_part(f, in, "RATIONAL_B_SPLINE_SURFACE"), 0);
    } else { /* the simple form: the name, then the same attributes in a row */
        base = with_knots = in->part;
        a->weights = -1;
    }
    const int b0 = in->complex ? 0 : 1, k0 = in->complex ? 0 : 8;
    for (int d = 0; d < 2; d++) {
        a->degree[d] = ic_step_param(f, base, b0 + d);
        a->closed[d] = ic_step_param(f, base, b0 + 4 + d);
        a->mult[d] = ic_step_param(f, with_knots, k0 + d);
        a->knots[d] = ic_step_param(f, with_knots, k0 + 2 + d);
    }
    a->points = ic_step_param(f, base, b0 + 2);
}

static int is_list(const ic_step_file *f, int v) { return v >= 0 && f->values[v].kind == IC_STEP_LIST; }

/* A whole number in 1..max, or -1. */
static int whole(const ic_step_file *f, int v, int max)
{
    double x;
    if (ic_step_number(f, v, &x) < 0 || x != floor(x) || x < 1 || x > max)
        return -1;
    return (int)x;
}

/* The sizes of an n_u x n_v list of lists (all rows the same length). */
static ic_status grid_size(const ic_step_file *f, int v, int count[2], const char *what,
                           const char *who, ic_error *err)
{
    if (!is_list(f, v) || f->values[v].count < 1)
        return ic_cad_fail(err, who, "its %s is not a list of lists", what);
    count[0] = f->values[v].count;
    count[1] = -1;
    for (int i = 0, row = f->values[v].child; row >= 0; i++, row = f->values[row].next) {
        if (!is_list(f, row))
            return ic_cad_fail(err, who, "row %d of its %s is not a list", i, what);
        if (count[1] >= 0 && f->values[row].count != count[1])
            return ic_cad_fail(err, who, "row %d of its %s has %d entries, row 0 has %d", i,
                               what, f->values[row].count, count[1]);
        count[1] = f->values[row].count;
    }
    return IC_OK;
}

/* Knot values and multiplicities expanded to count + degree + 1 knots. */
static ic_status expand_knots(const ic_step_file *f, int mults, int values, double *out,
                              int need, const char *dir, const char *who, ic_error *err)
{
    if (!is_list(f, mults) || !is_list(f, values) ||
        f->values[mults].count != f->values[values].count)
        return ic_cad_fail(err, who,
                           "its %s multiplicities and knots are not two lists of one length", dir);
    long sum = 0; /* of the multiplicities; each at most `need`, so no overflow */
    for (int m = f->values[mults].child, k = f->values[values].child; m >= 0 && k >= 0;
         m = f->values[m].next, k = f->values[k].next) {
        double t;
        const int times = whole(f, m, need);
        if (times < 0 || ic_step_number(f, k, &t) < 0)
            return ic_cad_fail(err, who,
                               "a %s multiplicity or knot is not a number (or the multiplicity "
                               "not a whole number from 1 to %d)",
                               dir, need);
        for (int r = 0; r < times; r++, sum++)
            if (sum < need)
                out[sum] = t;
    }
    if (sum != need)
        return ic_cad_fail(err, who,
                           "its %s multiplicities add up to %ld, but the degree and control "
                           "points need %d knots",
                           dir, sum, need);
    return IC_OK;
}

static ic_status read_points(const ic_step_file *f, int list, ic_cad_surface *s, const char *who,
                             ic_error *err)
{
    double *p = s->points_store;
    for (int row = f->values[list].child; row >= 0; row = f->values[row].next)
        for (int v = f->values[row].child; v >= 0; v = f->values[v].next, p += 3)
            if (ic_step_point(f, v, p, who, err) != IC_OK)
                return IC_ERR_INVALID;
    return IC_OK;
}

static ic_status read_weights(const ic_step_file *f, int list, const int count[2],
                              ic_cad_surface *s, const char *who, ic_error *err)
{
    int wcount[2];
    if (grid_size(f, list, wcount, "weights_data", who, err) != IC_OK)
        return IC_ERR_INVALID;
    if (wcount[0] != count[0] || wcount[1] != count[1])
        return ic_cad_fail(err, who, "its weights are %d x %d, its control points %d x %d",
                           wcount[0], wcount[1], count[0], count[1]);
    double *w = s->weights_store;
    for (int row = f->values[list].child; row >= 0; row = f->values[row].next)
        for (int v = f->values[row].child; v >= 0; v = f->values[v].next)
            if (ic_step_number(f, v, w++) < 0)
                return ic_cad_fail(err, who, "a weight is not a number");
    return IC_OK;
}

ic_status ic_step_bspline(const ic_step_file *f, const ic_step_instance *in, ic_cad_surface *out,
                          const char *who, ic_error *err)
{
    static const char *const dir[2] = {"u", "v"};
    bspline_attrs a;
    attributes(f, in, &a);
    if (in->complex && ic_step_part(f, in, "RATIONAL_B_SPLINE_SURFACE") >= 0 && a.weights < 0)
        return ic_cad_fail(err, who, "its RATIONAL_B_SPLINE_SURFACE has no weights");
    int degree[2], count[2], closed[2];
    for (int d = 0; d < 2; d++) {
        if ((degree[d] = whole(f, a.degree[d], IC_NURBS_MAX_DEGREE)) < 0)
            return ic_cad_fail(err, who, "its %s degree is not a whole number from 1 to %d",
                               dir[d], IC_NURBS_MAX_DEGREE);
        closed[d] = ic_step_is(f, a.closed[d], "T");
    }
    ic_status st = grid_size(f, a.points, count, "control_points_list", who, err);
    if (st == IC_OK)
        st = ic_cad_alloc_nurbs(out, degree, count, a.weights >= 0, who, err);
    for (int d = 0; d < 2 && st == IC_OK; d++)
        st = expand_knots(f, a.mult[d], a.knots[d], out->knots_store + (d ? count[0] + degree[0] + 1 : 0),
                          count[d] + degree[d] + 1, dir[d], who, err);
    if (st == IC_OK)
        st = read_points(f, a.points, out, who, err);
    if (st == IC_OK && a.weights >= 0)
        st = read_weights(f, a.weights, count, out, who, err);
    return st == IC_OK ? ic_cad_finish_nurbs(out, closed, who, err) : st;
}
