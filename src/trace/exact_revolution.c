/*
 * Exact paths for coaxial surfaces of revolution (docs/tracing.md, "Exact
 * paths"): a plane normal to the axis, a sphere centred on it, a cylinder,
 * a cone with its apex on it and a torus about it, all implicit primitives,
 * meet in circles about the axis and in points on it. Their meridian
 * profiles (exact_profile.c) meet where the surfaces do: a crossing at
 * rho > 0 is a transversal circle, a tangency there a tangential circle, a
 * tangency on the axis an isolated contact. Everything else (coincident or
 * nearly tangent profiles, a cone's apex on the other surface, a circle the
 * box cuts, axes only nearly one) is left to the general path, which stays
 * the reference (ic_trace_options.exact_paths = 0 always takes it).
 */
#include "exact_common.h"
#include "exact_profile.h"
#include "trace_internal.h"
#include "common/mathconst.h"
#include "common/vec3.h"
#include "surface/surface_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The report's method (ic_trace_report.method): the search's, and this
 * file's. */
const char ic_trace_method_search[] = "search";
const char ic_trace_method_revolution[] = "closed form: coaxial surfaces of revolution";

/* A primitive of the pair and its frame (rows e1, e2, e3; e3 the axis or
 * the plane's unit normal). */
typedef struct {
    const ic_primitive *p;
    const double (*frame)[3];
} revolved;

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

static int as_revolved(ic_surface *s, revolved *out)
{
    if (s->backend != BACKEND_PRIMITIVE || s->kind != IC_IMPLICIT)
        return 0;
    const ic_primitive *p = &s->prim;
    /* a torus whose tube reaches the axis is singular there (a spindle) */
    if (p->kind == IC_PRIM_ELLIPSOID || (p->kind == IC_PRIM_TORUS && !(p->radius < p->major_radius)))
        return 0;
    out->p = p;
    out->frame = (const double(*)[3])(p->kind == IC_PRIM_PLANE ? s->plane_frame : s->frame);
    return 1;
}

