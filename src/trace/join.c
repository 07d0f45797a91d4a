/* Joining traced curves through the singular points at their ends, and
 * dropping arcs traced twice. */
#include "trace_internal.h"
#include "common/vec3.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Reverses a curve in place: order, orientation (t, b) and arc length. */
static void reverse_curve(ic_trace_point *p, int n)
{
    const double L = p[n - 1].s + p[0].s;
    for (int i = 0; i < n / 2; i++) {
        const ic_trace_point tmp = p[i];
        p[i] = p[n - 1 - i];
        p[n - 1 - i] = tmp;
    }
    for (int i = 0; i < n; i++) {
        ic_scale3(p[i].t, p[i].t, -1.0);
        ic_scale3(p[i].b, p[i].b, -1.0);
        p[i].s = L - p[i].s;
    }
}

/* Joins curves through the tangential points at their ends where a branch
 * continues smoothly: the outgoing directions of the two ends are opposite.
 * A curve joined to itself is closed. */
ic_status ic_trace_join_curves(ic_trace_result *r, double shape_tol)
{
    for (int changed = 1; changed;) {
        changed = 0;
        for (int a = 0; a < r->ncurves && !changed; a++)
            for (int ea = 0; ea < 2 && !changed; ea++) {
                const int k = r->at[a][ea];
                if (k < 0 || r->curves[a].closed)
                    continue;
                for (int b = a; b < r->ncurves && !changed; b++)
                    for (int eb = 0; eb < 2 && !changed; eb++) {
                        if ((b == a && eb == ea) || r->at[b][eb] != k)
                            continue;
                        /* outgoing directions: +t at a start, -t at an end */
                        const ic_trace_curve *ca = &r->curves[a], *cb = &r->curves[b];
                        const ic_trace_point *pa =
                            ea ? &ca->points[ca->npoints - 1] : &ca->points[0];
                        const ic_trace_point *pb =
                            eb ? &cb->points[cb->npoints - 1] : &cb->points[0];
                        double oa[3], ob[3];
                        ic_scale3(oa, pa->t, ea ? -1.0 : 1.0);
                        ic_scale3(ob, pb->t, eb ? -1.0 : 1.0);
                        if (ic_dot3(oa, ob) > -1 + 1e-6)
                            continue;
                        ic_trace_point *A = r->storage[a];
                        int na = ca->npoints;
                        if (b == a) { /* both ends of one curve: it closes */
                            r->curves[a].closed = 1;
                            r->curves[a].ends[0] = r->curves[a].ends[1] = IC_TRACE_CLOSED;
                            r->at[a][0] = r->at[a][1] = -1;
                            changed = 1;
                            continue;
                        }
                        /* a's joining end last, b's joining end first */
                        if (ea == 0)
                            reverse_curve(A, na);
                        ic_trace_point *B = r->storage[b];
                        const int nb = cb->npoints;
                        if (eb == 1)
                            reverse_curve(B, nb);
                        ic_trace_point *J = realloc(A, (size_t)(na + nb - 1) * sizeof *J);
                        if (!J)
                            return IC_ERR_NOMEM;
                        const double shift = J[na - 1].s - B[0].s;
                        for (int i = 1; i < nb; i++) {
                            J[na - 1 + i] = B[i];
                            J[na - 1 + i].s += shift;
                        }
                        const int at0 = r->at[a][ea == 0 ? 1 : 0], at1 = r->at[b][eb == 1 ? 0 : 1];
                        const ic_trace_event e0 = ca->ends[ea == 0 ? 1 : 0];
                        const ic_trace_event e1 = cb->ends[eb == 1 ? 0 : 1];
                        free(B);
                        /* b leaves the list; a becomes the joined curve */
                        r->storage[a] = J;
                        r->curves[b] = r->curves[r->ncurves - 1];
                        r->storage[b] = r->storage[r->ncurves - 1];
                        r->at[b][0] = r->at[r->ncurves - 1][0];
                        r->at[b][1] = r->at[r->ncurves - 1][1];
                        const int ai = a == r->ncurves - 1 ? b : a;
                        r->ncurves--;
                        ic_trace_curve *c = &r->curves[ai];
                        r->storage[ai] = J;
                        c->points = J;
                        c->npoints = na + nb - 1;
                        c->ends[0] = e0;
                        c->ends[1] = e1;
                        r->at[ai][0] = at0;
                        r->at[ai][1] = at1;
                        changed = 1;
                    }
            }
    }
    for (int i = 0; i < r->ncurves; i++) {
        ic_trace_curve *c = &r->curves[i];
        c->points = r->storage[i];
        c->length = c->points[c->npoints - 1].s - c->points[0].s;
        c->shape = ic_trace_shape(c->points, c->npoints, c->length, shape_tol, c->tangential);
    }
    return IC_OK;
}

/* Drops a curve that runs along another, longer one all the way (traced
 * twice from two start points: it happens where one trace stopped early, at a
 * degenerate point of a parametrization, before covering the other start). */
void ic_trace_drop_duplicates(ic_trace_result *r, double radius)
{
    for (int a = 0; a < r->ncurves; a++) {
        const ic_trace_curve *ca = &r->curves[a];
        int inside = 0;
        for (int b = 0; b < r->ncurves && !inside; b++) {
            const ic_trace_curve *cb = &r->curves[b];
            if (b == a || cb->length < ca->length)
                continue;
            inside = 1;
            for (int k = 0; k < ca->npoints && inside; k++) {
                ic_candidate probe;
                memset(&probe, 0, sizeof probe);
                memcpy(probe.xyz, ca->points[k].xyz, sizeof probe.xyz);
                ic_trace_cover(&probe, 1, cb->points, cb->npoints, radius);
                inside = probe.covered;
            }
        }
        if (!inside)
            continue;
        free(r->storage[a]);
        const int last = --r->ncurves;
        r->curves[a] = r->curves[last];
        r->storage[a] = r->storage[last];
        r->at[a][0] = r->at[last][0], r->at[a][1] = r->at[last][1];
        a--;
    }
}
