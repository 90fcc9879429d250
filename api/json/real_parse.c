/* real_parse.c — decimal to double by one (rarely two) 64 x 64-bit products
 * (Eisel-Lemire; D. Lemire, "Number parsing at a gigabyte per second",
 * Software: Practice and Experience 51, 2021). See api/json/real_parse.h.
 *
 * Why: api/json/json_read.c reads most numbers exactly with one floating-point
 * operation (Clinger's fast path: at most 15-16 digits and |q| <= 22), but a
 * 17-digit number - what every client writing doubles exactly sends - went
 * through strtod()'s multi-precision path, ~1 µs. Here w (normalised to 64
 * bits) times the truncated 128-bit significand of 10^q (the table
 * api/json/real_pow10_128.h holds it plus one) gives the double's 54 leading bits; the
 * product is a lower bound within one unit of its last 64 bits, so whenever
 * the bits below the rounding bit cannot decide (all ones: a carry may come;
 * all zeros at the rounding bit: a possible exact tie) the answer is 0 and
 * strtod() decides. tests/api/test_real_text.c compares with strtod() on
 * millions of decimals (random 1-19 digits, every exponent, ties, neighbours
 * of ties, powers of ten). */
#include "json/real_parse.h"

#include <string.h>

#include "json/real_pow10_128.h"

__extension__ typedef unsigned __int128 u128;

/* floor(log2 10^q) for |q| <= 1233 (checked by the table's generator; the
 * constant is Lemire's 152170 + 65536 = 2^16 log2 10, rounded). */
static inline int floor_log2_pow10(int q)
{
    const int a = (152170 + 65536) * q;
    return a >= 0 ? a >> 16 : -((-a + 65535) >> 16);
}

int api_real_from_decimal(uint64_t w, int q, int negative, double *out)
{
    if (w == 0 || q < POW10_128_MIN || q > 308) return 0;
    const struct pow10_128 *g = &pow10_128_table[q - POW10_128_MIN];
    /* the table holds floor(10^q / 2^r) + 1: take the 1 back */
    const uint64_t thi = g->lo ? g->hi : g->hi - 1, tlo = g->lo - 1;
    const int lz = __builtin_clzll(w);
    w <<= lz;
    const u128 p = (u128)w * thi;
    uint64_t hi = (uint64_t)(p >> 64), lo = (uint64_t)p;
    if ((hi & 0x1FF) == 0x1FF) { /* a carry from the lower half may reach the rounding bit */
        const uint64_t mid = (uint64_t)(((u128)w * tlo) >> 64);
        lo += mid;
        if (lo < mid) hi++;
        /* still undecided within the product's error (< 2 units of lo) */
        if ((hi & 0x1FF) == 0x1FF && lo > UINT64_MAX - 2) return 0;
    }
    const int upper = (int)(hi >> 63);
    const int shift = upper + 9;
    uint64_t m = hi >> shift; /* 54 bits: the significand and one rounding bit */
    /* rounding bit set and nothing below it in hi: possibly an exact tie
     * (to even) or a value just above one; strtod decides */
    if ((m & 1) && (hi & ((UINT64_C(1) << shift) - 1)) == 0) return 0;
    int biased = floor_log2_pow10(q) + upper - lz + 63 + 1023;
    m = (m + (m & 1)) >> 1;
    if (m == UINT64_C(1) << 53) { /* rounding carried into a new bit */
        m >>= 1;
        biased++;
    }
    if (biased <= 0 || biased >= 2047) return 0; /* subnormal, zero or beyond the range */
    const uint64_t bits = ((uint64_t)(negative != 0) << 63) | ((uint64_t)biased << 52) |
                          (m & ((UINT64_C(1) << 52) - 1));
    memcpy(out, &bits, sizeof bits);
    return 1;
}
