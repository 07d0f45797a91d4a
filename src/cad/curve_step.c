/* Fitted intersection curves as an ISO 10303-21 file of AP214
 * (docs/output-formats.md, "STEP"): one product whose shape is a
 * geometrically bounded wireframe of B_SPLINE_CURVE_WITH_KNOTS, in
 * millimetres. */
#include "common/args.h"
#include "intercurve/writers.h"

#include "cad/curve_out.h"

#define STEP_SCHEMA "AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }"

/* References in a list per line, so that no line grows long. */
enum { STEP_ITEMS_PER_LINE = 8 };

/* The fixed entities, then each fitted curve's points and the curve. */
enum {
    ID_APPLICATION_CONTEXT = 1,
    ID_PROTOCOL,
    ID_PRODUCT_CONTEXT,
    ID_PRODUCT,
    ID_FORMATION,
    ID_DEFINITION_CONTEXT,
    ID_DEFINITION,
    ID_DEFINITION_SHAPE,
    ID_SHAPE_DEFINITION,
    ID_WIREFRAME,
    ID_CONTEXT,
    ID_LENGTH_UNIT,
    ID_ANGLE_UNIT,
    ID_SOLID_ANGLE_UNIT,
    ID_UNCERTAINTY,
    ID_CURVE_SET,
    ID_FIRST_CURVE
};

/* A Part 21 string: quotes doubled, backslashes doubled, only printable
 * ASCII. */
static void put_string(FILE *f, const char *s)
{
    char text[512];
    ic_curve_ascii(text, sizeof text, s);
    fputc('\'', f);
    for (const char *p = text; *p; p++) {
        if (*p == '\'' || *p == '\\')
            fputc(*p, f);
        fputc(*p, f);
    }
    fputc('\'', f);
}

static void put_real(FILE *f, double x)
{
    char r[IC_CURVE_REAL_SIZE];
    ic_curve_real(r, x);
    fputs(r, f);
}

/* The list separator before item k of a list. */
static void separate(FILE *f, int k)
{
    if (k > 0)
        fputs(k % STEP_ITEMS_PER_LINE ? "," : ",\n  ", f);
}

/* The entity number of curve i's B-spline (its points come just before). */
static int curve_id(const ic_trace_result *res, int i)
{
    int next = ID_FIRST_CURVE;
    for (int k = 0; k <= i; k++) {
        const ic_curve_fit *fit = ic_trace_result_fit(res, k);
        if (fit)
            next += fit->curve.ncontrol + 1;
    }
    return next - 1;
}

static void write_header(FILE *f, const char *title)
{
    char stamp[32];
    ic_curve_time_stamp(stamp, sizeof stamp, "%Y-%m-%dT%H:%M:%S");
    fputs("ISO-10303-21;\nHEADER;\n"
          "FILE_DESCRIPTION(('intersection curves as B-splines, written by intercurve'),'2;1');\n"
          "FILE_NAME(",
          f);
    put_string(f, title);
    fprintf(f, ",'%s',(''),(''),'intercurve','intercurve','');\n", stamp);
    fputs("FILE_SCHEMA(('" STEP_SCHEMA "'));\nENDSEC;\n", f);
}

/* The product, its shape, and the representation context in millimetres
 * with the fit tolerance as its uncertainty. */
