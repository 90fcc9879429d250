/* real_format.c — double -> the text jansson's json_dumps writes with
 * JSON_REAL_PRECISION(17) (printf %.17g plus jansson's touch-ups), fast (see
 * real_format.h for the contract; docs/design.md: reals print with 17
 * significant digits, the same bytes every run).
 *
 * printf's %.17g converts exactly with multi-precision arithmetic (glibc's
 * __printf_fp): ~0.5-1 µs per real, the largest cost of a small answer. Here
 * the 17 digits come from one 64-bit product instead, in the manner of
 * Loitsch 2010 ("Printing floating-point numbers quickly and accurately with
 * integers", PLDI; the diy-fp product and cached powers of ten): with v =
 * w·2^e (w exact, 64 bits) and c ~= 10^(16-X) (64 bits, within one unit),
 * N = round(v·10^(16-X)) is the 17-digit integer printf rounds to, unless the
 * discarded part lies within the product's error bound of one half: then
 * (a few per cent of values, and subnormals) snprintf decides. The result is
 * therefore always printf's own, byte for byte (tests/api/test_json_write.c
 * checks millions of values against json_dumps).
 *
 * The cached powers are exact-rounded from big-integer arithmetic at build
 * time (scripts/gen_pow10_table.py -> real_format_pow10.h, committed): a
 * table generated once and checked is easier to audit than big-number code
 * in C run at first use, costs no start-up work or thread synchronisation,
 * and keeps this file free of allocation. The fast path is integer
 * arithmetic only (64-bit, and one 128-bit product by 10^j, j < 8). */
#include "real_format.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
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

/* floor(a / b) for b > 0 (C's '/' truncates toward zero). */
static int floor_div(int a, int b)
{
    return a >= 0 ? a / b : -((-a + b - 1) / b);
}

__extension__ typedef unsigned __int128 u128;

static const uint64_t pow10_u64[] = {
    UINT64_C(1),           UINT64_C(10),           UINT64_C(100),
    UINT64_C(1000),        UINT64_C(10000),        UINT64_C(100000),
    UINT64_C(1000000),     UINT64_C(10000000),     UINT64_C(100000000),
    UINT64_C(1000000000),  UINT64_C(10000000000),  UINT64_C(100000000000),
    UINT64_C(1000000000000), UINT64_C(10000000000000), UINT64_C(100000000000000),
    UINT64_C(1000000000000000), UINT64_C(10000000000000000), UINT64_C(100000000000000000),
};

/* 10^s (POW10_K_MIN <= s < POW10_K_MIN + 8·POW10_COUNT) as a 64-bit
 * significand rounded to nearest-ish: the cached power at or below s times
 * the exact 10^j, j < 8, renormalised with rounding. Error < 1 unit of the
 * last place (1/2 from the table, 1/2 from the renormalisation). */
static struct diyfp pow10_diyfp(int s)
{
    const int i = floor_div(s - POW10_K_MIN, POW10_K_STEP);
    const struct pow10_cached *cp = &pow10_cache[i];
    const int j = s - cp->k; /* 0..7 */
    struct diyfp c = {cp->f, cp->e};
    if (j == 0) return c;
    u128 p = (u128)c.f * pow10_u64[j]; /* < 2^88 */
    int sh = 64 - leading_zeros64((uint64_t)(p >> 64)); /* 1..24 bits above 64 */
    u128 r = (p + ((u128)1 << (sh - 1))) >> sh;
    if (r >> 64) { /* rounding carried into a new bit */
        r >>= 1;
        sh++;
    }
    c.f = (uint64_t)r;
    c.e += sh;
    return c;
}

static const char two_digits[201] = /* "00" "01" ... "99" */
    "0001020304050607080910111213141516171819"
    "2021222324252627282930313233343536373839"
    "4041424344454647484950515253545556575859"
    "6061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

