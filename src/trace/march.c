/*
 * The marching core (trace.h): Taylor predictor, Newton corrector in the
 * plane normal to the curve, step control by truncation error and chord
 * height, events.
 */
#include "common/args.h"
#include "core/trace_constants.h"
#include "trace_internal.h"
#include "common/vec3.h"
#include "local/pair_access.h"
#include "tangential_curve.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

struct ic_tracer {
    ic_pair *pair;
    ic_trace_options opt;
    int par[2]; /* which sheets are parametric */
    double domain[2][2][2];
    int periodic[2][2];
    int dir; /* +1: along t = N_A x N_B, -1: against */
    ic_local_point cur;
    ic_local_result res; /* apparatus at cur, order opt.order */
    double s;
    double start_xyz[3], start_t[3];
    ic_trace_point *pts;
    int n, cap;
    int done;
    int tcurve; /* marching along a tangential curve */
    int knot_line; /* the point being recorded lies on knot lines: bit s for sheet s */
    double deadline; /* monotonic seconds; 0: none (ic_tracer_set_deadline) */
};

const char *ic_trace_event_name(ic_trace_event ev)
{
    static const char *const names[] = {"continue",   "closed", "left-domain", "left-box",
                                        "tangential", "budget", "failed"};
    return ev >= IC_TRACE_CONTINUE && ev <= IC_TRACE_FAILED ? names[ev] : "unknown";
}

ic_status ic_tracer_new(ic_tracer **out, ic_pair *pair, const ic_trace_options *opt, ic_error *err)
{
    IC_ARG_NOT_NULL(out, "tr");
    *out = NULL;
    IC_ARG_NOT_NULL(pair, "pair");
    IC_ARG_NOT_NULL(opt, "opt");
    const ic_trace_options a = ic_trace_absolute_options(opt, ic_trace_problem_scale(pair, opt));
    return ic_tracer_new_absolute(out, pair, &a, err);
}

ic_status ic_tracer_new_absolute(ic_tracer **out, ic_pair *pair, const ic_trace_options *opt,
                                 ic_error *err)
{
    *out = NULL;
    if (!pair || !opt || opt->order < 3 || opt->order > 12 || !(opt->tol > 0) ||
        !(opt->chord > 0) || !(opt->max_step > 0) || opt->max_points < 2)
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            "tracer: invalid options (order 3..12, positive tolerances)");
    ic_tracer *tr = calloc(1, sizeof *tr);
    if (!tr)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory creating a tracer");
    tr->pair = pair;
    tr->opt = *opt;
    for (int s = 0; s < 2; s++) {
        ic_surface *srf = ic_pair_surface(pair, s);
        tr->par[s] = ic_surface_get_kind(srf) == IC_PARAMETRIC;
        if (tr->par[s])
            ic_surface_get_domain(srf, tr->domain[s], tr->periodic[s]);
    }
    *out = tr;
    return IC_OK;
}

void ic_tracer_free(ic_tracer *tr)
{
    if (!tr)
        return;
    free(tr->pts);
    free(tr);
}

int ic_tracer_num_points(const ic_tracer *tr) { return tr ? tr->n : 0; }
const ic_trace_point *ic_tracer_point(const ic_tracer *tr, int i)
{
    return tr && i >= 0 && i < tr->n ? &tr->pts[i] : NULL;
}

/* t along the marching direction */
static void march_t(const ic_tracer *tr, const ic_local_result *res, double *t)
{
    ic_scale3(t, res->branches[0].t, (double)tr->dir);
}

static ic_status record(ic_tracer *tr, ic_error *err)
{
    if (tr->n == tr->cap) {
        const int cap = tr->cap ? 2 * tr->cap : 256;
        ic_trace_point *p = realloc(tr->pts, (size_t)cap * sizeof *p);
        if (!p)
            return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory tracing a curve");
        tr->pts = p;
        tr->cap = cap;
    }
    const ic_branch *br = &tr->res.branches[0];
    ic_trace_point *p = &tr->pts[tr->n++];
    memset(p, 0, sizeof *p);
    p->s = tr->s;
    memcpy(p->xyz, tr->cur.xyz, sizeof p->xyz);
    memcpy(p->params, tr->cur.params, sizeof p->params);
    march_t(tr, &tr->res, p->t);
    memcpy(p->n, br->n, sizeof p->n);
    ic_scale3(p->b, br->b, (double)tr->dir);
    p->kappa = br->kappa;
    p->tau = br->tau;
    p->angle = tr->res.angle;
    p->frame_defined = br->frame_defined;
    p->knot_line = tr->knot_line;
    p->knot_side = tr->knot_line ? 1 : 0;
    return IC_OK;
}

/* The angle between the normal lines at pt (as ic_local_apparatus measures
 * it), from first derivatives only; -1 where a surface is singular. */
