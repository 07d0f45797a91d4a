/*
 * Tangential tubes (certificate.h): a tangential curve the result reports
 * gets a tube of radius IC_CERTIFY_TUBE_HALF of the region's size about
 * its polyline, as a singular point gets a box. A cell that is neither
 * empty nor regular and whose image lies inside a tube is a tangential
 * cell: along a tangential curve the surfaces touch, J loses rank and no
 * interval test can tell the curve from a near miss, so what the tube
 * holds is the tracer's (docs/tracing.md, "Tangential tubes"); everything
 * outside it is proven as elsewhere. A tube must not come back on itself
 * or meet another: a tangential curve traced twice over a stretch (an
 * overlap) would otherwise go unseen.
 */
#include "certificate.h"
#include "system.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Segments per chunk of a tube: a chunk's box lets a cell far from it skip
 * its segments. */
#define IC_CERTIFY_TUBE_CHUNK 32
/* Two stretches of the tubes closer than this many radii, and farther
 * apart along the curve than IC_CERTIFY_TUBE_APART radii, overlap. */
#define IC_CERTIFY_TUBE_NEAR 2.0
#define IC_CERTIFY_TUBE_APART 8.0

/* The distance from p to the segment a..b. */
static double to_segment(const double *p, const double *a, const double *b)
{
    double ab[3], ap[3], t = 0.0, l2 = 0.0;
    for (int k = 0; k < 3; k++) {
        ab[k] = b[k] - a[k], ap[k] = p[k] - a[k];
        t += ab[k] * ap[k], l2 += ab[k] * ab[k];
    }
    t = l2 > 0.0 ? fmin(1.0, fmax(0.0, t / l2)) : 0.0;
    double d = 0.0;
    for (int k = 0; k < 3; k++)
        d = hypot(d, ap[k] - t * ab[k]);
    return d;
}

/* The point i of tube t (closed tubes wrap). */
static const double *tube_point(const ic_certify_tube *t, int i)
{
    return t->xyz + 3 * (size_t)(i % t->n);
}

static int segments(const ic_certify_tube *t) { return t->closed ? t->n : t->n - 1; }

int ic_certificate_set_tubes(ic_certificate *c, const ic_certify_tube *tubes, int n)
{
    c->tubes = tubes, c->ntubes = 0;
    if (n == 0)
        return 1;
    if (!ic_certificate_tube_size(c))
        return 0;
    c->ntubes = n;
    long chunks = 0;
    for (int k = 0; k < n; k++)
        chunks += (segments(&tubes[k]) + IC_CERTIFY_TUBE_CHUNK - 1) / IC_CERTIFY_TUBE_CHUNK;
    free(c->chunk_box);
    c->chunk_box = malloc((size_t)(chunks + 1) * sizeof *c->chunk_box);
    if (!c->chunk_box)
        return -1;
    long at = 0;
    for (int k = 0; k < n; k++)
        for (int s0 = 0; s0 < segments(&tubes[k]); s0 += IC_CERTIFY_TUBE_CHUNK, at++) {
            double *b = c->chunk_box[at];
            for (int j = 0; j < 3; j++)
                b[j] = HUGE_VAL, b[3 + j] = -HUGE_VAL;
            const int end = s0 + IC_CERTIFY_TUBE_CHUNK < segments(&tubes[k])
                                ? s0 + IC_CERTIFY_TUBE_CHUNK
                                : segments(&tubes[k]);
            for (int s = s0; s <= end; s++)
                for (int j = 0; j < 3; j++) {
                    const double x = tube_point(&tubes[k], s)[j];
                    b[j] = fmin(b[j], x), b[3 + j] = fmax(b[3 + j], x);
                }
        }
    return 1;
}

