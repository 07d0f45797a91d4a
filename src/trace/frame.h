/*
 * A problem far from the origin moved near it (frame.c; docs/tracing.md,
 * "Far from the origin"): the trace and the checker run on the surfaces
 * moved exactly by the frame, and the result is moved back.
 */
#ifndef IC_TRACE_FRAME_H
#define IC_TRACE_FRAME_H

#include "common/frame.h"
#include "core/result.h"

/* A problem is moved along a coordinate when its centre there lies
 * farther from the origin than this many times its size (the diagonal of
 * its bounds, or a parameter's domain width): nearer, rounding at the
 * centre costs less than 6 bits and nothing is moved. */
#define IC_TRACE_FRAME_FAR 64.0

/* The problem's moved copy: the frame, the moved pair (NULL: nothing
 * moved, trace the original) and the surfaces it owns. */
typedef struct {
    ic_frame frame;
    ic_pair *pair;
    ic_surface *own[2];
    double box[3][2]; /* the box moved (verify: the problem's box, moved or not) */
    int has_box;
} ic_trace_moved;

/* The frame of the pair's problem (opt: its box) and, when it moves
 * anything and every surface and the box move exactly, the moved pair
 * and box. IC_OK (m->pair NULL where it does not move), or IC_ERR_NOMEM. */
ic_status ic_trace_move(ic_trace_moved *m, ic_pair *pair, const double box[3][2], int has_box,
                        ic_error *err);
void ic_trace_moved_release(ic_trace_moved *m);

/* The result of the moved problem moved back to the user's coordinates:
 * its curves' points and parameters, its special points, its located
 * points and coincident points (the curve index, of moved points, is
 * dropped). */
void ic_trace_result_move_back(ic_trace_result *r, const ic_frame *fr);

#endif