static double normals_angle(const ic_tracer *tr, const ic_local_point *pt)
{
    double N[2][3];
    for (int s = 0; s < 2; s++) {
        ic_surface_geometry g;
        if (ic_surface_normal_at(ic_pair_surface(tr->pair, s), &g,
                                 tr->par[s] ? pt->params[s] : pt->xyz, NULL) != IC_OK)
            return -1;
        memcpy(N[s], g.normal, sizeof N[s]);
    }
    double cr[3];
    ic_cross3(cr, N[0], N[1]);
    return atan2(ic_norm3(cr), fabs(ic_dot3(N[0], N[1])));
}

/* The apparatus at a point; IC_TRACE_TANGENTIAL if it is tangential. */
static ic_status apparatus(ic_tracer *tr, ic_local_result *res, const ic_local_point *pt,
                           int *tangential, ic_error *err)
{
    ic_local_options o = tr->opt.local;
    ic_status st = ic_local_apparatus(tr->pair, res, pt, tr->opt.order, IC_METHOD_JET, &o, err);
    *tangential = 0;
    if (st == IC_OK && res->type != IC_POINT_TRANSVERSAL)
        *tangential = 1;
    return st;
}

ic_status ic_tracer_start(ic_tracer *tr, const ic_local_point *start, int direction, ic_error *err)
{
    IC_ARG_NOT_NULL(tr, "tr");
    IC_ARG_NOT_NULL(start, "start");
    tr->n = 0;
    tr->s = 0.0;
    tr->done = 0;
    tr->dir = direction < 0 ? -1 : 1;
    tr->cur = *start;
    int tangential;
    ic_status st = apparatus(tr, &tr->res, start, &tangential, err);
    if (st != IC_OK)
        return st;
    /* a point of a tangential curve starts a march along it; other
     * tangential points are ends, not starts */
    tr->tcurve = tangential && tr->res.type == IC_POINT_TANGENTIAL_CURVE && tr->res.nbranches >= 1;
    if (tangential && !tr->tcurve)
        return ic_error_set(err, IC_ERR_UNABLE, 0, "a curve cannot start at a tangential point");
    memcpy(tr->start_xyz, start->xyz, sizeof tr->start_xyz);
    march_t(tr, &tr->res, tr->start_t);
    return record(tr, err);
}

/* Taylor coefficients (marching direction) of the point and parameters at cur */
static void predict(const ic_tracer *tr, double h, double *X, double params[2][2])
{
    const ic_branch *br = &tr->res.branches[0];
    memcpy(X, tr->cur.xyz, 3 * sizeof *X);
    memcpy(params, tr->cur.params, sizeof tr->cur.params);
    double f = 1.0;
    for (int k = 1; k <= br->order; k++) {
        f *= tr->dir * h / k;
        ic_axpy3(X, X, f, br->derivs[k - 1]);
        for (int s = 0; s < 2; s++)
            if (tr->par[s] && k <= br->param_order) {
                params[s][0] += f * br->param_derivs[s][k - 1][0];
                params[s][1] += f * br->param_derivs[s][k - 1][1];
            }
    }
}

/* The step length from the truncation error and the chord height. */
static double step_length(const ic_tracer *tr)
{
    const ic_branch *br = &tr->res.branches[0];
    double h = tr->opt.max_step, fact = 1.0;
    for (int k = 1; k <= br->order; k++) {
        fact *= k;
        if (k >= br->order - 1) { /* the last two terms bound the truncation */
            const double a = ic_norm3(br->derivs[k - 1]) / fact;
            if (a > 0)
                h = fmin(h, pow(tr->opt.tol / a, 1.0 / k));
        }
    }
    if (br->kappa > 0)
        h = fmin(h, sqrt(8 * tr->opt.chord / br->kappa));
    return h;
}

/* A boundary the curve crosses: a parameter of a sheet, or a coordinate of
 * the box (sheet -1), and the bound. */
typedef struct {
    int sheet, index;
    double bound;
} boundary;

/* The period of sheet s's parameter i, 0 if it does not wrap. */
static double period_of(const ic_tracer *tr, int s, int i)
{
    return tr->periodic[s][i] ? tr->domain[s][i][1] - tr->domain[s][i][0] : 0;
}

/* A parameter value moved by whole periods next to `near` (unchanged where
 * the parameter does not wrap): the corrector returns wrapped values. */
static double unwrap_near(const ic_tracer *tr, int s, int i, double x, double near)
{
    const double P = period_of(tr, s, i);
    return P > 0 ? x + P * round((near - x) / P) : x;
}

static double coordinate(const ic_tracer *tr, const ic_local_point *pt, const boundary *b)
{
    if (b->sheet < 0)
        return pt->xyz[b->index];
    return unwrap_near(tr, b->sheet, b->index, pt->params[b->sheet][b->index], b->bound);
}