int ic_certificate_in_tube(const ic_certificate *c, long i)
{
    ic_interval img[3];
    if (c->ntubes == 0 || !ic_certificate_cell_image(c, i, img))
        return 0;
    double mid[3], rho = 0.0;
    for (int k = 0; k < 3; k++) {
        mid[k] = 0.5 * (img[k].lo + img[k].hi);
        rho = hypot(rho, 0.5 * (img[k].hi - img[k].lo));
    }
    /* every point of the image within the radius of one segment */
    const double reach = c->tube_half - rho;
    if (!(reach > 0.0))
        return 0;
    long at = 0;
    for (int k = 0; k < c->ntubes; k++) {
        const ic_certify_tube *t = &c->tubes[k];
        for (int s0 = 0; s0 < segments(t); s0 += IC_CERTIFY_TUBE_CHUNK, at++) {
            const double *b = c->chunk_box[at];
            int near = 1;
            for (int j = 0; j < 3 && near; j++)
                near = mid[j] >= b[j] - reach && mid[j] <= b[3 + j] + reach;
            for (int s = s0; near && s < s0 + IC_CERTIFY_TUBE_CHUNK && s < segments(t); s++)
                if (to_segment(mid, tube_point(t, s), tube_point(t, s + 1)) <= reach)
                    return 1;
        }
    }
    return 0;
}

/* Arc length along tube t from point i to point j (the short way round on a
 * closed one), from the cumulative lengths `at`. */
static double along(const ic_certify_tube *t, const double *at, int i, int j)
{
    const double d = fabs(at[j] - at[i]);
    return t->closed ? fmin(d, at[t->n] - d) : d;
}

/* Cumulative chord lengths of tube t (n + 1 entries: the last one closes a
 * closed tube). */
static void cumulate(const ic_certify_tube *t, double *at)
{
    at[0] = 0.0;
    for (int i = 1; i <= t->n; i++) {
        const double *a = tube_point(t, i - 1), *b = tube_point(t, i);
        at[i] = at[i - 1] + hypot(hypot(b[0] - a[0], b[1] - a[1]), b[2] - a[2]);
    }
}

/* Points p of tube a and q of tube b (a == b: far apart along it) closer
 * than IC_CERTIFY_TUBE_NEAR radii: 1 and the refusal. */
static int overlap(ic_certificate *c, int a, int b, const double *at_a)
{
    const ic_certify_tube *ta = &c->tubes[a], *tb = &c->tubes[b];
    const double near = IC_CERTIFY_TUBE_NEAR * c->tube_half;
    const double apart = IC_CERTIFY_TUBE_APART * c->tube_half;
    for (int i = 0; i < ta->n; i++)
        for (int j = a == b ? i + 1 : 0; j < tb->n; j++) {
            const double *p = tube_point(ta, i), *q = tube_point(tb, j);
            if (fabs(p[0] - q[0]) > near || fabs(p[1] - q[1]) > near || fabs(p[2] - q[2]) > near)
                continue;
            if (hypot(hypot(p[0] - q[0], p[1] - q[1]), p[2] - q[2]) > near)
                continue;
            if (a == b && along(ta, at_a, i, j) <= apart)
                continue;
            double shown[3];
            ic_frame_shown(&c->pg->frame, p, shown);
            ic_certificate_refuse(c, "tangential curve %d %s near (%.9g, %.9g, %.9g): traced "
                                     "twice over there, or two curves within the tube",
                                  a, a == b ? "comes back on itself" : "meets another", shown[0],
                                  shown[1], shown[2]);
            return 1;
        }
    return 0;
}

int ic_certificate_tubes_apart(ic_certificate *c)
{
    for (int a = 0; a < c->ntubes; a++) {
        double *at = malloc((size_t)(c->tubes[a].n + 1) * sizeof *at);
        if (!at)
            return -1;
        cumulate(&c->tubes[a], at);
        int hit = 0;
        for (int b = a; b < c->ntubes && !hit; b++)
            hit = overlap(c, a, b, at);
        free(at);
        if (hit)
            return 0;
    }
    return 1;
}
