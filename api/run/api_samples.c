/* api_samples.c — the answer budget: the samples one request asks for, in
 * all, counted on the validated body before any handler runs, against the
 * server's --max-samples (api/run/api_samples.h). */
#include "run/api_samples.h"

#include <stdio.h>
#include <string.h>

#include "run/api_init.h"
#include "http/respond.h"

/* An answer grows with the samples it is asked for (t, position, velocity... per
 * sample), so the samples of one request are bounded as a whole: the sum of
 * every numeric "samples" member anywhere in the body (a batch's or check's
 * items included: {"operation", "request"} objects whose request gives none
 * count their operation's default) must not pass the request's max_samples.
 * The count runs on the validated body, before the handler allocates anything. */
struct sample_count {
    double total, cap;
    char where[300]; /* pointer of the member where total first passed cap */
    int passed;
};

/* Append "/" + key (JSON-pointer escaped) to ptr[0..len); returns the new
 * length, or len unchanged when it would not fit (the pointer is then cut). */
static size_t pointer_push(char *ptr, size_t len, size_t cap, const char *key)
{
    size_t n = len;
    if (n + 2 >= cap) return len;
    ptr[n++] = '/';
    for (const char *k = key; *k; k++) {
        const char *esc = *k == '~' ? "~0" : *k == '/' ? "~1" : NULL;
        size_t w = esc ? 2 : 1;
        if (n + w + 1 >= cap) return len;
        if (esc) {
            memcpy(ptr + n, esc, 2);
        } else {
            ptr[n] = *k;
        }
        n += w;
    }
    ptr[n] = '\0';
    return n;
}

static void samples_add(struct sample_count *sc, double n, const char *ptr)
{
    sc->total += n;
    if (!sc->passed && sc->total > sc->cap) {
        sc->passed = 1;
        snprintf(sc->where, sizeof sc->where, "%s", ptr);
    }
}

/* Add up the samples under v. ptr (may be NULL: count only, the fast first
 * pass) holds v's JSON pointer in ptr[0..len) of cap bytes. */
static void samples_walk(const json_t *v, char *ptr, size_t len, size_t cap,
                         struct sample_count *sc, int depth)
{
    if (depth > 64) return; /* the parser caps depth well below this */
    if (json_is_object(v)) {
        const char *key;
        json_t *m;
        json_object_foreach((json_t *)v, key, m) {
            if (!json_is_object(m) && !json_is_array(m) && strcmp(key, "samples") != 0) continue;
            size_t n = ptr ? pointer_push(ptr, len, cap, key) : 0;
            if (!strcmp(key, "samples") && json_is_number(m) && json_number_value(m) > 0)
                samples_add(sc, json_number_value(m), ptr ? ptr : "");
            else
                samples_walk(m, ptr, n, cap, sc, depth + 1);
            if (ptr) ptr[len] = '\0';
        }
        /* An item of /v1/batch or /v1/check: its operation's default samples. */
        const json_t *op = json_object_get(v, "operation"), *rq = json_object_get(v, "request");
        if (json_is_string(op) && json_is_object(rq) && !json_object_get(rq, "samples")) {
            long ri = api_route_index(json_string_value(op));
            if (ri >= 0 && api_route_default_samples((size_t)ri) > 0) {
                if (ptr) pointer_push(ptr, len, cap, "request");
                samples_add(sc, api_route_default_samples((size_t)ri), ptr ? ptr : "");
                if (ptr) ptr[len] = '\0';
            }
        }
    } else if (json_is_array(v)) {
        size_t i;
        json_t *m;
        json_array_foreach(v, i, m) {
            if (!json_is_object(m) && !json_is_array(m)) continue; /* numbers: nothing under */
            size_t n = 0;
            if (ptr) {
                char idx[24];
                snprintf(idx, sizeof idx, "%zu", i);
                n = pointer_push(ptr, len, cap, idx);
            }
            samples_walk(m, ptr, n, cap, sc, depth + 1);
            if (ptr) ptr[len] = '\0';
        }
    }
}

/* Count the samples of body for route ri; ptr as in samples_walk. */
static void samples_count(size_t ri, const json_t *body, char *ptr, size_t len, size_t cap,
                          struct sample_count *sc)
{
    if (!json_object_get(body, "samples") && api_route_default_samples(ri) > 0)
        samples_add(sc, api_route_default_samples(ri), ptr ? ptr : "");
    samples_walk(body, ptr, len, cap, sc, 0);
}

/* NULL if body's samples fit in cap, else the problem naming where they pass
 * it (new reference). Routes whose schema has no samples and no nested
 * operations (most closed forms: a boost, an inertia) are not walked. */
json_t *api_answer_budget_problem(size_t ri, const json_t *body, const char *prefix, long cap)
{
    if (!api_route_counts_samples(ri)) return NULL;
    struct sample_count sc;
    memset(&sc, 0, sizeof sc);
    sc.cap = (double)cap;
    samples_count(ri, body, NULL, 0, 0, &sc); /* the usual case: fits, no pointers built */
    if (!sc.passed) return NULL;
    memset(&sc, 0, sizeof sc);
    sc.cap = (double)cap;
    char ptr[300];
    snprintf(ptr, sizeof ptr, "%s", prefix ? prefix : "");
    samples_count(ri, body, ptr, strlen(ptr), sizeof ptr, &sc);
    char d[300];
    snprintf(d, sizeof d,
             "the request asks for %.0f samples in all; this server answers at most %ld per "
             "request (--max-samples): ask for fewer or split the request",
             sc.total, cap);
    json_t *p = api_problem_object(API_PROBLEM_ANSWER_TOO_LARGE, d);
    char e[300];
    snprintf(e, sizeof e, "the samples up to here make more than %ld, the limit of one request",
             cap);
    json_t *errors = json_array();
    json_array_append_new(errors, api_error_entry(sc.where, e));
    json_object_set_new_nocheck(p, "errors", errors);
    json_object_set_new_nocheck(p, "limit", json_integer((json_int_t)cap));
    json_object_set_new_nocheck(p, "requested", json_integer((json_int_t)sc.total));
    return p;
}

double api_answer_samples(size_t ri, const json_t *body)
{
    if (!api_route_counts_samples(ri)) return 0.0;
    struct sample_count sc;
    memset(&sc, 0, sizeof sc);
    sc.cap = 1e300; /* count only */
    samples_count(ri, body, NULL, 0, 0, &sc);
    return sc.total;
}
