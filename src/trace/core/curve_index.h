/* A spatial hash of the traced curves' segments (curve_index.c). */
#ifndef IC_TRACE_CURVE_INDEX_H
#define IC_TRACE_CURVE_INDEX_H

#include "result.h"

/* An index of grid cell size h. ic_curve_index_near: 1 when a segment lies
 * within bound of x (less its sagitta), 0 when none, -1 when the index
 * cannot tell (then scan every curve). */
ic_curve_index *ic_curve_index_new(double h);
void ic_curve_index_free(ic_curve_index *ix);
void ic_curve_index_clear(ic_curve_index *ix);
int ic_curve_index_add(ic_curve_index *ix, int curve, const ic_trace_point *pts, int n);
int ic_curve_index_near(ic_curve_index *ix, const ic_trace_result *r, const double *x,
                        double bound);

#endif
