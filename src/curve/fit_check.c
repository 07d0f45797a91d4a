/* The fit's check (docs/bspline.md): at the middle of every stretch
 * between the nodes, the fitted curve against both surfaces (through a
 * pcurve's image where the sheet has one) and each pcurve's image against
 * the curve. */
#include "curve/fit_check.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "common/vec3.h"

/* The nearest representative of x modulo the period (periodic directions)
 * to the value the previous node predicts: a pcurve continues across a
 * seam rather than jumping back (as CAD systems expect). */
double ic_fit_unwrap(double x, double predicted, double period)
{
    if (!(period > 0))
        return x;
    return x + period * round((predicted - x) / period);
}

/* The distance from pcurve k's image at s to the curve's point X there;
 * -1 where it cannot be evaluated. */
static double pcurve_off(ic_pair *pair, const ic_curve_fit *f, int k, double s, const double X[3],
                         double uv[2])
{
    double R[3], d[3];
    if (ic_bspline_eval(&f->pcurves[k], s, 0, uv, NULL) != IC_OK ||
        ic_surface_eval(ic_pair_surface(pair, k), R, uv, NULL) != IC_OK)
        return -1;
    ic_axpy3(d, R, -1.0, X);
    return ic_norm3(d);
}

/* The fitted curve at the middle of a stretch (ok: 0 where it cannot be
 * evaluated) and each pcurve's image's distance from it there (pcurve_off;
 * -1 without a pcurve): found once for both checks. */
typedef struct {
    int ok;
    double s, X[3], off[2];
} fit_middle;

static void fit_middles(ic_pair *pair, const ic_curve_fit *f, const ic_hermite_node *nodes, int n,
                        fit_middle *mid)
{
    for (int i = 0; i + 1 < n; i++) {
        fit_middle *m = &mid[i];
        m->s = 0.5 * (nodes[i].s + nodes[i + 1].s);
        m->ok = ic_bspline_eval(&f->curve, m->s, 0, m->X, NULL) == IC_OK;
        for (int k = 0; k < 2; k++) {
            double uv[2];
            m->off[k] =
                m->ok && f->pcurves[k].ncontrol ? pcurve_off(pair, f, k, m->s, m->X, uv) : -1;
        }
    }
}

/* The pcurves at the middle of every stretch: one whose image leaves the
 * curve by more than tol somewhere (a stretch across a point where its
 * sheet's parametrisation degenerates, a sphere's pole: the parameters jump
 * there) is dropped, and said so. */
static void check_pcurves(ic_curve_fit *f, const fit_middle *mid, int n, double tol)
{
    for (int k = 0; k < 2; k++)
        for (int i = 0; f->pcurves[k].ncontrol && i + 1 < n; i++) {
            if (mid[i].off[k] >= 0 && mid[i].off[k] <= tol)
                continue;
            free(f->pcurves[k].knots);
            free(f->pcurves[k].control);
            memset(&f->pcurves[k], 0, sizeof f->pcurves[k]);
            f->pcurve_dropped[k] = 1;
        }
}

/* The distance from X to an implicit surface, first order: |f| / |grad f|. */
static double implicit_distance(ic_surface *S, const ic_jet_space *sp3, const double X[3])
{
    double t[4];
    if (ic_surface_taylor(S, t, X, sp3, NULL) != IC_OK)
        return -1;
    const double g = sqrt(t[1] * t[1] + t[2] * t[2] + t[3] * t[3]);
    return g > 0 ? fabs(t[0]) / g : -1;
}

/* The distance from X to a parametric sheet near uv: Gauss-Newton on
 * |R(u, v) - X|^2 from uv (a sheet without a pcurve: the parameters the
 * stretch's end points give its middle), a few steps. Every |R(u, v) - X|
 * met bounds the distance from above: the least is returned, so a step
 * that goes astray (near a degenerate point) never makes the fit look
 * better or worse than a point of the sheet shows. */
static double sheet_distance(ic_surface *S, const ic_jet_space *sp2, const double X[3],
                             const double uv0[2])
{
    double uv[2] = {uv0[0], uv0[1]}, least = INFINITY;
    for (int it = 0; it < 8; it++) {
        double t[9], d[3];
        if (ic_surface_taylor(S, t, uv, sp2, NULL) != IC_OK)
            break;
        const double Ru[3] = {t[1], t[4], t[7]}, Rv[3] = {t[2], t[5], t[8]};
        for (int k = 0; k < 3; k++)
            d[k] = t[3 * k] - X[k];
        least = fmin(least, ic_norm3(d));
        const double E = ic_dot3(Ru, Ru), F = ic_dot3(Ru, Rv), G = ic_dot3(Rv, Rv);
        const double a = ic_dot3(Ru, d), b = ic_dot3(Rv, d), det = E * G - F * F;
        if (!(det > 0))
            break;
        uv[0] -= (G * a - F * b) / det, uv[1] -= (E * b - F * a) / det;
    }
    return isfinite(least) ? least : -1;
}

