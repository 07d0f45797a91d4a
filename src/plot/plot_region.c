/*
 * What the 3D panel shows: the region drawn (the box the camera fits and the
 * implicit surfaces are meshed in) and the length of the Frenet arrows
 * (docs/plots.md, "The region drawn" and "Frenet frames").
 */
#include "plot_internal.h"

#include <math.h>
#include <string.h>

/* The smallest side of a region, in the problem's length unit: a region
 * around a single point still has a size. */
#define PLOT_REGION_MIN_SIDE 1e-3

static void grow(double lo[3], double hi[3], const double *p)
{
    for (int k = 0; k < 3; k++)
        lo[k] = fmin(lo[k], p[k]), hi[k] = fmax(hi[k], p[k]);
}

/* The bounding box of the parametric meshes and the traced curves; 0 when
 * there is nothing to bound. */
static int drawn_extent(double lo[3], double hi[3], const plot_mesh *mesh,
                        const ic_trace_result *tr)
{
    for (int k = 0; k < 3; k++)
        lo[k] = INFINITY, hi[k] = -INFINITY;
    for (int i = 0; i < mesh->n; i++)
        for (int v = 0; v < 3; v++)
            grow(lo, hi, mesh->t[i].v[v]);
    for (int c = 0; tr && c < ic_trace_result_num_curves(tr); c++) {
        const ic_trace_curve *cv = ic_trace_result_curve(tr, c);
        for (int p = 0; p < cv->npoints; p++)
            grow(lo, hi, cv->points[p].xyz);
    }
    return hi[0] >= lo[0] && hi[1] >= lo[1] && hi[2] >= lo[2];
}

static double largest_side(const double lo[3], const double hi[3])
{
    return fmax(fmax(hi[0] - lo[0], hi[1] - lo[1]), hi[2] - lo[2]);
}

/* Grows [lo, hi] by the extent of the implicit surface s inside `reach`,
 * face by face, only where the surface closes before that face of reach
 * (stays more than half a grid cell inside it): an unbounded plane or
 * cylinder does not stretch the picture to the end of the search. */
static ic_status grow_by_implicit(double lo[3], double hi[3], ic_surface *s,
                                  const double reach[3][2], int cells, ic_error *err)
{
    double ext[3][2];
    int found;
    const ic_status st = ic_plot_mesh_extent(s, reach, cells, ext, &found, err);
    if (st != IC_OK || !found)
        return st;
    for (int k = 0; k < 3; k++) {
        const double half_cell = 0.5 * (reach[k][1] - reach[k][0]) / cells;
        if (ext[k][0] > reach[k][0] + half_cell)
            lo[k] = fmin(lo[k], ext[k][0]);
        if (ext[k][1] < reach[k][1] - half_cell)
            hi[k] = fmax(hi[k], ext[k][1]);
    }
    return IC_OK;
}

ic_status ic_plot_region(double box[3][2], const ic_plot_scene *scene, const plot_mesh *parametric,
                      int cells, ic_error *err)
{
    if (scene->has_box) {
        memcpy(box, scene->box, 3 * sizeof box[0]);
        return IC_OK;
    }
    double lo[3], hi[3];
    if (!drawn_extent(lo, hi, parametric, scene->trace))
        for (int k = 0; k < 3; k++)
            lo[k] = -1, hi[k] = 1;
    const double side = fmax(largest_side(lo, hi), PLOT_REGION_MIN_SIDE);
    double reach[3][2];
    for (int k = 0; k < 3; k++)
        reach[k][0] = lo[k] - PLOT_REGION_REACH * side,
        reach[k][1] = hi[k] + PLOT_REGION_REACH * side;
    for (int s = 0; s < scene->nsurfaces; s++) {
        if (ic_surface_get_kind(scene->surfaces[s]) == IC_PARAMETRIC)
            continue;
        const ic_status st =
            grow_by_implicit(lo, hi, scene->surfaces[s], (const double(*)[2])reach, cells, err);
        if (st != IC_OK)
            return st;
    }
    const double margin = PLOT_REGION_MARGIN * fmax(largest_side(lo, hi), PLOT_REGION_MIN_SIDE);
    for (int k = 0; k < 3; k++)
        box[k][0] = lo[k] - margin, box[k][1] = hi[k] + margin;
    return IC_OK;
}

double ic_plot_arrow_length(const ic_trace_curve *cv, double box_diagonal)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int p = 0; p < cv->npoints; p++)
        grow(lo, hi, cv->points[p].xyz);
    double d2 = 0;
    for (int k = 0; k < 3; k++)
        d2 += cv->npoints > 0 ? (hi[k] - lo[k]) * (hi[k] - lo[k]) : 0;
    return fmin(PLOT_ARROW_BOX * box_diagonal, PLOT_ARROW_CURVE * sqrt(d2));
}
