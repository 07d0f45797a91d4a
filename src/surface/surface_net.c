/* A NURBS surface's recognised shape (surface_internal.h, net_shape.h):
 * recognised once, on first use, for the patch over its whole domain. */
#include "surface_internal.h"

const ic_net_shape *ic_surface_net_shape(ic_surface *s)
{
    if (!s || s->backend != BACKEND_NURBS)
        return NULL;
    for (int d = 0; d < 2; d++) /* a patch cut to part of its domain is a part */
        if (s->domain[d][0] != s->nurbs->domain[d][0] || s->domain[d][1] != s->nurbs->domain[d][1])
            return NULL;
    if (!s->net_tried) {
        if (ic_net_recognize(s->nurbs, &s->net_shape) != 0)
            return NULL; /* out of memory: tried again next time */
        s->net_tried = 1;
    }
    return s->net_shape;
}
