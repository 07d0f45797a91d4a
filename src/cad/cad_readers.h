/* The format readers that the dispatcher (cad.c) calls, on a parsed file:
 * ic_*_read the surface `entity` (or what it leads to), ic_*_list every
 * surface with the file's length unit in `info`. Only cad.c calls them. */
#ifndef IC_CAD_READERS_H
#define IC_CAD_READERS_H

#include "cad_types.h"
#include "iges_parse.h"
#include "step_parse.h"

ic_status ic_step_read(const ic_step_file *f, int entity, ic_cad_surface *out, ic_error *err);
ic_status ic_step_list(const ic_step_file *f, ic_cad_surface **list, int *n, ic_cad_info *info,
                       ic_error *err);
ic_status ic_iges_read(const ic_iges_file *f, int entity, ic_cad_surface *out, ic_error *err);
ic_status ic_iges_list(const ic_iges_file *f, ic_cad_surface **list, int *n, ic_cad_info *info,
                       ic_error *err);

#endif
