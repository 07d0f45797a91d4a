/* Traced intersections as VTK legacy PolyData (docs/output-formats.md):
 * one polyline per curve through its traced points and, where the curve
 * has its B-spline and a stretch turns more than VTK_STRETCH_TURN, points
 * of the B-spline between them, with the apparatus of the B-spline there
 * (array "traced" = 0), so the polyline stays smooth when zoomed. Numbers
 * are written with 17 significant digits. */
#include "common/args.h"
#include "intercurve/bspline.h"
#include "intercurve/writers.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "common/vec3.h"

/* radians: a stretch between traced points turning more than this gets
 * points of the B-spline, so that each chord turns at most this much (its
 * sagitta is a^2 / 8 of the radius: 5e-5) */
#define VTK_STRETCH_TURN 0.02
/* chords per stretch at most */
#define VTK_MAX_CHORDS 64
/* relative: |c' x c''| below this (of |c'|^3 / size) means no frame */
#define VTK_FLAT_REL 1e-12

/* one point of a polyline: a traced point, or one of the B-spline */
typedef struct {
    double s, xyz[3], t[3], n[3], b[3], kappa, tau;
    int frame, traced;
} vtk_point;

static void from_traced(vtk_point *v, const ic_trace_point *p)
{
    v->s = p->s;
    memcpy(v->xyz, p->xyz, sizeof v->xyz);
    memcpy(v->t, p->t, sizeof v->t);
    memcpy(v->n, p->n, sizeof v->n);
    memcpy(v->b, p->b, sizeof v->b);
    v->kappa = p->kappa;
    v->tau = p->tau;
    v->frame = p->frame_defined;
    v->traced = 1;
}

/* The B-spline's point and apparatus at s from its derivatives: t = c' /
 * |c'|, b along c' x c'', kappa = |c' x c''| / |c'|^3, tau = (c' x c'') .
 * c''' / |c' x c''|^2. 0 where it cannot be evaluated. */
static int from_bspline(vtk_point *v, const ic_bspline *c, double s)
{
    double d[12], cr[3];
    if (ic_bspline_eval(c, s, 3, d, NULL) != IC_OK)
        return 0;
    const double speed = ic_norm3(d + 3);
    if (!(speed > 0))
        return 0;
    ic_cross3(cr, d + 3, d + 6);
    const double area = ic_norm3(cr);
    memset(v, 0, sizeof *v);
    v->s = s;
    memcpy(v->xyz, d, sizeof v->xyz);
    ic_scale3(v->t, d + 3, 1 / speed);
    v->kappa = area / (speed * speed * speed);
    v->frame = area > VTK_FLAT_REL * speed * speed * speed;
    if (v->frame) {
        ic_scale3(v->b, cr, 1 / area);
        ic_cross3(v->n, v->b, v->t);
        v->tau = ic_dot3(cr, d + 9) / (area * area);
    }
    return 1;
}

/* Curve i's polyline into out (NULL: only counted): its traced points and
 * the B-spline's between them. Returns how many. */
static int curve_polyline(const ic_trace_result *res, int i, vtk_point *out)
{
    const ic_trace_curve *c = ic_trace_result_curve(res, i);
    const ic_curve_fit *fit = ic_trace_result_fit(res, i);
    int n = 0;
    for (int k = 0; k < c->npoints; k++) {
        const ic_trace_point *p = &c->points[k], *q = k > 0 ? &c->points[k - 1] : NULL;
        const double turn = q ? fmax(fabs(p->kappa), fabs(q->kappa)) * (p->s - q->s) : 0;
        const int chords = fit && isfinite(turn)
                               ? (int)fmin(VTK_MAX_CHORDS, ceil(turn / VTK_STRETCH_TURN))
                               : 1;
        for (int j = 1; j < chords; j++) {
            vtk_point v;
            if (!from_bspline(&v, &fit->curve, q->s + (p->s - q->s) * j / chords))
                continue;
            if (out)
                out[n] = v;
            n++;
        }
        if (out)
            from_traced(&out[n], p);
        n++;
    }
    return n;
}

/* One point-data array over every curve point, then the special points
 * (which have no frame: zero vectors, zero scalars, curve -1, traced 1). */
typedef enum {
    FIELD_T,
    FIELD_N,
    FIELD_B,
    FIELD_KAPPA,
    FIELD_TAU,
    FIELD_S,
    FIELD_CURVE,
    FIELD_TRACED
} field;