static int outside(const ic_tracer *tr, const ic_local_point *pt, ic_trace_event *ev, boundary *b)
{
    for (int s = 0; s < 2; s++)
        if (tr->par[s])
            for (int i = 0; i < 2; i++) {
                const double *d = tr->domain[s][i], x = pt->params[s][i];
                if (!tr->periodic[s][i] && (x < d[0] || x > d[1])) {
                    *ev = IC_TRACE_LEFT_DOMAIN;
                    *b = (boundary){s, i, x < d[0] ? d[0] : d[1]};
                    return 1;
                }
            }
    if (tr->opt.has_box)
        for (int k = 0; k < 3; k++) {
            const double *d = tr->opt.box[k], x = pt->xyz[k];
            if (x < d[0] || x > d[1]) {
                *ev = IC_TRACE_LEFT_BOX;
                *b = (boundary){-1, k, x < d[0] ? d[0] : d[1]};
                return 1;
            }
        }
    return 0;
}

int ic_tracer_outside(const ic_tracer *tr, const ic_local_point *pt)
{
    ic_trace_event ev;
    boundary b;
    return outside(tr, pt, &ev, &b);
}

static int corrected(const ic_tracer *tr, double h, ic_local_point *next, double *X);

/* A step's two ends: the corrected point `next` at predictor step h and
 * its apparatus `res`. */
typedef struct {
    const ic_tracer *tr;
    double h;
    const ic_local_point *next;
    const ic_local_result *res;
} step_ends;

/* Sheet s's parameter i along the step at tau: the cubic Hermite
 * interpolant of its values and derivatives d/ds at both ends (the
 * predictor's parameters are of lower order than its points). */
static double hermite_param(const step_ends *e, int s, int i, double near, double tau)
{
    const ic_tracer *tr = e->tr;
    const double h = e->h, x = tau / h;
    const double a0 = unwrap_near(tr, s, i, tr->cur.params[s][i], near);
    const double a1 = unwrap_near(tr, s, i, e->next->params[s][i], near);
    const double d0 = tr->dir * tr->res.branches[0].param_derivs[s][0][i] * h;
    const double d1 = tr->dir * e->res->branches[0].param_derivs[s][0][i] * h;
    const double x2 = x * x, x3 = x2 * x;
    return (2 * x3 - 3 * x2 + 1) * a0 + (x3 - 2 * x2 + x) * d0 + (-2 * x3 + 3 * x2) * a1 +
           (x3 - x2) * d1;
}

/* How far past boundary b the curve is at step tau (< 0: inside), along the
 * predictor (a box face) or the Hermite interpolant (a domain edge), and
 * the margin of that estimate. */
static double past(const step_ends *e, const boundary *b, int upper, double tau, double *margin)
{
    const ic_tracer *tr = e->tr;
    double x;
    if (b->sheet < 0) {
        double X[3], params[2][2];
        predict(tr, tau, X, params);
        x = X[b->index];
        *margin = IC_TRACE_EXCURSION_TOLS * tr->opt.tol;
    } else {
        x = hermite_param(e, b->sheet, b->index, b->bound, tau);
        const double width = tr->domain[b->sheet][b->index][1] - tr->domain[b->sheet][b->index][0];
        *margin = IC_TRACE_EXCURSION_TOLS * tr->opt.tol * width / tr->opt.local.scale;
    }
    return upper ? x - b->bound : b->bound - x;
}

/* The largest of past() over the step near sample j (golden section over
 * the two intervals beside it): *tau where. */
static double furthest(const step_ends *e, const boundary *b, int upper, int j, double *tau,
                       double *margin)
{
    const double dt = e->h / IC_TRACE_EXCURSION_SAMPLES, g = 0.5 * (sqrt(5.0) - 1.0);
    double a = fmax(0.0, (j - 1) * dt), c = fmin(e->h, (j + 1) * dt);
    for (int it = 0; it < IC_TRACE_EXCURSION_SECTIONS; it++) {
        const double x1 = c - g * (c - a), x2 = a + g * (c - a);
        if (past(e, b, upper, x1, margin) > past(e, b, upper, x2, margin))
            c = x2;
        else
            a = x1;
    }
    *tau = 0.5 * (a + c);
    return past(e, b, upper, *tau, margin);
}

/* The bounds a march may cross: the box's faces and the edges of the
 * domains that do not wrap; *n of them, with which side each is. */
static int bounds(const ic_tracer *tr, boundary *out, int *upper)
{
    int n = 0;
    for (int s = 0; s < 2; s++)
        for (int i = 0; tr->par[s] && i < 2; i++)
            for (int side = 0; side < 2 && !tr->periodic[s][i]; side++, n++)
                out[n] = (boundary){s, i, tr->domain[s][i][side]}, upper[n] = side;
    for (int k = 0; tr->opt.has_box && k < 3; k++)
        for (int side = 0; side < 2; side++, n++)
            out[n] = (boundary){-1, k, tr->opt.box[k][side]}, upper[n] = side;
    return n;
}

