/* json_write.c — compact JSON writer for responses (see api/json/json_write.h).
 *
 * Mirrors jansson 2.14's src/dump.c (do_dump, dump_string) for JSON_COMPACT
 * without the flags that change strings, and replaces its %.17g for reals by
 * api_real_format() (the shortest text that reads back as the same double).
 * Differences in how, not what: one growing buffer instead of a callback per
 * token, no per-container hash table for cycle detection (a depth bound
 * instead: beyond it, and for strings jansson would refuse, json_dumps()
 * decides whether the tree can be written at all, so a failure is always
 * jansson's).
 *
 * Allocation: malloc/realloc/free of the C library, because the text becomes
 * api_response.body, which api_response_free() frees with free(); realloc
 * lets the buffer grow in place. The allocation-failure sweep
 * (tests/api/test_alloc_failure.c) wraps these calls in libmechapi, so a
 * failure here is exercised and must end as the fixed 500. */
#include "json/json_write.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "json/real_format.h"

#define JW_INITIAL 512

enum jw_status { JW_OK, JW_NOMEM, JW_FALLBACK };

struct jw {
    char *buf;
    size_t len, cap;
    int max_depth; /* deepest container written (API_JSON_WRITE_MAX_DEPTH, or more
                      once json_dumps() has shown the tree is acyclic) */
};

/* Make room for `need` more bytes (capacity doubles). */
static int jw_grow(struct jw *w, size_t need)
{
    size_t cap = w->cap ? w->cap : JW_INITIAL;
    if (need > SIZE_MAX / 2 - w->len) return JW_NOMEM;
    while (cap - w->len < need)
        cap *= 2;
    char *b = realloc(w->buf, cap);
    if (!b) return JW_NOMEM;
    w->buf = b;
    w->cap = cap;
    return JW_OK;
}

static inline int jw_reserve(struct jw *w, size_t need)
{
    return w->cap - w->len >= need ? JW_OK : jw_grow(w, need);
}

/* Append n bytes of s, growing the buffer as needed. */
static inline int jw_append(struct jw *w, const char *s, size_t n)
{
    int st = jw_reserve(w, n);
    if (st) return st;
    memcpy(w->buf + w->len, s, n);
    w->len += n;
    return JW_OK;
}

/* Length of the UTF-8 sequence at s (n bytes left, n >= 1, s[0] >= 0x80),
 * or 0 when jansson's utf8_iterate() would refuse it (src/utf.c: lead byte
 * C2..F4, continuation bytes 80..BF, no overlong form, no surrogate, at most
 * U+10FFFF). */
static size_t utf8_sequence(const unsigned char *s, size_t n)
{
    unsigned char u = s[0];
    size_t count;
    uint32_t v;
    if (u >= 0xC2 && u <= 0xDF) {
        count = 2;
        v = u & 0x1Fu;
    } else if (u >= 0xE0 && u <= 0xEF) {
        count = 3;
        v = u & 0x0Fu;
    } else if (u >= 0xF0 && u <= 0xF4) {
        count = 4;
        v = u & 0x07u;
    } else {
        return 0;
    }
    if (count > n) return 0;
    for (size_t i = 1; i < count; i++) {
        if (s[i] < 0x80 || s[i] > 0xBF) return 0;
        v = (v << 6) | (s[i] & 0x3Fu);
    }
    if (v > 0x10FFFF || (v >= 0xD800 && v <= 0xDFFF)) return 0;
    if ((count == 3 && v < 0x800) || (count == 4 && v < 0x10000)) return 0;
    return count; /* count == 2 cannot be overlong: lead byte >= C2 */
}

/* dump_string() of jansson 2.14 without JSON_ENSURE_ASCII/JSON_ESCAPE_SLASH. */
static int jw_string(struct jw *w, const char *str, size_t n)
{
    static const char hex[] = "0123456789ABCDEF";
    if (n > (SIZE_MAX - 2) / 6) return JW_NOMEM;
    int st = jw_reserve(w, 6 * n + 2); /* worst case: every byte a \u00XX */
    if (st) return st;
    const unsigned char *s = (const unsigned char *)str;
    char *out = w->buf + w->len;
    *out++ = '"';
    size_t i = 0;
    while (i < n) {
        /* a run of bytes printed as they are */
        size_t j = i;
        while (j < n && s[j] >= 0x20 && s[j] < 0x80 && s[j] != '"' && s[j] != '\\')
            j++;
        memcpy(out, s + i, j - i);
        out += j - i;
        i = j;
        if (i == n) break;
        unsigned char c = s[i];
        if (c >= 0x80) {
            size_t k = utf8_sequence(s + i, n - i);
            if (!k) return JW_FALLBACK; /* json_dumps fails on it: let it */
            memcpy(out, s + i, k);
            out += k;
            i += k;
            continue;
        }
        *out++ = '\\';
        switch (c) {
        case '"':
            *out++ = '"';
            break;
        case '\\':
            *out++ = '\\';
            break;
        case '\b':
            *out++ = 'b';
            break;
        case '\f':
            *out++ = 'f';
            break;
        case '\n':
            *out++ = 'n';
            break;
        case '\r':
            *out++ = 'r';
            break;
        case '\t':
            *out++ = 't';
            break;
        default: /* other control characters: \u00XX, upper-case hex */
            *out++ = 'u';
            *out++ = '0';
            *out++ = '0';
            *out++ = hex[c >> 4];
            *out++ = hex[c & 15];
            break;
        }
        i++;
    }
    *out++ = '"';
    w->len = (size_t)(out - w->buf);
    return JW_OK;
}

