/* test_alloc_failure.c — allocation-failure sweep of the API entry point
 * (hostile input and faults).
 *
 * For each test request (per POST route: its catalog example, the same as
 * GET ?request=, and "{}" (a validation error); plus the catalog, the
 * examples resource, a problem document, malformed JSON and a wrong path):
 * run it once to learn its answer and its allocation count N, then for
 * n = P+1..N (P: a body parse done by jansson, see JANSSON_LEXER_BUG; 0 for
 * the plain bodies api/json/json_read.c parses itself) make allocation n
 * fail and check that
 *   - nothing crashes (ASan/UBSan build: a NULL dereference aborts the test);
 *   - the answer is the normal one (the failure was absorbed: same status,
 *     same bytes — a 200 with different bytes is a silently wrong answer), or
 *     a 500 internal-error problem+json (or the documented fallback: 500 with
 *     no body when even that could not be allocated);
 *   - every block allocated during the request is freed once
 *     api_response_free() has run (the wrapper keeps a table of live blocks).
 * N above ALLOC_SWEEP_CAP (default 600; env ALLOC_SWEEP_CAP overrides) is
 * sampled: the first CAP/2 positions, then evenly spaced ones, and the last;
 * and a request whose normal run is slow gets fewer positions (about
 * ALLOC_SWEEP_SECONDS, default 1.5, of failure runs; at least 20), so the
 * sweep stays bounded in time (a few minutes under ASan).
 *
 * Allocations counted and failed: malloc, calloc, realloc, strdup, free
 * (tracked) of libmech/libmechapi/this test, via
 *   -Wl,--wrap=malloc,--wrap=calloc,--wrap=realloc,--wrap=strdup,--wrap=free
 * and jansson's own allocations via json_set_alloc_funcs(). Not covered:
 * GSL's internal allocations (a shared library; its *_alloc calls return NULL
 * through GSL's error handler, which the program turns off) and libc-internal
 * ones. Linked without --wrap (the __real_* symbols are then absent) the test
 * says so and passes without sweeping.
 *
 * Known bugs (KNOWN[] below) are reported as "known" and do not fail the
 * test; every other finding fails it. A crash cannot be allow-listed, so a
 * route with a known crash is listed in KNOWN with what = "skip". */
#include <gsl/gsl_errno.h>
#include <jansson.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "api.h"
#include "json/json_read.h"
#include "mech/base/budget.h"
#include "run/routes.h"
#include "testlib.h"

/* ---- the allocator wrapper ---------------------------------------------------- */

extern void *__real_malloc(size_t) __attribute__((weak));
extern void *__real_calloc(size_t, size_t) __attribute__((weak));
extern void *__real_realloc(void *, size_t) __attribute__((weak));
extern char *__real_strdup(const char *) __attribute__((weak));
extern void __real_free(void *) __attribute__((weak));
void *__wrap_malloc(size_t n);
void *__wrap_calloc(size_t k, size_t n);
void *__wrap_realloc(void *p, size_t n);
char *__wrap_strdup(const char *s);
void __wrap_free(void *p);

static int counting;     /* count, fail and track only while a request runs */
static long n_allocs;    /* allocations counted so far in this request */
static long fail_at;     /* the allocation number that fails (0: none) */
static long n_failed;    /* allocations that were made to fail */

#define LIVE_SLOTS (1u << 17)
static void *live[LIVE_SLOTS]; /* open addressing; TOMB marks a deleted slot */
static size_t live_count, live_used;
static int live_overflow;
static char tomb_mark;
#define TOMB ((void *)&tomb_mark)

static size_t slot_of(const void *p)
{
    uintptr_t x = (uintptr_t)p;
    x ^= x >> 17;
    x *= 0x9E3779B97F4A7C15ULL;
    return (size_t)(x >> 20) & (LIVE_SLOTS - 1);
}

static void live_add(void *p)
{
    if (!p || !counting) return;
    if (live_used > LIVE_SLOTS / 4 * 3) { live_overflow = 1; return; }
    size_t i = slot_of(p);
    while (live[i] && live[i] != TOMB) i = (i + 1) & (LIVE_SLOTS - 1);
    if (!live[i]) live_used++;
    live[i] = p;
    live_count++;
}

static void live_del(void *p)
{
    if (!p || !live_count) return;
    for (size_t i = slot_of(p); live[i]; i = (i + 1) & (LIVE_SLOTS - 1))
        if (live[i] == p) { live[i] = TOMB; live_count--; return; }
}

