/* The traced curves' passages through the singular boxes of the points the
 * result reports (match.h): the cover does not examine a singular box, so
 * a curve may run through one unproven; a point's type bounds how many
 * curve pieces meet it (2 per branch through a branch point or a tacnode,
 * the 2 half-branches of a cusp, none at an isolated contact). A box met
 * more often holds more than its point: a loop cut where it passes an
 * isolated contact, say. */
#include "match.h"

#include <math.h>
#include <stdlib.h>

int ic_certify_passages_allowed(ic_point_type type, int nbranches, int approximate)
{
    if (approximate)
        return -1;
    switch (type) {
    case IC_POINT_ISOLATED_CONTACT: return 0;
    case IC_POINT_CUSP: return nbranches; /* half-branches */
    case IC_POINT_BRANCH:
    case IC_POINT_TACNODE: return 2 * nbranches;
    default: return -1; /* higher-order contacts, surface singular points: not bounded */
    }
}

static int in_box(const double xyz[3], const double p[3], double h)
{
    return fabs(xyz[0] - p[0]) <= h && fabs(xyz[1] - p[1]) <= h && fabs(xyz[2] - p[2]) <= h;
}

/* How often the curve with images xyz[0..n-1] enters or leaves the box of
 * half width h about p: 2 per run of points inside, less the curve's ends
 * in the run; a closed curve's runs cyclic. */
static int passages(const double (*xyz)[3], int n, int closed, const double p[3], double h)
{
    int start = -1; /* a point outside, where a closed curve's runs begin */
    for (int i = 0; i < n && start < 0; i++)
        if (!in_box(xyz[i], p, h))
            start = i;
    if (start < 0)
        return 0; /* the whole curve in the box */
    if (!closed)
        start = 0;
    int count = 0, inside = 0;
    for (int step = 0; step < n + (closed ? 1 : 0); step++) { /* closed: back to start */
        const int i = (start + step) % n, in = in_box(xyz[i], p, h);
        if (in && !inside)
            count += closed || i > 0 ? 1 : 0; /* entered; an open curve's start is an end */
        if (!in && inside)
            count++;
        inside = in;
    }
    return count; /* an open curve ending inside: that end is not a passage */
}

int ic_certify_passages(ic_certificate *c, const ic_certify_curve *curves, int ncurves,
                        const int *allowed, int nallowed)
{
    int *met = calloc((size_t)nallowed + 1, sizeof *met);
    if (!met)
        return -1;
    for (int k = 0; k < ncurves; k++) {
        const ic_certify_curve *cv = &curves[k];
        if (cv->tangential)
            continue; /* in its tube, which may pass a singular point */
        double(*xyz)[3] = malloc(((size_t)cv->npoints + 1) * sizeof *xyz);
        if (!xyz) {
            free(met);
            return -1;
        }
        int n = 0;
        for (int i = 0; i < cv->npoints; i++) {
            ic_error e;
            if (c->pg->kind->position(c->pg, cv->z + (size_t)i * (size_t)c->dim, xyz[n], &e) ==
                IC_OK)
                n++;
        }
        for (int s = 0; s < nallowed && s < c->nsingular; s++)
            if (allowed[s] >= 0)
                met[s] += passages((const double(*)[3])xyz, n, cv->closed, c->singular[s],
                                   c->singular_half * c->singular_scale[s]);
        free(xyz);
    }
    for (int s = 0; s < nallowed && s < c->nsingular; s++) {
        double shown[3];
        ic_frame_shown(&c->pg->frame, c->singular[s], shown);
        if (allowed[s] >= 0 && met[s] > allowed[s])
            ic_certificate_refuse(c,
                                  "the box of singular point %d (of the result's) near (%.9g, "
                                  "%.9g, %.9g) is met %d times by the curves, more than its "
                                  "type allows (%d)",
                                  s + 1, shown[0], shown[1], shown[2], met[s], allowed[s]);
    }
    free(met);
    return 1;
}
