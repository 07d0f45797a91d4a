/*
 * Exact paths for coaxial surfaces of revolution (docs/tracing.md, "Exact
 * paths"): a plane normal to the axis, a sphere centred on it, a cylinder,
 * a cone with its apex on it and a torus about it, implicit primitives or
 * NURBS patches recognised as them (exact_source.h), meet in circles about
 * the axis and in points on it. Their meridian profiles (exact_profile.c)
 * meet where the surfaces do: a crossing at rho > 0 is a transversal
 * circle, a tangency there a tangential circle, a tangency on the axis an
 * isolated contact. A patch keeps what it covers (exact_cover.c), and its
 * circles carry its parameters (exact_circle.c). Everything else
 * (coincident or nearly tangent profiles, a cone's apex on the other
 * surface, a circle the box or a patch's edge cuts, axes only nearly one)
 * is left to the general path, which stays the reference
 * (ic_trace_options.exact_paths = 0 always takes it).
 */
#include "exact_circle.h"
#include "exact_common.h"
#include "exact_profile.h"
#include "exact_source.h"
#include "exact_paths.h"
#include "trace/core/options.h"
#include "common/mathconst.h"
#include "common/vec3.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

const char ic_trace_method_revolution[] = "closed form: coaxial surfaces of revolution";
const char ic_trace_method_revolution_nets[] =
    "closed form: NURBS nets recognised as coaxial surfaces of revolution";


/* The common axis: through o along the unit e, with (u, v, e) right-handed
 * orthonormal (u is where the circles' points start). */
typedef struct {
    double o[3], e[3], u[3], v[3];
} axis;

/* A circle (rho > 0) or a contact point (rho = 0) of the intersection. */
typedef struct {
    double rho, z, angle;
    int tangent;
} piece_found;

/* The surfaces this path takes: no ellipsoid, no torus whose tube reaches
 * the axis (a spindle, singular there). */
static int revolves(const ic_exact_source *s)
{
    const ic_primitive *p = &s->prim;
    return p->kind != IC_PRIM_ELLIPSOID &&
           (p->kind != IC_PRIM_TORUS || p->radius < p->major_radius);
}

static int has_axis_line(const ic_exact_source *s)
{
    return s->prim.kind == IC_PRIM_CYLINDER || s->prim.kind == IC_PRIM_CONE ||
           s->prim.kind == IC_PRIM_TORUS;
}

/* u, v completing the unit e to a right-handed frame. */
static void complete_frame(axis *ax)
{
    int k = 0; /* the coordinate axis least aligned with e */
    for (int i = 1; i < 3; i++)
        if (fabs(ax->e[i]) < fabs(ax->e[k]))
            k = i;
    double x[3] = {0, 0, 0};
    x[k] = 1;
    ic_axpy3(ax->u, x, -ic_dot3(x, ax->e), ax->e);
    ic_normalize3(ax->u);
    ic_cross3(ax->v, ax->e, ax->u);
}

static void axis_from_frame(axis *ax, const double *o, const double (*frame)[3])
{
    memcpy(ax->o, o, sizeof ax->o);
    memcpy(ax->u, frame[0], sizeof ax->u);
    memcpy(ax->v, frame[1], sizeof ax->v);
    memcpy(ax->e, frame[2], sizeof ax->e);
}

/* The axis both surfaces would share: a surface's own axis line, else the
 * plane's normal through the sphere's centre, else the line of the
 * spheres' centres (any through them when they are one point). */
static void candidate_axis(const ic_exact_source *a, const ic_exact_source *b, axis *ax)
{
    const ic_exact_source *s[2] = {a, b};
    for (int i = 0; i < 2; i++)
        if (has_axis_line(s[i])) {
            axis_from_frame(ax, s[i]->prim.center, s[i]->frame);
            return;
        }
    for (int i = 0; i < 2; i++)
        if (s[i]->prim.kind == IC_PRIM_PLANE) {
            const ic_exact_source *other = s[1 - i];
            axis_from_frame(ax, other->prim.center, s[i]->frame);
            return;
        }
    memcpy(ax->o, a->prim.center, sizeof ax->o);
    ic_axpy3(ax->e, b->prim.center, -1.0, a->prim.center);
    if (ic_normalize3(ax->e) == 0.0)
        ax->e[0] = ax->e[1] = 0, ax->e[2] = 1;
    complete_frame(ax);
}

