/* Surfaces of an IGES file (cad_readers.h): the rational B-spline surface (entity
 * 128), alone or as the base surface of a trimmed surface (144), moved by
 * their transformation matrices (124). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cad_readers.h"
#include "iges_surface.h"

/* The IGES 5.3 surface entities, read or not, with their names. */
typedef struct {
    int type;
    const char *name;
} surface_type;

static const surface_type SURFACES[] = {
    {108, "plane"}, {114, "parametric spline surface"}, {118, "ruled surface"},
    {120, "surface of revolution"}, {122, "tabulated cylinder"},
    {128, "rational B-spline surface"}, {140, "offset surface"}, {143, "bounded surface"},
    {144, "trimmed surface"}, {190, "plane surface"}, {192, "right circular cylindrical surface"},
    {194, "right circular conical surface"}, {196, "spherical surface"}, {198, "toroidal surface"},
};

/* Transformation matrices lead to one another: followed this deep at most. */
enum { MAX_MATRIX_DEPTH = 8 };

static const char *surface_name(int type)
{
    for (size_t k = 0; k < sizeof SURFACES / sizeof SURFACES[0]; k++)
        if (SURFACES[k].type == type)
            return SURFACES[k].name;
    return NULL;
}

/* x' = R x + T for a 124 (form 0 or 1), then the 124's own matrix. */
static ic_status transform(const ic_iges_file *f, int de, double *points, size_t npoints,
                           const char *who, int depth, ic_error *err)
{
    if (de == 0)
        return IC_OK;
    const ic_iges_entry *e = ic_iges_entry_at(f, de);
    if (!e || e->type != 124 || (e->form != 0 && e->form != 1) || depth > MAX_MATRIX_DEPTH)
        return ic_cad_fail(err, who,
                           "its transformation matrix DE %d is not an entity 124 of form 0 or 1%s",
                           de, depth > MAX_MATRIX_DEPTH ? " (or the matrices form a loop)" : "");
    ic_iges_params p;
    ic_status st = ic_iges_entity_params(f, e, &p, err);
    if (st != IC_OK)
        return st;
    double m[12];
    for (int k = 0; k < 12 && st == IC_OK; k++)
        if (ic_iges_number(&p, k + 1, &m[k]) < 0)
            st = ic_cad_fail(err, who, "its transformation matrix DE %d lacks a number", de);
    ic_iges_params_free(&p);
    if (st != IC_OK)
        return st;
    for (size_t i = 0; i < npoints; i++) {
        double *x = points + 3 * i, y[3];
        for (int r = 0; r < 3; r++)
            y[r] = m[4 * r] * x[0] + m[4 * r + 1] * x[1] + m[4 * r + 2] * x[2] + m[4 * r + 3];
        memcpy(x, y, sizeof y);
    }
    return transform(f, e->matrix, points, npoints, who, depth + 1, err);
}

/* The numbers of an entity 128 from parameter `k` on: count of them into out. */
static ic_status numbers(const ic_iges_params *p, int *k, double *out, size_t count,
                         const char *what, const char *who, ic_error *err)
{
    for (size_t i = 0; i < count; i++, (*k)++)
        if (ic_iges_number(p, *k, &out[i]) < 0)
            return ic_cad_fail(err, who, "its %s end early or hold a string (parameter %d)", what,
                               *k);
    return IC_OK;
}

/* IGES lists weights and points with the u index fastest; ic_nurbs has
 * point (i, j) at i * count[1] + j. */
static void to_row_major(const double *in, double *out, const int count[2], int dim)
{
    for (int j = 0; j < count[1]; j++)
        for (int i = 0; i < count[0]; i++)
            memcpy(out + dim * ((size_t)i * count[1] + j), in + dim * ((size_t)j * count[0] + i),
                   (size_t)dim * sizeof(double));
}

/* 128: K1, K2, M1, M2, PROP1..5, knots S (K1+M1+2), T (K2+M2+2), weights
 * and control points ((K1+1)(K2+1), u fastest), U0, U1, V0, V1. */
