/* The surfaces of a pair as the exact paths take them (exact_source.h): an
 * implicit primitive as it is, a NURBS patch as the primitive it was
 * recognised as (surface_net.c), only when recognised over its whole
 * domain. */
#include "exact_profile.h"
#include "exact_source.h"
#include "common/vec3.h"
#include "surface/surface_access.h"

#include <string.h>

/* 1, 0 (neither an implicit primitive nor a recognised patch), or -1 out
 * of memory. */
static int source_of(ic_surface *s, ic_exact_source *out)
{
    memset(out, 0, sizeof *out);
    out->surface = s;
    const ic_primitive *prim = ic_surface_primitive(s);
    if (prim && ic_surface_get_kind(s) == IC_IMPLICIT) {
        out->prim = *prim;
        (void)ic_surface_primitive_frame(s, out->frame);
        return 1;
    }
    const ic_net_shape *sh;
    if (ic_surface_net_shape(s, &sh) != 0)
        return -1;
    if (!sh)
        return 0;
    out->prim = sh->prim;
    memcpy(out->frame, sh->frame, sizeof out->frame);
    out->net = sh;
    return 1;
}

int ic_exact_sources(ic_pair *pair, ic_exact_source src[2])
{
    if (ic_pair_is_self(pair))
        return 0;
    const int a = source_of(ic_pair_surface(pair, 0), &src[0]);
    const int b = a > 0 ? source_of(ic_pair_surface(pair, 1), &src[1]) : a;
    return b;
}

int ic_exact_net_coaxial(const ic_exact_source *src, const double o[3], const double e[3], double L)
{
    const ic_net_shape *sh = src->net;
    if (!sh || sh->kind != IC_NET_REVOLVED)
        return 0;
    double c[3], w[3];
    ic_cross3(c, sh->frame[2], e);
    ic_axpy3(w, sh->origin, -1.0, o);
    ic_axpy3(w, w, -ic_dot3(w, e), e);
    return ic_norm3(c) <= IC_EXACT_COAXIAL && ic_norm3(w) <= IC_EXACT_COAXIAL * L;
}
