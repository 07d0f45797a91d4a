/*
 * Exact paths for quadric pairs that meet in conics (docs/tracing.md,
 * "Exact paths"): a plane and a sphere, cylinder, cone or ellipsoid
 * meeting in an ellipse (exact_quadric.c; the coaxial ones are the
 * revolution path's), and two cylinders of equal radius whose axes meet,
 * two ellipses through two branch points (exact_cylinders.c). Implicit
 * primitives, or NURBS patches recognised as planes, cylinders and cones
 * (exact_source.h), each keeping what it covers of the ellipses
 * (exact_ellipse_cover.c) and giving their points its parameters
 * (exact_ellipse_nets.c). Every borderline case (a conic that is not an ellipse
 * or nearly is not, surfaces that nearly touch along it, an ellipse the box
 * cuts or nearly touches, or a patch's edge, axes that nearly miss, radii that nearly agree)
 * is left to the general path, the reference (ic_trace_options.exact_paths
 * = 0 always takes it).
 */
#include "exact_common.h"
#include "exact_conic.h"
#include "exact_paths.h"
#include "exact_ellipse_nets.h"
#include "exact_profile.h"
#include "trace/core/options.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

const char ic_trace_method_conic[] = "closed form: plane sections of quadrics";
const char ic_trace_method_conic_nets[] =
    "closed form: NURBS nets recognised as plane sections of quadrics";

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

/* Where the conics lie against the box (ic_exact_box_side, when there is
 * one) and what the patches cover: 1 all on, 0 all off, -1 otherwise (the
 * ellipses of two cylinders share their branch points: one on and one off
 * is only rounding at the margin). */
static int conics_side(const ic_trace_options *opt, const ic_exact_source src[2],
                       const ic_conic_found *f, double L)
{
    int in = 0, out = 0;
    for (int i = 0; i < f->nellipses; i++) {
        int side = 1;
        if (opt->has_box) {
            double ext[3];
            ic_exact_ellipse_extent(&f->ellipse[i], ext);
            side = ic_exact_box_side(opt, f->ellipse[i].c, ext, L);
        }
        for (int s = 0; s < 2 && side == 1; s++)
            side = ic_exact_ellipse_covered(&src[s], &f->ellipse[i], IC_EXACT_COVER_MARGIN * L);
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

/* The ellipses (their points pts[i] when on nets, taken: freed by the
 * result from now on; else written from the plan), then the branch points
 * (exact: located in closed form, of two branches each, as the search
 * classifies them). */
static ic_status add_found(ic_trace_result *r, const ic_conic_found *f, const ic_ellipse_plan *plan,
                           ic_trace_point **pts, const int *np, const ic_trace_options *opt,
                           ic_error *err)
{
    ic_status st = IC_OK;
    for (int i = 0; i < f->nellipses; i++) {
        if (st != IC_OK)
            free(pts[i]);
        else if (pts[i])
            st = ic_exact_add_ellipse_points(r, &f->ellipse[i], pts[i], np[i], opt, err);
        else
            st = ic_exact_add_ellipse(r, &f->ellipse[i], &plan[i], opt, err);
    }
    for (int i = 0; st == IC_OK && i < f->nbranch; i++) {
        if (ic_trace_add_exact_special(r, f->branch[i], IC_POINT_BRANCH) != 0)
            return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory adding a point");
        r->specials[r->nspecials - 1].nbranches = 2;
    }
    return st;
}

/* Every ellipse's points on the recognised patches (pts[i], np[i]; all
 * NULL when neither source is a patch): 0, 1 where the general path must
 * trace, -1 out of memory; nothing kept unless 0. */
static int ellipses_on_nets(ic_pair *pair, const ic_exact_source src[2], const ic_conic_found *f,
                            const ic_ellipse_plan *plan, double L, ic_trace_point **pts, int *np)
{
    int st = 0;
    for (int i = 0; i < 2; i++)
        pts[i] = NULL, np[i] = 0;
    for (int i = 0; st == 0 && i < f->nellipses && (src[0].net || src[1].net); i++)
        st = ic_exact_ellipse_net_points(pair, src, &f->ellipse[i], &plan[i], L, &pts[i], &np[i]);
    for (int i = 0; st != 0 && i < 2; i++) {
        free(pts[i]);
        pts[i] = NULL;
    }
    return st;
}

/* The conic path on the two sources (pair NULL for two implicit primitives
 * given as such: no patches to orient against). */
static ic_status conic_on_sources(ic_trace_result *r, ic_pair *pair, const ic_exact_source src[2],
                                  const ic_trace_options *user_opt, int *done, ic_error *err)
{
    *done = 0;
    const double L = r->scale;
    ic_conic_found f;
    if (conic_pieces(&src[0].prim, &src[1].prim, L, &f) != 0)
        return IC_OK;
    const int side = conics_side(user_opt, src, &f, L);
    if (side < 0)
        return IC_OK;
    if (side == 0) /* beyond the box or the patches: nothing there, as the search finds */
        f.nellipses = f.nbranch = 0;
    /* the marching's lengths at the size of what was found, as the search
     * would take them */
    const double F = found_scale(L, &f);
    const ic_trace_options opt = ic_trace_absolute_options(user_opt, F);
    ic_ellipse_plan plan[2];
    for (int i = 0; i < f.nellipses; i++)
        if (ic_exact_ellipse_plan(&opt, &f.ellipse[i], &plan[i]) != 0)
            return IC_OK; /* the general path reports the budget */
    ic_trace_point *pts[2];
    int np[2];
    const int st = ellipses_on_nets(pair, src, &f, plan, L, pts, np);
    if (st < 0)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory tracing an ellipse");
    if (st > 0)
        return IC_OK;
    *done = 1;
    r->scale = F;
    const int nets = src[0].net || src[1].net;
    ic_exact_report(&r->report, nets ? ic_trace_method_conic_nets : ic_trace_method_conic);
    return add_found(r, &f, plan, pts, np, &opt, err);
}

ic_status ic_trace_exact_conic_primitives(ic_trace_result *r, const ic_primitive *pa,
                                          const ic_primitive *pb, const ic_trace_options *user_opt,
                                          int *done, ic_error *err)
{
    ic_exact_source src[2];
    memset(src, 0, sizeof src);
    src[0].prim = *pa, src[1].prim = *pb;
    return conic_on_sources(r, NULL, src, user_opt, done, err);
}

ic_status ic_trace_exact_conic(ic_trace_result *r, ic_pair *pair, const ic_trace_options *user_opt,
                               int *done, ic_error *err)
{
    *done = 0;
    if (!user_opt->exact_paths)
        return IC_OK;
    ic_exact_source src[2];
    const int sources = ic_exact_sources(pair, src);
    if (sources < 0)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory recognising a NURBS patch");
    if (sources == 0 || !ic_exact_conic_source_ok(&src[0]) || !ic_exact_conic_source_ok(&src[1]))
        return IC_OK;
    if (!src[0].net && !src[1].net && !user_opt->has_box) /* implicit: sought in a box */
        return IC_OK;
    return conic_on_sources(r, pair, src, user_opt, done, err);
}
