/* Status names and the error record (include/intercurve/common.h). */
#include "intercurve/common.h"

#include <stdarg.h>
#include <stdio.h>

const char *ic_status_name(ic_status status)
{
    switch (status) {
    case IC_OK: return "ok";
    case IC_ERR_INVALID: return "invalid argument";
    case IC_ERR_PARSE: return "parse error";
    case IC_ERR_NOMEM: return "out of memory";
    case IC_ERR_DOMAIN: return "domain error";
    case IC_ERR_UNABLE: return "unable to compute";
    case IC_ERR_IO: return "input/output error";
    }
    return "unknown status";
}

void ic_error_clear(ic_error *err)
{
    if (!err)
        return;
    err->code = IC_OK;
    err->column = 0;
    err->path[0] = '\0';
    err->message[0] = '\0';
}

ic_status ic_error_set(ic_error *err, ic_status code, int column, const char *fmt, ...)
{
    if (!err)
        return code;
    err->code = code;
    err->column = column;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err->message, sizeof err->message, fmt, ap);
    va_end(ap);
    return code;
}

void ic_error_set_path(ic_error *err, const char *fmt, ...)
{
    if (!err)
        return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err->path, sizeof err->path, fmt, ap);
    va_end(ap);
}
