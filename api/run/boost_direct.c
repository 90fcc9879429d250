/* boost_direct.c — POST /v1/relativity/boost from bytes to bytes (see
 * api/run/boost_direct.h for the contract).
 *
 * Why: a boost's own arithmetic is ~20 ns per vector, but through the
 * general pipeline every number of the request and of the answer is a
 * jansson node (allocated, validated against the schema, filled with
 * defaults, serialised, freed): measured with callgrind, ~12,000
 * instructions per vector of a 100,000-vector request, and ~28,000 for a
 * one-vector request. The plain request shape is read here in one pass
 * straight into doubles, boosted, and written straight into the answer's
 * text (~1,000 instructions per vector).
 *
 * Correctness rests on declining: anything outside the plain shape, or that
 * the schema or the core would refuse, returns 0 before a byte is written,
 * and the general pipeline answers it (its errors stay the only errors).
 * When this path answers, it writes what the general one writes, in the
 * same member order (api_op_relativity_boost, api_velocity_describe), each
 * real through api_real_format with -0 written as 0.0 (api_real), numbers
 * read through api_json_number_scan (api_json_read's own reader); the API
 * tests compare both paths byte for byte on varied requests. */
#include "run/boost_direct.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "json/json_read.h"
#include "mech/relativity/boost.h"
#include "json/real_format.h"

/* The schema's bounds (api/ops/relativity/boost.json). */
#define BD_MAX_VECTORS 100000u
#define BD_COMPONENT_MAX 1e150

struct bd {
    const char *p, *end;
};

/* jansson's whitespace (src/load.c): space, tab, newline, carriage return. */
static inline void bd_space(struct bd *r)
{
    while (r->p < r->end && (*r->p == ' ' || *r->p == '\n' || *r->p == '\t' || *r->p == '\r'))
        r->p++;
}

/* The byte c (after whitespace), consumed. */
static inline int bd_byte(struct bd *r, char c)
{
    bd_space(r);
    if (r->p == r->end || *r->p != c) return 0;
    r->p++;
    return 1;
}

/* A number (after whitespace) into *v; with bounded, also within the
 * schema's component bounds. */
static inline int bd_number(struct bd *r, double *v, int bounded)
{
    bd_space(r);
    if (r->p == r->end) return 0;
    const char *next = api_json_number_scan(r->p, r->end, v);
    if (!next) return 0;
    r->p = next;
    return !bounded || (*v >= -BD_COMPONENT_MAX && *v <= BD_COMPONENT_MAX);
}

/* k numbers and ']' after an opening '[' into x. */
static int bd_numbers_open(struct bd *r, double *x, int k, int bounded)
{
    for (int i = 0; i < k; i++)
        if ((i && !bd_byte(r, ',')) || !bd_number(r, x + i, bounded)) return 0;
    return bd_byte(r, ']');
}

/* '[' k numbers ']' (after whitespace) into x. */
static int bd_numbers(struct bd *r, double *x, int k, int bounded)
{
    return bd_byte(r, '[') && bd_numbers_open(r, x, k, bounded);
}

/* A key (after whitespace) of printable ASCII without escapes, then ':'. */
static int bd_key(struct bd *r, const char **k, size_t *n)
{
    if (!bd_byte(r, '"')) return 0;
    const char *s = r->p;
    while (r->p < r->end && *r->p != '"') {
        const unsigned char c = (unsigned char)*r->p;
        if (c < 0x20 || c > 0x7E || c == '\\') return 0;
        r->p++;
    }
    if (r->p == r->end) return 0;
    *k = s;
    *n = (size_t)(r->p - s);
    r->p++;
    return bd_byte(r, ':');
}

static int key_is(const char *k, size_t n, const char *want)
{
    return strlen(want) == n && memcmp(k, want, n) == 0;
}

