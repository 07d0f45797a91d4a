/* Surfaces: construction, backends, Taylor coefficients, composition. */
#include "common/args.h"
#include "surface_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static ic_surface *surface_alloc(ic_surface_kind kind, ic_backend backend)
{
    ic_surface *s = calloc(1, sizeof *s);
    if (!s)
        return NULL;
    s->kind = kind;
    s->backend = backend;
    /* an unbounded domain until one is set */
    for (int i = 0; i < 2; i++) {
        s->domain[i][0] = -INFINITY;
        s->domain[i][1] = INFINITY;
    }
    return s;
}

/* Evaluations in the surface's own variables up to this order (Newton steps
 * of the searches and the locator, the fundamental forms, a pair's order-4
 * tensors) find their spaces and workspaces made at creation: the callers
 * that try another cell or step after a failed evaluation could not tell
 * out of memory there from a point where the surface is undefined. */
#define RESERVED_ORDER 4

ic_status ic_surface_reserve(ic_surface *s, ic_error *err)
{
    for (int k = 0; k <= RESERVED_ORDER; k++)
        if (!ic_surface_space(s, k, err)) {
            ic_surface_free(s);
            return IC_ERR_NOMEM;
        }
    const ic_jet_space *sp = s->spaces[RESERVED_ORDER];
    const size_t n = (size_t)ic_jet_space_len(sp);
    size_t eval = 0;
    if (s->backend == BACKEND_FORMULA)
        eval = (size_t)ic_surface_num_vars(s) * n + ic_expr_jet_work_len(s->expr, sp);
    else if (s->backend == BACKEND_PRIMITIVE)
        eval = 7 * n; /* ic_primitive_taylor's */
    else if (s->backend == BACKEND_NURBS)
        eval = ic_nurbs_taylor_work_len((int)n);
    /* the fundamental forms' Taylor coefficients, order 2 */
    const size_t forms = 3 * (size_t)ic_jet_space_len(s->spaces[2]);
    if ((eval && !ic_surface_work(s, IC_WORK_EVAL, eval)) ||
        !ic_surface_work(s, IC_WORK_COMPOSE, forms)) {
        ic_surface_free(s);
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory creating a surface");
    }
    return IC_OK;
}

ic_status ic_surface_new_parametric(ic_surface **out, const char *const xyz[3],
                                    const char *const params[2], const ic_constant *consts,
                                    int nconsts, int *which, ic_error *err)
{
    static const char *const default_params[2] = {"u", "v"};
    IC_ARG_NOT_NULL(out, "s");
    *out = NULL;
    IC_ARG_NOT_NULL(xyz, "xyz");
    IC_ARG_CHECK(nconsts >= 0, "nconsts", "must not be negative");
    IC_ARG_CHECK(nconsts == 0 || consts, "consts", "is NULL");
    ic_surface *s = surface_alloc(IC_PARAMETRIC, BACKEND_FORMULA);
    if (!s)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory creating a surface");
    ic_status st =
        ic_expr_compile(&s->expr, (const char *const *)xyz, 3, params ? params : default_params, 2,
                        consts, nconsts, which, err);
    if (st != IC_OK) {
        ic_surface_free(s);
        return st;
    }
    st = ic_surface_reserve(s, err);
    if (st == IC_OK)
        *out = s;
    return st;
}

ic_status ic_surface_new_implicit(ic_surface **out, const char *f, const ic_constant *consts,
                                  int nconsts, ic_error *err)
{
    static const char *const xyz[3] = {"x", "y", "z"};
    IC_ARG_NOT_NULL(out, "s");
    *out = NULL;
    IC_ARG_NOT_NULL(f, "f");
    IC_ARG_CHECK(nconsts >= 0, "nconsts", "must not be negative");
    IC_ARG_CHECK(nconsts == 0 || consts, "consts", "is NULL");
    ic_surface *s = surface_alloc(IC_IMPLICIT, BACKEND_FORMULA);
    if (!s)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory creating a surface");
    ic_status st = ic_expr_compile(&s->expr, &f, 1, xyz, 3, consts, nconsts, NULL, err);
    if (st != IC_OK) {
        ic_surface_free(s);
        return st;
    }
    st = ic_surface_reserve(s, err);
    if (st == IC_OK)
        *out = s;
    return st;
}

