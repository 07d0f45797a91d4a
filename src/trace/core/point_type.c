/* The classification of a traced curve's point (include/intercurve/trace.h):
 * what the writers and the chart print for each point, decided once here
 * from the result rather than by each of them. */
#include "intercurve/trace.h"

#include <math.h>

ic_point_type ic_trace_point_type(const ic_trace_result *res, const ic_trace_curve *c,
                                  const ic_trace_point *p)
{
    if (!p)
        return IC_POINT_TRANSVERSAL;
    for (int i = 0; i < ic_trace_result_num_specials(res); i++) {
        const ic_trace_special *sp = ic_trace_result_special(res, i);
        const double d = fmax(fmax(fabs(sp->xyz[0] - p->xyz[0]), fabs(sp->xyz[1] - p->xyz[1])),
                              fabs(sp->xyz[2] - p->xyz[2]));
        /* the special point is appended to the curve as it is: equal to rounding */
        if (d <= 1e-12 * (1 + fabs(p->xyz[0]) + fabs(p->xyz[1]) + fabs(p->xyz[2])))
            return sp->type;
    }
    return c && c->tangential ? IC_POINT_TANGENTIAL_CURVE : IC_POINT_TRANSVERSAL;
}
