/* json_read.c — request-body parser (see api/json/json_read.h).
 *
 * One recursive-descent pass over the bytes that builds the jansson tree with
 * jansson's own constructors (json_object, json_object_setn_new_nocheck,
 * json_array, json_array_append_new, json_real, json_stringn_nocheck,
 * json_true/false/null), so every allocation still goes through the allocator
 * api/json/api_alloc.c installs. It accepts only the plain case, which covers every request
 * our clients send:
 *   - a top-level object or array (jansson without JSON_DECODE_ANY);
 *   - whitespace ' ' \t \n \r (jansson 2.14 src/load.c, lex_scan);
 *   - strings and keys of bytes 0x20..0x7E without backslash escapes;
 *   - numbers in JSON's grammar -?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?
 *     (load.c, lex_scan_number), every one a real as with
 *     JSON_DECODE_INT_AS_REAL, valued as strtod() on the token (src/strconv.c,
 *     jsonp_strtod): an exact short cut where it provably gives the same bits
 *     (see jr_number), strtod() otherwise; overflow (ERANGE with ±HUGE_VAL)
 *     handed to jansson, underflow accepted as jansson accepts it;
 *   - true, false, null; nesting up to API_JSON_READ_MAX_DEPTH.
 * Anything else — a syntax error, a duplicate key, an escape, a byte outside
 * 0x20..0x7E in a string, a NUL, trailing bytes, a deeper document, a number
 * token longer than API_JSON_READ_MAX_NUMBER, a locale whose strtod() does
 * not take the token whole (decimal point not '.': jansson would rewrite the
 * '.' first) — frees what was built and calls json_loadb(), so trees, error
 * texts, positions and limits are jansson's by construction.
 *
 * Memory running out in the fast path is reported, not handed to jansson
 * (which in 2.14 corrupts its lexer when an allocation fails; see
 * tests/api/test_alloc_failure.c, JANSSON_LEXER_BUG). */
#include "json/json_read.h"
#include "json/real_parse.h"

#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define JSON_READ_FLAGS (JSON_DECODE_INT_AS_REAL | JSON_REJECT_DUPLICATES)

enum jr_status { JR_OK, JR_NOMEM, JR_FALLBACK };

struct jr {
    const unsigned char *p, *end;
    int depth;
};

static inline void jr_skip_space(struct jr *r)
{
    while (r->p < r->end && (*r->p == ' ' || *r->p == '\n' || *r->p == '\t' || *r->p == '\r'))
        r->p++;
}

static inline int jr_is_digit(unsigned char c)
{
    return c >= '0' && c <= '9';
}

/* A string's bytes after its opening quote: *s and *n the content, r->p past
 * the closing quote. JR_FALLBACK for an escape, a byte outside 0x20..0x7E or
 * a missing closing quote. */
static enum jr_status jr_string(struct jr *r, const char **s, size_t *n)
{
    const unsigned char *start = r->p, *p = r->p, *end = r->end;
    while (p < end && *p != '"') {
        if (*p < 0x20 || *p > 0x7E || *p == '\\') return JR_FALLBACK;
        p++;
    }
    if (p == end) return JR_FALLBACK;
    *s = (const char *)start;
    *n = (size_t)(p - start);
    r->p = p + 1;
    return JR_OK;
}

/* Exact powers of ten: 10^k is a double exactly for k <= 22 (5^22 < 2^53). */
static const double jr_pow10[23] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                    1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                    1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

#define JR_MANTISSA_MAX ((uint64_t)1 << 53)
/* Significant digits kept exactly in 64 bits (10^19 < 2^64). */
#define JR_DIGITS_MAX 19

/* api_json_number_scan (api/json/json_read.h): a number token's value.
 *
 * The value is strtod()'s (jsonp_strtod, strconv.c). Where the token's
 * digits, read as an integer M with the decimal exponent e, have M <= 2^53 and
 * |e| <= 22, M and 10^|e| are doubles exactly and one IEEE multiplication or
 * division rounds the exact quotient/product correctly, which is what
 * glibc's correctly rounded strtod() returns (Clinger 1990, "How to read
 * floating point numbers accurately", the fast path; needs FLT_EVAL_METHOD
 * 0, so no extended-precision intermediates). M = 0 is ±0 for any exponent.
 * Otherwise, with at most 19 significant digits (every nonzero digit kept in
 * M), api_real_from_decimal (api/json/real_parse.c, Eisel-Lemire) assembles the same
 * correctly rounded double from integer products or says it cannot decide;
 * what is left goes through strtod() on a NUL-terminated copy. */
