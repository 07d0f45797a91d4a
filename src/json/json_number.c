/* Numbers as printf's %.15g or %.17g would write them (json_number.h).
 *
 * A double is m 2^e with an integer m < 2^53. Its P significant digits are
 * the integer nearest to y = m 2^e 10^k, k = P - 1 - X where X is the
 * decimal exponent; for the exponents met in practice (|k| <= 32, small
 * shifts) y's numerator fits 128 bits, for smaller numbers down to about
 * 1e-180 512 bits (json_wide.c), so the rounding is exact, ties to even as
 * glibc rounds them. Every other number (and a compiler without 128-bit
 * integers) takes printf and strtod. */
#include "json/json_number.h"
#include "json/json_wide.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* the digits of printf's first choice and of the one that always reads back */
#define SHORT_DIGITS 15
#define LONG_DIGITS 17
/* the largest k with 5^k below 2^64 (pow5 below), and with 10^k exact as a
 * double (a correctly rounded read-back in one operation) */
#define MAX_POW5 27
#define MAX_EXACT_POW10 22
/* the largest k with m 5^k below 2^128 for every m < 2^53 */
#define MAX_POW5_128 32

/* printf and strtod: every number */
static size_t slow_text(char out[IC_JSON_NUMBER_MAX], double x)
{
    snprintf(out, IC_JSON_NUMBER_MAX, "%.15g", x);
    if (strtod(out, NULL) != x)
        snprintf(out, IC_JSON_NUMBER_MAX, "%.17g", x);
    return strlen(out);
}

#ifdef __SIZEOF_INT128__
__extension__ typedef unsigned __int128 u128;

static const uint64_t pow5[MAX_POW5 + 1] = {
    1ULL, 5ULL, 25ULL, 125ULL, 625ULL, 3125ULL, 15625ULL, 78125ULL, 390625ULL,
    1953125ULL, 9765625ULL, 48828125ULL, 244140625ULL, 1220703125ULL, 6103515625ULL,
    30517578125ULL, 152587890625ULL, 762939453125ULL, 3814697265625ULL,
    19073486328125ULL, 95367431640625ULL, 476837158203125ULL, 2384185791015625ULL,
    11920928955078125ULL, 59604644775390625ULL, 298023223876953125ULL,
    1490116119384765625ULL, 7450580596923828125ULL};

