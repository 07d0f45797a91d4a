/* The IGES reader's pieces (iges_surface.c, iges_units.c). */
#ifndef IC_IGES_SURFACE_H
#define IC_IGES_SURFACE_H

#include <stddef.h>

#include "cad_internal.h"
#include "iges_parse.h"

/* The file's length unit: its name ("" when not stated) and size in metres
 * (0 when unknown). */
void ic_iges_length_unit(const ic_iges_file *f, char *unit, size_t size, double *metres);

#endif