ic_status ic_surface_new_callback(ic_surface **out, ic_surface_kind kind, ic_surface_callback fn,
                                  void *user, ic_error *err)
{
    IC_ARG_NOT_NULL(out, "s");
    *out = NULL;
    IC_ARG_NOT_NULL(fn, "fn");
    if ((kind != IC_PARAMETRIC && kind != IC_IMPLICIT))
        return ic_error_set(err, IC_ERR_INVALID, 0, "callback surface: no function or bad kind");
    ic_surface *s = surface_alloc(kind, BACKEND_CALLBACK);
    if (!s)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory creating a surface");
    s->fn = fn;
    s->user = user;
    const ic_status st = ic_surface_reserve(s, err);
    if (st == IC_OK)
        *out = s;
    return st;
}

ic_status ic_surface_new_primitive(ic_surface **out, const ic_primitive *prim, ic_surface_kind form,
                                   ic_error *err)
{
    IC_ARG_NOT_NULL(out, "s");
    *out = NULL;
    IC_ARG_NOT_NULL(prim, "prim");
    if ((form != IC_PARAMETRIC && form != IC_IMPLICIT))
        return ic_error_set(err, IC_ERR_INVALID, 0, "primitive surface: bad arguments");
    ic_surface *s = surface_alloc(form, BACKEND_PRIMITIVE);
    if (!s)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory creating a surface");
    s->prim = *prim;
    ic_status st = ic_primitive_check(s, err);
    if (st != IC_OK) {
        ic_surface_free(s);
        return st;
    }
    if (form == IC_PARAMETRIC)
        ic_primitive_default_domain(s);
    st = ic_surface_reserve(s, err);
    if (st == IC_OK)
        *out = s;
    return st;
}

ic_status ic_surface_new_nurbs(ic_surface **out, const ic_nurbs *nurbs, ic_error *err)
{
    IC_ARG_NOT_NULL(out, "s");
    *out = NULL;
    IC_ARG_NOT_NULL(nurbs, "nurbs");
    ic_surface *s = surface_alloc(IC_PARAMETRIC, BACKEND_NURBS);
    if (!s)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory creating a surface");
    ic_status st = ic_nurbs_patch_new(&s->nurbs, nurbs, err);
    if (st == IC_OK)
        st = ic_surface_reserve(s, err); /* frees s on failure */
    else
        ic_surface_free(s);
    if (st != IC_OK)
        return st;
    /* its natural domain; a periodic flag must be borne out by the points */
    st = ic_surface_set_domain(s, s->nurbs->domain, nurbs->periodic, err);
    if (st != IC_OK) {
        ic_surface_free(s);
        if (err && err->path[0] == '\0')
            snprintf(err->path, sizeof err->path, "periodic");
        return st;
    }
    *out = s;
    return IC_OK;
}

int ic_surface_knot_crossed(const ic_surface *s, int dir, double from, double to, double *knot)
{
    if (!s || s->backend != BACKEND_NURBS || dir < 0 || dir > 1)
        return 0;
    return ic_nurbs_knot_crossed(s->nurbs, dir, from, to, knot);
}

int ic_surface_knot_seam(const ic_surface *s, int dir)
{
    return s && s->backend == BACKEND_NURBS && dir >= 0 && dir <= 1 && ic_nurbs_seam(s->nurbs, dir);
}

void ic_surface_set_knot_side(ic_surface *s, const int side[2])
{
    if (!s)
        return;
    for (int d = 0; d < 2; d++)
        s->knot_side[d] = side ? (side[d] > 0) - (side[d] < 0) : 0;
}

void ic_surface_free(ic_surface *s)
{
    if (!s)
        return;
    ic_nurbs_patch_free(s->nurbs);
    ic_net_shape_free(s->net_shape);
    ic_expr_free(s->expr);
    for (int k = 0; k <= IC_JET_MAX_ORDER; k++) {
        ic_jet_space_free(s->spaces[k]);
        ic_jet_space_free(s->plane_spaces[k]);
    }
    free(s->work[0]);
    free(s->work[1]);
    free(s);
}

