/* The geometry of traced polylines (polyline.c). */
#ifndef IC_TRACE_POLYLINE_H
#define IC_TRACE_POLYLINE_H

#include "result.h"

/* The distance from x to the curve between two traced points (to their
 * chord, less the chord's sagitta), and that sagitta. */
double ic_trace_segment_distance(const ic_trace_point *p, const ic_trace_point *q, const double *x);
double ic_trace_segment_sagitta(const ic_trace_point *p, const ic_trace_point *q);
/* Distance from x to the polyline pts (a single point when np = 1) when it
 * is at most `bound`; otherwise a value above bound (not always the
 * distance: far parts are skipped). */
double ic_trace_polyline_distance(const ic_trace_point *pts, int np, const double *x,
                                  double bound);
/* The box of the polyline pts widened by its largest sagitta and pad; and
 * whether x lies in a box. */
void ic_trace_curve_box(const ic_trace_point *pts, int np, double pad, double *lo, double *hi);
int ic_trace_in_box(const double *x, const double *lo, const double *hi);
/* Marks the candidates within radius of the polyline pts as covered. */
void ic_trace_cover(ic_candidate *c, int n, const ic_trace_point *pts, int np, double radius);

#endif