/* x < 10^8 as exactly eight decimal digits at d (no NUL). */
static void put8(char *d, uint32_t x)
{
    for (int i = 6; i >= 0; i -= 2) {
        const uint32_t q = x / 100u;
        memcpy(d + i, two_digits + 2u * (x - 100u * q), 2);
        x = q;
    }
}

/* The 17 significant digits of finite positive normal v correctly rounded,
 * as printf's %.16e writes them, and the decimal exponent X of the first:
 * v ~= d.dddddddddddddddd·10^X. N = round(v·10^(16-X)) comes from one 64-bit
 * product w·c (w exact, c = 10^(16-X) within 1 unit, the product rounded:
 * within 2 units of the true value); when the part below N is within that
 * error of one half, the product cannot decide the rounding and 0 is
 * returned (the caller asks snprintf; a few per cent of values). 1 on
 * success. */
static int digits17_fast(uint64_t f, int e, char digits[17], int *X)
{
    const int lz = leading_zeros64(f);
    const struct diyfp w = {f << lz, e - lz}; /* v = w.f·2^w.e, 2^63 <= w.f */
    /* floor(log10 v) within one: v in [2^(w.e+63), 2^(w.e+64)) */
    int k = floor_div((w.e + 63) * 78913, 1 << 18);
    for (int attempt = 0; attempt < 3; attempt++) {
        const int s = 16 - k;
        if (s < POW10_K_MIN || s >= POW10_K_MIN + POW10_K_STEP * POW10_COUNT) return 0;
        const struct diyfp p = diyfp_mul(w, pow10_diyfp(s));
        const int sh = -p.e; /* N ~ 2^54..2^57: sh ~ 7..10 */
        if (sh < 2 || sh > 62) return 0;
        uint64_t n = p.f >> sh;
        const uint64_t frac = p.f & ((UINT64_C(1) << sh) - 1), half = UINT64_C(1) << (sh - 1);
        if (n >= pow10_u64[17]) {
            k++;
            continue;
        }
        if (n < pow10_u64[16]) {
            k--;
            continue;
        }
        const uint64_t err = 4; /* > the 2-unit bound: a margin */
        if (frac + err >= half && frac <= half + err) return 0;
        if (frac > half) n++;
        if (n == pow10_u64[17]) {
            n = pow10_u64[16];
            k++;
        }
        /* 17 digits: one, then two groups of eight in 32-bit arithmetic. */
        const uint32_t hi = (uint32_t)(n / UINT64_C(100000000)); /* < 10^9 */
        digits[0] = (char)('0' + hi / 100000000u);
        put8(digits + 1, hi % 100000000u);
        put8(digits + 9, (uint32_t)(n % UINT64_C(100000000)));
        *X = k;
        return 1;
    }
    return 0;
}

/* As digits17_fast for any finite positive v, through snprintf("%.16e")
 * (exact, locale-independent for this conversion's digits and exponent)
 * where the fast path cannot decide or v is subnormal. */
static void digits17(double v, char digits[17], int *X)
{
    uint64_t bits;
    memcpy(&bits, &v, sizeof bits);
    const int biased = (int)((bits >> DBL_SIG_BITS) & 0x7FF);
    if (biased != 0 &&
        digits17_fast((bits & (DBL_HIDDEN - 1)) | DBL_HIDDEN, biased - DBL_EXP_BIAS, digits, X))
        return;
    char t[48]; /* d.dddddddddddddddde-308, the point in the locale's spelling */
    snprintf(t, sizeof t, "%.16e", v);
    const char *ex = strchr(t, 'e');
    int m = 0;
    for (const char *q = t; ex && q < ex && m < 17; q++)
        if (*q >= '0' && *q <= '9') digits[m++] = *q;
    while (m < 17)
        digits[m++] = '0';
    *X = ex ? atoi(ex + 1) : 0;
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

    char digits[17];
    int X; /* decimal exponent of the first digit */
    digits17(x, digits, &X);
    int n = 17; /* %g drops trailing zeros */
    while (n > 1 && digits[n - 1] == '0')
        n--;
    const int decpt = X + 1; /* digits before the point */

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