static void write_context(FILE *f, const ic_trace_result *res, const char *title)
{
    fprintf(f, "#%d=APPLICATION_CONTEXT('core data for automotive mechanical design processes');\n",
            ID_APPLICATION_CONTEXT);
    fprintf(f,
            "#%d=APPLICATION_PROTOCOL_DEFINITION('international standard','automotive_design',"
            "2000,#%d);\n",
            ID_PROTOCOL, ID_APPLICATION_CONTEXT);
    fprintf(f, "#%d=PRODUCT_CONTEXT('',#%d,'mechanical');\n", ID_PRODUCT_CONTEXT,
            ID_APPLICATION_CONTEXT);
    fprintf(f, "#%d=PRODUCT('intersection curves',", ID_PRODUCT);
    put_string(f, title);
    fprintf(f, ",'',(#%d));\n", ID_PRODUCT_CONTEXT);
    fprintf(f, "#%d=PRODUCT_DEFINITION_FORMATION('','',#%d);\n", ID_FORMATION, ID_PRODUCT);
    fprintf(f, "#%d=PRODUCT_DEFINITION_CONTEXT('part definition',#%d,'design');\n",
            ID_DEFINITION_CONTEXT, ID_APPLICATION_CONTEXT);
    fprintf(f, "#%d=PRODUCT_DEFINITION('design','',#%d,#%d);\n", ID_DEFINITION, ID_FORMATION,
            ID_DEFINITION_CONTEXT);
    fprintf(f, "#%d=PRODUCT_DEFINITION_SHAPE('','',#%d);\n", ID_DEFINITION_SHAPE, ID_DEFINITION);
    fprintf(f, "#%d=SHAPE_DEFINITION_REPRESENTATION(#%d,#%d);\n", ID_SHAPE_DEFINITION,
            ID_DEFINITION_SHAPE, ID_WIREFRAME);
    fprintf(f,
            "#%d=GEOMETRICALLY_BOUNDED_WIREFRAME_SHAPE_REPRESENTATION('intersection curves',"
            "(#%d),#%d);\n",
            ID_WIREFRAME, ID_CURVE_SET, ID_CONTEXT);
    fprintf(f,
            "#%d=(GEOMETRIC_REPRESENTATION_CONTEXT(3)GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT((#%d))"
            "GLOBAL_UNIT_ASSIGNED_CONTEXT((#%d,#%d,#%d))REPRESENTATION_CONTEXT('',''));\n",
            ID_CONTEXT, ID_UNCERTAINTY, ID_LENGTH_UNIT, ID_ANGLE_UNIT, ID_SOLID_ANGLE_UNIT);
    fprintf(f, "#%d=(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MILLI.,.METRE.));\n", ID_LENGTH_UNIT);
    fprintf(f, "#%d=(NAMED_UNIT(*)PLANE_ANGLE_UNIT()SI_UNIT($,.RADIAN.));\n", ID_ANGLE_UNIT);
    fprintf(f, "#%d=(NAMED_UNIT(*)SI_UNIT($,.STERADIAN.)SOLID_ANGLE_UNIT());\n",
            ID_SOLID_ANGLE_UNIT);
    fprintf(f, "#%d=UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(", ID_UNCERTAINTY);
    put_real(f, ic_trace_result_report(res)->fit_tol);
    fprintf(f, "),#%d,'distance_accuracy_value','the fit tolerance');\n", ID_LENGTH_UNIT);
}

static void write_curve_set(FILE *f, const ic_trace_result *res)
{
    fprintf(f, "#%d=GEOMETRIC_CURVE_SET('intersection curves',(", ID_CURVE_SET);
    for (int i = 0, k = 0; i < ic_trace_result_num_curves(res); i++)
        if (ic_trace_result_fit(res, i)) {
            separate(f, k++);
            fprintf(f, "#%d", curve_id(res, i));
        }
    fputs("));\n", f);
}

/* Curve i's control points as CARTESIAN_POINTs, then its B-spline. */
static void write_curve(FILE *f, const ic_trace_result *res, int i)
{
    const ic_bspline *b = &ic_trace_result_fit(res, i)->curve;
    const int id = curve_id(res, i), first = id - b->ncontrol;
    for (int k = 0; k < b->ncontrol; k++) {
        fprintf(f, "#%d=CARTESIAN_POINT('',(", first + k);
        for (int j = 0; j < 3; j++) {
            fputs(j ? "," : "", f);
            put_real(f, b->control[3 * k + j]);
        }
        fputs("));\n", f);
    }
    fprintf(f, "#%d=B_SPLINE_CURVE_WITH_KNOTS('curve %d',%d,(", id, i, b->degree);
    for (int k = 0; k < b->ncontrol; k++) {
        separate(f, k);
        fprintf(f, "#%d", first + k);
    }
    fprintf(f, "),\n  .UNSPECIFIED.,%s,.F.,(",
            ic_trace_result_curve(res, i)->closed ? ".T." : ".F.");
    const int nknots = b->ncontrol + b->degree + 1;
    int distinct = 0;
    for (int k = 0; k < nknots; k += ic_curve_knot_run(b, k)) {
        separate(f, distinct++);
        fprintf(f, "%d", ic_curve_knot_run(b, k));
    }
    fputs("),\n  (", f);
    distinct = 0;
    for (int k = 0; k < nknots; k += ic_curve_knot_run(b, k)) {
        separate(f, distinct++);
        put_real(f, b->knots[k]);
    }
    fputs("),.UNSPECIFIED.);\n", f);
}

ic_status ic_trace_write_step(FILE *f, const ic_trace_result *res, const char *title, ic_error *err)
{
    IC_ARG_NOT_NULL(f, "f");
    IC_ARG_NOT_NULL(res, "res");
    ic_status st = ic_curve_check_fits(res, "STEP", err);
    if (st != IC_OK)
        return st;
    write_header(f, title);
    fputs("DATA;\n", f);
    write_context(f, res, title);
    write_curve_set(f, res);
    for (int i = 0; i < ic_trace_result_num_curves(res); i++)
        if (ic_trace_result_fit(res, i))
            write_curve(f, res, i);
    fputs("ENDSEC;\nEND-ISO-10303-21;\n", f);
    if (ferror(f))
        return ic_error_set(err, IC_ERR_IO, 0, "writing the STEP output failed");
    return IC_OK;
}
