/* real_format.c — double -> shortest round-trip decimal (Grisu2), written
 * out in jansson's notation (see real_format.h for the contract).
 *
 * Algorithm: Loitsch 2010, "Printing floating-point numbers quickly and
 * accurately with integers" (PLDI), §5 "Grisu2", with the exponent window
 * alpha = -60, gamma = -32 so that the integral part of the scaled upper
 * boundary fits 32 bits and ten times its fraction fits 64. In short:
 *   v = f·2^e has the rounding interval [m-, m+] (the midpoints to its
 *   neighbours; m- is closer when f is a power of two above the smallest
 *   normal). Multiply w = v, m- and m+ by a cached c ~= 10^-k (64-bit,
 *   rounded; error < 1/2 unit of the last place each multiplication, so the
 *   products are off by < 1 unit): then narrow [m-·c, m+·c] by one unit on
 *   each side, so every number in the narrowed interval is strictly inside
 *   v's true rounding interval and reads back as v. Generate digits of the
 *   scaled m+ until the remainder falls within the interval (the fewest
 *   digits inside it), then step the last digit down towards w while that
 *   stays inside and gets closer ("round weed").
 * Why it is not always shortest: the narrowing by one unit can exclude the
 * only shortest candidate (Loitsch reports ~99.9 % shortest for Grisu2; the
 * test measures ours).
 *
 * The cached powers are exact-rounded from big-integer arithmetic at build
 * time (scripts/gen_pow10_table.py -> real_format_pow10.h, committed): a
 * table generated once and checked for every reachable exponent is easier to
 * audit than big-number code in C run at first use, costs no start-up work
 * or thread synchronisation, and keeps this file free of allocation.
 * All arithmetic is on unsigned 64-bit integers (no overflow, no signed
 * shifts); no floating-point arithmetic after the bit decomposition. */
#include "real_format.h"

#include <stdint.h>
#include <string.h>

#include "real_format_pow10.h"

struct diyfp {
    uint64_t f; /* significand */
    int e;      /* binary exponent: value = f * 2^e */
};

#define DBL_SIG_BITS 52
#define DBL_HIDDEN (UINT64_C(1) << DBL_SIG_BITS)
#define DBL_EXP_BIAS 1075 /* 1023 + 52: value = sig * 2^(biased - 1075) */

static int leading_zeros64(uint64_t x) /* x != 0 */
{
#if defined(__GNUC__) || defined(__clang__)
    return __builtin_clzll(x);
#else
    int n = 0;
    while (!(x & (UINT64_C(1) << 63))) {
        x <<= 1;
        n++;
    }
    return n;
#endif
}

/* Upper 64 bits of the 128-bit product, rounded to nearest (Loitsch §2). */
static struct diyfp diyfp_mul(struct diyfp x, struct diyfp y)
{
    const uint64_t m32 = UINT64_C(0xFFFFFFFF);
    uint64_t a = x.f >> 32, b = x.f & m32, c = y.f >> 32, d = y.f & m32;
    uint64_t ac = a * c, bc = b * c, ad = a * d, bd = b * d;
    uint64_t mid = (bd >> 32) + (ad & m32) + (bc & m32) + (UINT64_C(1) << 31);
    struct diyfp r = {ac + (ad >> 32) + (bc >> 32) + (mid >> 32), x.e + y.e + 64};
    return r;
}

/* Index into pow10_cache of the power that brings a number with binary
 * exponent e (of a 64-bit normalised significand) into [alpha, gamma]:
 * k = ceil((alpha - e - 1)·log10 2), 78913/2^18 ~= log10 2, C division
 * truncating toward zero (= ceil for negative x, floor + 1 for positive x).
 * The generator replicated this formula and checked it for every e the
 * formatter meets (-1137..960): always in range, product in the window. */
static int pow10_index(int e)
{
    int x = POW10_ALPHA - e - 1;
    int k = x * 78913 / (1 << 18) + (x > 0);
    return (-POW10_K_MIN + k + (POW10_K_STEP - 1)) / POW10_K_STEP;
}

/* Step the last digit down while the candidate stays in the interval
 * (rest + ten_k <= delta) and gets closer to w (Loitsch §5, "round_weed"
 * without the safety margin of Grisu3). dist = M+ - w, rest = M+ - candidate,
 * all in units of the scaled interval. */
static void round_weed(char *digits, int len, uint64_t dist, uint64_t delta, uint64_t rest,
                       uint64_t ten_k)
{
    while (rest < dist && delta - rest >= ten_k &&
           (rest + ten_k < dist || dist - rest > rest + ten_k - dist)) {
        digits[len - 1]--;
        rest += ten_k;
    }
}

/* Digits of the scaled upper boundary mp, stopping as soon as the rest is
 * within delta = mp - mm (Loitsch §5, DigitGen). Writes 1..17 digits, sets
 * *len and adds the decimal exponent of the last digit to *dexp. */
static void digit_gen(char *digits, int *len, int *dexp, struct diyfp mm, struct diyfp w,
                      struct diyfp mp)
{
    static const uint32_t pow10_32[] = {1u,      10u,      100u,      1000u,      10000u,
                                        100000u, 1000000u, 10000000u, 100000000u, 1000000000u};
    uint64_t delta = mp.f - mm.f;
    uint64_t dist = mp.f - w.f;
    const int shift = -mp.e; /* 32..60 */
    const uint64_t one = UINT64_C(1) << shift, mask = one - 1;
    uint32_t p1 = (uint32_t)(mp.f >> shift); /* integral part, > 0, < 2^32 */
    uint64_t p2 = mp.f & mask;               /* fractional part */
    int n = 0;

