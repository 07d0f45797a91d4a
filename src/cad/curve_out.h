/* What the STEP and IGES writers of fitted curves (curve_step.c,
 * curve_iges.c) share: numbers, text, knots and the check of what is
 * written (docs/output-formats.md, "STEP" and "IGES"). */
#ifndef IC_CURVE_OUT_H
#define IC_CURVE_OUT_H

#include <stddef.h>

#include "intercurve/trace.h"

#define IC_CURVE_REAL_SIZE 32

/* x (finite) with 17 significant digits, which read back to the same
 * double, always with a decimal point and an upper-case exponent ("1.",
 * "-0.25", "1.0000000000000001E-05"): a REAL of ISO 10303-21 and of IGES. */
void ic_curve_real(char out[IC_CURVE_REAL_SIZE], double x);

/* s with every byte that is not printable ASCII replaced by '?', cut to
 * size - 1 bytes; NULL is "". */
void ic_curve_ascii(char *out, size_t size, const char *s);

/* How many knots from index i on equal knots[i] (the multiplicity of
 * that distinct knot). */
int ic_curve_knot_run(const ic_bspline *b, int i);

/* IC_OK when res has at least one fitted curve and every fitted curve is a
 * B-spline in space with finite numbers; else IC_ERR_INVALID saying which
 * and, with none, to fit first (ic_trace_fit). `format` names the output. */
ic_status ic_curve_check_fits(const ic_trace_result *res, const char *format, ic_error *err);

/* The UTC time now as strftime writes `format` (e.g. "%Y-%m-%dT%H:%M:%S"). */
void ic_curve_time_stamp(char *out, size_t size, const char *format);

#endif
