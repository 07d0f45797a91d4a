/*
 * Start points by subdivision (docs/tracing.md). Cells of the search region
 * are split down to opt->depth levels; a cell where the interval enclosure of
 * a surface's equation excludes 0 holds no intersection point (proven, with
 * outward rounding) and is dropped. In each remaining leaf a Newton
 * iteration from the centre looks for a point on both surfaces; a leaf where
 * it finds none may still be proven empty by centred forms (centred.c); every
 * leaf left gets the loop test (loops.c).
 *  - implicit/implicit: cells of the box; f_A and f_B over the cell;
 *  - parametric/implicit: cells of the parameter domain; f(R(U, V)) with R's
 *    enclosure over the cell;
 *  - two parametric surfaces: cells of (u, v, p, q); R_A and R_B's boxes.
 * With `within`, one leaf is searched again a few levels finer.
 * Surfaces without interval evaluation (primitives, callbacks) cannot
 * exclude anything: then the leaves of a coarser grid are sampled and the
 * report says so.
 */
#include "trace_internal.h"
#include "common/vec3.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    double lo[4], hi[4];
    int depth;
} cell;

typedef struct {
    ic_candidate *c;
    int n, cap;
} cand_list;

static int push_candidate(cand_list *l, const ic_candidate *c)
{
    if (l->n == l->cap) {
        const int cap = l->cap ? 2 * l->cap : 64;
        ic_candidate *p = realloc(l->c, (size_t)cap * sizeof *p);
        if (!p)
            return -1;
        l->c = p;
        l->cap = cap;
    }
    l->c[l->n++] = *c;
    return 0;
}

static int excludes_zero(ic_interval a) { return ic_interval_is_empty(a) || a.lo > 0 || a.hi < 0; }

/* f and grad f of an implicit surface, both divided by the largest
 * component of grad f (the same zero set; squares of gradients near
 * overflow stay finite). */
static int value_grad(ic_surface *s, const ic_jet_space *sp, const double *x, double *f, double *g)
{
    double t[4];
    if (ic_surface_taylor(s, t, x, sp, NULL) != IC_OK)
        return -1;
    const double m = fmax(fabs(t[1]), fmax(fabs(t[2]), fabs(t[3])));
    if (!(m > 0) || !isfinite(m))
        return -1;
    *f = t[0] / m;
    g[0] = t[1] / m, g[1] = t[2] / m, g[2] = t[3] / m;
    return 0;
}

/* A Newton point is accepted when its distance to each surface is below
 * this fraction of (L + |x|): rounding leaves about 1e-15 of it. */
#define NEWTON_ACCEPT 1e-10

/* Min-norm Newton onto f_A = f_B = 0 from x: 0 converged, -1 not. */
static int newton_implicit(ic_surface *A, ic_surface *B, const ic_jet_space *sp, double L,
                           double *x)
{
    for (int it = 0; it < 40; it++) {
        double fa, fb, ga[3], gb[3];
        if (value_grad(A, sp, x, &fa, ga) || value_grad(B, sp, x, &fb, gb))
            return -1;
        const double a = ic_dot3(ga, ga), b = ic_dot3(ga, gb), c = ic_dot3(gb, gb);
        const double det = a * c - b * b;
        if (!(det > 1e-30 * a * c))
            return -1;
        const double y0 = (c * fa - b * fb) / det, y1 = (a * fb - b * fa) / det;
        double step[3];
        for (int k = 0; k < 3; k++)
            step[k] = y0 * ga[k] + y1 * gb[k];
        ic_axpy3(x, x, -1.0, step);
        if (ic_norm3(step) <= 1e-15 * (L + ic_norm3(x))) {
            const double accept = NEWTON_ACCEPT * (L + ic_norm3(x));
            return fabs(fa) / sqrt(a) < accept && fabs(fb) / sqrt(c) < accept ? 0 : -1;
        }
    }
    return -1;
}

