/* The defaults and limits of include/intercurve/defaults.h by name, for the
 * languages that cannot read its macros (the Python package). */
#include "intercurve/defaults.h"
#include "intercurve/local.h"

#include <math.h>
#include <string.h>

typedef struct {
    const char *name;
    double value;
} named_default;

static const named_default DEFAULTS[] = {
    {"tol", IC_TRACE_TOL_DEFAULT},
    {"depth", IC_TRACE_DEPTH_DEFAULT},
    {"fit_tol", IC_TRACE_FIT_TOL_DEFAULT},
    {"threads", IC_TRACE_THREADS_DEFAULT},
    {"rel_tol_max", IC_TRACE_REL_TOL_MAX},
    {"time_limit_max", IC_TRACE_TIME_LIMIT_MAX},
    {"point_tol", IC_LOCAL_POINT_TOL_DEFAULT},
    {"point_order", IC_POINT_ORDER_DEFAULT},
    {"point_closed_form_order", IC_POINT_CLOSED_FORM_ORDER_DEFAULT},
    {"width", IC_PLOT_WIDTH_DEFAULT},
    {"height", IC_PLOT_HEIGHT_DEFAULT},
    {"azimuth", IC_PLOT_AZIMUTH_DEFAULT},
    {"elevation", IC_PLOT_ELEVATION_DEFAULT},
    {"frames", IC_PLOT_FRAMES_DEFAULT},
    {"mesh", IC_PLOT_MESH_DEFAULT},
};

double ic_default_value(const char *name)
{
    for (size_t i = 0; name && i < sizeof DEFAULTS / sizeof DEFAULTS[0]; i++)
        if (strcmp(name, DEFAULTS[i].name) == 0)
            return DEFAULTS[i].value;
    return NAN;
}

/* the closed forms' default order is the highest they give */
_Static_assert(IC_POINT_CLOSED_FORM_ORDER_DEFAULT == IC_CLOSED_FORM_MAX_ORDER,
               "the closed-form default order must be the closed forms' highest");