ic_surface_kind ic_surface_get_kind(const ic_surface *s) { return s ? s->kind : IC_SURFACE_NONE; }
int ic_surface_num_vars(const ic_surface *s) { return !s ? 0 : s->kind == IC_PARAMETRIC ? 2 : 3; }
int ic_surface_num_outputs(const ic_surface *s) { return !s ? 0 : s->kind == IC_PARAMETRIC ? 3 : 1; }

/* relative: the two ends of a periodic parameter must give the same point
 * to this fraction of the largest sampled coordinate (rounding leaves
 * 1e-16 of it) */
#define PERIOD_MATCH 1e-9

/* fraction of a periodic parameter's width: the lines this far beside its
 * two ends must match as the ends do (a formula's sheet continues across
 * its seam as one: the checker evaluates it across, certify/leaf.c) */
#define PERIOD_BAND (1.0 / 16)

/* The largest difference between R at z[i] = domain[i][0] + t and at
 * domain[i][1] + t over samples along the other parameter, and where;
 * samples where the surface is not defined are skipped. */
static double period_gap(ic_surface *s, const double domain[2][2], int i, double t,
                         double *size, double *at_worst)
{
    const int o = 1 - i;
    const double w0 = isfinite(domain[o][0]) ? domain[o][0] : -1.0;
    const double w1 = isfinite(domain[o][1]) ? domain[o][1] : w0 + 2.0;
    enum { SAMPLES = 9 };
    double worst = 0;
    for (int k = 0; k < SAMPLES; k++) {
        double at[2], x[2][3];
        at[o] = w0 + (w1 - w0) * (k + 0.5) / SAMPLES;
        int ok = 1;
        for (int e = 0; e < 2; e++) {
            at[i] = domain[i][e] + t;
            ok = ok && ic_surface_eval(s, x[e], at, NULL) == IC_OK; /* else skipped */
        }
        for (int c = 0; ok && c < 3; c++) {
            *size = fmax(*size, fmax(fabs(x[0][c]), fabs(x[1][c])));
            if (fabs(x[1][c] - x[0][c]) > worst)
                worst = fabs(x[1][c] - x[0][c]), *at_worst = at[o];
        }
    }
    return worst;
}

/* A parameter declared periodic must close the surface: R at both ends of
 * its domain, sampled along the other parameter, is the same point; for a
 * formula also on the lines PERIOD_BAND of the width beside both ends (a
 * tube whose two ends merely meet, at a crease, is no periodic surface:
 * the checker, taking it for one, proved a double line beside the seam
 * away). */
static ic_status check_period(ic_surface *s, const double domain[2][2], int i, ic_error *err)
{
    const int o = 1 - i;
    const double band = PERIOD_BAND * (domain[i][1] - domain[i][0]);
    const int lines = s->backend == BACKEND_FORMULA ? 1 : 0;
    for (int line = 0; line <= 2 * lines; line++) {
        const double t = line == 0 ? 0.0 : line == 1 ? -band : band;
        double size = 0, at_worst = 0;
        const double worst = period_gap(s, domain, i, t, &size, &at_worst);
        if (worst <= PERIOD_MATCH * size)
            continue;
        if (line == 0)
            return ic_error_set(err, IC_ERR_INVALID, 0,
                                "parameter %d is not periodic over [%g, %g]: the surface's points "
                                "at its two ends differ by %.3g at parameter %d = %g",
                                i + 1, domain[i][0], domain[i][1], worst, o + 1, at_worst);
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            "parameter %d is not periodic over [%g, %g]: its two ends meet, but "
                            "the surface does not continue across them (at %g beside both ends "
                            "its points differ by %.3g at parameter %d = %g)",
                            i + 1, domain[i][0], domain[i][1], t, worst, o + 1, at_worst);
    }
    return IC_OK;
}

/* A NURBS patch is defined over its knots' domain: a domain set on it
 * lies inside that, and a periodic parameter spans all of it (the patch
 * wraps by that period). */
static ic_status check_nurbs_domain(ic_surface *s, const double domain[2][2],
                                    const int periodic[2], ic_error *err)
{
    const ic_nurbs_patch *pt = s->nurbs;
    for (int i = 0; i < 2; i++) {
        const int whole = domain[i][0] == pt->domain[i][0] && domain[i][1] == pt->domain[i][1];
        if (domain[i][0] < pt->domain[i][0] || domain[i][1] > pt->domain[i][1] ||
            (periodic && periodic[i] && !whole))
            return ic_error_set(err, IC_ERR_INVALID, 0,
                                "domain of parameter %d, [%g, %g], must lie in the NURBS patch's "
                                "[%g, %g] (and be all of it where periodic)",
                                i + 1, domain[i][0], domain[i][1], pt->domain[i][0],
                                pt->domain[i][1]);
    }
    return IC_OK;
}