/* Whether the surface is one of revolution about the axis, within
 * IC_EXACT_COAXIAL: its direction along e, its centre on the line. */
static int about_axis(const ic_exact_source *s, const axis *ax, double L)
{
    double w[3], c[3];
    if (s->prim.kind != IC_PRIM_SPHERE) {
        ic_cross3(c, s->frame[2], ax->e);
        if (ic_norm3(c) > IC_EXACT_COAXIAL)
            return 0;
    }
    if (s->prim.kind == IC_PRIM_PLANE)
        return 1;
    ic_axpy3(w, s->prim.center, -1.0, ax->o);
    ic_axpy3(w, w, -ic_dot3(w, ax->e), ax->e);
    return ic_norm3(w) <= IC_EXACT_COAXIAL * L;
}

static void set_line(ic_profile_piece *pc, double rho, double z, double drho, double dz)
{
    pc->circle = 0;
    pc->c[0] = rho, pc->c[1] = z, pc->d[0] = drho, pc->d[1] = dz;
}

static void set_circle(ic_profile_piece *pc, double rho, double z, double r)
{
    pc->circle = 1;
    pc->c[0] = rho, pc->c[1] = z, pc->r = r;
}

static void profile_of(const ic_exact_source *s, const axis *ax, ic_profile *pr)
{
    const ic_primitive *p = &s->prim;
    double w[3];
    ic_axpy3(w, p->center, -1.0, ax->o);
    const double h = ic_dot3(w, ax->e);
    pr->n = 1;
    pr->flat_on_axis = p->kind == IC_PRIM_PLANE || p->kind == IC_PRIM_SPHERE;
    switch (p->kind) {
    case IC_PRIM_PLANE:
        set_line(&pr->piece[0], 0, h, 1, 0);
        break;
    case IC_PRIM_SPHERE:
        set_circle(&pr->piece[0], 0, h, p->radius);
        break;
    case IC_PRIM_CYLINDER:
        set_line(&pr->piece[0], p->radius, 0, 0, 1);
        break;
    case IC_PRIM_CONE: /* both nappes */
        pr->n = 2;
        set_line(&pr->piece[0], 0, h, sin(p->half_angle), cos(p->half_angle));
        set_line(&pr->piece[1], 0, h, sin(p->half_angle), -cos(p->half_angle));
        break;
    case IC_PRIM_TORUS:
        set_circle(&pr->piece[0], p->major_radius, h, p->radius);
        break;
    case IC_PRIM_ELLIPSOID:
        break;
    }
}

/* The centre of the circle of the axis of radius rho at height z, and its
 * half-extent along each coordinate axis. */
static void circle_extent(const axis *ax, double rho, double z, double centre[3], double ext[3])
{
    for (int k = 0; k < 3; k++) {
        centre[k] = ax->o[k] + z * ax->e[k];
        ext[k] = rho * sqrt(fmax(0.0, 1.0 - ax->e[k] * ax->e[k]));
    }
}

/* Where a circle of the axis (a point when rho = 0) lies against the box
 * (ic_exact_box_side). */
static int box_side(const ic_trace_options *opt, const axis *ax, double rho, double z, double L)
{
    double centre[3], ext[3];
    circle_extent(ax, rho, z, centre, ext);
    return ic_exact_box_side(opt, centre, ext, L);
}

/* Where the circle (the point when rho = 0) at height z lies against the
 * box (when there is one) and the patches' covered parts: 1 on all, 0 off
 * one, -1 where the general path must decide. */
static int place_side(const ic_trace_options *opt, const axis *ax, const ic_exact_source src[2],
                      double rho, double z, double L)
{
    const int box = opt->has_box ? box_side(opt, ax, rho, z, L) : 1;
    if (box <= 0)
        return box;
    double c[3];
    ic_axpy3(c, ax->o, z, ax->e);
    int side = 1;
    for (int s = 0; s < 2 && side != 0; s++) {
        const int on = ic_exact_covers(&src[s], c, ax->e, rho, IC_EXACT_COVER_MARGIN * L);
        side = on == 0 ? 0 : on < 0 ? -1 : side;
    }
    return side;
}