/* The step (e) from cur, inside at both ends, leaves the box or a domain
 * between them (IC_TRACE_EXCURSION_*): 1 with *hx, a step to a corrected
 * point outside, and the boundary *b (the first along the step). */
static int excursion(const step_ends *e, double *hx, boundary *b, ic_trace_event *ev)
{
    const ic_tracer *tr = e->tr;
    const double h = e->h;
    boundary all[14];
    int upper[14];
    const int n = bounds(tr, all, upper);
    double first = 2.0 * h;
    for (int q = 0; q < n; q++) {
        int best = 0;
        double gbest = -HUGE_VAL, margin = 0.0;
        for (int j = 1; j < IC_TRACE_EXCURSION_SAMPLES; j++) {
            const double g = past(e, &all[q], upper[q], j * h / IC_TRACE_EXCURSION_SAMPLES,
                                  &margin);
            if (g > gbest)
                gbest = g, best = j;
        }
        /* the reach in the coordinate's own units: margin is tol there */
        const double reach = IC_TRACE_EXCURSION_REACH * h * margin /
                             (IC_TRACE_EXCURSION_TOLS * tr->opt.tol);
        double tau;
        if (gbest < -reach || furthest(e, &all[q], upper[q], best, &tau, &margin) < -margin ||
            tau >= first)
            continue;
        ic_local_point mid;
        double X[3];
        ic_trace_event ev_here;
        boundary bd;
        if (corrected(tr, tau, &mid, X) && outside(tr, &mid, &ev_here, &bd))
            first = tau, *hx = tau, *b = bd, *ev = ev_here;
    }
    return first < 2.0 * h;
}

/* Adds h (du/ds, dv/ds) of sheet s to uv: the march tangent t = R_u du/ds
 * + R_v dv/ds solved by least squares in the sheet's tangent basis. 0 where
 * the sheet is singular. */
static int param_velocity(const ic_tracer *tr, int s, double h, double uv[2])
{
    ic_surface_geometry g;
    if (ic_surface_normal_at(ic_pair_surface(tr->pair, s), &g, tr->cur.params[s], NULL) != IC_OK)
        return 0;
    double t[3];
    march_t(tr, &tr->res, t);
    const double E = ic_dot3(g.basis[0], g.basis[0]), F = ic_dot3(g.basis[0], g.basis[1]);
    const double G = ic_dot3(g.basis[1], g.basis[1]);
    const double a = ic_dot3(g.basis[0], t), b = ic_dot3(g.basis[1], t), det = E * G - F * F;
    if (!(det > 0))
        return 0;
    uv[0] += h * (G * a - F * b) / det;
    uv[1] += h * (E * b - F * a) / det;
    return 1;
}

/* A curve that reached a domain edge or a box face exactly (a step landed on
 * it) and heads out: no corrected point exists beyond it (the projection
 * onto a parametric sheet stays in its domain), so every step fails; it has
 * left, at its current point. Within IC_TRACE_EDGE_REL of the domain's
 * width or of L, and the predicted step crosses the bound. */
static int on_boundary_heading_out(const ic_tracer *tr, ic_trace_event *event)
{
    ic_local_point ahead = tr->cur;
    const double h = step_length(tr);
    predict(tr, h, ahead.xyz, ahead.params);
    if (tr->res.branches[0].param_order < 1) /* a tangential curve's branch */
        for (int s = 0; s < 2; s++)
            if (tr->par[s] && !param_velocity(tr, s, h, ahead.params[s]))
                return 0;
    boundary b;
    if (!outside(tr, &ahead, event, &b))
        return 0;
    const double width = b.sheet < 0 ? tr->opt.local.scale
                                     : tr->domain[b.sheet][b.index][1] -
                                           tr->domain[b.sheet][b.index][0];
    return fabs(coordinate(tr, &tr->cur, &b) - b.bound) <= IC_TRACE_EDGE_REL * width;
}

/* The corrected point after a step of length h (0 if the corrector fails);
 * X receives the predicted point. */
/* The arc length of an accepted step: the predictor's parameter h plus
 * how far the corrector moved the point along the curve, (next - X) . t
 * with t the predictor's unit tangent at h. An accurate predictor leaves
 * that term at the truncation error; where the jets are poor (two sheets
 * meeting at a small angle, by the Whitney umbrella's pinch point) it
 * carries what s += h alone would miss. */
static double step_arc(const ic_tracer *tr, double h, const double *X, const double *next)
{
    double params[2][2], Y[3], t[3], d[3];
    const double dh = 1e-6 * h;
    predict(tr, h + dh, Y, params);
    ic_axpy3(t, Y, -1.0, X);
    const double len = ic_norm3(t);
    if (!(len > 0))
        return h;
    ic_scale3(t, t, 1 / len);
    ic_axpy3(d, next, -1.0, X);
    const double along = ic_dot3(d, t);
    return isfinite(along) ? h + along : h;
}