/* Min-norm Newton onto f(R(u, v)) = 0 from uv. */
static int newton_mixed(ic_surface *P, ic_surface *I, const ic_jet_space *sp2,
                        const ic_jet_space *sp3, double L, double *uv, double *x)
{
    for (int it = 0; it < 40; it++) {
        double t[9], f, g[3];
        if (ic_surface_taylor(P, t, uv, sp2, NULL))
            return -1;
        const double X[3] = {t[0], t[3], t[6]};
        const double Ru[3] = {t[1], t[4], t[7]}, Rv[3] = {t[2], t[5], t[8]};
        if (value_grad(I, sp3, X, &f, g))
            return -1;
        const double du = ic_dot3(g, Ru), dv = ic_dot3(g, Rv), nn = du * du + dv * dv;
        if (!(nn > 0))
            return -1;
        uv[0] -= f * du / nn;
        uv[1] -= f * dv / nn;
        memcpy(x, X, sizeof X);
        if (fabs(f) * sqrt(1 / nn) <= 1e-15 * (1 + fabs(uv[0]) + fabs(uv[1])))
            return fabs(f) / ic_norm3(g) < NEWTON_ACCEPT * (L + ic_norm3(x)) ? 0 : -1;
    }
    return -1;
}

/* Min-norm Newton onto R_A(u, v) = R_B(p, q) from z = (u, v, p, q). */
static int newton_params(ic_surface *A, ic_surface *B, const ic_jet_space *sp2, double L,
                         double *z, double *x)
{
    for (int it = 0; it < 40; it++) {
        double ta[9], tb[9];
        if (ic_surface_taylor(A, ta, z, sp2, NULL) || ic_surface_taylor(B, tb, z + 2, sp2, NULL))
            return -1;
        double F[3], J[3][4];
        for (int k = 0; k < 3; k++) {
            F[k] = ta[3 * k] - tb[3 * k];
            J[k][0] = ta[3 * k + 1], J[k][1] = ta[3 * k + 2];
            J[k][2] = -tb[3 * k + 1], J[k][3] = -tb[3 * k + 2];
        }
        x[0] = ta[0], x[1] = ta[3], x[2] = ta[6];
        /* step = J^T (J J^T)^-1 F */
        double M[3][3], y[3];
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++) {
                M[a][b] = 0;
                for (int j = 0; j < 4; j++)
                    M[a][b] += J[a][j] * J[b][j];
            }
        const double det = ic_det3(M[0], M[1], M[2]);
        /* relative: det scales like the sixth power of the problem's size */
        if (!(fabs(det) > 1e-30 * fabs(M[0][0] * M[1][1] * M[2][2])))
            return -1;
        double c0[3] = {M[0][0], M[1][0], M[2][0]}, c1[3] = {M[0][1], M[1][1], M[2][1]},
               c2[3] = {M[0][2], M[1][2], M[2][2]};
        y[0] = ic_det3(F, c1, c2) / det, y[1] = ic_det3(c0, F, c2) / det;
        y[2] = ic_det3(c0, c1, F) / det;
        double size = 0;
        for (int j = 0; j < 4; j++) {
            const double step = J[0][j] * y[0] + J[1][j] * y[1] + J[2][j] * y[2];
            z[j] -= step;
            size = fmax(size, fabs(step));
        }
        if (size <= 1e-15 * (1 + fabs(z[0]) + fabs(z[1]) + fabs(z[2]) + fabs(z[3])))
            return ic_norm3(F) < NEWTON_ACCEPT * (L + ic_norm3(x)) ? 0 : -1;
    }
    return -1;
}

