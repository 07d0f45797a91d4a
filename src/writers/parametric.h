/* What every document writer asks of the pair first: which of its two
 * surfaces are parametric (they carry parameters and pcurves; an implicit
 * one has none). */
#ifndef IC_WRITERS_PARAMETRIC_H
#define IC_WRITERS_PARAMETRIC_H

#include "intercurve/local.h"

static inline void ic_writer_parametric(const ic_pair *pair, int parametric[2])
{
    for (int s = 0; s < 2; s++)
        parametric[s] = ic_surface_get_kind(ic_pair_surface(pair, s)) == IC_PARAMETRIC;
}

#endif
