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

/* A traced curve in search coordinates: npoints x dim values. */
typedef struct {
    const double *z;
    int npoints, closed;
    /* 1: a tangential curve, not walked: it lies in its tube, whose cells
     * are not examined (tube.c) */
    int tangential;
} ic_certify_curve;

/* Holds the curves against the cover c (whose summary must say accepted):
 * on a mismatch the certificate is refused with the reason. IC_OK, or an
 * error out of memory. */
ic_status ic_certify_curves(ic_certificate *c, const ic_certify_curve *curves, int ncurves,
                            ic_error *err);

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
    int nsingular;
    const ic_certify_tube *tubes; /* its tangential curves, each in a tube */
    int ntubes;
} ic_certify_claim;

/* The cover of pg's region (box: the problem's) grown within lim, and the
 * claim held against it (run.c): *out the summary. IC_OK, or an error (out
 * of memory, a region without a finite box). */
ic_status ic_certify_run(const ic_pairing *pg, const double box[3][2], int has_box,
                         const ic_certify_limits *lim, const ic_certify_claim *claim,
                         ic_certify_summary *out, ic_error *err);

#endif