/* The parameter box of sheet s: its domain, which must be finite. */
static ic_status domain_box(ic_surface *const S[2], int s, double lo[2], double hi[2],
                            int per[2], ic_error *err)
{
    double dom[2][2];
    ic_surface_get_domain(S[s], dom, per);
    for (int i = 0; i < 2; i++) {
        if (!isfinite(dom[i][0]) || !isfinite(dom[i][1]) || !isfinite(dom[i][1] - dom[i][0]))
            return ic_error_set(err, IC_ERR_INVALID, 0,
                                "tracing needs a finite \"domain\" for the parametric surface %c "
                                "(surfaces[%d] of a problem file)",
                                'A' + s, s);
        lo[i] = dom[i][0], hi[i] = dom[i][1];
    }
    return IC_OK;
}

/* What one search needs: the surfaces, the pairing, the region and the
 * jet spaces of the Newton iterations. */
typedef struct {
    ic_surface *S[2];
    int par[2], both, self, mixed, P, I, dim;
    double lo[4], hi[4]; /* the whole search region */
    int periodic[4];     /* coordinates whose domain is a period */
    double dwidth[2];    /* a leaf's width in (u, v) at the first search's depth */
    int proven;
    double L; /* the problem's size */
    ic_jet_space *sp2, *sp3;
} search_ctx;

static ic_status ctx_init(search_ctx *x, ic_pair *pair, const ic_trace_options *opt,
                          ic_error *err)
{
    memset(x, 0, sizeof *x);
    ic_surface **S = x->S;
    S[0] = ic_pair_surface(pair, 0), S[1] = ic_pair_surface(pair, 1);
    x->par[0] = ic_surface_get_kind(S[0]) == IC_PARAMETRIC;
    x->par[1] = ic_surface_get_kind(S[1]) == IC_PARAMETRIC;
    x->both = x->par[0] && x->par[1], x->self = ic_pair_is_self(pair);
    x->mixed = !x->both && (x->par[0] || x->par[1]);
    x->P = x->par[0] ? 0 : 1, x->I = 1 - x->P;
    x->dim = x->both ? 4 : x->mixed ? 2 : 3;
    x->L = opt->local.scale > 0 ? opt->local.scale : 1.0;
    if (x->both) { /* (u, v, p, q) */
        if (domain_box(S, 0, x->lo, x->hi, x->periodic, err) != IC_OK ||
            domain_box(S, 1, x->lo + 2, x->hi + 2, x->periodic + 2, err) != IC_OK)
            return IC_ERR_INVALID;
    } else if (x->mixed) {
        if (domain_box(S, x->P, x->lo, x->hi, x->periodic, err) != IC_OK)
            return IC_ERR_INVALID;
    } else {
        if (!opt->has_box)
            return ic_error_set(err, IC_ERR_INVALID, 0,
                                "tracing two implicit surfaces needs a \"box\"");
        for (int k = 0; k < 3; k++) {
            x->lo[k] = opt->box[k][0], x->hi[k] = opt->box[k][1];
            if (!isfinite(x->hi[k] - x->lo[k]) || !(x->hi[k] > x->lo[k]))
                return ic_error_set(err, IC_ERR_INVALID, 0,
                                    "the box must have finite, increasing bounds");
        }
    }
    /* can the surfaces be enclosed? (formula surfaces and implicit primitives) */
    ic_interval probe_in[4], probe_out[3];
    for (int k = 0; k < 4; k++)
        probe_in[k] = (ic_interval){k < x->dim ? x->lo[k] : 0, k < x->dim ? x->hi[k] : 0};
    x->proven =
        ic_surface_eval_interval(S[0], probe_out, probe_in, NULL) == IC_OK &&
        ic_surface_eval_interval(S[1], probe_out, probe_in + (x->both ? 2 : 0), NULL) == IC_OK;
    const int full = x->both ? opt->depth - 1 : opt->depth;
    for (int k = 0; k < 2; k++)
        x->dwidth[k] = (x->hi[k] - x->lo[k]) / (1 << full);
    ic_status st = ic_jet_space_new(&x->sp2, 2, 1, err);
    if (st == IC_OK)
        st = ic_jet_space_new(&x->sp3, 3, 1, err);
    return st;
}

