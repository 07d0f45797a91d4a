/*
 * The data of the interactive page besides the trace (docs/plots.md, "The
 * interactive page"): the title, the surfaces' names, the region drawn, the
 * view and the surface meshes of the pictures (plot_mesh.c), as one JSON
 * object. Written by hand rather than with cJSON: a mesh has tens of
 * thousands of coordinates, which need 7 digits, not 17.
 */
#include "plot_html.h"

#include <math.h>
#include <stdlib.h>

void ic_html_json_string(FILE *f, const char *s)
{
    if (!s) {
        fputs("null", f);
        return;
    }
    fputc('"', f);
    for (const unsigned char *c = (const unsigned char *)s; *c; c++) {
        if (*c == '"' || *c == '\\')
            fprintf(f, "\\%c", *c);
        else if (*c < 0x20 || *c == '<') /* '<': nothing can close the script element */
            fprintf(f, "\\u%04x", *c);
        else
            fputc(*c, f);
    }
    fputc('"', f);
}

/* The meshes as the pictures make them: the parametric surfaces first (cut
 * to the scene's box, if any), which the region drawn takes in, then the
 * implicit ones inside that region. */
static ic_status make_meshes(plot_mesh *mesh, double box[3][2], const ic_plot_scene *scene,
                             int cells, ic_error *err)
{
    const int implicit_cells = cells / 2; /* as in the pictures (plot_draw3d.c) */
    ic_status st = IC_OK;
    for (int s = 0; s < scene->nsurfaces && st == IC_OK; s++)
        if (ic_surface_get_kind(scene->surfaces[s]) == IC_PARAMETRIC)
            st = ic_plot_mesh_surface(mesh, scene->surfaces[s], s,
                                      scene->has_box ? scene->box : NULL, cells, err);
    if (st == IC_OK)
        st = ic_plot_region(box, scene, mesh, implicit_cells > 4 ? implicit_cells : 4, err);
    for (int s = 0; s < scene->nsurfaces && st == IC_OK; s++)
        if (ic_surface_get_kind(scene->surfaces[s]) != IC_PARAMETRIC)
            st = ic_plot_mesh_surface(mesh, scene->surfaces[s], s, (const double(*)[2])box,
                                      implicit_cells, err);
    return st;
}

static int finite_triangle(const plot_tri *t)
{
    for (int v = 0; v < 3; v++)
        for (int k = 0; k < 3; k++)
            if (!isfinite(t->v[v][k]))
                return 0;
    return 1;
}

/* One surface's triangles as a flat array of vertex coordinates. */
static void write_mesh(FILE *f, const plot_mesh *mesh, int surface)
{
    fprintf(f, "{\"surface\": %d, \"positions\": [", surface);
    int first = 1;
    for (int i = 0; i < mesh->n; i++) {
        const plot_tri *t = &mesh->t[i];
        if (t->surface != surface || !finite_triangle(t))
            continue;
        for (int v = 0; v < 3; v++)
            fprintf(f, "%s%.7g,%.7g,%.7g", first && v == 0 ? "" : ",", t->v[v][0], t->v[v][1],
                    t->v[v][2]);
        fputc('\n', f);
        first = 0;
    }
    fputs("]}", f);
}

ic_status ic_html_write_scene(FILE *f, const ic_plot_scene *scene, const ic_plot_options *opt,
                              ic_error *err)
{
    plot_mesh mesh = {NULL, 0, 0};
    double box[3][2];
    const ic_status st = make_meshes(&mesh, box, scene, opt->mesh, err);
    if (st != IC_OK) {
        free(mesh.t);
        return st;
    }
    fputs("{\"title\": ", f);
    ic_html_json_string(f, scene->title);
    fputs(", \"names\": [", f);
    for (int s = 0; s < scene->nsurfaces; s++) {
        fputs(s ? ", " : "", f);
        ic_html_json_string(f, scene->names[s]);
    }
    fprintf(f, "], \"self\": %s, \"box\": [[%.17g, %.17g], [%.17g, %.17g], [%.17g, %.17g]]",
            scene->nsurfaces == 1 ? "true" : "false", box[0][0], box[0][1], box[1][0], box[1][1],
            box[2][0], box[2][1]);
    fprintf(f, ", \"view\": [%.17g, %.17g], \"frames\": %d, \"chart\": %s", opt->azimuth,
            opt->elevation, opt->frames, opt->chart ? "true" : "false");
    fputs(", \"meshes\": [", f);
    for (int s = 0; s < scene->nsurfaces; s++) {
        fputs(s ? ",\n" : "\n", f);
        write_mesh(f, &mesh, s);
    }
    fputs("]}\n", f);
    free(mesh.t);
    return IC_OK;
}
