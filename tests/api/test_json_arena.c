/* test_json_arena.c — the per-request jansson arena (api/json/json_arena.c) and
 * operation requests that run on it.
 *
 * The arena itself: nothing is handed out outside a scope; allocations are
 * 16-byte aligned, disjoint and owned; a full arena answers NULL (the caller
 * falls back to malloc) after handing out no more than its size; nested
 * scopes reclaim only at the outermost end; each thread has its own arena.
 * Through api_handle(): a 2,000-vector boost (a tree some 20 times larger
 * than the arena, so it spills to malloc) and a one-vector boost answered
 * repeatedly on the same thread give the Lorentz transformation's closed form,
 * and identical requests give identical bytes (reuse after reclaim corrupts
 * nothing); a request on a fresh thread gives it an arena and closes its
 * scope (so the API does run on the arena). Under AddressSanitizer the arena is poisoned outside live
 * allocations, so any tree outliving its request fails this and every other
 * API test of the sanitizer run. */
#include <gsl/gsl_errno.h>
#include <jansson.h>
#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "api.h"
#include "json/json_arena.h"
#include "mech/base/budget.h"
#include "testlib.h"

static void test_outside_scope(void)
{
    CHECK(api_json_arena_alloc(16) == NULL);
    CHECK(!api_json_arena_owns(NULL));
    api_json_arena_end(); /* unbalanced: ignored */
    CHECK(api_json_arena_alloc(16) == NULL);
}

static void test_alloc_and_fill(void)
{
    api_json_arena_begin();
    char *a = api_json_arena_alloc(1), *b = api_json_arena_alloc(24), *c = api_json_arena_alloc(0);
    CHECK(a && b && c);
    if (!a || !b || !c) {
        api_json_arena_end();
        return;
    }
    CHECK(((uintptr_t)a % 16) == 0 && ((uintptr_t)b % 16) == 0 && ((uintptr_t)c % 16) == 0);
    CHECK(b >= a + 1 && c >= b + 24); /* disjoint, in order */
    CHECK(api_json_arena_owns(a) && api_json_arena_owns(b + 23) && api_json_arena_owns(c));
    memset(a, 0x5a, 1);
    memset(b, 0xa5, 24);
    CHECK(a[0] == 0x5a && b[0] == (char)0xa5 && b[23] == (char)0xa5);
    char *m = malloc(32);
    CHECK(m && !api_json_arena_owns(m));
    free(m);
    CHECK(api_json_arena_alloc(API_JSON_ARENA_BYTES + 1) == NULL);

    /* Fill it: everything handed out lies in the arena, none of it twice. */
    size_t handed = 64; /* a, b, c above: 16 + 32 + 16 after rounding up */
    long n = 0;
    char *last = c, *p;
    while ((p = api_json_arena_alloc(100)) != NULL) {
        CHECK(p >= last + 16 && ((uintptr_t)p % 16) == 0 && api_json_arena_owns(p + 99));
        memset(p, (int)(n & 0xff), 100);
        last = p;
        handed += 112;
        n++;
    }
    CHECK(handed <= API_JSON_ARENA_BYTES);
    CHECK(handed + 112 > API_JSON_ARENA_BYTES); /* stopped only when full */
    CHECK((api_json_arena_alloc(1) != NULL) == (API_JSON_ARENA_BYTES - handed >= 16));
    CHECK(n > 500);
    api_json_arena_end();
    CHECK(api_json_arena_alloc(16) == NULL);
    CHECK(api_json_arena_owns(a)); /* still the thread's arena memory: never free()d */

    /* A new scope starts from the beginning again. */
    api_json_arena_begin();
    char *again = api_json_arena_alloc(8);
    CHECK(again == a);
    api_json_arena_end();
}

static void test_nesting(void)
{
    api_json_arena_begin();
    char *a = api_json_arena_alloc(32);
    api_json_arena_begin();
    char *b = api_json_arena_alloc(32);
    api_json_arena_end(); /* inner end: nothing reclaimed */
    char *c = api_json_arena_alloc(32);
    CHECK(a && b && c && b == a + 32 && c == b + 32);
    api_json_arena_end();
    api_json_arena_begin();
    CHECK(api_json_arena_alloc(32) == a);
    api_json_arena_end();
}

struct other {
    const void *mine; /* from the main thread's arena */
    int owns_mine, got, owns_got, distinct;
};

static void *other_thread(void *arg)
{
    struct other *o = arg;
    o->owns_mine = api_json_arena_owns(o->mine);
    api_json_arena_begin();
    void *p = api_json_arena_alloc(64);
    o->got = p != NULL;
    o->owns_got = api_json_arena_owns(p);
    o->distinct = p != o->mine;
    api_json_arena_end();
    return NULL; /* the thread's arena is freed at exit (LeakSanitizer checks) */
}

static void test_threads(void)
{
    api_json_arena_begin();
    struct other o = {api_json_arena_alloc(64), -1, 0, 0, 0};
    pthread_t t;
    CHECK(pthread_create(&t, NULL, other_thread, &o) == 0);
    pthread_join(t, NULL);
    CHECK(o.mine && o.owns_mine == 0);
    CHECK(o.got && o.owns_got && o.distinct);
    api_json_arena_end();
}

/* ---- through the API -------------------------------------------------------- */

