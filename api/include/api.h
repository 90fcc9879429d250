/* api.h — the network-free entry point of mechd's API layer.
 *
 * api_handle() turns one HTTP-shaped request into one HTTP-shaped response:
 * routing, content-type check, JSON parse, schema validation, the endpoint's
 * core calls, encoding and problem+json errors. The server (server/) and the
 * in-process tests (tests/api/) both call it. Thread-safe: any number of
 * threads may call api_handle() at once.
 */
#ifndef API_API_H
#define API_API_H

#include <stddef.h>

/* Kinds of problem+json answer. Append-only; pinned by tests/api/test_problem.c. */
enum api_problem {
    API_PROBLEM_NONE = 0,
    API_PROBLEM_MALFORMED_JSON,     /* 400 */
    API_PROBLEM_NOT_FOUND,          /* 404 */
    API_PROBLEM_METHOD_NOT_ALLOWED, /* 405 */
    API_PROBLEM_BODY_TOO_LARGE,     /* 413 */
    API_PROBLEM_UNSUPPORTED_MEDIA,  /* 415 */
    API_PROBLEM_VALIDATION,         /* 422, with errors[] */
    API_PROBLEM_DOMAIN,             /* 422, physically impossible input, with errors[] */
    API_PROBLEM_BUDGET,             /* 422, steps/samples/deadline exhausted, with progress */
    API_PROBLEM_NUMERIC,            /* 422, the numerics failed (non-finite, step underflow) */
    API_PROBLEM_QUEUE_FULL,         /* 503 + Retry-After */
    API_PROBLEM_INTERNAL,           /* 500, generic detail */
    API_PROBLEM_CANCELLED,          /* 503, server shutting down */
    API_PROBLEM_UNAUTHORIZED,       /* 401, --token-file set and no/wrong bearer token */
    API_PROBLEM_CORS_FORBIDDEN,     /* 403, CORS preflight from an origin not allowed */
    API_PROBLEM_REQUEST_MISSING,    /* 400, GET/HEAD of an operation without ?request= */
    API_PROBLEM_ANSWER_TOO_LARGE,   /* 422, the request asks for more samples than --max-samples */
    API_PROBLEM_BAD_FRAMING,        /* 400, ambiguous or unsupported body framing (server) */
    API_PROBLEM_ANSWER_MEMORY,      /* 503 + Retry-After, the answer-memory budget is spent */
    API_PROBLEM_BAD_REQUEST,        /* 400, a malformed request head (HTTP/1.1 without Host) */
    API_PROBLEM_URI_TOO_LONG,       /* 414, the request target is longer than the server reads */
    API_PROBLEM_HEADERS_TOO_LARGE,  /* 431, the request head is larger than the server reads */
    API_PROBLEM_COUNT
};

struct api_request {
    const char *method;        /* "GET", "POST", ... */
    const char *path;          /* "/v1/rigid/inertia" (no query string) */
    const char *content_type;  /* Content-Type header or NULL */
    const char *body;          /* may be NULL when body_len == 0; need not be NUL-terminated */
    size_t body_len;
    long max_steps;            /* step budget for integrations (> 0) */
    double deadline;           /* absolute, mech_clock_seconds(); computations stop after it */
    const volatile int *cancel;/* may be NULL; nonzero cancels running work */
};

/* Default answer budget (--max-samples): two full-size (100,000-sample)
 * integrations per request, an answer of some 15-30 MB. */
#define API_DEFAULT_MAX_SAMPLES 200000L

struct api_response {
    int status;               /* HTTP status */
    const char *content_type; /* static string */
    char *body;               /* malloc'd, NUL-terminated; owned by the response */
    size_t body_len;
    int retry_after;          /* seconds for Retry-After, 0 for none */
    char note[200];           /* for the server log only, never sent: why a 500 happened */
    char etag[24];            /* "" or a strong entity tag, quoted ("\"0123456789abcdef\"") */
    const char *cache_control;/* static string for Cache-Control, or NULL for none */
    const char *allow;        /* a 405's Allow header (static string), or NULL */
    int depends_on_load;      /* 1: the answer depended on load or time (a deadline, a budget,
                                 a partial result): never cached, never given an ETag */
    int body_static;          /* 1: body is static memory (not freed, not to be freed) */
    const char *content_encoding; /* static string for Content-Encoding ("gzip"), or NULL */
    const char *vary;         /* static string for Vary ("Accept-Encoding"), or NULL */
    size_t full_length;       /* a 304's: the length of the 200's body when known (sent as its
                                 Content-Length, RFC 9110 8.6), 0 for unknown: none is sent */
    int instance_set;         /* a problem body already carries "instance" */
    int deferred;             /* 1: not run: api_request_ext's gate stopped it before it
                                 computed (status 0, no body); run it again without a gate */
};

