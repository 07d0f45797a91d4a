/* Where a circle of an exact path crosses the knot lines of the recognised
 * patches (exact_circle.h): on a revolved patch about the circle's axis the
 * lines of its turning parameter are meridians, crossed at the angles the
 * patch's circle has at its knots (and its seam, where the parameter
 * wraps); on a planar patch they are straight lines of the plane, met
 * where a quadratic says. A revolved patch's profile lines are parallels:
 * the circle is one of them or crosses none. */
#include "exact_circle.h"
#include "exact_profile.h"
#include "common/mathconst.h"
#include "common/vec3.h"

#include <math.h>
#include <stdlib.h>

int ic_exact_mark_add(ic_exact_marks *k, double phi, int sheet, int dir, int seam, double value)
{
    if (k->n == k->cap) {
        const int cap = 2 * k->cap + 8;
        ic_exact_knot *m = realloc(k->m, sizeof *m * (size_t)cap);
        if (!m)
            return -1;
        k->m = m, k->cap = cap;
    }
    phi = fmod(phi, 2 * IC_PI);
    k->m[k->n++] = (ic_exact_knot){phi < 0 ? phi + 2 * IC_PI : phi, sheet, dir, seam, value};
    return 0;
}

void ic_exact_knot_snap(const ic_exact_source *src, const ic_exact_knot *k, double *t)
{
    double dom[2][2];
    int periodic[2];
    ic_surface_get_domain(src->surface, dom, periodic);
    const double period = dom[k->dir][1] - dom[k->dir][0];
    if (!periodic[k->dir]) {
        *t = k->value;
        return;
    }
    const double r = round((*t - k->value) / period);
    *t = r == 1 && k->seam ? dom[k->dir][1] : k->value + r * period;
}

/* A revolved patch: its circle's angle at every interior knot (the ends of
 * its spans among its pieces) and at its seam where it wraps. */
static int revolved_knots(const ic_exact_source *src, int sheet, double theta0, int way,
                          ic_exact_marks *k)
{
    const ic_net_shape *sh = src->net;
    const ic_net_pieces *pc = &sh->pieces[0];
    double dom[2][2];
    int periodic[2];
    ic_surface_get_domain(src->surface, dom, periodic);
    if (periodic[sh->around] &&
        ic_exact_mark_add(k, -way * theta0, sheet, sh->around, 1, pc->t[0]) != 0)
        return -1;
    for (int i = 1; i < pc->n; i++)
        if (pc->span[i] != pc->span[i - 1] &&
            ic_exact_mark_add(k, way * (pc->pos[i] - theta0), sheet, sh->around, 0, pc->t[i]) != 0)
            return -1;
    return 0;
}

/* A planar patch: the lines f(u) = f(kappa) (g(v) = g(kappa)) of its
 * distinct interior knots against the circle. 1 where one nearly touches
 * it: rho^2 - d^2 (d its distance from the centre; the square of half
 * its chord) within (IC_EXACT_NEAR L)^2 of 0. */
static int planar_knots(const ic_exact_circle *c, const ic_exact_source *src, int sheet, double L,
                        ic_exact_marks *k)
{
    const ic_net_shape *sh = src->net;
    for (int d = 0; d < 2; d++) {
        const ic_net_curve *cv = &sh->curve[d];
        const double *kn = cv->knots, f0 = sh->pieces[d].pos[0], *Eo = sh->E[1 - d];
        for (int i = cv->p + 1; i < cv->n; i++) {
            if (!(kn[i] > kn[cv->p] && kn[i] < kn[cv->n]) || kn[i] == kn[i - 1])
                continue;
            double f[2], w[3];
            ic_net_curve_point(cv, kn[i], f);
            ic_axpy3(w, sh->corner, f[0] - f0, sh->E[d]);
            ic_axpy3(w, w, -1.0, c->centre);
            /* |w + beta Eo|^2 = rho^2 */
            const double b = ic_dot3(w, Eo), disc = b * b - (ic_dot3(w, w) - c->rho * c->rho);
            const double near = IC_EXACT_NEAR * L;
            if (fabs(disc) <= near * near)
                return 1;
            for (int sg = -1; disc > 0 && sg <= 1; sg += 2) {
                double r[3];
                ic_axpy3(r, w, -b + sg * sqrt(disc), Eo);
                if (ic_exact_mark_add(k, atan2(ic_dot3(r, c->v), ic_dot3(r, c->u)), sheet, d, 0,
                                      kn[i]) != 0)
                    return -1;
            }
        }
    }
    return 0;
}

int ic_exact_circle_knots(const ic_exact_circle *c, const ic_exact_source src[2],
                          const double theta0[2], const int way[2], ic_exact_knot **out, int *n,
                          double L)
{
    ic_exact_marks k = {NULL, 0, 0};
    int st = 0;
    for (int s = 0; s < 2 && st == 0; s++) {
        if (!src[s].net)
            continue;
        st = src[s].net->kind == IC_NET_PLANAR ? planar_knots(c, &src[s], s, L, &k)
                                               : revolved_knots(&src[s], s, theta0[s], way[s], &k);
    }
    if (st != 0) {
        free(k.m);
        return st;
    }
    *out = k.m;
    *n = k.n;
    return 0;
}
