/* Curve shapes from the corollaries 3.1-3.5 of Abdel-All et al. (2012), and
 * their names. */
#include "trace_internal.h"
#include "common/vec3.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

const char *ic_shape_name(ic_shape shape)
{
    static const char *const names[] = {"general", "line",           "circle",
                                        "planar",  "circular-helix", "helix"};
    return shape >= IC_SHAPE_GENERAL && shape <= IC_SHAPE_HELIX ? names[shape] : "unknown";
}

/* Points where the normals are this close to parallel carry large
 * transversal torsion errors (eps/angle^2 near Viviani's branch point, about
 * eps/angle^3.5 near those of Abdel-All et al. (2012), Example 5.1: 500 at
 * 1e-5 rad, 1e-5 at 1e-3 rad; docs/tangential.md): the shape tests skip
 * them. */
#define SHAPE_MIN_ANGLE 1e-2

/* Abdel-All et al. (2012), corollaries 3.1-3.5, on the sampled kappa and tau, relative to the
 * largest curvature (lines: to the total turning kappa L). The shape; along a transversal curve the
 * points near tangency are skipped (their torsion is unreliable), along a tangential curve none is
 * (its apparatus comes from the height-difference method). */
ic_shape ic_trace_shape(const ic_trace_point *p, int n, double length, double tol, int tangential)
{
    /* a curve whose every point is near tangency (two spheres overlapping
     * by 1e-6 meet at 2e-3 rad) keeps all its points: none would read as
     * no curvature, a line */
    int usable = 0;
    for (int i = 0; i < n && !usable; i++)
        usable = p[i].angle >= SHAPE_MIN_ANGLE;
    if (!usable)
        tangential = 1;
    double kmax = 0, kmin = INFINITY, tmax = -INFINITY, tmin = INFINITY, rmax = -INFINITY,
           rmin = INFINITY;
    int framed = 0;
    for (int i = 0; i < n; i++) {
        if (p[i].angle < SHAPE_MIN_ANGLE && !tangential)
            continue;
        kmax = fmax(kmax, p[i].kappa);
        kmin = fmin(kmin, p[i].kappa);
        if (p[i].frame_defined) {
            framed++;
            tmax = fmax(tmax, p[i].tau);
            tmin = fmin(tmin, p[i].tau);
            if (p[i].tau != 0) {
                rmax = fmax(rmax, p[i].kappa / p[i].tau);
                rmin = fmin(rmin, p[i].kappa / p[i].tau);
            }
        }
    }
    if (kmax * length <= tol)
        return IC_SHAPE_LINE;
    if (!framed)
        return IC_SHAPE_GENERAL;
    const int planar = fmax(fabs(tmax), fabs(tmin)) <= tol * kmax;
    const int kconst = kmax - kmin <= tol * kmax;
    if (planar)
        return kconst ? IC_SHAPE_CIRCLE : IC_SHAPE_PLANAR;
    const double tbar = fmax(fabs(tmax), fabs(tmin));
    if (kconst && tmax - tmin <= tol * tbar)
        return IC_SHAPE_CIRCULAR_HELIX;
    if (tmin * tmax > 0 && rmax - rmin <= tol * fmax(fabs(rmax), fabs(rmin)))
        return IC_SHAPE_HELIX;
    return IC_SHAPE_GENERAL;
}