static void live_reset(void)
{
    memset(live, 0, sizeof live);
    live_count = live_used = 0;
    live_overflow = 0;
}

/* 1 if this allocation must fail. */
static int should_fail(void)
{
    if (!counting) return 0;
    n_allocs++;
    if (n_allocs == fail_at) { n_failed++; return 1; }
    return 0;
}

void *__wrap_malloc(size_t n)
{
    if (should_fail()) return NULL;
    void *p = __real_malloc(n);
    live_add(p);
    return p;
}

void *__wrap_calloc(size_t k, size_t n)
{
    if (should_fail()) return NULL;
    void *p = __real_calloc(k, n);
    live_add(p);
    return p;
}

void *__wrap_realloc(void *p, size_t n)
{
    if (should_fail()) return NULL; /* p stays valid and owned by the caller */
    void *q = __real_realloc(p, n);
    if (q || n == 0) live_del(p);
    live_add(q);
    return q;
}

char *__wrap_strdup(const char *s)
{
    if (should_fail()) return NULL;
    char *p = __real_strdup(s);
    live_add(p);
    return p;
}

void __wrap_free(void *p)
{
    live_del(p);
    __real_free(p);
}

static void *json_alloc(size_t n) { return __wrap_malloc(n); }
static void json_free(void *p) { __wrap_free(p); }

/* ---- known bugs (allow-list) ---------------------------------------------------- */

struct known {
    const char *label; /* request label (see add_requests), or "*text": labels containing text */
    const char *what;  /* a kind_name ("misreported", "leak", ...) or "skip" (a crash: not swept) */
    const char *bug;   /* the bug, for the lead: file, function, what fails */
};

static const struct known KNOWN[] = {
    {NULL, NULL, NULL},
};

static const struct known *known_for(const char *label, const char *what)
{
    for (const struct known *k = KNOWN; k->label; k++) {
        int match = k->label[0] == '*' ? strstr(label, k->label + 1) != NULL
                                       : !strcmp(label, k->label);
        if (match && !strcmp(k->what, what)) return k;
    }
    return NULL;
}

/* ---- requests ------------------------------------------------------------------- */

struct request {
    char label[160];
    const char *method, *path, *body, *query;
    const char *content_type;
};

#define MAX_REQ 256
static struct request reqs[MAX_REQ];
static size_t n_reqs;

static void add(const char *label, const char *method, const char *path, const char *body,
                const char *query)
{
    if (n_reqs == MAX_REQ) return;
    struct request *r = &reqs[n_reqs++];
    snprintf(r->label, sizeof r->label, "%s", label);
    r->method = method;
    r->path = path;
    r->body = body;
    r->query = query;
    r->content_type = "application/json";
}

