/* The interactive page of a scene (docs/plots.md, "The interactive page"):
 * one self-contained HTML file with three.js, the page's own scripts, the
 * trace document and the surface meshes. */
#ifndef IC_PLOT_HTML_H
#define IC_PLOT_HTML_H

#include <stdio.h>

#include "plot_internal.h"

/* Writes the page into `path` (as ic_write_file_atomic writes). IC_ERR_UNABLE
 * when the library was built without three.js (web/node_modules). */
ic_status ic_plot_write_html(const char *path, const ic_plot_scene *scene,
                             const ic_plot_options *opt, ic_error *err);

/* The page's data besides the trace: title, names, region drawn, view, frame
 * count, chart flag and the surface meshes, one JSON object with every '<'
 * escaped. */
ic_status ic_html_write_scene(FILE *f, const ic_plot_scene *scene, const ic_plot_options *opt,
                              ic_error *err);

/* s as a JSON string ("null" for NULL) with '<' and control characters
 * escaped as \u00XX. */
void ic_html_json_string(FILE *f, const char *s);

#endif
