/* Output files written safely: the files that -o names (docs/output-formats.md,
 * "How files are written").
 *
 * - a new path or a regular file: written to a temporary file created with
 *   O_CREAT | O_EXCL (so a planted link is never followed) under a hidden name
 *   beside it, ".NAME.XXXXXX", then renamed over it; a failure removes that
 *   temporary and leaves the target as it was. An existing file keeps its
 *   permission bits, a new one gets 0666 less the umask, as fopen would give;
 * - a symbolic link: stays a link; a link to a regular file gets the same
 *   treatment beside the file it resolves to, a link to anything else is
 *   written through in place; a dangling link is refused;
 * - a device, FIFO or socket: opened without O_CREAT and written in place;
 * - a directory: refused.
 * Every failure sets IC_ERR_IO (IC_ERR_NOMEM) with "cannot write NAME: reason". */
#ifndef IC_SAFE_FILE_H
#define IC_SAFE_FILE_H

#include <stddef.h>
#include <stdio.h>

#include "intercurve/common.h"

typedef struct ic_safe_file ic_safe_file;

/* Opens `path` for writing as above; *out is NULL on failure. */
ic_status ic_safe_open(ic_safe_file **out, const char *path, ic_error *err);

/* Writes n bytes. */
ic_status ic_safe_write(ic_safe_file *sf, const void *data, size_t n, ic_error *err);

/* Finishes and frees sf: the temporary synced, closed and renamed over the
 * target, or the device closed. On failure the temporary is removed. */
ic_status ic_safe_commit(ic_safe_file *sf, ic_error *err);

/* Gives up and frees sf: closes it and removes the temporary (NULL: nothing). */
void ic_safe_abort(ic_safe_file *sf);

/* ic_write_file_atomic (intercurve/writers.h) writes whole documents the
 * same way, gathered in memory first. */

#endif
