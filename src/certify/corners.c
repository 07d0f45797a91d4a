/* Singular boxes where a curve meets the boundary of the region or the box
 * other than across one face (match.h): at an end in a corner, where it
 * leaves across an edge of a cell and the crossing lies on two faces at
 * once, and where it touches a face and turns back (Viviani's curve on a
 * NURBS sphere whose seam is a domain edge), a double root no face
 * isolates. The box is placed at the tracer's point, so it proves nothing
 * there; the crossings of the regular cells around it are isolated and
 * matched as anywhere else. */
#include "match.h"
#include "system.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* How many faces of the region (its coordinates that are not periodic) and
 * of the box the point z lies on; its image in xyz (of z on the region: the
 * tracer's point may lie past its face by rounding). -1 with no image. */
static int faces_reached(const ic_certificate *c, const double *z, double xyz[3])
{
    double w[4];
    ic_interval Z[4], img[3];
    ic_certificate_wrap(c, z, w);
    int n = 0;
    for (int k = 0; k < c->dim; k++) {
        w[k] = fmin(fmax(w[k], c->lo[k]), c->hi[k]); /* the tracer's rounding past an edge */
        Z[k] = (ic_interval){w[k], w[k]};
        const double reach = IC_CERTIFY_END_REACH * (c->hi[k] - c->lo[k]);
        if (!c->periodic[k])
            n += fabs(w[k] - c->lo[k]) <= reach || fabs(w[k] - c->hi[k]) <= reach;
    }
    if (!ic_certify_image(c->pg, Z, img))
        return -1;
    for (int k = 0; k < 3; k++) {
        xyz[k] = 0.5 * img[k].lo + 0.5 * img[k].hi;
        const double reach = IC_CERTIFY_BOX_REACH * (c->box[k][1] - c->box[k][0]);
        if (c->has_box && c->dim != 3) /* the implicit pairing's region is the box */
            n += fabs(xyz[k] - c->box[k][0]) <= reach || fabs(xyz[k] - c->box[k][1]) <= reach;
    }
    return n;
}

/* How many periodic seams z lies on (within IC_CERTIFY_END_REACH). */
static int seams_reached(const ic_certificate *c, const double *z)
{
    double w[4];
    ic_certificate_wrap(c, z, w);
    int n = 0;
    for (int k = 0; k < c->dim; k++) {
        const double reach = IC_CERTIFY_END_REACH * (c->hi[k] - c->lo[k]);
        if (c->periodic[k])
            n += fabs(w[k] - c->lo[k]) <= reach || fabs(w[k] - c->hi[k]) <= reach;
    }
    return n;
}

/* Appends p to the singular points, with a box of the usual size. */
static int add_point(ic_certificate *c, const double p[3])
{
    const size_t n = (size_t)c->nsingular + 1;
    double(*grown)[3] = realloc(c->singular, n * sizeof *grown);
    if (grown)
        c->singular = grown;
    double *scale = grown ? realloc(c->singular_scale, n * sizeof *scale) : NULL;
    if (scale)
        c->singular_scale = scale;
    long *cells = scale ? realloc(c->box_cells, n * sizeof *cells) : NULL;
    if (cells)
        c->box_cells = cells;
    long *smooth = cells ? realloc(c->box_smooth, n * sizeof *smooth) : NULL;
    if (!smooth)
        return 0;
    c->box_smooth = smooth;
    scale[c->nsingular] = 1.0;
    cells[c->nsingular] = smooth[c->nsingular] = 0;
    memcpy(c->singular[c->nsingular++], p, sizeof grown[0]);
    return 1;
}

/* p lies in a singular box already. */
static int boxed(const ic_certificate *c, const double p[3])
{
    for (int s = 0; s < c->nsingular; s++) {
        const double h = c->singular_half * c->singular_scale[s];
        if (fabs(p[0] - c->singular[s][0]) <= h && fabs(p[1] - c->singular[s][1]) <= h &&
            fabs(p[2] - c->singular[s][2]) <= h)
            return 1;
    }
    return 0;
}

/* Which side of periodic coordinate k's seam z lies on: 0 within the
 * first half of the period, 1 the second. */
static int seam_side(const ic_certificate *c, const double *z, int k)
{
    double w[4];
    ic_certificate_wrap(c, z, w);
    return w[k] - c->lo[k] > 0.5 * (c->hi[k] - c->lo[k]);
}

/* The distance of z from the nearer face (or seam) across coordinate k,
 * as a fraction of the region's width; that face's value in *face. */
static double face_distance(const ic_certificate *c, const double *z, int k, double *face)
{
    double w[4];
    ic_certificate_wrap(c, z, w);
    const double T = c->hi[k] - c->lo[k];
    const double lo = fabs(w[k] - c->lo[k]), hi = fabs(c->hi[k] - w[k]);
    *face = lo <= hi ? c->lo[k] : c->hi[k];
    return fmin(lo, hi) / T;
}

/* Point i within curve cv is the sample nearest a face across some
 * coordinate (within IC_CERTIFY_TOUCH_NEAR of the width, both neighbours
 * farther and, at a seam, on its side): the curve may touch the face
 * between samples. Newton's method on the face from there finds the touch
 * (a double root: it converges linearly, hence two rounds), whose image
 * goes in xyz. 0 when there is none. */
static int touch_near(const ic_certificate *c, const ic_certify_curve *cv, int i, double xyz[3])
{
    const int n = cv->npoints, dim = c->dim;
    if (!cv->closed && (i == 0 || i == n - 1))
        return 0;
    const double *z = cv->z + (size_t)i * (size_t)dim;
    const double *a = cv->z + (size_t)((i + n - 1) % n) * (size_t)dim;
    const double *b = cv->z + (size_t)((i + 1) % n) * (size_t)dim;
    for (int k = 0; k < dim; k++) {
        double face, fa, fb;
        const double d = face_distance(c, z, k, &face);
        if (d > IC_CERTIFY_TOUCH_NEAR || face_distance(c, a, k, &fa) < d ||
            face_distance(c, b, k, &fb) < d)
            continue;
        if (c->periodic[k]) { /* one seam: the neighbours on one side of it */
            if (seam_side(c, a, k) != seam_side(c, b, k))
                continue;
            face = seam_side(c, a, k) ? c->hi[k] : c->lo[k];
        } else if (fa != face || fb != face)
            continue;
        double q[4], on_face[4];
        ic_certificate_wrap(c, z, q);
        q[k] = face;
        memcpy(on_face, q, sizeof on_face);
        /* near: a tenth of a box's half width, taken in search coordinates
         * (parameters of about unit speed; the box is a hole wherever it
         * lands, so this only decides whether it lands on the touch) */
        if (!ic_certify_project(c, q, k) && !ic_certify_project(c, q, k) &&
            !ic_certify_near_curve(c, q, 0.1 * c->singular_half)) {
            /* where the face's Jacobian is singular at the touch itself
             * Newton's method stops: the sample there will do */
            memcpy(q, on_face, sizeof q);
            if (!ic_certify_near_curve(c, q, 0.1 * c->singular_half))
                continue;
        }
        int near = 1;
        double w[4];
        ic_certificate_wrap(c, z, w);
        for (int j = 0; j < dim && near; j++) /* q[k] is on the face (either side of a seam) */
            near = j == k || (fabs(q[j] - w[j]) <= IC_CERTIFY_TOUCH_NEAR * (c->hi[j] - c->lo[j]) &&
                              q[j] >= c->lo[j] && q[j] <= c->hi[j]);
        if (near && faces_reached(c, q, xyz) >= 0)
            return 1;
    }
    return 0;
}

/* Point i of curve cv meets the boundary other than across one face: a
 * point on two faces or seams at once (a corner; two sheets' seams met
 * together), or a point within the curve that touches a face or a seam, at
 * the sample or between samples. The image of the end, of the
 * touch or (where Newton's method finds none) of the sample on a face, in
 * xyz. */
static int meets_boundary(const ic_certificate *c, const ic_certify_curve *cv, int i,
                          double xyz[3])
{
    const int end = !cv->closed && (i == 0 || i == cv->npoints - 1);
    const double *z = cv->z + (size_t)i * (size_t)c->dim;
    const int faces = faces_reached(c, z, xyz);
    if (faces < 0)
        return 0;
    if (faces + seams_reached(c, z) >= 2) /* two faces or seams at once: a cell's edge */
        return 1;
    return !end && (touch_near(c, cv, i, xyz) || faces >= 1);
}

/* The face across coordinate k on which z lies (within
 * IC_CERTIFY_END_REACH), 0 or 1 in *side: 1 when it lies on one. */
static int on_face_k(const ic_certificate *c, const double *z, int k, int *side)
{
    const double reach = IC_CERTIFY_END_REACH * (c->hi[k] - c->lo[k]);
    if (c->periodic[k])
        return 0;
    *side = fabs(z[k] - c->hi[k]) <= reach;
    return *side || fabs(z[k] - c->lo[k]) <= reach;
}

/* Ends a and b lie on one face of the region within IC_CERTIFY_TOUCH_NEAR
 * of each other: where a curve touches a domain edge the tracer stops on
 * it and starts again, and the touch between them (found by Newton's
 * method on the face from their midpoint, else the midpoint) goes in xyz. */
static int ends_meet(const ic_certificate *c, const double *a, const double *b, double xyz[3])
{
    for (int k = 0; k < c->dim; k++) {
        int sa, sb;
        if (!on_face_k(c, a, k, &sa) || !on_face_k(c, b, k, &sb) || sa != sb)
            continue;
        double q[4], keep[4];
        int near = 1;
        for (int j = 0; j < c->dim; j++) {
            near = near && fabs(a[j] - b[j]) <= IC_CERTIFY_TOUCH_NEAR * (c->hi[j] - c->lo[j]);
            q[j] = 0.5 * (a[j] + b[j]);
        }
        if (!near)
            continue;
        q[k] = sa ? c->hi[k] : c->lo[k];
        memcpy(keep, q, sizeof keep);
        if (!ic_certify_project(c, q, k) && !ic_certify_project(c, q, k))
            memcpy(q, keep, sizeof q);
        return faces_reached(c, q, xyz) >= 0;
    }
    return 0;
}

/* Boxes where two curve ends meet on a face (ends_meet). */
static int meeting_ends(ic_certificate *c, const ic_certify_curve *curves, int ncurves)
{
    const int dim = c->dim;
    for (int k = 0; k < ncurves * 2; k++)
        for (int l = k + 1; l < ncurves * 2; l++) {
            const ic_certify_curve *p = &curves[k / 2], *q = &curves[l / 2];
            if (p->closed || q->closed || p->tangential || q->tangential || p->npoints < 1 ||
                q->npoints < 1 || c->summary.corners >= IC_CERTIFY_MAX_CORNERS)
                continue;
            const double *a = p->z + (size_t)(k % 2 ? p->npoints - 1 : 0) * (size_t)dim;
            const double *b = q->z + (size_t)(l % 2 ? q->npoints - 1 : 0) * (size_t)dim;
            double xyz[3];
            if (!ends_meet(c, a, b, xyz) || boxed(c, xyz))
                continue;
            if (!add_point(c, xyz))
                return -1;
            c->summary.corners++;
        }
    return 1;
}

int ic_certificate_add_corner_ends(ic_certificate *c, const ic_certify_curve *curves,
                                   int ncurves)
{
    if (c->singular_half == 0.0)
        return 1; /* no boxes at all: the cover refuses there */
    for (int k = 0; k < ncurves; k++) {
        const ic_certify_curve *cv = &curves[k];
        for (int i = 0; !cv->tangential && i < cv->npoints; i++) {
            double xyz[3];
            if (c->summary.corners >= IC_CERTIFY_MAX_CORNERS || !meets_boundary(c, cv, i, xyz) ||
                boxed(c, xyz))
                continue;
            if (!add_point(c, xyz))
                return -1;
            c->summary.corners++;
        }
    }
    return meeting_ends(c, curves, ncurves);
}
