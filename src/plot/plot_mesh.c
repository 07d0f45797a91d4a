/*
 * Surface meshes for the pictures. Parametric: a grid over the domain, two
 * triangles a cell, cut to the box when there is one. Implicit: marching
 * tetrahedra on a grid of the box (each cube split into the six Kuhn
 * tetrahedra along its main diagonal, so neighbouring cubes agree on their
 * faces), the surface crossing each edge where f changes sign placed by
 * linear interpolation.
 */
#include "plot_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static int push(plot_mesh *m, const double *a, const double *b, const double *c, int surface)
{
    if (m->n == m->cap) {
        const int cap = m->cap ? 2 * m->cap : 1024;
        plot_tri *t = realloc(m->t, (size_t)cap * sizeof *t);
        if (!t)
            return -1;
        m->t = t;
        m->cap = cap;
    }
    plot_tri *t = &m->t[m->n++];
    memcpy(t->v[0], a, 3 * sizeof *a);
    memcpy(t->v[1], b, 3 * sizeof *b);
    memcpy(t->v[2], c, 3 * sizeof *c);
    t->surface = surface;
    return 0;
}

static int inside_box(const double box[3][2], const double *a, const double *b, const double *c)
{
    if (!box)
        return 1;
    for (int k = 0; k < 3; k++) {
        const double m = (a[k] + b[k] + c[k]) / 3, w = 0.02 * (box[k][1] - box[k][0]);
        if (m < box[k][0] - w || m > box[k][1] + w)
            return 0;
    }
    return 1;
}

static ic_status parametric_mesh(plot_mesh *mesh, ic_surface *s, int which, const double box[3][2],
                                 int cells, ic_error *err)
{
    double dom[2][2];
    int per[2];
    ic_surface_get_domain(s, dom, per);
    for (int i = 0; i < 2; i++)
        if (!isfinite(dom[i][0]) || !isfinite(dom[i][1]))
            return ic_error_set(err, IC_ERR_INVALID, 0,
                                "plotting surface %c needs a finite \"domain\"", 'A' + which);
    const int n = cells + 1;
    double(*P)[3] = malloc((size_t)n * (size_t)n * sizeof *P);
    char *ok = malloc((size_t)n * (size_t)n);
    if (!P || !ok) {
        free(P);
        free(ok);
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory meshing a surface");
    }
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            const double uv[2] = {dom[0][0] + (dom[0][1] - dom[0][0]) * i / cells,
                                  dom[1][0] + (dom[1][1] - dom[1][0]) * j / cells};
            ok[i * n + j] = ic_surface_eval(s, P[i * n + j], uv, NULL) == IC_OK;
        }
    ic_status st = IC_OK;
    for (int i = 0; i < cells && st == IC_OK; i++)
        for (int j = 0; j < cells && st == IC_OK; j++) {
            const int a = i * n + j, b = a + n, c = a + n + 1, d = a + 1;
            if (!ok[a] || !ok[b] || !ok[c] || !ok[d])
                continue;
            if ((inside_box(box, P[a], P[b], P[c]) && push(mesh, P[a], P[b], P[c], which)) ||
                (inside_box(box, P[a], P[c], P[d]) && push(mesh, P[a], P[c], P[d], which)))
                st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory meshing a surface");
        }
    free(P);
    free(ok);
    return st;
}

/* The point on edge (a, b) where the linear interpolant of f vanishes. */
static void edge_point(double *out, const double *a, const double *b, double fa, double fb)
{
    const double t = fa / (fa - fb);
    for (int k = 0; k < 3; k++)
        out[k] = a[k] + t * (b[k] - a[k]);
}

/* The surface's piece in one tetrahedron. */
static int tetrahedron(plot_mesh *m, const double (*p)[3], const double *f, int which)
{
    int neg[4], pos[4], nn = 0, np = 0;
    for (int i = 0; i < 4; i++) {
        if (!isfinite(f[i]))
            return 0;
        if (f[i] < 0)
            neg[nn++] = i;
        else
            pos[np++] = i;
    }
    if (nn == 0 || np == 0)
        return 0;
    double q[4][3];
    if (nn == 1 || np == 1) { /* one vertex apart: a triangle */
        const int lone = nn == 1 ? neg[0] : pos[0];
        const int *others = nn == 1 ? pos : neg;
        for (int k = 0; k < 3; k++)
            edge_point(q[k], p[lone], p[others[k]], f[lone], f[others[k]]);
        return push(m, q[0], q[1], q[2], which);
    }
    /* two and two: a quadrilateral, in cyclic order */
    edge_point(q[0], p[neg[0]], p[pos[0]], f[neg[0]], f[pos[0]]);
    edge_point(q[1], p[neg[0]], p[pos[1]], f[neg[0]], f[pos[1]]);
    edge_point(q[2], p[neg[1]], p[pos[1]], f[neg[1]], f[pos[1]]);
    edge_point(q[3], p[neg[1]], p[pos[0]], f[neg[1]], f[pos[0]]);
    return push(m, q[0], q[1], q[2], which) || push(m, q[0], q[2], q[3], which);
}

