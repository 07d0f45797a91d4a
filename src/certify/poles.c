/* The poles of the parametric sheets (certificate.h): domain edges whose
 * whole image is one point, found by the checker itself, and the strips of
 * parameters beside them whose image lies in the pole's singular box. */
#include "certificate.h"
#include "system.h"

#include <math.h>

/* Where sheet s's parameters start among the search coordinates: -1 when
 * it has none (an implicit sheet). */
static int first_coordinate(const ic_pairing *pg, int s)
{
    switch (pg->kind->dim) {
    case 2:
        return s == pg->P ? 0 : -1;
    case 4:
        return 2 * s;
    default:
        return -1;
    }
}

/* The image of sheet s over uv[2] within the box of half width h about p
 * (p NULL: its midpoint in p_out, and whether it lies within h of it). */
static int image_within(ic_surface *s, const ic_interval uv[2], const double *p, double h,
                        double p_out[3])
{
    ic_interval img[3];
    if (ic_surface_eval_interval(s, img, uv, NULL) != IC_OK)
        return 0;
    for (int i = 0; i < 3; i++) {
        if (!isfinite(img[i].lo) || !isfinite(img[i].hi))
            return 0;
        const double at = p ? p[i] : 0.5 * img[i].lo + 0.5 * img[i].hi;
        if (p_out)
            p_out[i] = at;
        if (!(img[i].lo >= at - h && img[i].hi <= at + h))
            return 0;
    }
    return 1;
}

/* The strip beside edge (k, side) of dom: the widest of the domain's width
 * halved whose image lies in the box of half width h about p (signed,
 * into the domain), or 0. */
static double strip_of(ic_surface *s, const double dom[2][2], int k, int side, const double *p,
                       double h)
{
    double w = dom[k][1] - dom[k][0];
    for (int it = 0; it < IC_CERTIFY_POLE_HALVINGS; it++, w *= 0.5) {
        ic_interval uv[2];
        uv[!k] = (ic_interval){dom[!k][0], dom[!k][1]};
        uv[k] = side ? (ic_interval){dom[k][1] - w, dom[k][1]}
                     : (ic_interval){dom[k][0], dom[k][0] + w};
        if (image_within(s, uv, p, h, NULL))
            return side ? -w : w;
    }
    return 0.0;
}

/* Pole edges of sheet s, appended to c->poles. */
static void sheet_poles(ic_certificate *c, int s, double size)
{
    const int j0 = first_coordinate(c->pg, s);
    if (j0 < 0)
        return;
    ic_surface *S = c->pg->S[s];
    double dom[2][2];
    int periodic[2];
    ic_surface_get_domain(S, dom, periodic);
    for (int k = 0; k < 2; k++)
        for (int side = 0; side < 2 && c->npoles < IC_CERTIFY_MAX_POLES; side++) {
            ic_interval edge[2];
            edge[k] = (ic_interval){dom[k][side], dom[k][side]};
            edge[!k] = (ic_interval){dom[!k][0], dom[!k][1]};
            double p[3];
            if (periodic[k] || !image_within(S, edge, NULL, IC_CERTIFY_POLE_SPREAD * size, p))
                continue;
            const double strip = strip_of(S, dom, k, side, p, c->singular_half);
            if (strip == 0.0)
                continue;
            c->poles[c->npoles].j = j0 + k;
            c->poles[c->npoles].edge = dom[k][side];
            c->poles[c->npoles].strip = strip;
            for (int i = 0; i < 3; i++)
                c->poles[c->npoles].xyz[i] = p[i];
            c->npoles++;
        }
}

void ic_certificate_find_poles(ic_certificate *c)
{
    const double size = c->singular_half / IC_CERTIFY_SINGULAR_HALF;
    c->npoles = 0;
    for (int s = 0; s < 2; s++)
        sheet_poles(c, s, size);
}

int ic_certificate_pole_split(const ic_certificate *c, long i, double *at)
{
    const ic_cell *cl = &c->cells[i];
    for (int p = 0; p < c->npoles; p++) {
        const int j = c->poles[p].j;
        const double edge = c->poles[p].edge, other = edge + c->poles[p].strip;
        const int from_edge = c->poles[p].strip > 0 ? cl->lo[j] == edge : cl->hi[j] == edge;
        if (from_edge && other > cl->lo[j] && other < cl->hi[j]) {
            *at = other;
            return j;
        }
    }
    return -1;
}
