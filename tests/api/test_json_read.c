/* test_json_read.c — api_json_read() (api/json/json_read.c) against jansson.
 *
 * For every input the answer must be json_loadb(text, len,
 * JSON_DECODE_INT_AS_REAL | JSON_REJECT_DUPLICATES)'s: both NULL with the same
 * err text, line, column, position, source and code, or two trees that are
 * json_equal AND have every real bit-identical AND the same key order (a
 * tree walker), with the same err fields after success too. Inputs:
 * hand-written corner cases (numbers of every form, nesting at and beyond the
 * depth bound, whitespace, duplicate keys, escapes, UTF-8, NUL, trailing
 * bytes), every prefix of several valid documents, random documents and
 * random mutations of them, every catalog example (which must also take the
 * fast path), the out-of-memory answer for every allocation position of a
 * parse, and a timing figure (printed, never asserted). */
#include <gsl/gsl_errno.h>
#include <jansson.h>
#include <locale.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "json/json_read.h"
#include "mech/base/budget.h"
#include "run/routes.h"
#include "testlib.h"

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_UNDEFINED__)
#define RANDOM_DOCS 20000L
#define TIMING_SECONDS 0.05
#else
#define RANDOM_DOCS 100000L
#define TIMING_SECONDS 0.25
#endif

#define FLAGS (JSON_DECODE_INT_AS_REAL | JSON_REJECT_DUPLICATES)