/* The largest correction of a predicted point accepted in a step of length
 * h (IC_TRACE_CORRECTION_TOLS, IC_TRACE_CORRECTION_OF_STEP). */
static double max_correction(const ic_tracer *tr, double h)
{
    return fmax(IC_TRACE_CORRECTION_TOLS * tr->opt.tol, IC_TRACE_CORRECTION_OF_STEP * h);
}

static int corrected(const ic_tracer *tr, double h, ic_local_point *next, double *X)
{
    double params[2][2];
    predict(tr, h, X, params);
    if (tr->tcurve)
        return ic_tcurve_correct(tr->pair, tr->par, X, params, max_correction(tr, h),
                                 &tr->opt.local, next) == IC_OK;
    return ic_local_locate_guess(tr->pair, next, X, params, &tr->opt.local, NULL) == IC_OK;
}

/* Ends the curve exactly on the boundary it crosses within the step h: the
 * step hb whose corrected point has the boundary's coordinate, by regula
 * falsi (Illinois) on hb; a corner (a second boundary crossed first) moves
 * the target. The coordinate is then set to the bound (a rounding-level
 * change). Returns 0 with *out and *hb, or -1 (no convergence, or a
 * degenerate point there: the curve then ends at its last point). */
static int land_on_boundary(const ic_tracer *tr, double h, boundary b, ic_local_point *out,
                            double *hb)
{
    for (int corner = 0; corner < 4; corner++) {
        double a = 0, fa = coordinate(tr, &tr->cur, &b) - b.bound, c = h, fc;
        ic_local_point p;
        double X[3];
        if (!corrected(tr, c, &p, X))
            return -1;
        fc = coordinate(tr, &p, &b) - b.bound;
        if (fa * fc > 0)
            return -1;
        int side = 0, done = 0;
        for (int it = 0; it < 100 && !done; it++) {
            const double m = (a * fc - c * fa) / (fc - fa);
            if (!corrected(tr, m, &p, X))
                return -1;
            const double fm = coordinate(tr, &p, &b) - b.bound;
            done = fabs(fm) <= 1e-14 * (1 + fabs(b.bound)) || c - a <= 1e-15 * h;
            if (fm * fc > 0) {
                c = m, fc = fm;
                if (side == 1)
                    fa *= 0.5;
                side = 1;
            } else {
                a = m, fa = fm;
                if (side == -1)
                    fc *= 0.5;
                side = -1;
            }
            *hb = m;
            *out = p;
        }
        if (!done)
            return -1;
        if (b.sheet < 0)
            out->xyz[b.index] = b.bound;
        else
            out->params[b.sheet][b.index] = b.bound;
        ic_trace_event ev;
        boundary other;
        if (!outside(tr, out, &ev, &other))
            return 0;
        b = other, h = *hb;
    }
    return -1;
}

/* Has the step from cur over length h (to `next`) passed the start point?
 * Then *hs is the exact step to it (Newton on (X(h) - X0) . X'(h) = 0). */
static int closes(const ic_tracer *tr, const double *next, double h, double *hs)
{
    if (tr->n < 3)
        return 0;
    double t[3], d[3], e[3];
    march_t(tr, &tr->res, t);
    ic_axpy3(d, tr->start_xyz, -1.0, tr->cur.xyz);
    ic_axpy3(e, next, -1.0, tr->cur.xyz);
    const double along = ic_dot3(d, e) / ic_dot3(e, e);
    if (along < 0 || along > 1 + 1e-9 || ic_dot3(t, tr->start_t) <= 0)
        return 0;
    double off[3];
    ic_axpy3(off, d, -along, e);
    if (ic_norm3(off) > 4 * tr->opt.chord + 1e-10 * tr->opt.local.scale)
        return 0;
    /* the exact step: minimise |X(h) - X0| along the predictor */
    double hh = along * h;
    for (int it = 0; it < 20; it++) {
        double X[3], X1[3], p[2][2], q[2][2];
        const double dh = 1e-7 * h;
        predict(tr, hh, X, p);
        predict(tr, hh + dh, X1, q);
        double g[3], dX[3];
        ic_axpy3(g, X, -1.0, tr->start_xyz);
        ic_axpy3(dX, X1, -1.0, X);
        ic_scale3(dX, dX, 1.0 / dh);
        const double step = ic_dot3(g, dX) / ic_dot3(dX, dX);
        hh -= step;
        if (fabs(step) < 1e-15 * h)
            break;
    }
    *hs = hh;
    return 1;
}

/* Does the angle between the normals dip below the threshold inside the
 * step (0, h) though it is above it at both ends? At a tacnode or a cusp the
 * angle falls like the square of the distance and t = N_A x N_B keeps its
 * sign, so a step can pass over the point. Where both end angles are small
 * (below WATCH) the angle at the predicted midpoint and at the vertex of the
 * parabola through the three is checked. */
