/* Surfaces read from CAD files: STEP Part 21 (ISO 10303-21) and IGES 5.x
 * (docs/cad-files.md). The reader gives a plain description of each
 * surface, a NURBS patch or a placed primitive, in the file's own numbers
 * and length unit; making an ic_surface of it is the caller's job.
 *
 * Every failure names the file's entity (STEP "#42", IGES "DE 7") and what
 * is wrong with it or what is not supported. Any bytes are safe to read: the
 * parsers never read past the buffer, and sizes are bounded (cad_types.h). */
#ifndef IC_CAD_H
#define IC_CAD_H

#include <stddef.h>

#include "cad_types.h"

/* The format of a text: STEP when it starts (after blanks) with
 * "ISO-10303-21", IGES when its first record has 'S' in column 73, else
 * IC_CAD_ANY (neither). */
ic_cad_format ic_cad_sniff(const char *data, size_t len);
const char *ic_cad_format_name(ic_cad_format format);

/* Every surface of a file in memory, in the order of the file: readable ones
 * and those that are not (supported 0, with the reason). `format` IC_CAD_ANY
 * finds it with ic_cad_sniff; a file of another format than asked is an error.
 * *list (free with ic_cad_list_free) is NULL when *n is 0; `info` (NULL
 * allowed) receives the format and the length unit. */
ic_status ic_cad_list_buffer(const char *data, size_t len, ic_cad_format format,
                             ic_cad_surface **list, int *n, ic_cad_info *info, ic_error *err);
/* One surface: `entity` a surface, or (STEP) a face whose geometry is a
 * surface, or (IGES) a trimmed surface 144 whose base is a 128. An entity
 * that is absent, not a surface, or of an unsupported kind is an error. */
ic_status ic_cad_read_buffer(const char *data, size_t len, ic_cad_format format, int entity,
                             ic_cad_surface *out, ic_error *err);
/* The same; on failure *entity_fault is 1 when the file was read and the
 * entity is at fault (absent, not a surface, not supported, malformed), 0
 * when the file is (unreadable, of another format, malformed). */
ic_status ic_cad_read_entity(const char *path, ic_cad_format format, int entity,
                             ic_cad_surface *out, int *entity_fault, ic_error *err);

/* The same from a file (at most IC_CAD_MAX_FILE bytes); messages begin with
 * the path. */
ic_status ic_cad_list(const char *path, ic_cad_format format, ic_cad_surface **list, int *n,
                      ic_cad_info *info, ic_error *err);
ic_status ic_cad_read(const char *path, ic_cad_format format, int entity, ic_cad_surface *out,
                      ic_error *err);

#endif
