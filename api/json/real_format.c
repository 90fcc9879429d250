/* real_format.c — double -> the shortest decimal text that reads back as the
 * same double (see api/json/real_format.h for the contract and the layout).
 *
 * The digits come from Schubfach (Giulietti 2020, "The Schubfach way to
 * render doubles"; the 64-bit-limb arrangement of R. Abolz's Drachennest):
 * with the double v = c 2^q, the rounding interval's ends and v itself are
 * scaled by 10^-k (k = floor(log10 2^q), one 128-bit power of ten from the
 * table, each product rounded to odd), which leaves at most two candidates
 * of the shortest length in the interval - ten times coarser than 10^k, then
 * at 10^k - and the one nearest v is taken (ties to even). Exact: no
 * fallback, integer arithmetic only (64 x 64 -> 128-bit products), no
 * allocation, no locale. Several times cheaper than the exact %.17g conversion it
 * replaces (glibc's multi-precision printf), and the texts are shorter
 * (0.6 instead of 0.59999999999999998).
 *
 * The powers of ten are generated once with exact big-integer arithmetic
 * (scripts/gen_pow10_128.py -> api/json/real_pow10_128.h, committed, also read by
 * api/json/real_parse.c): a generated and checked table is easier to audit than
 * multi-precision code run at first use. tests/api/test_json_write.c checks
 * the contract's text, built there from snprintf and strtod alone, on ~2
 * million values; tests/api/test_real_text.c reads every text back with
 * api_json_number_scan. */
#include "json/real_format.h"

#include <stdint.h>
#include <string.h>

#include "json/real_pow10_128.h"

__extension__ typedef unsigned __int128 u128;

#define DBL_SIG_BITS 52
#define DBL_HIDDEN (UINT64_C(1) << DBL_SIG_BITS)
#define DBL_EXP_BIAS 1075 /* 1023 + 52: value = c * 2^(biased - 1075) */

/* floor(a / 2^s) for any sign of a (an arithmetic shift, spelled out). */
static inline int floor_shift(int a, int s)
{
    return a >= 0 ? a >> s : -((-a + (1 << s) - 1) >> s);
}

/* floor(log2 10^e), |e| <= 1233 (checked by the table's generator). */
static inline int floor_log2_pow10(int e)
{
    return floor_shift(e * 1741647, 19);
}

/* The integer part of g * cp / 2^128 with its lowest bit set when the
 * discarded part is not (near) zero: the "round to odd" of Schubfach, where
 * g is 10^-k rounded up, so a true remainder of zero shows as 0 or 1 in the
 * 64 bits kept below the integer part. */
static inline uint64_t round_to_odd(const struct pow10_128 *g, uint64_t cp)
{
    const u128 x = (u128)g->lo * cp;
    const u128 y = (u128)g->hi * cp;
    const u128 z = y + (uint64_t)(x >> 64);
    const uint64_t z1 = (uint64_t)(z >> 64), z0 = (uint64_t)z;
    return z1 | (z0 > 1);
}

/* The shortest decimal d 10^e in the rounding interval of the positive
 * finite double with significand field `sig` and biased exponent `biased`,
 * the one nearest the double among those (ties: even d). d may end in
 * zeros. */
static void shortest(uint64_t sig, int biased, uint64_t *d, int *e)
{
    uint64_t c;
    int q;
    if (biased != 0) {
        c = DBL_HIDDEN | sig;
        q = biased - DBL_EXP_BIAS;
        /* an integer below 2^53: itself (no shorter text reads back) */
        if (q <= 0 && -q < 53 && (c & ((UINT64_C(1) << -q) - 1)) == 0) {
            *d = c >> -q;
            *e = 0;
            return;
        }
    } else {
        c = sig; /* subnormal */
        q = 1 - DBL_EXP_BIAS;
    }
    const int even = (c & 1) == 0;
    /* the lower gap is half the upper one at a power of two (not the
     * smallest normal exponent, whose lower neighbour is subnormal) */
    const int lower_closer = sig == 0 && biased > 1;
    const uint64_t cbl = 4 * c - 2 + (uint64_t)lower_closer, cb = 4 * c, cbr = 4 * c + 2;
    /* k = floor(log10 2^q), or floor(log10 (3/4) 2^q) when lower_closer */
    const int k = floor_shift(q * 1262611 - (lower_closer ? 524031 : 0), 22);
    const int h = q + floor_log2_pow10(-k) + 1; /* 1..4 */
    const struct pow10_128 *g = &pow10_128_table[-k - POW10_128_MIN];
    const uint64_t vbl = round_to_odd(g, cbl << h);
    const uint64_t vb = round_to_odd(g, cb << h);
    const uint64_t vbr = round_to_odd(g, cbr << h);
    const uint64_t lower = vbl + !even, upper = vbr - !even;
    const uint64_t s = vb / 4;
    if (s >= 10) { /* one digit fewer: 10 s' or 10 (s' + 1) */
        const uint64_t sp = s / 10;
        const int up_inside = lower <= 40 * sp, wp_inside = 40 * sp + 40 <= upper;
        if (up_inside != wp_inside) {
            *d = sp + (uint64_t)wp_inside;
            *e = k + 1;
            return;
        }
    }
    const int u_inside = lower <= 4 * s, w_inside = 4 * s + 4 <= upper;
    if (u_inside != w_inside) {
        *d = s + (uint64_t)w_inside;
        *e = k;
        return;
    }
    const uint64_t mid = 4 * s + 2; /* both inside: the nearer, ties to even */
    *d = s + (uint64_t)(vb > mid || (vb == mid && (s & 1) != 0));
    *e = k;
}