static int angle_dips(const ic_tracer *tr, double h, double a1)
{
    const double WATCH = 1e3 * tr->opt.local.tangential_angle, a0 = tr->res.angle;
    if (!(a0 < WATCH && a1 < WATCH))
        return 0;
    ic_local_point p = tr->cur;
    predict(tr, 0.5 * h, p.xyz, p.params);
    const double am = normals_angle(tr, &p);
    if (am < 0)
        return 0;
    if (am < tr->opt.local.tangential_angle)
        return 1;
    /* a(x) = a0 + b x + c x^2 through x = 0, 1/2, 1 */
    const double c = 2 * (a0 - 2 * am + a1), b = a1 - a0 - c;
    if (!(c > 0) || -b / (2 * c) <= 0 || -b / (2 * c) >= 1)
        return 0;
    predict(tr, -b / (2 * c) * h, p.xyz, p.params);
    const double av = normals_angle(tr, &p);
    return av >= 0 && av < tr->opt.local.tangential_angle;
}

/* The step closed the curve: the last point is the start point itself. */
static ic_status close_at_start(ic_tracer *tr, double hs, ic_trace_event *event, ic_error *err)
{
    tr->s += hs;
    memcpy(tr->cur.xyz, tr->start_xyz, sizeof tr->start_xyz);
    ic_trace_point first = tr->pts[0];
    first.s = tr->s;
    const ic_status st = record(tr, err);
    if (st != IC_OK)
        return st;
    tr->pts[tr->n - 1] = first;
    tr->done = 1;
    *event = IC_TRACE_CLOSED;
    return IC_OK;
}

/* The step left the region across bd: the curve ends exactly on it (a
 * tangential curve too: its edge point is a point of the tangential curve,
 * oriented along the march), or at its last point where that fails. */
static ic_status end_on_boundary(ic_tracer *tr, double h, boundary bd, ic_trace_event *event,
                                 ic_error *err)
{
    tr->done = 1;
    ic_local_point edge;
    ic_local_result res;
    double hb;
    int tangential;
    if (land_on_boundary(tr, h, bd, &edge, &hb) != 0 ||
        apparatus(tr, &res, &edge, &tangential, NULL) != IC_OK)
        return IC_OK;
    if (tangential && !(tr->tcurve && res.type == IC_POINT_TANGENTIAL_CURVE && res.nbranches >= 1)) {
        /* the curve meets the boundary at a singular point (a branch point
         * on a strip's edge): it ends at a tangential point ahead, where the
         * singular points are located and the curves joined through them */
        if (!tr->tcurve)
            *event = IC_TRACE_TANGENTIAL;
        return IC_OK;
    }
    if (tr->tcurve) {
        double t0[3], te[3];
        march_t(tr, &tr->res, t0);
        march_t(tr, &res, te);
        if (ic_dot3(te, t0) < 0)
            ic_branch_reverse(&res.branches[0]);
    }
    /* the arc as for any step: the corrector may slide the point along the
     * curve (a tangential curve's does) */
    double Xb[3], pb[2][2];
    predict(tr, hb, Xb, pb);
    const double ds = step_arc(tr, hb, Xb, edge.xyz);
    tr->cur = edge;
    tr->res = res;
    tr->s += ds;
    return record(tr, err);
}

/* Within IC_TRACE_KNOT_SNAP_REL of sheet s's domain width. */
static double knot_snap(const ic_tracer *tr, int s, int i)
{
    return IC_TRACE_KNOT_SNAP_REL * (tr->domain[s][i][1] - tr->domain[s][i][0]);
}

/* Whether parameter i of sheet s at x stands on a knot line. */
static int on_knot_line(const ic_tracer *tr, int s, int i, double x)
{
    const double snap = knot_snap(tr, s, i);
    double knot;
    return ic_surface_knot_crossed(ic_pair_surface(tr->pair, s), i, x - snap, x + snap, &knot);
}

/* The knot line, or the seam of a wrapping NURBS parameter, that sheet s's
 * parameter i meets first going from a to z (z unwrapped next to a): 1 and
 * *at (in a's frame), else 0. One that a stands on is not met again. */
static int meets_line(const ic_tracer *tr, int s, int i, double a, double z, double *at)
{
    ic_surface *S = ic_pair_surface(tr->pair, s);
    const double *d = tr->domain[s][i], snap = knot_snap(tr, s, i);
    double knot;
    if (ic_surface_knot_crossed(S, i, a, z, &knot) && fabs(knot - a) > snap) {
        *at = knot;
        return 1;
    }
    if (!tr->periodic[s][i] || !ic_surface_knot_seam(S, i))
        return 0;
    const double seam = z > a ? d[1] : d[0];
    if ((z > a ? z >= seam : z <= seam) && fabs(seam - a) > snap) {
        *at = seam;
        return 1;
    }
    return 0;
}

/* The knot line of a NURBS sheet (docs/nurbs.md) the step from cur to
 * next crosses first, as a boundary to land on. */