ic_status ic_surface_set_domain(ic_surface *s, const double domain[2][2], const int periodic[2],
                                ic_error *err)
{
    IC_ARG_NOT_NULL(s, "s");
    IC_ARG_NOT_NULL(domain, "domain");
    if (s->kind != IC_PARAMETRIC)
        return ic_error_set(err, IC_ERR_INVALID, 0, "an implicit surface has no parameter domain");
    for (int i = 0; i < 2; i++) {
        if (!(domain[i][0] < domain[i][1]))
            return ic_error_set(err, IC_ERR_INVALID, 0, "domain of parameter %d is empty: [%g, %g]",
                                i + 1, domain[i][0], domain[i][1]);
        if (periodic && periodic[i] && !(isfinite(domain[i][0]) && isfinite(domain[i][1])))
            return ic_error_set(err, IC_ERR_INVALID, 0,
                                "periodic parameter %d needs a finite domain", i + 1);
    }
    if (s->backend == BACKEND_NURBS && check_nurbs_domain(s, domain, periodic, err) != IC_OK)
        return IC_ERR_INVALID;
    for (int k = 0; s->backend == BACKEND_NURBS && k < 2; k++)
        s->nurbs->periodic[k] = 0; /* no wrapping while the ends are compared */
    for (int i = 0; periodic && i < 2; i++)
        if (periodic[i] && check_period(s, domain, i, err) != IC_OK) {
            for (int k = 0; s->backend == BACKEND_NURBS && k < 2; k++)
                s->nurbs->periodic[k] = s->periodic[k]; /* as before the call */
            return IC_ERR_INVALID;
        }
    if (s->backend == BACKEND_NURBS) /* the patch wraps its parameters from now on */
        for (int i = 0; i < 2; i++)
            s->nurbs->periodic[i] = periodic ? periodic[i] != 0 : 0;
    memcpy(s->domain, domain, sizeof s->domain);
    for (int i = 0; i < 2; i++)
        s->periodic[i] = periodic ? periodic[i] != 0 : 0;
    return IC_OK;
}

void ic_surface_get_domain(const ic_surface *s, double domain[2][2], int periodic[2])
{
    if (!s)
        return;
    if (domain)
        memcpy(domain, s->domain, sizeof s->domain);
    if (periodic) {
        periodic[0] = s->periodic[0];
        periodic[1] = s->periodic[1];
    }
}

double *ic_surface_work(ic_surface *s, int slot, size_t len)
{
    if (len <= s->work_len[slot])
        return s->work[slot];
    double *w = realloc(s->work[slot], len * sizeof *w);
    if (!w)
        return NULL;
    s->work[slot] = w;
    s->work_len[slot] = len;
    return w;
}

const ic_jet_space *ic_surface_space(ic_surface *s, int order, ic_error *err)
{
    if (order < 0 || order > IC_JET_MAX_ORDER) {
        ic_error_set(err, IC_ERR_INVALID, 0, "order %d outside 0..%d", order, IC_JET_MAX_ORDER);
        return NULL;
    }
    if (!s->spaces[order] &&
        ic_jet_space_new(&s->spaces[order], ic_surface_num_vars(s), order, err) != IC_OK)
        return NULL;
    return s->spaces[order];
}

const ic_jet_space *ic_surface_plane_space(ic_surface *s, int order, ic_error *err)
{
    if (order < 0 || order > IC_JET_MAX_ORDER) {
        ic_error_set(err, IC_ERR_INVALID, 0, "order %d outside 0..%d", order, IC_JET_MAX_ORDER);
        return NULL;
    }
    if (!s->plane_spaces[order] &&
        ic_jet_space_new(&s->plane_spaces[order], 2, order, err) != IC_OK)
        return NULL;
    return s->plane_spaces[order];
}

