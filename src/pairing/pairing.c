/* Building a pairing and what its kinds share (pairing.h). */
#include "pairing.h"
#include "common/vec3.h"

#include <math.h>
#include <string.h>

ic_status ic_pairing_init(ic_pairing *p, ic_surface *A, ic_surface *B, int self, ic_error *err)
{
    memset(p, 0, sizeof *p);
    p->S[0] = A;
    p->S[1] = B;
    p->par[0] = ic_surface_get_kind(A) == IC_PARAMETRIC;
    p->par[1] = ic_surface_get_kind(B) == IC_PARAMETRIC;
    p->P = p->par[0] ? 0 : 1;
    p->I = 1 - p->P;
    if (self)
        p->kind = &ic_pairing_self;
    else if (p->par[0] && p->par[1])
        p->kind = &ic_pairing_params;
    else if (p->par[0] || p->par[1])
        p->kind = &ic_pairing_mixed;
    else
        p->kind = &ic_pairing_implicit;
    ic_status st = ic_jet_space_new(&p->sp2, 2, 1, err);
    if (st == IC_OK)
        st = ic_jet_space_new(&p->sp3, 3, 1, err);
    p->glue.axis = -1;
    if (st == IC_OK && self)
        ic_pairing_find_glue(p);
    if (st != IC_OK)
        ic_pairing_release(p);
    return st;
}

void ic_pairing_release(ic_pairing *p)
{
    ic_jet_space_free(p->sp2);
    ic_jet_space_free(p->sp3);
    p->sp2 = p->sp3 = NULL;
}

int ic_pairing_excludes_zero(ic_interval a)
{
    return ic_interval_is_empty(a) || a.lo > 0 || a.hi < 0;
}

int ic_pairing_unbounded(ic_interval a) { return !(isfinite(a.lo) && isfinite(a.hi)); }

int ic_pairing_value_grad(ic_surface *s, const ic_jet_space *sp, const double *x, double *f,
                          double *g)
{
    double t[4];
    if (ic_surface_taylor(s, t, x, sp, NULL) != IC_OK)
        return -1;
    const double m = fmax(fabs(t[1]), fmax(fabs(t[2]), fabs(t[3])));
    if (!(m > 0) || !isfinite(m))
        return -1;
    *f = t[0] / m;
    g[0] = t[1] / m, g[1] = t[2] / m, g[2] = t[3] / m;
    return 0;
}

ic_status ic_pairing_domain_box(const ic_pairing *p, int s, double lo[2], double hi[2],
                                int periodic[2], ic_error *err)
{
    double dom[2][2];
    ic_surface_get_domain(p->S[s], dom, periodic);
    for (int i = 0; i < 2; i++) {
        if (!isfinite(dom[i][0]) || !isfinite(dom[i][1]) || !isfinite(dom[i][1] - dom[i][0]))
            return ic_error_set(err, IC_ERR_INVALID, 0,
                                "tracing needs a finite \"domain\" for the parametric surface %c "
                                "(surfaces[%d] of a problem file)",
                                'A' + s, s);
        lo[i] = dom[i][0], hi[i] = dom[i][1];
    }
    return IC_OK;
}

int ic_pairing_enclose_sheet(const ic_pairing *p, int s, const ic_interval *in, ic_interval *out)
{
    return ic_surface_eval_interval(p->S[s], out, in, NULL) == IC_OK;
}

/* Where the sheet cannot be evaluated at the centre (a kink, a pole) the
 * interval enclosure of the cell's image places it; where neither works
 * the radius stays 0 (the cell is then never counted as covered). */
void ic_pairing_place_sheet(const ic_pairing *p, int s, const double *lo, const double *hi,
                            double xyz[3], double *radius)
{
    const double uvc[2] = {0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])};
    double t[9];
    if (ic_surface_taylor(p->S[s], t, uvc, p->sp2, NULL) == IC_OK &&
        isfinite(t[0] + t[3] + t[6])) {
        const double Ru[3] = {t[1], t[4], t[7]}, Rv[3] = {t[2], t[5], t[8]};
        xyz[0] = t[0], xyz[1] = t[3], xyz[2] = t[6];
        *radius = (hi[0] - lo[0]) * ic_norm3(Ru) + (hi[1] - lo[1]) * ic_norm3(Rv);
        if (isfinite(*radius))
            return;
    }
    const ic_interval box[2] = {{lo[0], hi[0]}, {lo[1], hi[1]}};
    ic_interval X[3];
    *radius = 0.0;
    if (ic_surface_eval_interval(p->S[s], X, box, NULL) != IC_OK)
        return;
    double half[3];
    for (int k = 0; k < 3; k++) {
        xyz[k] = 0.5 * (X[k].lo + X[k].hi);
        half[k] = 0.5 * (X[k].hi - X[k].lo);
    }
    const double r = 2 * ic_norm3(half);
    *radius = isfinite(r) && isfinite(ic_norm3(xyz)) ? r : 0.0;
}