static int has_axis_line(const revolved *s)
{
    return s->p->kind == IC_PRIM_CYLINDER || s->p->kind == IC_PRIM_CONE ||
           s->p->kind == IC_PRIM_TORUS;
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
static void candidate_axis(const revolved *a, const revolved *b, axis *ax)
{
    const revolved *s[2] = {a, b};
    for (int i = 0; i < 2; i++)
        if (has_axis_line(s[i])) {
            axis_from_frame(ax, s[i]->p->center, s[i]->frame);
            return;
        }
    for (int i = 0; i < 2; i++)
        if (s[i]->p->kind == IC_PRIM_PLANE) {
            const revolved *other = s[1 - i];
            axis_from_frame(ax, other->p->center, s[i]->frame);
            return;
        }
    memcpy(ax->o, a->p->center, sizeof ax->o);
    ic_axpy3(ax->e, b->p->center, -1.0, a->p->center);
    if (ic_normalize3(ax->e) == 0.0)
        ax->e[0] = ax->e[1] = 0, ax->e[2] = 1;
    complete_frame(ax);
}

/* Whether the surface is one of revolution about the axis, within
 * IC_EXACT_COAXIAL: its direction along e, its centre on the line. */
static int about_axis(const revolved *s, const axis *ax, double L)
{
    double w[3], c[3];
    if (s->p->kind != IC_PRIM_SPHERE) {
        ic_cross3(c, s->frame[2], ax->e);
        if (ic_norm3(c) > IC_EXACT_COAXIAL)
            return 0;
    }
    if (s->p->kind == IC_PRIM_PLANE)
        return 1;
    ic_axpy3(w, s->p->center, -1.0, ax->o);
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

static void profile_of(const revolved *s, const axis *ax, ic_profile *pr)
{
    const ic_primitive *p = s->p;
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

/* The circles and contact points in the box: their count, or -1 where the
 * general path must decide. */
static int intersection_pieces(const ic_profile *pa, const ic_profile *pb, const axis *ax,
                               const ic_trace_options *opt, double L,
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
        const int side = box_side(opt, ax, rho, m[i].z, L);
        if (side < 0)
            return -1;
        if (side == 0)
            continue;
        found[nf].rho = rho, found[nf].z = m[i].z, found[nf].angle = m[i].angle;
        found[nf++].tangent = m[i].tangent;
    }
    return nf;
}

/* The arcs a circle is traced in, a multiple of 8 (circle_points); 0 when
 * the point budget is too small. */
static int circle_arcs(const ic_trace_options *opt, double rho)
{
    double n = ceil(2 * IC_PI * rho / ic_exact_circle_step(opt, rho) / 8) * 8;
    n = n < IC_EXACT_MIN_ARCS ? IC_EXACT_MIN_ARCS : n;
    return n + 1 <= opt->max_points ? (int)n : 0;
}

/* Point k of n on the circle, at the angle whose cosine and sine are cs, sn:
 * its exact apparatus: t about e (counterclockwise), n towards the axis,
 * b = e, kappa = 1 / rho, tau = 0. */
static void circle_point(ic_trace_point *p, int k, int n, const double *centre, const axis *ax,
                         const piece_found *f, double cs, double sn)
{
    memset(p, 0, sizeof *p);
    p->s = f->rho * (2 * IC_PI * k / n);
    for (int i = 0; i < 3; i++) {
        const double radial = cs * ax->u[i] + sn * ax->v[i];
        p->xyz[i] = centre[i] + f->rho * radial;
        p->t[i] = -sn * ax->u[i] + cs * ax->v[i];
        p->n[i] = -radial;
        p->b[i] = ax->e[i];
    }
    p->kappa = 1.0 / f->rho;
    p->tau = 0.0;
    p->angle = f->angle;
    p->frame_defined = 1;
}

/* The closed circle's n + 1 points, n a multiple of 8, the last the first
 * again at s = 2 pi rho. The cosine and sine of one octant serve all eight
 * (exact reflections: a quarter of the time of computing each). */
static void circle_points(ic_trace_point *pts, int n, const axis *ax, const piece_found *f)
{
    double c[3];
    ic_axpy3(c, ax->o, f->z, ax->e);
    const int q = n / 4;
    for (int j = 0; j <= n / 8; j++) {
        const double cs = cos(2 * IC_PI * j / n), sn = sin(2 * IC_PI * j / n);
        const int k[8] = {j, q - j, q + j, 2 * q - j, 2 * q + j, 3 * q - j, 3 * q + j, (n - j) % n};
        const double cc[8] = {cs, sn, -sn, -cs, -cs, -sn, sn, cs};
        const double ss[8] = {sn, cs, cs, sn, -sn, -cs, -cs, -sn};
        for (int m = 0; m < 8; m++)
            circle_point(&pts[k[m]], k[m], n, c, ax, f, cc[m], ss[m]);
    }
    pts[n] = pts[0];
    pts[n].s = 2 * IC_PI * f->rho;
}

static ic_status add_pieces(ic_trace_result *r, const axis *ax, const piece_found *found, int nf,
                            const ic_trace_options *opt, ic_error *err)
{
    for (int i = 0; i < nf; i++) {
        const piece_found *f = &found[i];
        if (f->rho == 0) {
            double x[3];
            ic_axpy3(x, ax->o, f->z, ax->e);
            if (ic_trace_add_exact_special(r, x, IC_POINT_ISOLATED_CONTACT) != 0)
                return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory adding a point");
            continue;
        }
        const int n = circle_arcs(opt, f->rho);
        ic_trace_point *pts = malloc((size_t)(n + 1) * sizeof *pts);
        if (!pts)
            return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory adding a curve");
        circle_points(pts, n, ax, f);
        /* a circle by construction: kappa constant, tau 0 exactly, which
         * the shape test (shape.c) reads as a circle at any tolerance */
        const ic_status st =
            ic_trace_add_shaped_curve(r, pts, n + 1, 1, IC_TRACE_CLOSED, IC_TRACE_CLOSED,
                                      opt->shape_tol, IC_SHAPE_CIRCLE, -1, -1, err);
        if (st != IC_OK)
            return st;
        r->curves[r->ncurves - 1].tangential = f->tangent;
    }
    return IC_OK;
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

ic_status ic_trace_exact_revolution(ic_trace_result *r, ic_pair *pair,
                                    const ic_trace_options *user_opt, int *done, ic_error *err)
{
    *done = 0;
    revolved a, b;
    if (!user_opt->exact_paths || !user_opt->has_box || ic_pair_is_self(pair) ||
        !as_revolved(ic_pair_surface(pair, 0), &a) || !as_revolved(ic_pair_surface(pair, 1), &b))
        return IC_OK;
    const double L = r->scale;
    axis ax;
    candidate_axis(&a, &b, &ax);
    if (!about_axis(&a, &ax, L) || !about_axis(&b, &ax, L))
        return IC_OK;
    ic_profile pa, pb;
    profile_of(&a, &ax, &pa);
    profile_of(&b, &ax, &pb);
    piece_found found[IC_PROFILE_MAX_MEETINGS];
    const int nf = intersection_pieces(&pa, &pb, &ax, user_opt, L, found);
    if (nf < 0)
        return IC_OK;
    /* the marching's lengths at the size of what was found, as the search
     * would take them */
    const double F = found_scale(L, &ax, found, nf);
    const ic_trace_options opt = ic_trace_absolute_options(user_opt, F);
    for (int i = 0; i < nf; i++)
        if (found[i].rho > 0 && circle_arcs(&opt, found[i].rho) == 0)
            return IC_OK; /* the general path reports the budget */
    *done = 1;
    r->scale = F;
    ic_exact_report(&r->report, ic_trace_method_revolution);
    return add_pieces(r, &ax, found, nf, &opt, err);
}
