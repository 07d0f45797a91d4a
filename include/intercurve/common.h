/**
 * @file common.h
 * Status codes and the error record shared by every layer of intercurve.
 *
 * Fallible functions return ::ic_status (IC_OK = 0). The codes come in two
 * families (docs/conventions.md):
 *  - the caller's mistakes: IC_ERR_INVALID, IC_ERR_PARSE, IC_ERR_NOMEM;
 *  - mathematical outcomes: IC_ERR_DOMAIN (the result is undefined there),
 *    IC_ERR_UNABLE (no convergence, singular system).
 * An optional ::ic_error (may be NULL) receives the code, a position and a
 * message in fixed buffers, so even out-of-memory can be reported.
 * The library never prints and never aborts.
 *
 * Arguments (docs/conventions.md, "Argument checking"): a NULL object,
 * output, string or array a function needs, or a count or index out of
 * range, is IC_ERR_INVALID with a message naming the function and the
 * argument ("ic_trace: pair is NULL"); getters return 0, -1 or NULL (as
 * their comments say) for a NULL object or an index out of range; functions
 * returning void do nothing with a NULL argument. `err` may be NULL anywhere.
 */
#ifndef INTERCURVE_COMMON_H
#define INTERCURVE_COMMON_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* IC_API marks the library's API: the shared library is built with hidden
 * visibility and exports only the functions that carry it (docs/packaging.md). */
#if defined(__GNUC__) || defined(__clang__)
#define IC_API __attribute__((visibility("default")))
#define IC_NODISCARD __attribute__((warn_unused_result))
#define IC_PRINTF(f, a) __attribute__((format(printf, f, a)))
#else
#define IC_API
#define IC_NODISCARD
#define IC_PRINTF(f, a)
#endif

typedef enum {
    IC_OK = 0,
    IC_ERR_INVALID = 1, /**< invalid argument (caller's mistake) */
    IC_ERR_PARSE = 2,   /**< malformed formula or problem file (caller's mistake) */
    IC_ERR_NOMEM = 3,   /**< out of memory */
    IC_ERR_DOMAIN = 4,  /**< mathematically undefined: log of <= 0, zero normal, ... */
    IC_ERR_UNABLE = 5,  /**< no convergence, singular system */
    IC_ERR_IO = 6       /**< a file could not be read or written */
} ic_status;

/** Sizes of the fixed buffers of ::ic_error. */
#define IC_ERROR_PATH_LEN 160
#define IC_ERROR_MESSAGE_LEN 320

/**
 * What went wrong and where. `column` is the 1-based column in a formula
 * (0 when the error is not in a formula); `path` is a JSON path such as
 * `surfaces[1].xyz[2]` when the error comes from a problem file (else "").
 */
typedef struct {
    ic_status code;
    int column;
    char path[IC_ERROR_PATH_LEN];
    char message[IC_ERROR_MESSAGE_LEN];
} ic_error;

/** A named constant of a problem ("R": 2). */
typedef struct {
    const char *name;
    double value;
} ic_constant;

/** Short English name of a status ("domain error", ...): a static string,
 *  never NULL. */
IC_API const char *ic_status_name(ic_status status);

/** Clears an error record (code IC_OK, empty strings). NULL is allowed. */
IC_API void ic_error_clear(ic_error *err);

/**
 * Fills `err` (if not NULL) with `code`, `column` and a printf-formatted
 * message; keeps an existing path. Returns `code`, so callers can write
 * `return ic_error_set(err, IC_ERR_DOMAIN, 0, "...")`.
 */
IC_API ic_status ic_error_set(ic_error *err, ic_status code, int column, const char *fmt, ...)
    IC_PRINTF(4, 5);

/** Sets the JSON path of `err` (printf-formatted). NULL `err` is allowed. */
IC_API void ic_error_set_path(ic_error *err, const char *fmt, ...) IC_PRINTF(2, 3);

#ifdef __cplusplus
}
#endif
#endif