static char *boost_request(int n, double beta)
{
    size_t cap = (size_t)n * 96 + 128, o = 0;
    char *s = malloc(cap);
    if (!s) return NULL;
    o += (size_t)snprintf(s, cap, "{\"vectors\":[");
    for (int i = 0; i < n; i++)
        o += (size_t)snprintf(s + o, cap - o, "%s[%.17g,%.17g,%.17g,-0.125]", i ? "," : "",
                              1.0 + i, 0.5 * i - 3.0, 0.25 * (i % 7));
    /* the rapidity form: the beta form of a boost is answered without
     * trees (api/run/boost_direct.c), and these requests are here for the trees */
    snprintf(s + o, cap - o, "],\"velocity\":{\"rapidity\":%.17g,\"direction\":[1,0,0]}}",
             atanh(beta));
    return s;
}

static int post(const char *path, const char *body, struct api_response *resp)
{
    struct api_request req = {"POST", path, "application/json", body, strlen(body), 1000000,
                              mech_clock_seconds() + 60.0, NULL};
    api_handle(&req, resp);
    return resp->status;
}

/* The answer's vectors against t' = g (t - b x), x' = g (x - b t), y, z kept. */
static void check_boost(int n, double beta)
{
    char *body = boost_request(n, beta);
    CHECK(body != NULL);
    if (!body) return;
    struct api_response resp;
    CHECK_EQ_INT(post("/v1/relativity/boost", body, &resp), 200);
    json_t *a = resp.body ? json_loads(resp.body, 0, NULL) : NULL;
    json_t *v = json_object_get(a, "vectors");
    CHECK(json_is_array(v) && (int)json_array_size(v) == n);
    double g = 1.0 / sqrt((1.0 - beta) * (1.0 + beta)); /* no cancellation in 1 - b^2 */
    int bad = 0;
    for (int i = 0; json_is_array(v) && i < n && i < (int)json_array_size(v); i++) {
        json_t *e = json_array_get(v, (size_t)i);
        double t = 1.0 + i, x = 0.5 * i - 3.0, y = 0.25 * (i % 7), z = -0.125;
        double want[4] = {g * (t - beta * x), g * (x - beta * t), y, z};
        for (int k = 0; k < 4; k++) {
            double got = json_real_value(json_array_get(e, (size_t)k));
            double scale = fabs(g) * (fabs(t) + fabs(x)) + 1.0;
            if (!(fabs(got - want[k]) <= 1e-15 * scale)) bad++;
        }
    }
    CHECK_EQ_INT(bad, 0);
    json_decref(a);
    api_response_free(&resp);
    free(body);
}

/* A fresh thread has no arena until an operation request opens a scope:
 * afterwards it has one, and the scope is closed (the API really runs on the
 * arena, so the sanitizer run's poisoning covers every API test). */
struct fresh {
    int before, after_base, after_closed, status;
};

static void *fresh_thread(void *arg)
{
    struct fresh *f = arg;
    f->before = api_json_arena_tls.base == NULL;
    struct api_response resp;
    f->status = post("/v1/relativity/boost",
                     "{\"vectors\":[1.0,0.5,0.25,-0.125],\"velocity\":{\"gamma\":1.25,"
                     "\"direction\":[1,0,0]}}",
                     &resp);
    api_response_free(&resp);
    f->after_base = api_json_arena_tls.base != NULL;
    f->after_closed = api_json_arena_tls.depth == 0 && api_json_arena_alloc(16) == NULL;
    return NULL;
}

static void test_api_uses_arena(void)
{
    struct fresh f = {0, 0, 0, 0};
    pthread_t t;
    CHECK(pthread_create(&t, NULL, fresh_thread, &f) == 0);
    pthread_join(t, NULL);
    CHECK(f.before);
    CHECK_EQ_INT(f.status, 200);
    CHECK(f.after_base);
    CHECK(f.after_closed);
}

static void test_through_api(void)
{
    check_boost(2000, 0.6); /* tree far larger than the arena: spills to malloc */
    check_boost(1, -0.999);
    /* The same request again and again on one thread: identical bytes. */
    const char *one =
        "{\"vectors\":[1.0,0.5,0.25,-0.125],\"velocity\":{\"gamma\":1.25,\"direction\":[1,0,0]}}";
    struct api_response first;
    CHECK_EQ_INT(post("/v1/relativity/boost", one, &first), 200);
    int differ = 0;
    for (int i = 0; i < 200; i++) {
        struct api_response again;
        post("/v1/relativity/boost", i % 2 ? one : "{\"vectors\":[1,2,3,4],\"velocity\":{\"beta\":[0,0.5,0]}}",
             &again);
        if (i % 2 && (again.body_len != first.body_len || memcmp(again.body, first.body, first.body_len)))
            differ++;
        api_response_free(&again);
    }
    CHECK_EQ_INT(differ, 0);
    /* A malformed body and a validation error inside a scope, then a good one. */
    struct api_response e1, e2;
    CHECK_EQ_INT(post("/v1/relativity/boost", "{\"vectors\":[1,2,3", &e1), 400);
    CHECK_EQ_INT(post("/v1/relativity/boost", "{\"vectors\":\"no\",\"velocity\":{}}", &e2), 422);
    api_response_free(&e1);
    api_response_free(&e2);
    check_boost(3, 0.25);
    api_response_free(&first);
}

int main(void)
{
    gsl_set_error_handler_off();
    api_install_json_allocator(); /* process-wide, as GSL's handler */
    CHECK(api_init() == 0);
    test_outside_scope();
    test_alloc_and_fill();
    test_nesting();
    test_threads();
    test_api_uses_arena();
    test_through_api();
    TEST_MAIN_END();
}
