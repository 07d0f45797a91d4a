/*
 * Where a parametric sheet crosses the problem's box inside a regular cell
 * (certificate.h): the cell's arcs are known (its face crossings, paired),
 * and the box cuts them. Each root of the square system
 *   G(z) = (F(z), R_k(z) - b),  b = box[k][side],
 * in the cell is a point where an arc meets the box face: a curve end. The
 * roots are isolated by subdividing the cell until each part is excluded
 * or holds exactly one root, proven by the Krawczyk image lying strictly
 * inside it (Krawczyk 1969; Moore 1977); each is put on the arc whose range
 * along the cell's monotone coordinate holds it (the arcs' ranges are
 * disjoint). Face crossings whose image lies outside the box are marked:
 * no traced curve can meet them.
 */
#include "certificate.h"
#include "system.h"

#include <stdlib.h>
#include <string.h>

/* G and its Jacobian over X: 0 without enclosures. */
static int enclose_g(const ic_certificate *c, const ic_interval *X, int k, double b,
                     ic_interval *G, ic_interval JG[4][4], ic_certify_eval *e)
{
    ic_interval v, g[4];
    if (!ic_certify_enclose(c->pg, X, e) || !ic_certify_image_grad(c->pg, X, k, &v, g))
        return 0;
    for (int i = 0; i < c->m; i++) {
        G[i] = e->F[i];
        for (int j = 0; j < c->dim; j++)
            JG[i][j] = e->J[i][j];
    }
    G[c->m] = ic_interval_sub(v, (ic_interval){b, b});
    for (int j = 0; j < c->dim; j++)
        JG[c->m][j] = g[j];
    return 1;
}

/* 1: no root in X; 2: one root, proven (K filled); 0: undecided. */
static int decide(const ic_certificate *c, const ic_interval *X, int k, double b, ic_interval *K)
{
    ic_interval G[4], JG[4][4], Gc[4], Jc[4][4];
    ic_certify_eval e, ec;
    if (!enclose_g(c, X, k, b, G, JG, &e))
        return 0;
    for (int i = 0; i <= c->m; i++)
        if (G[i].lo > 0.0 || G[i].hi < 0.0)
            return 1;
    double mid[4];
    ic_interval C[4];
    if (!ic_certify_centre(c->pg, X, mid, &ec))
        return 0;
    if (ic_certify_excludes_centred(c->pg, X, &e, mid, &ec))
        return 1;
    for (int j = 0; j < c->dim; j++)
        C[j] = (ic_interval){mid[j], mid[j]};
    if (!enclose_g(c, C, k, b, Gc, Jc, &ec))
        return 0;
    if (!ic_imat_krawczyk(X, Gc, JG, c->dim, K))
        return 0;
    if (ic_imat_disjoint(K, X, c->dim))
        return 1;
    return ic_imat_strictly_inside(K, X, c->dim) ? 2 : 0;
}

/* The widest coordinate of X relative to the region. */
static int widest(const ic_certificate *c, const ic_interval *X)
{
    int best = 0;
    double wbest = -1.0;
    for (int j = 0; j < c->dim; j++) {
        const double w = (X[j].hi - X[j].lo) / (c->hi[j] - c->lo[j]);
        if (w > wbest)
            best = j, wbest = w;
    }
    return best;
}

/* The roots on box face (k, side) in cell i appended: 1, 0 undecided, -1
 * out of memory. */
static int isolate(ic_certificate *c, long i, int k, int side, int max_boxes)
{
    ic_interval(*stack)[4] = c->face_stack; /* room for max_boxes + 1: face.c made it */
    if (c->face_cap < max_boxes + 1)
        return 0;
    const double b = c->box[k][side];
    int n = 1, used = 0;
    for (int j = 0; j < c->dim; j++)
        stack[0][j] = (ic_interval){c->cells[i].lo[j], c->cells[i].hi[j]};
    while (n > 0) {
        ic_interval X[4], K[4];
        memcpy(X, stack[--n], sizeof X);
        const int d = decide(c, X, k, b, K);
        if (d == 2) {
            ic_crossing x;
            memset(&x, 0, sizeof x);
            x.cell = (int)i, x.face = -1, x.side = side, x.mate = -1, x.box = 2 * k + side;
            memcpy(x.X, X, sizeof x.X);
            memcpy(x.K, K, sizeof x.K);
            if (ic_certificate_add_crossing(c, &x) < 0)
                return -1;
        }
        if (d != 0)
            continue;
        if (++used >= max_boxes || n + 2 > max_boxes + 1)
            return 0;
        const int j = widest(c, X);
        const double mid = 0.5 * X[j].lo + 0.5 * X[j].hi;
        if (!(mid > X[j].lo && mid < X[j].hi))
            return 0;
        memcpy(stack[n], X, sizeof X), stack[n][j].hi = mid;
        memcpy(stack[n + 1], X, sizeof X), stack[n + 1][j].lo = mid;
        n += 2;
    }
    return 1;
}

/* Each box crossing from `first` on put on its arc (the face crossings
 * first..first+nface-1 of the cell, paired along axis): 0 when one lies on
 * no arc's range or on two. */
static int on_arcs(ic_certificate *c, long first, long nface, long from, int axis)
{
    for (long e = from; e < c->ncross; e++) {
        const ic_interval t = c->cross[e].K[axis];
        int arc = -1;
        for (long a = first; a < first + nface; a += 2) {
            const double lo = c->cross[a].K[axis].lo, hi = c->cross[a + 1].K[axis].hi;
            if (t.hi < lo || t.lo > hi)
                continue;
            if (arc >= 0 || t.lo < lo || t.hi > hi)
                return 0; /* two arcs, or the range's end: not decided */
            arc = (int)a;
        }
        if (arc < 0)
            return 0;
        c->cross[e].mate = arc;
    }
    return 1;
}

int ic_certify_box_crossings(ic_certificate *c, long i, int max_boxes)
{
    ic_interval img[3];
    if (!ic_certificate_cell_image(c, i, img))
        return 0;
    const long first = c->cells[i].first, nface = c->cells[i].ncross, from = c->ncross;
    for (long x = first; x < first + nface; x++) {
        const int where = ic_certificate_against_box(c, c->cross[x].K);
        if (where < 0)
            return 0; /* across a face of the box: not decided */
        c->cross[x].outside = where == 1;
    }
    for (int k = 0; k < 3; k++)
        for (int side = 0; side < 2; side++) {
            const double b = c->box[k][side];
            if (!(img[k].lo <= b && b <= img[k].hi))
                continue;
            const int rc = isolate(c, i, k, side, max_boxes);
            if (rc <= 0) {
                c->ncross = from;
                return rc;
            }
        }
    if (!on_arcs(c, first, nface, from, c->cells[i].axis)) {
        c->ncross = from;
        return 0;
    }
    c->cells[i].nbox = (int)(c->ncross - from);
    return 1;
}
