/* test_real_text.c — numbers in and out: the JSON number reader
 * (api_json_number_scan: Clinger's exact path, Eisel-Lemire in
 * api/json/real_parse.c, strtod for the rest) against glibc's strtod, and the
 * writer's texts (api_real_format) read back by it.
 *
 * (a) the reader gives strtod's double bit for bit on ~2 million texts:
 *     every double's %.17g, %.16e and %.15g over random bit patterns;
 *     random decimals of 1 to 19 digits at every exponent from -350 to 330
 *     (underflow to 0 and subnormals included); more than 19 digits
 *     (trailing zeros and not); powers of ten 1e-350..1e310; exact ties
 *     halfway between two doubles written with few digits (2^53 + 1,
 *     (2k + 1) 2^(e-1) for small e: round to even) and one unit of the last
 *     digit on either side of them; the smallest subnormal, DBL_MIN and
 *     DBL_MAX and their neighbours; negative zero; overflow (1e309) is
 *     refused as jansson refuses it.
 * (b) every text api_real_format writes for ~1 million doubles (random bits,
 *     subnormals, powers of two) reads back through the reader as the same
 *     double, and is never longer than %.17g's.
 * (c) the fast paths carry the load: on random 17-digit texts, the reader
 *     calls strtod for fewer than 1 % (counted through the Eisel-Lemire
 *     function's own verdict, deterministic). */
#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "json/json_read.h"
#include "json/real_format.h"
#include "json/real_parse.h"
#include "testlib.h"

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_UNDEFINED__)
#define SCALE 4
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(undefined_behavior_sanitizer)
#define SCALE 4
#endif
#endif
#ifndef SCALE
#define SCALE 1
#endif

