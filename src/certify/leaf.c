/*
 * One leaf of the cover proven (certificate.h): empty, outside the box,
 * diagonal (self-intersections), or regular with its crossings and arcs;
 * else undecided, to be split.
 *
 * Why a regular cell's arcs are its crossings paired along `axis`: the
 * minor of J without column `axis` is regular at every point of the cell,
 * so on each slice z[axis] = const, a convex box, F is one-to-one (the mean
 * value theorem) and has at most one zero. Each component of the zero set
 * in the cell is then an arc monotone in z[axis] (no loop can be), and with
 * every face crossing transversal (face.c) its two ends are two crossings;
 * different arcs occupy disjoint ranges of z[axis]. Sorted along axis, the
 * crossings therefore pair up: (1st, 2nd), (3rd, 4th), ...
 */
#include "certificate.h"
#include "system.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static void cell_box(const ic_cell *cl, int dim, ic_interval *X)
{
    for (int k = 0; k < dim; k++)
        X[k] = (ic_interval){cl->lo[k], cl->hi[k]};
}

/* The boxes A of (u, v) and B of (p, q) overlap (2) or lie apart by at
 * most the wider one's width (1), once a periodic parameter of B is
 * shifted by whole periods; 0 farther. *Bs receives B so shifted. (Apart,
 * the test below can prove them empty: a cell beside the diagonal is
 * neither empty by its enclosure nor regular, as R(a) - R(b) nearly
 * vanishes there, and a figure-8 Klein bottle's cover ran out of cells at
 * them.) */
static int boxes_meet(const ic_certificate *c, const ic_interval A[2], const ic_interval B[2],
                      ic_interval Bs[2])
{
    int overlap = 2;
    for (int k = 0; k < 2; k++) {
        const double T = c->periodic[k] ? c->hi[k] - c->lo[k] : 0.0;
        const double slack = fmax(A[k].hi - A[k].lo, B[k].hi - B[k].lo);
        int found = 0;
        for (int pass = 0; pass < 2 && !found; pass++) /* overlapping first */
            for (int s = -1; s <= 1 && !found; s++) {
                const double g = pass ? slack : 0.0;
                if ((s != 0 && T == 0.0) ||
                    !(A[k].lo <= B[k].hi + s * T + g && B[k].lo + s * T <= A[k].hi + g))
                    continue;
                found = 1, Bs[k] = (ic_interval){B[k].lo + s * T, B[k].hi + s * T};
                overlap = pass ? 1 : overlap;
            }
        if (!found)
            return 0;
    }
    return overlap;
}

/* A box of one preimage carried back across the sheet's glued edges
 * (pairing/pairing_glue.c), outward: by the glue its points are the same
 * points of the surface. */
static void glue_back(const ic_certificate *c, const ic_interval in[2], ic_interval out[2])
{
    double a[2], b[2];
    const double lo[2] = {in[0].lo, in[1].lo}, hi[2] = {in[0].hi, in[1].hi};
    ic_pairing_glue_back(c->pg, lo, a);
    ic_pairing_glue_back(c->pg, hi, b);
    for (int k = 0; k < 2; k++) {
        out[k].lo = nextafter(fmin(a[k], b[k]), -INFINITY);
        out[k].hi = nextafter(fmax(a[k], b[k]), INFINITY);
    }
}

/* The (u, v) box A and the (p, q) box of a self-intersection cell where
 * they meet (boxes_meet's 2, or 1 beside each other): as they are, modulo
 * the periods, or either carried back across the glued edges; A and B
 * receive the pair that meets. */
static int near_diagonal(const ic_certificate *c, const ic_interval *X, ic_interval A[2],
                         ic_interval B[2])
{
    const ic_interval U[2] = {X[0], X[1]}, P[2] = {X[2], X[3]};
    A[0] = U[0], A[1] = U[1];
    int meet = boxes_meet(c, U, P, B);
    if (meet || c->pg->glue.axis < 0)
        return meet;
    ic_interval G[2];
    glue_back(c, P, G);
    if ((meet = boxes_meet(c, U, G, B)) != 0)
        return meet;
    glue_back(c, U, A);
    return boxes_meet(c, A, P, B);
}

