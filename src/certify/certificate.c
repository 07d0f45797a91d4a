/* A certificate's storage, its refusals and its point location
 * (certificate.h). */
#include "certificate.h"
#include "system.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Points along each line of the region on which a coordinate's length in
 * space is measured: the polylines' chords, 9 lines of a sheet's other
 * parameter (81 positions a coordinate). */
#define IC_CERTIFY_SPAN_SAMPLES 9

/* The sheet and its parameter that search coordinate k is: -1 for a point
 * of space (x, y, z over the box, its own length). */
static int coordinate_sheet(const ic_pairing *pg, int dim, int k, int *param)
{
    if (pg->kind->nparams == 0)
        return -1;
    *param = k % 2;
    if (dim == 2)
        return pg->P;
    return k < 2 || !pg->S[1] ? 0 : 1;
}

/* The length in space of coordinate k across the region: the longest
 * polyline through IC_CERTIFY_SPAN_SAMPLES points along it, over as many
 * values of the sheet's other parameter; 0 where nothing evaluates. */
static double coordinate_span(const ic_certificate *c, int k)
{
    int param = 0;
    const int sheet = coordinate_sheet(c->pg, c->dim, k, &param);
    if (sheet < 0)
        return c->hi[k] - c->lo[k];
    const int other = param ? k - 1 : k + 1;
    const int N = IC_CERTIFY_SPAN_SAMPLES;
    double longest = 0.0;
    for (int j = 0; j < N; j++) {
        double at[2], prev[3], len = 0.0;
        at[1 - param] = c->lo[other] + (c->hi[other] - c->lo[other]) * j / (N - 1);
        int have = 0;
        for (int i = 0; i < N; i++) {
            double xyz[3];
            ic_error e;
            at[param] = c->lo[k] + (c->hi[k] - c->lo[k]) * i / (N - 1);
            if (ic_surface_eval(c->pg->S[sheet], xyz, at, &e) != IC_OK) {
                have = 0;
                continue;
            }
            if (have)
                len += hypot(hypot(xyz[0] - prev[0], xyz[1] - prev[1]), xyz[2] - prev[2]);
            memcpy(prev, xyz, sizeof prev);
            have = 1;
        }
        if (isfinite(len))
            longest = fmax(longest, len);
    }
    return longest;
}

/* Coordinates whose lengths in space differ by at most this factor are
 * split by their widths relative to the region, as if equal (the covers of
 * every bundled case but two; a torus against a plane by lengths in space
 * took twice the cells); farther apart, by their lengths in space. */
#define IC_CERTIFY_SPAN_RATIO 8.0

static void set_spans(ic_certificate *c)
{
    double lo = INFINITY, hi = 0.0;
    for (int k = 0; k < c->dim; k++) {
        c->span[k] = coordinate_span(c, k);
        lo = fmin(lo, c->span[k]), hi = fmax(hi, c->span[k]);
    }
    c->by_span = hi > IC_CERTIFY_SPAN_RATIO * lo && isfinite(hi);
}

double ic_certificate_rel(const ic_certificate *c, int k, double d, int floor)
{
    const double w = c->hi[k] - c->lo[k];
    if (!c->by_span)
        return d / w;
    double longest = 0.0;
    for (int j = 0; j < c->dim; j++)
        longest = fmax(longest, c->span[j]);
    const double least = floor || !(c->span[k] > 0.0) ? IC_CERTIFY_SPAN_FLOOR * longest : 0.0;
    return d / w * (fmax(c->span[k], least) / longest);
}

/* A self-intersection's periods cut elsewhere than at the domain's start,
 * and the second preimage's (p, q) elsewhere than the first's (u, v): the
 * double curves of a symmetric surface (a surface of revolution, a torus
 * with a figure-eight section) often run along v = 0, in the seam, and have
 * both preimages at the same u, so with the periods cut at the domain's
 * start, or both at the same place, the curve lies in a face of the region
 * or crosses two faces at once, on an edge, where no crossing can be
 * isolated. A period may be cut anywhere: the sheets are evaluated across
 * their seam (a NURBS net's interval and point evaluations wrap a periodic
 * parameter). */