/* "%" JSON_INTEGER_FORMAT of jansson (json_int_t, decimal). */
static int jw_integer(struct jw *w, json_int_t v)
{
    char tmp[24];
    char *end = tmp + sizeof tmp, *p = end;
    /* magnitude in unsigned arithmetic: no overflow for the most negative */
    unsigned long long m = v < 0 ? 0ull - (unsigned long long)v : (unsigned long long)v;
    do {
        *--p = (char)('0' + m % 10);
        m /= 10;
    } while (m);
    if (v < 0) *--p = '-';
    return jw_append(w, p, (size_t)(end - p));
}

static int jw_value(struct jw *w, const json_t *j, int depth)
{
    int st;
    if (!j) return JW_FALLBACK; /* json_dumps fails on a NULL member */
    switch (json_typeof(j)) {
    case JSON_NULL:
        return jw_append(w, "null", 4);
    case JSON_TRUE:
        return jw_append(w, "true", 4);
    case JSON_FALSE:
        return jw_append(w, "false", 5);
    case JSON_INTEGER:
        return jw_integer(w, json_integer_value(j));
    case JSON_REAL:
        if ((st = jw_reserve(w, API_REAL_FORMAT_SIZE))) return st;
        w->len += api_real_format(json_real_value(j), w->buf + w->len);
        return JW_OK;
    case JSON_STRING:
        return jw_string(w, json_string_value(j), json_string_length(j));
    case JSON_ARRAY: {
        if (depth >= w->max_depth) return JW_FALLBACK;
        size_t n = json_array_size(j);
        if ((st = jw_append(w, "[", 1))) return st;
        for (size_t i = 0; i < n; i++) {
            if (i) {
                if ((st = jw_append(w, ",", 1))) return st;
            }
            if ((st = jw_value(w, json_array_get(j, i), depth + 1))) return st;
        }
        if ((st = jw_append(w, "]", 1))) return st;
        return JW_OK;
    }
    case JSON_OBJECT: {
        if (depth >= w->max_depth) return JW_FALLBACK;
        if ((st = jw_append(w, "{", 1))) return st;
        int first = 1;
        for (void *it = json_object_iter((json_t *)j); it;
             it = json_object_iter_next((json_t *)j, it)) {
            if (!first) {
                if ((st = jw_append(w, ",", 1))) return st;
            }
            first = 0;
            if ((st = jw_string(w, json_object_iter_key(it), json_object_iter_key_len(it))))
                return st;
            if ((st = jw_append(w, ":", 1))) return st;
            if ((st = jw_value(w, json_object_iter_value(it), depth + 1))) return st;
        }
        if ((st = jw_append(w, "}", 1))) return st;
        return JW_OK;
    }
    default:
        return JW_FALLBACK;
    }
}

/* Deepest tree written once json_dumps() has accepted it: jansson's parser
 * stops at 2048 levels, and answers built in C are a few levels deep. */
#define JW_DEEP_MAX_DEPTH 65536

static int jw_write(struct jw *w, const json_t *j, const char *suffix)
{
    size_t m = suffix ? strlen(suffix) : 0;
    int st = j ? jw_value(w, j, 0) : JW_FALLBACK;
    if (st == JW_OK) st = jw_append(w, suffix ? suffix : "", m + 1); /* with its NUL */
    if (st == JW_OK) w->len--; /* the NUL is not part of the text */
    return st;
}

/* The unusual cases: where json_dumps() fails (a reference cycle, a string
 * that is not UTF-8), so do we; a tree deeper than the bound that it
 * accepts (so it has no cycle) is written here with the bound raised, so
 * its reals have the same text as everywhere else. */
static char *jw_fallback(const json_t *j, const char *suffix, size_t *len)
{
    char *s = j ? json_dumps(j, JSON_COMPACT | JSON_ENCODE_ANY) : NULL;
    if (!s) return NULL;
    json_malloc_t jmalloc;
    json_free_t jfree;
    json_get_alloc_funcs(&jmalloc, &jfree);
    jfree(s);
    struct jw w = {NULL, 0, 0, JW_DEEP_MAX_DEPTH};
    if (jw_write(&w, j, suffix) != JW_OK) {
        free(w.buf);
        return NULL;
    }
    if (len) *len = w.len;
    return w.buf;
}

char *api_json_write_compact(const json_t *j, const char *suffix, size_t *len)
{
    struct jw w = {NULL, 0, 0, API_JSON_WRITE_MAX_DEPTH};
    int st = jw_write(&w, j, suffix);
    if (st == JW_OK) {
        if (len) *len = w.len;
        return w.buf;
    }
    free(w.buf);
    if (st == JW_NOMEM || !j) return NULL;
    return jw_fallback(j, suffix, len);
}
