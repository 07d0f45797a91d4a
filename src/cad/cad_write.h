/* The listing of `intercurve surfaces` (docs/cad-files.md, "Listing a file"). */
#ifndef IC_CAD_WRITE_H
#define IC_CAD_WRITE_H

#include <stdio.h>

#include "cad.h"

/* Writes the surfaces of `file` as text lines, or (json) as one JSON
 * document. IC_ERR_IO when f reports an error, IC_ERR_NOMEM. */
ic_status ic_cad_write_list(FILE *f, const char *file, const ic_cad_info *info,
                            const ic_cad_surface *list, int n, int json, ic_error *err);

#endif
