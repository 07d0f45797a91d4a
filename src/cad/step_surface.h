/* The STEP reader's pieces (step_surface.c, step_bspline.c, step_units.c,
 * step_placement.c). */
#ifndef IC_STEP_SURFACE_H
#define IC_STEP_SURFACE_H

#include "cad_internal.h"
#include "step_parse.h"

/* A ref_direction whose part normal to the axis is shorter than this (the
 * sine of its angle to the unit axis) counts as along the axis. */
#define IC_STEP_PARALLEL_TOL 1e-12

/* The file's units, found once. */
typedef struct {
    char length[24];   /* "mm", "inch", ...; "" when the file has no length unit */
    double metres;     /* that unit in metres; 0 when unknown */
    double radians;    /* the plane angle unit in radians (1 when not stated) */
} ic_step_units;

void ic_step_find_units(const ic_step_file *f, ic_step_units *u);

/* 1 when the instance is a surface of ISO 10303-42 (read or not), with its
 * type name ("RATIONAL_B_SPLINE_SURFACE" for the rational complex form). */
int ic_step_surface_type(const ic_step_file *f, const ic_step_instance *in, char *type,
                         size_t size);
/* The CARTESIAN_POINT a REF value names (three coordinates). */
ic_status ic_step_point(const ic_step_file *f, int v, double out[3], const char *who,
                        ic_error *err);
/* The AXIS2_PLACEMENT_3D(name, location, axis, ref_direction) a REF value
 * names, into prim's center, axis and ref_direction: the axis defaults to z;
 * the reference direction to x (y when the axis is along x, as ISO
 * 10303-42's first_proj_axis has it) and loses its component along the
 * axis. */
ic_status ic_step_placement(const ic_step_file *f, int v, ic_primitive *prim, const char *who,
                            ic_error *err);
/* A B_SPLINE_SURFACE_WITH_KNOTS, simple or complex (with RATIONAL_B_SPLINE_SURFACE). */
ic_status ic_step_bspline(const ic_step_file *f, const ic_step_instance *in, ic_cad_surface *out,
                          const char *who, ic_error *err);

#endif