static ic_status implicit_mesh(plot_mesh *mesh, ic_surface *s, int which, const double box[3][2],
                               int cells, ic_error *err)
{
    const int n = cells + 1;
    double *F = malloc((size_t)n * n * n * sizeof *F);
    if (!F)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory meshing a surface");
    double h[3];
    for (int k = 0; k < 3; k++)
        h[k] = (box[k][1] - box[k][0]) / cells;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++)
            for (int l = 0; l < n; l++) {
                const double x[3] = {box[0][0] + i * h[0], box[1][0] + j * h[1],
                                     box[2][0] + l * h[2]};
                double f;
                F[(i * n + j) * n + l] = ic_surface_eval(s, &f, x, NULL) == IC_OK ? f : NAN;
            }
    /* the six tetrahedra: from corner 000 to 111 along the axes in each order */
    static const int ORDER[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2},
                                    {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    ic_status st = IC_OK;
    for (int i = 0; i < cells && st == IC_OK; i++)
        for (int j = 0; j < cells && st == IC_OK; j++)
            for (int l = 0; l < cells && st == IC_OK; l++)
                for (int t = 0; t < 6 && st == IC_OK; t++) {
                    int c[3] = {i, j, l};
                    double p[4][3], f[4];
                    for (int v = 0; v < 4; v++) {
                        if (v > 0)
                            c[ORDER[t][v - 1]]++;
                        for (int k = 0; k < 3; k++)
                            p[v][k] = box[k][0] + c[k] * h[k];
                        f[v] = F[(c[0] * n + c[1]) * n + c[2]];
                    }
                    if (tetrahedron(mesh, (const double(*)[3])p, f, which))
                        st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory meshing a surface");
                }
    free(F);
    return st;
}

ic_status ic_plot_mesh_extent(ic_surface *s, const double box[3][2], int cells, double ext[3][2],
                           int *found, ic_error *err)
{
    plot_mesh coarse = {NULL, 0, 0};
    const ic_status st = implicit_mesh(&coarse, s, 0, box, cells, err);
    *found = st == IC_OK && coarse.n > 0;
    for (int k = 0; k < 3 && *found; k++) {
        ext[k][0] = INFINITY, ext[k][1] = -INFINITY;
        for (int i = 0; i < coarse.n; i++)
            for (int v = 0; v < 3; v++)
                ext[k][0] = fmin(ext[k][0], coarse.t[i].v[v][k]),
                ext[k][1] = fmax(ext[k][1], coarse.t[i].v[v][k]);
    }
    free(coarse.t);
    return st;
}

ic_status ic_plot_mesh_surface(plot_mesh *mesh, ic_surface *s, int which, const double box[3][2],
                            int cells, ic_error *err)
{
    if (ic_surface_get_kind(s) == IC_PARAMETRIC)
        return parametric_mesh(mesh, s, which, box, cells, err);
    if (!box)
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            "plotting the implicit surface %c needs a \"box\"", 'A' + which);
    /* a coarse pass finds where the surface is in the box; the mesh is made
     * there (a small sphere in a large box gets all the cells) */
    const int coarse_cells = cells / 2 > 4 ? cells / 2 : 4;
    double ext[3][2], sub[3][2];
    int found;
    const ic_status st = ic_plot_mesh_extent(s, box, coarse_cells, ext, &found, err);
    if (st != IC_OK || !found)
        return st;
    for (int k = 0; k < 3; k++) {
        const double cell = (box[k][1] - box[k][0]) / coarse_cells;
        sub[k][0] = fmax(box[k][0], ext[k][0] - cell);
        sub[k][1] = fmin(box[k][1], ext[k][1] + cell);
    }
    return implicit_mesh(mesh, s, which, (const double(*)[2])sub, cells, err);
}
