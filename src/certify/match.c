/*
 * The traced curves held against the cover (match.h). Each curve is walked
 * through the cells: between two of its points the chord is followed, and
 * where it leaves a cell the true crossing of that face is found by Newton's
 * method on the face (the curve itself, not the chord) and must be one of
 * the crossings the cover proved there. A chord longer than a quarter of the
 * cells it joins is first halved at a point put back on the curve, so the
 * walk sees every cell the curve passes through.
 */
#include "match.h"
#include "common/vec3.h"
#include "system.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Newton's steps and the step, relative to the region's width, at which a
 * projection has converged; or, after all the steps, the step it must be
 * below (beside a singular point J is ill-conditioned and the steps stay at
 * the rounding's level times the condition: 1e-10 is still far inside the
 * crossings' face boxes). */
#define IC_CERTIFY_NEWTON_STEPS 30
#define IC_CERTIFY_NEWTON_DONE 1e-14
#define IC_CERTIFY_NEWTON_NOISE 1e-10
/* A projected point belongs to a crossing's face box grown by this fraction
 * of the region's width (rounding only: the box holds the root strictly). */
#define IC_CERTIFY_MATCH_SLACK 1e-12
/* A chord is followed directly when shorter than this fraction of the cells
 * at its two ends; most halvings of one chord. */
#define IC_CERTIFY_CHORD_OF_CELL 0.25
#define IC_CERTIFY_MAX_HALVINGS 40
/* A point clamped onto the region is on the curve when within this
 * fraction of the region's width of it, to first order. */
#define IC_CERTIFY_NEAR_CURVE 1e-12
/* A midpoint this near a pole's edge (a fraction of the region's width) is
 * tried on the edge where Newton's method fails (a NURBS sheet has no
 * values past its domain). */
#define IC_CERTIFY_POLE_REACH 1e-2
/* Cells one short chord crosses at most: examined ones, and any. */
#define IC_CERTIFY_CHORD_CELLS 64
#define IC_CERTIFY_CHORD_CELLS_ANY 4096
/* The chord across a face, found by halving along the curve, is shorter
 * than this fraction of the cell it leaves. */
#define IC_CERTIFY_EXIT_CHORD 1e-3

typedef struct {
    ic_certificate *c;
    int curve;
    long leaf;        /* the cell the walk is in */
    long entry;       /* the crossing it came in by, or -1 (the curve's start) */
    long first_exit;  /* a closed curve: the crossing its first passage left by */
    long leaf_start;  /* a closed curve: the cell it starts in */
    long events;
    int failed;
} walker;

static double width(const ic_certificate *c, int k) { return c->hi[k] - c->lo[k]; }

/* The region's largest width. */
static double width_max(const ic_certificate *c)
{
    double w = 0.0;
    for (int k = 0; k < c->dim; k++)
        w = fmax(w, width(c, k));
    return w;
}

int ic_certify_project(const ic_certificate *c, double *z, int j)
{
    const int m = c->m, dim = c->dim;
    double last = 1.0;
    for (int it = 0; it < IC_CERTIFY_NEWTON_STEPS; it++) {
        double F[3], J[3][4], A[4][4], Y[4][4], step[4] = {0, 0, 0, 0}, zw[4];
        ic_certificate_wrap(c, z, zw); /* a periodic sheet evaluated in its period */
        if (!ic_certify_at(c->pg, zw, F, J))
            return 0;
        if (j >= 0) { /* the face's square system */
            for (int i = 0; i < m; i++)
                for (int k = 0, col = 0; k < dim; k++)
                    if (k != j)
                        A[i][col++] = J[i][k];
            if (!ic_imat_point_inverse(A, m, Y))
                return 0;
            for (int k = 0, col = 0; k < dim; k++)
                if (k != j) {
                    for (int i = 0; i < m; i++)
                        step[k] += Y[col][i] * F[i];
                    col++;
                }
        } else { /* J^T (J J^T)^-1 F */
            double g[3] = {0, 0, 0};
            for (int a = 0; a < m; a++)
                for (int b = 0; b < m; b++) {
                    A[a][b] = 0.0;
                    for (int k = 0; k < dim; k++)
                        A[a][b] += J[a][k] * J[b][k];
                }
            if (!ic_imat_point_inverse(A, m, Y))
                return 0;
            for (int a = 0; a < m; a++)
                for (int b = 0; b < m; b++)
                    g[a] += Y[a][b] * F[b];
            for (int k = 0; k < dim; k++)
                for (int a = 0; a < m; a++)
                    step[k] += J[a][k] * g[a];
        }
        double big = 0.0;
        for (int k = 0; k < dim; k++) {
            z[k] -= step[k];
            big = fmax(big, ic_certificate_rel(c, k, fabs(step[k]), 0));
        }
        if (!isfinite(big))
            return 0;
        if (big < IC_CERTIFY_NEWTON_DONE)
            return 1;
        last = big;
    }
    return last < IC_CERTIFY_NEWTON_NOISE;
}

/* The crossing of leaf i on face (j, side) whose box holds q (region
 * coordinates but j), or -1. */
static long crossing_at(const ic_certificate *c, long i, int j, int side, const double *q)
{
    const ic_cell *cl = &c->cells[i];
    if (cl->kind != IC_CELL_REGULAR)
        return -1;
    for (long x = cl->first; x < cl->first + cl->ncross; x++) {
        const ic_crossing *r = &c->cross[x];
        int in = r->face == j && r->side == side;
        for (int k = 0; in && k < c->dim; k++) {
            const double slack = IC_CERTIFY_MATCH_SLACK * width(c, k);
            in = k == j || (q[k] >= r->X[k].lo - slack && q[k] <= r->X[k].hi + slack);
        }
        if (in)
            return x;
    }
    return -1;
}

/* "(z0, z1, ...)" of a point in search coordinates. */
static void format_point(const ic_certificate *c, const double *z, char *out, size_t size)
{
    int at = snprintf(out, size, "(");
    for (int k = 0; k < c->dim && at > 0 && (size_t)at < size; k++)
        at += snprintf(out + at, size - (size_t)at, "%s%.9g", k ? ", " : "",
                       z[k] + ic_certificate_origin(c, k));
    if (at > 0 && (size_t)at < size)
        snprintf(out + at, size - (size_t)at, ")");
}

static void refuse_at(walker *w, const char *what, const double *z)
{
    char where[120];
    format_point(w->c, z, where, sizeof where);
    if (!w->failed)
        ic_certificate_refuse(w->c, "curve %d %s near %s (search coordinates)", w->curve, what,
                              where);
    w->failed = 1;
}

/* The arc a crossing lies on: the lower index of the arc's two face
 * crossings (a box crossing keeps it as its mate). */
static long arc_of(const ic_certificate *c, long x)
{
    const ic_crossing *r = &c->cross[x];
    return r->box >= 0 ? r->mate : (x < r->mate ? x : r->mate);
}

/* The walk leaves its cell by crossing x: the passage in from w->entry must
 * be one of the cell's arcs (from its other end, or from a box crossing on
 * it). */
static void leave_by(walker *w, long x, const double *q)
{
    w->c->cross[x].events++;
    w->events++;
    const ic_crossing *in = w->entry >= 0 ? &w->c->cross[w->entry] : NULL;
    if (w->entry < 0 && w->first_exit == -2)
        w->first_exit = x;
    else if (!in || (in->box < 0 ? in->mate != x : in->mate != arc_of(w->c, x)))
        refuse_at(w, "passes through a cell other than along one of its arcs", q);
}

static void enter_by(walker *w, long x)
{
    w->c->cross[x].events++;
    w->entry = x;
}

/* The largest width of leaf i relative to the region. */
static double leaf_size(const ic_certificate *c, long i, int k)
{
    return c->cells[i].hi[k] - c->cells[i].lo[k];
}

/* The chord a..b is short next to the cells at both ends (a, b wrapped). */
static int short_chord(const ic_certificate *c, const double *a, const double *b)
{
    double wa[4], wb[4];
    ic_certificate_wrap(c, a, wa), ic_certificate_wrap(c, b, wb);
    const long la = ic_certificate_locate(c, wa, -1, 0);
    const long lb = ic_certificate_locate(c, wb, -1, 0);
    if (la < 0 || lb < 0)
        return 1; /* the walk says where it left the region */
    if (la == lb)
        return 1;
    for (int k = 0; k < c->dim; k++) {
        const double d = fabs(b[k] - a[k]);
        if (d > IC_CERTIFY_CHORD_OF_CELL * fmin(leaf_size(c, la, k), leaf_size(c, lb, k)))
            return 0;
    }
    return 1;
}

/* Where the chord from cw to tw (both in the frame of leaf L, tw outside
 * it) leaves L: the point p, the face j and its side. */
static void chord_exit(const ic_certificate *c, long L, const double *cw, const double *tw,
                       double *p, int *j, int *side)
{
    const ic_cell *cl = &c->cells[L];
    double t = 1.0;
    *j = 0, *side = 1;
    for (int k = 0; k < c->dim; k++) {
        double tk = 2.0;
        if (tw[k] > cl->hi[k])
            tk = (cl->hi[k] - cw[k]) / (tw[k] - cw[k]);
        else if (tw[k] < cl->lo[k])
            tk = (cl->lo[k] - cw[k]) / (tw[k] - cw[k]);
        if (tk < t)
            t = tk, *j = k, *side = tw[k] > cl->hi[k];
    }
    for (int k = 0; k < c->dim; k++)
        p[k] = cw[k] + t * (tw[k] - cw[k]);
    p[*j] = *side ? cl->hi[*j] : cl->lo[*j];
}

static int inside_leaf(const ic_certificate *c, long L, const double *z)
{
    const ic_cell *cl = &c->cells[L];
    for (int k = 0; k < c->dim; k++)
        if (!(z[k] >= cl->lo[k] && z[k] <= cl->hi[k]))
            return 0;
    return 1;
}

/* z brought onto the region where it lies past a face that is not a seam
 * by rounding (within IC_CERTIFY_END_REACH of the width: the tracer's end
 * on a domain edge, Newton's method along a pole's edge). */
static void onto_region(const ic_certificate *c, double *z)
{
    for (int k = 0; k < c->dim; k++) {
        const double reach = IC_CERTIFY_END_REACH * width(c, k);
        if (c->periodic[k])
            continue;
        if (z[k] > c->hi[k] && z[k] <= c->hi[k] + reach)
            z[k] = c->hi[k];
        else if (z[k] < c->lo[k] && z[k] >= c->lo[k] - reach)
            z[k] = c->lo[k];
    }
}

int ic_certify_near_curve(const ic_certificate *c, const double *z, double tol)
{
    double F[3], J[3][4], w[4];
    ic_certificate_wrap(c, z, w);
    if (!ic_certify_at(c->pg, w, F, J))
        return 0;
    for (int i = 0; i < c->m; i++) {
        double g = 0.0;
        for (int k = 0; k < c->dim; k++)
            g = hypot(g, J[i][k]);
        if (!(fabs(F[i]) <= tol * g))
            return 0;
    }
    return 1;
}

/* z lies in the region (its periodic coordinates anywhere). */
static int in_region(const ic_certificate *c, const double *z)
{
    for (int k = 0; k < c->dim; k++)
        if (!c->periodic[k] && !(z[k] >= c->lo[k] && z[k] <= c->hi[k]))
            return 0;
    return 1;
}

/* m near a pole's edge (a chord across the gap the tracer joins over a
 * pole) put on the edge, which lies on the curve where the pole does: 1
 * when that puts it on the curve. */
static int onto_pole(const ic_certificate *c, double *m)
{
    for (int p = 0; p < c->npoles; p++) {
        const int j = c->poles[p].j;
        if (fabs(m[j] - c->poles[p].edge) > IC_CERTIFY_POLE_REACH * width(c, j))
            continue;
        double q[4];
        memcpy(q, m, sizeof q);
        q[j] = c->poles[p].edge;
        if (ic_certify_near_curve(c, q, IC_CERTIFY_NEAR_CURVE * width_max(c))) {
            memcpy(m, q, sizeof q);
            return 1;
        }
    }
    return 0;
}

/* The midpoint m of a chord put back on the curve; where Newton's method
 * fails (beside a singular point, where J loses rank) a midpoint in a
 * singular cell is kept as it is: nothing is claimed there. 0: neither. */
static int put_back(const ic_certificate *c, double *m)
{
    double keep[4], mw[4];
    memcpy(keep, m, sizeof keep);
    if (ic_certify_project(c, m, -1)) {
        onto_region(c, m);
        if (in_region(c, m))
            return 1;
        /* past a pole's edge, where the formula folds back: the edge itself
         * is on the curve there */
        for (int k = 0; k < c->dim; k++)
            if (!c->periodic[k])
                m[k] = fmin(fmax(m[k], c->lo[k]), c->hi[k]);
        if (ic_certify_near_curve(c, m, IC_CERTIFY_NEAR_CURVE * width_max(c)))
            return 1;
    }
    memcpy(m, keep, sizeof keep);
    if (onto_pole(c, m))
        return 1;
    ic_certificate_wrap(c, m, mw);
    const long L = ic_certificate_locate(c, mw, -1, 0);
    return L >= 0 && ic_cell_unexamined(c->cells[L].kind);
}

/* Where the curve from cw (in leaf L) to tw (outside it) leaves L: the
 * two are brought together by halving along the curve (each midpoint put
 * back on it) until their chord is short next to L, then that chord's exit
 * face gives j and side and Newton's method on the face the crossing q: 1,
 * or 2 with q the chord's exit where Newton's method fails (beside a
 * singular point), 0 when the halving fails. */
static int bracket_exit(const ic_certificate *c, long L, const double *cw, const double *tw,
                        double *q, int *j, int *side)
{
    double a[4], b[4];
    memcpy(a, cw, sizeof a), memcpy(b, tw, sizeof b);
    for (int it = 0; it < IC_CERTIFY_MAX_HALVINGS; it++) {
        int near = 1;
        for (int k = 0; k < c->dim; k++)
            near = near && fabs(b[k] - a[k]) <= IC_CERTIFY_EXIT_CHORD * leaf_size(c, L, k);
        if (near)
            break;
        double m[4];
        for (int k = 0; k < c->dim; k++)
            m[k] = 0.5 * (a[k] + b[k]);
        if (!put_back(c, m))
            return 0;
        memcpy(inside_leaf(c, L, m) ? a : b, m, sizeof m);
    }
    chord_exit(c, L, a, b, q, j, side);
    double on_chord[4];
    memcpy(on_chord, q, sizeof on_chord);
    if (ic_certify_project(c, q, *j)) {
        onto_region(c, q); /* q[j] is on a face of the cell already */
        return 1;
    }
    memcpy(q, on_chord, sizeof on_chord);
    return 2;
}

/* The point q on face (j, side) of leaf L lies on that face's part. */
static int on_face(const ic_certificate *c, long L, const double *q, int j)
{
    const ic_cell *cl = &c->cells[L];
    for (int k = 0; k < c->dim; k++) {
        const double slack = IC_CERTIFY_MATCH_SLACK * width(c, k);
        if (k != j && !(q[k] >= cl->lo[k] - slack && q[k] <= cl->hi[k] + slack))
            return 0;
    }
    return 1;
}

/* q on face (j, side) of a cell, in the frame of the cell beyond it:
 * across a periodic seam, on its other side. */
static void beyond_face(const ic_certificate *c, const double *q, int j, int side, double *qn)
{
    ic_certificate_wrap(c, q, qn);
    if (c->periodic[j] && side && q[j] >= c->hi[j])
        qn[j] = c->lo[j]; /* across the seam, upwards */
    else if (c->periodic[j] && !side && q[j] <= c->lo[j])
        qn[j] = c->hi[j]; /* across the seam, downwards */
}

/* The face (j, side) of leaf L at q lies between two singular cells, where
 * the walk may cross it anywhere. */
static int between_singular(const ic_certificate *c, long L, const double *q, int j, int side)
{
    if (!ic_cell_unexamined(c->cells[L].kind))
        return 0;
    double qn[4];
    beyond_face(c, q, j, side, qn);
    const long next = ic_certificate_locate(c, qn, j, side ? 1 : -1);
    return next >= 0 && next != L && ic_cell_unexamined(c->cells[next].kind);
}

/* The walk leaves its cell across face (j, side) at q: a regular cell by
 * one of its crossings, a singular one anywhere (what it holds is not
 * proven). 0: refused. */
static int leave_cell(walker *w, int j, int side, const double *q)
{
    const ic_cell_kind kind = w->c->cells[w->leaf].kind;
    if (ic_cell_unexamined(kind))
        return 1;
    const long xa = kind == IC_CELL_REGULAR ? crossing_at(w->c, w->leaf, j, side, q) : -1;
    if (xa < 0) {
        refuse_at(w, "crosses a cell's face where no crossing is proven", q);
        return 0;
    }
    leave_by(w, xa, q);
    return !w->failed;
}

/* The walk enters leaf `next` across its face (j, !side) at qn: a regular
 * cell by one of its crossings, a singular one anywhere. 0: refused. */
static int enter_cell(walker *w, long next, int j, int side, const double *qn)
{
    const ic_cell_kind kind = w->c->cells[next].kind;
    if (ic_cell_unexamined(kind)) {
        w->entry = -1;
        return 1;
    }
    const long xb = kind == IC_CELL_REGULAR ? crossing_at(w->c, next, j, !side, qn) : -1;
    if (xb < 0) {
        refuse_at(w, "enters a cell where no crossing is proven", qn);
        return 0;
    }
    enter_by(w, xb);
    return 1;
}

/* A point on a periodic seam, wrapped to one side, taken on the side of
 * leaf L (a walk that came to it across the seam stays in its cell). */
static void to_leaf_frame(const ic_certificate *c, long L, double *w)
{
    const ic_cell *cl = &c->cells[L];
    for (int k = 0; k < c->dim; k++) {
        const double T = width(c, k);
        if (!c->periodic[k] || (w[k] >= cl->lo[k] && w[k] <= cl->hi[k]))
            continue;
        if (w[k] + T >= cl->lo[k] && w[k] + T <= cl->hi[k])
            w[k] += T;
        else if (w[k] - T >= cl->lo[k] && w[k] - T <= cl->hi[k])
            w[k] -= T;
    }
}

/* One step of the walk: from cur (on the curve) towards target, across the
 * face where the chord leaves the current cell. 1: target reached, 0: a
 * face crossed (cur, target moved on), -1: refused. */
static int cross_face(walker *w, double *cur, double *target)
{
    const ic_certificate *c = w->c;
    double cw[4], tw[4], q[4];
    ic_certificate_wrap(c, cur, cw);
    to_leaf_frame(c, w->leaf, cw);
    memcpy(q, cw, sizeof q); /* where a refusal names, should the halving fail */
    for (int k = 0; k < c->dim; k++)
        tw[k] = target[k] + (cw[k] - cur[k]);
    onto_region(c, tw);
    const ic_cell *cl = &c->cells[w->leaf];
    int inside = 1;
    for (int k = 0; k < c->dim; k++)
        inside = inside && tw[k] >= cl->lo[k] && tw[k] <= cl->hi[k];
    if (inside)
        return 1;
    int j, side;
    const int found = bracket_exit(c, w->leaf, cw, tw, q, &j, &side);
    if (!found || !on_face(c, w->leaf, q, j) ||
        (found == 2 && !between_singular(c, w->leaf, q, j, side))) {
        refuse_at(w, "cannot be followed across a cell's face", q);
        return -1;
    }
    if (!leave_cell(w, j, side, q))
        return -1;
    const int dir = side ? 1 : -1;
    double qn[4];
    beyond_face(c, q, j, side, qn);
    const long next = ic_certificate_locate(c, qn, j, dir);
    if (next < 0) {
        refuse_at(w, "leaves the region where it does not end", q);
        return -1;
    }
    if (!enter_cell(w, next, j, side, qn))
        return -1;
    w->leaf = next;
    for (int k = 0; k < c->dim; k++) { /* continue in the frame of qn */
        target[k] = tw[k] + (qn[k] - q[k]);
        cur[k] = qn[k];
    }
    return w->failed ? -1 : 0;
}

/* The walk along the chord a..b of a curve, halved until short. */
static void walk_chord(walker *w, const double *a, const double *b, int halvings)
{
    if (w->failed)
        return;
    if (!short_chord(w->c, a, b)) {
        double m[4];
        for (int k = 0; k < w->c->dim; k++)
            m[k] = 0.5 * (a[k] + b[k]);
        if (halvings >= IC_CERTIFY_MAX_HALVINGS || !put_back(w->c, m)) {
            refuse_at(w, "has a chord that cannot be put back on the curve", a);
            return;
        }
        walk_chord(w, a, m, halvings + 1);
        walk_chord(w, m, b, halvings + 1);
        return;
    }
    double cur[4], target[4];
    memcpy(cur, a, (size_t)w->c->dim * sizeof *a);
    memcpy(target, b, (size_t)w->c->dim * sizeof *b);
    /* a short chord crosses few examined cells; along a pole's strip it
     * may cross many singular ones */
    for (int step = 0, examined = 0; step < IC_CERTIFY_CHORD_CELLS_ANY &&
                                     examined < IC_CERTIFY_CHORD_CELLS;
         step++) {
        examined += !ic_cell_unexamined(w->c->cells[w->leaf].kind);
        const int rc = cross_face(w, cur, target);
        if (rc != 0)
            return;
    }
    refuse_at(w, "crosses too many cells along one chord", a);
}

/* Leaf L (-1: none) is a singular or tangential cell, where a branch may
 * end. */
static int in_singular_cell(const ic_certificate *c, long L)
{
    return L >= 0 && ic_cell_unexamined(c->cells[L].kind);
}

/* An open curve's end z: on a face of its cell that is the region's
 * boundary, at one of the crossings proven there: that crossing, or -1. */
static long end_crossing(walker *w, const double *z, long *leaf)
{
    const ic_certificate *c = w->c;
    double zw[4];
    ic_certificate_wrap(c, z, zw);
    *leaf = ic_certificate_locate(c, zw, -1, 0);
    if (*leaf < 0)
        return -1;
    const ic_cell *cl = &c->cells[*leaf];
    for (int j = 0; j < c->dim; j++)
        for (int side = 0; side < 2; side++) {
            const double v = side ? cl->hi[j] : cl->lo[j];
            const double edge = side ? c->hi[j] : c->lo[j];
            if (c->periodic[j] || v != edge ||
                fabs(zw[j] - v) > IC_CERTIFY_END_REACH * width(c, j))
                continue;
            double q[4];
            memcpy(q, zw, sizeof q);
            q[j] = v;
            if (!ic_certify_project(w->c, q, j))
                continue;
            const long x = crossing_at(c, *leaf, j, side, q);
            if (x >= 0)
                return x;
        }
    return -1;
}

/* An open curve's end z on the box in a cell the box cuts: on the box's
 * face (within IC_CERTIFY_BOX_REACH of its width: the tracer lands on it
 * to rounding), in the box of one of the cell's box crossings there: that
 * crossing, or -1. */
static long box_end(const ic_certificate *c, long L, const double *z)
{
    if (L < 0 || c->cells[L].kind != IC_CELL_REGULAR)
        return -1;
    const ic_cell *cl = &c->cells[L];
    double zw[4];
    ic_certificate_wrap(c, z, zw);
    ic_interval Z[4], xyz[3];
    for (int k = 0; k < c->dim; k++)
        Z[k] = (ic_interval){zw[k], zw[k]};
    if (!ic_certify_image(c->pg, Z, xyz))
        return -1;
    for (long x = cl->first + cl->ncross; x < cl->first + cl->ncross + cl->nbox; x++) {
        const int face = c->cross[x].box / 2, side = c->cross[x].box % 2;
        const double reach = IC_CERTIFY_BOX_REACH * (c->box[face][1] - c->box[face][0]);
        const double at = 0.5 * xyz[face].lo + 0.5 * xyz[face].hi;
        int in = fabs(at - c->box[face][side]) <= reach;
        for (int k = 0; in && k < c->dim; k++) {
            const double slack = IC_CERTIFY_MATCH_SLACK * width(c, k);
            in = zw[k] >= c->cross[x].X[k].lo - slack && zw[k] <= c->cross[x].X[k].hi + slack;
        }
        if (in)
            return x;
    }
    return -1;
}

/* Walks curve k (its points z, continuous across seams). */
static void walk_curve(walker *w, const double *z, int n, int closed)
{
    const int dim = w->c->dim;
    w->entry = -1, w->first_exit = closed ? -2 : -1, w->events = 0;
    if (!closed) {
        long x = end_crossing(w, z, &w->leaf);
        if (x < 0)
            x = box_end(w->c, w->leaf, z);
        if (x < 0 && !in_singular_cell(w->c, w->leaf)) {
            refuse_at(w, "starts inside the region, not at a crossing of its boundary nor "
                         "by a singular point",
                      z);
            return;
        }
        if (x >= 0)
            enter_by(w, x);
    } else {
        double zw[4];
        ic_certificate_wrap(w->c, z, zw);
        w->leaf = ic_certificate_locate(w->c, zw, -1, 0);
        if (w->leaf < 0) {
            refuse_at(w, "lies outside the region", z);
            return;
        }
        w->leaf_start = w->leaf;
    }
    for (int i = 0; i + 1 < n && !w->failed; i++)
        walk_chord(w, z + (size_t)i * dim, z + (size_t)(i + 1) * dim, 0);
    if (w->failed)
        return;
    if (closed) { /* back to the start, continuous across the seams */
        const double *last = z + (size_t)(n - 1) * dim;
        double first[4];
        for (int k = 0; k < dim; k++) {
            const double T = w->c->periodic[k] ? width(w->c, k) : 0.0;
            first[k] = z[k] + (T > 0 ? T * nearbyint((last[k] - z[k]) / T) : 0.0);
        }
        const int from_unexamined = in_singular_cell(w->c, w->leaf_start);
        walk_chord(w, last, first, 0);
        if (w->failed)
            return;
        /* a curve that starts in a singular or tangential cell closes in one
         * (a tangential curve lies in its tube all along) */
        if (from_unexamined ? !in_singular_cell(w->c, w->leaf)
                            : (w->events == 0 || w->entry < 0 ||
                               w->c->cross[w->entry].mate != w->first_exit))
            refuse_at(w, "closes other than along an arc of a cell", z);
        return;
    }
    long leaf;
    const double *end = z + (size_t)(n - 1) * dim;
    const long x = end_crossing(w, end, &leaf);
    if (x < 0 && in_singular_cell(w->c, w->leaf))
        return; /* a branch ends at a singular point */
    const long e = x < 0 ? box_end(w->c, w->leaf, end) : -1;
    if (e >= 0) { /* on the box: the passage in must be along e's arc */
        const ic_crossing *in = w->entry >= 0 ? &w->c->cross[w->entry] : NULL;
        w->c->cross[e].events++;
        if (!in || e == w->entry || arc_of(w->c, w->entry) != w->c->cross[e].mate)
            refuse_at(w, "ends on the box other than along an arc of its cell", end);
        return;
    }
    if (x < 0 || leaf != w->leaf) {
        refuse_at(w, "ends inside the region, not at a crossing of its boundary nor by a "
                     "singular point",
                  end);
        return;
    }
    leave_by(w, x, end);
}

/* Consecutive points a, b of a curve lie on opposite edges of a domain that
 * is not periodic (a closed curve through the seam of a sphere's net, say):
 * farther apart than this fraction of its width, ... */
#define IC_CERTIFY_JUMP 0.5
/* ... and the straight way between them in the parameters is no step of
 * the curve: through its middle's image it is longer in space than this
 * many times the distance of their images (across a seam the images meet,
 * the middle is across the surface; a step across a domain narrower than
 * the steps, a strip 7e-4 wide, goes straight). */
#define IC_CERTIFY_JUMP_DETOUR 2.0

static int jump(const ic_certificate *c, const double *a, const double *b)
{
    int far = 0;
    double m[4];
    for (int k = 0; k < c->dim; k++) {
        far |= !c->periodic[k] && fabs(b[k] - a[k]) > IC_CERTIFY_JUMP * width(c, k);
        m[k] = 0.5 * (a[k] + b[k]);
    }
    if (!far)
        return 0;
    double xa[3], xb[3], xm[3];
    ic_error e;
    if (c->pg->kind->position(c->pg, a, xa, &e) != IC_OK ||
        c->pg->kind->position(c->pg, b, xb, &e) != IC_OK ||
        c->pg->kind->position(c->pg, m, xm, &e) != IC_OK)
        return 1;
    double am[3], mb[3], ab[3];
    ic_axpy3(am, xm, -1.0, xa), ic_axpy3(mb, xb, -1.0, xm), ic_axpy3(ab, xb, -1.0, xa);
    return !(ic_norm3(am) + ic_norm3(mb) <= IC_CERTIFY_JUMP_DETOUR * ic_norm3(ab));
}

/* The first point of a closed curve that lies strictly inside a regular
 * cell (a walk started on a face would leave the first cell unpaired, one
 * started in a singular cell would have no arc to close on). */
static int strictly_inside_from(const ic_certificate *c, const double *z, int n)
{
    for (int i = 0; i < n; i++) {
        double zw[4];
        ic_certificate_wrap(c, z + (size_t)i * c->dim, zw);
        const long L = ic_certificate_locate(c, zw, -1, 0);
        int in = L >= 0 && c->cells[L].kind == IC_CELL_REGULAR;
        for (int k = 0; in && k < c->dim; k++)
            in = zw[k] > c->cells[L].lo[k] && zw[k] < c->cells[L].hi[k];
        if (in)
            return i;
    }
    return 0;
}

/* The closed curve z started at point i0 instead, continuous across the
 * seams. */
static void rotated(const ic_certificate *c, const double *z, int n, int i0, double *out)
{
    const int dim = c->dim;
    for (int s = 0; s < n; s++) {
        double *o = out + (size_t)s * dim;
        memcpy(o, z + (size_t)((i0 + s) % n) * dim, (size_t)dim * sizeof *o);
        for (int k = 0; s > 0 && k < dim; k++)
            if (c->periodic[k]) {
                const double T = width(c, k);
                o[k] += T * nearbyint((o[k - dim] - o[k]) / T);
            }
    }
}

/* Walks a curve (z: n points, continuous across periodic seams) as the
 * pieces its jumps across a domain cut it into: a closed curve that jumps
 * is open pieces from edge to edge of the search region. */
static void walk_pieces(walker *w, const double *z, int n, int closed, double *buf)
{
    const int dim = w->c->dim;
    int start = -1;
    for (int i = 0; i + 1 < n && start < 0; i++)
        if (jump(w->c, z + (size_t)i * dim, z + (size_t)(i + 1) * dim))
            start = i + 1;
    const int closing = closed && jump(w->c, z + (size_t)(n - 1) * dim, z);
    if (closed && start < 0 && !closing) {
        rotated(w->c, z, n, strictly_inside_from(w->c, z, n), buf);
        walk_curve(w, buf, n, 1);
        return;
    }
    if (!closed || closing)
        start = 0;
    int m = 0;
    for (int step = 0; step < n && !w->failed; step++) {
        const double *p = z + (size_t)((start + step) % n) * dim;
        double *out = buf + (size_t)m * dim;
        memcpy(out, p, (size_t)dim * sizeof *p);
        for (int k = 0; m > 0 && k < dim; k++)
            if (w->c->periodic[k]) { /* continuous across the rotation too */
                const double T = width(w->c, k);
                out[k] += T * nearbyint((out[k - dim] - out[k]) / T);
            }
        m++;
        const double *next = z + (size_t)((start + step + 1) % n) * dim;
        const int last = step + 1 == n;
        if (last || jump(w->c, p, next)) {
            if (m >= 2)
                walk_curve(w, buf, m, 0);
            else
                refuse_at(w, "has a piece of one point between two edges of the domain", p);
            m = 0;
        }
    }
}

/* A curve's point this fraction of the region's width outside it, or less,
 * is a rounding away from its face (the tracer lands on faces to rounding). */
#define IC_CERTIFY_ONTO_FACE 1e-12

/* The curve's points made continuous across the seams of periodic
 * coordinates (a point may have been brought into the period), and a point
 * a rounding outside the region put on its face (a branch point on the
 * face, located 1e-37 beyond it: outside, no cell holds it). */
static void unwrap(const ic_certificate *c, const double *z, int n, double *out, int mirror)
{
    const int dim = c->dim;
    for (int i = 0; i < n; i++)
        for (int k = 0; k < dim; k++) {
            /* a self-intersection's mirror: (u, v, p, q) read as (p, q, u, v) */
            const int src = mirror ? (k + 2) % 4 : k;
            double v = z[(size_t)i * dim + src];
            if (i > 0 && c->periodic[k]) {
                const double T = width(c, k), prev = out[(size_t)(i - 1) * dim + k];
                v += T * nearbyint((prev - v) / T);
            }
            const double on = fmin(fmax(v, c->lo[k]), c->hi[k]);
            if (!c->periodic[k] && fabs(v - on) <= IC_CERTIFY_ONTO_FACE * width(c, k))
                v = on;
            out[(size_t)i * dim + k] = v;
        }
}

/* Every crossing met by exactly one traced passage, or refused (the first
 * reason kept); an arc no passage met gives its crossing's centre as a
 * seed, once per arc. */
static void check_arcs_met(ic_certificate *c)
{
    for (long x = 0; x < c->ncross; x++) {
        const ic_crossing *r = &c->cross[x];
        if (r->outside || r->events == 1)
            continue; /* outside: a face crossing outside the box, no curve meets it */
        double q[4] = {0};
        char where[120];
        for (int k = 0; k < c->dim; k++)
            q[k] = 0.5 * r->K[k].lo + 0.5 * r->K[k].hi;
        format_point(c, q, where, sizeof where);
        ic_certificate_refuse(c, "the arc of cell %d through %s is %s", r->cell, where,
                              r->events == 0 ? "not traced" : "traced more than once");
        /* the arc's other crossing, looked at already, gave its seed */
        const ic_crossing *m = r->mate >= 0 ? &c->cross[r->mate] : NULL;
        const int seen = m && r->mate < x && m->events == 0 && !m->outside;
        ic_certify_summary *s = &c->summary;
        if (r->events == 0 && !seen && s->nseeds < IC_CERTIFY_MAX_SEEDS)
            memcpy(s->seeds[s->nseeds++], q, sizeof q);
    }
}

ic_status ic_certify_curves(ic_certificate *c, const ic_certify_curve *curves, int ncurves,
                            ic_error *err)
{
    for (long x = 0; x < c->ncross; x++)
        c->cross[x].events = 0;
    const int mirrors = c->pg->kind == &ic_pairing_self ? 2 : 1;
    for (int k = 0; k < ncurves && c->summary.accepted; k++)
        for (int mir = 0; mir < mirrors && c->summary.accepted; mir++) {
            const ic_certify_curve *cv = &curves[k];
            if (cv->tangential)
                continue; /* in its tube (tube.c) */
            if (cv->npoints < 2) {
                ic_certificate_refuse(c, "curve %d has fewer than two points", k);
                break;
            }
            double *z = malloc(2 * (size_t)cv->npoints * (size_t)c->dim * sizeof *z);
            if (!z)
                return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory certifying");
            unwrap(c, cv->z, cv->npoints, z, mir);
            walker w = {.c = c, .curve = k};
            walk_pieces(&w, z, cv->npoints, cv->closed, z + (size_t)cv->npoints * c->dim);
            free(z);
        }
    if (c->summary.accepted)
        check_arcs_met(c);
    return IC_OK;
}
