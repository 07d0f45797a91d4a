/*
 * A problem far from the origin moved near it (frame.h; docs/tracing.md,
 * "Far from the origin"). A saddle z - o = 0.05((x - o)^2 - (y - o)^2) at
 * o = 1e6 evaluated where it is keeps 1.2e-10 of absolute precision beside
 * a branch point whose branches are 1e-5 apart at 1e-5 from it: the
 * tracer traced its diagonals two or three times and the checker could
 * isolate no crossing there. Moved by (o, o, o) its formulas are those of
 * the saddle at the origin, combined exactly (expr/shift.c), and both
 * keep every digit. The origin is the centre of the problem's bounds
 * rounded to a power of 2 near its size, so that the region's bounds and
 * its points subtract from it exactly (Sterbenz).
 */
#include "frame.h"
#include "core/curve_index.h"
#include "core/options.h"
#include "local/pair_access.h"
#include "surface/surface_copy.h"

#include <math.h>
#include <string.h>

/* c rounded to a multiple of the power of 2 at most `size`: exact to form,
 * within size / 2 of c. */
static double rounded_origin(double c, double size)
{
    const double q = exp2(floor(log2(size)));
    return q * nearbyint(c / q);
}

/* The origin of one coordinate spanning [lo, hi]: 0 unless it lies far. */
static double origin_of(double lo, double hi, double size)
{
    const double c = 0.5 * lo + 0.5 * hi;
    return isfinite(c) && size > 0 && isfinite(size) && fabs(c) > IC_TRACE_FRAME_FAR * size
               ? rounded_origin(c, size)
               : 0.0;
}

static void choose(ic_frame *fr, ic_pair *pair, const ic_trace_options *opt)
{
    memset(fr, 0, sizeof *fr);
    double lo[3], hi[3];
    ic_trace_problem_bounds(pair, opt, lo, hi);
    const double L = ic_trace_problem_scale(pair, opt);
    for (int k = 0; k < 3; k++)
        if (lo[k] <= hi[k])
            fr->xyz[k] = origin_of(lo[k], hi[k], L);
    for (int s = 0; s < 2; s++) {
        const ic_surface *S = ic_pair_surface(pair, s);
        if (ic_surface_get_kind(S) != IC_PARAMETRIC)
            continue;
        double dom[2][2];
        int per[2];
        ic_surface_get_domain(S, dom, per);
        for (int k = 0; k < 2; k++)
            fr->params[s][k] = origin_of(dom[k][0], dom[k][1], dom[k][1] - dom[k][0]);
    }
    for (int k = 0; k < 3; k++)
        fr->moved |= fr->xyz[k] != 0.0;
    for (int k = 0; k < 4; k++)
        fr->moved |= fr->params[k / 2][k % 2] != 0.0;
}

/* The box moved: 0 when a bound does not subtract exactly. */
static int move_box(const ic_frame *fr, const double box[3][2], double out[3][2])
{
    for (int k = 0; k < 3; k++)
        for (int e = 0; e < 2; e++) {
            out[k][e] = ic_exact_difference(box[k][e], fr->xyz[k]);
            if (isnan(out[k][e]))
                return 0;
        }
    return 1;
}

/* The surfaces moved and paired: IC_ERR_UNABLE where one cannot move. */
static ic_status move_pair(ic_trace_moved *m, ic_pair *pair, ic_error *err)
{
    const int self = ic_pair_is_self(pair);
    ic_status st = IC_OK;
    for (int s = 0; s < (self ? 1 : 2) && st == IC_OK; s++)
        st = ic_surface_shifted(&m->own[s], ic_pair_surface(pair, s), m->frame.xyz,
                                m->frame.params[s], err);
    if (st == IC_OK)
        st = ic_pair_new(&m->pair, m->own[0], self ? NULL : m->own[1], err);
    if (st == IC_OK)
        ic_pair_set_frame(m->pair, &m->frame);
    return st;
}

ic_status ic_trace_move(ic_trace_moved *m, ic_pair *pair, const double box[3][2], int has_box,
                        ic_error *err)
{
    memset(m, 0, sizeof *m);
    ic_trace_options opt = {.has_box = has_box};
    if (has_box)
        memcpy(opt.box, box, sizeof opt.box);
    choose(&m->frame, pair, &opt);
    if (ic_pair_is_self(pair)) /* one sheet in both places */
        memcpy(m->frame.params[1], m->frame.params[0], sizeof m->frame.params[1]);
    if (!m->frame.moved || (has_box && !move_box(&m->frame, box, m->box))) {
        memset(&m->frame, 0, sizeof m->frame);
        return IC_OK;
    }
    ic_error local;
    ic_error_clear(&local);
    const ic_status st = move_pair(m, pair, &local);
    if (st == IC_OK)
        return IC_OK;
    ic_trace_moved_release(m); /* not moved: traced where it is */
    if (st == IC_ERR_NOMEM)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory moving the problem");
    return IC_OK;
}

void ic_trace_moved_release(ic_trace_moved *m)
{
    ic_pair_free(m->pair);
    ic_surface_free(m->own[0]);
    ic_surface_free(m->own[1]);
    memset(m, 0, sizeof *m);
}

void ic_trace_result_move_back(ic_trace_result *r, const ic_frame *fr)
{
    if (!r || !fr->moved)
        return;
    for (int c = 0; c < r->ncurves; c++)
        for (int i = 0; i < r->curves[c].npoints; i++) {
            ic_trace_point *p = &r->storage[c][i];
            ic_frame_move(fr, 1.0, p->xyz, p->params);
        }
    for (int k = 0; k < r->nspecials; k++) {
        ic_frame_move(fr, 1.0, r->specials[k].xyz, NULL);
        ic_frame_move(fr, 1.0, r->located[k].pt.xyz, r->located[k].pt.params);
    }
    for (int k = 0; k < r->ncoincident; k++)
        ic_frame_move(fr, 1.0, r->coincident[k], NULL);
    ic_curve_index_free(r->index);
    r->index = NULL;
}
