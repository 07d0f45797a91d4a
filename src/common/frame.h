/*
 * Where a problem's coordinates were moved to (docs/tracing.md, "Far from
 * the origin"): the tracer and the checker work in x' = x - xyz and, on
 * each parametric sheet s, in u' = u - params[s], so that a feature of size
 * 1 at 1e6 keeps its digits. moved 0: nothing was moved (all zeros).
 */
#ifndef IC_COMMON_FRAME_H
#define IC_COMMON_FRAME_H

#include <math.h>

typedef struct {
    int moved;
    double xyz[3];
    double params[2][2];
} ic_frame;

/* a - b when it is a double exactly (Sterbenz: b within a factor 2 of a,
 * or b = 0), else NAN: Knuth's two-sum of a and -b has no error. */
static inline double ic_exact_difference(double a, double b)
{
    const double d = a - b;
    const double bv = d - a;
    return isfinite(d) && (a - (d - bv)) + (-b - bv) == 0.0 ? d : NAN;
}

/* A point of the moved problem as the user's: xyz + the frame's origin
 * (f NULL: unchanged), for messages. */
static inline void ic_frame_shown(const ic_frame *f, const double xyz[3], double out[3])
{
    for (int k = 0; k < 3; k++)
        out[k] = xyz[k] + (f ? f->xyz[k] : 0.0);
}

/* A point moved by sign times the frame: -1 into the moved problem
 * (verify), +1 back to the user's (the trace's result); params may be NULL. */
static inline void ic_frame_move(const ic_frame *f, double sign, double xyz[3],
                                 double params[2][2])
{
    for (int k = 0; k < 3; k++)
        xyz[k] += sign * f->xyz[k];
    for (int k = 0; params && k < 4; k++)
        params[k / 2][k % 2] += sign * f->params[k / 2][k % 2];
}

/* Where search coordinate k of a search of dimension dim was moved from:
 * the xyz origin for two implicit surfaces (3), else the sheets'
 * parameters' (4: u, v, p, q; 2: the parametric sheet's, the implicit
 * sheet's being 0). */
static inline double ic_frame_search_origin(const ic_frame *f, int dim, int k)
{
    if (dim == 3)
        return f->xyz[k];
    return dim == 2 ? f->params[0][k] + f->params[1][k] : f->params[k / 2][k % 2];
}

#endif
