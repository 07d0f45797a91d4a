/* Internal layout of a surface, shared by surface.c, primitive.c, geometry.c. */
#ifndef IC_SURFACE_INTERNAL_H
#define IC_SURFACE_INTERNAL_H

#include "intercurve/expr.h"
#include "intercurve/surface.h"
#include "net_shape.h"
#include "nurbs.h"
#include "surface_access.h"

typedef enum { BACKEND_FORMULA, BACKEND_CALLBACK, BACKEND_PRIMITIVE, BACKEND_NURBS } ic_backend;

struct ic_surface {
    ic_surface_kind kind;
    ic_backend backend;
    ic_expr *expr;                 /* formula */
    ic_surface_callback fn;        /* callback */
    void *user;
    ic_primitive prim;             /* primitive */
    ic_nurbs_patch *nurbs;         /* NURBS patch */
    ic_net_shape *net_shape;       /* NURBS: what it was recognised as (ic_surface_net_shape) */
    int net_tried;                 /* NURBS: recognition was run (net_shape its answer) */
    int knot_side[2];              /* NURBS: -1, +1 a piece forced on knot lines; 0 by heading */
    double plane_frame[3][3];      /* plane: e1, e2, unit normal */
    int placed;                    /* primitive not in standard position: uses frame */
    double frame[3][3];            /* placed primitive: rows e1, e2, e3 (placement.c) */
    double domain[2][2];
    int periodic[2];
    /* Spaces of the surface's own inputs (2 or 3 variables), by order,
     * created on first use, and a growing workspace. */
    ic_jet_space *spaces[IC_JET_MAX_ORDER + 1];
    /* two-variable spaces by order, made on first use (ic_surface_plane_space) */
    ic_jet_space *plane_spaces[IC_JET_MAX_ORDER + 1];
    double *work[2];
    size_t work_len[2];
};

/* Workspace slots: backends evaluate in slot 0; composition keeps the
 * Taylor polynomial and its scratch in slot 1. */
enum { IC_WORK_EVAL = 0, IC_WORK_COMPOSE = 1 };

/* Makes the spaces and workspaces of the evaluations up to order 4 (a
 * failed allocation there could not be told from a point where the surface
 * is undefined); IC_ERR_NOMEM, and s freed, if it cannot. */
ic_status ic_surface_reserve(ic_surface *s, ic_error *err);

/* Workspace slot of at least len doubles (grows, keeps nothing). NULL on OOM. */
double *ic_surface_work(ic_surface *s, int slot, size_t len);
/* ic_surface_space, ic_surface_taylor_toward */
#include "surface_jets.h"

/* Primitives (primitive.c) */
ic_status ic_primitive_check(ic_surface *s, ic_error *err);
/* Sets the natural domain and periodic flags of a parametric primitive. */
void ic_primitive_default_domain(ic_surface *s);
ic_status ic_primitive_taylor(ic_surface *s, double *out, const double *at,
                              const ic_jet_space *sp, ic_error *err);

/* The primitive composed with jets, by jet arithmetic (slot 1). */
ic_status ic_primitive_compose(ic_surface *s, double *out, const double *const *in,
                               const ic_jet_space *sp, ic_error *err);

/* The implicit primitives other than the torus, in local coordinates d:
 * f = sum_i A_i d_i^2 + B_i d_i + C (zeros for the torus). */
void ic_primitive_quadric_coefficients(const ic_primitive *p, double A[3], double B[3], double *C);

/* An implicit primitive over a box (interval arithmetic, outward rounded;
 * primitive_implicit_interval.c). */
ic_status ic_primitive_interval(ic_surface *s, ic_interval *out, const ic_interval *in,
                                ic_error *err);
/* The same with the gradient of f (out->d[0..2]). */
void ic_primitive_interval_grad(ic_surface *s, ic_interval_grad *out, const ic_interval *in);
/* A parametric primitive's (x, y, z) and their (u, v) derivatives over the
 * box `in` (primitive_param_interval.c). */
void ic_primitive_param_interval_grad(const ic_surface *s, ic_interval_grad *out,
                                      const ic_interval *in);

/* Placement of a primitive (placement.c): frame rows e1, e2, e3; local
 * coordinates L and space x are related by x = center + sum_j L_j e_j. */
/* Rotates 3 consecutive jets of length n (x, y, z) in place from local
 * coordinates to space: out_k = sum_j e_j[k] in_j. */
void ic_placement_jets_to_space(const double frame[3][3], double *xyz, int n);
/* Rotates 3 jets in place from space to local coordinates: L_j = e_j . d. */
void ic_placement_jets_to_local(const double frame[3][3], double *const d[3], int n);
/* The same on intervals, outward rounded: a box of space offsets to an
 * enclosure of its local coordinates, and a local vector to space. */
void ic_placement_interval_to_local(const double frame[3][3], ic_interval d[3]);
void ic_placement_interval_to_space(const double frame[3][3], ic_interval v[3]);

#endif
