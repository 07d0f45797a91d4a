/* The digits of the JSON documents' smallest numbers (json_number.c):
 * m 5^k / 2^sh rounded exactly, in 512-bit integers, where 128 bits are not
 * enough (5^k above 2^75: numbers from about 1e-18 down to 1e-180, the
 * rounding noise of coordinates that are 0). */
#ifndef IC_JSON_WIDE_H
#define IC_JSON_WIDE_H

#include <stdint.h>

/* The integer nearest to y = m 5^k / 2^sh (0 < sh < 511), ties to even;
 * 0 where m 5^k does not fit 512 bits or y not 64. *within: 1 when the
 * rounded integer is within half an ulp of the double m 2^e it was scaled
 * from (k + e = -sh: half an ulp is 5^k / 2 in y's numerator, an exact tie
 * counting where m is even; below a power of two, m = 2^52, the ulp is
 * half as wide), 0 when not. */
uint64_t ic_json_wide_round(uint64_t m, int k, int sh, int *within);

#endif
