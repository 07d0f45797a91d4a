/*
 * Start points by subdivision (DESIGN.md 2.3). Cells of the search region
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

/* f and grad f of an implicit surface */
static int value_grad(ic_surface *s, const ic_jet_space *sp, const double *x, double *f, double *g)
{
    double t[4];
    if (ic_surface_taylor(s, t, x, sp, NULL) != IC_OK)
        return -1;
    *f = t[0];
    g[0] = t[1], g[1] = t[2], g[2] = t[3];
    return 0;
}

/* Min-norm Newton onto f_A = f_B = 0 from x: 0 converged, -1 not. */
static int newton_implicit(ic_surface *A, ic_surface *B, const ic_jet_space *sp, double *x)
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
        if (ic_norm3(step) <= 1e-15 * (1 + ic_norm3(x)))
            return fabs(fa) / sqrt(a) < 1e-10 && fabs(fb) / sqrt(c) < 1e-10 ? 0 : -1;
    }
    return -1;
}

/* Min-norm Newton onto f(R(u, v)) = 0 from uv. */
static int newton_mixed(ic_surface *P, ic_surface *I, const ic_jet_space *sp2,
                        const ic_jet_space *sp3, double *uv, double *x)
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
            return fabs(f) / ic_norm3(g) < 1e-10 ? 0 : -1;
    }
    return -1;
}

/* Min-norm Newton onto R_A(u, v) = R_B(p, q) from z = (u, v, p, q). */
static int newton_params(ic_surface *A, ic_surface *B, const ic_jet_space *sp2, double *z,
                         double *x)
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
        if (!(fabs(det) > 1e-30))
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
            return ic_norm3(F) < 1e-10 * (1 + ic_norm3(x)) ? 0 : -1;
    }
    return -1;
}

/* The parameter box of sheet s: its domain, which must be finite. */
static ic_status domain_box(ic_surface *const S[2], int s, double lo[2], double hi[2],
                            ic_error *err)
{
    double dom[2][2];
    int per[2];
    ic_surface_get_domain(S[s], dom, per);
    for (int i = 0; i < 2; i++) {
        if (!isfinite(dom[i][0]) || !isfinite(dom[i][1]))
            return ic_error_set(err, IC_ERR_INVALID, 0,
                                "tracing needs a finite \"domain\" for the parametric surface %c "
                                "(surfaces[%d] of a problem file)",
                                'A' + s, s);
        lo[i] = dom[i][0], hi[i] = dom[i][1];
    }
    return IC_OK;
}