/* Sheet k's parameters at the middle of the stretch from a to b: the mean
 * of theirs, across a periodic seam by the nearer representative. */
static void middle_params(ic_surface *S, const ic_trace_point *a, const ic_trace_point *b, int k,
                          double uv[2])
{
    double dom[2][2];
    int periodic[2];
    ic_surface_get_domain(S, dom, periodic);
    for (int i = 0; i < 2; i++) {
        const double period = periodic[i] ? dom[i][1] - dom[i][0] : 0;
        uv[i] = 0.5 * (a->params[k][i] + ic_fit_unwrap(b->params[k][i], a->params[k][i], period));
    }
}

void ic_fit_spaces_free(fit_spaces *sp)
{
    ic_jet_space_free(sp->sheet);
    ic_jet_space_free(sp->sheet1);
    ic_jet_space_free(sp->point1);
}

ic_status ic_fit_spaces_new(fit_spaces *sp, ic_error *err)
{
    memset(sp, 0, sizeof *sp);
    if (ic_jet_space_new(&sp->sheet, 2, 2, err) == IC_OK &&
        ic_jet_space_new(&sp->sheet1, 2, 1, err) == IC_OK &&
        ic_jet_space_new(&sp->point1, 3, 1, err) == IC_OK)
        return IC_OK;
    ic_fit_spaces_free(sp);
    return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory fitting a curve");
}

/* The fitted curve's point at m, the middle of the stretch from point a to
 * point b, against both surfaces: its distance to each (through a pcurve's
 * image where the sheet has one). -1 where it cannot be measured. */
static double check_at(ic_pair *pair, const ic_curve_fit *f, const ic_trace_point *a,
                       const ic_trace_point *b, const fit_middle *m, const fit_spaces *sp)
{
    double worst = 0;
    if (!m->ok)
        return -1;
    for (int k = 0; k < 2; k++) {
        ic_surface *S = ic_pair_surface(pair, k);
        double uv[2], e;
        if (ic_surface_get_kind(S) == IC_IMPLICIT)
            e = implicit_distance(S, sp->point1, m->X);
        else if (f->pcurves[k].ncontrol)
            e = m->off[k];
        else { /* from the mean of the ends' parameters, and from each end's:
                * across a glued edge the mean lies far away (a Klein
                * bottle's u = 2 pi to u = 0), and each start only bounds
                * the distance from above */
            middle_params(S, a, b, k, uv);
            e = sheet_distance(S, sp->sheet1, m->X, uv);
            for (int end = 0; end < 2; end++) {
                const double ea = sheet_distance(S, sp->sheet1, m->X, (end ? b : a)->params[k]);
                e = ea >= 0 && (e < 0 || ea < e) ? ea : e;
            }
        }
        if (e < 0)
            return -1;
        worst = fmax(worst, e);
    }
    return worst;
}

/* Checks the fit at the middle of every stretch between its nodes. */
static void check_fit(ic_pair *pair, ic_curve_fit *f, const ic_trace_curve *c,
                      const fit_middle *mid, const int *source, int n, double tol,
                      const fit_spaces *sp, double *bad, int *nbad)
{
    *nbad = 0;
    f->fit_error = 0;
    f->checks = 0;
    for (int k = 0; k + 1 < n; k++) {
        const double e =
            check_at(pair, f, &c->points[source[k]], &c->points[source[k + 1]], &mid[k], sp);
        if (e < 0) /* no corrected point there: unchecked, said by checks */
            continue;
        f->fit_error = fmax(f->fit_error, e);
        f->checks++;
        if (e > tol) /* to be refined: a node at its middle */
            bad[(*nbad)++] = mid[k].s;
    }
}

/* The pcurves checked, then the fit (check_pcurves, check_fit), at the
 * middles of the stretches between the n nodes. */
ic_status ic_fit_check_all(ic_pair *pair, ic_curve_fit *f, const ic_trace_curve *c,
                           const ic_hermite_node *nodes, const int *source, int n, double tol,
                           const fit_spaces *sp, double *bad, int *nbad, ic_error *err)
{
    fit_middle *mid = malloc(sizeof *mid * (size_t)n);
    if (!mid)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory checking a curve's fit");
    fit_middles(pair, f, nodes, n, mid);
    check_pcurves(f, mid, n, tol);
    check_fit(pair, f, c, mid, source, n, tol, sp, bad, nbad);
    free(mid);
    return IC_OK;
}
