/*
 * The found scale and coincident surfaces (docs/tracing.md, "Scale" and
 * "Coincident surfaces"); the problem's scale L itself is core/scale.c's.
 *
 * After the first search L shrinks to the bounding box of what that search
 * left: its start points and the cells it could not exclude (a parametric
 * surface may reach far beyond the intersection).
 *
 * Two surfaces coincide around a common point with parallel normals when
 * points of A around it, at distances L 2^-k in eight directions of the
 * tangent plane, lie on B within IC_TRACE_COINCIDENT_TOL L. A contact of
 * any finite order separates the surfaces by far more at L / 8.
 */
#include "core/trace_constants.h"
#include "trace_internal.h"
#include "common/mathconst.h"
#include "common/vec3.h"
#include "local/pair_access.h"
#include "surface/surface_access.h"

#include <math.h>
#include <string.h>

double ic_trace_found_scale(double L, const ic_candidate *c, int nc, const ic_unresolved *u,
                            int nu)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int i = 0; i < nc; i++)
        for (int k = 0; k < 3; k++)
            lo[k] = fmin(lo[k], c[i].xyz[k]), hi[k] = fmax(hi[k], c[i].xyz[k]);
    for (int i = 0; i < nu; i++)
        for (int k = 0; u[i].radius > 0 && k < 3; k++)
            lo[k] = fmin(lo[k], u[i].xyz[k] - u[i].radius),
            hi[k] = fmax(hi[k], u[i].xyz[k] + u[i].radius);
    double d2 = 0;
    for (int k = 0; k < 3; k++)
        d2 += hi[k] > lo[k] ? (hi[k] - lo[k]) * (hi[k] - lo[k]) : 0.0;
    const double F = sqrt(d2);
    /* never below a thousandth of the region: a lone point has no size */
    return isfinite(F) && F > 1e-3 * L && F < L ? F : L;
}

/* The distance from x to surface s (first order for an implicit one; a
 * Gauss-Newton closest point from uv for a parametric one); -1 when it
 * cannot be evaluated. */
static double distance_to(ic_surface *s, const double *x, const double *uv0,
                          const ic_jet_space *sp2, const ic_jet_space *sp3)
{
    double t[9];
    if (ic_surface_get_kind(s) == IC_IMPLICIT) {
        if (ic_surface_taylor(s, t, x, sp3, NULL) != IC_OK)
            return -1;
        const double g = sqrt(t[1] * t[1] + t[2] * t[2] + t[3] * t[3]);
        return g > 0 && isfinite(t[0]) ? fabs(t[0]) / g : -1;
    }
    double uv[2] = {uv0[0], uv0[1]}, d = -1;
    for (int it = 0; it < 20; it++) { /* normal equations of R(uv) ~ x */
        if (ic_surface_taylor(s, t, uv, sp2, NULL) != IC_OK)
            return -1;
        const double r[3] = {t[0] - x[0], t[3] - x[1], t[6] - x[2]};
        const double Ru[3] = {t[1], t[4], t[7]}, Rv[3] = {t[2], t[5], t[8]};
        const double a = ic_dot3(Ru, Ru), b = ic_dot3(Ru, Rv), c = ic_dot3(Rv, Rv);
        const double det = a * c - b * b, pu = ic_dot3(Ru, r), pv = ic_dot3(Rv, r);
        d = ic_norm3(r);
        if (!(det > 0))
            return -1;
        uv[0] -= (c * pu - b * pv) / det, uv[1] -= (a * pv - b * pu) / det;
    }
    return isfinite(d) ? d : -1;
}

/* A point of A at about distance rho from pt in direction theta of the
 * tangent plane: a parameter step on a parametric A, a step projected back
 * by Newton on an implicit one. 0 when it cannot be made. */
static int point_of_a(ic_surface *A, const ic_local_point *pt, double rho, double theta,
                      const ic_jet_space *sp2, const ic_jet_space *sp3, double *x)
{
    double t[9];
    if (ic_surface_get_kind(A) == IC_PARAMETRIC) {
        if (ic_surface_taylor(A, t, pt->params[0], sp2, NULL) != IC_OK)
            return 0;
        const double Ru[3] = {t[1], t[4], t[7]}, Rv[3] = {t[2], t[5], t[8]};
        const double su = rho * cos(theta) / ic_norm3(Ru), sv = rho * sin(theta) / ic_norm3(Rv);
        const double uv[2] = {pt->params[0][0] + su, pt->params[0][1] + sv};
        if (!isfinite(uv[0] + uv[1]) || ic_surface_taylor(A, t, uv, sp2, NULL) != IC_OK)
            return 0;
        x[0] = t[0], x[1] = t[3], x[2] = t[6];
        return isfinite(x[0] + x[1] + x[2]);
    }
    if (ic_surface_taylor(A, t, pt->xyz, sp3, NULL) != IC_OK)
        return 0;
    double n[3] = {t[1], t[2], t[3]}, e1[3], e2[3];
    ic_scale3(n, n, 1 / ic_norm3(n));
    ic_plane_basis3(n, e1, e2);
    for (int k = 0; k < 3; k++)
        x[k] = pt->xyz[k] + rho * (cos(theta) * e1[k] + sin(theta) * e2[k]);
    for (int it = 0; it < 8; it++) { /* back onto A along its gradient */
        if (ic_surface_taylor(A, t, x, sp3, NULL) != IC_OK)
            return 0;
        const double g2 = t[1] * t[1] + t[2] * t[2] + t[3] * t[3];
        if (!(g2 > 0))
            return 0;
        for (int k = 0; k < 3; k++)
            x[k] -= t[0] * t[1 + k] / g2;
    }
    return isfinite(x[0] + x[1] + x[2]);
}

int ic_trace_coincident_at(ic_pair *pair, const ic_local_point *pt, double L)
{
    if (ic_pair_is_self(pair))
        return 0;
    ic_surface *A = ic_pair_surface(pair, 0), *B = ic_pair_surface(pair, 1);
    ic_jet_space *sp2 = NULL, *sp3 = NULL;
    if (ic_jet_space_new(&sp2, 2, 1, NULL) != IC_OK || ic_jet_space_new(&sp3, 3, 1, NULL) != IC_OK) {
        ic_jet_space_free(sp2);
        return 0;
    }
    int samples = 0, on_b = 0;
    for (int k = 3; k <= 6; k++)
        for (int j = 0; j < 8; j++) {
            double x[3];
            if (!point_of_a(A, pt, L * ldexp(1.0, -k), j * 0.25 * IC_PI, sp2, sp3, x))
                continue;
            const double d = distance_to(B, x, pt->params[1], sp2, sp3);
            samples++;
            on_b += d >= 0 && d <= IC_TRACE_COINCIDENT_TOL * L;
        }
    ic_jet_space_free(sp2);
    ic_jet_space_free(sp3);
    /* at least half of the directions could be sampled, and all lie on B */
    return samples >= 16 && on_b == samples;
}