static void add_requests(void)
{
    char label[160];
    for (size_t i = 0; i < api_route_count; i++) {
        const struct api_route *rt = api_routes[i];
        if (strcmp(rt->method, "POST")) {
            snprintf(label, sizeof label, "GET %s", rt->path);
            add(label, "GET", rt->path, NULL, NULL);
            continue;
        }
        snprintf(label, sizeof label, "POST %s example", rt->path);
        add(label, "POST", rt->path, rt->example, NULL);
        snprintf(label, sizeof label, "GET %s ?request=example", rt->path);
        add(label, "GET", rt->path, NULL, rt->example);
        snprintf(label, sizeof label, "POST %s {}", rt->path);
        add(label, "POST", rt->path, "{}", NULL);
    }
    add("GET /v1", "GET", "/v1", NULL, NULL);
    add("GET /v1/openapi.json", "GET", "/v1/openapi.json", NULL, NULL);
    add("GET /problems/domain-error", "GET", "/problems/domain-error", NULL, NULL);
    add("POST /v1/nowhere", "POST", "/v1/nowhere", "{}", NULL);
    add("POST /v1/relativity/boost malformed", "POST", "/v1/relativity/boost", "{\"a\": [1, 2", NULL);
    add("POST /v1/batch two", "POST", "/v1/batch",
        "{\"operations\": [{\"path\": \"/v1/relativity/boost\", \"request\": {}},"
        " {\"path\": \"/v1/nowhere\", \"request\": {}}]}", NULL);
    /* /v1/check's whole-quantity kinds (eigenvectors with a degenerate plane,
     * axis_angle), a unit and the revealing feedback: api/check/check_kind.c's paths. */
    add("POST /v1/check eigenvectors", "POST", "/v1/check",
        "{\"operation\": \"/v1/rigid/inertia\", \"request\": {\"bodies\": [{\"shape\": "
        "\"cylinder\", \"mass\": 2, \"radius\": 1, \"height\": 1, \"position\": [0, 0, 0]}]}, "
        "\"answer\": {\"pointer\": \"/principal/axes\", \"value\": [[0.6, 0.8, 0], [0.8, -0.6, 0], "
        "[0, 0, 0]]}, \"reveal\": true}", NULL);
    add("POST /v1/check axis_angle deg", "POST", "/v1/check",
        "{\"operation\": \"/v1/rotation/convert\", \"request\": {\"axis_angle\": {\"axis\": "
        "[0, 0, 1], \"angle\": 1}}, \"answer\": {\"pointer\": \"/axis_angle\", \"value\": "
        "{\"axis\": [0, 0, -1], \"angle\": -57.3}, \"unit\": \"deg\"}, \"reveal\": true}", NULL);
    /* a student's odd answers: text with a unit read, swapped components and
     * the reciprocal found by grading copies (api/check/check_answer.c, api/check/check_slip.c) */
    add("POST /v1/check swapped text", "POST", "/v1/check",
        "{\"operation\": \"/v1/rigid/inertia\", \"request\": {\"bodies\": [{\"shape\": "
        "\"box\", \"mass\": 12, \"size\": [1, 2, 3], \"position\": [0, 0, 0]}]}, "
        "\"answer\": {\"pointer\": \"/principal/moments\", \"value\": \"[\\\"5 kg m2\\\", 13, 10]\"}}",
        NULL);
    add("POST /v1/check reciprocal", "POST", "/v1/check",
        "{\"operation\": \"/v1/rigid/inertia\", \"request\": {\"bodies\": [{\"shape\": "
        "\"box\", \"mass\": 12, \"size\": [1, 2, 3], \"position\": [0, 0, 0]}]}, "
        "\"answer\": {\"pointer\": \"/principal/moments\", \"value\": [\"1/5\", 0.1, 0.076923076923]}}",
        NULL);
}

/* ---- running and judging ------------------------------------------------------------ */

struct outcome {
    int status;
    char *body; /* copy (real malloc), or NULL */
};

static void run(const struct request *r, long fail, struct outcome *o, size_t *leaked,
                long *allocs)
{
    struct api_request req = {
        .method = r->method,
        .path = r->path,
        .content_type = r->content_type,
        .body = r->body,
        .body_len = r->body ? strlen(r->body) : 0,
        .max_steps = 10000000,
        .deadline = mech_clock_seconds() + 60.0,
        .cancel = NULL,
    };
    struct api_request_ext ext = {.query_request = r->query, .if_none_match = NULL, .no_cost = 1};
    struct api_response resp;
    live_reset();
    n_allocs = 0;
    fail_at = fail;
    counting = 1;
    api_handle_ext(&req, &ext, &resp);
    counting = 0;
    o->status = resp.status;
    o->body = resp.body ? __real_strdup(resp.body) : NULL;
    if (resp.body && (strlen(resp.body) != resp.body_len || !resp.content_type)) o->status = -1;
    counting = 1; /* so the response's blocks leave the table when freed */
    *allocs = n_allocs;
    api_response_free(&resp);
    counting = 0;
    *leaked = live_overflow ? 0 : live_count;
}

/* A clean out-of-memory answer: 500 internal-error problem+json, or no body. */
static int is_clean_500(const struct outcome *o)
{
    if (o->status != 500) return 0;
    if (!o->body) return 1;
    json_t *j = json_loads(o->body, 0, NULL); /* not counting: nothing fails here */
    const char *type = json_string_value(json_object_get(j, "type"));
    int ok = type && !strcmp(type, "/problems/internal-error") &&
             json_integer_value(json_object_get(j, "status")) == 500;
    json_decref(j);
    return ok;
}

/* /v1/batch answers 200 with one status per operation, so a failure inside
 * one operation is reported in its own item: accept a 200 whose items each
 * equal the normal item or are a clean 500 internal-error. */
static int batch_items_ok(const char *got, const char *normal)
{
    json_t *g = json_loads(got, 0, NULL), *b = json_loads(normal, 0, NULL);
    json_t *gr = json_object_get(g, "results"), *br = json_object_get(b, "results");
    int ok = json_is_array(gr) && json_is_array(br) && json_array_size(gr) == json_array_size(br) &&
             json_object_size(g) == json_object_size(b);
    for (size_t i = 0; ok && i < json_array_size(gr); i++) {
        json_t *gi = json_array_get(gr, i), *bi = json_array_get(br, i);
        if (json_equal(gi, bi)) continue;
        const char *type =
            json_string_value(json_object_get(json_object_get(gi, "problem"), "type"));
        ok = json_integer_value(json_object_get(gi, "status")) == 500 && type &&
             !strcmp(type, "/problems/internal-error");
    }
    json_decref(g);
    json_decref(b);
    return ok;
}

