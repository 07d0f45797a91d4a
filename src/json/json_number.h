/* The numbers of the JSON documents as text: the same bytes as printf's
 * "%.15g" where those 15 significant digits read back to the number
 * exactly, else "%.17g" (which always do); 0 for -0. About ten times
 * faster than printf and strtod: the digits come from exact integer
 * arithmetic, the read-back test from one correctly rounded division. */
#ifndef IC_JSON_NUMBER_H
#define IC_JSON_NUMBER_H

#include <stddef.h>

/* enough for "-d.dddddddddddddddde-308" and its terminating zero */
#define IC_JSON_NUMBER_MAX 32

/* x (finite) into out; returns the text's length. */
size_t ic_json_number_text(char out[IC_JSON_NUMBER_MAX], double x);

#endif
