/* The whole check in one call (certificate.h): the cover grown and proven,
 * the curves held against it, the summary kept, the cover freed. */
#include "match.h"
#include "plan.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The checker's work limits: cells of the cover (a few times as many as
 * the tracer's search examined, between the two bounds: the cost of the
 * proof follows the cost of the trace, and the limit, unlike a clock, gives
 * the same verdict on every machine; the Enneper surface's self-
 * intersection, a search of 35175 cells, needs 72881), the smallest cell as a fraction of the
 * region's width, boxes per face isolation. */
#define IC_CERTIFY_CELLS_PER_SEARCH_CELL 4
#define IC_CERTIFY_MIN_CELLS 20000
#define IC_CERTIFY_MAX_CELLS 200000
#define IC_CERTIFY_MIN_WIDTH 1e-8
#define IC_CERTIFY_FACE_BOXES 256
/* Cells more per tube radius of tangential curve: beside a tangential curve
 * the surfaces touch and cells at distance d are proven empty only when of
 * width of order d, so the cover grows with the curve's length over the
 * tube's radius (21 to 95 cells per radius on the bundled and torture
 * tangential cases); and the most cells in all then. */
#define IC_CERTIFY_TUBE_CELLS 128
#define IC_CERTIFY_MAX_TUBE_CELLS 1000000

ic_certify_limits ic_certify_limits_for(long search_cells, double deadline)
{
    const double want = (double)IC_CERTIFY_CELLS_PER_SEARCH_CELL * (double)search_cells;
    const long cells = want < IC_CERTIFY_MIN_CELLS   ? IC_CERTIFY_MIN_CELLS
                       : want > IC_CERTIFY_MAX_CELLS ? IC_CERTIFY_MAX_CELLS
                                                     : (long)want;
    return (ic_certify_limits){cells, IC_CERTIFY_MIN_WIDTH, IC_CERTIFY_FACE_BOXES, deadline};
}

/* lim with room for the cover along the tubes (IC_CERTIFY_TUBE_CELLS). */
static ic_certify_limits with_tubes(const ic_certificate *c, const ic_certify_limits *lim)
{
    ic_certify_limits out = *lim;
    double radii = 0.0;
    for (int k = 0; k < c->ntubes; k++) {
        const ic_certify_tube *t = &c->tubes[k];
        for (int i = 1; i < t->n + (t->closed ? 1 : 0); i++) {
            const double *a = t->xyz + 3 * (size_t)(i - 1), *b = t->xyz + 3 * (size_t)(i % t->n);
            radii += hypot(hypot(b[0] - a[0], b[1] - a[1]), b[2] - a[2]) / c->tube_half;
        }
    }
    const double extra = IC_CERTIFY_TUBE_CELLS * radii;
    if (extra > 0.0)
        out.max_cells = (long)fmin((double)IC_CERTIFY_MAX_TUBE_CELLS,
                                   (double)lim->max_cells + extra);
    return out;
}

/* The cover as a certificate file in io->doc. */
static ic_status keep_file(const ic_certificate *c, ic_certify_io *io, ic_error *err)
{
    FILE *mem = open_memstream(&io->doc, &io->len);
    if (!mem)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory writing the certificate");
    ic_status st = ic_certificate_write_cover(mem, c, err);
    /* a memory stream fails only for want of memory */
    if (fclose(mem) != 0 || st == IC_ERR_IO)
        st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory writing the certificate");
    if (st != IC_OK) {
        free(io->doc);
        io->doc = NULL, io->len = 0;
    }
    return st;
}

ic_status ic_certify_run(const ic_pairing *pg, const double box[3][2], int has_box,
                         const ic_certify_limits *lim, const ic_certify_claim *claim,
                         ic_certify_io *io, ic_certify_summary *out, ic_error *err)
{
    if (io)
        io->doc = NULL, io->len = 0;
    memset(out, 0, sizeof *out);
    ic_certificate *c = ic_certificate_new(pg, box, has_box, err);
    if (!c)
        return err ? err->code : IC_ERR_NOMEM;
    ic_status st = IC_OK;
    int placed = ic_certificate_set_singular(c, claim->singular, claim->singular_scale,
                                             claim->nsingular);
    if (placed > 0)
        placed = ic_certificate_add_corner_ends(c, claim->curves, claim->ncurves);
    if (placed > 0)
        placed = ic_certificate_set_tubes(c, claim->tubes, claim->ntubes);
    if (placed < 0)
        st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory certifying");
    else if (placed == 0)
        ic_certificate_refuse(c, "the region's image has no enclosure: singular boxes and "
                                 "tangential tubes cannot be placed");
    else if (io && io->replay) /* a tree of another region: bad input */
        st = ic_cover_plan_check(io->replay, c, err);
    if (st == IC_OK && placed > 0) {
        const ic_certify_limits grown = with_tubes(c, lim);
        c->plan = io ? io->replay : NULL;
        st = ic_certify_cover(c, &grown, err);
    }
    /* a claimed singular point where the cover proves the curve smooth */
    if (st == IC_OK && c->summary.accepted)
        ic_certificate_refute_smooth(c, claim->nsingular);
    if (st == IC_OK && c->summary.accepted)
        ic_certify_tubes_real(c, claim->curves, claim->ncurves);
    if (st == IC_OK && c->summary.accepted)
        ic_certify_points_on(c, claim->curves, claim->ncurves);
    int apart = 1;
    if (st == IC_OK && c->summary.accepted && (apart = ic_certificate_tubes_apart(c)) < 0)
        st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory certifying");
    if (st == IC_OK && c->summary.accepted && apart)
        st = ic_certify_curves(c, claim->curves, claim->ncurves, err);
    if (st == IC_OK && c->summary.accepted && apart && claim->singular_passages &&
        ic_certify_passages(c, claim->curves, claim->ncurves, claim->singular_passages,
                            claim->nsingular) < 0)
        st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory certifying");
    *out = c->summary;
    if (st == IC_OK && io && io->keep)
        st = keep_file(c, io, err);
    ic_certificate_free(c);
    return st;
}