/* What only the HTTP server and `mechd eval` know about a request (all optional).
 * Kept apart from struct api_request so existing initialisers stay valid. */
struct api_request_ext {
    const char *query_request; /* GET/HEAD: the URL-decoded ?request= value (JSON text), or NULL */
    const char *if_none_match; /* If-None-Match header, or NULL */
    int no_cost;               /* 1: drop the measured cost, so the body is byte-deterministic */
    const char *accept_encoding; /* Accept-Encoding header, or NULL (gzip of /v1, openapi.json) */
    long max_samples;          /* answer budget: samples one request may ask for, summed over
                                  every "samples" of its body (and of a batch's items);
                                  0 means API_DEFAULT_MAX_SAMPLES (--max-samples) */
    /* Admission (may be NULL: every request runs). Called at most once per
     * request, on its operation (never on a batch's or check's items), after
     * the body is parsed and validated and the samples budget has passed, and
     * before the handler runs: route is the operation's index (api.h route
     * numbering), samples what the request asks for in all (counted as the
     * samples budget counts, 0 for an operation without samples). Returns 0
     * to run the request, or nonzero to refuse it: the answer is then 503
     * answer-memory-full with Retry-After: 1, and nothing is computed. */
    int (*admit)(void *ctx, long route, double samples);
    void *admit_ctx;
    const char *host;          /* Host header, or NULL: GET /v1's curl lines name this host
                                  and port instead of 127.0.0.1:8080 */
    /* Cost gate (may be NULL: nothing is stopped). Called at most once per
     * request, on its own operation (never on a batch's items), by an
     * operation that predicts its cost (api_gated_route) once the prediction
     * is made and before anything long is computed: predicted_cpu_s is the
     * chosen method's predicted CPU seconds (the chooser's predicted_cpu_s),
     * or -1 when nothing predicts it (a method and step given by the client,
     * or a first pass of unknown length to run before the choice). Returns
     * 0 to go on, nonzero to stop: the response is then resp->deferred = 1
     * (status 0, no body), and the caller runs the request again, elsewhere
     * and without the gate. */
    int (*gate)(void *ctx, double predicted_cpu_s);
    void *gate_ctx;
};

/* Process-wide set-up of the API layer: main() (the server's, `mechd eval`'s,
 * every test's and bench's) calls it once, before any thread starts and before
 * api_init(), as it calls gsl_set_error_handler_off() for GSL. It makes jansson
 * allocate through the API layer, which notices a failed allocation (the
 * request then gets the fixed 500 out-of-memory problem, never an answer with
 * a member silently missing) and serves an operation's JSON from a per-thread
 * arena. A test that installs its own jansson allocator (json_set_alloc_funcs)
 * does so first: it is then wrapped, and the arena stays off. Calling it again
 * does nothing. Not thread-safe (process set-up). */
void api_install_json_allocator(void);

/* One-time set-up (parses the route schemas). Called by api_handle() on first
 * use through pthread_once, so calling it is optional. Returns 0 on success;
 * fails (api_init_error says why) when api_install_json_allocator() was not
 * called first. */
int api_init(void);

/* Why api_init() failed (a route schema or example is broken), or NULL. */
const char *api_init_error(void);

/* Handle one request. Never fails: on any failure the response is a
 * problem+json. resp is overwritten; free it with api_response_free(). */
void api_handle(const struct api_request *req, struct api_response *resp);