static int crosses_knot_line(const ic_tracer *tr, const ic_local_point *next, boundary *b)
{
    int found = 0;
    double first = INFINITY;
    for (int s = 0; s < 2; s++)
        for (int i = 0; tr->par[s] && i < 2; i++) {
            const double a = tr->cur.params[s][i];
            const double z = unwrap_near(tr, s, i, next->params[s][i], a);
            double knot;
            if (!meets_line(tr, s, i, a, z, &knot))
                continue;
            const double f = (knot - a) / (z - a); /* how far along the step */
            if (f < first)
                first = f, *b = (boundary){s, i, knot}, found = 1;
        }
    return found;
}

/* Sets the knot side of every sheet parameter of `on` on a knot line to
 * the way the step heads (the landed one's first: two sheets of one
 * surface share the setting); returns which sheets are on one. */
static int set_knot_sides(const ic_tracer *tr, const ic_local_point *on, const ic_local_point *next,
                          boundary landed)
{
    int side[2][2] = {{0, 0}, {0, 0}}, sheets = 0;
    for (int s = 0; s < 2; s++)
        for (int i = 0; tr->par[s] && i < 2; i++)
            if (on_knot_line(tr, s, i, on->params[s][i])) {
                sheets |= 1 << s;
                side[s][i] = unwrap_near(tr, s, i, next->params[s][i], on->params[s][i]) >
                                     on->params[s][i]
                                 ? 1
                                 : -1;
            }
    const double ahead = unwrap_near(tr, landed.sheet, landed.index,
                                     next->params[landed.sheet][landed.index], landed.bound);
    side[landed.sheet][landed.index] = ahead > landed.bound ? 1 : -1;
    for (int s = 1; s >= 0; s--) /* sheet 0 last: it wins where the sheets share a surface */
        if (tr->par[s])
            ic_surface_set_knot_side(ic_pair_surface(tr->pair, s), side[s]);
    if (tr->par[0] && tr->par[1] && ic_pair_surface(tr->pair, 0) == ic_pair_surface(tr->pair, 1))
        ic_surface_set_knot_side(ic_pair_surface(tr->pair, 0), side[landed.sheet]);
    return sheets | 1 << landed.sheet;
}

static void clear_knot_sides(const ic_tracer *tr)
{
    for (int s = 0; s < 2; s++)
        if (tr->par[s])
            ic_surface_set_knot_side(ic_pair_surface(tr->pair, s), NULL);
}

static int regular_ahead(ic_tracer *tr, double h, const ic_local_point *next,
                         const double t[3], ic_local_result *res, int *near_tangential);

/* A step from cur to next crosses knot line bd: the curve gets a point on
 * it, whose apparatus is that of the piece the curve goes into (the sheet's
 * knot side set for the evaluation). 1 with *st when done; 0 where the
 * landing fails (the step is then taken as it is). */
static int step_onto_knot_line(ic_tracer *tr, double h, boundary bd, const ic_local_point *next,
                               const double t[3], ic_status *st, ic_error *err)
{
    ic_local_point on;
    double hb;
    if (land_on_boundary(tr, h, bd, &on, &hb) != 0)
        return 0;
    const int sheets = set_knot_sides(tr, &on, next, bd);
    ic_local_result res;
    int near_tangential = 0;
    const int ok = regular_ahead(tr, hb, &on, t, &res, &near_tangential);
    clear_knot_sides(tr);
    if (!ok)
        return 0;
    double Xb[3], pb[2][2];
    predict(tr, hb, Xb, pb);
    const double ds = step_arc(tr, hb, Xb, on.xyz);
    tr->cur = on;
    tr->res = res;
    tr->s += ds;
    tr->knot_line = sheets;
    *st = record(tr, err);
    tr->knot_line = 0;
    return 1;
}

/* The apparatus at the corrected point `next`, oriented along the march;
 * 0 when the step is to be shortened: a tangential point ahead (or passed:
 * t = N_A x N_B flips across a branch point), which sets *near_tangential,
 * or no apparatus there. */
static int regular_ahead(ic_tracer *tr, double h, const ic_local_point *next,
                         const double t[3], ic_local_result *res, int *near_tangential)
{
    /* on a transversal curve the angle shortens the step without the
     * (costly) classification */
    const double angle = tr->tcurve ? -1 : normals_angle(tr, next);
    if (angle >= 0 && (angle < tr->opt.local.tangential_angle || angle_dips(tr, h, angle))) {
        *near_tangential = 1;
        return 0;
    }
    int tangential;
    if (apparatus(tr, res, next, &tangential, NULL) != IC_OK)
        return 0;
    double tn[3];
    if (tr->tcurve) { /* stay on the tangential curve, oriented along it */
        tangential = res->type != IC_POINT_TANGENTIAL_CURVE || res->nbranches < 1;
        march_t(tr, res, tn);
        if (!tangential && ic_dot3(tn, t) < 0)
            ic_branch_reverse(&res->branches[0]);
    }
    march_t(tr, res, tn);
    if (tangential || ic_dot3(tn, t) <= 0) {
        *near_tangential = 1;
        return 0;
    }
    return 1;
}