/* true or false (after whitespace) into *b. */
static int bd_bool(struct bd *r, int *b)
{
    bd_space(r);
    const size_t left = (size_t)(r->end - r->p);
    if (left >= 4 && !memcmp(r->p, "true", 4)) {
        *b = 1;
        r->p += 4;
        return 1;
    }
    if (left >= 5 && !memcmp(r->p, "false", 5)) {
        *b = 0;
        r->p += 5;
        return 1;
    }
    return 0;
}

/* "vectors": one 4-vector (*single = 1) or a list of 1..cap of them, into x
 * (room for 4 cap doubles); *n the count. */
static int bd_vectors(struct bd *r, double *x, size_t cap, size_t *n, int *single)
{
    if (!bd_byte(r, '[')) return 0;
    bd_space(r);
    if (r->p == r->end) return 0;
    if (*r->p != '[') { /* one 4-vector */
        *single = 1;
        *n = 1;
        return bd_numbers_open(r, x, 4, 1);
    }
    *single = 0;
    size_t k = 0;
    for (;;) {
        if (k == cap || !bd_numbers(r, x + 4 * k, 4, 1)) return 0;
        k++;
        bd_space(r);
        if (r->p == r->end || *r->p != ',') break;
        r->p++;
    }
    *n = k;
    return bd_byte(r, ']');
}

/* "velocity": exactly {"beta": [3 numbers]}. */
static int bd_velocity(struct bd *r, double beta[3])
{
    const char *k;
    size_t kn;
    if (!bd_byte(r, '{') || !bd_key(r, &k, &kn) || !key_is(k, kn, "beta")) return 0;
    return bd_numbers(r, beta, 3, 0) && bd_byte(r, '}');
}

/* ---- the answer's text ---------------------------------------------------- */

struct bw {
    char *p;
};

static inline void bw_text(struct bw *w, const char *s, size_t n)
{
    memcpy(w->p, s, n);
    w->p += n;
}
#define BW_LIT(w, s) bw_text((w), (s), sizeof(s) - 1)

/* A real as api_real() and api/json/json_write.c write it: -0 as 0.0. The caller
 * checked it is finite and left API_REAL_FORMAT_SIZE bytes of room. */
static inline void bw_real(struct bw *w, double x)
{
    w->p += api_real_format(x == 0 ? 0.0 : x, w->p);
}

static void bw_reals(struct bw *w, const double *x, size_t n)
{
    *w->p++ = '[';
    for (size_t i = 0; i < n; i++) {
        if (i) *w->p++ = ',';
        bw_real(w, x[i]);
    }
    *w->p++ = ']';
}

static int all_finite(const double *x, size_t n)
{
    /* the sum of x times 0 is 0 exactly when every x is finite and the
     * partial sums do not overflow; only then the exact test */
    double s = 0.0;
    for (size_t i = 0; i < n; i++)
        s += x[i] * 0.0;
    if (s == 0.0) return 1;
    for (size_t i = 0; i < n; i++)
        if (!isfinite(x[i])) return 0;
    return 1;
}

/* Bytes a real may take with the comma before it (API_REAL_FORMAT_SIZE
 * covers the longest text and its NUL). */
#define BD_REAL_ROOM (API_REAL_FORMAT_SIZE + 1)