static void offset_seams(ic_certificate *c)
{
    for (int k = 0; k < 4; k++) {
        if (!c->periodic[k])
            continue;
        const double f = k < 2 ? IC_CERTIFY_SELF_SEAM_OFFSET : 2 * IC_CERTIFY_SELF_SEAM_OFFSET;
        const double d = f * (c->hi[k] - c->lo[k]);
        c->lo[k] += d, c->hi[k] += d;
    }
}

double ic_certificate_origin(const ic_certificate *c, int k)
{
    return ic_frame_search_origin(&c->pg->frame, c->dim, k);
}

ic_certificate *ic_certificate_new(const ic_pairing *pg, const double box[3][2], int has_box,
                                   ic_error *err)
{
    ic_certificate *c = calloc(1, sizeof *c);
    if (!c) {
        ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory certifying");
        return NULL;
    }
    c->pg = pg;
    c->dim = pg->kind->dim;
    c->m = c->dim - 1;
    c->has_box = has_box;
    if (has_box)
        memcpy(c->box, box, sizeof c->box);
    const ic_status st = pg->kind->region(pg, box, has_box, c->lo, c->hi, c->periodic, err);
    if (st == IC_OK && pg->kind == &ic_pairing_self)
        offset_seams(c);
    if (st != IC_OK || ic_certificate_add_cell(c, c->lo, c->hi) < 0) {
        if (err && err->code == IC_OK)
            ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory certifying");
        ic_certificate_free(c);
        return NULL;
    }
    set_spans(c);
    return c;
}

void ic_certificate_free(ic_certificate *c)
{
    if (!c)
        return;
    free(c->cells);
    free(c->cross);
    free(c->face_stack);
    free(c->chunk_box);
    free(c->singular);
    free(c->singular_scale);
    free(c->box_cells);
    free(c->box_smooth);
    free(c);
}

/* Room for one more element of size `size` in *items (count n, room *cap). */
static int grow(void **items, long n, long *cap, size_t size)
{
    if (n < *cap)
        return 1;
    const long room = *cap ? 2 * *cap : 64;
    void *p = realloc(*items, (size_t)room * size);
    if (!p)
        return 0;
    *items = p;
    *cap = room;
    return 1;
}

/* Points per coordinate at which the region's image is sampled for its
 * size: 9^4 = 6561 positions at most, microseconds each. */
#define IC_CERTIFY_SIZE_SAMPLES 9

/* The diagonal of the box around the images of a grid of points of the
 * region (corners included); 0 when none has a finite image. */
static double sampled_size(const ic_certificate *c)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    long total = 1;
    for (int k = 0; k < c->dim; k++)
        total *= IC_CERTIFY_SIZE_SAMPLES;
    for (long i = 0; i < total; i++) {
        double z[4], xyz[3];
        long rest = i;
        for (int k = 0; k < c->dim; k++, rest /= IC_CERTIFY_SIZE_SAMPLES) {
            const double t =
                (double)(rest % IC_CERTIFY_SIZE_SAMPLES) / (IC_CERTIFY_SIZE_SAMPLES - 1);
            z[k] = t == 1.0 ? c->hi[k] : c->lo[k] + t * (c->hi[k] - c->lo[k]);
        }
        ic_error e;
        if (c->pg->kind->position(c->pg, z, xyz, &e) != IC_OK)
            continue;
        for (int k = 0; k < 3; k++)
            if (isfinite(xyz[k]))
                lo[k] = fmin(lo[k], xyz[k]), hi[k] = fmax(hi[k], xyz[k]);
    }
    double d = 0.0;
    for (int k = 0; k < 3; k++)
        d = hi[k] >= lo[k] ? hypot(d, hi[k] - lo[k]) : d;
    return isfinite(d) ? d : 0.0;
}

/* The region's size in space: the diagonal of its image, from its
 * enclosure and from samples, the smaller (an enclosure may be far wider
 * than the image: a quotient whose denominator nearly vanishes in the
 * region; the singular boxes and tubes, not examined, must stay small);
 * 0 when the image has no enclosure. */
