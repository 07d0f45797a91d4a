/* Argument checks of the public functions (docs/conventions.md, "Argument
 * checking"): a NULL pointer a function needs is the caller's mistake, so it
 * gets IC_ERR_INVALID with a message naming the function and the argument
 * ("ic_trace: pair is NULL"), never a crash. */
#ifndef IC_COMMON_ARGS_H
#define IC_COMMON_ARGS_H

#include "intercurve/common.h"

/* Returns IC_ERR_INVALID from the enclosing function, whose error record is
 * `err`, when `ptr` is NULL; `name` is the argument as the header spells it. */
#define IC_ARG_NOT_NULL(ptr, name)                                                                \
    do {                                                                                          \
        if (!(ptr))                                                                               \
            return ic_error_set(err, IC_ERR_INVALID, 0, "%s: %s is NULL", __func__, name);        \
    } while (0)

/* The same when the condition `ok` on argument `name` fails; `what` says
 * what it must be ("must be at least 1"). */
#define IC_ARG_CHECK(ok, name, what)                                                              \
    do {                                                                                          \
        if (!(ok))                                                                                \
            return ic_error_set(err, IC_ERR_INVALID, 0, "%s: %s %s", __func__, name, what);       \
    } while (0)

#endif
