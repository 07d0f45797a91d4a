/*
 * Singular points of a surface itself met by a curve: a point of an
 * implicit surface where grad f = 0, a cone's apex. The intersection
 * curves through it are not tangential there (a normal does not exist),
 * so the tangential locators cannot find it: Newton on grad f = 0 from the
 * curve's end does, with the Hessian from differences of the exact
 * gradient. The point is recorded with the type "surface-singular", and
 * the curve ends there are joined through it like those at a branch point.
 */
#include "trace_internal.h"
#include "common/vec3.h"

#include <math.h>
#include <string.h>

/* relative (of L): the differences of the gradient that give the Hessian */
#define HESSIAN_STEP 1e-6
/* relative: grad f at the point, against its size at the curve's end */
#define FLAT_GRADIENT 1e-6

static int gradient(ic_surface *s, const ic_jet_space *sp, const double *x, double *f, double *g)
{
    double t[4];
    if (ic_surface_taylor(s, t, x, sp, NULL) != IC_OK || !isfinite(t[0] + t[1] + t[2] + t[3]))
        return -1;
    *f = t[0];
    g[0] = t[1], g[1] = t[2], g[2] = t[3];
    return 0;
}

/* Solves the 3 x 3 system H d = -g (Cramer); 0 when singular. */
static int solve3(double H[3][3], const double *g, double *d)
{
    const double det = ic_det3(H[0], H[1], H[2]);
    if (!(fabs(det) > 0) || !isfinite(det))
        return 0;
    double c[3][3];
    for (int k = 0; k < 3; k++) {
        memcpy(c, H, sizeof c);
        for (int i = 0; i < 3; i++)
            c[i][k] = -g[i];
        d[k] = ic_det3(c[0], c[1], c[2]) / det;
    }
    return 1;
}

/* Newton on grad f = 0 of implicit surface s from x (within reach): 1 with
 * the point in x when grad f vanishes there relative to g0. */
static int flat_point(ic_surface *s, const ic_jet_space *sp, double L, double g0, double reach,
                      double *x)
{
    const double start[3] = {x[0], x[1], x[2]};
    for (int it = 0; it < 30; it++) {
        double f, g[3], H[3][3], d[3];
        if (gradient(s, sp, x, &f, g) != 0)
            return 0;
        if (ic_norm3(g) <= FLAT_GRADIENT * g0)
            break;
        const double h = HESSIAN_STEP * L;
        for (int k = 0; k < 3; k++) { /* central differences: column k */
            double xp[3], xm[3], gp[3], gm[3], fp, fm;
            memcpy(xp, x, sizeof xp), memcpy(xm, x, sizeof xm);
            xp[k] += h, xm[k] -= h;
            if (gradient(s, sp, xp, &fp, gp) != 0 || gradient(s, sp, xm, &fm, gm) != 0)
                return 0;
            for (int i = 0; i < 3; i++)
                H[i][k] = (gp[i] - gm[i]) / (2 * h);
        }
        if (!solve3(H, g, d))
            return 0;
        ic_axpy3(x, x, 1.0, d);
    }
    double f, g[3], e[3];
    ic_axpy3(e, x, -1.0, start);
    return gradient(s, sp, x, &f, g) == 0 && ic_norm3(g) <= FLAT_GRADIENT * g0 &&
           ic_norm3(e) <= reach && fabs(f) <= FLAT_GRADIENT * g0 * L;
}

int ic_trace_locate_surface_singular(ic_pair *pair, const double *near, double L, double *out)
{
    ic_jet_space *sp = NULL;
    if (ic_jet_space_new(&sp, 3, 1, NULL) != IC_OK)
        return 0;
    int found = 0;
    for (int s = 0; s < 2 && !found; s++) {
        ic_surface *S = ic_pair_surface(pair, s);
        if (ic_surface_get_kind(S) != IC_IMPLICIT)
            continue;
        double f, g[3], x[3] = {near[0], near[1], near[2]};
        if (gradient(S, sp, x, &f, g) != 0 || !(ic_norm3(g) > 0))
            continue;
        /* the other surface must pass there too */
        ic_surface *O = ic_pair_surface(pair, 1 - s);
        double fo, go[3];
        found = flat_point(S, sp, L, ic_norm3(g), 1e-2 * L, x) && ic_surface_get_kind(O) == IC_IMPLICIT &&
                gradient(O, sp, x, &fo, go) == 0 && ic_norm3(go) > 0 &&
                fabs(fo) / ic_norm3(go) <= 1e-10 * L;
        if (found)
            memcpy(out, x, sizeof x);
    }
    ic_jet_space_free(sp);
    return found;
}