const char *api_json_number_scan(const char *text, const char *limit, double *value)
{
    const unsigned char *s = (const unsigned char *)text, *p = s, *end = (const unsigned char *)limit;
    int negative = 0, nd = 0, dropped = 0; /* significant digits kept in m; a nonzero one left out */
    uint64_t m = 0;
    long e10 = 0;
    if (p < end && *p == '-') {
        negative = 1;
        p++;
    }
    if (p < end && *p == '0') {
        p++;
    } else if (p < end && jr_is_digit(*p)) {
        while (p < end && jr_is_digit(*p)) {
            if (nd < JR_DIGITS_MAX) {
                m = m * 10 + (uint64_t)(*p - '0');
                nd++;
            } else {
                e10++;
                dropped |= *p != '0';
            }
            p++;
        }
    } else {
        return NULL;
    }
    if (p < end && *p == '.') {
        p++;
        if (p == end || !jr_is_digit(*p)) return NULL;
        while (p < end && jr_is_digit(*p)) {
            if (nd < JR_DIGITS_MAX) {
                m = m * 10 + (uint64_t)(*p - '0');
                nd += m != 0; /* leading zeros of a fraction are not significant */
                e10--;
            } else {
                dropped |= *p != '0';
            }
            p++;
        }
    }
    if (p < end && (*p == 'e' || *p == 'E')) {
        int eneg = 0;
        long ex = 0;
        p++;
        if (p < end && (*p == '+' || *p == '-')) eneg = *p++ == '-';
        if (p == end || !jr_is_digit(*p)) return NULL;
        while (p < end && jr_is_digit(*p)) {
            if (ex < 100000) ex = ex * 10 + (*p - '0');
            p++;
        }
        e10 += eneg ? -ex : ex;
    }
    size_t n = (size_t)(p - s);
    if (n > API_JSON_READ_MAX_NUMBER) return NULL;
    double v;
#if defined(FLT_EVAL_METHOD) && FLT_EVAL_METHOD == 0
    const int exact = !dropped && (m == 0 || (m <= JR_MANTISSA_MAX && e10 >= -22 && e10 <= 22));
#else
    const int exact = !dropped && m == 0;
#endif
    if (exact) {
        double x = (double)m;
        if (m != 0) x = e10 >= 0 ? x * jr_pow10[e10] : x / jr_pow10[-e10];
        v = negative ? -x : x;
    } else if (!dropped && e10 >= -400 && e10 <= 400 &&
               api_real_from_decimal(m, (int)e10, negative, &v)) {
        /* Eisel-Lemire (api/json/real_parse.c): strtod's value without strtod */
    } else {
        char buf[API_JSON_READ_MAX_NUMBER + 1];
        memcpy(buf, s, n);
        buf[n] = '\0';
        /* jsonp_strtod (strconv.c): errno = 0; strtod; ERANGE with ±HUGE_VAL
         * is "real number overflow" — jansson's to report. A locale whose
         * decimal point is not '.' stops strtod at the '.': jansson's too. */
        int saved_errno = errno;
        errno = 0;
        char *stop;
        v = strtod(buf, &stop);
        int overflow = (v == HUGE_VAL || v == -HUGE_VAL) && errno == ERANGE;
        errno = saved_errno;
        if (stop != buf + n || overflow) return NULL;
    }
    *value = v;
    return (const char *)p;
}

/* A number token at r->p (first byte '-' or a digit), as a real. */
static enum jr_status jr_number(struct jr *r, json_t **out)
{
    double v;
    const char *next =
        api_json_number_scan((const char *)r->p, (const char *)r->end, &v);
    if (!next) return JR_FALLBACK;
    *out = json_real(v);
    if (!*out) return JR_NOMEM; /* v is finite: only memory can fail */
    r->p = (const unsigned char *)next;
    return JR_OK;
}

static enum jr_status jr_value(struct jr *r, json_t **out);

/* After a member or element: 1 at the closing byte `close` (consumed), 0
 * after a ',' (consumed, and the space after it), -1 on anything else. */
static int jr_after_item(struct jr *r, unsigned char close)
{
    jr_skip_space(r);
    if (r->p == r->end) return -1;
    if (*r->p == close) {
        r->p++;
        return 1;
    }
    if (*r->p != ',') return -1;
    r->p++;
    jr_skip_space(r);
    return 0;
}

/* An object; r->p just past its '{'. */
static enum jr_status jr_object(struct jr *r, json_t **out)
{
    json_t *obj = json_object();
    if (!obj) return JR_NOMEM;
    enum jr_status st = JR_FALLBACK;
    jr_skip_space(r);
    if (r->p < r->end && *r->p == '}') {
        r->p++;
        *out = obj;
        return JR_OK;
    }
    for (;;) {
        if (r->p == r->end || *r->p != '"') goto fail;
        r->p++;
        const char *key;
        size_t klen;
        if ((st = jr_string(r, &key, &klen)) != JR_OK) goto fail;
        st = JR_FALLBACK;
        if (json_object_getn(obj, key, klen)) goto fail; /* duplicate key */
        jr_skip_space(r);
        if (r->p == r->end || *r->p != ':') goto fail;
        r->p++;
        jr_skip_space(r);
        json_t *v = NULL;
        if ((st = jr_value(r, &v)) != JR_OK) goto fail;
        if (json_object_setn_new_nocheck(obj, key, klen, v)) { /* steals v */
            st = JR_NOMEM;
            goto fail;
        }
        st = JR_FALLBACK;
        int next = jr_after_item(r, '}');
        if (next < 0) goto fail;
        if (next) break;
    }
    *out = obj;
    return JR_OK;
fail:
    json_decref(obj);
    return st;
}