static void ctx_free(search_ctx *x)
{
    ic_jet_space_free(x->sp2);
    ic_jet_space_free(x->sp3);
}

/* 1 when interval arithmetic proves that the cell holds no intersection
 * point (an enclosure that failed excludes nothing). */
static int cell_excluded(const search_ctx *x, const cell *c)
{
    if (!x->proven)
        return 0;
    ic_surface *const *S = x->S;
    if (x->both) {
        const ic_interval ua[2] = {{c->lo[0], c->hi[0]}, {c->lo[1], c->hi[1]}};
        const ic_interval ub[2] = {{c->lo[2], c->hi[2]}, {c->lo[3], c->hi[3]}};
        ic_interval xa[3], xb[3];
        if (ic_surface_eval_interval(S[0], xa, ua, NULL) != IC_OK ||
            ic_surface_eval_interval(S[1], xb, ub, NULL) != IC_OK)
            return 0;
        for (int k = 0; k < 3; k++)
            if (ic_interval_is_empty(xa[k]) || ic_interval_is_empty(xb[k]) ||
                xa[k].hi < xb[k].lo || xb[k].hi < xa[k].lo)
                return 1;
        return 0;
    }
    ic_interval box[3], fa, fb, xyz[3];
    for (int k = 0; k < x->dim; k++)
        box[k] = (ic_interval){c->lo[k], c->hi[k]};
    if (x->mixed)
        return ic_surface_eval_interval(S[x->P], xyz, box, NULL) == IC_OK &&
               ic_surface_eval_interval(S[x->I], &fb, xyz, NULL) == IC_OK && excludes_zero(fb);
    return (ic_surface_eval_interval(S[0], &fa, box, NULL) == IC_OK && excludes_zero(fa)) ||
           (ic_surface_eval_interval(S[1], &fb, box, NULL) == IC_OK && excludes_zero(fb));
}

static int unbounded(ic_interval a) { return !(isfinite(a.lo) && isfinite(a.hi)); }

/* 1 when an enclosure of the surfaces over the cell is unbounded (values
 * beyond double precision, or a pole): subdividing such a cell near the
 * overflow does not bound it, so it is left undecided, not refined. */
static int cell_overflows(const search_ctx *x, const cell *c)
{
    if (!x->proven)
        return 0;
    ic_interval box[4], out[2][3], f;
    for (int k = 0; k < x->dim; k++)
        box[k] = (ic_interval){c->lo[k], c->hi[k]};
    for (int s = 0; s < 2; s++) {
        ic_surface *S = x->S[s];
        const int par = x->par[s];
        const ic_interval *in = x->both && s == 1 ? box + 2 : box;
        if (!par && x->mixed) /* f over the parametric sheet's image */
            in = out[x->P];
        if (ic_surface_eval_interval(S, par ? out[s] : &f, in, NULL) != IC_OK)
            return 1;
        for (int k = 0; k < (par ? 3 : 1); k++)
            if (unbounded(par ? out[s][k] : f))
                return 1;
    }
    return 0;
}

/* Self-intersections: one sheet pair per curve ((u, v) before (p, q)), and
 * away from the trivial diagonal (u, v) = (p, q) by two leaf widths of the
 * first search (the band does not shrink with refinement: the diagonal is a
 * whole surface of trivial solutions). */
static int off_diagonal_skip(const search_ctx *x, const cell *c, int leaf)
{
    const double *w = x->dwidth;
    return c->lo[0] > c->hi[2] ||
           (leaf && c->hi[0] >= c->lo[2] - 2 * w[0] && c->lo[0] <= c->hi[2] + 2 * w[0] &&
            c->hi[1] >= c->lo[3] - 2 * w[1] && c->lo[1] <= c->hi[3] + 2 * w[1]);
}

/* Newton from the cell's centre: 1 with *cand set when it converged near
 * the cell (within a cell width, inside the region); *converged says
 * whether it converged at all. */
