/* A NURBS surface's recognised shape (surface_internal.h, net_shape.h):
 * recognised once, on first use, for the patch over its whole domain. */
#include "surface_internal.h"

int ic_surface_net_shape(ic_surface *s, const ic_net_shape **out)
{
    *out = NULL;
    if (!s || s->backend != BACKEND_NURBS)
        return 0;
    for (int d = 0; d < 2; d++) /* a patch cut to part of its domain is a part */
        if (s->domain[d][0] != s->nurbs->domain[d][0] || s->domain[d][1] != s->nurbs->domain[d][1])
            return 0;
    if (!s->net_tried) {
        if (ic_net_recognize(s->nurbs, &s->net_shape) != 0)
            return -1;
        s->net_tried = 1;
    }
    *out = s->net_shape;
    return 0;
}