/* Callback: partial derivatives in, Taylor coefficients out. */
static ic_status callback_taylor(ic_surface *s, double *out, const double *at,
                                 const ic_jet_space *sp, ic_error *err)
{
    if (s->fn(s->user, out, at, sp) != 0)
        return ic_error_set(err, IC_ERR_DOMAIN, 0, "the surface callback failed at this point");
    const int n = ic_jet_space_len(sp), nout = ic_surface_num_outputs(s);
    for (int k = 0; k < nout; k++)
        for (int i = 0; i < n; i++) {
            out[k * n + i] /= ic_jet_factorial(sp, i);
            if (!isfinite(out[k * n + i]))
                return ic_error_set(err, IC_ERR_DOMAIN, 0,
                                    "the surface callback returned a non-finite derivative");
        }
    return IC_OK;
}

/* The piece of a NURBS on each knot line: forced (ic_surface_set_knot_side),
 * else where the parameter jet heads, else the one above. */
static void nurbs_sides(const ic_surface *s, const double *heading, ic_nurbs_side side[2])
{
    for (int d = 0; d < 2; d++) {
        const double way = s->knot_side[d] ? s->knot_side[d] : heading ? heading[d] : 0;
        side[d] = way < 0 ? IC_NURBS_LEFT : IC_NURBS_RIGHT;
    }
}

/* NURBS: on a knot line, the piece the direction `heading` (NULL: none)
 * goes into; the right one without a direction. */
static ic_status nurbs_taylor(ic_surface *s, double *out, const double *at, const double *heading,
                              const ic_jet_space *sp, ic_error *err)
{
    double *w = ic_surface_work(s, IC_WORK_EVAL, ic_nurbs_taylor_work_len(ic_jet_space_len(sp)));
    if (!w)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory evaluating a surface");
    ic_nurbs_side side[2];
    nurbs_sides(s, heading, side);
    return ic_nurbs_taylor(s->nurbs, out, at, side, sp, w, err);
}

int ic_surface_nurbs_point(ic_surface *s, const double uv[2], double out[3])
{
    if (s->backend != BACKEND_NURBS)
        return -1;
    ic_nurbs_side side[2];
    nurbs_sides(s, NULL, side);
    ic_nurbs_point(s->nurbs, uv, side, out);
    return 0;
}

/* The direction a parameter jet moves in: its first nonzero coefficient of
 * degree 1 (in the order of the space's variables), 0 if it stands still. */
static double jet_heading(const double *jet, const ic_jet_space *sp)
{
    if (ic_jet_space_order(sp) < 1)
        return 0;
    const int start = ic_jet_degree_start(sp, 1);
    for (int i = 0; i < ic_jet_space_num_vars(sp); i++)
        if (jet[start + i] != 0)
            return jet[start + i];
    return 0;
}

/* NURBS composed with parameter jets directly (nurbs_eval.c). */
static ic_status nurbs_compose(ic_surface *s, double *out, const double *const *in,
                               const ic_jet_space *sp, ic_error *err)
{
    const int n = ic_jet_space_len(sp);
    double *w = ic_surface_work(s, IC_WORK_EVAL, ic_nurbs_compose_work_len(s->nurbs, n));
    if (!w)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory composing a surface");
    const double heading[2] = {jet_heading(in[0], sp), jet_heading(in[1], sp)};
    ic_nurbs_side side[2];
    nurbs_sides(s, heading, side);
    return ic_nurbs_compose(s->nurbs, out, in, side, sp, w, err);
}

/* Formula: the tape on the coordinate jets of the point. */
static ic_status formula_taylor(ic_surface *s, double *out, const double *at,
                                const ic_jet_space *sp, ic_error *err)
{
    const int n = ic_jet_space_len(sp), nin = ic_surface_num_vars(s);
    double *w =
        ic_surface_work(s, IC_WORK_EVAL, (size_t)nin * n + ic_expr_jet_work_len(s->expr, sp));
    if (!w)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory evaluating a surface");
    const double *in[3];
    for (int i = 0; i < nin; i++) {
        ic_jet_set_var(w + i * n, at[i], i, sp);
        in[i] = w + i * n;
    }
    return ic_expr_eval_jet(s->expr, out, in, sp, w + (size_t)nin * n, err);
}

