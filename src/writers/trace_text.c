/* `intercurve trace --format text`: a summary table for people of the
 * curves, the singular points and the report (docs/output-formats.md). */
#include "common/args.h"
#include "intercurve/writers.h"

static void text_curves(FILE *f, const ic_trace_result *r)
{
    const int nc = ic_trace_result_num_curves(r);
    fprintf(f, "curves: %d\n", nc);
    if (nc > 0)
        fprintf(f, "  %-3s %-7s %-12s %-20s %-7s %-14s %s\n", "#", "closed", "type", "length",
                "points", "shape", "ends");
    for (int i = 0; i < nc; i++) {
        const ic_trace_curve *c = ic_trace_result_curve(r, i);
        char ends[64];
        if (c->closed)
            snprintf(ends, sizeof ends, "-");
        else
            snprintf(ends, sizeof ends, "%s, %s", ic_trace_event_name(c->ends[0]),
                     ic_trace_event_name(c->ends[1]));
        fprintf(f, "  %-3d %-7s %-12s %-20.15g %-7d %-14s %s\n", i + 1, c->closed ? "yes" : "no",
                c->tangential ? "tangential" : "transversal", c->length, c->npoints,
                ic_shape_name(c->shape), ends);
    }
}

static void text_specials(FILE *f, const ic_trace_result *r)
{
    const int ns = ic_trace_result_num_specials(r);
    fprintf(f, "singular points: %d\n", ns);
    if (ns > 0)
        fprintf(f, "  %-3s %-20s %-22s %-22s %-22s %s\n", "#", "type", "x", "y", "z", "branches");
    for (int i = 0; i < ns; i++) {
        const ic_trace_special *sp = ic_trace_result_special(r, i);
        fprintf(f, "  %-3d %-20s %-22.15g %-22.15g %-22.15g %d%s\n", i + 1,
                ic_point_type_name(sp->type), sp->xyz[0], sp->xyz[1], sp->xyz[2], sp->nbranches,
                sp->approximate ? " (approximate)" : "");
    }
}

static void text_report(FILE *f, const ic_trace_report *rep)
{
    fprintf(f, "result: %s\n",
            rep->complete ? "complete (proven by the certificate)"
            : rep->tracer_complete
                ? "INCOMPLETE (complete by the tracer's account, not proven by the certificate)"
                : "INCOMPLETE (see the failures: parts of the search were not decided)");
    const ic_trace_certificate *c = &rep->certificate;
    if (c->checked)
        fprintf(f,
                "certificate: %s, %ld cells (%ld empty, %ld outside, %ld diagonal, %ld regular, "
                "%ld singular, %ld tangential, %ld refused), %ld crossings, %ld arcs, "
                "boxes at %d poles and %d corners\n",
                c->accepted ? "accepted" : "refused", c->cells, c->empty, c->outside, c->diagonal,
                c->regular, c->singular, c->tangential, c->refused, c->crossings, c->arcs,
                c->poles, c->corners);
    if (c->checked && c->restarts > 0)
        fprintf(f, "certificate: the tracer started again from %d points of arcs it had missed\n",
                c->restarts);
    fprintf(f,
            "search: %d cells, %d excluded by interval arithmetic (%s), %d loop-free, %d where a "
            "small loop is not excluded, %d refined, %d uncovered, %d unproven, %d undecided "
            "loop cells, %d coincident\n",
            rep->cells, rep->cells_excluded, rep->proven ? "proven" : "sampled only",
            rep->loop_free_cells, rep->loop_cells, rep->refined_cells, rep->uncovered_cells,
            rep->unproven_cells, rep->undecided_loop_cells, rep->coincident_cells);
    fprintf(f, "failures: %d\n", rep->nfailures);
    for (int i = 0; i < rep->nfailures; i++)
        fprintf(f, "  %s\n", rep->failures[i]);
}

ic_status ic_trace_write_text(FILE *f, const ic_trace_result *res, const char *title, ic_error *err)
{
    IC_ARG_NOT_NULL(f, "f");
    IC_ARG_NOT_NULL(res, "res");
    if (title && *title)
        fprintf(f, "%s\n", title);
    text_curves(f, res);
    text_specials(f, res);
    text_report(f, ic_trace_result_report(res));
    return ferror(f) ? ic_error_set(err, IC_ERR_IO, 0, "writing the trace's text output failed")
                     : IC_OK;
}
