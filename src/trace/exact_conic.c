/*
 * Exact paths for quadric pairs that meet in conics (docs/tracing.md,
 * "Exact paths"): a plane and a sphere, cylinder, cone or ellipsoid
 * meeting in an ellipse (exact_quadric.c; the coaxial ones are the
 * revolution path's), and two cylinders of equal radius whose axes meet,
 * two ellipses through two branch points (exact_cylinders.c). Implicit
 * primitives only. Every borderline case (a conic that is not an ellipse
 * or nearly is not, surfaces that nearly touch along it, an ellipse the box
 * cuts or nearly touches, axes that nearly miss, radii that nearly agree)
 * is left to the general path, the reference (ic_trace_options.exact_paths
 * = 0 always takes it).
 */
#include "exact_common.h"
#include "exact_conic.h"
#include "exact_profile.h"
#include "surface/surface_internal.h"

#include <math.h>
#include <string.h>

const char ic_trace_method_conic[] = "closed form: plane sections of quadrics";

int ic_exact_ellipse_fair(const ic_exact_ellipse *e, double L)
{
    const double lo = fmin(e->a, e->b), hi = fmax(e->a, e->b);
    return lo > IC_EXACT_NEAR * L && hi <= IC_EXACT_MAX_ASPECT * lo;
}

/* The plane's ellipse on the quadric, the gradients in the pair's order. */
static int plane_and_quadric(const ic_primitive *plane, const ic_quadric *q, int plane_first,
                             double L, ic_conic_found *f)
{
    const int met = ic_exact_plane_section(plane, q, L, &f->ellipse[0]);
    if (met < 0)
        return -1;
    f->nellipses = met;
    if (met && !plane_first) {
        ic_exact_ellipse *e = &f->ellipse[0];
        double g[3][3];
        memcpy(g, e->grad[0], sizeof g);
        memcpy(e->grad[0], e->grad[1], sizeof g);
        memcpy(e->grad[1], g, sizeof g);
    }
    return 0;
}

/* The conics of the two primitives: 0 with them in *f, -1 where the general
 * path must decide. */
static int conic_pieces(const ic_primitive *pa, const ic_primitive *pb, double L, ic_conic_found *f)
{
    memset(f, 0, sizeof *f);
    ic_quadric q[2];
    const ic_primitive *p[2] = {pa, pb};
    int quadrics = 0, plane = -1;
    for (int i = 0; i < 2; i++) {
        if (p[i]->kind == IC_PRIM_PLANE)
            plane = i;
        else if (ic_quadric_of(p[i], &q[i]) == 0)
            quadrics++;
    }
    if (quadrics == 2)
        return ic_exact_equal_cylinders(&q[0], &q[1], L, f);
    if (quadrics == 1 && plane >= 0)
        return plane_and_quadric(p[plane], &q[1 - plane], plane == 0, L, f);
    return -1;
}

/* Where the conics lie against the box (ic_exact_box_side): 1 all inside,
 * 0 all outside, -1 otherwise (the ellipses of two cylinders share their
 * branch points: one in and one out is only rounding at the margin). */
static int conics_side(const ic_trace_options *opt, const ic_conic_found *f, double L)
{
    int in = 0, out = 0;
    for (int i = 0; i < f->nellipses; i++) {
        double ext[3];
        ic_exact_ellipse_extent(&f->ellipse[i], ext);
        const int side = ic_exact_box_side(opt, f->ellipse[i].c, ext, L);
        if (side < 0)
            return -1;
        in += side == 1, out += side == 0;
    }
    return in && out ? -1 : out == 0;
}

/* The size of what was found (ic_exact_found_scale): the box around the
 * ellipses. */
static double found_scale(double L, const ic_conic_found *f)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int i = 0; i < f->nellipses; i++) {
        double ext[3];
        ic_exact_ellipse_extent(&f->ellipse[i], ext);
        ic_exact_extent_add(lo, hi, f->ellipse[i].c, ext);
    }
    return ic_exact_found_scale(L, lo, hi);
}

/* The ellipses, then the branch points (exact: located in closed form, of
 * two branches each, as the search classifies them). */
static ic_status add_found(ic_trace_result *r, const ic_conic_found *f, const ic_ellipse_plan *plan,
                           const ic_trace_options *opt, ic_error *err)
{
    for (int i = 0; i < f->nellipses; i++) {
        const ic_status st = ic_exact_add_ellipse(r, &f->ellipse[i], &plan[i], opt, err);
        if (st != IC_OK)
            return st;
    }
    for (int i = 0; i < f->nbranch; i++) {
        if (ic_trace_add_exact_special(r, f->branch[i], IC_POINT_BRANCH) != 0)
            return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory adding a point");
        r->specials[r->nspecials - 1].nbranches = 2;
    }
    return IC_OK;
}

ic_status ic_trace_exact_conic_primitives(ic_trace_result *r, const ic_primitive *pa,
                                          const ic_primitive *pb, const ic_trace_options *user_opt,
                                          int *done, ic_error *err)
{
    *done = 0;
    const double L = r->scale;
    ic_conic_found f;
    if (conic_pieces(pa, pb, L, &f) != 0)
        return IC_OK;
    const int side = conics_side(user_opt, &f, L);
    if (side < 0)
        return IC_OK;
    if (side == 0) /* beyond the box: nothing there, as the search finds */
        f.nellipses = f.nbranch = 0;
    /* the marching's lengths at the size of what was found, as the search
     * would take them */
    const double F = found_scale(L, &f);
    const ic_trace_options opt = ic_trace_absolute_options(user_opt, F);
    ic_ellipse_plan plan[2];
    for (int i = 0; i < f.nellipses; i++)
        if (ic_exact_ellipse_plan(&opt, &f.ellipse[i], &plan[i]) != 0)
            return IC_OK; /* the general path reports the budget */
    *done = 1;
    r->scale = F;
    ic_exact_report(&r->report, ic_trace_method_conic);
    return add_found(r, &f, plan, &opt, err);
}

ic_status ic_trace_exact_conic(ic_trace_result *r, ic_pair *pair, const ic_trace_options *user_opt,
                               int *done, ic_error *err)
{
    *done = 0;
    if (!user_opt->exact_paths || !user_opt->has_box || ic_pair_is_self(pair))
        return IC_OK;
    const ic_primitive *p[2];
    for (int i = 0; i < 2; i++) {
        const ic_surface *s = ic_pair_surface(pair, i);
        if (s->backend != BACKEND_PRIMITIVE || s->kind != IC_IMPLICIT)
            return IC_OK;
        p[i] = &s->prim;
    }
    return ic_trace_exact_conic_primitives(r, p[0], p[1], user_opt, done, err);
}