static double region_size(const ic_certificate *c)
{
    ic_interval X[4], img[3];
    for (int k = 0; k < c->dim; k++)
        X[k] = (ic_interval){c->lo[k], c->hi[k]};
    if (!ic_certify_image(c->pg, X, img))
        return 0.0;
    double d = 0.0;
    for (int k = 0; k < 3; k++)
        d = hypot(d, img[k].hi - img[k].lo);
    const double sampled = sampled_size(c);
    if (sampled > 0.0)
        d = fmin(d, sampled);
    return d > 0.0 && isfinite(d) ? d : 0.0;
}

int ic_certificate_set_singular(ic_certificate *c, const double (*xyz)[3], const double *scale,
                                int n)
{
    c->nsingular = 0, c->npoles = 0;
    const double d = region_size(c);
    c->singular_half = IC_CERTIFY_SINGULAR_HALF * d;
    if (d == 0.0)
        return n == 0;
    ic_certificate_find_poles(c);
    free(c->singular), free(c->singular_scale), free(c->box_cells), free(c->box_smooth);
    const size_t room = (size_t)n + (size_t)c->npoles + 1;
    c->singular = malloc(room * sizeof *c->singular);
    c->singular_scale = malloc(room * sizeof *c->singular_scale);
    c->box_cells = calloc(room, sizeof *c->box_cells);
    c->box_smooth = calloc(room, sizeof *c->box_smooth);
    if (!c->singular || !c->singular_scale || !c->box_cells || !c->box_smooth)
        return -1;
    if (n > 0)
        memcpy(c->singular, xyz, (size_t)n * sizeof *c->singular);
    for (int p = 0; p < c->npoles; p++)
        memcpy(c->singular[n + p], c->poles[p].xyz, sizeof c->singular[0]);
    for (int p = 0; p < n + c->npoles; p++)
        c->singular_scale[p] = scale && p < n ? scale[p] : 1.0;
    c->summary.poles = c->npoles;
    c->nsingular = n + c->npoles;
    return 1;
}

int ic_certificate_tube_size(ic_certificate *c)
{
    const double d = region_size(c);
    c->tube_half = IC_CERTIFY_TUBE_HALF * d;
    return d > 0.0;
}

int ic_certificate_cell_image(const ic_certificate *c, long i, ic_interval img[3])
{
    ic_interval X[4];
    for (int k = 0; k < c->dim; k++)
        X[k] = (ic_interval){c->cells[i].lo[k], c->cells[i].hi[k]};
    return ic_certify_image(c->pg, X, img);
}

int ic_certificate_against_box(const ic_certificate *c, const ic_interval *X)
{
    ic_interval xyz[3];
    if (!ic_certify_image(c->pg, X, xyz))
        return -1;
    int inside = 1;
    for (int k = 0; k < 3; k++) {
        if (xyz[k].hi < c->box[k][0] || xyz[k].lo > c->box[k][1])
            return 1;
        if (xyz[k].lo < c->box[k][0] || xyz[k].hi > c->box[k][1])
            inside = 0;
    }
    return inside ? 0 : -1;
}

/* The singular point whose box holds img (the first), or -1. */
static int image_in_singular_box(const ic_certificate *c, const ic_interval img[3])
{
    for (int s = 0; s < c->nsingular; s++) {
        const double *p = c->singular[s], h = c->singular_half * c->singular_scale[s];
        int in = 1;
        for (int k = 0; k < 3 && in; k++)
            in = img[k].lo >= p[k] - h && img[k].hi <= p[k] + h;
        if (in)
            return s;
    }
    return -1;
}

/* Either sheet's image will do: where F = 0 the two are one point (a
 * sheet's pole strip is thin only in its own parameters). */
