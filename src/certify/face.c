/*
 * The crossings of a cell's face (certificate.h): every root of F on the
 * face z[j] = v is isolated by subdividing the face until each part is
 * either excluded (an enclosure of F, or a Krawczyk image, misses 0 there)
 * or holds exactly one root, proven by the Krawczyk image lying strictly
 * inside it (Krawczyk 1969; Moore 1977). The Krawczyk test on the face uses
 * the minor of J without column j: a proven root is a transversal crossing
 * (the curve's tangent has a nonzero j-component there).
 */
#include "certificate.h"
#include "system.h"

#include <stdlib.h>
#include <string.h>

/* J without column j (an m x m matrix). */
static void minor_without(const ic_certify_eval *e, int m, int j, ic_interval M[4][4])
{
    for (int i = 0; i < m; i++)
        for (int k = 0, c = 0; k <= m; k++)
            if (k != j)
                M[i][c++] = e->J[i][k];
}

/* The unknowns of the face (every coordinate but j). */
static void unknowns(const ic_interval *X, int dim, int j, ic_interval *U)
{
    for (int k = 0, c = 0; k < dim; k++)
        if (k != j)
            U[c++] = X[k];
}

/* 1: no root in X; 2: one root, proven (K filled); 0: undecided. */
static int decide(const ic_certificate *c, const ic_interval *X, int j, ic_interval *K)
{
    ic_certify_eval e, ec;
    if (!ic_certify_enclose(c->pg, X, &e))
        return 0;
    if (ic_certify_excludes(&e, c->m))
        return 1;
    double mid[4];
    if (!ic_certify_centre(c->pg, X, mid, &ec))
        return 0;
    if (ic_certify_excludes_centred(c->pg, X, &e, mid, &ec))
        return 1;
    ic_interval M[4][4], U[4], KU[4];
    minor_without(&e, c->m, j, M);
    unknowns(X, c->dim, j, U);
    if (!ic_imat_krawczyk(U, ec.F, M, c->m, KU))
        return 0;
    if (ic_imat_disjoint(KU, U, c->m))
        return 1;
    if (!ic_imat_strictly_inside(KU, U, c->m))
        return 0;
    for (int k = 0, u = 0; k < c->dim; k++)
        K[k] = k == j ? X[k] : KU[u++];
    return 2;
}

/* Krawczyk steps at most that narrow a crossing's enclosure. */
#define IC_CERTIFY_TIGHTEN_STEPS 8

void ic_certify_tighten(const ic_certificate *c, ic_crossing *x)
{
    const int j = x->face;
    for (int it = 0; it < IC_CERTIFY_TIGHTEN_STEPS; it++) {
        ic_certify_eval e, ec;
        double mid[4];
        if (!ic_certify_enclose(c->pg, x->K, &e) || !ic_certify_centre(c->pg, x->K, mid, &ec))
            return;
        ic_interval M[4][4], U[4], KU[4];
        minor_without(&e, c->m, j, M);
        unknowns(x->K, c->dim, j, U);
        if (!ic_imat_krawczyk(U, ec.F, M, c->m, KU))
            return;
        double before = 0.0, after = 0.0;
        for (int u = 0; u < c->m; u++) { /* the root lies in both */
            KU[u] = (ic_interval){KU[u].lo > U[u].lo ? KU[u].lo : U[u].lo,
                                  KU[u].hi < U[u].hi ? KU[u].hi : U[u].hi};
            if (!(KU[u].lo <= KU[u].hi))
                return;
            before += U[u].hi - U[u].lo, after += KU[u].hi - KU[u].lo;
        }
        for (int k = 0, u = 0; k < c->dim; k++)
            if (k != j)
                x->K[k] = KU[u++];
        if (!(after < 0.5 * before))
            return;
    }
}

/* The widest unknown of X relative to the region's widths. */
static int widest(const ic_certificate *c, const ic_interval *X, int j)
{
    int best = -1;
    double wbest = -1.0;
    for (int k = 0; k < c->dim; k++) {
        const double w = (X[k].hi - X[k].lo) / (c->hi[k] - c->lo[k]);
        if (k != j && w > wbest)
            best = k, wbest = w;
    }
    return best;
}

static int add_root(ic_certificate *c, long cell, int j, int side, const ic_interval *X,
                    const ic_interval *K)
{
    ic_crossing x;
    memset(&x, 0, sizeof x);
    x.cell = (int)cell, x.face = j, x.side = side, x.mate = -1, x.box = -1;
    memcpy(x.X, X, sizeof x.X);
    memcpy(x.K, K, sizeof x.K);
    return ic_certificate_add_crossing(c, &x) < 0 ? -1 : 1;
}

int ic_certify_face(ic_certificate *c, long cell, int j, int side, int max_boxes)
{
    const ic_cell *cl = &c->cells[cell];
    if (c->face_cap < max_boxes + 1) {
        void *p = realloc(c->face_stack, (size_t)(max_boxes + 1) * sizeof *c->face_stack);
        if (!p)
            return -1;
        c->face_stack = p;
        c->face_cap = max_boxes + 1;
    }
    ic_interval(*stack)[4] = c->face_stack;
    int n = 1, used = 0, rc = 1;
    for (int k = 0; k < c->dim; k++)
        stack[0][k] = (ic_interval){cl->lo[k], cl->hi[k]};
    const double v = side ? cl->hi[j] : cl->lo[j];
    stack[0][j] = (ic_interval){v, v};
    while (n > 0 && rc == 1) {
        ic_interval b[4], K[4];
        memcpy(b, stack[--n], sizeof b);
        const int d = decide(c, b, j, K);
        if (d == 2)
            rc = add_root(c, cell, j, side, b, K);
        if (d != 0)
            continue;
        if (++used >= max_boxes) {
            rc = 0;
            break;
        }
        const int k = widest(c, b, j);
        const double mid = 0.5 * b[k].lo + 0.5 * b[k].hi;
        if (!(mid > b[k].lo && mid < b[k].hi)) { /* no room left to split */
            rc = 0;
            break;
        }
        memcpy(stack[n], b, sizeof b), stack[n][k].hi = mid;
        memcpy(stack[n + 1], b, sizeof b), stack[n + 1][k].lo = mid;
        n += 2;
    }
    return rc;
}