static const char two_digits[201] = /* "00" "01" ... "99" */
    "0001020304050607080910111213141516171819"
    "2021222324252627282930313233343536373839"
    "4041424344454647484950515253545556575859"
    "6061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

/* d > 0 (at most 17 digits, no trailing zero) as decimal digits at out;
 * returns their count. */
static int put_digits(uint64_t d, char out[20])
{
    char t[40]; /* the digits end at t + 20; a fixed 20-byte copy inlines */
    int i = 20;
    while (d >= 100) {
        const uint64_t q = d / 100;
        i -= 2;
        memcpy(t + i, two_digits + 2 * (d - 100 * q), 2);
        d = q;
    }
    if (d >= 10) {
        i -= 2;
        memcpy(t + i, two_digits + 2 * d, 2);
    } else {
        t[--i] = (char)('0' + d);
    }
    memcpy(out, t + i, 20);
    return 20 - i;
}

static char *write_exponent(char *p, int x) /* |x| <= 324 */
{
    *p++ = 'e';
    if (x < 0) {
        *p++ = '-';
        x = -x;
    }
    if (x >= 100) {
        *p++ = (char)('0' + x / 100);
        x %= 100;
        *p++ = (char)('0' + x / 10);
    } else if (x >= 10) {
        *p++ = (char)('0' + x / 10);
    }
    *p++ = (char)('0' + x % 10);
    return p;
}

size_t api_real_format(double x, char buf[API_REAL_FORMAT_SIZE])
{
    uint64_t bits;
    memcpy(&bits, &x, sizeof bits);
    const int biased = (int)((bits >> DBL_SIG_BITS) & 0x7FF);
    if (biased == 0x7FF) { /* NaN or infinity */
        memcpy(buf, "null", 5);
        return 4;
    }
    /* The text is composed in t with fixed-size copies (inlined, no call
     * per piece) and leaves in one fixed copy of API_REAL_FORMAT_SIZE bytes:
     * the bytes of buf after the NUL are unspecified. */
    char t[64], *p = t;
    if (bits >> 63) *p++ = '-';
    const uint64_t sig = bits & (DBL_HIDDEN - 1);
    if (biased == 0 && sig == 0) { /* +-0 */
        memcpy(p, "0.0", 4);
        memcpy(buf, t, 5);
        return (size_t)(p - t) + 3;
    }
    uint64_t d;
    int e;
    shortest(sig, biased, &d, &e);
    /* shortest: no trailing zeros (an exact binary fraction such as 4.375
     * comes out as 4375000000000000 10^-15: strip them in large steps) */
    while (d % 100000000 == 0) {
        d /= 100000000;
        e += 8;
    }
    if (d % 10000 == 0) {
        d /= 10000;
        e += 4;
    }
    if (d % 100 == 0) {
        d /= 100;
        e += 2;
    }
    if (d % 10 == 0) {
        d /= 10;
        e++;
    }
    char digits[40]; /* n digits, then slack for the fixed-size copies */
    const int n = put_digits(d, digits);
    const int X = e + n - 1; /* decimal exponent of the first digit */
    const int decpt = X + 1; /* digits before the point */

    if (X < -4 || X >= 17) { /* scientific, as %.17g switches */
        *p++ = digits[0];
        if (n > 1) {
            *p++ = '.';
            memcpy(p, digits + 1, 20);
            p += n - 1;
        }
        p = write_exponent(p, X);
    } else if (decpt <= 0) { /* 0.000ddd: -3 <= decpt <= 0 */
        memcpy(p, "0.000000", 8);
        p += 2 - decpt;
        memcpy(p, digits, 20);
        p += n;
    } else if (decpt < n) { /* ddd.ddd */
        memcpy(p, digits, 20);
        p += decpt;
        *p++ = '.';
        memcpy(p, digits + decpt, 20);
        p += n - decpt;
    } else { /* ddd000.0 (decpt <= 17) */
        memcpy(p, digits, 20);
        p += n;
        memcpy(p, "0000000000000000", 16);
        p += decpt - n;
        memcpy(p, ".0", 2);
        p += 2;
    }
    *p = '\0';
    memcpy(buf, t, API_REAL_FORMAT_SIZE);
    return (size_t)(p - t);
}
