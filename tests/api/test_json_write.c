/* test_json_write.c — the response writer (api/json/json_write.c) and its real
 * formatter (api/json/real_format.c: the shortest text that reads back as the
 * same double).
 *
 * (a) ~2.2 million doubles (random bit patterns over every exponent,
 *     "decimal-looking" k/10^n, integers up to 2^53, neighbours of every
 *     power of ten and two, subnormal and normal extremes, both signs):
 *     api_real_format's text is byte for byte the contract's text built here
 *     from snprintf and strtod alone (for P = 1..17 the two P-digit decimals
 *     around x; the first P where one reads back as x, the nearer one when
 *     both do, in the %.17g layout), and strtod reads it back as the same
 *     double;
 * (c) exact texts for hand-chosen values, the digits from CPython's repr
 *     (David Gay's shortest conversion, not glibc's nor ours);
 * (d) json_dumps byte identity for trees without reals (escapes, UTF-8,
 *     NUL, nesting, integer extremes, random trees, the fallbacks), and for
 *     trees with reals the same values read back and never more bytes than
 *     jansson's %.17g.
 * Counts scale down under sanitizers; a micro benchmark prints ns per real
 * (never asserted). */
#include <float.h>
#include <jansson.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "json/json_write.h"
#include "mech/base/budget.h"
#include "json/real_format.h"
#include "testlib.h"

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_UNDEFINED__)
#define SCALE 4 /* sanitizers: a quarter of the counts */
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(undefined_behavior_sanitizer)
#define SCALE 4
#endif
#endif
#ifndef SCALE
#define SCALE 1
#endif

#define DUMP_FLAGS (JSON_COMPACT | JSON_REAL_PRECISION(17))

/* ---- helpers -------------------------------------------------------------------- */