    int kappa = 1; /* number of decimal digits in p1 */
    while (kappa < 10 && p1 >= pow10_32[kappa])
        kappa++;

    while (kappa > 0) {
        uint32_t p = pow10_32[kappa - 1];
        uint32_t d = p1 / p;
        p1 %= p;
        digits[n++] = (char)('0' + d);
        kappa--;
        uint64_t rest = ((uint64_t)p1 << shift) + p2;
        if (rest <= delta) {
            *len = n;
            *dexp += kappa;
            round_weed(digits, n, dist, delta, rest, (uint64_t)pow10_32[kappa] << shift);
            return;
        }
    }
    /* The fraction: p2 < 2^60, so 10·p2 < 2^64; delta and dist stay below
     * p2 (else the loop has stopped), so they do not overflow either. */
    for (;;) {
        p2 *= 10;
        delta *= 10;
        dist *= 10;
        digits[n++] = (char)('0' + (p2 >> shift));
        p2 &= mask;
        kappa--;
        if (p2 <= delta) break;
    }
    *len = n;
    *dexp += kappa;
    round_weed(digits, n, dist, delta, p2, one);
}

/* Shortest (nearly always) digits of finite positive v: value = digits·10^dexp. */
static int grisu2(double v, char *digits, int *dexp)
{
    uint64_t bits;
    memcpy(&bits, &v, sizeof bits);
    const uint64_t frac = bits & (DBL_HIDDEN - 1);
    const int biased = (int)((bits >> DBL_SIG_BITS) & 0x7FF);
    struct diyfp w;
    if (biased == 0) { /* subnormal */
        w.f = frac;
        w.e = 1 - DBL_EXP_BIAS;
    } else {
        w.f = frac | DBL_HIDDEN;
        w.e = biased - DBL_EXP_BIAS;
    }

    /* Boundaries: midpoints to the neighbours. The lower neighbour is half
     * as far when frac == 0 (a power of two), except at the smallest normal
     * whose lower neighbour is the largest subnormal at the same spacing. */
    struct diyfp mp = {(w.f << 1) + 1, w.e - 1}, mm;
    if (frac == 0 && biased > 1) {
        mm.f = (w.f << 2) - 1;
        mm.e = w.e - 2;
    } else {
        mm.f = (w.f << 1) - 1;
        mm.e = w.e - 1;
    }
    const int lz = leading_zeros64(mp.f);
    mp.f <<= lz;
    mp.e -= lz;
    mm.f <<= mm.e - mp.e; /* 0..63: mm < mp at the same scale */
    mm.e = mp.e;
    /* w normalised: 2f+1 has exactly one bit more than f, so w lands on mp.e */
    w.f <<= w.e - mp.e;
    w.e = mp.e;

    const struct pow10_cached *cp = &pow10_cache[pow10_index(mp.e)];
    const struct diyfp c = {cp->f, cp->e};
    struct diyfp W = diyfp_mul(w, c), Mm = diyfp_mul(mm, c), Mp = diyfp_mul(mp, c);
    /* Each product is within 1/2 unit; with c's own rounding, within 1 unit:
     * shrink the interval so everything inside reads back as v. */
    Mm.f += 1;
    Mp.f -= 1;
    int len = 0;
    *dexp = -cp->k;
    digit_gen(digits, &len, dexp, Mm, W, Mp);
    return len;
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
    char *p = buf;
    if (((bits >> DBL_SIG_BITS) & 0x7FF) == 0x7FF) { /* NaN or infinity */
        memcpy(buf, "null", 5);
        return 4;
    }
    if (bits >> 63) *p++ = '-';
    if ((bits & ~(UINT64_C(1) << 63)) == 0) { /* +-0 */
        memcpy(p, "0.0", 4);
        return (size_t)(p - buf) + 3;
    }
    if (bits >> 63) x = -x;

    char digits[32]; /* at most 17 are written (checked by the test) */
    int dexp;
    const int n = grisu2(x, digits, &dexp); /* 1..17 digits */
    const int decpt = n + dexp;             /* digits before the point */
    const int X = decpt - 1;                /* decimal exponent of the first digit */

    if (X < -4 || X >= 17) { /* %g with P = 17 */
        *p++ = digits[0];
        if (n > 1) {
            *p++ = '.';
            memcpy(p, digits + 1, (size_t)(n - 1));
            p += n - 1;
        }
        p = write_exponent(p, X);
    } else if (decpt <= 0) { /* 0.000ddd: -3 <= decpt <= 0 */
        *p++ = '0';
        *p++ = '.';
        for (int i = 0; i < -decpt; i++)
            *p++ = '0';
        memcpy(p, digits, (size_t)n);
        p += n;
    } else if (decpt < n) { /* ddd.ddd */
        memcpy(p, digits, (size_t)decpt);
        p += decpt;
        *p++ = '.';
        memcpy(p, digits + decpt, (size_t)(n - decpt));
        p += n - decpt;
    } else { /* ddd000.0 */
        memcpy(p, digits, (size_t)n);
        p += n;
        for (int i = n; i < decpt; i++)
            *p++ = '0';
        *p++ = '.';
        *p++ = '0';
    }
    *p = '\0';
    return (size_t)(p - buf);
}
