/* The descriptions of surfaces read from CAD files (cad.h): the format, one
 * surface, what a listing says of the whole file, the sizes read at most,
 * and how a description's arrays are freed (cad_surface.c). At the bottom
 * of the reader: the format readers fill these, the dispatcher (cad.c)
 * hands them out. */
#ifndef IC_CAD_TYPES_H
#define IC_CAD_TYPES_H

#include "intercurve/surface.h"

/* Largest CAD file read, in bytes. */
#define IC_CAD_MAX_FILE (64 * 1024 * 1024)
/* Most control points of one patch (the product along u and v), and most
 * along one direction. */
#define IC_CAD_MAX_POINTS 1000000
#define IC_CAD_MAX_COUNT 10000

typedef enum { IC_CAD_ANY, IC_CAD_STEP, IC_CAD_IGES } ic_cad_format;

/* One surface of a CAD file. */
typedef struct {
    int entity;         /* STEP instance number, or IGES directory-entry number */
    char type[48];      /* "B_SPLINE_SURFACE_WITH_KNOTS", "CYLINDRICAL_SURFACE", "128", ... */
    char name[64];      /* the file's label for it, or "" */
    int supported;      /* 0: not readable, `problem` says why (the fields below are unset) */
    char problem[240];
    int is_nurbs;       /* 1: `nurbs`; 0: `prim` */
    ic_nurbs nurbs;     /* points into the arrays below */
    ic_primitive prim;  /* placed (axis, ref_direction set); cone: center is the apex */
    double domain[2][2]; /* parameter range; +-HUGE_VAL where unbounded (plane, cylinder, cone v) */
    int periodic[2];
    char unit[24];      /* the file's length unit: "mm", "m", "inch", ...; "" when not stated */
    double unit_metres; /* that unit in metres; 0 when not stated */
    /* owned */
    double *knots_store; /* both knot vectors, u then v */
    double *points_store;
    double *weights_store; /* NULL when every weight is 1 */
} ic_cad_surface;

/* What a listing says of the whole file. */
typedef struct {
    ic_cad_format format;
    char unit[24];      /* as in ic_cad_surface */
    double unit_metres;
} ic_cad_info;

/* Frees what a description owns and zeroes it; NULL is allowed. */
void ic_cad_surface_clear(ic_cad_surface *s);
void ic_cad_list_free(ic_cad_surface *list, int n);

#endif
