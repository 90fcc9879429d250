/* api.c — api_handle(): routing, media-type check, JSON parse, schema
 * validation, the endpoint call, cost accounting and encoding. Everything an
 * HTTP request to /v1 can meet passes through here, with or without a socket. */
#include "api.h"

#include <ctype.h>
#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>
#include <strings.h>

#include <jansson.h>
#include <zlib.h>

#include "catalog.h"
#include "json_arena.h"
#include "json_read.h"
#include "respond.h"
#include "routes.h"
#include "schema.h"

/* Parsed route schemas, index-aligned with api_routes; read-only after init.
 * route_compiled[i] is route_schemas[i] compiled (it borrows from it); both
 * live for the whole process (api.h has no shutdown: they stay reachable
 * through these pointers, which leak checkers do not report). */
static json_t **route_schemas;
static struct api_schema **route_compiled;
/* Parsed answer schemas (each route's response_schema, from its data file). */
static json_t **route_responses;
/* Per route: its schema's default for a top-level "samples" (0 if none), and
 * whether its requests can ask for samples at all (its schema names samples,
 * or it runs other operations: /v1/batch, /v1/check). */
static double *route_default_samples;
static unsigned char *route_counts_samples;
static int init_status = -1;
static char init_error[300] = "api_init not run";
static pthread_once_t init_once = PTHREAD_ONCE_INIT;

/* ---- allocation failures inside jansson ------------------------------------------
 *
 * Endpoints build answers with json_object_set_new(), json_array_append_new(),
 * json_pack() and the encoders; checking each of those hundreds of calls would
 * bury the physics, and one unchecked failure silently drops a member (a 200
 * with a field missing, or a 422 listing fewer errors than it counts). So
 * jansson allocates through json_malloc_checked() (installed by main() through
 * api_install_json_allocator(), api.h), which records a failure in
 * a per-thread flag; api_handle_ext() clears the flag before a request and,
 * when it is raised afterwards, answers the fixed 500 out-of-memory problem
 * instead of whatever was built. The previous allocator (the C library's, or
 * one a test installed before api_init) does the allocating — except inside
 * an operation request (run_operation), where the per-thread arena of
 * json_arena.c serves what fits while the previous allocator is the C
 * library's. A test's own allocator turns the arena off, so an
 * allocation-failure sweep still reaches every jansson allocation. */
static _Thread_local int json_alloc_failed;
static json_malloc_t prev_json_malloc;
static json_free_t prev_json_free;
static int json_arena_enabled;

static void *json_malloc_checked(size_t n)
{
    void *p = api_json_arena_alloc(n); /* NULL outside a scope or when full */
    if (!p) p = prev_json_malloc ? prev_json_malloc(n) : malloc(n);
    if (!p) json_alloc_failed = 1;
    return p;
}

static void json_free_checked(void *p)
{
    if (api_json_arena_owns(p)) return; /* reclaimed when its scope ends */
    if (prev_json_free)
        prev_json_free(p);
    else
        free(p);
}

void api_install_json_allocator(void)
{
    json_malloc_t m;
    json_free_t f;
    json_get_alloc_funcs(&m, &f);
    if (m == json_malloc_checked) return;
    prev_json_malloc = m;
    prev_json_free = f;
    json_arena_enabled = m == malloc && f == free;
    json_set_alloc_funcs(json_malloc_checked, json_free_checked);
}

/* ---- GET /v1 and /v1/openapi.json: ETag, gzip, 304 ---------------------------------
 *
 * Both documents are fixed for the life of the process (generated from the
 * route table at init), 0.5 and 1.2 MB of JSON that gzip shrinks tenfold. Each
 * is kept with a gzip copy (zlib, level 6: 55 and 89 KB, 15 ms together; made
 * on the first request that accepts gzip, so `mechd eval` and a server that
 * is never asked pay nothing) and a strong ETag per
 * representation: FNV-1a 64 of (build, the identity text), with "-gz" for the
 * gzip one. Served as static memory (no copy per request), Cache-Control
 * "no-cache" (a cache may keep them but revalidates: they change with the
 * build), Vary: Accept-Encoding, and 304 with the 200's Content-Length for a
 * matching If-None-Match. */
struct doc_cache {
    const char *text; /* borrowed from catalog.c */
    size_t len;
    unsigned char *gz; /* gzip of text, or NULL (then only identity is served) */
    size_t gz_len;
    char etag[24], etag_gz[24];
    pthread_once_t gz_once; /* doc_gzip runs once, on first use */
};
static struct doc_cache doc_catalog = {.gz_once = PTHREAD_ONCE_INIT},
                        doc_openapi = {.gz_once = PTHREAD_ONCE_INIT};

