/* The JSON documents' numbers (json/json_number.h) against printf and strtod,
 * the rule they replace: "%.15g" where it reads back to the number, else
 * "%.17g"; 0 for -0. Byte for byte, on numbers of every exponent, on exact
 * decimal ties at the 15th and 17th digit (glibc rounds them to even), on
 * the neighbours of powers of ten and of the %g switches to exponents, and
 * on the tiny numbers that need 512-bit digits (json/json_wide.h). */
#include <float.h>
#include <stdint.h>
#include <string.h>

#include "harness.h"
#include "json/json_number.h"

/* the rule, written the slow way */
static void reference(char out[IC_JSON_NUMBER_MAX], double x)
{
    if (x == 0) {
        strcpy(out, "0");
        return;
    }
    snprintf(out, IC_JSON_NUMBER_MAX, "%.15g", x);
    if (strtod(out, NULL) != x)
        snprintf(out, IC_JSON_NUMBER_MAX, "%.17g", x);
}

static long mismatches; /* printed for the first few only */

static void compare(double x)
{
    if (!isfinite(x)) /* the writers write null for these */
        return;
    char got[IC_JSON_NUMBER_MAX], want[IC_JSON_NUMBER_MAX];
    const size_t n = ic_json_number_text(got, x);
    reference(want, x);
    if (strcmp(got, want) != 0 || n != strlen(want)) {
        if (mismatches++ < 10)
            fprintf(stderr, "%a: %s, printf %s\n", x, got, want);
    }
}

/* A generator of its own (no global state): xorshift64*. */
static uint64_t next(uint64_t *state)
{
    *state ^= *state >> 12;
    *state ^= *state << 25;
    *state ^= *state >> 27;
    return *state * 2685821657736338717ULL;
}

static double from_bits(uint64_t bits)
{
    double x;
    memcpy(&x, &bits, sizeof x);
    return x;
}

static void check(const char *what)
{
    CHECK(mismatches == 0, "%s: %ld numbers differ from printf", what, mismatches);
    mismatches = 0;
}

int main(void)
{
    uint64_t state = 0x9e3779b97f4a7c15ULL;
    for (int i = 0; i < 300000; i++) { /* every exponent, subnormals too */
        const double x = from_bits(next(&state));
        if (isfinite(x))
            compare(x);
    }
    check("random bit patterns");
    for (int i = 0; i < 300000; i++) { /* the magnitudes of coordinates and curvatures */
        const double x = ((double)(next(&state) >> 11) / 9007199254740992.0 - 0.5) *
                         pow(10, (int)(next(&state) % 25) - 12);
        compare(x);
    }
    check("numbers of 1e-13 to 1e12");
    for (int i = 0; i < 200000; i++) { /* rounding noise about zero: 512-bit digits */
        const double x = ((double)(next(&state) >> 11) / 9007199254740992.0 - 0.5) *
                         pow(10, -(int)(next(&state) % 180) - 17);
        compare(x);
    }
    check("numbers of 1e-197 to 1e-17");
    /* integers of 16 and 18 digits ending in 5: exact ties at the 15th and
     * 17th significant digit (below 2^53 and 2^63 where exactly a double) */
    for (int64_t i = 0; i < 100000; i++) {
        compare((double)(1000000000000005LL + 10 * i * 7919));
        compare(-(double)(1000000000000005LL + 10 * i * 7919));
        compare(ldexp((double)(next(&state) >> 11), -(int)(next(&state) % 60)));
    }
    compare(9007199254740993.0);
    compare(4503599627370497.5);
    check("exact ties");
    for (int p = -320; p <= 308; p++) { /* powers of ten and their neighbours */
        const double t = pow(10, p);
        compare(t);
        compare(nextafter(t, 0));
        compare(nextafter(t, INFINITY));
        compare(-t);
        compare(5 * t);
        compare(9.9999999999999995 * t);
        compare(1.0000000000000005 * t);
    }
    check("powers of ten");
    for (int p = -1074; p <= 1023; p++) { /* the ulp below a power of two is half as wide */
        const double t = ldexp(1, p);
        compare(t);
        compare(-t);
        compare(nextafter(t, 0));
        compare(nextafter(t, INFINITY));
        compare(3 * t);
    }
    check("powers of two");
    const double special[] = {1e-4, 9.99999999999999e-5, 1e-5, 1e15, 1e17, 123456789012345678.0,
                              DBL_MAX, DBL_MIN, DBL_TRUE_MIN, 0.1, 0.2, 0.3, 1.0 / 3, 3.141592653589793,
                              -0.0, 1, -1, 0.5, 2.5, 1e22, 1e23, 8.41e21, 5e-324};
    for (size_t i = 0; i < sizeof special / sizeof special[0]; i++)
        compare(special[i]);
    check("special numbers");
    char out[IC_JSON_NUMBER_MAX];
    CHECK(ic_json_number_text(out, -0.0) == 1 && strcmp(out, "0") == 0, "-0 is written 0");
    return harness_finish("json_number");
}