/* api_handle() with the HTTP extras (ext may be NULL). Determinism contract:
 * a GET or HEAD of a POST operation with ?request=<JSON> runs it with the
 * cost dropped; a 200 answer then carries etag = FNV-1a 64 of (build version,
 * path, canonical request: parsed JSON re-serialised compactly with sorted keys)
 * and Cache-Control "public, max-age=86400", and the same ETag always comes
 * with the same bytes — unless the answer depended on load or time
 * (resp->depends_on_load: a handler set call->depends_on_load, or an item ran
 * out of deadline or budget), which gets no ETag and "no-store". If
 * If-None-Match matches that ETag (or is "*"), the answer is 304 with no body
 * and the operation is not run. POST answers and every problem from an
 * operation carry Cache-Control "no-store". Every problem+json gets "instance":
 * the request path. GET /v1 and /v1/openapi.json are static memory
 * (body_static), gzip when ext->accept_encoding admits it, with a strong ETag,
 * "no-cache", Vary: Accept-Encoding and 304 (full_length set). */
void api_handle_ext(const struct api_request *req, const struct api_request_ext *ext,
                    struct api_response *resp);

struct api_call;
struct json_t;
/* For /v1/check and /v1/batch: run the POST operation at `path` on the parsed
 * `request` (borrowed) in-process, through the same pipeline as api_handle()
 * (schema validation, handler, non-finite check, cost), sharing the outer
 * call's budget (deadline, steps, cancel). Pointers of every error are
 * prefixed with pointer_prefix ("/request"). If the inner answer depended on
 * load (a deadline, a budget, a partial result), outer->depends_on_load is
 * set, so the outer answer is not cached either. Returns the HTTP status and sets
 * *out to a new reference: the answer (200) or the problem object. Returns -1
 * with *out = NULL if no POST operation has that path. The inner operation
 * inherits the outer call's no_cost. */
int api_run_operation(struct api_call *outer, const char *path, const struct json_t *request,
                      const char *pointer_prefix, struct json_t **out);

/* Fill resp with a problem+json of the given kind and detail (may be NULL).
 * Used by the server for 413, 415, 503. */
void api_response_problem(struct api_response *resp, enum api_problem kind, const char *detail);

/* Give a problem+json body in resp its RFC 9457 "instance" member (instance
 * is copied, JSON-escaped, at most 256 bytes of it), unless it has one or resp
 * is not a problem. Used by api_handle_ext() (the request path) and by the
 * server for the problems it builds. When memory runs out resp becomes the
 * fixed 500 out-of-memory problem (never a problem silently missing a member). */
void api_response_set_instance(struct api_response *resp, const char *instance);

/* Give a problem+json body in resp a "request_id" member (the request's
 * X-Request-Id, copied, JSON-escaped, at most 256 bytes), as its last member;
 * nothing for other bodies or an empty id. Out of memory as above. Used by the
 * server for every problem it sends. */
void api_response_set_request_id(struct api_response *resp, const char *id);

/* Free the body of a response (safe on a zeroed or already-freed response). */
void api_response_free(struct api_response *resp);

/* HTTP status for a problem kind; its stable type URI ("/problems/<slug>") and title. */
int api_problem_status(enum api_problem kind);
const char *api_problem_type(enum api_problem kind);
const char *api_problem_title(enum api_problem kind);

/* Whether a request is cheap enough to run on the I/O thread (GET of the
 * catalog, health, static text) or must go to a compute worker (POST). */
int api_is_inline(const char *method, const char *path);

/* Whether a POST may be answered on the I/O thread: its route is marked quick
 * (closed form, cost linear in the body). Returns the route's index in
 * api_routes, or -1 for anything else. Any body size: whether it runs there
 * is the server's decision, from the cost it predicts for this body (its
 * --inline-max-us), not from the size. The deadline and step budget still
 * apply to a quick request. */
long api_quick_route(const char *method, const char *path, size_t body_len);

/* Whether a POST operation predicts its own cost before it computes (its
 * chooser's predicted CPU, through api_request_ext's gate): the route's index,
 * or -1. Such a request can be started on the I/O thread with a gate that
 * stops it, before anything long is computed, when the prediction is too
 * long for there. */
long api_gated_route(const char *method, const char *path);

/* The route table, read through accessors (the server sees no struct
 * api_route). Routes are numbered 0 .. api_operation_count()-1 in a fixed
 * order, the numbering of api_quick_route(). For i out of range the path and
 * method are NULL and quick is 0. Strings are static. */
size_t api_operation_count(void);
const char *api_operation_path(size_t i);   /* "/v1/rigid/inertia" */
const char *api_operation_method(size_t i); /* "POST" or "GET" */
int api_operation_quick(size_t i);          /* 1: closed form, may run on the I/O thread */

#endif
