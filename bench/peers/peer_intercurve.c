/* intercurve on a case: the two nets as NURBS surfaces (ic_surface_new_nurbs),
 * or the exact surfaces as implicit primitives (ic_surface_new_primitive, in
 * a box around both nets, as OpenCASCADE's analytic engine gets them), the
 * whole intersection traced with the default options (ic_trace), its own
 * curvature and torsion at every traced point. */
#include <math.h>
#include <stdio.h>
#include <time.h>

#include "intercurve.h"
#include "peers.h"

/* a surface that differs from our own evaluation of the net by more than this
 * (length units) means the conversion is wrong */
#define CONVERSION_TOL 1e-12

static double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static ic_status make_surface(ic_surface **s, const case_net *net, ic_error *err)
{
    const ic_nurbs nurbs = {
        .degree = {net->degree[0], net->degree[1]},
        .count = {net->count[0], net->count[1]},
        .knots = {net->knots[0], net->knots[1]},
        .points = net->points,
        .weights = net->weights,
        .periodic = {net->periodic[0], net->periodic[1]},
    };
    return ic_surface_new_nurbs(s, &nurbs, err);
}

/* Largest difference between intercurve's surface and our evaluation of the
 * net, on the 5 x 5 parameter points the other engines are checked on. */
static double conversion_error(ic_surface *s, const case_net *net)
{
    double worst = 0.0;
    for (int a = 0; a <= 4; a++)
        for (int b = 0; b <= 4; b++) {
            double par[2], theirs[3], ours[3];
            for (int d = 0; d < 2; d++) {
                const double lo = net->knots[d][net->degree[d]], hi = net->knots[d][net->count[d]];
                par[d] = lo + (hi - lo) * (0.1 + 0.2 * (d ? b : a));
            }
            ic_error err;
            if (ic_surface_eval(s, theirs, par, &err) != IC_OK)
                return INFINITY;
            net_eval(net, par[0], par[1], ours);
            for (int k = 0; k < 3; k++)
                worst = fmax(worst, fabs(theirs[k] - ours[k]));
        }
    return worst;
}

/* The exact surface as an implicit primitive, placed as the net is. */
static ic_status make_primitive(ic_surface **s, const exact_surface *e, ic_error *err)
{
    ic_primitive p = {0};
    for (int k = 0; k < 3; k++) {
        p.center[k] = e->center[k];
        p.axis[k] = e->kind == EXACT_PLANE ? 0.0 : e->axis[k];
        p.normal[k] = e->kind == EXACT_PLANE ? e->axis[k] : 0.0;
        p.ref_direction[k] = e->ref[k];
    }
    p.kind = e->kind == EXACT_PLANE    ? IC_PRIM_PLANE
             : e->kind == EXACT_SPHERE ? IC_PRIM_SPHERE
             : e->kind == EXACT_TORUS  ? IC_PRIM_TORUS
                                       : IC_PRIM_CYLINDER;
    p.radius = e->radius;
    p.major_radius = e->major;
    return ic_surface_new_primitive(s, &p, IC_IMPLICIT, err);
}

/* relative to the box's size: the margin added on every side of the box
 * where both nets lie (a plane's net is flat) */
#define PRIMITIVE_BOX_MARGIN 0.05

/* The box of the primitives: where the bounding boxes of both nets' control
 * points (which hold their patches) overlap, with a margin. */
static void primitive_box(const bench_case *c, double box[3][2])
{
    const case_net *nets[2] = {&c->netA, &c->netB};
    double size = 0.0;
    for (int k = 0; k < 3; k++) {
        box[k][0] = -INFINITY, box[k][1] = INFINITY;
        for (int n = 0; n < 2; n++) {
            double lo = INFINITY, hi = -INFINITY;
            for (int i = 0; i < nets[n]->count[0] * nets[n]->count[1]; i++) {
                lo = fmin(lo, nets[n]->points[3 * i + k]);
                hi = fmax(hi, nets[n]->points[3 * i + k]);
            }
            box[k][0] = fmax(box[k][0], lo), box[k][1] = fmin(box[k][1], hi);
        }
        size = fmax(size, box[k][1] - box[k][0]);
    }
    for (int k = 0; k < 3; k++)
        box[k][0] -= PRIMITIVE_BOX_MARGIN * size, box[k][1] += PRIMITIVE_BOX_MARGIN * size;
}

static int collect_specials(const ic_trace_result *res, peer_output *out);

static int collect(const ic_trace_result *res, peer_output *out)
{
    out->ncurves = ic_trace_result_num_curves(res);
    for (int i = 0; i < out->ncurves; i++) {
        const ic_trace_curve *cv = ic_trace_result_curve(res, i);
        out->length += cv->length;
        if (cv->tangential)
            peer_output_note(out, "curve %d tangential; ", i);
        for (int k = 0; k < cv->npoints; k++) {
            const ic_trace_point *p = cv->points + k;
            if (peer_output_add(out, p->xyz, p->kappa, p->tau, 1, p->frame_defined) != 0)
                return -1;
        }
    }
    return collect_specials(res, out);
}