/* R(a) - R(b) = M (a - b) with M in J_R over the hull of both boxes: when
 * two rows of it form a regular 2 x 2 interval matrix, R(a) = R(b) forces
 * a = b (the trivial solutions of a self-intersection). */
static int only_diagonal(const ic_certificate *c, const ic_interval A[2], const ic_interval B[2])
{
    ic_interval H[2];
    for (int k = 0; k < 2; k++)
        H[k] = (ic_interval){fmin(A[k].lo, B[k].lo), fmax(A[k].hi, B[k].hi)};
    ic_interval_grad R[3];
    if (ic_surface_eval_interval_grad(c->pg->S[0], R, H, NULL) != IC_OK)
        return 0;
    static const int rows[3][2] = {{0, 1}, {0, 2}, {1, 2}};
    for (int r = 0; r < 3; r++) {
        ic_interval M[4][4];
        for (int i = 0; i < 2; i++)
            for (int k = 0; k < 2; k++)
                M[i][k] = R[rows[r][i]].d[k];
        if (ic_imat_regular(M, 2))
            return 1;
    }
    return 0;
}

/* The minor of J without column k is regular over the cell. */
static int monotone_along(const ic_certificate *c, const ic_certify_eval *e, int k)
{
    ic_interval M[4][4];
    for (int i = 0; i < c->m; i++)
        for (int j = 0, col = 0; j < c->dim; j++)
            if (j != k)
                M[i][col++] = e->J[i][j];
    return ic_imat_regular(M, c->m);
}

/* A cell is grown by this fraction of the region's width each way before
 * it is called smooth: a singular point a rounding outside every cell (on
 * a periodic seam at u = pi, the domain [-pi, pi] rounded inwards at both
 * ends) is then in one. */
#define IC_CERTIFY_SMOOTH_GROW 1e-9

/* The curve's tangent has a component away from zero over the cell X grown
 * by IC_CERTIFY_SMOOTH_GROW: no singular point there. */
static int smooth(const ic_certificate *c, const ic_interval *X)
{
    ic_interval G[4];
    for (int k = 0; k < c->dim; k++) {
        const double g = IC_CERTIFY_SMOOTH_GROW * (c->hi[k] - c->lo[k]);
        G[k] = (ic_interval){X[k].lo - g, X[k].hi + g};
    }
    ic_certify_eval e;
    if (!ic_certify_enclose(c->pg, G, &e))
        return 0;
    for (int k = 0; k < c->dim; k++)
        if (monotone_along(c, &e, k))
            return 1;
    return 0;
}

/* Halvings at most of a singular cell in the test below. */
#define IC_CERTIFY_SMOOTH_HALVINGS 9

/* No singular point in X, a cell in a singular box: every piece of X, X
 * halved across its widest coordinate down to `depth` halvings, is proven
 * empty or smooth. Whether a claimed point is refuted (a box all smooth,
 * ic_certificate_refute_smooth) must not hang on how coarse the cover's
 * cells in its box are: a cover whose cells fit the box just so (a
 * certificate file's may) would hide that the intersection there is a
 * smooth arc. 1 so; 0 at the first piece at the last halving that is
 * neither. */