static int leaf_newton(const search_ctx *x, const cell *c, ic_candidate *cand, int *converged)
{
    memset(cand, 0, sizeof *cand);
    double z[4], xyz[3] = {0, 0, 0};
    for (int k = 0; k < x->dim; k++)
        z[k] = 0.5 * (c->lo[k] + c->hi[k]);
    if (x->both)
        *converged = newton_params(x->S[0], x->S[1], x->sp2, x->L, z, xyz) == 0;
    else if (x->mixed)
        *converged = newton_mixed(x->S[x->P], x->S[x->I], x->sp2, x->sp3, x->L, z, xyz) == 0;
    else {
        memcpy(xyz, z, sizeof xyz);
        *converged = newton_implicit(x->S[0], x->S[1], x->sp3, x->L, xyz) == 0;
        memcpy(z, xyz, sizeof xyz);
    }
    int ok = *converged;
    for (int k = 0; ok && k < x->dim; k++) {
        const double w = c->hi[k] - c->lo[k];
        ok = z[k] >= c->lo[k] - w && z[k] <= c->hi[k] + w && z[k] >= x->lo[k] && z[k] <= x->hi[k];
    }
    if (ok && x->self) /* distinct preimages */
        ok = fabs(z[0] - z[2]) + fabs(z[1] - z[3]) > 4 * (x->dwidth[0] + x->dwidth[1]);
    if (x->both) {
        cand->params[0][0] = z[0], cand->params[0][1] = z[1];
        cand->params[1][0] = z[2], cand->params[1][1] = z[3];
    } else if (x->mixed)
        cand->params[x->P][0] = z[0], cand->params[x->P][1] = z[1];
    memcpy(cand->xyz, xyz, sizeof xyz);
    return ok;
}

/* The place of a cell in space: its centre's point and a radius covering
 * the cell. Where the surface cannot be evaluated at the centre (a kink, a
 * pole) the interval enclosure of the cell's image is used; where neither
 * works the radius stays 0 (the cell is then never counted as covered). */
static void describe_cell(const search_ctx *x, const cell *c, ic_unresolved *u)
{
    memcpy(u->lo, c->lo, sizeof u->lo);
    memcpy(u->hi, c->hi, sizeof u->hi);
    if (!x->mixed && !x->both) {
        double half[3];
        for (int k = 0; k < 3; k++) {
            u->xyz[k] = 0.5 * (c->lo[k] + c->hi[k]);
            half[k] = 0.5 * (c->hi[k] - c->lo[k]);
        }
        u->radius = 2 * ic_norm3(half);
        return;
    }
    const int sheet = x->both ? 0 : x->P;
    const double uvc[2] = {0.5 * (c->lo[0] + c->hi[0]), 0.5 * (c->lo[1] + c->hi[1])};
    u->params[sheet][0] = uvc[0], u->params[sheet][1] = uvc[1];
    if (x->both)
        u->params[1][0] = 0.5 * (c->lo[2] + c->hi[2]), u->params[1][1] = 0.5 * (c->lo[3] + c->hi[3]);
    double t[9];
    if (ic_surface_taylor(x->S[sheet], t, uvc, x->sp2, NULL) == IC_OK && isfinite(t[0] + t[3] + t[6])) {
        const double Ru[3] = {t[1], t[4], t[7]}, Rv[3] = {t[2], t[5], t[8]};
        u->xyz[0] = t[0], u->xyz[1] = t[3], u->xyz[2] = t[6];
        u->radius = (c->hi[0] - c->lo[0]) * ic_norm3(Ru) + (c->hi[1] - c->lo[1]) * ic_norm3(Rv);
        if (isfinite(u->radius))
            return;
    }
    const ic_interval box[2] = {{c->lo[0], c->hi[0]}, {c->lo[1], c->hi[1]}};
    ic_interval X[3];
    u->radius = 0.0;
    if (ic_surface_eval_interval(x->S[sheet], X, box, NULL) != IC_OK)
        return;
    double half[3];
    for (int k = 0; k < 3; k++) {
        u->xyz[k] = 0.5 * (X[k].lo + X[k].hi);
        half[k] = 0.5 * (X[k].hi - X[k].lo);
    }
    const double r = 2 * ic_norm3(half);
    u->radius = isfinite(r) && isfinite(ic_norm3(u->xyz)) ? r : 0.0;
}