/* The isolated points, the types of the special points, the report. */
static int collect_specials(const ic_trace_result *res, peer_output *out)
{
    for (int i = 0; i < ic_trace_result_num_specials(res); i++) {
        const ic_trace_special *sp = ic_trace_result_special(res, i);
        peer_output_note(out, "%s%s; ", ic_point_type_name(sp->type),
                         sp->approximate ? " (approx.)" : "");
        if (sp->type == IC_POINT_ISOLATED_CONTACT) {
            if (out->npoints < PEER_MAX_POINTS)
                for (int k = 0; k < 3; k++)
                    out->points[out->npoints][k] = sp->xyz[k];
            out->npoints++;
        }
    }
    const ic_trace_report *rep = ic_trace_result_report(res);
    peer_output_note(out, "complete=%d", rep->complete);
    if (rep->nfailures > 0)
        peer_output_note(out, " (%d undecided regions, listed on stderr)", rep->nfailures);
    for (int i = 0; i < rep->nfailures; i++)
        fprintf(stderr, "intercurve: undecided: %s\n", rep->failures[i]);
    return 0;
}

/* Samples along each fitted B-spline (docs/bspline.md): SAMPLES_PER_STRETCH
 * points between traced points, curvature and torsion from the B-spline's
 * own derivatives, as for the other engines' curves. */
enum { SAMPLES_PER_STRETCH = 4 };

static int collect_bsplines(const ic_trace_result *res, peer_output *out)
{
    out->ncurves = ic_trace_result_num_curves(res);
    for (int i = 0; i < out->ncurves; i++) {
        const ic_trace_curve *cv = ic_trace_result_curve(res, i);
        const ic_curve_fit *fit = ic_trace_result_fit(res, i);
        out->length += cv->length;
        if (!fit) {
            peer_output_note(out, "curve %d not fitted; ", i);
            continue;
        }
        const double s0 = cv->points[0].s, s1 = cv->points[cv->npoints - 1].s;
        const int n = SAMPLES_PER_STRETCH * (cv->npoints - 1);
        for (int k = 0; k <= n; k++) {
            double d[12], deriv[3][3];
            if (ic_bspline_eval(&fit->curve, s0 + (s1 - s0) * k / n, 3, d, NULL) != IC_OK)
                return -1;
            for (int r = 0; r < 3; r++)
                for (int j = 0; j < 3; j++)
                    deriv[r][j] = d[3 * (r + 1) + j];
            if (peer_output_add_derivs(out, d, (const double(*)[3])deriv, 1.0) != 0)
                return -1;
        }
    }
    peer_output_note(out, "fit error %.1e; ", ic_trace_result_report(res)->fit_error);
    return collect_specials(res, out);
}

/* intercurve, traced on the nets or (`primitives`) the exact surfaces (and
 * with `fitted`, its curves fitted as B-splines, timed with the trace, and
 * scored on them). */
static int run_intercurve(const bench_case *c, peer_output *out, double *seconds, int fitted,
                          int primitives)
{
    ic_surface *A = NULL, *B = NULL;
    ic_pair *pair = NULL;
    ic_trace_result *res = NULL;
    ic_error err;
    int rc = -1;
    const ic_status made = primitives ? make_primitive(&A, &c->A, &err) == IC_OK
                                            ? make_primitive(&B, &c->B, &err)
                                            : IC_ERR_INVALID
                           : make_surface(&A, &c->netA, &err) == IC_OK
                               ? make_surface(&B, &c->netB, &err)
                               : IC_ERR_INVALID;
    if (made != IC_OK || ic_pair_new(&pair, A, B, &err) != IC_OK) {
        peer_output_note(out, "setup: %s", err.message);
        goto done;
    }
    const double conv =
        primitives ? 0.0 : fmax(conversion_error(A, &c->netA), conversion_error(B, &c->netB));
    if (!(conv <= CONVERSION_TOL)) {
        peer_output_note(out, "the intercurve surfaces are not the nets (off by %.1e)", conv);
        goto done;
    }
    ic_trace_options opt;
    ic_trace_defaults(&opt);
    if (primitives) {
        primitive_box(c, opt.box);
        opt.has_box = 1;
    }
    const double t0 = now_seconds();
    ic_status st = ic_trace(&res, pair, &opt, &err);
    if (st == IC_OK && fitted)
        st = ic_trace_fit(res, pair, IC_TRACE_FIT_TOL_DEFAULT, &err);
    *seconds = now_seconds() - t0;
    if (st != IC_OK) {
        out->failed = 1;
        peer_output_note(out, "ic_trace: %s: %s", ic_status_name(st), err.message);
        rc = 0;
        goto done;
    }
    /* how it was found: the search, or a closed form (on primitives, or on
     * nets recognised as them) */
    peer_output_note(out, "%s; ", ic_trace_result_report(res)->method);
    rc = fitted ? collect_bsplines(res, out) : collect(res, out);
done:
    ic_trace_result_free(res);
    ic_pair_free(pair);
    ic_surface_free(A);
    ic_surface_free(B);
    return rc;
}

int peer_intercurve(const bench_case *c, peer_output *out, double *seconds)
{
    return run_intercurve(c, out, seconds, 0, 0);
}

int peer_intercurve_bspline(const bench_case *c, peer_output *out, double *seconds)
{
    return run_intercurve(c, out, seconds, 1, 0);
}

int peer_intercurve_primitives(const bench_case *c, peer_output *out, double *seconds)
{
    return run_intercurve(c, out, seconds, 0, 1);
}