ic_status ic_surface_taylor(ic_surface *s, double *out, const double *at, const ic_jet_space *sp,
                            ic_error *err)
{
    IC_ARG_NOT_NULL(s, "s");
    IC_ARG_NOT_NULL(out, "out");
    IC_ARG_NOT_NULL(at, "at");
    IC_ARG_NOT_NULL(sp, "sp");
    if (ic_jet_space_num_vars(sp) != ic_surface_num_vars(s))
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            "ic_surface_taylor: the space has %d variables, the surface %d",
                            ic_jet_space_num_vars(sp), ic_surface_num_vars(s));
    for (int i = 0; i < ic_surface_num_vars(s); i++)
        if (!isfinite(at[i]))
            return ic_error_set(err, IC_ERR_INVALID, 0, "non-finite coordinate %d", i + 1);
    switch (s->backend) {
    case BACKEND_FORMULA:
        return formula_taylor(s, out, at, sp, err);
    case BACKEND_CALLBACK:
        return callback_taylor(s, out, at, sp, err);
    case BACKEND_PRIMITIVE:
        return ic_primitive_taylor(s, out, at, sp, err);
    case BACKEND_NURBS:
        return nurbs_taylor(s, out, at, NULL, sp, err);
    }
    return ic_error_set(err, IC_ERR_INVALID, 0, "corrupt surface");
}

int ic_surface_is_formula(const ic_surface *s) { return s->backend == BACKEND_FORMULA; }

int ic_surface_polynomial_degree(const ic_surface *s)
{
    if (s->backend != BACKEND_PRIMITIVE)
        return -1;
    if (s->prim.kind == IC_PRIM_PLANE)
        return 1; /* placement is linear: degrees stay */
    if (s->kind == IC_PARAMETRIC)
        return -1;
    return s->prim.kind == IC_PRIM_TORUS ? 4 : 2;
}

ic_status ic_surface_taylor_toward(ic_surface *s, double *out, const double *at,
                                   const double *heading, const ic_jet_space *sp, ic_error *err)
{
    if (s->backend != BACKEND_NURBS || !heading || ic_jet_space_num_vars(sp) != 2)
        return ic_surface_taylor(s, out, at, sp, err);
    for (int i = 0; i < 2; i++)
        if (!isfinite(at[i]))
            return ic_error_set(err, IC_ERR_INVALID, 0, "non-finite coordinate %d", i + 1);
    return nurbs_taylor(s, out, at, heading, sp, err);
}

ic_status ic_surface_compose(ic_surface *s, double *out, const double *const *in,
                             const ic_jet_space *sp, ic_error *err)
{
    IC_ARG_NOT_NULL(s, "s");
    IC_ARG_NOT_NULL(out, "out");
    IC_ARG_NOT_NULL(in, "in");
    IC_ARG_NOT_NULL(sp, "sp");
    const int n = ic_jet_space_len(sp), nin = ic_surface_num_vars(s);
    const int nout = ic_surface_num_outputs(s);
    if (s->backend == BACKEND_FORMULA) {
        double *w = ic_surface_work(s, IC_WORK_EVAL, ic_expr_jet_work_len(s->expr, sp));
        if (!w)
            return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory evaluating a surface");
        return ic_expr_eval_jet(s->expr, out, in, sp, w, err);
    }
    if (s->backend == BACKEND_PRIMITIVE)
        return ic_primitive_compose(s, out, in, sp, err);
    if (s->backend == BACKEND_NURBS)
        return nurbs_compose(s, out, in, sp, err);
    /* Callbacks: Taylor polynomial at the constant terms, then the chain rule. */
    const ic_jet_space *tsp = ic_surface_space(s, ic_jet_space_order(sp), err);
    if (!tsp)
        return err ? err->code : IC_ERR_NOMEM;
    const int tn = ic_jet_space_len(tsp);
    double at[3];
    for (int i = 0; i < nin; i++)
        at[i] = in[i][0];
    double *taylor =
        ic_surface_work(s, IC_WORK_COMPOSE, (size_t)nout * tn + ic_jet_scratch_len(sp));
    if (!taylor)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory composing a surface");
    double *scratch = taylor + (size_t)nout * tn;
    ic_status st = ic_surface_taylor(s, taylor, at, tsp, err);
    if (st != IC_OK)
        return st;
    for (int k = 0; k < nout; k++)
        ic_jet_compose(out + (size_t)k * n, taylor + (size_t)k * tn, tsp, in, sp, scratch);
    return st;
}

