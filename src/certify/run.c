/* The whole check in one call (certificate.h): the cover grown and proven,
 * the curves held against it, the summary kept, the cover freed. */
#include "match.h"

#include <string.h>

/* The checker's work limits: cells of the cover (as many as the tracer's
 * search examined, between the two bounds: the cost of the proof follows
 * the cost of the trace, and the limit, unlike a clock, gives the same
 * verdict on every machine), the smallest cell as a fraction of the
 * region's width, boxes per face isolation. */
#define IC_CERTIFY_MIN_CELLS 20000
#define IC_CERTIFY_MAX_CELLS 200000
#define IC_CERTIFY_MIN_WIDTH 1e-6
#define IC_CERTIFY_FACE_BOXES 256

ic_certify_limits ic_certify_limits_for(long search_cells, double deadline)
{
    const long cells = search_cells < IC_CERTIFY_MIN_CELLS   ? IC_CERTIFY_MIN_CELLS
                       : search_cells > IC_CERTIFY_MAX_CELLS ? IC_CERTIFY_MAX_CELLS
                                                             : search_cells;
    return (ic_certify_limits){cells, IC_CERTIFY_MIN_WIDTH, IC_CERTIFY_FACE_BOXES, deadline};
}

ic_status ic_certify_run(const ic_pairing *pg, const double box[3][2], int has_box,
                         const ic_certify_limits *lim, const ic_certify_claim *claim,
                         ic_certify_summary *out, ic_error *err)
{
    memset(out, 0, sizeof *out);
    ic_certificate *c = ic_certificate_new(pg, box, has_box, err);
    if (!c)
        return err ? err->code : IC_ERR_NOMEM;
    ic_status st = IC_OK;
    if (!ic_certificate_set_singular(c, claim->singular, claim->nsingular))
        ic_certificate_refuse(c, "the region's image has no enclosure: singular boxes cannot "
                                 "be placed");
    else
        st = ic_certify_cover(c, lim, err);
    if (st == IC_OK && c->summary.accepted)
        st = ic_certify_curves(c, claim->curves, claim->ncurves, err);
    *out = c->summary;
    ic_certificate_free(c);
    return st;
}
