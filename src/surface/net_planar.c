/* Planar affine nets (net_shape.h; docs/nurbs.md, "Recognised nets"): one
 * weight for all (a polynomial patch) and control points P_ij = O + f_i E1
 * + g_j E2 on a grid, E1, E2 unit and not parallel. Then S = O + f(u) E1 +
 * g(v) E2 with f = sum N_i f_i, g = sum M_j g_j (the bases sum to 1). With
 * f and g strictly monotone (the Bernstein coefficients of their
 * derivatives on every span, net_pieces.c) the patch is exactly the
 * parallelogram O + [f(u0), f(u1)] E1 + [g(v0), g(v1)] E2, and one to one
 * onto it. */
#include "net_shape.h"
#include "common/vec3.h"

#include <math.h>
#include <string.h>

/* sine of the angle between E1 and E2: a parallelogram flatter than this
 * is too ill-conditioned to invert (and no CAD plane is) */
#define NET_MIN_SINE 1e-6

static void point(const ic_nurbs_patch *pt, int i, int j, double P[3])
{
    const double *h = pt->hom + 4 * (i * pt->n[1] + j);
    for (int k = 0; k < 3; k++)
        P[k] = h[k] / h[3];
}

/* The edge from P_00 along dir: its unit direction E and the coordinates
 * of its control points along it (into the curve), each within tol of the
 * line. */
static int edge(const ic_nurbs_patch *pt, int dir, double tol, double E[3], ic_net_curve *c)
{
    double O[3], P[3], w[3];
    point(pt, 0, 0, O);
    const int n = pt->n[dir];
    point(pt, dir == 0 ? n - 1 : 0, dir == 0 ? 0 : n - 1, P);
    ic_axpy3(E, P, -1.0, O);
    if (!(ic_normalize3(E) > tol))
        return 0;
    for (int i = 0; i < n; i++) {
        point(pt, dir == 0 ? i : 0, dir == 0 ? 0 : i, P);
        ic_axpy3(w, P, -1.0, O);
        const double f = ic_dot3(w, E);
        ic_axpy3(w, w, -f, E);
        if (!(ic_norm3(w) <= tol))
            return 0;
        c->hom[i][0] = f, c->hom[i][1] = 0, c->hom[i][2] = 1;
    }
    return 1;
}

/* Every control point on the grid O + f_i E1 + g_j E2. */
static int on_grid(const ic_nurbs_patch *pt, const ic_net_shape *sh, double tol)
{
    double O[3], P[3], m[3];
    point(pt, 0, 0, O);
    for (int i = 0; i < pt->n[0]; i++)
        for (int j = 0; j < pt->n[1]; j++) {
            point(pt, i, j, P);
            ic_axpy3(m, O, sh->curve[0].hom[i][0], sh->E[0]);
            ic_axpy3(m, m, sh->curve[1].hom[j][0], sh->E[1]);
            ic_axpy3(m, P, -1.0, m);
            if (!(ic_norm3(m) <= tol))
                return 0;
        }
    return 1;
}

/* The parallelogram, the plane primitive and its frame. */
static void parallelogram(const ic_nurbs_patch *pt, ic_net_shape *sh)
{
    double O[3], f[2][2];
    point(pt, 0, 0, O);
    for (int d = 0; d < 2; d++) {
        const ic_net_pieces *pc = &sh->pieces[d];
        f[d][0] = pc->pos[0], f[d][1] = pc->pos[pc->n];
        ic_scale3(sh->edge[d], sh->E[d], f[d][1] - f[d][0]);
    }
    ic_axpy3(sh->corner, O, f[0][0], sh->E[0]);
    ic_axpy3(sh->corner, sh->corner, f[1][0], sh->E[1]);
    memcpy(sh->frame[0], sh->E[0], sizeof sh->frame[0]);
    ic_cross3(sh->frame[2], sh->E[0], sh->E[1]);
    ic_normalize3(sh->frame[2]);
    ic_cross3(sh->frame[1], sh->frame[2], sh->frame[0]);
    ic_primitive *p = &sh->prim;
    memset(p, 0, sizeof *p);
    p->kind = IC_PRIM_PLANE;
    ic_axpy3(p->center, sh->corner, 0.5, sh->edge[0]);
    ic_axpy3(p->center, p->center, 0.5, sh->edge[1]);
    memcpy(p->normal, sh->frame[2], sizeof p->normal);
    memcpy(p->ref_direction, sh->frame[0], sizeof p->ref_direction);
}

int ic_net_recognize_planar(const ic_nurbs_patch *pt, ic_net_shape *sh)
{
    const double tol = IC_NET_REL * sh->size, origin[2] = {0, 0}, along[2] = {1, 0};
    if (pt->rational)
        return 1;
    for (int d = 0; d < 2; d++)
        if (ic_net_curve_alloc(&sh->curve[d], pt->p[d], pt->n[d], pt->knots[d]) != 0)
            return -1;
    if (!edge(pt, 0, tol, sh->E[0], &sh->curve[0]) || !edge(pt, 1, tol, sh->E[1], &sh->curve[1]))
        return 1;
    double cr[3];
    ic_cross3(cr, sh->E[0], sh->E[1]);
    if (!(ic_norm3(cr) > NET_MIN_SINE) || !on_grid(pt, sh, tol))
        return 1;
    for (int d = 0; d < 2; d++) {
        const int st =
            ic_net_pieces_make(&sh->pieces[d], &sh->curve[d], IC_NET_ALONG, origin, along);
        if (st != 0)
            return st;
    }
    parallelogram(pt, sh);
    return 0;
}