static int smooth_within(const ic_certificate *c, const ic_interval *X, int depth)
{
    ic_certify_eval e;
    if ((ic_certify_enclose(c->pg, X, &e) && ic_certify_excludes(&e, c->m)) || smooth(c, X))
        return 1;
    if (depth == 0)
        return 0;
    int k = 0; /* the widest, relative to the region */
    for (int j = 1; j < c->dim; j++)
        if ((X[j].hi - X[j].lo) / (c->hi[j] - c->lo[j]) >
            (X[k].hi - X[k].lo) / (c->hi[k] - c->lo[k]))
            k = j;
    ic_interval half[4];
    memcpy(half, X, (size_t)c->dim * sizeof *X);
    const double mid = 0.5 * (X[k].lo + X[k].hi);
    half[k].hi = mid;
    if (!smooth_within(c, half, depth - 1))
        return 0;
    half[k] = (ic_interval){mid, X[k].hi};
    return smooth_within(c, half, depth - 1);
}

/* Sorts the crossings x[0..n-1] along axis: 1 when their ranges there
 * are disjoint, else 0 with *at the first that overlaps the one before. */
static int sorted_apart(ic_crossing *x, long n, int axis, long *at)
{
    for (long a = 1; a < n; a++) /* insertion sort: a cell has few crossings */
        for (long b = a; b > 0 && x[b].K[axis].lo < x[b - 1].K[axis].lo; b--) {
            const ic_crossing t = x[b];
            x[b] = x[b - 1], x[b - 1] = t;
        }
    for (long a = 1; a < n; a++)
        if (!(x[a - 1].K[axis].hi < x[a].K[axis].lo)) {
            *at = a;
            return 0;
        }
    return 1;
}

/* Sorted along axis, the crossings first..first+n-1 pair up as arcs:
 * their ranges along axis are disjoint (two that overlap narrowed first:
 * beside a cusp two crossings lie closer than their face boxes' widths)
 * and their number is even. */
static int pair_arcs(ic_certificate *c, long first, long n, int axis)
{
    if (n % 2 != 0)
        return 0;
    if (n == 0) /* no crossing: no arc (and c->cross may not exist yet) */
        return 1;
    ic_crossing *x = c->cross + first;
    long at;
    int narrowed = 0;
    while (!sorted_apart(x, n, axis, &at)) {
        if (narrowed++ >= n)
            return 0;
        ic_certify_tighten(c, &x[at - 1]);
        ic_certify_tighten(c, &x[at]);
    }
    for (long a = 0; a < n; a += 2) {
        x[a].mate = (int)(first + a + 1);
        x[a + 1].mate = (int)(first + a);
    }
    return 1;
}

/* The cofactors of J at the cell's centre (the curve's tangent there, up to
 * a factor), to try the most promising axis first. */
static void axis_order(const ic_certificate *c, const ic_certify_eval *at, int order[4])
{
    double J[3][4], T[4] = {0, 0, 0, 0};
    for (int k = 0; k < c->dim; k++) {
        order[k] = k;
        for (int i = 0; at && i < c->m; i++)
            J[i][k] = 0.5 * at->J[i][k].lo + 0.5 * at->J[i][k].hi;
    }
    if (at) /* no enclosure at the centre: the natural order */
        for (int k = 0; k < c->dim; k++) {
            double M[4][4], Y[4][4];
            for (int i = 0; i < c->m; i++)
                for (int j = 0, col = 0; j < c->dim; j++)
                    if (j != k)
                        M[i][col++] = J[i][j] * (c->hi[j] - c->lo[j]);
            /* a regular minor's inverse is small where the tangent's k-component is large */
            if (ic_imat_point_inverse(M, c->m, Y)) {
                double s = 0.0;
                for (int i = 0; i < c->m; i++)
                    for (int j = 0; j < c->m; j++)
                        s += fabs(Y[i][j]);
                T[k] = 1.0 / s;
            }
        }
    for (int a = 1; a < c->dim; a++)
        for (int b = a; b > 0 && T[order[b]] > T[order[b - 1]]; b--) {
            const int t = order[b];
            order[b] = order[b - 1], order[b - 1] = t;
        }
}

/* Regular along some axis, with every face's crossings isolated and paired:
 * 1, 0 undecided, -1 out of memory. */