static uint64_t rng_state = 0x2545F4914F6CDD1DULL;
static uint64_t rnd(void) /* splitmix64 */
{
    uint64_t z = (rng_state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

static double of_bits(uint64_t b)
{
    double x;
    memcpy(&x, &b, sizeof x);
    return x;
}

static long n_read, n_read_bad;

/* The reader on text t against strtod (both refuse overflow: jansson's). */
static void check_read(const char *t)
{
    const size_t n = strlen(t);
    double v = 0.0;
    const char *end = api_json_number_scan(t, t + n, &v);
    errno = 0;
    char *stop;
    const double w = strtod(t, &stop);
    const int overflow = (w == HUGE_VAL || w == -HUGE_VAL) && errno == ERANGE;
    n_read++;
    int ok;
    if (overflow) ok = end == NULL;
    else ok = end == t + n && memcmp(&v, &w, sizeof v) == 0;
    if (!ok && n_read_bad++ < 10)
        fprintf(stderr, "read \"%s\": %s %a, strtod %a\n", t, end ? "got" : "refused", v, w);
}

/* A random decimal of nd digits (first nonzero) with exponent e, signed. */
static void random_decimal(char *t, int nd, int e)
{
    char d[64];
    for (int k = 0; k < nd; k++)
        d[k] = (char)('0' + rnd() % 10);
    d[0] = (char)('1' + rnd() % 9);
    d[nd] = '\0';
    const char *sign = rnd() % 2 ? "-" : "";
    switch (rnd() % 3) {
    case 0: sprintf(t, "%s%se%d", sign, d, e); break;
    case 1: sprintf(t, "%s%c.%sE%+d", sign, d[0], nd > 1 ? d + 1 : "0", e); break;
    default: { /* a point inside the digits when the exponent allows */
        int pt = (int)(rnd() % (unsigned)nd) + 1;
        sprintf(t, "%s%.*s.%s%se%d", sign, pt, d, pt < nd ? d + pt : "0", "", e - (nd - pt));
    }
    }
}

static void test_read(void)
{
    char t[128];
    const long per = 400000 / SCALE;
    for (long i = 0; i < per; i++) { /* every double's texts */
        uint64_t b = rnd();
        if (((b >> 52) & 0x7FF) == 0x7FF) continue;
        const double x = of_bits(b);
        snprintf(t, sizeof t, "%.17g", x);
        check_read(t);
        snprintf(t, sizeof t, "%.16e", x);
        check_read(t);
        snprintf(t, sizeof t, "%.15g", x);
        check_read(t);
    }
    for (long i = 0; i < per; i++) { /* 1..19 digits, every exponent */
        random_decimal(t, 1 + (int)(rnd() % 19), (int)(rnd() % 681) - 350);
        check_read(t);
    }
    for (long i = 0; i < per / 4; i++) { /* more than 19 digits */
        int nd = 20 + (int)(rnd() % 20);
        random_decimal(t, nd, (int)(rnd() % 600) - 300);
        if (rnd() % 2) { /* trailing zeros only past the 19th */
            char *e = strpbrk(t, "eE"), *p = e;
            int zeros = nd - 19;
            while (zeros > 0 && p > t && p[-1] != '.' && p[-1] != '-') {
                *--p = '0';
                zeros--;
            }
        }
        check_read(t);
    }
    for (int e = -350; e <= 310; e++) { /* powers of ten */
        snprintf(t, sizeof t, "1e%d", e);
        check_read(t);
        snprintf(t, sizeof t, "-10000000000000000000e%d", e - 19);
        check_read(t);
    }
    /* exact ties between doubles, and one unit of the last digit around them */
    for (long i = 0; i < per / 4; i++) {
        const int e = (int)(rnd() % 60) - 20; /* the tie m 2^(e-1), m odd */
        const uint64_t m = ((UINT64_C(1) << 53) | (rnd() >> 11)) | 1; /* 54 bits, odd */
        /* m 2^(e-1) exactly, as a decimal: for e - 1 >= 0 an integer, else
         * m 5^(1-e) 10^(e-1), at most 54 + 47 bits: print in long double
         * only where exact, else skip */
        if (e - 1 >= 0 && e - 1 <= 10) {
            const unsigned long long v = (unsigned long long)m << (e - 1);
            if (v >> 63) continue;
            snprintf(t, sizeof t, "%llu", v);
            check_read(t);
            snprintf(t, sizeof t, "%llu", v + 1);
            check_read(t);
            snprintf(t, sizeof t, "%llu", v - 1);
            check_read(t);
        } else if (e - 1 < 0 && e - 1 >= -8) {
            /* m 2^(e-1) = m 5^k / 10^k, k = 1 - e: 5^k m < 2^64 for k <= 4 */
            const int k = 1 - e;
            unsigned long long p5 = 1;
            for (int j = 0; j < k; j++) p5 *= 5;
            const unsigned __int128 v = (unsigned __int128)m * p5;
            if (v >> 64) continue;
            const unsigned long long u = (unsigned long long)v;
            snprintf(t, sizeof t, "%llue-%d", u, k);
            check_read(t);
            snprintf(t, sizeof t, "%llue-%d", u + 1, k);
            check_read(t);
            snprintf(t, sizeof t, "%llue-%d", u - 1, k);
            check_read(t);
        }
    }
    check_read("9007199254740993"); /* 2^53 + 1: to even, 2^53 */
    check_read("9007199254740995"); /* to even, 2^53 + 4 */
    check_read("4.9406564584124654e-324");
    check_read("2.4703282292062327e-324"); /* half the smallest subnormal: 0 */
    check_read("2.4703282292062328e-324"); /* just above: the smallest */
    check_read("2.2250738585072011e-308");
    check_read("2.2250738585072014e-308");
    check_read("1.7976931348623157e308");
    check_read("1.7976931348623158e308");
    check_read("1.7976931348623159e308"); /* rounds to infinity: refused */
    check_read("1e309");
    check_read("-0");
    check_read("-0.0e-999");
    check_read("0.000000000000000000000000000000001");
    check_read("123456789012345678901234567890");
    printf("reader: %ld texts, %ld differ from strtod\n", n_read, n_read_bad);
    CHECK(n_read >= 1500000 / SCALE);
    CHECK_EQ_INT(n_read_bad, 0);
}

static long n_back, n_back_bad;

static void check_back(double x)
{
    char buf[API_REAL_FORMAT_SIZE], p17[40];
    const size_t n = api_real_format(x, buf);
    double v = 0.0;
    const char *end = api_json_number_scan(buf, buf + n, &v);
    snprintf(p17, sizeof p17, "%.17g", x);
    n_back++;
    const int ok = end == buf + n && memcmp(&v, &x, sizeof v) == 0 && n <= strlen(p17) + 2;
    if (!ok && n_back_bad++ < 10) fprintf(stderr, "back: %a -> \"%s\" -> %a\n", x, buf, v);
}

static void test_back(void)
{
    const long per = 300000 / SCALE;
    for (long i = 0; i < per; i++) {
        uint64_t b = rnd();
        if (((b >> 52) & 0x7FF) != 0x7FF) check_back(of_bits(b));
        check_back(of_bits(b & 0x800FFFFFFFFFFFFFULL)); /* subnormal (or zero) */
        check_back(of_bits((b & 0x8000000000000000ULL) | ((1 + rnd() % 2046) << 52))); /* 2^e */
    }
    check_back(DBL_TRUE_MIN);
    check_back(DBL_MAX);
    check_back(-DBL_MIN);
    printf("writer -> reader: %ld doubles, %ld do not come back\n", n_back, n_back_bad);
    CHECK_EQ_INT(n_back_bad, 0);
}

static void test_fast_share(void)
{
    long undecided = 0, n = 200000 / SCALE;
    for (long i = 0; i < n; i++) {
        uint64_t w = UINT64_C(10000000000000000) + rnd() % UINT64_C(90000000000000000);
        int q = (int)(rnd() % 600) - 300 - 16;
        double v;
        if (!api_real_from_decimal(w, q, 0, &v)) undecided++;
    }
    printf("Eisel-Lemire left %ld of %ld random 17-digit decimals (|x| 1e-300..1e300) to strtod\n",
           undecided, n);
    CHECK(undecided * 100 < n);
}

int main(void)
{
    test_read();
    test_back();
    test_fast_share();
    TEST_MAIN_END();
}