/* 1 when the cell, enlarged by a quarter each side, is proven loop-free: a
 * closed curve of extent below a quarter cell through a point of this cell
 * lies inside the enlarged one. The enlargement stops at the region's
 * edges, where no curve is sought, except across a period (the curve goes
 * on there). */
static int leaf_loop_free(const search_ctx *x, const cell *c)
{
    if (!x->proven)
        return 0;
    double elo[4], ehi[4];
    for (int k = 0; k < x->dim; k++) {
        const double q = 0.25 * (c->hi[k] - c->lo[k]);
        elo[k] = c->lo[k] - q, ehi[k] = c->hi[k] + q;
        if (!x->periodic[k])
            elo[k] = fmax(elo[k], x->lo[k]), ehi[k] = fmin(ehi[k], x->hi[k]);
    }
    return ic_trace_cell_loop_free(x->S, x->par[0], x->par[1], elo, ehi);
}

typedef struct {
    ic_unresolved *u;
    int n, cap;
} unres_list;

static int push_unresolved(unres_list *l, const ic_unresolved *u)
{
    if (l->n == l->cap) {
        const int cap = l->cap ? 2 * l->cap : 64;
        ic_unresolved *p = realloc(l->u, (size_t)cap * sizeof *p);
        if (!p)
            return -1;
        l->u = p;
        l->cap = cap;
    }
    l->u[l->n++] = *u;
    return 0;
}

/* A leaf: Newton, centred forms, the loop test; a start point is kept, a
 * leaf that holds none, or that fails the loop test, is returned as
 * unresolved. -1: out of memory. */
static int process_leaf(const search_ctx *x, const cell *c, int level, cand_list *list,
                        unres_list *unres, ic_trace_report *rep)
{
    ic_candidate cand;
    int converged;
    const int ok = leaf_newton(x, c, &cand, &converged);
    /* nothing found: centred forms may still prove the leaf empty (they
     * separate two surfaces closer than a cell, centred.c) */
    if (!ok && x->proven && ic_trace_cell_excluded_centred(x->S, x->par[0], x->par[1], c->lo, c->hi)) {
        rep->cells_excluded++;
        rep->cells_excluded_centred++;
        return 0;
    }
    const int loop = !leaf_loop_free(x, c);
    if (x->proven) {
        if (loop)
            rep->loop_cells++;
        else
            rep->loop_free_cells++;
    }
    if (ok && push_candidate(list, &cand) != 0)
        return -1;
    if (ok && !loop)
        return 0;
    ic_unresolved u;
    memset(&u, 0, sizeof u);
    u.converged_elsewhere = converged && !ok;
    u.loop = loop;
    u.has_candidate = ok;
    u.level = level;
    u.overflow = cell_overflows(x, c);
    u.degenerate = loop && (x->mixed || x->both) &&
                   ic_trace_cell_may_degenerate(x->S, x->par[0], x->par[1], c->lo, c->hi);
    describe_cell(x, c, &u);
    return push_unresolved(unres, &u);
}

/* A cell the budget left unexamined: returned as unresolved, unplaced
 * (radius 0), so that it is never counted as covered. */
static int push_unexamined(const search_ctx *x, const cell *c, int level, unres_list *unres)
{
    ic_unresolved u;
    memset(&u, 0, sizeof u);
    u.loop = 1;
    u.level = level;
    describe_cell(x, c, &u);
    u.radius = 0.0;
    return push_unresolved(unres, &u);
}