/* Kinds of finding, counted per request; the first of each kind is shown. */
enum kind { K_MISREPORTED, K_CORRUPT200, K_DEGRADED, K_LEAK, K_COUNT };
static const char *const kind_name[K_COUNT] = {"misreported", "corrupt200", "degraded", "leak"};
static const char *const kind_help[K_COUNT] = {
    "a failed allocation answered with another status than the normal one or a 500",
    "a failed allocation gave a 200 whose bytes differ from the normal answer",
    "same error status, but the problem body lost or changed content",
    "blocks allocated during the request still live after api_response_free",
};
static int n_findings, n_known;

struct tally {
    long count[K_COUNT], first[K_COUNT];
    char sample[K_COUNT][300];
};

static void note(struct tally *t, enum kind k, long n, const char *sample)
{
    if (!t->count[k]++) {
        t->first[k] = n;
        snprintf(t->sample[k], sizeof t->sample[k], "%s", sample);
    }
}

static void report(const struct request *r, const struct tally *t)
{
    for (int k = 0; k < K_COUNT; k++) {
        if (!t->count[k]) continue;
        const struct known *kn = known_for(r->label, kind_name[k]);
        if (kn) n_known++; else n_findings++;
        fprintf(stderr, "%s %s: %s x%ld (first at allocation %ld): %s\n", kn ? "known  " : "FINDING",
                r->label, kind_name[k], t->count[k], t->first[k], t->sample[k]);
    }
}

/* JANSSON_LEXER_BUG: jansson 2.14 (Debian libjansson4 2.14-2), load.c: lex_save()
 * ignores a failed strbuffer_append_byte(), so an allocation failing inside
 * json_loads()/json_loadb() corrupts the lexer: out-of-bounds write (SEGV) or
 * a free of a non-heap pointer inside libjansson (upstream akheron/jansson
 * issues #362, PR #364). Not mechd's code. Request bodies (and ?request=) are
 * parsed by api_json_read() (api/json/json_read.c): a plain document entirely by
 * its own fast path, whose allocations are swept like any other (P = 0);
 * anything else is handed to json_loadb(), so for such a text the sweep does
 * not fail the parse's allocations: it counts them (P) by parsing the same
 * text the same way, and sweeps n = P+1 .. N. */
static long parse_allocs(const struct request *r)
{
    const char *text = r->query ? r->query : r->body;
    if (!text || !strcmp(r->method, "GET") != !!r->query) return 0;
    int is_json_route = 0;
    for (size_t i = 0; i < api_route_count; i++)
        if (!strcmp(api_routes[i]->path, r->path) && !strcmp(api_routes[i]->method, "POST"))
            is_json_route = 1;
    if (!is_json_route) return 0;
    json_t *j = NULL;
    int plain = api_json_read_plain(text, strlen(text), &j, NULL);
    json_decref(j);
    if (plain == 1) return 0;
    live_reset();
    n_allocs = 0;
    fail_at = 0;
    counting = 1;
    j = api_json_read(text, strlen(text), NULL);
    long p = n_allocs;
    counting = 0;
    json_decref(j);
    return p;
}

/* The k-th allocation position to fail (k = 0 .. min(N, cap) - 1): every one
 * when N <= cap, else the first cap/2 and then cap/2 evenly spaced up to N. */
static long sample_position(long k, long N, long cap)
{
    if (N <= cap || k < cap / 2) return k + 1;
    long h = cap / 2, j = k - h; /* 0 .. cap - h - 1 */
    long m = cap - h;
    return h + 1 + (m > 1 ? j * (N - h - 1) / (m - 1) : 0);
}

