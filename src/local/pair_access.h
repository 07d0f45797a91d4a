/* What the layers above the local layer (trace, curve) may use of a pair
 * beyond the public API: accessor functions, not its layout
 * (local_internal.h keeps that to the local folder). */
#ifndef IC_LOCAL_PAIR_ACCESS_H
#define IC_LOCAL_PAIR_ACCESS_H

#include "intercurve/jet.h"
#include "intercurve/local.h"
#include "pairing/pairing.h"

/* Out of memory is noted in the pair, like a stream's error indicator: an
 * operation built on others that tries another way after a failed step (a
 * search, a march, a locator) cannot tell it from a step that fails, and
 * asks afterwards. Returns st, noted when it is IC_ERR_NOMEM; IC_ERR_NOMEM
 * (err set) when memory ran out during the operation (the pair's count is
 * no longer `before`), whatever st says. */
ic_status ic_pair_nomem_check(ic_pair *pair, long before, ic_status st, ic_error *err);

/* The pair's count of operations that ran out of memory: `before` of
 * ic_pair_nomem_check. */
long ic_pair_nomem_count(const ic_pair *pair);

/* Sets the count back to `before`: an out of memory that its caller
 * answers itself (a march made ahead of the serial order, dropped) is not
 * the pair's. */
void ic_pair_nomem_restore(ic_pair *pair, long before);

/* Adds the count of `copy` (another thread's pair, trace/workers.c) to the
 * pair's and clears the copy's: the trace asks only its own pair. */
void ic_pair_nomem_take(ic_pair *pair, ic_pair *copy);

/* The pair's pairing (pairing/pairing.h), built with it. */
const ic_pairing *ic_pair_pairing(const ic_pair *pair);

/* Notes that the pair's surfaces are a problem moved by fr (trace/frame.c),
 * so that messages show the user's coordinates (pairing.h: frame). */
void ic_pair_set_frame(ic_pair *pair, const ic_frame *fr);

/* The pair's jet space of order 2 in nvars (2: a parametric sheet's, 3: an
 * implicit one's) variables, made with the pair: using it allocates
 * nothing. */
const ic_jet_space *ic_pair_near_space(const ic_pair *pair, int nvars);

/* The parameters of the point of parametric sheet `which` nearest to X, by
 * damped Newton on |R(u, v) - X|^2 from uv (updated); *dist the distance. */
ic_status ic_local_project(ic_pair *pair, int which, double uv[2], const double X[3],
                           const ic_local_options *opt, double *dist);

/* The bend across a tangential curve at its point pt (1/length,
 * docs/tracing.md "Crossings of a tangential curve"): the trace of
 * II_B - II_A over the tangent plane, B's normal turned to A's side, which
 * on the curve is the relative normal curvature across it. It changes sign
 * where a transversal curve crosses. */
ic_status ic_local_tangential_bend(ic_pair *pair, const ic_local_point *pt, double *bend,
                                   ic_error *err);

#endif
