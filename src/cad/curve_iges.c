/* Fitted intersection curves as an IGES 5.3 file (docs/output-formats.md,
 * "IGES"): each a rational B-spline curve (entity 126) that is polynomial
 * (PROP3 = 1, weights 1), in millimetres (units flag 2), model scale 1. */
#include "common/args.h"
#include "intercurve/writers.h"

#include <math.h>
#include <string.h>

#include "cad/curve_out.h"
#include "cad/iges_records.h"

enum {
    IGES_BSPLINE_CURVE = 126,
    IGES_UNITS_MM = 2,
    IGES_VERSION_5_3 = 11,
    IGES_TEXT_MAX = 60 /* a string of the G section fits one line */
};

/* A field and its delimiter as one piece, so that they stay on one line. */
static void put_real(iges_records *r, double x, char delim)
{
    char num[IC_CURVE_REAL_SIZE], field[IC_CURVE_REAL_SIZE + 2];
    ic_curve_real(num, x);
    snprintf(field, sizeof field, "%s%c", num, delim);
    ic_iges_records_put(r, field);
}

static void put_int(iges_records *r, int n, char delim)
{
    char field[16];
    snprintf(field, sizeof field, "%d%c", n, delim);
    ic_iges_records_put(r, field);
}

/* A Hollerith string, nHtext (printable ASCII, cut to IGES_TEXT_MAX). */
static void put_string(iges_records *r, const char *s, char delim)
{
    char text[IGES_TEXT_MAX + 1], field[IGES_TEXT_MAX + 16];
    ic_curve_ascii(text, sizeof text, s);
    snprintf(field, sizeof field, "%zuH%s%c", strlen(text), text, delim);
    ic_iges_records_put(r, field);
}

static int write_start(FILE *f, const char *title)
{
    char text[512];
    ic_curve_ascii(text, sizeof text,
                   title && title[0] ? title : "intersection curves as B-splines");
    iges_records r;
    ic_iges_records_start(&r, f, 'S');
    char chunk[73];
    const size_t n = strlen(text);
    for (size_t k = 0; k < n; k += 72) {
        snprintf(chunk, sizeof chunk, "%.72s", text + k);
        ic_iges_records_put(&r, chunk);
        ic_iges_records_end_line(&r);
    }
    return r.seq;
}

/* The largest absolute coordinate of the control points written. */
static double largest_coordinate(const ic_trace_result *res)
{
    double m = 0;
    for (int i = 0; i < ic_trace_result_num_curves(res); i++) {
        const ic_curve_fit *fit = ic_trace_result_fit(res, i);
        for (int k = 0; fit && k < 3 * fit->curve.ncontrol; k++)
            m = fmax(m, fabs(fit->curve.control[k]));
    }
    return m;
}

/* The global section (IGES 5.3, 2.2.4): its 25 fields, the 26th left out. */
static int write_global(FILE *f, const ic_trace_result *res, const char *title)
{
    char stamp[32];
    ic_curve_time_stamp(stamp, sizeof stamp, "%Y%m%d.%H%M%S");
    const char *product = title && title[0] ? title : "intersection curves";
    iges_records r;
    ic_iges_records_start(&r, f, 'G');
    put_string(&r, ",", ',');                   /* 1 parameter delimiter */
    put_string(&r, ";", ',');                   /* 2 record delimiter */
    put_string(&r, product, ',');               /* 3 sender's product id */
    put_string(&r, "intersection curves", ','); /* 4 file name */
    put_string(&r, "intercurve", ',');          /* 5 native system */
    put_string(&r, "intercurve", ',');          /* 6 preprocessor */
    put_int(&r, 32, ',');                       /* 7 bits of an integer */
    put_int(&r, 38, ',');                       /* 8, 9 single precision */
    put_int(&r, 6, ',');
    put_int(&r, 308, ','); /* 10, 11 double precision */
    put_int(&r, 15, ',');
    put_string(&r, product, ',');    /* 12 receiver's product id */
    put_real(&r, 1, ',');            /* 13 model space scale */
    put_int(&r, IGES_UNITS_MM, ','); /* 14, 15 units */
    put_string(&r, "MM", ',');
    put_int(&r, 1, ',');                                     /* 16 line weight gradations */
    put_real(&r, 0, ',');                                    /* 17 largest line width */
    put_string(&r, stamp, ',');                              /* 18 when written */
    put_real(&r, ic_trace_result_report(res)->fit_tol, ','); /* 19 resolution */
    put_real(&r, largest_coordinate(res), ',');              /* 20 largest coordinate */
    ic_iges_records_put(&r, ",,");                           /* 21, 22 author, organisation: none */
    put_int(&r, IGES_VERSION_5_3, ',');                      /* 23 version */
    put_int(&r, 0, ',');                                     /* 24 drafting standard: none */
    put_string(&r, stamp, ';');                              /* 25 when the model was made */
    ic_iges_records_end_line(&r);
    return r.seq;
}