/* The circles and contact points in the box and on the patches: their
 * count, or -1 where the general path must decide. */
static int intersection_pieces(const ic_profile *pa, const ic_profile *pb, const axis *ax,
                               const ic_exact_source src[2], const ic_trace_options *opt, double L,
                               piece_found found[IC_PROFILE_MAX_MEETINGS])
{
    ic_profile_meeting m[IC_PROFILE_MAX_MEETINGS];
    int nm, nf = 0;
    if (ic_profile_meet(pa, pb, L, m, &nm) != 0)
        return -1;
    for (int i = 0; i < nm; i++) {
        double rho = m[i].rho;
        if (rho < -IC_EXACT_NEAR * L) /* the mirror image of a meeting at -rho */
            continue;
        if (rho <= IC_EXACT_NEAR * L) { /* on the axis: a contact where both are flat there */
            if (!m[i].tangent || fabs(rho) > IC_EXACT_TANGENT * L || !pa->flat_on_axis ||
                !pb->flat_on_axis)
                return -1;
            rho = 0;
        } else if (!m[i].tangent && m[i].angle < IC_EXACT_MIN_ANGLE) {
            return -1;
        }
        const int side = place_side(opt, ax, src, rho, m[i].z, L);
        if (side < 0)
            return -1;
        if (side == 0)
            continue;
        found[nf].rho = rho, found[nf].z = m[i].z, found[nf].angle = m[i].angle;
        found[nf++].tangent = m[i].tangent;
    }
    return nf;
}

/* The arcs a circle is traced in, a multiple of 8 (exact_circle.c); 0 when
 * the point budget is too small. */
static int circle_arcs(const ic_trace_options *opt, double rho)
{
    double n = ceil(2 * IC_PI * rho / ic_exact_circle_step(opt, rho) / 8) * 8;
    n = n < IC_EXACT_MIN_ARCS ? IC_EXACT_MIN_ARCS : n;
    return n + 1 <= opt->max_points ? (int)n : 0;
}

/* The circle a piece found sweeps about the axis. */
static ic_exact_circle circle_of(const axis *ax, const piece_found *f)
{
    ic_exact_circle c;
    ic_axpy3(c.centre, ax->o, f->z, ax->e);
    memcpy(c.u, ax->u, sizeof c.u);
    memcpy(c.v, ax->v, sizeof c.v);
    memcpy(c.e, ax->e, sizeof c.e);
    c.rho = f->rho, c.angle = f->angle, c.tangent = f->tangent;
    return c;
}

/* Every circle's points (pts[i], np[i]; NULL for a contact point): 0, 1
 * where the general path must trace (a patch's parameters cannot follow a
 * circle), -1 out of memory; nothing kept unless 0. */
static int circles_traced(ic_pair *pair, const axis *ax, const piece_found *found, int nf,
                          const ic_exact_source src[2], const ic_trace_options *opt, double L,
                          ic_trace_point *pts[IC_PROFILE_MAX_MEETINGS],
                          int np[IC_PROFILE_MAX_MEETINGS])
{
    int st = 0;
    for (int i = 0; i < nf; i++) {
        pts[i] = NULL;
        if (st != 0 || found[i].rho == 0)
            continue;
        ic_exact_circle c = circle_of(ax, &found[i]);
        st = ic_exact_circle_points(&c, circle_arcs(opt, found[i].rho), src, L, &pts[i], &np[i]);
        /* on recognised nets, the way the general path runs (two implicit
         * primitives keep theirs: counterclockwise about the axis) */
        if (st == 0 && !found[i].tangent && (src[0].net || src[1].net))
            ic_exact_circle_orient(pair, pts[i], np[i]);
    }
    for (int i = 0; st != 0 && i < nf; i++) {
        free(pts[i]);
        pts[i] = NULL;
    }
    return st;
}

/* The circles (their points taken, freed by the result from now on) and
 * the contact points into the result. */