static ic_status bspline(const ic_iges_params *p, ic_cad_surface *out, const char *who,
                         ic_error *err)
{
    double head[9];
    int k = 1;
    if (numbers(p, &k, head, 9, "counts and flags", who, err) != IC_OK)
        return IC_ERR_INVALID;
    for (int i = 0; i < 4; i++)
        if (head[i] != floor(head[i]) || fabs(head[i]) > IC_CAD_MAX_COUNT)
            return ic_cad_fail(err, who, "K1, K2, M1, M2 must be whole numbers within %d",
                               IC_CAD_MAX_COUNT);
    const int degree[2] = {(int)head[2], (int)head[3]};
    const int count[2] = {(int)head[0] + 1, (int)head[1] + 1};
    const int rational = head[6] == 0; /* PROP3: 0 rational, 1 polynomial */
    ic_status st = ic_cad_alloc_nurbs(out, degree, count, rational, who, err);
    const size_t npoints = (size_t)count[0] * (size_t)count[1];
    if (st == IC_OK)
        st = numbers(p, &k, out->knots_store, (size_t)(count[0] + degree[0] + 1), "u knots", who,
                     err);
    if (st == IC_OK)
        st = numbers(p, &k, out->knots_store + count[0] + degree[0] + 1,
                     (size_t)(count[1] + degree[1] + 1), "v knots", who, err);
    if (st != IC_OK)
        return st;
    /* weights then points, read in IGES order into the points' store, then
     * reordered through the weights' (a polynomial patch's weights are skipped) */
    double *tmp = malloc(3 * npoints * sizeof(double));
    if (!tmp)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "%s: out of memory", who);
    st = numbers(p, &k, tmp, npoints, "weights", who, err);
    if (st == IC_OK && rational)
        to_row_major(tmp, out->weights_store, count, 1);
    if (st == IC_OK)
        st = numbers(p, &k, tmp, 3 * npoints, "control points", who, err);
    if (st == IC_OK)
        to_row_major(tmp, out->points_store, count, 3);
    free(tmp);
    double range[4];
    if (st == IC_OK)
        st = numbers(p, &k, range, 4, "parameter range U0, U1, V0, V1", who, err);
    const int closed[2] = {head[4] != 0 || head[7] != 0, head[5] != 0 || head[8] != 0};
    if (st == IC_OK)
        st = ic_cad_finish_nurbs(out, closed, who, err);
    /* U0..U1 x V0..V1 narrows the knots' range where it lies within it */
    for (int d = 0; d < 2 && st == IC_OK; d++) {
        const double a = range[2 * d], b = range[2 * d + 1];
        if (a < b && a >= out->domain[d][0] && b <= out->domain[d][1] &&
            (a > out->domain[d][0] || b < out->domain[d][1])) {
            out->domain[d][0] = a;
            out->domain[d][1] = b;
            out->periodic[d] = out->nurbs.periodic[d] = 0;
        }
    }
    return st;
}

static void describe(const ic_iges_entry *e, ic_cad_surface *out)
{
    out->entity = e->de;
    snprintf(out->type, sizeof out->type, "%d", e->type);
    if (e->subscript != 0)
        snprintf(out->name, sizeof out->name, "%s(%d)", e->label, e->subscript);
    else
        snprintf(out->name, sizeof out->name, "%s", e->label);
}

/* The 128 at `e`, moved by its matrix and then by `outer` (the 144's). */
static ic_status read_128(const ic_iges_file *f, const ic_iges_entry *e, int outer,
                          ic_cad_surface *out, const char *who, ic_error *err)
{
    ic_iges_params p;
    ic_status st = ic_iges_entity_params(f, e, &p, err);
    if (st != IC_OK)
        return st;
    st = bspline(&p, out, who, err);
    ic_iges_params_free(&p);
    const size_t npoints = (size_t)out->nurbs.count[0] * (size_t)out->nurbs.count[1];
    if (st == IC_OK)
        st = transform(f, e->matrix, out->points_store, npoints, who, 0, err);
    if (st == IC_OK)
        st = transform(f, outer, out->points_store, npoints, who, 0, err);
    return st;
}

/* 144: PTS (the base surface's DE), N1, N2, PTO, PTI...: the base surface
 * is read; the boundaries are not. */