/* Curve i's parameters (IGES 5.3, 4.23) into r, which counts the lines. */
static void put_curve(iges_records *r, const ic_trace_result *res, int i)
{
    const ic_bspline *b = &ic_trace_result_fit(res, i)->curve;
    put_int(r, IGES_BSPLINE_CURVE, ',');
    put_int(r, b->ncontrol - 1, ',');                       /* K */
    put_int(r, b->degree, ',');                             /* M */
    put_int(r, 0, ',');                                     /* PROP1: not said planar */
    put_int(r, ic_trace_result_curve(res, i)->closed, ','); /* PROP2: closed */
    put_int(r, 1, ',');                                     /* PROP3: polynomial */
    put_int(r, b->periodic, ',');                             /* PROP4: periodic */
    for (int k = 0; k < b->ncontrol + b->degree + 1; k++)
        put_real(r, b->knots[k], ',');
    for (int k = 0; k < b->ncontrol; k++)
        put_real(r, 1, ',');
    for (int k = 0; k < 3 * b->ncontrol; k++)
        put_real(r, b->control[k], ',');
    put_real(r, b->knots[b->degree], ','); /* V0, V1 */
    put_real(r, b->knots[b->ncontrol], ',');
    for (int k = 0; k < 3; k++) /* unused normal */
        put_real(r, 0, k < 2 ? ',' : ';');
    ic_iges_records_end_line(r);
}

/* The parameter lines of curve i (counted, not written). */
static int curve_lines(const ic_trace_result *res, int i)
{
    iges_records r;
    ic_iges_records_start(&r, NULL, 'P');
    put_curve(&r, res, i);
    return r.seq;
}

/* Two directory lines per curve (IGES 5.3, 2.2.4.4); returns how many. */
static int write_directory(FILE *f, const ic_trace_result *res)
{
    int seq = 0, pline = 1;
    for (int i = 0; i < ic_trace_result_num_curves(res); i++) {
        if (!ic_trace_result_fit(res, i))
            continue;
        const int lines = curve_lines(res, i);
        fprintf(f, "%8d%8d%8d%8d%8d%8d%8d%8d%8sD%7d\n", IGES_BSPLINE_CURVE, pline, 0, 0, 0, 0, 0, 0,
                "00000000", seq + 1);
        fprintf(f, "%8d%8d%8d%8d%8d%8s%8s%8s%8dD%7d\n", IGES_BSPLINE_CURVE, 0, 0, lines, 0, "", "",
                "CURVE", i, seq + 2);
        seq += 2;
        pline += lines;
    }
    return seq;
}

static int write_parameters(FILE *f, const ic_trace_result *res)
{
    iges_records r;
    ic_iges_records_start(&r, f, 'P');
    for (int i = 0, de = 1; i < ic_trace_result_num_curves(res); i++)
        if (ic_trace_result_fit(res, i)) {
            r.de = de;
            put_curve(&r, res, i);
            de += 2;
        }
    return r.seq;
}

ic_status ic_trace_write_iges(FILE *f, const ic_trace_result *res, const char *title, ic_error *err)
{
    IC_ARG_NOT_NULL(f, "f");
    IC_ARG_NOT_NULL(res, "res");
    ic_status st = ic_curve_check_fits(res, "IGES", err);
    if (st != IC_OK)
        return st;
    const int s = write_start(f, title);
    const int g = write_global(f, res, title);
    const int d = write_directory(f, res);
    const int p = write_parameters(f, res);
    fprintf(f, "S%7dG%7dD%7dP%7d%40sT%7d\n", s, g, d, p, "", 1);
    if (ferror(f))
        return ic_error_set(err, IC_ERR_IO, 0, "writing the IGES output failed");
    return IC_OK;
}