/* Every step failed: the curve ends at a tangential point ahead, on a
 * bound it stands on, or with a failure. */
static ic_status no_step(ic_tracer *tr, int near_tangential, ic_trace_event *event,
                         ic_error *err)
{
    tr->done = 1;
    if (near_tangential) {
        *event = IC_TRACE_TANGENTIAL;
        return IC_OK;
    }
    if (on_boundary_heading_out(tr, event))
        return IC_OK;
    *event = IC_TRACE_FAILED;
    double at[3];
    ic_frame_shown(&ic_pair_pairing(tr->pair)->frame, tr->cur.xyz, at);
    return ic_error_set(err, IC_ERR_UNABLE, 0,
                        "the tracer could not make a step at s = %g, (%g, %g, %g): the corrector "
                        "did not converge down to the minimum step %g",
                        tr->s, at[0], at[1], at[2], tr->opt.min_step);
}

static ic_status step(ic_tracer *tr, ic_trace_event *event, ic_error *err)
{
    *event = IC_TRACE_CONTINUE;
    if (tr->done)
        return ic_error_set(err, IC_ERR_INVALID, 0, "the curve has ended; start another");
    if (tr->n >= tr->opt.max_points) {
        tr->done = 1;
        *event = IC_TRACE_BUDGET;
        return IC_OK;
    }
    double h = step_length(tr);
    int near_tangential = 0;
    for (int attempt = 0; attempt < IC_TRACE_STEP_HALVINGS; attempt++, h *= 0.5) {
        if (h < tr->opt.min_step ||
            (near_tangential &&
             h < IC_TRACE_TANGENTIAL_MIN_STEP * (tr->opt.local.scale + ic_norm3(tr->cur.xyz))))
            break;
        double X[3];
        ic_local_point next;
        if (!corrected(tr, h, &next, X))
            continue;
        /* the corrector moves the point in the normal plane: accept small
         * corrections that move forward */
        double t[3], d[3], c[3];
        march_t(tr, &tr->res, t);
        ic_axpy3(d, next.xyz, -1.0, tr->cur.xyz);
        ic_axpy3(c, next.xyz, -1.0, X);
        if (ic_dot3(d, t) <= IC_TRACE_STEP_ADVANCE * h || ic_norm3(c) > max_correction(tr, h))
            continue;
        double hs;
        if (closes(tr, next.xyz, h, &hs))
            return close_at_start(tr, hs, event, err);
        boundary bd;
        if (outside(tr, &next, event, &bd))
            return end_on_boundary(tr, h, bd, event, err);
        ic_status st;
        if (crosses_knot_line(tr, &next, &bd) && step_onto_knot_line(tr, h, bd, &next, t, &st, err))
            return st;
        ic_local_result res;
        if (!regular_ahead(tr, h, &next, t, &res, &near_tangential))
            continue;
        double hx = h;
        const step_ends ends = {tr, h, &next, &res};
        if (excursion(&ends, &hx, &bd, event))
            return end_on_boundary(tr, hx, bd, event, err);
        const double ds = step_arc(tr, h, X, next.xyz);
        tr->cur = next;
        tr->res = res;
        tr->s += ds;
        return record(tr, err);
    }
    return no_step(tr, near_tangential, event, err);
}

/* A step tries shorter steps after a failed one: out of memory there is the
 * pair's to tell (ic_pair_nomem_check; tests/test_nomem.c, "trace,
 * tangential"). */
ic_status ic_tracer_step(ic_tracer *tr, ic_trace_event *event, ic_error *err)
{
    IC_ARG_NOT_NULL(tr, "tr");
    IC_ARG_NOT_NULL(event, "event");
    const long before = ic_pair_nomem_count(tr->pair);
    return ic_pair_nomem_check(tr->pair, before, step(tr, event, err), err);
}

void ic_tracer_set_deadline(ic_tracer *tr, double deadline) { tr->deadline = deadline; }

ic_status ic_tracer_run(ic_tracer *tr, ic_trace_event *event, ic_error *err)
{
    IC_ARG_NOT_NULL(tr, "tr");
    IC_ARG_NOT_NULL(event, "event");
    /* the clock is read after every step (a step costs tens of microseconds
     * and near a tangential point far more; a reading costs tens of
     * nanoseconds); past the deadline the curve stops as at its budget */
    for (;;) {
        ic_status st = ic_tracer_step(tr, event, err);
        if (st != IC_OK || *event != IC_TRACE_CONTINUE)
            return st;
        if (tr->deadline > 0 && ic_trace_now() > tr->deadline) {
            *event = IC_TRACE_BUDGET;
            return IC_OK;
        }
    }
}