ic_status ic_surface_eval(ic_surface *s, double *out, const double *at, ic_error *err)
{
    IC_ARG_NOT_NULL(s, "s");
    IC_ARG_NOT_NULL(out, "out");
    IC_ARG_NOT_NULL(at, "at");
    if (s->backend == BACKEND_FORMULA) {
        double *w = ic_surface_work(s, IC_WORK_EVAL, ic_expr_work_len(s->expr));
        if (!w)
            return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory evaluating a surface");
        return ic_expr_eval(s->expr, out, at, w, err);
    }
    const ic_jet_space *sp = ic_surface_space(s, 0, err);
    if (!sp)
        return err ? err->code : IC_ERR_NOMEM;
    return ic_surface_taylor(s, out, at, sp, err);
}

ic_status ic_surface_eval_interval_grad(ic_surface *s, ic_interval_grad *out, const ic_interval *in,
                                        ic_error *err)
{
    IC_ARG_NOT_NULL(s, "s");
    IC_ARG_NOT_NULL(out, "out");
    IC_ARG_NOT_NULL(in, "in");
    if (s->backend == BACKEND_PRIMITIVE) {
        if (s->kind == IC_IMPLICIT)
            ic_primitive_interval_grad(s, out, in);
        else
            ic_primitive_param_interval_grad(s, out, in);
        return IC_OK;
    }
    if (s->backend == BACKEND_NURBS)
        return ic_nurbs_interval_grad(s->nurbs, out, in, 1, err);
    if (s->backend != BACKEND_FORMULA)
        return ic_error_set(err, IC_ERR_UNABLE, 0,
                            "interval evaluation needs a formula surface, a primitive or a NURBS");
    const int nin = s->kind == IC_PARAMETRIC ? 2 : 3;
    ic_interval_grad x[3];
    for (int i = 0; i < nin; i++) {
        x[i].v = in[i];
        for (int k = 0; k < nin; k++)
            x[i].d[k] = (ic_interval){i == k ? 1.0 : 0.0, i == k ? 1.0 : 0.0};
    }
    ic_interval_grad work[128];
    ic_interval_grad *w = work;
    const size_t len = ic_expr_interval_grad_work_len(s->expr);
    if (len > 128) {
        w = malloc(len * sizeof *w);
        if (!w)
            return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory");
    }
    const int whole = ic_expr_eval_interval_grad(s->expr, out, x, nin, w);
    if (w != work)
        free(w);
    if (!whole) /* not defined everywhere on the box: the callers' arguments fail */
        return ic_error_set(err, IC_ERR_DOMAIN, 0,
                            "the surface's formula is not defined over the whole box");
    return IC_OK;
}

ic_status ic_surface_eval_interval(ic_surface *s, ic_interval *out, const ic_interval *in,
                                   ic_error *err)
{
    IC_ARG_NOT_NULL(s, "s");
    IC_ARG_NOT_NULL(out, "out");
    IC_ARG_NOT_NULL(in, "in");
    if (s->backend == BACKEND_PRIMITIVE && s->kind == IC_IMPLICIT)
        return ic_primitive_interval(s, out, in, err);
    if (s->backend == BACKEND_PRIMITIVE) {
        ic_interval_grad g[3];
        ic_primitive_param_interval_grad(s, g, in);
        for (int k = 0; k < 3; k++)
            out[k] = g[k].v;
        return IC_OK;
    }
    if (s->backend == BACKEND_NURBS) {
        ic_interval_grad g[3];
        const ic_status st = ic_nurbs_interval_grad(s->nurbs, g, in, 0, err);
        for (int k = 0; k < 3; k++)
            out[k] = g[k].v;
        return st;
    }
    if (s->backend != BACKEND_FORMULA)
        return ic_error_set(err, IC_ERR_UNABLE, 0,
                            "interval evaluation needs a formula surface, a primitive or a NURBS");
    ic_interval work[256];
    ic_interval *w = work;
    const size_t len = ic_expr_interval_work_len(s->expr);
    if (len > 256) {
        w = malloc(len * sizeof *w);
        if (!w)
            return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory");
    }
    ic_expr_eval_interval(s->expr, out, in, w);
    if (w != work)
        free(w);
    return IC_OK;
}