/* An array; r->p just past its '['. */
static enum jr_status jr_array(struct jr *r, json_t **out)
{
    json_t *arr = json_array();
    if (!arr) return JR_NOMEM;
    enum jr_status st = JR_FALLBACK;
    jr_skip_space(r);
    if (r->p < r->end && *r->p == ']') {
        r->p++;
        *out = arr;
        return JR_OK;
    }
    for (;;) {
        json_t *v = NULL;
        if ((st = jr_value(r, &v)) != JR_OK) goto fail;
        if (json_array_append_new(arr, v)) { /* steals v */
            st = JR_NOMEM;
            goto fail;
        }
        st = JR_FALLBACK;
        int next = jr_after_item(r, ']');
        if (next < 0) goto fail;
        if (next) break;
    }
    *out = arr;
    return JR_OK;
fail:
    json_decref(arr);
    return st;
}

/* The literal word w (length n) at r->p; the byte after it is checked by the
 * caller (whatever follows a value must be whitespace , ] } or the end). */
static enum jr_status jr_literal(struct jr *r, const char *w, size_t n, json_t *v, json_t **out)
{
    if ((size_t)(r->end - r->p) < n || memcmp(r->p, w, n)) return JR_FALLBACK;
    r->p += n;
    *out = v;
    return JR_OK;
}

/* A value at r->p (leading whitespace skipped). */
static enum jr_status jr_value(struct jr *r, json_t **out)
{
    if (r->p == r->end) return JR_FALLBACK;
    unsigned char c = *r->p;
    switch (c) {
    case '{':
    case '[': {
        if (r->depth >= API_JSON_READ_MAX_DEPTH) return JR_FALLBACK;
        r->depth++;
        r->p++;
        enum jr_status st = c == '{' ? jr_object(r, out) : jr_array(r, out);
        r->depth--;
        return st;
    }
    case '"': {
        const char *s;
        size_t n;
        r->p++;
        enum jr_status st = jr_string(r, &s, &n);
        if (st != JR_OK) return st;
        *out = json_stringn_nocheck(s, n);
        return *out ? JR_OK : JR_NOMEM;
    }
    case 't':
        return jr_literal(r, "true", 4, json_true(), out);
    case 'f':
        return jr_literal(r, "false", 5, json_false(), out);
    case 'n':
        return jr_literal(r, "null", 4, json_null(), out);
    default:
        if (c == '-' || jr_is_digit(c)) return jr_number(r, out);
        return JR_FALLBACK;
    }
}

/* jsonp_error_init(err, "<buffer>") of jansson (src/error.c): the code byte
 * (text[JSON_ERROR_TEXT_LENGTH - 1]) is left as it was, as there. */
static void jr_error_init(json_error_t *err)
{
    err->text[0] = '\0';
    err->line = -1;
    err->column = -1;
    err->position = 0;
    memcpy(err->source, "<buffer>", sizeof "<buffer>");
}

int api_json_read_plain(const char *text, size_t len, json_t **out, json_error_t *err)
{
    *out = NULL;
    /* Fallback for NULL ("wrong arguments") and for sizes whose position
     * jansson stores through an int cast. */
    if (!text || len > (size_t)1 << 30) return 0;
    struct jr r = {(const unsigned char *)text, (const unsigned char *)text + len, 0};
    jr_skip_space(&r);
    if (r.p == r.end || (*r.p != '{' && *r.p != '[')) return 0;
    json_t *root = NULL;
    enum jr_status st = jr_value(&r, &root);
    if (st == JR_OK) {
        jr_skip_space(&r);
        if (r.p != r.end) {
            json_decref(root);
            return 0;
        }
        if (err) {
            jr_error_init(err);
            err->position = (int)len; /* len <= 2^30 */
        }
        *out = root;
        return 1;
    }
    if (st == JR_FALLBACK) return 0;
    if (err) {
        jr_error_init(err);
        err->position = (int)(r.p - (const unsigned char *)text);
        snprintf(err->text, sizeof err->text, "%s", "out of memory");
        err->text[JSON_ERROR_TEXT_LENGTH - 1] = (char)json_error_out_of_memory;
    }
    return -1;
}

json_t *api_json_read(const char *text, size_t len, json_error_t *err)
{
    json_t *j;
    if (api_json_read_plain(text, len, &j, err)) return j;
    return json_loadb(text, len, JSON_READ_FLAGS, err);
}