static void vtk_array(FILE *f, const vtk_point *pts, const int *curve_of, int npts, int nspecial,
                      field which)
{
    static const char *const names[] = {"t", "n", "b", "kappa", "tau", "s", "curve", "traced"};
    const int vector = which <= FIELD_B, integer = which >= FIELD_CURVE;
    if (vector)
        fprintf(f, "VECTORS %s double\n", names[which]);
    else
        fprintf(f, "SCALARS %s %s 1\nLOOKUP_TABLE default\n", names[which],
                integer ? "int" : "double");
    for (int k = 0; k < npts; k++) {
        const vtk_point *p = &pts[k];
        const double zero[3] = {0, 0, 0};
        const double *v = which == FIELD_T ? p->t : !p->frame ? zero : which == FIELD_N ? p->n : p->b;
        if (vector)
            fprintf(f, "%.17g %.17g %.17g\n", v[0], v[1], v[2]);
        else if (integer)
            fprintf(f, "%d\n", which == FIELD_CURVE ? curve_of[k] : p->traced);
        else
            fprintf(f, "%.17g\n",
                    which == FIELD_KAPPA ? p->kappa
                    : which == FIELD_S   ? p->s
                    : p->frame           ? p->tau
                                         : 0.0);
    }
    for (int i = 0; i < nspecial; i++)
        fputs(vector                    ? "0 0 0\n"
              : which == FIELD_CURVE    ? "-1\n"
              : which == FIELD_TRACED   ? "1\n"
                                        : "0\n",
              f);
}

static void vtk_geometry(FILE *f, const ic_trace_result *res, const vtk_point *pts,
                         const int *count, int npts)
{
    const int ncurves = ic_trace_result_num_curves(res);
    const int nspecial = ic_trace_result_num_specials(res);
    fprintf(f, "POINTS %d double\n", npts + nspecial);
    for (int k = 0; k < npts; k++)
        fprintf(f, "%.17g %.17g %.17g\n", pts[k].xyz[0], pts[k].xyz[1], pts[k].xyz[2]);
    for (int i = 0; i < nspecial; i++) {
        const double *x = ic_trace_result_special(res, i)->xyz;
        fprintf(f, "%.17g %.17g %.17g\n", x[0], x[1], x[2]);
    }
    if (nspecial > 0) {
        fprintf(f, "VERTICES %d %d\n", nspecial, 2 * nspecial);
        for (int i = 0; i < nspecial; i++)
            fprintf(f, "1 %d\n", npts + i);
    }
    if (ncurves > 0) {
        fprintf(f, "LINES %d %d\n", ncurves, ncurves + npts);
        for (int i = 0, first = 0; i < ncurves; first += count[i++]) {
            fprintf(f, "%d", count[i]);
            for (int k = 0; k < count[i]; k++)
                fprintf(f, " %d", first + k);
            fputc('\n', f);
        }
    }
}

ic_status ic_trace_write_vtk(FILE *f, const ic_trace_result *res, ic_error *err)
{
    IC_ARG_NOT_NULL(f, "f");
    IC_ARG_NOT_NULL(res, "res");
    const int ncurves = ic_trace_result_num_curves(res);
    const int nspecial = ic_trace_result_num_specials(res);
    int *count = malloc(sizeof *count * (size_t)(ncurves + 1)), npts = 0;
    for (int i = 0; count && i < ncurves; i++)
        npts += count[i] = curve_polyline(res, i, NULL);
    vtk_point *pts = count ? malloc(sizeof *pts * (size_t)(npts + 1)) : NULL;
    int *curve_of = pts ? malloc(sizeof *curve_of * (size_t)(npts + 1)) : NULL;
    if (!curve_of) {
        free(count);
        free(pts);
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory writing the VTK output");
    }
    for (int i = 0, first = 0; i < ncurves; first += count[i++]) {
        curve_polyline(res, i, pts + first);
        for (int k = 0; k < count[i]; k++)
            curve_of[first + k] = i;
    }
    fputs("# vtk DataFile Version 3.0\nintercurve trace\nASCII\nDATASET POLYDATA\n", f);
    vtk_geometry(f, res, pts, count, npts);
    if (npts + nspecial > 0) {
        fprintf(f, "POINT_DATA %d\n", npts + nspecial);
        for (field w = FIELD_T; w <= FIELD_TRACED; w++)
            vtk_array(f, pts, curve_of, npts, nspecial, w);
    }
    free(count);
    free(pts);
    free(curve_of);
    if (ferror(f))
        return ic_error_set(err, IC_ERR_IO, 0, "writing the VTK output failed");
    return IC_OK;
}