static ic_status add_pieces(ic_trace_result *r, const axis *ax, const piece_found *found, int nf,
                            ic_trace_point **pts, const int *np, const ic_trace_options *opt,
                            ic_error *err)
{
    ic_status st = IC_OK;
    for (int i = 0; i < nf; i++) {
        const piece_found *f = &found[i];
        if (f->rho == 0) {
            double x[3];
            ic_axpy3(x, ax->o, f->z, ax->e);
            if (st == IC_OK && ic_trace_add_exact_special(r, x, IC_POINT_ISOLATED_CONTACT) != 0)
                st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory adding a point");
            continue;
        }
        if (st != IC_OK) {
            free(pts[i]);
            continue;
        }
        /* a circle by construction: kappa constant, tau 0 exactly, which
         * the shape test (shape.c) reads as a circle at any tolerance */
        st = ic_trace_add_shaped_curve(r, pts[i], np[i], 1, IC_TRACE_CLOSED, IC_TRACE_CLOSED,
                                       opt->shape_tol, IC_SHAPE_CIRCLE, -1, -1, err);
        if (st == IC_OK)
            r->curves[r->ncurves - 1].tangential = f->tangent;
    }
    return st;
}

/* The size of what was found (ic_exact_found_scale): the box around the
 * circles and points. */
static double found_scale(double L, const axis *ax, const piece_found *found, int nf)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int i = 0; i < nf; i++) {
        double centre[3], ext[3];
        circle_extent(ax, found[i].rho, found[i].z, centre, ext);
        ic_exact_extent_add(lo, hi, centre, ext);
    }
    return ic_exact_found_scale(L, lo, hi);
}

/* The profiles about the common axis and where they meet: the count of
 * circles and points, or -1 (the general path). */
static int coaxial_pieces(const ic_exact_source src[2], const ic_trace_options *opt, double L,
                          axis *ax, piece_found found[IC_PROFILE_MAX_MEETINGS])
{
    candidate_axis(&src[0], &src[1], ax);
    if (!about_axis(&src[0], ax, L) || !about_axis(&src[1], ax, L))
        return -1;
    ic_profile pa, pb;
    profile_of(&src[0], ax, &pa);
    profile_of(&src[1], ax, &pb);
    return intersection_pieces(&pa, &pb, ax, src, opt, L, found);
}

ic_status ic_trace_exact_revolution(ic_trace_result *r, ic_pair *pair,
                                    const ic_trace_options *user_opt, int *done, ic_error *err)
{
    *done = 0;
    ic_exact_source src[2];
    if (!user_opt->exact_paths)
        return IC_OK;
    const int sources = ic_exact_sources(pair, src);
    if (sources < 0)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory recognising a NURBS patch");
    if (sources == 0 || !revolves(&src[0]) || !revolves(&src[1]))
        return IC_OK;
    const int nets = src[0].net || src[1].net;
    if (!nets && !user_opt->has_box) /* two implicit surfaces are sought in a box */
        return IC_OK;
    const double L = r->scale;
    axis ax;
    piece_found found[IC_PROFILE_MAX_MEETINGS];
    const int nf = coaxial_pieces(src, user_opt, L, &ax, found);
    if (nf < 0)
        return IC_OK;
    /* the marching's lengths at the size of what was found, as the search
     * would take them */
    const double F = found_scale(L, &ax, found, nf);
    const ic_trace_options opt = ic_trace_absolute_options(user_opt, F);
    for (int i = 0; i < nf; i++)
        if (found[i].rho > 0 && circle_arcs(&opt, found[i].rho) == 0)
            return IC_OK; /* the general path reports the budget */
    ic_trace_point *pts[IC_PROFILE_MAX_MEETINGS];
    int np[IC_PROFILE_MAX_MEETINGS];
    const int st = circles_traced(pair, &ax, found, nf, src, &opt, L, pts, np);
    if (st < 0)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory tracing a circle");
    if (st > 0)
        return IC_OK;
    *done = 1;
    r->scale = F;
    ic_exact_report(&r->report, nets ? ic_trace_method_revolution_nets : ic_trace_method_revolution);
    return add_pieces(r, &ax, found, nf, pts, np, &opt, err);
}