static int regular(ic_certificate *c, long i, const ic_certify_eval *e,
                   const ic_certify_eval *at, const ic_certify_limits *lim)
{
    int order[4];
    axis_order(c, at, order);
    for (int a = 0; a < c->dim; a++) {
        const int k = order[a];
        if (!monotone_along(c, e, k))
            continue;
        const long first = c->ncross;
        int rc = 1;
        for (int j = 0; j < c->dim && rc == 1; j++)
            for (int side = 0; side < 2 && rc == 1; side++)
                rc = ic_certify_face(c, i, j, side, lim->face_boxes);
        if (rc < 0)
            return -1;
        if (rc == 1 && pair_arcs(c, first, c->ncross - first, k)) {
            ic_cell *cl = &c->cells[i];
            cl->kind = IC_CELL_REGULAR, cl->axis = k;
            cl->first = (int)first, cl->ncross = (int)(c->ncross - first);
            return 1;
        }
        c->ncross = first;
        return 0;
    }
    return 0;
}

int ic_certify_leaf(ic_certificate *c, long i, const ic_certify_limits *lim)
{
    ic_interval X[4];
    cell_box(&c->cells[i], c->dim, X);
    ic_certify_eval e;
    ic_cell *cl = &c->cells[i];
    if (!ic_certify_enclose(c->pg, X, &e)) {
        if (!ic_certify_values_exclude(c->pg, X))
            return 0;
        cl->kind = IC_CELL_EMPTY;
        return 1;
    }
    double mid[4];
    ic_certify_eval at;
    const int centred = ic_certify_centre(c->pg, X, mid, &at);
    if (ic_certify_excludes(&e, c->m) ||
        (centred && ic_certify_excludes_centred(c->pg, X, &e, mid, &at))) {
        cl->kind = IC_CELL_EMPTY;
        return 1;
    }
    int across = 0; /* the image straddles the box */
    if (c->has_box && c->dim != 3) {
        const int side = ic_certificate_against_box(c, X);
        if (side == 1) {
            cl->kind = IC_CELL_OUTSIDE;
            return 1;
        }
        across = side < 0;
    }
    ic_interval A[2], B[2];
    const int near = c->pg->kind == &ic_pairing_self ? near_diagonal(c, X, A, B) : 0;
    if (near && only_diagonal(c, A, B)) { /* beside it: no solution at all */
        cl->kind = IC_CELL_DIAGONAL;
        return 1;
    }
    if (near == 2) {
        /* beside the diagonal the trivial solutions fill the cell: it is
         * never regular, and singular when a box holds it (a pinch point
         * where the double curve's two preimages meet) */
        const int box = ic_certificate_singular_box(c, i);
        if (box < 0)
            return 0;
        cl->kind = IC_CELL_SINGULAR;
        c->box_cells[box]++; /* never smooth: the trivial solutions meet it */
        return 1;
    }
    /* in a singular box or a tube nothing more is examined: not even
     * whether the cell is regular (its faces would be isolated in vain);
     * a box's cells are counted, and those where the curve's tangent has a
     * component away from zero (a full-rank Jacobian: no singular point) */
    const int box = ic_certificate_singular_box(c, i);
    if (box >= 0) {
        cl->kind = IC_CELL_SINGULAR;
        c->box_cells[box]++;
        c->box_smooth[box] += smooth_within(c, X, IC_CERTIFY_SMOOTH_HALVINGS);
        return 1;
    }
    if (ic_certificate_in_tube(c, i)) {
        cl->kind = IC_CELL_TANGENTIAL;
        return 1;
    }
    const long first = c->ncross;
    int rc = regular(c, i, &e, centred ? &at : NULL, lim);
    if (rc == 1 && across) { /* the box cuts the arcs: their ends on it */
        rc = ic_certify_box_crossings(c, i, lim->face_boxes);
        if (rc != 1) {
            c->ncross = first;
            c->cells[i].kind = IC_CELL_REFUSED;
        }
    }
    return rc;
}