static uint64_t rng_state = 0x2545F4914F6CDD1DULL;
static uint64_t rnd(void) /* splitmix64 */
{
    uint64_t z = (rng_state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}
static unsigned rnd_below(unsigned n)
{
    return (unsigned)(rnd() % n);
}

/* ---- comparison ----------------------------------------------------------------- */

/* Same type, same values (reals bit for bit), same key order. */
static int same_tree(const json_t *a, const json_t *b)
{
    if (json_typeof(a) != json_typeof(b)) return 0;
    switch (json_typeof(a)) {
    case JSON_OBJECT: {
        if (json_object_size(a) != json_object_size(b)) return 0;
        void *ia = json_object_iter((json_t *)a), *ib = json_object_iter((json_t *)b);
        while (ia && ib) {
            size_t la = json_object_iter_key_len(ia), lb = json_object_iter_key_len(ib);
            if (la != lb || memcmp(json_object_iter_key(ia), json_object_iter_key(ib), la))
                return 0;
            if (!same_tree(json_object_iter_value(ia), json_object_iter_value(ib))) return 0;
            ia = json_object_iter_next((json_t *)a, ia);
            ib = json_object_iter_next((json_t *)b, ib);
        }
        return !ia && !ib;
    }
    case JSON_ARRAY:
        if (json_array_size(a) != json_array_size(b)) return 0;
        for (size_t i = 0; i < json_array_size(a); i++)
            if (!same_tree(json_array_get(a, i), json_array_get(b, i))) return 0;
        return 1;
    case JSON_STRING:
        return json_string_length(a) == json_string_length(b) &&
               !memcmp(json_string_value(a), json_string_value(b), json_string_length(a));
    case JSON_REAL: {
        double x = json_real_value(a), y = json_real_value(b);
        return !memcmp(&x, &y, sizeof x);
    }
    case JSON_INTEGER:
        return json_integer_value(a) == json_integer_value(b);
    default:
        return 1;
    }
}

static long n_compared, n_fast, n_shown;

static void show(const char *what, const char *text, size_t len)
{
    if (n_shown++ >= 10) return;
    fprintf(stderr, "mismatch (%s) for %zu bytes: '", what, len);
    for (size_t i = 0; i < len && i < 300; i++) {
        unsigned char c = (unsigned char)text[i];
        if (c >= 0x20 && c < 0x7F) fputc(c, stderr);
        else fprintf(stderr, "\\x%02x", c);
    }
    fprintf(stderr, "'\n");
}

/* api_json_read vs json_loadb on len bytes at text; 1 when identical. */
static int same_as_jansson(const char *text, size_t len)
{
    json_error_t e1, e2;
    memset(&e1, 0x5A, sizeof e1);
    memset(&e2, 0x5A, sizeof e2);
    json_t *j1 = api_json_read(text, len, &e1);
    json_t *j2 = json_loadb(text, len, FLAGS, &e2);
    n_compared++;
    int ok = 1;
    if (!j1 != !j2) {
        show(j1 ? "we parsed, jansson did not" : "jansson parsed, we did not", text, len);
        ok = 0;
    } else if (j1 && !(json_equal(j1, j2) && same_tree(j1, j2))) {
        show("trees differ", text, len);
        ok = 0;
    } else if (strcmp(e1.text, e2.text) || e1.line != e2.line || e1.column != e2.column ||
               e1.position != e2.position || strcmp(e1.source, e2.source) ||
               (!j1 && json_error_code(&e1) != json_error_code(&e2))) {
        show("errors differ", text, len);
        if (n_shown <= 10)
            fprintf(stderr, "  ours: %d:%d@%d %s '%s'; jansson: %d:%d@%d %s '%s'\n", e1.line,
                    e1.column, e1.position, e1.source, e1.text, e2.line, e2.column, e2.position,
                    e2.source, e2.text);
        ok = 0;
    }
    json_t *fast = NULL;
    if (api_json_read_plain(text, len, &fast, NULL) == 1) n_fast++;
    json_decref(fast);
    json_decref(j1);
    json_decref(j2);
    return ok;
}

static int same_str(const char *s)
{
    return same_as_jansson(s, strlen(s));
}

/* ---- hand-written cases ---------------------------------------------------------- */

static const char *const corner[] = {
    /* numbers */
    "[0]", "[-0]", "[-0.0]", "[0.0]", "[1]", "[-1]", "[0.1]", "[1e308]", "[1.7976931348623157e308]",
    "[1.7976931348623159e308]", "[1e309]", "[-1e309]", "[1e-400]", "[-1e-400]", "[4.9e-324]",
    "[2.4703282292062327e-324]", "[2.4703282292062328e-324]", "[2.2250738585072011e-308]",
    "[9007199254740993]", "[18446744073709551616]", "[123456789012345678901234567890]",
    "[0.1000000000000000055511151231257827021181583404541015625]",
    "[1.00000000000000011102230246251565404236316680908203125]",
    "[1E5]", "[1e+5]", "[1e-5]", "[1E-05]", "[1e0005]", "[0e0]", "[-0e-0]", "[1.5e3]",
    "[123.456e-7]", "[1e99999999999]", "[1e-99999999999]",
    /* bad numbers */
    "[01]", "[-01]", "[1.]", "[.5]", "[-]", "[+1]", "[1e]", "[1e+]", "[1.e5]", "[--1]", "[0x10]",
    "[1.5.3]", "[Infinity]", "[NaN]", "[-Infinity]", "[1 2]", "[1,]", "[,1]", "[1x]", "[1e5e5]",
    /* literals */
    "[true,false,null]", "[tru]", "[truex]", "[True]", "[nul]", "[nulll]", "[true1]", "[falsee]",
    /* objects and arrays */
    "{}", "[]", "{ }", "[ ]", " {} ", "\t\n\r [ \t\n\r 1 \t\n\r , \t\n\r 2 \t\n\r ] \t\n\r ",
    "{\"a\":1}", "{\"a\" : 1 , \"b\" : [ ] , \"c\" : { } }", "{\"a\":1,\"a\":2}",
    "{\"a\":{\"b\":1},\"a\":2}", "{\"a\":1,\"b\":2,\"a\":3}", "{\"\":1}", "{\"\":1,\"\":2}",
    "{\"a\":1,}", "{,}", "{\"a\"}", "{\"a\":}", "{\"a\" 1}", "{1:2}", "{\"a\":1 \"b\":2}", "[[[]]]",
    "[{},[],{\"x\":[{}]}]", "{\"z\":1,\"y\":2,\"x\":3,\"w\":4}", "[1]]", "[1]}", "{}{}", "{} x",
    "[] \x00", "[\"a\"]", "[\"\"]", "[\" ~!#$%&'()*+,-./:;<=>?@[]^_`{|}\"]",
    /* not plain: escapes, controls, UTF-8, NUL */
    "[\"a\\\"b\"]", "[\"a\\nb\"]", "[\"\\u0041\"]", "[\"\\u0000\"]", "{\"\\u0000\":1}",
    "[\"\\ud800\"]", "[\"\\ud83d\\ude00\"]", "[\"\\x\"]", "[\"tab\there\"]", "[\"nl\nhere\"]",
    "[\"\x7f\"]", "[\"caf\xc3\xa9\"]", "{\"caf\xc3\xa9\":1}", "[\"\xc3\"]", "[\"\xff\"]",
    "[\"\xed\xa0\x80\"]", "[\"\xf4\x90\x80\x80\"]", "\xef\xbb\xbf[]", "[\"unterminated]",
    "[\"a\"", "{\"a", "{\"a\":\"b", "'a'", "[\"a\" \"b\"]",
    /* top level */
    "", " ", "1", "\"a\"", "true", "null", "x", "]", "}", "[", "{", "\n\n  [1,\n  2,\n  x]",
    "{\n\"a\": 1,\n\"a\": 2\n}",
};

/* Embedded NULs need explicit lengths. */
static void check_nul_cases(void)
{
    static const struct {
        const char *s;
        size_t n;
    } c[] = {
        {"[1]\0", 4}, {"\0[1]", 4}, {"[\"a\0b\"]", 7}, {"{\"a\0\":1}", 9}, {"[1,\0 2]", 7},
        {"[1\0]", 4}, {"\0", 1}, {"{}\0\0", 4},
    };
    for (size_t i = 0; i < sizeof c / sizeof c[0]; i++) CHECK(same_as_jansson(c[i].s, c[i].n));
}

static void check_nesting(void)
{
    static const int depths[] = {1, 2, 63, 64, 65, 100, 2047, 2048, 2049, 3000};
    static char buf[6 * 3000 + 16];
    for (size_t k = 0; k < sizeof depths / sizeof depths[0]; k++) {
        int d = depths[k];
        size_t n = 0;
        for (int i = 0; i < d; i++) buf[n++] = '[';
        for (int i = 0; i < d; i++) buf[n++] = ']';
        CHECK(same_as_jansson(buf, n));
        /* objects: {"a":{"a":...0}} */
        n = 0;
        for (int i = 0; i < d; i++) {
            memcpy(buf + n, "{\"a\":", 5);
            n += 5;
        }
        buf[n++] = '0';
        for (int i = 0; i < d; i++) buf[n++] = '}';
        CHECK(same_as_jansson(buf, n));
    }
    /* the fast path takes exactly API_JSON_READ_MAX_DEPTH levels */
    size_t n = 0;
    for (int i = 0; i < API_JSON_READ_MAX_DEPTH; i++) buf[n++] = '[';
    for (int i = 0; i < API_JSON_READ_MAX_DEPTH; i++) buf[n++] = ']';
    json_t *j = NULL;
    CHECK(api_json_read_plain(buf, n, &j, NULL) == 1);
    json_decref(j);
    memmove(buf + 1, buf, n);
    buf[0] = '[';
    buf[n + 1] = ']';
    j = NULL;
    CHECK(api_json_read_plain(buf, n + 2, &j, NULL) == 0 && !j);
}

/* Valid documents whose every prefix is checked. */
static const char *const documents[] = {
    "{\"velocity\": {\"beta\": [0.6, 0, -0.25]}, \"event\": {\"t\": 1.5e-3, \"x\": [1, 2, 3]}}",
    "[1e308, -0, 4.9e-324, 0.1, 9007199254740993, true, false, null, \"s p a c e\", {}, []]",
    "{\"a\":{\"b\":{\"c\":[[[1.25E+2]]]}},\"d\":\"x\",\"e\":[{\"f\":null}]}",
    " \n{ \"k\" :\t[ 1 , 2.5 , -3e-2 ] ,\r\n \"m\" : { } } \n",
    "{\"caf\xc3\xa9\": \"na\\u00efve\", \"esc\": \"a\\\\b\"}",
};

static void check_prefixes(void)
{
    for (size_t i = 0; i < sizeof documents / sizeof documents[0]; i++) {
        size_t n = strlen(documents[i]);
        for (size_t k = 0; k <= n; k++) CHECK(same_as_jansson(documents[i], k));
    }
}

/* ---- random documents ------------------------------------------------------------ */

struct text {
    char buf[4096];
    size_t n;
};

static void put(struct text *t, const char *s, size_t n)
{
    if (t->n + n < sizeof t->buf) {
        memcpy(t->buf + t->n, s, n);
        t->n += n;
    }
}
static void putc_(struct text *t, char c)
{
    put(t, &c, 1);
}

static void gen_space(struct text *t)
{
    static const char ws[] = " \t\n\r";
    if (rnd_below(4)) return;
    unsigned k = 1 + rnd_below(3);
    for (unsigned i = 0; i < k; i++) putc_(t, ws[rnd_below(4)]);
}

static void gen_digits(struct text *t, unsigned n, int nonzero_first)
{
    for (unsigned i = 0; i < n; i++)
        putc_(t, (char)('0' + (i == 0 && nonzero_first ? 1 + rnd_below(9) : rnd_below(10))));
}

static void gen_number(struct text *t)
{
    if (rnd_below(2)) putc_(t, '-');
    if (rnd_below(4) == 0) putc_(t, '0');
    else gen_digits(t, 1 + rnd_below(rnd_below(3) ? 4 : 25), 1);
    if (rnd_below(2)) {
        putc_(t, '.');
        gen_digits(t, 1 + rnd_below(rnd_below(3) ? 6 : 40), 0);
    }
    if (rnd_below(3) == 0) {
        putc_(t, rnd_below(2) ? 'e' : 'E');
        unsigned s = rnd_below(3);
        if (s) putc_(t, s == 1 ? '+' : '-');
        gen_digits(t, 1 + rnd_below(3), 0);
    }
}

static void gen_string(struct text *t)
{
    static const char keys[][4] = {"a", "b", "c", "x", "t", ""};
    putc_(t, '"');
    unsigned kind = rnd_below(20);
    if (kind < 12) {
        const char *k = keys[rnd_below(6)];
        put(t, k, strlen(k));
    } else if (kind < 18) {
        unsigned n = rnd_below(12);
        for (unsigned i = 0; i < n; i++) {
            char c = (char)(0x20 + rnd_below(0x5F));
            if (c == '"' || c == '\\') c = '_';
            putc_(t, c);
        }
    } else if (kind == 18) {
        static const char *const esc[] = {"\\n", "\\\"", "\\u00e9", "\\u0000", "\\/", "\\ud83d\\ude00"};
        const char *e = esc[rnd_below(6)];
        put(t, e, strlen(e));
    } else {
        static const char *const utf[] = {"\xc3\xa9", "\xe2\x82\xac", "\xf0\x9f\x98\x80", "\xc3", "\x7f"};
        const char *u = utf[rnd_below(5)];
        put(t, u, strlen(u));
    }
    putc_(t, '"');
}

static void gen_value(struct text *t, int depth)
{
    unsigned k = rnd_below(depth > 4 ? 6 : 9);
    if (k == 0 || k == 1) {
        gen_number(t);
    } else if (k == 2) {
        gen_string(t);
    } else if (k == 3) {
        static const char *const lit[] = {"true", "false", "null"};
        const char *l = lit[rnd_below(3)];
        put(t, l, strlen(l));
    } else if (k == 4 || k == 5) {
        gen_number(t);
    } else if (k == 6 || k == 7) {
        putc_(t, '{');
        unsigned n = rnd_below(5);
        for (unsigned i = 0; i < n; i++) {
            if (i) putc_(t, ',');
            gen_space(t);
            gen_string(t);
            gen_space(t);
            putc_(t, ':');
            gen_space(t);
            gen_value(t, depth + 1);
            gen_space(t);
        }
        if (!n) gen_space(t);
        putc_(t, '}');
    } else {
        putc_(t, '[');
        unsigned n = rnd_below(5);
        for (unsigned i = 0; i < n; i++) {
            if (i) putc_(t, ',');
            gen_space(t);
            gen_value(t, depth + 1);
            gen_space(t);
        }
        if (!n) gen_space(t);
        putc_(t, ']');
    }
}

static void gen_document(struct text *t)
{
    t->n = 0;
    gen_space(t);
    if (rnd_below(2)) {
        putc_(t, '{');
        unsigned n = 1 + rnd_below(4);
        for (unsigned i = 0; i < n; i++) {
            if (i) putc_(t, ',');
            gen_string(t);
            putc_(t, ':');
            gen_value(t, 1);
        }
        putc_(t, '}');
    } else {
        putc_(t, '[');
        unsigned n = 1 + rnd_below(4);
        for (unsigned i = 0; i < n; i++) {
            if (i) putc_(t, ',');
            gen_value(t, 1);
        }
        putc_(t, ']');
    }
    gen_space(t);
}

static void mutate(struct text *t)
{
    static const char alphabet[] = "{}[]:,\"\\ \t\n\r0123456789-+.eEtrufalsn x/";
    unsigned m = 1 + rnd_below(3);
    for (unsigned i = 0; i < m && t->n > 0; i++) {
        size_t at = rnd_below((unsigned)t->n);
        char c = rnd_below(16) ? alphabet[rnd_below(sizeof alphabet - 1)]
                               : (char)rnd_below(256); /* NUL, controls, non-ASCII */
        switch (rnd_below(5)) {
        case 0: /* delete */
            memmove(t->buf + at, t->buf + at + 1, t->n - at - 1);
            t->n--;
            break;
        case 1: /* insert */
            if (t->n + 1 < sizeof t->buf) {
                memmove(t->buf + at + 1, t->buf + at, t->n - at);
                t->buf[at] = c;
                t->n++;
            }
            break;
        case 2: /* replace */
            t->buf[at] = c;
            break;
        case 3: /* truncate */
            t->n = at;
            break;
        default: /* duplicate a piece */ {
            size_t len = 1 + rnd_below(8);
            if (at + len <= t->n && t->n + len < sizeof t->buf) {
                memmove(t->buf + at + len, t->buf + at, t->n - at);
                t->n += len;
            }
        }
        }
    }
}

static void check_random(void)
{
    static struct text t;
    long bad = 0, fast_before = n_fast, cmp_before = n_compared;
    for (long i = 0; i < RANDOM_DOCS; i++) {
        gen_document(&t);
        if (!same_as_jansson(t.buf, t.n)) bad++;
        mutate(&t);
        if (!same_as_jansson(t.buf, t.n)) bad++;
    }
    CHECK_EQ_INT(bad, 0);
    printf("random: %ld documents compared (half of them mutated), %ld on the fast path\n",
           n_compared - cmp_before, n_fast - fast_before);
}

/* Numbers around the exact conversion's edges (M <= 2^53, |e| <= 22) and
 * random tokens of every shape, each compared alone in an array. */
static void check_numbers(void)
{
    static const char *const edge[] = {
        "9007199254740992", "9007199254740993", "9007199254740991", "9007199254740992e22",
        "9007199254740993e-22", "9007199254740992e-22", "9007199254740992e23", "1e22", "1e23",
        "1e-22", "1e-23", "-1e22", "-1e-23", "900719925474099.2", "900719925474099.3e-21",
        "0.000000000000000000000001", "0.0000000000000000000001", "10000000000000000000000",
        "100000000000000000000000", "1.7976931348623157e308", "2.2250738585072014e-308",
        "0e400", "-0e-400", "0.0e0", "00", "-", "1e400000000000000000000", "123e-0000000000000001",
    };
    char buf[128];
    long bad = 0, n = 0;
    for (size_t i = 0; i < sizeof edge / sizeof edge[0]; i++) {
        snprintf(buf, sizeof buf, "[%s]", edge[i]);
        bad += !same_str(buf);
        n++;
    }
    for (long i = 0; i < RANDOM_DOCS; i++) {
        size_t k = 0;
        buf[k++] = '[';
        if (rnd_below(2)) buf[k++] = '-';
        unsigned digits = 1 + rnd_below(rnd_below(2) ? 17 : 30);
        unsigned point = rnd_below(digits + 1); /* digits before the '.' (0: none) */
        for (unsigned d = 0; d < digits; d++) {
            if (point && d == point) buf[k++] = '.';
            buf[k++] = (char)('0' + (d == 0 && digits > 1 && point != 1 ? 1 + rnd_below(9)
                                                                          : rnd_below(10)));
        }
        if (rnd_below(2)) {
            buf[k++] = 'e';
            k += (size_t)snprintf(buf + k, sizeof buf - k, "%d", (int)rnd_below(61) - 30);
        }
        buf[k++] = ']';
        bad += !same_as_jansson(buf, k);
        n++;
    }
    CHECK_EQ_INT(bad, 0);
    printf("numbers: %ld tokens compared\n", n);
}

/* ---- catalog examples ------------------------------------------------------------ */

static void check_examples(void)
{
    long n = 0, fast = 0;
    for (size_t i = 0; i < api_route_count; i++) {
        const char *ex = api_routes[i]->example;
        if (!ex) continue;
        n++;
        CHECK(same_str(ex));
        json_t *j = NULL;
        if (api_json_read_plain(ex, strlen(ex), &j, NULL) == 1) fast++;
        else printf("example of %s takes jansson's path\n", api_routes[i]->path);
        json_decref(j);
    }
    printf("catalog examples: %ld compared, %ld on the fast path\n", n, fast);
    CHECK(n > 0);
}

/* ---- out of memory --------------------------------------------------------------- */

static long alloc_count, alloc_fail_at, alloc_live;

static void *counting_malloc(size_t n)
{
    if (++alloc_count == alloc_fail_at) return NULL;
    void *p = malloc(n);
    if (p) alloc_live++;
    return p;
}
static void counting_free(void *p)
{
    if (p) alloc_live--;
    free(p);
}

static void check_out_of_memory(void)
{
    json_malloc_t m0;
    json_free_t f0;
    json_get_alloc_funcs(&m0, &f0);
    json_set_alloc_funcs(counting_malloc, counting_free);
    const char *doc = documents[0];
    size_t len = strlen(doc);
    alloc_count = 0;
    alloc_fail_at = 0;
    json_t *j = api_json_read(doc, len, NULL);
    long total = alloc_count;
    CHECK(j != NULL && total > 0);
    json_decref(j);
    CHECK_EQ_INT(alloc_live, 0);
    long ok = 0;
    for (long k = 1; k <= total; k++) {
        json_error_t e;
        alloc_count = 0;
        alloc_fail_at = k;
        j = api_json_read(doc, len, &e);
        if (!j && !strcmp(e.text, "out of memory") &&
            json_error_code(&e) == json_error_out_of_memory && alloc_live == 0)
            ok++;
        json_decref(j);
    }
    CHECK_EQ_INT(ok, total);
    json_set_alloc_funcs(m0, f0);
    printf("out of memory: all %ld allocation positions of a parse answer \"out of memory\", "
           "nothing leaked\n", total);
}

/* ---- timing (printed, never asserted) -------------------------------------------- */

static void print_timing(void)
{
    const char *body = NULL;
    for (size_t i = 0; i < api_route_count; i++)
        if (!strcmp(api_routes[i]->path, "/v1/relativity/boost")) body = api_routes[i]->example;
    if (!body) return;
    size_t len = strlen(body);
    double t[2];
    for (int which = 0; which < 2; which++) {
        long n = 0;
        double t0 = mech_clock_seconds(), dt;
        do {
            for (int i = 0; i < 64; i++) {
                json_t *j = which ? json_loadb(body, len, FLAGS, NULL)
                                  : api_json_read(body, len, NULL);
                json_decref(j);
            }
            n += 64;
            dt = mech_clock_seconds() - t0;
        } while (dt < TIMING_SECONDS);
        t[which] = dt / (double)n * 1e9;
    }
    printf("timing: boost example (%zu bytes): api_json_read %.0f ns, json_loadb %.0f ns "
           "per parse (ratio %.2f)\n", len, t[0], t[1], t[0] / t[1]);
}

int main(void)
{
    gsl_set_error_handler_off();
    for (size_t i = 0; i < sizeof corner / sizeof corner[0]; i++) CHECK(same_str(corner[i]));
    check_nul_cases();
    check_nesting();
    check_prefixes();
    CHECK(same_as_jansson(NULL, 0));
    /* A locale whose decimal point is not '.': jansson's path decides. */
    const char *loc = setlocale(LC_NUMERIC, "de_DE.UTF-8");
    if (!loc) loc = setlocale(LC_NUMERIC, "fr_FR.UTF-8");
    if (loc) {
        for (size_t i = 0; i < sizeof corner / sizeof corner[0]; i++) CHECK(same_str(corner[i]));
        printf("locale %s: corner cases compared\n", loc);
        setlocale(LC_NUMERIC, "C");
    } else {
        printf("no locale with a ',' decimal point installed: that case not run\n");
    }
    check_numbers();
    check_examples();
    check_random();
    check_out_of_memory();
    printf("compared %ld inputs, %ld on the fast path\n", n_compared, n_fast);
    print_timing();
    TEST_MAIN_END();
}