static ic_status read_144(const ic_iges_file *f, const ic_iges_entry *e, ic_cad_surface *out,
                          const char *who, ic_error *err)
{
    ic_iges_params p;
    ic_status st = ic_iges_entity_params(f, e, &p, err);
    if (st != IC_OK)
        return st;
    double pts = 0;
    const int ok = ic_iges_number(&p, 1, &pts) == 0;
    ic_iges_params_free(&p);
    const ic_iges_entry *base = ok && pts == floor(pts) && fabs(pts) < 1e9
                                    ? ic_iges_entry_at(f, (int)pts)
                                    : NULL;
    if (!base)
        return ic_cad_fail(err, who, "its base surface (PTS) is not a directory entry");
    if (base->type != 128) {
        const char *name = surface_name(base->type);
        return ic_cad_fail(err, who,
                           "its base surface DE %d is an entity %d (%s), not a 128 (rational "
                           "B-spline surface), the only base surface read",
                           base->de, base->type, name ? name : "not a surface");
    }
    char base_who[64];
    snprintf(base_who, sizeof base_who, "DE %d (entity 128, the base of DE %d)", base->de, e->de);
    return read_128(f, base, e->matrix, out, base_who, err);
}

static ic_status read_entry(const ic_iges_file *f, const ic_iges_entry *e, const char *unit,
                            double metres, ic_cad_surface *out, ic_error *err)
{
    char who[64];
    snprintf(who, sizeof who, "DE %d (entity %d)", e->de, e->type);
    memset(out, 0, sizeof *out);
    describe(e, out);
    snprintf(out->unit, sizeof out->unit, "%s", unit);
    out->unit_metres = metres;
    ic_status st;
    if (e->type == 128)
        st = read_128(f, e, 0, out, who, err);
    else if (e->type == 144)
        st = read_144(f, e, out, who, err);
    else if (surface_name(e->type))
        st = ic_cad_fail(err, who,
                         "the %s is not read (read are entity 128, the rational B-spline "
                         "surface, and 144, a trimmed surface whose base is a 128)",
                         surface_name(e->type));
    else
        st = ic_cad_fail(err, who, "not a surface");
    if (st != IC_OK) {
        ic_cad_surface_clear(out);
        describe(e, out);
        snprintf(out->unit, sizeof out->unit, "%s", unit);
        out->unit_metres = metres;
    }
    out->supported = st == IC_OK;
    return st;
}

ic_status ic_iges_read(const ic_iges_file *f, int entity, ic_cad_surface *out, ic_error *err)
{
    memset(out, 0, sizeof *out);
    const ic_iges_entry *e = ic_iges_entry_at(f, entity);
    if (!e)
        return ic_error_set(err, IC_ERR_INVALID, 0,
                            "DE %d: no such directory entry (the file has %d: DE 1, 3, ..., %d)",
                            entity, f->nentries, 2 * f->nentries - 1);
    char unit[24];
    double metres;
    ic_iges_length_unit(f, unit, sizeof unit, &metres);
    const ic_status st = read_entry(f, e, unit, metres, out, err);
    if (st != IC_OK)
        ic_cad_surface_clear(out);
    return st;
}

ic_status ic_iges_list(const ic_iges_file *f, ic_cad_surface **list, int *n, ic_cad_info *info,
                       ic_error *err)
{
    char unit[24];
    double metres;
    ic_iges_length_unit(f, unit, sizeof unit, &metres);
    snprintf(info->unit, sizeof info->unit, "%s", unit);
    info->unit_metres = metres;
    int cap = 0;
    for (int k = 0; k < f->nentries; k++) {
        if (!surface_name(f->entries[k].type))
            continue;
        ic_cad_surface s;
        ic_error why;
        ic_error_clear(&why);
        ic_status st = read_entry(f, &f->entries[k], unit, metres, &s, &why);
        if (st == IC_ERR_NOMEM)
            return ic_error_set(err, st, 0, "%s", why.message);
        if (st != IC_OK)
            snprintf(s.problem, sizeof s.problem, "%s", why.message);
        if ((st = ic_cad_list_append(list, n, &cap, &s, err)) != IC_OK)
            return st;
    }
    return IC_OK;
}
