/* Exact rounding of m 5^k / 2^sh in 512 bits (json_wide.h). */
#include "json/json_wide.h"

#include <string.h>

#ifdef __SIZEOF_INT128__
#define LIMBS 8 /* of 64 bits, least significant first */
#define BITS (64 * LIMBS)
#define POW5_STEP 27 /* 5^27 is the largest power of five below 2^64 */
#define POW5_STEP_VALUE 7450580596923828125ULL

__extension__ typedef unsigned __int128 u128;

typedef struct {
    uint64_t w[LIMBS];
} wide;

/* a *= b, a having `used` limbs that may be non-zero (the rest are 0);
 * returns the limbs used after, 0 on overflow */
static int mul(wide *a, int used, uint64_t b)
{
    u128 carry = 0;
    for (int i = 0; i < used; i++) {
        const u128 p = (u128)a->w[i] * b + carry;
        a->w[i] = (uint64_t)p;
        carry = p >> 64;
    }
    if (carry == 0)
        return used;
    if (used == LIMBS)
        return 0;
    a->w[used] = (uint64_t)carry;
    return used + 1;
}

/* a = 5^k; the limbs used, 0 where it does not fit */
static int pow5(wide *a, int k)
{
    static const uint64_t small[POW5_STEP] = {
        1ULL, 5ULL, 25ULL, 125ULL, 625ULL, 3125ULL, 15625ULL, 78125ULL, 390625ULL,
        1953125ULL, 9765625ULL, 48828125ULL, 244140625ULL, 1220703125ULL, 6103515625ULL,
        30517578125ULL, 152587890625ULL, 762939453125ULL, 3814697265625ULL,
        19073486328125ULL, 95367431640625ULL, 476837158203125ULL, 2384185791015625ULL,
        11920928955078125ULL, 59604644775390625ULL, 298023223876953125ULL,
        1490116119384765625ULL};
    memset(a, 0, sizeof *a);
    a->w[0] = small[k % POW5_STEP];
    int used = 1;
    for (int i = 0; used && i < k / POW5_STEP; i++)
        used = mul(a, used, POW5_STEP_VALUE);
    return used;
}

static int bit(const wide *a, int i)
{
    return (int)((a->w[i / 64] >> (i % 64)) & 1);
}

/* a mod 2^n */
static wide low_bits(const wide *a, int n)
{
    wide r = *a;
    for (int i = 0; i < LIMBS; i++) {
        const int from = 64 * i;
        if (from >= n)
            r.w[i] = 0;
        else if (n - from < 64)
            r.w[i] &= (1ULL << (n - from)) - 1;
    }
    return r;
}

static int is_zero(const wide *a)
{
    for (int i = 0; i < LIMBS; i++)
        if (a->w[i])
            return 0;
    return 1;
}

/* a >> n where it fits 64 bits; *fits 0 else */
static uint64_t high_bits(const wide *a, int n, int *fits)
{
    const int limb = n / 64, off = n % 64;
    const uint64_t next = limb + 1 < LIMBS ? a->w[limb + 1] : 0;
    *fits = off ? next >> off == 0 : next == 0;
    for (int i = limb + 2; i < LIMBS; i++)
        *fits = *fits && a->w[i] == 0;
    return off ? a->w[limb] >> off | next << (64 - off) : a->w[limb];
}

/* a - b (a >= b) */
static wide minus(const wide *a, const wide *b)
{
    wide r;
    uint64_t borrow = 0;
    for (int i = 0; i < LIMBS; i++) {
        const uint64_t d = a->w[i] - b->w[i] - borrow;
        borrow = a->w[i] < b->w[i] || (a->w[i] == b->w[i] && borrow);
        r.w[i] = d;
    }
    return r;
}

/* 2a (a below 2^(BITS - 1)) */
static wide twice(const wide *a)
{
    wide r;
    for (int i = LIMBS - 1; i >= 0; i--)
        r.w[i] = a->w[i] << 1 | (i > 0 ? a->w[i - 1] >> 63 : 0);
    return r;
}

/* the sign of a - b */
static int compare(const wide *a, const wide *b)
{
    for (int i = LIMBS - 1; i >= 0; i--)
        if (a->w[i] != b->w[i])
            return a->w[i] > b->w[i] ? 1 : -1;
    return 0;
}

uint64_t ic_json_wide_round(uint64_t m, int k, int sh, int *within)
{
    wide p5;
    int fits;
    const int used = sh > 0 && sh < BITS - 1 ? pow5(&p5, k) : 0;
    if (!used)
        return 0;
    wide n = p5;
    if (!mul(&n, used, m))
        return 0;
    const uint64_t q = high_bits(&n, sh, &fits);
    if (!fits)
        return 0;
    const wide r = low_bits(&n, sh), below_half = low_bits(&n, sh - 1);
    const int up = bit(&n, sh - 1) && (!is_zero(&below_half) || (q & 1));
    if (q + up < q) /* 2^64 */
        return 0;
    wide dist = r; /* |rounded 2^sh - n| */
    if (up) {
        wide power = {{0}};
        power.w[sh / 64] = 1ULL << (sh % 64);
        dist = minus(&power, &r);
    }
    /* half an ulp is 5^k / 2; below a power of two (m = 2^52, even) 5^k / 4 */
    wide scaled_dist = twice(&dist);
    if (m == 1ULL << 52 && !up)
        scaled_dist = twice(&scaled_dist);
    const int side = compare(&scaled_dist, &p5);
    *within = side < 0 || (side == 0 && !(m & 1)); /* a tie goes to the even one */
    return q + (uint64_t)up;
}
#else
uint64_t ic_json_wide_round(uint64_t m, int k, int sh, int *within)
{
    (void)m;
    (void)k;
    (void)sh;
    *within = -1;
    return 0; /* printf and strtod then */
}
#endif
