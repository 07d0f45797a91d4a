/*
 * The traced curves held against a proven cover (match.c): every arc of
 * every regular cell is traced by exactly one curve, every curve crosses the
 * cells' faces only at proven crossings, passes through a cell from one end
 * of one of its arcs to the other, and ends only where a crossing of the
 * region's boundary is (or closes on itself).
 */
#ifndef IC_CERTIFY_MATCH_H
#define IC_CERTIFY_MATCH_H

#include "certificate.h"
#include "intercurve/local.h"

/* A traced curve in search coordinates: npoints x dim values. */
typedef struct {
    const double *z;
    int npoints, closed;
    /* 1: a tangential curve, not walked: it lies in its tube, whose cells
     * are not examined (tube.c) */
    int tangential;
} ic_certify_curve;

/* Newton's method for F = 0 with z[j] fixed (j = -1: the least-norm step
 * onto the curve), from z (match.c). 1 when it converged. */
int ic_certify_project(const ic_certificate *c, double *z, int j);

/* z lies within tol (in search coordinates) of the curve, to first order:
 * |F_i| <= tol |grad F_i| for every equation. */
int ic_certify_near_curve(const ic_certificate *c, const double *z, double tol);

/* A singular box at each end of an open curve that lies on two faces of
 * the region or the box at once, and at each point within a curve that
 * lies on one (corners.c): no crossing can be isolated where a curve
 * leaves across a corner, a cell's edge, or touches a face. At most
 * IC_CERTIFY_MAX_CORNERS (a curve along a face gets none past them, and
 * the cover refuses there). 1, or -1 out of memory. */
#define IC_CERTIFY_MAX_CORNERS 32
/* A curve's sample nearer a face than this fraction of the region's width,
 * its neighbours farther, is where a touch of the face is sought. */
#define IC_CERTIFY_TOUCH_NEAR 1e-2
int ic_certificate_add_corner_ends(ic_certificate *c, const ic_certify_curve *curves,
                                   int ncurves);

/* Holds the curves against the cover c (whose summary must say accepted):
 * on a mismatch the certificate is refused with the reason. IC_OK, or an
 * error out of memory. */
ic_status ic_certify_curves(ic_certificate *c, const ic_certify_curve *curves, int ncurves,
                            ic_error *err);

/* The most passages of traced curves through the singular box of a point
 * of this type and number of branches (as the result reports them): 0 at
 * an isolated contact, the half-branches at a cusp, 2 per branch at a
 * branch point or a tacnode; -1 not bounded (approximate points,
 * higher-order contacts, surface singular points). passages.c */
int ic_certify_passages_allowed(ic_point_type type, int nbranches, int approximate);

/* Refuses c when the curves pass through the box of a reported singular
 * point s (s < nallowed) more often than allowed[s] (-1: any): 1, or -1
 * out of memory. passages.c */
int ic_certify_passages(ic_certificate *c, const ic_certify_curve *curves, int ncurves,
                        const int *allowed, int nallowed);

/* The largest residual at a point of a tangential curve (claims.c): its
 * distances to the surfaces over the region's size, and the sine of the
 * angle between their normals. The tracer's tangential points are on both
 * surfaces to 1e-12 of the region's size where implicit, to sqrt(eps) of it
 * on a net (a double root, known across to half the digits only). */
#define IC_CERTIFY_TANGENTIAL_RESIDUAL 1e-6

/* How far a traced point may lie off the intersection, to first order, as
 * a fraction of the region's largest width (claims.c): the tracer's points
 * are on both surfaces to 1e-11 of the problem's size and better. */
#define IC_CERTIFY_POINT_REACH 1e-8

/* Every point of every transversal curve of the claim lies on the
 * intersection or in a singular box (claims.c), else c is refused: 1, 0
 * refused. */
int ic_certify_points_on(ic_certificate *c, const ic_certify_curve *curves, int ncurves);

/* Every point of every tangential curve of the claim is a point where the
 * surfaces touch (claims.c), else c is refused: 1, 0 refused. */
int ic_certify_tubes_real(ic_certificate *c, const ic_certify_curve *curves, int ncurves);

/* The work limits of a check after a search of search_cells cells (run.c),
 * with a deadline on the monotonic clock (0: none). */
ic_certify_limits ic_certify_limits_for(long search_cells, double deadline);

/* What a result claims: its curves, its singular points (xyz), each of
 * which gets a singular box, and its tangential curves (xyz), each of which
 * gets a tube (certificate.h). */
typedef struct {
    const ic_certify_curve *curves;
    int ncurves;
    const double (*singular)[3];
    const double *singular_scale; /* each box's size (certificate.h); NULL all 1 */
    /* per singular point, the most passages of curves through its box
     * (ic_certify_passages_allowed; -1 any); NULL: not checked */
    const int *singular_passages;
    int nsingular;
    const ic_certify_tube *tubes; /* its tangential curves, each in a tube */
    int ntubes;
} ic_certify_claim;

/* A check's certificate file (plan.h): the one to replay, and the one
 * it writes. */
typedef struct {
    const ic_cover_plan *replay; /* NULL: the cover is grown */
    int keep;                    /* 1: the cover written as a file into doc */
    char *doc;                   /* the file (the caller frees it), len bytes */
    size_t len;
} ic_certify_io;

/* The cover of pg's region (box: the problem's) grown within lim, or with
 * io->replay replayed, and the claim held against it (run.c): *out the
 * summary, io->doc the file when io->keep. IC_OK, or an error (out of
 * memory, a region without a finite box, a replayed tree that does not fit
 * the region: IC_ERR_INVALID). io may be NULL. */
ic_status ic_certify_run(const ic_pairing *pg, const double box[3][2], int has_box,
                         const ic_certify_limits *lim, const ic_certify_claim *claim,
                         ic_certify_io *io, ic_certify_summary *out, ic_error *err);

#endif
