/* test_robustness.c — no input crashes, leaks or prints NaN.
 *
 * Takes every route's example request and feeds api_handle() hundreds of
 * deterministic mutations of it (MUTATIONS_PER_ROUTE each): numbers replaced by extremes (0, -0, 1e-320,
 * ±1e308, huge integers), values replaced by other types, keys dropped, arrays
 * emptied or grown, bytes flipped, bodies truncated. Every answer must be a
 * JSON document with an allowed status (200, 400, 422 — never 500), problem
 * answers must carry type/title/status/detail. (jansson cannot encode a NaN;
 * api_real() turns one into a numerical-failure problem, so a non-finite
 * result shows up here as a missing 200, never as bad JSON.) Runs under
 * ASan+UBSan in CI, which catches memory errors and undefined behaviour.
 */
#include <gsl/gsl_errno.h>
#include <stdint.h>
#include <string.h>

#include "api.h"
#include "mech/base/budget.h"
#include "run/routes.h"
#include "testlib.h"

/* Mutations per route (each also sent byte-damaged: about twice as many
 * requests). Sized so the whole run stays well inside CTest's timeout under
 * ASan with 40+ routes; each request gets a small step budget and deadline. */
enum { MUTATIONS_PER_ROUTE = 400 };

static uint64_t rng = 0x9E3779B97F4A7C15ull;
static uint64_t next(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return rng;
}

static const double extremes[] = {0.0, -0.0, 1e-320, -1e-320, 1e308, -1e308, 1e-15, 1 - 1e-16,
                                  1.0, -1.0, 2.0, 0.5, 1e15, 35.0, 700.0, 1e5, -7.0, 3.0};

static json_t *random_value(void)
{
    switch (next() % 7) {
    case 0: return json_real(extremes[next() % (sizeof extremes / sizeof extremes[0])]);
    case 1: return json_string("x");
    case 2: return json_null();
    case 3: return json_true();
    case 4: return json_array();
    case 5: return json_object();
    default: return json_pack("[f,f,f]", 1e308, -1e308, 0.0);
    }
}

/* Mutate one randomly chosen node of a JSON tree in place. */
static void mutate(json_t *j, int depth)
{
    if (json_is_object(j) && json_object_size(j)) {
        size_t pick = next() % json_object_size(j), i = 0;
        const char *k;
        json_t *v;
        json_object_foreach(j, k, v) {
            if (i++ != pick) continue;
            uint64_t r = next() % 10;
            if (r == 0) { json_object_del(j, k); return; }
            if (r == 1 || depth > 6 || !(json_is_object(v) || json_is_array(v)) ) {
                if (json_is_number(v) && r < 7)
                    json_object_set_new(j, k, json_real(extremes[next() % (sizeof extremes / sizeof extremes[0])]));
                else
                    json_object_set_new(j, k, random_value());
                return;
            }
            mutate(v, depth + 1);
            return;
        }
    } else if (json_is_array(j) && json_array_size(j)) {
        size_t idx = next() % json_array_size(j);
        json_t *v = json_array_get(j, idx);
        uint64_t r = next() % 10;
        if (r == 0) { json_array_remove(j, idx); return; }
        if (r == 1) { json_array_append(j, v); return; }
        if (json_is_object(v) || json_is_array(v)) mutate(v, depth + 1);
        else if (json_is_number(v) && r < 8)
            json_array_set_new(j, idx, json_real(extremes[next() % (sizeof extremes / sizeof extremes[0])]));
        else json_array_set_new(j, idx, random_value());
    }
}

static void run_one(const char *path, const char *body, size_t len)
{
    struct api_request req = {"POST", path, "application/json", body, len,
                              5000, mech_clock_seconds() + 2, NULL};
    struct api_response resp;
    api_handle(&req, &resp);
    int ok_status = resp.status == 200 || resp.status == 400 || resp.status == 422;
    if (!ok_status) fprintf(stderr, "status %d for %s body %.400s -> %.400s\n", resp.status, path, body, resp.body);
    CHECK(ok_status);
    json_t *j = resp.body ? json_loads(resp.body, 0, NULL) : NULL;
    CHECK(j != NULL);
    if (resp.status != 200 && j) {
        CHECK(json_is_string(json_object_get(j, "type")) && json_is_string(json_object_get(j, "title")) &&
              json_is_integer(json_object_get(j, "status")) && json_is_string(json_object_get(j, "detail")));
    }
    json_decref(j);
    api_response_free(&resp);
}

int main(void)
{
    gsl_set_error_handler_off();
    api_install_json_allocator(); /* process-wide, as GSL's handler */
    CHECK(api_init() == 0);
    for (size_t r = 0; r < api_route_count; r++) {
        if (!api_routes[r]->example) continue; /* GET resources take no body */
        const char *path = api_routes[r]->path;
        double t0 = mech_clock_seconds();
        json_t *ex = json_loads(api_routes[r]->example, JSON_DECODE_INT_AS_REAL, NULL);
        CHECK(ex != NULL);
        for (int n = 0; n < MUTATIONS_PER_ROUTE; n++) {
            json_t *m = json_deep_copy(ex);
            int rounds = 1 + (int)(next() % 3);
            for (int k = 0; k < rounds; k++) mutate(m, 0);
            char *s = json_dumps(m, JSON_COMPACT | JSON_REAL_PRECISION(17));
            run_one(path, s, strlen(s));
            /* Byte-level damage: flip a byte or truncate. */
            size_t len = strlen(s);
            if (len > 2) {
                if (next() % 2) s[next() % len] = (char)(next() & 0xff);
                run_one(path, s, next() % len);
            }
            free(s);
            json_decref(m);
        }
        json_decref(ex);
        printf("%-44s %7.2f s\n", path, mech_clock_seconds() - t0);
    }
    TEST_MAIN_END();
}
