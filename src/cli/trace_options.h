/* The trace's options as `intercurve trace` and `intercurve plot` both take
 * them: one entry of each option table, its help text the command's own
 * (include/intercurve/defaults.h gives the defaults and ranges). */
#ifndef IC_CLI_TRACE_OPTIONS_H
#define IC_CLI_TRACE_OPTIONS_H

#include "cli/cli.h"

#define IC_CLI_OPTION_TOL(help_text)                                                               \
    {                                                                                              \
        .name = "--tol", .metavar = "T", .kind = IC_OPT_REAL, .lo = 0, .hi = IC_TRACE_REL_TOL_MAX, \
        .fallback = IC_CLI_TEXT_OF(IC_TRACE_TOL_DEFAULT), .help = help_text                        \
    }
#define IC_CLI_OPTION_DEPTH(help_text)                                                             \
    {                                                                                              \
        .name = "--depth", .metavar = "D", .kind = IC_OPT_INT, .lo = 1, .hi = IC_TRACE_MAX_DEPTH,  \
        .fallback = IC_CLI_TEXT_OF(IC_TRACE_DEPTH_DEFAULT), .help = help_text                      \
    }
#define IC_CLI_OPTION_THREADS(help_text)                                                           \
    {                                                                                              \
        .name = "--threads", .metavar = "N", .kind = IC_OPT_INT, .lo = 0,                          \
        .hi = IC_TRACE_MAX_THREADS, .fallback = IC_CLI_TEXT_OF(IC_TRACE_THREADS_DEFAULT),          \
        .help = help_text                                                                          \
    }
#define IC_CLI_OPTION_NO_EXACT(help_text)                                                          \
    {                                                                                              \
        .name = "--no-exact", .kind = IC_OPT_FLAG, .help = help_text                               \
    }

#endif