/* The box around the point: `rel` of each parametric coordinate's domain
 * width (the kind's search region) on either side. */
int ic_pairing_point_may_degenerate(const ic_pairing *p, const double xyz[3],
                                    const double params[2][2], double rel)
{
    double z[4], lo[4], hi[4], dlo[4], dhi[4];
    int periodic[4];
    const double box[3][2] = {{xyz[0], xyz[0]}, {xyz[1], xyz[1]}, {xyz[2], xyz[2]}};
    if (p->kind->region(p, box, 1, dlo, dhi, periodic, NULL) != IC_OK)
        return 0;
    p->kind->flatten(p, xyz, params, z);
    for (int k = 0; k < p->kind->dim; k++) {
        const double half = rel * (dhi[k] - dlo[k]);
        lo[k] = z[k] - half, hi[k] = z[k] + half;
    }
    return p->kind->may_degenerate(p, lo, hi);
}

int ic_pairing_gap_may_degenerate(const ic_pairing *p, const double xyz_a[3],
                                  const double params_a[2][2], const double xyz_b[3],
                                  const double params_b[2][2])
{
    double za[4], zb[4], lo[4], hi[4], dlo[4], dhi[4];
    int periodic[4];
    const double box[3][2] = {{xyz_a[0], xyz_a[0]}, {xyz_a[1], xyz_a[1]}, {xyz_a[2], xyz_a[2]}};
    if (p->kind->region(p, box, 1, dlo, dhi, periodic, NULL) != IC_OK)
        return 0;
    p->kind->flatten(p, xyz_a, params_a, za);
    p->kind->flatten(p, xyz_b, params_b, zb);
    /* the march stops short of a pole by a step or so on either side: the
     * hull grown by its own size each way reaches it; a periodic parameter
     * the short way round (not across the whole period) */
    for (int k = 0; k < p->kind->dim; k++) {
        const double T = periodic[k] ? dhi[k] - dlo[k] : 0.0;
        if (T > 0.0)
            zb[k] += T * nearbyint((za[k] - zb[k]) / T);
        const double d = fabs(za[k] - zb[k]);
        lo[k] = fmin(za[k], zb[k]) - d, hi[k] = fmax(za[k], zb[k]) + d;
    }
    return p->kind->may_degenerate(p, lo, hi);
}

ic_status ic_pairing_sheet_eval1(const ic_pairing *p, int s, const double *uv, double R[3],
                                 double Ru[3], double Rv[3], ic_error *err)
{
    double t[9]; /* order 1: 1, u, v per component */
    ic_status st = ic_surface_taylor(p->S[s], t, uv, p->sp2, err);
    if (st != IC_OK)
        return st;
    for (int k = 0; k < 3; k++)
        R[k] = t[3 * k], Ru[k] = t[3 * k + 1], Rv[k] = t[3 * k + 2];
    return IC_OK;
}

ic_status ic_pairing_implicit_eval1(const ic_pairing *p, int s, const double *x, double *f,
                                    double grad[3], double *gnorm, ic_error *err)
{
    double t[4];
    ic_status st = ic_surface_taylor(p->S[s], t, x, p->sp3, err);
    if (st != IC_OK)
        return st;
    *f = t[0];
    grad[0] = t[1], grad[1] = t[2], grad[2] = t[3];
    *gnorm = ic_norm3(grad);
    if (!(*gnorm > 0))
        return ic_error_set(err, IC_ERR_DOMAIN, 0, "grad f = 0 on the intersection");
    return IC_OK;
}

void ic_pairing_step_sheet(const ic_pairing *p, int s, double *uv, const double *duv)
{
    double domain[2][2];
    int periodic[2];
    ic_surface_get_domain(p->S[s], domain, periodic);
    for (int i = 0; i < 2; i++) {
        uv[i] -= duv[i];
        if (periodic[i]) { /* back into the period */
            const double w = domain[i][1] - domain[i][0];
            uv[i] = domain[i][0] + fmod(fmod(uv[i] - domain[i][0], w) + w, w);
        }
    }
}