int ic_certificate_singular_box(const ic_certificate *c, long i)
{
    ic_interval img[3];
    if (c->nsingular == 0)
        return -1;
    int s = ic_certificate_cell_image(c, i, img) ? image_in_singular_box(c, img) : -1;
    if (s >= 0 || c->dim != 4)
        return s;
    ic_interval pq[2] = {{c->cells[i].lo[2], c->cells[i].hi[2]},
                         {c->cells[i].lo[3], c->cells[i].hi[3]}};
    return ic_surface_eval_interval(c->pg->S[1], img, pq, NULL) == IC_OK
               ? image_in_singular_box(c, img)
               : -1;
}

int ic_certificate_refute_smooth(ic_certificate *c, int nclaimed)
{
    for (int s = 0; s < nclaimed && s < c->nsingular; s++) {
        if (c->box_cells[s] > c->box_smooth[s])
            continue;
        double p[3];
        ic_frame_shown(&c->pg->frame, c->singular[s], p);
        ic_certificate_refuse(c, "singular point %d (of the result's) near (%.9g, %.9g, %.9g) is "
                                 "none: %s",
                              s, p[0], p[1], p[2],
                              c->box_cells[s] ? "the intersection is proven smooth all through "
                                                "its box"
                                              : "no cell of the cover lies in its box (the "
                                                "cells about it are proven empty or smooth)");
        return 0;
    }
    return 1;
}

long ic_certificate_add_cell(ic_certificate *c, const double *lo, const double *hi)
{
    if (!grow((void **)&c->cells, c->ncells, &c->capc, sizeof *c->cells))
        return -1;
    ic_cell *cell = &c->cells[c->ncells];
    memset(cell, 0, sizeof *cell);
    memcpy(cell->lo, lo, (size_t)c->dim * sizeof *lo);
    memcpy(cell->hi, hi, (size_t)c->dim * sizeof *hi);
    cell->kind = IC_CELL_REFUSED;
    cell->child[0] = cell->child[1] = -1;
    return c->ncells++;
}

long ic_certificate_add_crossing(ic_certificate *c, const ic_crossing *x)
{
    if (!grow((void **)&c->cross, c->ncross, &c->capx, sizeof *c->cross))
        return -1;
    c->cross[c->ncross] = *x;
    return c->ncross++;
}

void ic_certificate_count(ic_certificate *c, ic_cell_kind kind)
{
    ic_certify_summary *s = &c->summary;
    s->empty += kind == IC_CELL_EMPTY;
    s->outside += kind == IC_CELL_OUTSIDE;
    s->diagonal += kind == IC_CELL_DIAGONAL;
    s->regular += kind == IC_CELL_REGULAR;
    s->singular += kind == IC_CELL_SINGULAR;
    s->tangential += kind == IC_CELL_TANGENTIAL;
    s->refused += kind == IC_CELL_REFUSED;
}

void ic_certificate_refuse(ic_certificate *c, const char *fmt, ...)
{
    c->summary.accepted = 0;
    if (c->summary.reason[0])
        return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(c->summary.reason, sizeof c->summary.reason, fmt, ap);
    va_end(ap);
}

void ic_certificate_wrap(const ic_certificate *c, const double *z, double *w)
{
    for (int k = 0; k < c->dim; k++) {
        w[k] = z[k];
        if (c->periodic[k] && !(z[k] >= c->lo[k] && z[k] <= c->hi[k])) {
            const double T = c->hi[k] - c->lo[k];
            w[k] = c->lo[k] + fmod(z[k] - c->lo[k], T);
            if (w[k] < c->lo[k])
                w[k] += T;
            if (w[k] >= c->hi[k])
                w[k] = c->lo[k];
        }
    }
}

long ic_certificate_locate(const ic_certificate *c, const double *z, int j, int dir)
{
    for (int k = 0; k < c->dim; k++)
        if (!(z[k] >= c->lo[k] && z[k] <= c->hi[k]))
            return -1;
    long i = 0;
    while (c->cells[i].kind == IC_CELL_SPLIT) {
        const ic_cell *n = &c->cells[i];
        const double x = z[n->axis];
        const int upper = n->axis == j && x == n->at ? dir > 0 : x >= n->at;
        i = n->child[upper];
    }
    return i;
}