static uint64_t rng_state = 0x9E3779B97F4A7C15ULL;
static uint64_t rnd(void) /* splitmix64 */
{
    uint64_t z = (rng_state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

static uint64_t bits_of(double x)
{
    uint64_t b;
    memcpy(&b, &x, sizeof b);
    return b;
}

static double of_bits(uint64_t b)
{
    double x;
    memcpy(&x, &b, sizeof x);
    return x;
}

/* The contract's layout (api/json/real_format.h) of the significant digits d (n of
 * them, no trailing zero) with X the decimal exponent of the first, sign
 * first. */
static void layout(int negative, const char *d, int n, int X, char *out)
{
    char *p = out;
    if (negative) *p++ = '-';
    if (X < -4 || X >= 17) {
        *p++ = d[0];
        if (n > 1) {
            *p++ = '.';
            memcpy(p, d + 1, (size_t)(n - 1));
            p += n - 1;
        }
        p += sprintf(p, "e%d", X);
    } else if (X < 0) {
        p += sprintf(p, "0.");
        for (int i = 0; i < -X - 1; i++) *p++ = '0';
        memcpy(p, d, (size_t)n);
        p += n;
    } else {
        for (int i = 0; i <= X || i < n; i++) {
            if (i == X + 1) *p++ = '.';
            *p++ = i < n ? d[i] : '0';
        }
        if (n <= X + 1) p += sprintf(p, ".0");
    }
    *p = '\0';
}

/* Whether the P digits d at exponent X read back as x (> 0). */
static int reads_back(const char *d, int P, int X, double x)
{
    char t[64];
    snprintf(t, sizeof t, "%c.%.*se%d", d[0], P - 1, d + 1, X);
    return strtod(t, NULL) == x;
}

/* Whether some P-digit decimal reads back as a > 0: the nearest one
 * (%.{P-1}e, correctly rounded) when it does, else the P-digit decimal on
 * the other side of a; its digits in d (P of them) and the exponent of the
 * first in *X. */
static int candidate(double a, int P, char d[24], int *X)
{
    char t[64];
    snprintf(t, sizeof t, "%.*e", P - 1, a); /* the nearest P-digit decimal */
    int n = 0;
    const char *e = strchr(t, 'e');
    for (const char *q = t; q < e; q++)
        if (*q >= '0' && *q <= '9') d[n++] = *q;
    *X = atoi(e + 1);
    const double y = strtod(t, NULL);
    if (y == a) return 1;
    int i = P - 1; /* the P-digit decimal on the other side of a */
    if (y < a) {
        while (i >= 0 && d[i] == '9') d[i--] = '0';
        if (i < 0) { /* 99..9 + 1 = 10..0: one more digit, dropped */
            d[0] = '1';
            (*X)++;
        } else {
            d[i]++;
        }
    } else {
        while (i >= 0 && d[i] == '0') d[i--] = '9';
        d[i]--;
        if (d[0] == '0') { /* 10..0 - 1 = 99..9, a digit fewer */
            memmove(d, d + 1, (size_t)(P - 1));
            d[P - 1] = '9';
            (*X)--;
        }
    }
    return reads_back(d, P, *X, a);
}

/* The contract's text of finite x from snprintf and strtod alone: the
 * smallest P with a P-digit decimal that reads back (no shorter decimal
 * does: one with fewer digits is also a (P-1)-digit decimal with zeros
 * appended), that decimal, laid out. hint (the digit count of the text
 * under test) is tried first: P = hint when no (hint-1)-digit decimal reads
 * back and a hint-digit one does; otherwise every P from 1 is searched. */
static void reference_text(double x, int hint, char *out)
{
    if (x == 0) {
        strcpy(out, signbit(x) ? "-0.0" : "0.0");
        return;
    }
    const double a = fabs(x);
    char d[24];
    int X, P = 0;
    if (hint >= 1 && hint <= 17 && (hint == 1 || !candidate(a, hint - 1, d, &X)) &&
        candidate(a, hint, d, &X))
        P = hint;
    for (int k = 1; !P && k <= 17; k++)
        if (candidate(a, k, d, &X)) P = k;
    if (!P) {
        strcpy(out, "(no text)");
        return;
    }
    while (P > 1 && d[P - 1] == '0') P--;
    layout(x < 0, d, P, X, out);
}

/* Significant digits of a number text (leading and trailing zeros not
 * counted). */
static int significant_digits(const char *t)
{
    char d[40];
    int n = 0;
    for (const char *q = t; *q && *q != 'e' && n < 39; q++)
        if (*q >= '0' && *q <= '9' && (n || *q != '0')) d[n++] = *q;
    while (n > 0 && d[n - 1] == '0') n--;
    return n;
}

static long n_roundtrip, n_bad_roundtrip, n_notation_bad;

static void check_one(double x)
{
    char buf[API_REAL_FORMAT_SIZE + 8], jt[64];
    memset(buf, 'x', sizeof buf);
    size_t len = api_real_format(x, buf);
    n_roundtrip++;
    int ok = len == strlen(buf) && len < API_REAL_FORMAT_SIZE;
    char *end;
    double y = strtod(buf, &end);
    ok = ok && *end == '\0' && bits_of(y) == bits_of(x);
    if (!ok && n_bad_roundtrip++ < 10)
        fprintf(stderr, "round trip: %a (%.17g) -> \"%s\" -> %a\n", x, x, buf, y);
    reference_text(x, significant_digits(buf), jt);
    if (strcmp(buf, jt) && n_notation_bad++ < 10)
        fprintf(stderr, "text: %a -> \"%s\", reference \"%s\"\n", x, buf, jt);
}

static void check_pm(double x)
{
    check_one(x);
    check_one(-x);
}

/* x and its 8 neighbours on each side, both signs. */
static void check_neighbours(double x)
{
    double lo = x, hi = x;
    check_pm(x);
    for (int k = 0; k < 8; k++) {
        lo = nextafter(lo, 0.0);
        hi = nextafter(hi, INFINITY);
        check_pm(lo);
        if (isfinite(hi)) check_pm(hi);
    }
}

/* ---- (a) round trip ---------------------------------------------------------- */

static void test_round_trip(void)
{
    const long per = 560000 / SCALE;
    /* random bit patterns, every exponent */
    for (long i = 0; i < per; i++) {
        uint64_t b = rnd();
        if (((b >> 52) & 0x7FF) == 0x7FF) continue;
        check_one(of_bits(b));
    }
    /* every biased exponent (0 = subnormal) with a few random significands */
    for (uint64_t be = 0; be < 0x7FF; be++)
        for (int k = 0; k < 40 / (SCALE > 1 ? 4 : 1); k++) {
            uint64_t frac = k == 0 ? 0 : k == 1 ? 1 : k == 2 ? (1ULL << 52) - 1 : rnd() >> 12;
            if (be == 0 && frac == 0) continue;
            check_pm(of_bits(be << 52 | frac));
        }
    /* decimal-looking: k / 10^n with k of 1..17 digits */
    static const double p10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                 1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
    for (long i = 0; i < per; i++) {
        int nd = 1 + (int)(rnd() % 17), n = (int)(rnd() % 23);
        uint64_t k = rnd() % (uint64_t)p10[nd];
        double x = (double)k / p10[n];
        if (rnd() & 1) x = (double)k * p10[n % 16];
        check_one(rnd() & 1 ? -x : x);
    }
    /* integers up to 2^53 */
    for (long i = 0; i < per / 2; i++) {
        uint64_t k = rnd() >> (11 + rnd() % 53);
        check_one((double)k);
    }
    /* short decimal texts at every decade (the nearest double) */
    for (long i = 0; i < per / 2; i++) {
        char t[48];
        snprintf(t, sizeof t, "%llue%d", (unsigned long long)(rnd() % 100000000ULL),
                 (int)(rnd() % 640) - 330);
        double x = strtod(t, NULL);
        if (isfinite(x)) check_one(x);
    }
    /* neighbours of every power of ten (as strtod reads "1eN") and of two */
    for (int e = -330; e <= 310; e++) {
        char t[16];
        snprintf(t, sizeof t, "1e%d", e);
        double x = strtod(t, NULL);
        if (!isfinite(x)) continue;
        check_neighbours(x);
    }
    for (int e = -1074; e <= 1023; e++)
        check_neighbours(ldexp(1.0, e));
    /* extremes: the smallest and largest subnormals, around DBL_MIN, DBL_MAX */
    for (uint64_t f = 1; f <= 20000 / SCALE; f++) {
        check_pm(of_bits(f));
        check_pm(of_bits((1ULL << 52) - f));
        check_pm(of_bits((1ULL << 52) + f - 1));
        check_pm(of_bits(0x7FEFFFFFFFFFFFFFULL - f + 1));
    }
    check_pm(DBL_MIN);
    check_pm(DBL_MAX);
    check_pm(DBL_TRUE_MIN);
    check_pm(DBL_EPSILON);
    printf("%ld values: %ld do not read back, %ld differ from the reference text\n", n_roundtrip,
           n_bad_roundtrip, n_notation_bad);
    CHECK(n_roundtrip >= 2000000 / SCALE);
    CHECK(n_bad_roundtrip == 0);
    CHECK(n_notation_bad == 0);
}

/* ---- value generators ------------------------------------------------------ */

static double gen_bits(void)
{
    for (;;) {
        uint64_t b = rnd();
        if (((b >> 52) & 0x7FF) != 0x7FF) return of_bits(b);
    }
}

static double gen_decimal(void) /* a 1..12-digit decimal at any decade, finite */
{
    for (;;) {
        char t[48];
        snprintf(t, sizeof t, "%llue%d", (unsigned long long)(rnd() % 1000000000000ULL),
                 (int)(rnd() % 600) - 300);
        double x = strtod(t, NULL);
        if (isfinite(x)) return x;
    }
}

static double gen_physics(void) /* what responses hold: sums and products of short inputs */
{
    double a = (double)(rnd() % 1000) / 10.0, b = (double)(rnd() % 1000 + 1) / 100.0;
    switch (rnd() % 4) {
    case 0:
        return a + b;
    case 1:
        return a * b;
    case 2:
        return a / b;
    default:
        return sqrt(a * a + b * b);
    }
}

/* ---- (c) exact texts ------------------------------------------------------------- */

static void check_text(double x, const char *want)
{
    char buf[API_REAL_FORMAT_SIZE];
    size_t n = api_real_format(x, buf);
    int ok = !strcmp(buf, want) && n == strlen(want);
    CHECK(ok);
    if (!ok) fprintf(stderr, "  %.17g: got \"%s\", want \"%s\"\n", x, buf, want);
}

static void test_texts(void)
{
    /* Digits: CPython's repr(x); layout: api/json/real_format.h's (%.17g's switch to
     * scientific at X < -4 or X >= 17, ".0" on integral texts, exponent
     * without '+' and leading zeros). */
    check_text(0.6, "0.6");
    check_text(0.1 + 0.2, "0.30000000000000004");
    check_text(0.1, "0.1");
    check_text(0.3, "0.3");
    check_text(123.456, "123.456");
    check_text(1.0, "1.0");
    check_text(-0.0, "-0.0");
    check_text(0.0, "0.0");
    check_text(100.0, "100.0");
    check_text(-2.5, "-2.5");
    check_text(1e21, "1e21");
    check_text(1e22, "1e22");
    check_text(1e17, "1e17");
    check_text(1e16, "10000000000000000.0"); /* X = 16 < 17: fixed */
    check_text(12345678901234567.0, "12345678901234568.0");
    check_text(123456789012345680.0, "1.2345678901234568e17");
    check_text(0x1p60, "1.152921504606847e18"); /* a power of two: the closer lower gap */
    check_text(5e-324, "5e-324");
    check_text(-5e-324, "-5e-324");
    check_text(DBL_TRUE_MIN * 3, "1.5e-323");
    check_text(5e-310, "5e-310");
    check_text(DBL_MIN, "2.2250738585072014e-308");
    check_text(DBL_MAX, "1.7976931348623157e308");
    check_text(-DBL_MAX, "-1.7976931348623157e308");
    check_text(of_bits(0x000FFFFFFFFFFFFFULL), "2.225073858507201e-308"); /* largest subnormal */
    check_text(0.0001, "0.0001");                                        /* X = -4: fixed */
    check_text(0.00012, "0.00012");
    check_text(0.00001, "1e-5"); /* X = -5: scientific */
    check_text(0x1p-20, "9.5367431640625e-7");
    check_text(1e-7, "1e-7");
    check_text(2.5e-300, "2.5e-300");
    check_text(1e30, "1e30");
    check_text(1e23, "1e23");
    check_text(9007199254740992.0, "9007199254740992.0");
    check_text(9007199254740993.0, "9007199254740992.0");
    check_text(299792458.0, "299792458.0");
    check_text(6.62607015e-34, "6.62607015e-34");
    check_text(1.0 / 3.0, "0.3333333333333333");
    check_text(2.0 / 3.0, "0.6666666666666666");
    check_text(0x1p-1052, "2.0722615e-317");
    check_text(INFINITY, "null");
    check_text(NAN, "null");
}

/* ---- (d) writer vs json_dumps ------------------------------------------------- */

/* The writer's text of j against json_dumps's (consumes j): byte for byte
 * when the tree has no reals; with reals, the same values read back (every
 * real exactly) and never more bytes than jansson's %.17g; both fail
 * together. */
static int compare_tree(json_t *j, int reals)
{
    size_t n = 0;
    char *mine = api_json_write_compact(j, NULL, &n);
    char *theirs = json_dumps(j, DUMP_FLAGS | JSON_ENCODE_ANY);
    int ok;
    if (!mine || !theirs) {
        ok = !mine && !theirs;
    } else if (!reals) {
        ok = n == strlen(mine) && !strcmp(mine, theirs);
    } else {
        json_t *back = json_loads(mine, JSON_DECODE_ANY | JSON_ALLOW_NUL, NULL);
        ok = n == strlen(mine) && strlen(mine) <= strlen(theirs) && back && json_equal(back, j);
        json_decref(back);
    }
    if (!ok) {
        size_t at = 0;
        while (mine && theirs && mine[at] && mine[at] == theirs[at])
            at++;
        fprintf(stderr, "tree: first difference at byte %zu: mine %.300s\n   jansson %.300s\n", at,
                mine ? mine + (at > 40 ? at - 40 : 0) : "(null)",
                theirs ? theirs + (at > 40 ? at - 40 : 0) : "(null)");
    }
    free(mine);
    free(theirs);
    json_decref(j);
    return ok;
}

static json_t *random_string(int nul)
{
    static const char *pieces[] = {"a",
                                   "Z",
                                   " ",
                                   "\"",
                                   "\\",
                                   "/",
                                   "\b",
                                   "\f",
                                   "\n",
                                   "\r",
                                   "\t",
                                   "\x01",
                                   "\x1f",
                                   "\x7f",
                                   "\xc3\xa9",
                                   "\xe2\x82\xac",
                                   "\xf0\x9f\x98\x80",
                                   "\xef\xbf\xbf",
                                   "\xc2\x80",
                                   "\xf4\x8f\xbf\xbf",
                                   "\xed\x9f\xbf",
                                   "\xee\x80\x80",
                                   "kg",
                                   "m/s"};
    char t[256];
    size_t n = 0, k = rnd() % 24;
    for (size_t i = 0; i < k; i++) {
        if (nul && rnd() % 8 == 0) { /* NUL inside (json_stringn) */
            t[n++] = '\0';
            continue;
        }
        const char *p = pieces[rnd() % (sizeof pieces / sizeof *pieces)];
        size_t m = strlen(p);
        memcpy(t + n, p, m);
        n += m;
    }
    return json_stringn(t, n);
}

static json_t *random_tree(int depth, int reals)
{
    unsigned kind = (unsigned)(rnd() % (depth > 4 ? 6 : 8));
    switch (kind) {
    case 0:
        return json_null();
    case 1:
        return rnd() & 1 ? json_true() : json_false();
    case 2: {
        json_int_t v = (json_int_t)(rnd() >> (rnd() % 64));
        return json_integer(rnd() & 1 ? v : -v);
    }
    case 3:
        return random_string(1);
    case 4:
        if (reals) return json_real(rnd() & 1 ? gen_physics() : gen_bits());
        return json_integer((json_int_t)(rnd() % 1000));
    case 5:
        return json_integer(rnd() & 1 ? INT64_MAX : INT64_MIN);
    case 6: {
        json_t *a = json_array();
        for (int n = (int)(rnd() % 6); n > 0; n--)
            json_array_append_new(a, random_tree(depth + 1, reals));
        return a;
    }
    default: {
        json_t *o = json_object();
        for (int n = (int)(rnd() % 6); n > 0; n--) {
            /* json_loads refuses NUL in keys: none where texts are parsed back */
            json_t *key = random_string(!reals);
            json_object_setn_new(o, json_string_value(key), json_string_length(key),
                                 random_tree(depth + 1, reals));
            json_decref(key);
        }
        return o;
    }
    }
}

static void test_writer(void)
{
    /* hand-made trees */
    CHECK(compare_tree(json_object(), 0));
    CHECK(compare_tree(json_array(), 0));
    CHECK(compare_tree(json_pack("{s:{},s:[],s:[{}],s:[[[]]]}", "a", "b", "c", "d"), 0));
    CHECK(compare_tree(json_pack("{s:s,s:i,s:I,s:I,s:b,s:b,s:n}", "name", "mechd", "n", -42, "max",
                                 (json_int_t)INT64_MAX, "min", (json_int_t)INT64_MIN, "t", 1, "f",
                                 0, "z"), 0));
    CHECK(compare_tree(json_pack("[s,s,s,s]", "quote \" back \\ slash / tab \t nl \n cr \r",
                                 "\b\f\x01\x02\x1f\x7f",
                                 "caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x98\x80", ""), 0));
    CHECK(compare_tree(json_pack("{s:s%}", "nul", "a\0b\0", (size_t)4), 0));
    {
        json_t *o = json_object();
        json_object_setn_new(o, "k\0\"\n\xc3\xa9", 6, json_integer(1));
        json_object_set_new(o, "second", json_string("x"));
        json_object_set_new(o, "first", json_string("y")); /* insertion order, not sorted */
        CHECK(compare_tree(o, 0));
    }
    /* scalars at the top (JSON_ENCODE_ANY) */
    CHECK(compare_tree(json_integer(0), 0));
    CHECK(compare_tree(json_string("s"), 0));
    CHECK(compare_tree(json_null(), 0));
    /* invalid UTF-8 (json_stringn_nocheck): json_dumps fails, and so do we */
    CHECK(compare_tree(json_pack("[o]", json_stringn_nocheck("\xff\xfe", 2)), 0));
    CHECK(compare_tree(json_pack("[o]", json_stringn_nocheck("\xed\xa0\x80", 3)), 0));
    CHECK(compare_tree(json_pack("[o]", json_stringn_nocheck("\xe0\x80\x80", 3)), 0));
    CHECK(compare_tree(json_pack("[o]", json_stringn_nocheck("\xc3", 1)), 0));
    /* deeper than the bound: json_dumps's text, with reals through it */
    {
        json_t *root = json_array(), *cur = root;
        for (int i = 0; i < API_JSON_WRITE_MAX_DEPTH + 20; i++) {
            json_t *next = json_array();
            json_array_append_new(cur, json_integer(i));
            json_array_append_new(cur, json_real(0.1 * i));
            json_array_append_new(cur, next);
            cur = next;
        }
        /* its reals in the same shortest text as everywhere else */
        char *t = api_json_write_compact(root, NULL, NULL);
        CHECK(t && strstr(t, "[145,14.5,[146,14.600000000000001,[147,14.700000000000001,[]]]]"));
        free(t);
        CHECK(compare_tree(root, 1));
    }
    /* suffix and length */
    {
        json_t *o = json_pack("{s:f,s:[f,f]}", "beta", 0.6, "v", 0.1, 1e-7);
        size_t n = 0;
        char *s = api_json_write_compact(o, "\n", &n);
        CHECK(s && !strcmp(s, "{\"beta\":0.6,\"v\":[0.1,1e-7]}\n") && n == strlen(s));
        free(s);
        s = api_json_write_compact(o, NULL, NULL);
        CHECK(s && !strcmp(s, "{\"beta\":0.6,\"v\":[0.1,1e-7]}"));
        free(s);
        json_decref(o);
        CHECK(api_json_write_compact(NULL, "\n", &n) == NULL);
    }
    /* a large array (buffer growth): 100,000 vectors */
    {
        json_t *a = json_array();
        for (int i = 0; i < 100000 / SCALE; i++)
            json_array_append_new(
                a, json_pack("[f,f,f,f]", gen_bits(), gen_physics(), gen_decimal(), (double)i));
        CHECK(compare_tree(a, 1));
    }
    /* random trees */
    long same = 0, n_trees = 20000 / SCALE;
    for (long i = 0; i < n_trees; i++)
        same += compare_tree(random_tree(0, 0), 0);
    CHECK_EQ_INT(same, n_trees);
    same = 0;
    for (long i = 0; i < n_trees; i++)
        same += compare_tree(random_tree(0, 1), 1);
    CHECK_EQ_INT(same, n_trees);
}

/* ---- micro benchmark (printed, never asserted) --------------------------------- */

static void bench(void)
{
    enum { N = 4096 };
    static double xs[N];
    for (int i = 0; i < N; i++)
        xs[i] = i & 1 ? gen_bits() : gen_physics();
    const int rounds = 100 / SCALE;
    size_t sink = 0;
    char buf[64];
    double t0 = mech_clock_seconds();
    for (int r = 0; r < rounds; r++)
        for (int i = 0; i < N; i++)
            sink += api_real_format(xs[i], buf);
    double t1 = mech_clock_seconds();
    for (int r = 0; r < rounds; r++)
        for (int i = 0; i < N; i++)
            sink += (size_t)snprintf(buf, sizeof buf, "%.17g", xs[i]);
    double t2 = mech_clock_seconds();
    double per = (double)rounds * N;
    printf("micro: api_real_format %.1f ns per real, snprintf(\"%%.17g\") %.1f ns (ratio %.1f)%s "
           "[%zu]\n",
           (t1 - t0) / per * 1e9, (t2 - t1) / per * 1e9, (t2 - t1) / (t1 - t0),
           SCALE > 1 ? " (sanitizer build)" : "", sink % 10);
}

int main(void)
{
    test_texts();
    test_round_trip();
    test_writer();
    bench();
    TEST_MAIN_END();
}