int main(void)
{
    gsl_set_error_handler_off();
    if (!__real_malloc || !__real_calloc || !__real_realloc || !__real_strdup || !__real_free) {
        printf("test_alloc_failure: not linked with -Wl,--wrap=malloc,...: nothing swept\n");
        return 0;
    }
    json_set_alloc_funcs(json_alloc, json_free);
    api_install_json_allocator(); /* wraps the test's allocator: every allocation counted */
    CHECK(api_init() == 0);
    add_requests();
    long cap = getenv("ALLOC_SWEEP_CAP") ? atol(getenv("ALLOC_SWEEP_CAP")) : 600;
    if (cap < 10) cap = 10;
    const char *only = getenv("ALLOC_SWEEP_ONLY"); /* a label substring, for debugging */
    int trace = getenv("ALLOC_SWEEP_TRACE") != NULL; /* print each n before running it */
    double per_req = getenv("ALLOC_SWEEP_SECONDS") ? atof(getenv("ALLOC_SWEEP_SECONDS")) : 1.5;
    long total_runs = 0;

    for (size_t i = 0; i < n_reqs; i++) {
        const struct request *r = &reqs[i];
        if (only && !strstr(r->label, only)) continue;
        if (known_for(r->label, "skip")) {
            printf("skip  %-60s (known crash, see KNOWN)\n", r->label);
            n_known++;
            continue;
        }
        struct outcome base, o;
        size_t leaked;
        long N, got;
        run(r, 0, &base, &leaked, &N); /* warm-up: lazily initialised state */
        __real_free(base.body);
        double t0 = mech_clock_seconds();
        run(r, 0, &base, &leaked, &N);
        double t_run = mech_clock_seconds() - t0;
        CHECK(base.status > 0);
        /* Bounded time: at most about per_req seconds of failure runs per request. */
        long cap_r = t_run > 0 && per_req / t_run < (double)cap ? (long)(per_req / t_run) : cap;
        if (cap_r < 20) cap_r = 20;
        /* Allocations 1..P are the body parse when jansson's parser does it (the parse
         * is the first thing api_handle_ext allocates in): not failed, see
         * JANSSON_LEXER_BUG; P = 0 for the plain bodies api_json_read parses itself. */
        long P = parse_allocs(r);
        struct tally t;
        memset(&t, 0, sizeof t);
        if (leaked) note(&t, K_LEAK, 0, "a normal run leaks");
        long runs = 0, absorbed = 0, oom = 0;
        for (long k = 0, prev = 0; k < (N - P < cap_r ? N - P : cap_r); k++) {
            long n = P + sample_position(k, N - P, cap_r);
            if (n <= prev) continue;
            prev = n;
            n_failed = 0;
            if (trace) fprintf(stderr, "trace: %s: failing allocation %ld\n", r->label, n);
            run(r, n, &o, &leaked, &got);
            runs++;
            char sample[300];
            snprintf(sample, sizeof sample, "status %d (normally %d): %.200s", o.status,
                     base.status, o.body ? o.body : "(no body)");
            if (n_failed == 0) { /* the request allocated less this time: fine */
                absorbed++;
            } else if (o.status == base.status &&
                       ((!o.body && !base.body) ||
                        (o.body && base.body && !strcmp(o.body, base.body)))) {
                absorbed++;
            } else if (is_clean_500(&o)) {
                oom++;
            } else if (o.status == 200 && base.status == 200 && strstr(r->label, "/v1/batch") &&
                       o.body && base.body && batch_items_ok(o.body, base.body)) {
                oom++; /* an operation's own 500 inside the batch */
            } else if (o.status != base.status) {
                note(&t, K_MISREPORTED, n, sample);
            } else if (o.status == 200) {
                /* Show where the bytes part: that names the member that went wrong. */
                size_t d = 0;
                const char *ob = o.body ? o.body : "", *bb = base.body ? base.body : "";
                while (ob[d] && ob[d] == bb[d]) d++;
                size_t from = d > 80 ? d - 80 : 0;
                snprintf(sample, sizeof sample, "bytes differ at %zu: got ...%.120s | normally ...%.80s",
                         d, ob + from, bb + d);
                note(&t, K_CORRUPT200, n, sample);
            } else {
                note(&t, K_DEGRADED, n, sample);
            }
            if (leaked) {
                snprintf(sample, sizeof sample, "%zu block(s) live", leaked);
                note(&t, K_LEAK, n, sample);
            }
            __real_free(o.body);
        }
        total_runs += runs;
        printf("%-58s P=%-4ld N=%-6ld runs=%-5ld same=%-5ld 500=%ld\n", r->label, P, N, runs, absorbed,
               oom);
        fflush(stdout);
        report(r, &t);
        __real_free(base.body);
    }
    for (int k = 0; k < K_COUNT; k++) printf("  %-12s %s\n", kind_name[k], kind_help[k]);
    printf("test_alloc_failure: %zu requests, %ld failure runs, %d findings, %d known\n", n_reqs,
           total_runs, n_findings, n_known);
    CHECK(n_findings == 0);
    TEST_MAIN_END();
}