ic_status ic_trace_candidates(ic_pair *pair, const ic_trace_options *opt,
                              const ic_unresolved *within, ic_candidate **out, int *nout,
                              ic_unresolved **unres, int *nunres, ic_trace_report *rep,
                              ic_error *err)
{
    *out = NULL;
    *nout = 0;
    *unres = NULL;
    *nunres = 0;
    int capu = 0;
    ic_surface *S[2] = {ic_pair_surface(pair, 0), ic_pair_surface(pair, 1)};
    const int par[2] = {ic_surface_get_kind(S[0]) == IC_PARAMETRIC,
                        ic_surface_get_kind(S[1]) == IC_PARAMETRIC};
    const int both = par[0] && par[1], self = ic_pair_is_self(pair);
    const int mixed = !both && (par[0] || par[1]);
    const int P = par[0] ? 0 : 1, I = 1 - P;
    int dim = 3;
    double lo[4], hi[4];
    if (both) { /* (u, v, p, q) */
        if (domain_box(S, 0, lo, hi, err) != IC_OK ||
            domain_box(S, 1, lo + 2, hi + 2, err) != IC_OK)
            return IC_ERR_INVALID;
        dim = 4;
    } else if (mixed) {
        if (domain_box(S, P, lo, hi, err) != IC_OK)
            return IC_ERR_INVALID;
        dim = 2;
    } else {
        if (!opt->has_box)
            return ic_error_set(err, IC_ERR_INVALID, 0,
                                "tracing two implicit surfaces needs a \"box\"");
        for (int k = 0; k < 3; k++)
            lo[k] = opt->box[k][0], hi[k] = opt->box[k][1];
    }
    /* can the surfaces be enclosed? (formula surfaces only) */
    ic_interval probe_in[4], probe_out[3];
    for (int k = 0; k < 4; k++)
        probe_in[k] = (ic_interval){k < dim ? lo[k] : 0, k < dim ? hi[k] : 0};
    if (!within) /* a finer search keeps the whole search's answer */
        rep->proven =
            ic_surface_eval_interval(S[0], probe_out, probe_in, NULL) == IC_OK &&
            ic_surface_eval_interval(S[1], probe_out, probe_in + (both ? 2 : 0), NULL) == IC_OK;
    /* four parameters: one level less (16 children a split) */
    const int full = both ? opt->depth - 1 : opt->depth;
    int depth = rep->proven ? full : (full < 4 ? full : 4);
    if (within) { /* a finer search of one leaf cell: 2^(dim * levels) leaves */
        memcpy(lo, within->lo, sizeof lo);
        memcpy(hi, within->hi, sizeof hi);
        depth = dim == 4 ? 2 : 3;
    }
    ic_jet_space *sp2 = NULL, *sp3 = NULL;
    ic_status st = ic_jet_space_new(&sp2, 2, 1, err);
    if (st == IC_OK)
        st = ic_jet_space_new(&sp3, 3, 1, err);
    cand_list list = {0};
    const size_t max_stack = 16 * (size_t)depth + 16;
    cell *stack = malloc(max_stack * sizeof *stack);
    const double dwidth[2] = {(hi[0] - lo[0]) / (1 << depth), (hi[1] - lo[1]) / (1 << depth)};
    if (st == IC_OK && !stack)
        st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory searching start points");
    int top = 0;
    if (st == IC_OK) {
        memcpy(stack[0].lo, lo, sizeof lo);
        memcpy(stack[0].hi, hi, sizeof hi);
        stack[0].depth = 0;
        top = 1;
    }
    double size = 0.0;
    for (int k = 0; k < dim; k++)
        size = fmax(size, (hi[k] - lo[k]) / (1 << depth));
    rep->cell_size = within ? fmin(rep->cell_size, size) : size;
    while (st == IC_OK && top > 0) {
        const cell c = stack[--top];
        rep->cells++;
        if (self) {
            /* one sheet pair per curve: (u, v) before (p, q); and away from the
             * trivial diagonal (u, v) = (p, q), two leaf widths at least */
            if (c.lo[0] > c.hi[2] ||
                (c.hi[0] >= c.lo[2] - 2 * dwidth[0] && c.lo[0] <= c.hi[2] + 2 * dwidth[0] &&
                 c.hi[1] >= c.lo[3] - 2 * dwidth[1] && c.lo[1] <= c.hi[3] + 2 * dwidth[1] &&
                 c.depth == depth))
                continue;
        }
        if (rep->proven && both) {
            ic_interval ua[2] = {{c.lo[0], c.hi[0]}, {c.lo[1], c.hi[1]}};
            ic_interval ub[2] = {{c.lo[2], c.hi[2]}, {c.lo[3], c.hi[3]}};
            ic_interval xa[3], xb[3];
            int empty = 0;
            if (ic_surface_eval_interval(S[0], xa, ua, NULL) == IC_OK &&
                ic_surface_eval_interval(S[1], xb, ub, NULL) == IC_OK)
                for (int k = 0; k < 3; k++)
                    if (ic_interval_is_empty(xa[k]) || ic_interval_is_empty(xb[k]) ||
                        xa[k].hi < xb[k].lo || xb[k].hi < xa[k].lo)
                        empty = 1;
            if (empty) {
                rep->cells_excluded++;
                continue;
            }
        } else if (rep->proven) {
            ic_interval box[3], fa, fb, xyz[3];
            for (int k = 0; k < dim; k++)
                box[k] = (ic_interval){c.lo[k], c.hi[k]};
            int empty; /* an enclosure that failed excludes nothing */
            if (mixed)
                empty = ic_surface_eval_interval(S[P], xyz, box, NULL) == IC_OK &&
                        ic_surface_eval_interval(S[I], &fb, xyz, NULL) == IC_OK &&
                        excludes_zero(fb);
            else
                empty =
                    (ic_surface_eval_interval(S[0], &fa, box, NULL) == IC_OK &&
                     excludes_zero(fa)) ||
                    (ic_surface_eval_interval(S[1], &fb, box, NULL) == IC_OK && excludes_zero(fb));
            if (empty) {
                rep->cells_excluded++;
                continue;
            }
        }
        if (c.depth < depth) { /* split into 2^dim children */
            for (int m = 0; m < (1 << dim); m++) {
                cell ch;
                ch.depth = c.depth + 1;
                for (int k = 0; k < dim; k++) {
                    const double mid = 0.5 * (c.lo[k] + c.hi[k]);
                    ch.lo[k] = (m >> k) & 1 ? mid : c.lo[k];
                    ch.hi[k] = (m >> k) & 1 ? c.hi[k] : mid;
                }
                stack[top++] = ch;
            }
            continue;
        }
        /* a leaf: Newton from the centre, kept if it stays near the cell */
        ic_candidate cand;
        memset(&cand, 0, sizeof cand);
        double x[3], uv[2];
        int ok, converged;
        if (both) {
            double z[4];
            for (int k = 0; k < 4; k++)
                z[k] = 0.5 * (c.lo[k] + c.hi[k]);
            ok = converged = newton_params(S[0], S[1], sp2, z, x) == 0;
            for (int k = 0; ok && k < 4; k++) {
                const double w = c.hi[k] - c.lo[k];
                ok = z[k] >= c.lo[k] - w && z[k] <= c.hi[k] + w && z[k] >= lo[k] && z[k] <= hi[k];
            }
            if (ok && self) /* distinct preimages */
                ok = fabs(z[0] - z[2]) + fabs(z[1] - z[3]) > 4 * (dwidth[0] + dwidth[1]);
            cand.params[0][0] = z[0], cand.params[0][1] = z[1];
            cand.params[1][0] = z[2], cand.params[1][1] = z[3];
        } else if (mixed) {
            uv[0] = 0.5 * (c.lo[0] + c.hi[0]), uv[1] = 0.5 * (c.lo[1] + c.hi[1]);
            ok = converged = newton_mixed(S[P], S[I], sp2, sp3, uv, x) == 0;
            for (int k = 0; ok && k < 2; k++) {
                const double w = c.hi[k] - c.lo[k];
                ok = uv[k] >= c.lo[k] - w && uv[k] <= c.hi[k] + w && uv[k] >= lo[k] &&
                     uv[k] <= hi[k];
            }
            cand.params[P][0] = uv[0], cand.params[P][1] = uv[1];
        } else {
            for (int k = 0; k < 3; k++)
                x[k] = 0.5 * (c.lo[k] + c.hi[k]);
            ok = converged = newton_implicit(S[0], S[1], sp3, x) == 0;
            for (int k = 0; ok && k < 3; k++) {
                const double w = c.hi[k] - c.lo[k];
                ok = x[k] >= c.lo[k] - w && x[k] <= c.hi[k] + w && x[k] >= lo[k] && x[k] <= hi[k];
            }
        }
        /* nothing found: centred forms may still prove the leaf empty (they
         * separate two surfaces closer than a cell, centred.c) */
        if (!ok && rep->proven && ic_trace_cell_excluded_centred(S, par[0], par[1], c.lo, c.hi)) {
            rep->cells_excluded++;
            rep->cells_excluded_centred++;
            continue;
        }
        /* the loop test */
        int loop = 1;
        if (rep->proven) {
            /* enlarged by a quarter cell each side: a closed curve of extent
             * below a quarter cell through a point of this cell lies inside */
            double elo[4], ehi[4];
            for (int k = 0; k < dim; k++) {
                const double q = 0.25 * (c.hi[k] - c.lo[k]);
                elo[k] = c.lo[k] - q, ehi[k] = c.hi[k] + q;
            }
            loop = !ic_trace_cell_loop_free(S, par[0], par[1], elo, ehi);
            if (loop)
                rep->loop_cells++;
            else
                rep->loop_free_cells++;
        }
        if (ok) {
            memcpy(cand.xyz, x, sizeof x);
            if (push_candidate(&list, &cand) != 0)
                st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory searching start points");
        } else { /* no start point in this cell: a curve may pass here unfound */
            ic_unresolved u;
            memset(&u, 0, sizeof u);
            u.converged_elsewhere = converged;
            u.loop = loop;
            memcpy(u.lo, c.lo, sizeof u.lo);
            memcpy(u.hi, c.hi, sizeof u.hi);
            double t[9];
            if (mixed || both) {
                const double uvc[2] = {0.5 * (c.lo[0] + c.hi[0]), 0.5 * (c.lo[1] + c.hi[1])};
                if (ic_surface_taylor(S[both ? 0 : P], t, uvc, sp2, NULL) != IC_OK)
                    continue;
                const double Ru[3] = {t[1], t[4], t[7]}, Rv[3] = {t[2], t[5], t[8]};
                u.xyz[0] = t[0], u.xyz[1] = t[3], u.xyz[2] = t[6];
                u.radius = (c.hi[0] - c.lo[0]) * ic_norm3(Ru) + (c.hi[1] - c.lo[1]) * ic_norm3(Rv);
                const int sheet = both ? 0 : P;
                u.params[sheet][0] = uvc[0], u.params[sheet][1] = uvc[1];
                if (both)
                    u.params[1][0] = 0.5 * (c.lo[2] + c.hi[2]),
                    u.params[1][1] = 0.5 * (c.lo[3] + c.hi[3]);
            } else {
                double half[3];
                for (int k = 0; k < 3; k++) {
                    u.xyz[k] = 0.5 * (c.lo[k] + c.hi[k]);
                    half[k] = 0.5 * (c.hi[k] - c.lo[k]);
                }
                u.radius = 2 * ic_norm3(half);
            }
            if (*nunres == capu) {
                capu = capu ? 2 * capu : 64;
                ic_unresolved *p = realloc(*unres, (size_t)capu * sizeof *p);
                if (!p) {
                    st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory");
                    continue;
                }
                *unres = p;
            }
            (*unres)[(*nunres)++] = u;
        }
    }
    free(stack);
    ic_jet_space_free(sp2);
    ic_jet_space_free(sp3);
    if (st != IC_OK) {
        free(list.c);
        free(*unres);
        *unres = NULL;
        *nunres = 0;
        return st;
    }
    rep->candidates += list.n;
    *out = list.c;
    *nout = list.n;
    return IC_OK;
}
