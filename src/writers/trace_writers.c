/* Traced intersections as CSV and OBJ (VTK: trace_vtk.c)
 * (docs/output-formats.md). Numbers are written with 17 significant digits so
 * that they read back to the same doubles. */
#include "common/args.h"
#include "intercurve/writers.h"
#include "parametric.h"

#include <math.h>
#include <string.h>

static ic_status io_failed(ic_error *err, const char *what)
{
    return ic_error_set(err, IC_ERR_IO, 0, "writing the %s output failed", what);
}

/* A CSV field: the number, or nothing where it is undefined. */
static void csv_number(FILE *f, double x, int defined)
{
    if (defined && isfinite(x))
        fprintf(f, ",%.17g", x);
    else
        fputc(',', f);
}

static void csv_vector(FILE *f, const double *x, int defined)
{
    for (int k = 0; k < 3; k++)
        csv_number(f, x[k], defined);
}

ic_status ic_trace_write_csv(FILE *f, const ic_trace_result *res, const ic_pair *pair,
                             ic_error *err)
{
    IC_ARG_NOT_NULL(f, "f");
    IC_ARG_NOT_NULL(res, "res");
    IC_ARG_NOT_NULL(pair, "pair");
    int parametric[2];
    ic_writer_parametric(pair, parametric);
    fputs("curve,s,x,y,z,u,v,p,q,tx,ty,tz,nx,ny,nz,bx,by,bz,kappa,tau,type\n", f);
    for (int i = 0; i < ic_trace_result_num_curves(res); i++) {
        const ic_trace_curve *c = ic_trace_result_curve(res, i);
        for (int k = 0; k < c->npoints; k++) {
            const ic_trace_point *p = &c->points[k];
            fprintf(f, "%d", i);
            csv_number(f, p->s, 1);
            csv_vector(f, p->xyz, 1);
            for (int s = 0; s < 2; s++)
                for (int j = 0; j < 2; j++)
                    csv_number(f, p->params[s][j], parametric[s]);
            csv_vector(f, p->t, 1);
            csv_vector(f, p->n, p->frame_defined);
            csv_vector(f, p->b, p->frame_defined);
            csv_number(f, p->kappa, 1);
            csv_number(f, p->tau, p->frame_defined);
            fprintf(f, ",%s\n", ic_point_type_name(ic_trace_point_type(res, c, p)));
        }
    }
    /* points found on their own (and the curve ends again): no curve, no frame */
    for (int i = 0; i < ic_trace_result_num_specials(res); i++) {
        const ic_trace_special *sp = ic_trace_result_special(res, i);
        fputs(",", f);
        csv_vector(f, sp->xyz, 1);
        fprintf(f, ",,,,,,,,,,,,,,,,%s\n", ic_point_type_name(sp->type));
    }
    return ferror(f) ? io_failed(err, "CSV") : IC_OK;
}

ic_status ic_trace_write_obj(FILE *f, const ic_trace_result *res, ic_error *err)
{
    IC_ARG_NOT_NULL(f, "f");
    IC_ARG_NOT_NULL(res, "res");
    const int ncurves = ic_trace_result_num_curves(res);
    fputs("# intercurve trace: one polyline per curve, special points as point elements\n", f);
    for (int i = 0; i < ncurves; i++) {
        const ic_trace_curve *c = ic_trace_result_curve(res, i);
        for (int k = 0; k < c->npoints; k++)
            fprintf(f, "v %.17g %.17g %.17g\n", c->points[k].xyz[0], c->points[k].xyz[1],
                    c->points[k].xyz[2]);
    }
    for (int i = 0; i < ic_trace_result_num_specials(res); i++) {
        const double *x = ic_trace_result_special(res, i)->xyz;
        fprintf(f, "v %.17g %.17g %.17g\n", x[0], x[1], x[2]);
    }
    int first = 1; /* OBJ indices start at 1 */
    for (int i = 0; i < ncurves; i++) {
        const int n = ic_trace_result_curve(res, i)->npoints;
        fprintf(f, "o curve_%d\nl", i);
        for (int k = 0; k < n; k++)
            fprintf(f, " %d", first + k);
        fputc('\n', f);
        first += n;
    }
    for (int i = 0; i < ic_trace_result_num_specials(res); i++)
        fprintf(f, "o point_%d_%s\np %d\n", i,
                ic_point_type_name(ic_trace_result_special(res, i)->type), first + i);
    return ferror(f) ? io_failed(err, "OBJ") : IC_OK;
}