static const double pow10_exact[MAX_EXACT_POW10 + 1] = {
    1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
    1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

static const uint64_t pow10_int[LONG_DIGITS + 1] = {
    1ULL, 10ULL, 100ULL, 1000ULL, 10000ULL, 100000ULL, 1000000ULL, 10000000ULL, 100000000ULL,
    1000000000ULL, 10000000000ULL, 100000000000ULL, 1000000000000ULL, 10000000000000ULL,
    100000000000000ULL, 1000000000000000ULL, 10000000000000000ULL, 100000000000000000ULL};

/* q, the quotient num / den, rounded to nearest, ties to even. */
static uint64_t round_quotient(u128 num, u128 den)
{
    const u128 q = num / den, r = num % den;
    const int up = 2 * r > den || (2 * r == den && (q & 1));
    return (uint64_t)q + (uint64_t)up;
}

/* num / 2^sh (0 < sh < 127) rounded to nearest, ties to even: shifts, not
 * a 128-bit division. */
static uint64_t round_shift(u128 num, int sh)
{
    const u128 q = num >> sh, r = num & (((u128)1 << sh) - 1), half = (u128)1 << (sh - 1);
    const int up = r > half || (r == half && (q & 1));
    return (uint64_t)q + (uint64_t)up;
}

/* 5^k for k <= MAX_POW5_128; 0 beyond */
static u128 pow5_wide(int k)
{
    if (k > MAX_POW5_128)
        return 0;
    return k <= MAX_POW5 ? pow5[k] : (u128)pow5[MAX_POW5] * pow5[k - MAX_POW5];
}

/* m 2^e 10^k rounded to an integer; 0 where it does not fit the arithmetic. */
static uint64_t scaled(uint64_t m, int e, int k)
{
    if (k >= 0) {
        const u128 p5 = pow5_wide(k);
        const int s = e + k;
        if (!p5) { /* a tiny number: 512 bits */
            int within = -1;
            return s < 0 ? ic_json_wide_round(m, k, -s, &within) : 0;
        }
        const u128 n = m * p5; /* below 2^128 */
        if (s >= 0) /* an integer, and y < 10^18 where X is at most one off */
            return s < 64 && (n << s) >> s == n ? (uint64_t)(n << s) : 0;
        return s > -127 ? round_shift(n, -s) : 0;
    }
    if (-k > MAX_POW5 || e < 0 || e > 74) /* m 2^e within 2^127 */
        return 0;
    const u128 ten = (u128)pow5[-k] << -k; /* 10^-k */
    return round_quotient((u128)m << e, ten);
}

/* Whether y (at exponent x) is below 10^(P-1) though it rounds to it: then
 * the digits are those one place further, *digits, unless they round up to
 * 10^P (hi). -1 where the exact arithmetic cannot tell. */
static int x_is_high(uint64_t m, int e, int P, int x, uint64_t hi, uint64_t *digits)
{
    const uint64_t d = scaled(m, e, P - x);
    if (d == 0)
        return -1; /* beyond the exact arithmetic */
    if (d >= hi)
        return 0;
    *digits = d;
    return 1;
}

/* floor(log10(a)), perhaps one off, for a = m 2^e: from the binary
 * exponent and a comparison with an exact power of ten where there is one,
 * else from log10. */
static int decimal_exponent(double a, int e)
{
    const int binary = e + 52; /* 2^binary <= a < 2^(binary + 1) */
    int x = (int)floor(binary * 0.30102999566398120); /* log10(2) */
    if (x + 1 < 0 || x + 1 > MAX_EXACT_POW10)
        return (int)floor(log10(a)); /* far from 1: one off at most */
    if (a >= pow10_exact[x + 1])
        x++;
    return x;
}

/* The P significant digits of a = m 2^e (positive, normal; x its decimal
 * exponent or one off) as the integer *digits
 * and the decimal exponent *X of the rounded number; 0 where the exact
 * arithmetic cannot reach. */
static int significant_digits(uint64_t m, int e, int P, int x, uint64_t *digits, int *X)
{
    const uint64_t lo = pow10_int[P - 1], hi = pow10_int[P]; /* lo <= digits < hi */
    int high;
    for (int tries = 0; tries < 3; tries++) { /* the estimate x may be one off */
        const uint64_t d = scaled(m, e, P - 1 - x);
        if (d == 0)
            return 0;
        if (d < lo) {
            x--;
        } else if (d > hi) {
            x++;
        } else if (d == lo && (high = x_is_high(m, e, P, x, hi, digits)) != 0) {
            *X = x - 1; /* y was below 10^(P-1), rounded up to it */
            return high > 0;
        } else {
            *digits = d == hi ? lo : d; /* rounded up to the next power of ten */
            *X = d == hi ? x + 1 : x;
            return 1;
        }
    }
    return 0;
}

/* Whether digits, the rounding of y = m 2^e 10^k (k >= 0, e + k < 0), is
 * within half an ulp of a = m 2^e, where strtod reads it back to a: in
 * units of 2^(e + k), y's numerator is n = m 5^k and half an ulp 5^k / 2
 * (5^k / 4 below a power of two: no power of two between 1e-18 and 1e-8
 * has a 15-digit decimal in between, so only json_wide.c, below 1e-18,
 * takes that case; here printf does). -1 where it cannot tell. */
static int within_half_ulp(uint64_t m, int e, int k, uint64_t digits)
{
    const int sh = -(e + k);
    const u128 p5 = pow5_wide(k);
    if (!p5 && sh > 0) { /* a tiny number: 512 bits */
        int within = -1;
        return ic_json_wide_round(m, k, sh, &within) == digits ? within : -1;
    }
    if (sh <= 0 || sh >= 127 || m == 1ULL << 52) /* powers of two: printf (34 numbers) */
        return -1;
    const u128 n = m * p5, q = n >> sh, r = n & (((u128)1 << sh) - 1);
    u128 dist;
    if (digits == q)
        dist = r;
    else if (digits == q + 1)
        dist = ((u128)1 << sh) - r;
    else
        return -1;
    return 2 * dist < p5 || (2 * dist == p5 && !(m & 1)); /* ties to even */
}

/* a = digits 10^(X - P + 1) exactly, as strtod would read it back:
 * 1 yes, 0 no, -1 not decidable with exact arithmetic. */
static int reads_back(double a, uint64_t m, int e, uint64_t digits, int X, int P)
{
    const int k = P - 1 - X;
    if (k > MAX_EXACT_POW10)
        return within_half_ulp(m, e, k, digits);
    if (k < -MAX_EXACT_POW10)
        return -1;
    /* digits < 2^53 and 10^|k| exact: one correctly rounded operation */
    const double back = k >= 0 ? (double)digits / pow10_exact[k] : (double)digits * pow10_exact[-k];
    return back == a;
}

/* printf's %.Pg of a number with P significant digits `digits` and decimal
 * exponent X: trailing zeros dropped, exponential below 1e-4 and from 10^P. */
static size_t g_format(char *out, int negative, uint64_t digits, int X, int P)
{
    char d[LONG_DIGITS];
    for (int i = P - 1; i >= 0; i--, digits /= 10)
        d[i] = (char)('0' + digits % 10);
    int nd = P;
    while (nd > 1 && d[nd - 1] == '0')
        nd--;
    char *o = out;
    if (negative)
        *o++ = '-';
    if (X < -4 || X >= P) {
        *o++ = d[0];
        if (nd > 1) {
            *o++ = '.';
            memcpy(o, d + 1, (size_t)nd - 1);
            o += nd - 1;
        }
        *o++ = 'e';
        *o++ = X < 0 ? '-' : '+';
        const int ex = abs(X); /* at least two digits, as printf */
        if (ex >= 100)
            *o++ = (char)('0' + ex / 100);
        *o++ = (char)('0' + ex / 10 % 10);
        *o++ = (char)('0' + ex % 10);
    } else if (X >= 0) {
        memcpy(o, d, (size_t)X + 1);
        o += X + 1;
        if (nd > X + 1) {
            *o++ = '.';
            memcpy(o, d + X + 1, (size_t)(nd - X - 1));
            o += nd - X - 1;
        }
    } else {
        *o++ = '0';
        *o++ = '.';
        for (int i = 0; i < -X - 1; i++)
            *o++ = '0';
        memcpy(o, d, (size_t)nd);
        o += nd;
    }
    *o = '\0';
    return (size_t)(o - out);
}

/* The exact path; 0 where it cannot decide and printf must. */
static size_t fast_text(char out[IC_JSON_NUMBER_MAX], double x)
{
    const double a = fabs(x);
    uint64_t bits;
    memcpy(&bits, &a, sizeof bits);
    const int biased = (int)(bits >> 52);
    if (biased == 0 || biased == 2047) /* subnormal, or not finite: printf */
        return 0;
    const uint64_t m = (bits & ((1ULL << 52) - 1)) | (1ULL << 52); /* a = m 2^e */
    const int e = biased - 1075;
    uint64_t digits;
    int X;
    if (!significant_digits(m, e, SHORT_DIGITS, decimal_exponent(a, e), &digits, &X))
        return 0;
    const int back = reads_back(a, m, e, digits, X, SHORT_DIGITS);
    if (back < 0)
        return 0;
    if (back)
        return g_format(out, x < 0, digits, X, SHORT_DIGITS);
    if (!significant_digits(m, e, LONG_DIGITS, X, &digits, &X)) /* X, or one less */
        return 0;
    return g_format(out, x < 0, digits, X, LONG_DIGITS);
}
#else
static size_t fast_text(char out[IC_JSON_NUMBER_MAX], double x)
{
    (void)out;
    (void)x;
    return 0;
}
#endif

size_t ic_json_number_text(char out[IC_JSON_NUMBER_MAX], double x)
{
    if (x == 0) { /* and -0 */
        memcpy(out, "0", 2);
        return 1;
    }
    const size_t n = fast_text(out, x);
    return n ? n : slow_text(out, x);
}
