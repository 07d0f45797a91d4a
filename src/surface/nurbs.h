/* NURBS patches inside the surface layer: the data a patch keeps, its
 * evaluation (nurbs.c) and its interval enclosures (nurbs_interval.c). */
#ifndef IC_SURFACE_NURBS_H
#define IC_SURFACE_NURBS_H

#include "intercurve/surface.h"

/* A patch in homogeneous form: hom[4 * (i * n[1] + j)] = (w x, w y, w z, w)
 * of control point (i, j). Hodograph nets (derivative patches, docs/nurbs.md)
 * are made at creation for the interval gradients. */
typedef struct {
    int p[2];         /* degrees along u, v */
    int n[2];         /* control points along u, v */
    double *knots[2]; /* n[d] + p[d] + 1 each */
    double *hom;      /* n[0] * n[1] * 4 */
    double *hodo[2];  /* d/du: (n[0]-1) x n[1] x 4 over knots[0][1..]; d/dv: n[0] x (n[1]-1) x 4 */
    int rational;     /* some weight differs from the others */
    int periodic[2];  /* parameters wrap by the natural domain's period */
    double domain[2][2];
} ic_nurbs_patch;

/* Which polynomial piece a parameter exactly on a knot takes: the span to
 * its right (the usual convention) or to its left (a curve heading to
 * smaller parameters takes its derivatives from the side it goes to). */
typedef enum { IC_NURBS_RIGHT = 0, IC_NURBS_LEFT = 1 } ic_nurbs_side;

/* Validates and copies a description; errors name the field in err->path. */
ic_status ic_nurbs_patch_new(ic_nurbs_patch **out, const ic_nurbs *desc, ic_error *err);
void ic_nurbs_patch_free(ic_nurbs_patch *patch);
/* A deep copy (a worker thread's own: trace/workers.c). IC_ERR_NOMEM. */
ic_status ic_nurbs_patch_copy(ic_nurbs_patch **out, const ic_nurbs_patch *patch, ic_error *err);

/* Doubles of workspace ic_nurbs_taylor needs for jets of n coefficients. */
size_t ic_nurbs_taylor_work_len(int n);

/* Taylor coefficients of (x, y, z) at (u, v) in the 2-variable space sp,
 * each parameter's piece chosen by side[] where it sits on a knot. */
ic_status ic_nurbs_taylor(const ic_nurbs_patch *patch, double *out, const double at[2],
                          const ic_nurbs_side side[2], const ic_jet_space *sp, double *work,
                          ic_error *err);

/* The point at (u, v), wrapped along periodic parameters, each
 * parameter's piece chosen by side[] on a knot: the basis values and the
 * homogeneous tensor sum, no jets; the same bits as ic_nurbs_taylor's
 * constant terms. */
void ic_nurbs_point(const ic_nurbs_patch *patch, const double uv[2], const ic_nurbs_side side[2],
                    double out[3]);

/* Doubles of workspace ic_nurbs_compose needs for jets of n coefficients. */
size_t ic_nurbs_compose_work_len(const ic_nurbs_patch *patch, int n);

/* (x, y, z) composed with the parameter jets in[0], in[1] of sp: each basis
 * function's polynomial on the point's span (its whole Taylor expansion) by
 * Horner's rule in jet arithmetic, the homogeneous sums, the quotient. */
ic_status ic_nurbs_compose(const ic_nurbs_patch *patch, double *out, const double *const *in,
                           const ic_nurbs_side side[2], const ic_jet_space *sp, double *work,
                           ic_error *err);

/* (x, y, z) and their u, v derivatives over a parameter box, sound with
 * outward rounding; IC_ERR_DOMAIN where the box leaves the natural domain
 * along a parameter that does not wrap. */
ic_status ic_nurbs_interval_grad(const ic_nurbs_patch *patch, ic_interval_grad *out,
                                 const ic_interval in[2], int with_grad, ic_error *err);

/* out[k * ostride + e] (k = 0..deg, e < dim <= 4) = the blossom f(a^(deg-k),
 * b^k) of the piece on span s of a degree-deg B-spline with knots kn: the
 * piece's Bezier net over [a, b]; ctrl[i * cstride + e] its deg + 1 control
 * points (those of span s, the first being control point s - deg). */
void ic_nurbs_blossom(double *out, int ostride, const double *ctrl, int cstride, int dim, int deg,
                      const double *kn, int s, double a, double b);

/* Span index s with knots[s] <= t < knots[s + 1] (LEFT: knots[s] < t <=
 * knots[s + 1]) among the nonempty spans of the domain; t outside the
 * domain takes the end span (the end pieces extended). */
int ic_nurbs_find_span(const ic_nurbs_patch *patch, int dir, double t, ic_nurbs_side side);

/* The same over any knot vector k of a degree-p B-spline with n control
 * points (curves too). */
int ic_knot_span(const double *k, int p, int n, double t, ic_nurbs_side side);

/* d^r/dt^r / r! of the degree-p basis functions nonzero on span s of knots
 * k at t: taylor[r][i] for N_{s-p+i,p}(t), r = 0..m (m <= p), i = 0..p
 * (Cox-de Boor; Piegl and Tiller 1997, eqs. 2.5 and 2.9). */
void ic_basis_taylor(double taylor[][IC_NURBS_MAX_DEGREE + 1], const double *k, int s, int p,
                     double t, int m);

/* t moved into the natural domain by whole periods along a wrapping
 * parameter (unchanged otherwise). */
double ic_nurbs_wrap(const ic_nurbs_patch *patch, int dir, double t);

/* The first knot line of the patch met going from `from` to `to` along
 * dir (from itself excluded, to included): 1 and *knot, or 0. Knot lines
 * are the distinct knots inside the domain (a wrapping parameter's seam is
 * not one: parameters jump there). from and to on one side of the seam. */
int ic_nurbs_knot_crossed(const ic_nurbs_patch *patch, int dir, double from, double to,
                          double *knot);

/* ic_nurbs_wrap, and on a wrapping parameter's seam with side LEFT the
 * domain's upper end (so the piece below the seam is taken). */
double ic_nurbs_wrap_side(const ic_nurbs_patch *patch, int dir, double t, ic_nurbs_side side);

/* Whether parameter dir wraps at a seam (where derivatives may jump). */
int ic_nurbs_seam(const ic_nurbs_patch *patch, int dir);

#endif