static int out_of_budget(ic_trace_budget *b)
{
    if (b->stopped)
        return 1;
    if (b->cells_left <= 0) {
        b->stopped = IC_TRACE_STOP_CELLS;
        return 1;
    }
    b->cells_left--;
    /* the clock is read every 256 cells: a cell costs microseconds */
    return (b->cells_left & 255) == 0 && ic_trace_out_of_time(b);
}

ic_status ic_trace_candidates(ic_pair *pair, const ic_trace_options *opt,
                              const ic_unresolved *within, ic_candidate **out, int *nout,
                              ic_unresolved **unres, int *nunres, ic_trace_report *rep,
                              ic_trace_budget *budget, ic_error *err)
{
    *out = NULL, *nout = 0, *unres = NULL, *nunres = 0;
    search_ctx x;
    ic_status st = ctx_init(&x, pair, opt, err);
    if (st != IC_OK) {
        ctx_free(&x);
        return st;
    }
    if (!within)
        rep->proven = x.proven;
    x.proven = rep->proven; /* a finer search keeps the whole search's answer */
    /* four parameters: one level less (16 children a split); without
     * enclosures nothing is excluded: a coarser grid is sampled */
    const int full = x.both ? opt->depth - 1 : opt->depth;
    int depth = x.proven ? full : (full < 4 ? full : 4), level = 0;
    double lo[4], hi[4];
    memcpy(lo, x.lo, sizeof lo), memcpy(hi, x.hi, sizeof hi);
    if (within) { /* a finer search of one cell: its 2^dim children */
        memcpy(lo, within->lo, sizeof lo), memcpy(hi, within->hi, sizeof hi);
        depth = 1;
        level = within->level + 1;
    }
    double size = 0.0;
    for (int k = 0; k < x.dim; k++)
        size = fmax(size, (hi[k] - lo[k]) / (1 << depth));
    rep->cell_size = within ? fmin(rep->cell_size, size) : size;
    cand_list list = {0};
    unres_list ul = {0};
    cell *stack = malloc(((size_t)16 * depth + 16) * sizeof *stack);
    if (!stack)
        st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory searching start points");
    int top = 0;
    if (st == IC_OK) {
        memcpy(stack[0].lo, lo, sizeof lo), memcpy(stack[0].hi, hi, sizeof hi);
        stack[0].depth = 0;
        top = 1;
    }
    while (st == IC_OK && top > 0) {
        const cell c = stack[--top];
        const int leaf = c.depth == depth;
        if (x.self && off_diagonal_skip(&x, &c, leaf))
            continue;
        if (out_of_budget(budget)) {
            if (push_unexamined(&x, &c, level + c.depth - depth, &ul) != 0)
                st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory");
            continue;
        }
        rep->cells++;
        if (cell_excluded(&x, &c)) {
            rep->cells_excluded++;
            continue;
        }
        if (!leaf) { /* split into 2^dim children */
            for (int m = 0; m < (1 << x.dim); m++) {
                cell ch;
                ch.depth = c.depth + 1;
                for (int k = 0; k < x.dim; k++) {
                    const double mid = 0.5 * (c.lo[k] + c.hi[k]);
                    ch.lo[k] = (m >> k) & 1 ? mid : c.lo[k];
                    ch.hi[k] = (m >> k) & 1 ? c.hi[k] : mid;
                }
                stack[top++] = ch;
            }
            continue;
        }
        if (process_leaf(&x, &c, level, &list, &ul, rep) != 0)
            st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory searching start points");
    }
    free(stack);
    ctx_free(&x);
    if (st != IC_OK) {
        free(list.c);
        free(ul.u);
        return st;
    }
    rep->candidates += list.n;
    *out = list.c, *nout = list.n;
    *unres = ul.u, *nunres = ul.n;
    return IC_OK;
}
