/* The accessors the layers above read a surface by (surface_access.h). */
#include "surface_internal.h"

#include <string.h>

const ic_primitive *ic_surface_primitive(const ic_surface *s)
{
    return s && s->backend == BACKEND_PRIMITIVE ? &s->prim : NULL;
}

int ic_surface_primitive_frame(const ic_surface *s, double frame[3][3])
{
    if (!ic_surface_primitive(s))
        return -1;
    /* primitive.c keeps a plane's frame apart from the placement of the others */
    memcpy(frame, s->prim.kind == IC_PRIM_PLANE ? s->plane_frame : s->frame, sizeof s->frame);
    return 0;
}
