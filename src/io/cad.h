/* Surfaces read from CAD files: STEP Part 21 (ISO 10303-21) and IGES 5.x
 * (docs/cad-files.md). The reader gives a plain description of each
 * surface, a NURBS patch or a placed primitive, in the file's own numbers
 * and length unit; making an ic_surface of it is the caller's job.
 *
 * Every failure names the file's entity (STEP "#42", IGES "DE 7") and what
 * is wrong with it or what is not supported. Any bytes are safe to read: the
 * parsers never read past the buffer, and sizes are bounded (below). */
#ifndef IC_CAD_H
#define IC_CAD_H

#include <stddef.h>

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

/* The format of a text: STEP when it starts (after blanks) with
 * "ISO-10303-21", IGES when its first record has 'S' in column 73, else
 * IC_CAD_ANY (neither). */
ic_cad_format ic_cad_sniff(const char *data, size_t len);
const char *ic_cad_format_name(ic_cad_format format);

/* What a listing says of the whole file. */
typedef struct {
    ic_cad_format format;
    char unit[24];      /* as in ic_cad_surface */
    double unit_metres;
} ic_cad_info;

/* Every surface of a file in memory, in the order of the file: readable ones
 * and those that are not (supported 0, with the reason). `format` IC_CAD_ANY
 * finds it with ic_cad_sniff; a file of another format than asked is an error.
 * *list (free with ic_cad_list_free) is NULL when *n is 0; `info` (NULL
 * allowed) receives the format and the length unit. */
ic_status ic_cad_list_buffer(const char *data, size_t len, ic_cad_format format,
                             ic_cad_surface **list, int *n, ic_cad_info *info, ic_error *err);
/* One surface: `entity` a surface, or (STEP) a face whose geometry is a
 * surface, or (IGES) a trimmed surface 144 whose base is a 128. An entity
 * that is absent, not a surface, or of an unsupported kind is an error. */
ic_status ic_cad_read_buffer(const char *data, size_t len, ic_cad_format format, int entity,
                             ic_cad_surface *out, ic_error *err);
/* The same; on failure *entity_fault is 1 when the file was read and the
 * entity is at fault (absent, not a surface, not supported, malformed), 0
 * when the file is (unreadable, of another format, malformed). */
ic_status ic_cad_read_entity(const char *path, ic_cad_format format, int entity,
                             ic_cad_surface *out, int *entity_fault, ic_error *err);

/* The same from a file (at most IC_CAD_MAX_FILE bytes); messages begin with
 * the path. */
ic_status ic_cad_list(const char *path, ic_cad_format format, ic_cad_surface **list, int *n,
                      ic_cad_info *info, ic_error *err);
ic_status ic_cad_read(const char *path, ic_cad_format format, int entity, ic_cad_surface *out,
                      ic_error *err);

/* Frees what a description owns and zeroes it; NULL is allowed. */
void ic_cad_surface_clear(ic_cad_surface *s);
void ic_cad_list_free(ic_cad_surface *list, int n);

#endif