static uint64_t fnv1a(uint64_t h, const char *s);

#ifndef MECHD_BUILD_ID
#define MECHD_BUILD_ID ""
#endif

/* gzip (RFC 1952) of text into d->gz; left NULL when memory runs out. */
static int doc_gzip(struct doc_cache *d)
{
    z_stream zs;
    memset(&zs, 0, sizeof zs);
    if (deflateInit2(&zs, 6, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK) return -1;
    uLong cap = deflateBound(&zs, (uLong)d->len);
    d->gz = malloc(cap);
    if (!d->gz) {
        deflateEnd(&zs);
        return -1;
    }
    zs.next_in = (Bytef *)(uintptr_t)d->text;
    zs.avail_in = (uInt)d->len;
    zs.next_out = d->gz;
    zs.avail_out = (uInt)cap;
    int rc = deflate(&zs, Z_FINISH);
    d->gz_len = zs.total_out;
    deflateEnd(&zs);
    if (rc != Z_STREAM_END) {
        free(d->gz);
        d->gz = NULL;
        return -1;
    }
    return 0;
}

static int doc_init(struct doc_cache *d, const char *text)
{
    if (!text) return -1;
    d->text = text;
    d->len = strlen(text);
    uint64_t h = fnv1a(0xcbf29ce484222325ULL, "mechd " MECHD_VERSION " " MECHD_BUILD_ID);
    h = fnv1a(h, text);
    snprintf(d->etag, sizeof d->etag, "\"%016llx\"", (unsigned long long)h);
    snprintf(d->etag_gz, sizeof d->etag_gz, "\"%016llx-gz\"", (unsigned long long)h);
    return 0;
}

static void gzip_catalog(void)
{
    doc_gzip(&doc_catalog);
}

static void gzip_openapi(void)
{
    doc_gzip(&doc_openapi);
}

static int init_routes(void)
{
    route_schemas = calloc(api_route_count, sizeof *route_schemas);
    route_compiled = calloc(api_route_count, sizeof *route_compiled);
    route_default_samples = calloc(api_route_count, sizeof *route_default_samples);
    route_counts_samples = calloc(api_route_count, sizeof *route_counts_samples);
    route_responses = calloc(api_route_count, sizeof *route_responses);
    if (!route_schemas || !route_compiled || !route_default_samples || !route_counts_samples ||
        !route_responses) {
        snprintf(init_error, sizeof init_error, "out of memory");
        return -1;
    }
    for (size_t i = 0; i < api_route_count; i++) {
        const struct api_route *r = api_routes[i];
        json_error_t jerr;
        char msg[200];
        /* Parsed as written (integers stay integers in the documents). */
        if (r->response_schema) {
            route_responses[i] = json_loads(r->response_schema, 0, &jerr);
            if (!json_is_object(route_responses[i])) {
                snprintf(init_error, sizeof init_error,
                         "%s: response_schema is not a JSON object (line %d: %s)", r->path,
                         jerr.line, route_responses[i] ? "not an object" : jerr.text);
                return -1;
            }
        }
        if (!strcmp(r->method, "GET")) {
            /* A read-only resource: no body, so no schema or example. */
            if (r->schema || r->example) {
                snprintf(init_error, sizeof init_error, "%s: a GET route takes no body", r->path);
                return -1;
            }
            continue;
        }
        /* Parsed as written: the validator reads numbers with
         * json_number_value(), and the catalog prints integers as integers. */
        json_t *s = json_loads(r->schema, 0, &jerr);
        if (!s) {
            snprintf(init_error, sizeof init_error, "%s: schema is not JSON (line %d: %s)",
                     r->path, jerr.line, jerr.text);
            return -1;
        }
        route_schemas[i] = s;
        /* Every operation takes the envelope keys ("cost"): added here, once. */
        if (api_route_schema_add_envelope(s, msg, sizeof msg)) {
            snprintf(init_error, sizeof init_error, "%s: schema: %s", r->path, msg);
            return -1;
        }
        json_t *def = json_object_get(
            json_object_get(json_object_get(s, "properties"), "samples"), "default");
        route_default_samples[i] = json_is_number(def) ? json_number_value(def) : 0;
        route_counts_samples[i] =
            strstr(r->schema, "\"samples\"") != NULL || strstr(r->schema, "\"operation\"") != NULL;
        /* Checked and compiled once; requests are validated against the tree. */
        route_compiled[i] = api_schema_compile(s, msg, sizeof msg);
        if (!route_compiled[i]) {
            snprintf(init_error, sizeof init_error, "%s: schema: %s", r->path, msg);
            return -1;
        }
        /* The catalog's example must be a request the schema accepts. */
        json_t *ex = json_loads(r->example, JSON_DECODE_INT_AS_REAL, &jerr);
        size_t nerr = ex ? api_schema_validate(route_compiled[i], ex, "", NULL) : 1;
        json_decref(ex);
        if (nerr) {
            snprintf(init_error, sizeof init_error, "%s: example does not match its schema",
                     r->path);
            return -1;
        }
    }
    if (api_catalog_init((const json_t *const *)route_schemas,
                         (const json_t *const *)route_responses, init_error, sizeof init_error))
        return -1;
    if (doc_init(&doc_catalog, api_catalog_text()) || doc_init(&doc_openapi, api_openapi_text())) {
        snprintf(init_error, sizeof init_error, "the catalog or OpenAPI text is missing");
        return -1;
    }
    return 0;
}

static void init_once_fn(void)
{
    json_malloc_t m;
    json_free_t f;
    json_get_alloc_funcs(&m, &f);
    if (m != json_malloc_checked) {
        /* Process-wide set-up belongs to main(), before any thread starts. */
        snprintf(init_error, sizeof init_error,
                 "api_install_json_allocator() was not called before api_init() (main's set-up)");
        init_status = -1;
        return;
    }
    init_status = init_routes();
}

int api_init(void)
{
    pthread_once(&init_once, init_once_fn);
    return init_status;
}

const char *api_init_error(void)
{
    return init_status == 0 ? NULL : init_error;
}

const json_t *api_route_schema(size_t i)
{
    return i < api_route_count && route_schemas ? route_schemas[i] : NULL;
}

const struct api_schema *api_route_schema_compiled(size_t i)
{
    return i < api_route_count && route_compiled ? route_compiled[i] : NULL;
}

const json_t *api_route_response_schema(size_t i)
{
    return i < api_route_count && route_responses ? route_responses[i] : NULL;
}

/* ---- helpers ---------------------------------------------------------------- */

static int is_get(const char *m)
{
    return !strcmp(m, "GET") || !strcmp(m, "HEAD");
}

/* Media type equals application/json, ignoring case, parameters and spaces. */
static int is_json_media_type(const char *ct)
{
    if (!ct) return 0;
    while (*ct == ' ' || *ct == '\t') ct++;
    static const char want[] = "application/json";
    if (strncasecmp(ct, want, sizeof want - 1)) return 0;
    const char *rest = ct + sizeof want - 1;
    while (*rest == ' ' || *rest == '\t') rest++;
    return *rest == '\0' || *rest == ';';
}

static long route_index(const char *path)
{
    for (size_t i = 0; i < api_route_count; i++)
        if (!strcmp(api_routes[i]->path, path)) return (long)i;
    return -1;
}

int api_is_inline(const char *method, const char *path)
{
    /* Only POST operations compute; GET routes return precomputed or cheap
     * descriptions and answer on the I/O thread. */
    return !(method && path && !strcmp(method, "POST") && route_index(path) >= 0);
}

long api_quick_route(const char *method, const char *path, size_t body_len)
{
    if (!method || !path || strcmp(method, "POST") != 0 || body_len > API_QUICK_MAX_BODY) return -1;
    long ri = route_index(path);
    return ri >= 0 && api_routes[ri]->quick ? ri : -1;
}

size_t api_operation_count(void)
{
    return api_route_count;
}

const char *api_operation_path(size_t i)
{
    return i < api_route_count ? api_routes[i]->path : NULL;
}

const char *api_operation_method(size_t i)
{
    return i < api_route_count ? api_routes[i]->method : NULL;
}

int api_operation_quick(size_t i)
{
    return i < api_route_count && api_routes[i]->quick;
}

/* A GET route: call the handler without a body; it cannot fail on input. */
static void run_resource(size_t ri, const struct api_request *req, struct api_response *resp)
{
    struct api_call call;
    memset(&call, 0, sizeof call);
    call.req = req;
    json_t *result = api_routes[ri]->fn(&call, NULL);
    if (!result || call.problem != API_PROBLEM_NONE || call.nonfinite) {
        api_response_problem(resp, API_PROBLEM_INTERNAL, "internal error");
        snprintf(resp->note, sizeof resp->note, "%.40s: resource handler failed",
                 api_routes[ri]->path);
    } else {
        api_respond_json(resp, 200, "application/json", result);
    }
    json_decref(result);
    json_decref(call.errors);
    json_decref(call.extra);
}

/* GET /problems/<slug>: what a problem type means (its type URI resolves here). */
static void serve_problem_doc(const char *slug, struct api_response *resp)
{
    enum api_problem k = api_problem_by_slug(slug);
    if (k == API_PROBLEM_NONE) {
        api_response_problem(resp, API_PROBLEM_NOT_FOUND, "no such problem type");
        return;
    }
    json_t *doc = json_pack("{s:s,s:s,s:i,s:s}", "type", api_problem_type(k), "title",
                            api_problem_title(k), "status", api_problem_status(k),
                            "description", api_problem_description(k));
    api_respond_json(resp, 200, "application/json", doc);
    json_decref(doc);
}

/* 405 for a path that takes `want` ("GET" or "POST"), with its Allow header
 * (RFC 9110 §15.5.6). An operation also answers GET/HEAD with ?request=. */
static void method_not_allowed(struct api_response *resp, const char *want)
{
    int post = !strcmp(want, "POST");
    api_response_problem(resp, API_PROBLEM_METHOD_NOT_ALLOWED,
                         post ? "this path takes POST (or GET with ?request= and the JSON body, "
                                "URL-encoded)"
                              : "this path takes GET (or HEAD)");
    resp->allow = post ? "POST, GET, HEAD" : "GET, HEAD";
}

/* ---- operations ---------------------------------------------------------------- */

/* Every request api_handle_ext() runs is wrapped so that code holding only the
 * struct api_request (a handler's call->req, e.g. /v1/batch) can still see the
 * extras. Only api.c creates api_request pointers that reach handlers. */
struct full_request {
    struct api_request req; /* first member */
    int no_cost;
    long max_samples; /* > 0 */
};

static int request_no_cost(const struct api_request *req)
{
    return req ? ((const struct full_request *)(const void *)req)->no_cost : 0;
}

static long request_max_samples(const struct api_request *req)
{
    return req ? ((const struct full_request *)(const void *)req)->max_samples
               : API_DEFAULT_MAX_SAMPLES;
}

/* Copy of `errors` with every pointer prefixed (new reference). */
static json_t *prefixed_errors(const json_t *errors, const char *prefix)
{
    json_t *out = json_array();
    size_t i;
    json_t *e;
    json_array_foreach(errors, i, e) {
        json_t *c = json_deep_copy(e);
        const char *p = json_string_value(json_object_get(e, "pointer"));
        if (c && p && prefix && *prefix) {
            size_t n = strlen(prefix) + strlen(p) + 1;
            char *q = malloc(n);
            if (q) {
                snprintf(q, n, "%s%s", prefix, p);
                json_object_set_new_nocheck(c, "pointer", json_string(q));
                free(q);
            }
        }
        json_array_append_new(out, c);
    }
    return out;
}

static json_t *problem_json(enum api_problem kind, const char *detail, const json_t *errors,
                            const json_t *extra)
{
    json_t *p = api_problem_object(kind, detail);
    if (p && errors) json_object_set(p, "errors", (json_t *)errors);
    if (p && extra) json_object_update(p, (json_t *)extra);
    return p;
}

/* ---- the answer budget: samples, counted before computing ------------------------
 *
 * An answer grows with the samples it is asked for (t, position, velocity... per
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
            long ri = route_index(json_string_value(op));
            if (ri >= 0 && route_default_samples[ri] > 0) {
                if (ptr) pointer_push(ptr, len, cap, "request");
                samples_add(sc, route_default_samples[ri], ptr ? ptr : "");
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
    if (!json_object_get(body, "samples") && route_default_samples[ri] > 0)
        samples_add(sc, route_default_samples[ri], ptr ? ptr : "");
    samples_walk(body, ptr, len, cap, sc, 0);
}

/* NULL if body's samples fit in cap, else the problem naming where they pass
 * it (new reference). Routes whose schema has no samples and no nested
 * operations (most closed forms: a boost, an inertia) are not walked. */
static json_t *answer_budget_problem(size_t ri, const json_t *body, const char *prefix,
                                     long cap)
{
    if (!route_counts_samples[ri]) return NULL;
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

/* Whether a problem kind says the answer depended on load or time. */
static int problem_depends_on_load(enum api_problem k)
{
    return k == API_PROBLEM_BUDGET || k == API_PROBLEM_CANCELLED || k == API_PROBLEM_QUEUE_FULL;
}

/* The pipeline after parsing: schema validation, the answer budget, the
 * handler, the non-finite check, cost accounting. Returns the HTTP status and
 * sets *out to the answer or the problem object (new reference; NULL only
 * when memory ran out). Error pointers are prefixed with prefix ("" at top
 * level). note gets the reason of a 500 for the log. no_cost: an enclosing
 * request (a batch) asked for no measured cost. *dep is set to 1 when the
 * outcome depended on load or time (the handler said so, or a budget,
 * deadline or cancellation stopped it), else left alone. */
static int run_parsed(size_t ri, const struct api_request *req, const json_t *body,
                      const char *prefix, int no_cost, json_t **out, char *note, size_t note_n,
                      int *dep)
{
    const struct api_route *r = api_routes[ri];
    *out = NULL;
    /* Count first: a valid body (the usual case) then costs no error
     * pointers. Zero counted means zero listed (the modes differ only past
     * API_SCHEMA_MAX_ERRORS); for an invalid body the listing run's count is
     * the one reported, as before. */
    size_t nerr = api_schema_validate(route_compiled[ri], body, prefix, NULL);
    if (nerr) {
        json_t *errors = json_array();
        nerr = api_schema_validate(route_compiled[ri], body, prefix, errors);
        char d[120];
        snprintf(d, sizeof d, "%zu error%s in the request", nerr, nerr == 1 ? "" : "s");
        *out = problem_json(API_PROBLEM_VALIDATION, d, errors, NULL);
        json_decref(errors);
        return api_problem_status(API_PROBLEM_VALIDATION);
    }
    long cap = request_max_samples(req);
    json_t *too_large = answer_budget_problem(ri, body, prefix, cap);
    if (too_large) {
        *out = too_large;
        return api_problem_status(API_PROBLEM_ANSWER_TOO_LARGE);
    }

    /* The handler sees the body with its schema's defaults filled in (a
     * copy; the caller's body is left as it is), so no handler restates a
     * default. The envelope keys are the framework's and stay as given. */
    static const char *const envelope_keys[] = {"cost", NULL};
    json_t *full = api_schema_apply_defaults(route_compiled[ri], body, envelope_keys);
    if (!full) {
        if (note) snprintf(note, note_n, "%.40s: out of memory filling defaults", r->path);
        *out = problem_json(API_PROBLEM_INTERNAL, "internal error", NULL, NULL);
        return api_problem_status(API_PROBLEM_INTERNAL);
    }

    struct api_call call;
    memset(&call, 0, sizeof call);
    call.req = req;
    call.given = body;
    call.body = full;
    call.budget.max_steps = req->max_steps > 0 ? req->max_steps : 1;
    call.budget.deadline = isfinite(req->deadline) ? req->deadline : 0;
    call.budget.cancel = req->cancel;
    int want_cost =
        !no_cost && !request_no_cost(req) && !json_is_false(json_object_get(body, "cost"));
    call.no_cost = !want_cost;

    /* The thread CPU clock is a system call, not a vDSO read: only for routes
     * that report it. */
    double cpu0 = r->reports_cost ? mech_cpu_seconds() : 0.0;
    json_t *result = r->fn(&call, full);
    double cpu = r->reports_cost ? mech_cpu_seconds() - cpu0 : 0.0;
    json_decref(full);

    if (result && call.problem == API_PROBLEM_NONE && call.nonfinite) {
        call.problem = API_PROBLEM_NUMERIC;
        snprintf(call.detail, sizeof call.detail,
                 "the result is not finite for this input (overflow or a singularity)");
    }
    if (call.depends_on_load || problem_depends_on_load(call.problem)) *dep = 1;
    if (!result || call.problem != API_PROBLEM_NONE) {
        enum api_problem k = call.problem != API_PROBLEM_NONE ? call.problem : API_PROBLEM_INTERNAL;
        char d[300];
        if (call.errors && json_array_size(call.errors)) {
            size_t n = json_array_size(call.errors);
            snprintf(d, sizeof d, "%s", n == 1 ? json_string_value(json_object_get(
                                                     json_array_get(call.errors, 0), "detail"))
                                               : "several fields are invalid");
        } else {
            snprintf(d, sizeof d, "%s", call.detail[0] ? call.detail : "internal error");
        }
        if (k == API_PROBLEM_INTERNAL) {
            *out = problem_json(k, "internal error", NULL, NULL);
            if (note)
                snprintf(note, note_n, "%.40s: %.150s", r->path,
                         call.detail[0] ? call.detail : "handler returned no result");
        } else {
            json_t *pe = call.errors ? prefixed_errors(call.errors, prefix) : NULL;
            *out = problem_json(k, d, pe, call.extra);
            json_decref(pe);
        }
        json_decref(result);
        json_decref(call.errors);
        json_decref(call.extra);
        return api_problem_status(k);
    }
    json_decref(call.errors);
    json_decref(call.extra);

    if (r->reports_cost) {
        if (want_cost) {
            json_t *cost = json_object_get(result, "cost");
            if (!json_is_object(cost)) {
                cost = json_object();
                json_object_set_new_nocheck(result, "cost", cost);
            }
            if (cost) json_object_set_new_nocheck(cost, "cpu_seconds", json_real(cpu));
        } else {
            json_object_del(result, "cost");
        }
    }
    *out = result;
    return 200;
}

int api_run_operation(struct api_call *outer, const char *path, const json_t *request,
                      const char *pointer_prefix, json_t **out)
{
    *out = NULL;
    long ri = path ? route_index(path) : -1;
    if (ri < 0 || strcmp(api_routes[ri]->method, "POST") != 0 || !outer || !outer->req) return -1;
    char note[200];
    note[0] = '\0';
    int dep = 0;
    int status = run_parsed((size_t)ri, outer->req, request, pointer_prefix ? pointer_prefix : "",
                            outer->no_cost, out, note, sizeof note, &dep);
    if (dep) outer->depends_on_load = 1;
    if (!*out) {
        *out = problem_json(API_PROBLEM_INTERNAL, "internal error", NULL, NULL);
        status = 500;
    }
    return status;
}

/* Serialise an outcome of run_parsed into resp (consumes `out`). */
static void respond_outcome(struct api_response *resp, int status, json_t *out, const char *note)
{
    if (!out) {
        api_response_problem(resp, API_PROBLEM_INTERNAL, "internal error");
    } else {
        api_respond_json(resp, status, status == 200 ? "application/json"
                                                      : "application/problem+json", out);
        json_decref(out);
        if (status == 503) resp->retry_after = 1;
    }
    if (note && note[0]) snprintf(resp->note, sizeof resp->note, "%s", note);
}

/* A parse that failed for lack of memory is the server's failure, not a
 * malformed body: answer 500 (return 1, resp filled) instead of 400. */
static int parse_out_of_memory(const json_error_t *jerr, struct api_response *resp)
{
    if (json_error_code(jerr) != json_error_out_of_memory) return 0;
    api_response_problem(resp, API_PROBLEM_INTERNAL, "internal error");
    snprintf(resp->note, sizeof resp->note, "out of memory while parsing the request");
    return 1;
}

/* Parse, validate, run and answer an operation's JSON body. */
static void run_body(size_t ri, const struct api_request *req, struct api_response *resp)
{
    json_error_t jerr;
    json_t *body = api_json_read(req->body ? req->body : "", req->body ? req->body_len : 0, &jerr);
    if (!body) {
        if (parse_out_of_memory(&jerr, resp)) return;
        char d[300];
        snprintf(d, sizeof d, "line %d, column %d: %s", jerr.line, jerr.column, jerr.text);
        api_response_problem(resp, API_PROBLEM_MALFORMED_JSON, d);
        return;
    }
    json_t *out = NULL;
    char note[200];
    note[0] = '\0';
    int dep = 0;
    int status = run_parsed(ri, req, body, "", 0, &out, note, sizeof note, &dep);
    json_decref(body);
    respond_outcome(resp, status, out, note);
    resp->depends_on_load = dep;
}

static void run_operation(size_t ri, const struct api_request *req, struct api_response *resp)
{
    if (!is_json_media_type(req->content_type)) {
        char d[200];
        snprintf(d, sizeof d, "send the body as Content-Type: application/json (got %s%.80s%s)",
                 req->content_type ? "'" : "", req->content_type ? req->content_type : "none",
                 req->content_type ? "'" : "");
        api_response_problem(resp, API_PROBLEM_UNSUPPORTED_MEDIA, d);
        return;
    }
    /* Every tree of this request (body, answer) is built and released in
     * this scope; the answer leaves as malloc()ed text (json_arena.c). */
    if (json_arena_enabled) api_json_arena_begin();
    run_body(ri, req, resp);
    if (json_arena_enabled) api_json_arena_end();
}

/* ---- GET ?request= : determinism, ETag, 304 ------------------------------------- */

/* FNV-1a 64 over the parts, each followed by a NUL separator. */
static uint64_t fnv1a(uint64_t h, const char *s)
{
    for (const unsigned char *p = (const unsigned char *)s; *p; p++) {
        h ^= *p;
        h *= 0x100000001b3ULL;
    }
    h *= 0x100000001b3ULL; /* the separator: h ^= 0 */
    return h;
}

/* Strong ETag of (build, path, canonical request) into buf (>= 19 bytes).
 * Returns 0, or -1 if memory ran out. */
static int request_etag(const char *path, const json_t *body, char *buf, size_t n)
{
    char *canon = json_dumps(body, JSON_COMPACT | JSON_SORT_KEYS | JSON_REAL_PRECISION(17) |
                                       JSON_ENCODE_ANY);
    if (!canon) return -1;
    uint64_t h = 0xcbf29ce484222325ULL;
    h = fnv1a(h, "mechd " MECHD_VERSION " " MECHD_BUILD_ID);
    h = fnv1a(h, path);
    h = fnv1a(h, canon);
    free(canon);
    snprintf(buf, n, "\"%016llx\"", (unsigned long long)h);
    return 0;
}

/* Whether an If-None-Match header value lists `etag` (weak comparison, RFC 9110
 * 13.1.2: a W/ prefix is ignored) or is "*". */
static int etag_matches(const char *header, const char *etag)
{
    if (!header || !etag || !etag[0]) return 0;
    size_t elen = strlen(etag);
    const char *p = header;
    while (*p) {
        while (*p == ' ' || *p == '\t' || *p == ',') p++;
        if (!*p) break;
        const char *start = p;
        while (*p && *p != ',') p++;
        const char *end = p;
        while (end > start && (end[-1] == ' ' || end[-1] == '\t')) end--;
        if (end - start == 1 && *start == '*') return 1;
        if (end - start >= 2 && start[0] == 'W' && start[1] == '/') start += 2;
        if ((size_t)(end - start) == elen && !strncmp(start, etag, elen)) return 1;
    }
    return 0;
}

/* Whether an Accept-Encoding header value admits gzip (RFC 9110 12.5.3): listed
 * as gzip or x-gzip with q > 0, or not listed while "*" is with q > 0. */
static int accepts_gzip(const char *h)
{
    int gzip = -1, star = -1;
    while (h && *h) {
        while (*h == ' ' || *h == '\t' || *h == ',') h++;
        if (!*h) break;
        const char *name = h;
        while (*h && *h != ',' && *h != ';' && *h != ' ' && *h != '\t') h++;
        size_t nl = (size_t)(h - name);
        int ok = 1; /* q defaults to 1 */
        while (*h && *h != ',') {
            while (*h == ';' || *h == ' ' || *h == '\t') h++;
            if ((h[0] == 'q' || h[0] == 'Q') && h[1] == '=') {
                ok = strtod(h + 2, NULL) > 0; /* a qvalue is 0..1 with at most 3 decimals */
            }
            while (*h && *h != ',' && *h != ';') h++;
        }
        if ((nl == 4 && !strncasecmp(name, "gzip", 4)) ||
            (nl == 6 && !strncasecmp(name, "x-gzip", 6)))
            gzip = ok;
        else if (nl == 1 && *name == '*')
            star = ok;
    }
    return gzip >= 0 ? gzip : star == 1;
}

/* GET/HEAD of /v1 or /v1/openapi.json (see doc_cache above). */
static void serve_doc(struct doc_cache *d, const struct api_request_ext *ext,
                      struct api_response *resp)
{
    int gz = ext && accepts_gzip(ext->accept_encoding);
    if (gz) pthread_once(&d->gz_once, d == &doc_catalog ? gzip_catalog : gzip_openapi);
    gz = gz && d->gz;
    const char *etag = gz ? d->etag_gz : d->etag;
    size_t len = gz ? d->gz_len : d->len;
    memset(resp, 0, sizeof *resp);
    snprintf(resp->etag, sizeof resp->etag, "%s", etag);
    resp->cache_control = "no-cache";
    resp->vary = "Accept-Encoding";
    if (ext && etag_matches(ext->if_none_match, etag)) {
        resp->status = 304;
        resp->full_length = len;
        return;
    }
    resp->status = 200;
    resp->content_type = "application/json";
    resp->body = gz ? (char *)d->gz : (char *)(uintptr_t)d->text;
    resp->body_len = len;
    resp->body_static = 1;
    resp->content_encoding = gz ? "gzip" : NULL;
}

static void run_query(size_t ri, const struct api_request *req, const struct api_request_ext *ext,
                      struct api_response *resp)
{
    json_error_t jerr;
    /* json_loads of a C string: the same tree or error as json_loadb of its strlen. */
    json_t *body = api_json_read(ext->query_request, strlen(ext->query_request), &jerr);
    if (!body) {
        if (parse_out_of_memory(&jerr, resp)) {
            resp->cache_control = "no-store";
            return;
        }
        char d[300];
        snprintf(d, sizeof d, "the request query parameter: line %d, column %d: %s", jerr.line,
                 jerr.column, jerr.text);
        api_response_problem(resp, API_PROBLEM_MALFORMED_JSON, d);
        resp->cache_control = "no-store";
        return;
    }
    char etag[sizeof resp->etag];
    if (request_etag(api_routes[ri]->path, body, etag, sizeof etag)) etag[0] = '\0';
    if (etag[0] && etag_matches(ext->if_none_match, etag)) {
        json_decref(body);
        memset(resp, 0, sizeof *resp);
        resp->status = 304;
        snprintf(resp->etag, sizeof resp->etag, "%s", etag);
        resp->cache_control = "public, max-age=86400";
        return;
    }
    json_t *out = NULL;
    char note[200];
    note[0] = '\0';
    int dep = 0;
    int status = run_parsed(ri, req, body, "", 0, &out, note, sizeof note, &dep);
    json_decref(body);
    respond_outcome(resp, status, out, note);
    /* An answer that depended on load (a batch item stopped by the deadline,
     * a partial result) is not the answer of this request: it must neither be
     * cached nor carry the ETag the full answer has. */
    resp->depends_on_load = dep;
    if (resp->status == 200 && etag[0] && !dep) {
        snprintf(resp->etag, sizeof resp->etag, "%s", etag);
        resp->cache_control = "public, max-age=86400";
    } else {
        resp->cache_control = "no-store";
    }
}

void api_handle(const struct api_request *req, struct api_response *resp)
{
    api_handle_ext(req, NULL, resp);
}

static void handle(const struct api_request *req0, const struct api_request_ext *ext,
                   struct api_response *resp);

void api_handle_ext(const struct api_request *req0, const struct api_request_ext *ext,
                    struct api_response *resp)
{
    json_alloc_failed = 0;
    handle(req0, ext, resp);
    if (json_alloc_failed) { /* something was dropped: never send it (see above) */
        api_respond_out_of_memory(resp);
        snprintf(resp->note, sizeof resp->note, "out of memory while building the answer");
    }
    /* RFC 9457 instance: the request path (the same bytes with or without a
     * server, so `mechd eval` matches; X-Request-Id names the occurrence). */
    api_response_set_instance(resp, req0 && req0->path ? req0->path : "");
}

static void handle(const struct api_request *req0, const struct api_request_ext *ext,
                   struct api_response *resp)
{
    memset(resp, 0, sizeof *resp);
    struct full_request full;
    memset(&full, 0, sizeof full);
    full.req = *req0;
    const struct api_request *req = &full.req;
    const char *query = ext ? ext->query_request : NULL;
    full.no_cost = (ext && ext->no_cost) || (query && is_get(req->method ? req->method : ""));
    full.max_samples = ext && ext->max_samples > 0 ? ext->max_samples : API_DEFAULT_MAX_SAMPLES;
    if (api_init() != 0) {
        api_response_problem(resp, API_PROBLEM_INTERNAL, "internal error");
        snprintf(resp->note, sizeof resp->note, "api_init failed: %.150s", init_error);
        return;
    }
    const char *m = req->method ? req->method : "";
    const char *path = req->path ? req->path : "";

    if (!strcmp(path, "/v1") || !strcmp(path, "/v1/")) {
        if (!is_get(m)) { method_not_allowed(resp, "GET"); return; }
        serve_doc(&doc_catalog, ext, resp);
        return;
    }
    if (!strcmp(path, "/v1/openapi.json")) {
        if (!is_get(m)) { method_not_allowed(resp, "GET"); return; }
        serve_doc(&doc_openapi, ext, resp);
        return;
    }
    if (!strncmp(path, "/problems/", 10)) {
        if (!is_get(m)) { method_not_allowed(resp, "GET"); return; }
        serve_problem_doc(path + 10, resp);
        return;
    }
    long ri = route_index(path);
    if (ri < 0) {
        char d[200];
        snprintf(d, sizeof d, "no operation at %.120s; GET /v1 lists them all", path);
        api_response_problem(resp, API_PROBLEM_NOT_FOUND, d);
        return;
    }
    const char *want = api_routes[ri]->method;
    if (!strcmp(want, "POST") && is_get(m) && query) {
        run_query((size_t)ri, req, ext, resp);
        return;
    }
    if (!strcmp(want, "POST") && is_get(m)) {
        api_response_problem(resp, API_PROBLEM_REQUEST_MISSING,
                             "this operation needs a request: POST it as the JSON body, or GET "
                             "this path with ?request=<the request JSON, URL-encoded>");
        resp->cache_control = "no-store";
        return;
    }
    if (!strcmp(want, "GET") ? !is_get(m) : strcmp(m, want) != 0) {
        method_not_allowed(resp, want);
        return;
    }
    if (!strcmp(want, "GET")) {
        run_resource((size_t)ri, req, resp);
    } else {
        run_operation((size_t)ri, req, resp);
        resp->cache_control = "no-store";
    }
}