int api_boost_direct(const char *text, size_t len, const struct mech_budget *budget,
                     struct api_response *resp)
{
    if (!text || !budget || len < 2) return 0;
    struct bd r = {text, text + len};
    /* the shortest vector text, "[0,0,0,0]," is 10 bytes */
    size_t cap = len / 9 + 1;
    if (cap > BD_MAX_VECTORS) cap = BD_MAX_VECTORS;
    double *x = malloc(10 * cap * sizeof *x); /* in, out: 4 cap each; invariants: cap each */
    if (!x) return 0;
    size_t n = 0;
    int single = 0, matrix = 0, cost = 0, have_vectors = 0, have_velocity = 0, have_matrix = 0,
        have_cost = 0, ok = bd_byte(&r, '{');
    double beta[3] = {0, 0, 0};
    while (ok) {
        const char *k;
        size_t kn;
        if (!bd_key(&r, &k, &kn)) ok = 0;
        else if (key_is(k, kn, "vectors") && !have_vectors)
            ok = have_vectors = bd_vectors(&r, x, cap, &n, &single);
        else if (key_is(k, kn, "velocity") && !have_velocity)
            ok = have_velocity = bd_velocity(&r, beta);
        else if (key_is(k, kn, "matrix") && !have_matrix)
            ok = have_matrix = bd_bool(&r, &matrix);
        else if (key_is(k, kn, "cost") && !have_cost)
            ok = have_cost = bd_bool(&r, &cost);
        else
            ok = 0; /* another key, or a duplicate */
        if (!ok || bd_byte(&r, '}')) break;
        ok = bd_byte(&r, ',');
    }
    bd_space(&r);
    struct mech_boost b;
    if (!ok || !have_vectors || !have_velocity || r.p != r.end ||
        mech_boost_from_beta(mech_vec3_make(beta[0], beta[1], beta[2]), &b, NULL) != MECH_OK)
        goto decline;
    double *out = x + 4 * cap, *ib = x + 8 * cap, *ia = x + 9 * cap;
    if (mech_boost_apply_batch(&b, x, out, ib, ia, n, budget, NULL) != MECH_OK) goto decline;
    double m[4][4];
    if (matrix) mech_boost_matrix(&b, m);
    const double about[7] = {b.gamma,      b.gamma_minus_one, b.rapidity,    b.one_minus_beta,
                             b.beta_vec.x, b.beta_vec.y,      b.beta_vec.z};
    if (!all_finite(out, 4 * n) || !all_finite(ib, n) || !all_finite(ia, n) ||
        !all_finite(about, 7) || (matrix && !all_finite(&m[0][0], 16)))
        goto decline;
    /* the vectors with their brackets, the invariants, the matrix, the names */
    char *body = malloc(n * (6 * BD_REAL_ROOM + 4) + 24 * BD_REAL_ROOM + 256);
    if (!body) goto decline;
    struct bw w = {body};
    BW_LIT(&w, "{\"vectors\":");
    if (single) {
        bw_reals(&w, out, 4);
    } else {
        *w.p++ = '[';
        for (size_t i = 0; i < n; i++) {
            if (i) *w.p++ = ',';
            bw_reals(&w, out + 4 * i, 4);
        }
        *w.p++ = ']';
    }
    BW_LIT(&w, ",\"gamma\":");
    bw_real(&w, b.gamma);
    BW_LIT(&w, ",\"gamma_minus_one\":");
    bw_real(&w, b.gamma_minus_one);
    BW_LIT(&w, ",\"beta\":");
    bw_reals(&w, about + 4, 3);
    BW_LIT(&w, ",\"rapidity\":");
    bw_real(&w, b.rapidity);
    BW_LIT(&w, ",\"one_minus_beta\":");
    bw_real(&w, b.one_minus_beta);
    BW_LIT(&w, ",\"invariants_before\":");
    if (single) bw_real(&w, ib[0]);
    else bw_reals(&w, ib, n);
    BW_LIT(&w, ",\"invariants_after\":");
    if (single) bw_real(&w, ia[0]);
    else bw_reals(&w, ia, n);
    if (matrix) {
        BW_LIT(&w, ",\"matrix\":[");
        for (int i = 0; i < 4; i++) {
            if (i) *w.p++ = ',';
            bw_reals(&w, m[i], 4);
        }
        *w.p++ = ']';
    }
    BW_LIT(&w, "}\n");
    *w.p = '\0';
    free(x);
    memset(resp, 0, sizeof *resp);
    resp->status = 200;
    resp->content_type = "application/json";
    resp->body = body;
    resp->body_len = (size_t)(w.p - body);
    return 1;
decline:
    free(x);
    return 0;
}
