/*
 * A spatial hash of the traced curves' segments, so that "does a traced
 * curve pass near x?" costs what is near x, not the number of curves (the
 * egg-crate of the trust issue has 7,938 loops, and every open cell asks).
 * Each segment is entered in every grid cell that its box, widened by its
 * sagitta, touches; a query visits the cells its ball touches, or, when
 * that ball is too large for the grid, falls back to every curve.
 */
#include "result.h"
#include "curve_index.h"
#include "polyline.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* cells a query may visit before the plain scan of every curve is cheaper */
#define MAX_QUERY_CELLS 4096
/* grid coordinates beyond this are not hashed (a far or huge box) */
#define MAX_COORD 1e9

typedef struct {
    int next;       /* the next entry of the bucket, -1 at its end */
    int curve, seg; /* the segment: points seg and seg + 1 of curve */
    long key[3];    /* its grid cell */
} entry;

struct ic_curve_index {
    double h; /* grid cell size */
    int *head, nbuckets;
    entry *e;
    int n, cap;
    int unhashed; /* a segment lies beyond the grid: queries scan everything */
};

ic_curve_index *ic_curve_index_new(double h)
{
    ic_curve_index *ix = calloc(1, sizeof *ix);
    if (!ix)
        return NULL;
    ix->h = h > 0 && isfinite(h) ? h : 1.0;
    ix->nbuckets = 1 << 14;
    ix->head = malloc((size_t)ix->nbuckets * sizeof *ix->head);
    if (!ix->head) {
        free(ix);
        return NULL;
    }
    memset(ix->head, 0xff, (size_t)ix->nbuckets * sizeof *ix->head);
    return ix;
}

void ic_curve_index_free(ic_curve_index *ix)
{
    if (!ix)
        return;
    free(ix->head);
    free(ix->e);
    free(ix);
}

void ic_curve_index_clear(ic_curve_index *ix)
{
    memset(ix->head, 0xff, (size_t)ix->nbuckets * sizeof *ix->head);
    ix->n = 0;
    ix->unhashed = 0;
}

static unsigned bucket(const ic_curve_index *ix, const long *k)
{
    const unsigned long hsh = (unsigned long)k[0] * 73856093ul ^ (unsigned long)k[1] * 19349663ul ^
                              (unsigned long)k[2] * 83492791ul;
    return (unsigned)(hsh & (unsigned long)(ix->nbuckets - 1));
}

/* The grid range of [lo, hi]; 0 when it is out of the hashed range. */
static int cell_range(const ic_curve_index *ix, const double *lo, const double *hi, long *a,
                      long *b)
{
    for (int k = 0; k < 3; k++) {
        const double fa = floor(lo[k] / ix->h), fb = floor(hi[k] / ix->h);
        if (!(fabs(fa) < MAX_COORD && fabs(fb) < MAX_COORD))
            return 0;
        a[k] = (long)fa, b[k] = (long)fb;
    }
    return 1;
}

static int put(ic_curve_index *ix, int curve, int seg, const long *key)
{
    if (ix->n == ix->cap) {
        const int cap = ix->cap ? 2 * ix->cap : 1024;
        entry *p = realloc(ix->e, (size_t)cap * sizeof *p);
        if (!p)
            return -1;
        ix->e = p;
        ix->cap = cap;
    }
    entry *en = &ix->e[ix->n];
    en->curve = curve, en->seg = seg;
    memcpy(en->key, key, sizeof en->key);
    const unsigned bk = bucket(ix, key);
    en->next = ix->head[bk];
    ix->head[bk] = ix->n++;
    return 0;
}

int ic_curve_index_add(ic_curve_index *ix, int curve, const ic_trace_point *pts, int n)
{
    for (int s = 0; s + 1 < n || (n == 1 && s == 0); s++) {
        const ic_trace_point *p = &pts[s], *q = &pts[n == 1 ? 0 : s + 1];
        const double w = ic_trace_segment_sagitta(p, q);
        double lo[3], hi[3];
        for (int k = 0; k < 3; k++) {
            lo[k] = fmin(p->xyz[k], q->xyz[k]) - w;
            hi[k] = fmax(p->xyz[k], q->xyz[k]) + w;
        }
        long a[3], b[3], key[3];
        if (!cell_range(ix, lo, hi, a, b)) {
            ix->unhashed = 1; /* queries scan every curve */
            return 0;
        }
        for (key[0] = a[0]; key[0] <= b[0]; key[0]++)
            for (key[1] = a[1]; key[1] <= b[1]; key[1]++)
                for (key[2] = a[2]; key[2] <= b[2]; key[2]++)
                    if (put(ix, curve, s, key) != 0)
                        return -1;
        if (n == 1)
            break;
    }
    return 0;
}

int ic_curve_index_near(ic_curve_index *ix, const ic_trace_result *r, const double *x,
                        double bound)
{
    double lo[3], hi[3];
    for (int k = 0; k < 3; k++)
        lo[k] = x[k] - bound, hi[k] = x[k] + bound;
    long a[3], b[3], key[3];
    if (ix->unhashed || !cell_range(ix, lo, hi, a, b) ||
        (double)(b[0] - a[0] + 1) * (double)(b[1] - a[1] + 1) * (double)(b[2] - a[2] + 1) >
            MAX_QUERY_CELLS)
        return -1;
    for (key[0] = a[0]; key[0] <= b[0]; key[0]++)
        for (key[1] = a[1]; key[1] <= b[1]; key[1]++)
            for (key[2] = a[2]; key[2] <= b[2]; key[2]++)
                for (int i = ix->head[bucket(ix, key)]; i >= 0; i = ix->e[i].next) {
                    const entry *en = &ix->e[i];
                    if (memcmp(en->key, key, sizeof key) != 0 || en->curve >= r->ncurves)
                        continue;
                    const ic_trace_curve *c = &r->curves[en->curve];
                    const ic_trace_point *p = &c->points[en->seg];
                    const ic_trace_point *q = c->npoints > 1 ? p + 1 : p;
                    if (ic_trace_segment_distance(p, q, x) <= bound)
                        return 1;
                }
    return 0;
}
