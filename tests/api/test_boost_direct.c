/* test_boost_direct.c — the boost answered from bytes (api/run/boost_direct.c)
 * against the general pipeline, and against the Lorentz transformation.
 *
 * Same bytes: for varied plain requests (one 4-vector or lists of 1..3000;
 * components of every size from 1e-300 to 1e150, both signs, zeros and -0,
 * integers, exponents, 17-digit decimals; beta from 0 to 1 - 1e-15 in any
 * direction; whitespace of every kind between tokens; matrix and cost given
 * or not), api_boost_direct answers and its body is byte for byte the
 * answer of the general pipeline (parse, schema, handler, writer) for the
 * same bytes. Declines: every request the pipeline answers with an error
 * (|beta| >= 1, a component beyond 1e150, 100,001 vectors, a 3-vector,
 * an unknown or duplicate key, an escaped key, trailing bytes, a budget of
 * too few steps, a number that overflows) is declined, and so are plain
 * requests in other velocity forms. Values: the answer of a boost along x
 * against x0' = gamma (x0 - beta x1), x1' = gamma (x1 - beta x0) and the
 * invariant -x0^2 + |x|^2 computed by hand. Through api_handle() the
 * answer equals the general pipeline's too. */
#include <gsl/gsl_errno.h>
#include <jansson.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "api.h"
#include "run/api_init.h"
#include "run/api_run.h"
#include "run/boost_direct.h"
#include "json/json_read.h"
#include "mech/base/budget.h"
#include "testlib.h"

static size_t boost_ri;

static uint64_t rng = 0x9E3779B97F4A7C15u;
static uint64_t next_u64(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return rng;
}
static double uniform(void) { return (double)(next_u64() >> 11) * 0x1p-53; }

/* The general pipeline's answer to body (status in *status); malloc'd. */
static char *general_answer(const char *body, long max_steps, int *status)
{
    struct api_full_request full;
    memset(&full, 0, sizeof full);
    full.req.method = "POST";
    full.req.path = "/v1/relativity/boost";
    full.req.content_type = "application/json";
    full.req.body = body;
    full.req.body_len = strlen(body);
    full.req.max_steps = max_steps;
    full.req.deadline = mech_clock_seconds() + 60.0;
    full.max_samples = API_DEFAULT_MAX_SAMPLES;
    struct api_response resp;
    memset(&resp, 0, sizeof resp);
    json_error_t err;
    json_t *j = api_json_read(body, strlen(body), &err);
    if (!j) {
        *status = 400;
        return strdup("");
    }
    api_run_body_into(boost_ri, &full, j, &resp);
    *status = resp.status;
    char *b = strndup(resp.body ? resp.body : "", resp.body_len);
    api_response_free(&resp);
    return b;
}

/* The direct path's answer, or NULL when it declines. */
static char *direct_answer(const char *body, long max_steps)
{
    struct mech_budget budget = {max_steps, mech_clock_seconds() + 60.0, NULL};
    struct api_response resp;
    memset(&resp, 0, sizeof resp);
    if (!api_boost_direct(body, strlen(body), &budget, &resp)) return NULL;
    CHECK_EQ_INT(resp.status, 200);
    CHECK(resp.content_type && !strcmp(resp.content_type, "application/json"));
    CHECK(resp.body && strlen(resp.body) == resp.body_len);
    char *b = strndup(resp.body ? resp.body : "", resp.body_len);
    api_response_free(&resp);
    return b;
}

static int n_same, n_declined;

/* Both paths on body: the direct one must answer (want_direct) with the
 * general one's bytes, or decline. */
static void compare(const char *body, int want_direct, long max_steps)
{
    int st = 0;
    char *g = general_answer(body, max_steps, &st);
    char *d = direct_answer(body, max_steps);
    if (want_direct) {
        CHECK(d != NULL);
        CHECK_EQ_INT(st, 200);
        if (d && g && strcmp(d, g)) {
            CHECK(!"direct answer differs from the pipeline's");
            fprintf(stderr, "request %.300s\n direct  %.300s\n general %.300s\n", body, d, g);
        } else if (d) {
            n_same++;
        }
    } else {
        if (d) fprintf(stderr, "answered, expected a decline: %.300s\n", body);
        CHECK(d == NULL);
        n_declined++;
    }
    free(g);
    free(d);
}

/* Whitespace between tokens: none, or a random run of jansson's four. */
static void put_space(char **o, int mode)
{
    if (!mode || next_u64() % 3) return;
    static const char ws[] = " \t\n\r";
    int k = 1 + (int)(next_u64() % 3);
    while (k--) *(*o)++ = ws[next_u64() % 4];
}

/* A component of random kind within the schema's bounds. */
static double component(void)
{
    switch (next_u64() % 9) {
    case 0: return 0.0;
    case 1: return -0.0;
    case 2: return (double)((int64_t)(next_u64() % 2001) - 1000);
    case 3: return (uniform() - 0.5) * 8.0;
    case 4: return ldexp(uniform() + 0.5, (int)(next_u64() % 400) - 200);
    case 5: return -ldexp(uniform() + 0.5, (int)(next_u64() % 900) - 990); /* to ~1e-298 */
    case 6: return 1e150;
    case 7: return -1e150 * uniform();
    default: return (next_u64() % 2 ? 1 : -1) * pow(10.0, (double)(next_u64() % 300) - 150.0);
    }
}

/* A number's text: %.17g, %.3g, an integer, or an exponent form. */
static int put_number(char *o, double x)
{
    switch (next_u64() % 4) {
    case 0: return sprintf(o, "%.17g", x);
    case 1: return sprintf(o, "%.3g", x);
    case 2: return sprintf(o, "%.17E", x);
    default: return sprintf(o, "%.16e", x);
    }
}

static char *random_request(size_t n, int single, int ws)
{
    char *b = malloc(n * 4 * 40 + 1024), *o = b;
    o += sprintf(o, "{");
    put_space(&o, ws);
    int vec_first = (int)(next_u64() % 2);
    const int matrix = (int)(next_u64() % 3), cost = (int)(next_u64() % 3);
    double beta[3] = {0, 0, 0};
    double speed = next_u64() % 5 == 0 ? 1.0 - pow(10.0, -1.0 - (double)(next_u64() % 15))
                                        : uniform() * 0.99;
    int axis = (int)(next_u64() % 4);
    if (axis < 3) beta[axis] = (next_u64() % 2 ? speed : -speed);
    else {
        double u[3] = {uniform() - 0.5, uniform() - 0.5, uniform() - 0.5};
        double un = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) + 1e-3;
        for (int k = 0; k < 3; k++) beta[k] = u[k] / un * speed * 0.999;
    }
    for (int part = 0; part < 2; part++) {
        if (part) {
            *o++ = ',';
            put_space(&o, ws);
        }
        if ((part == 0) == vec_first) {
            o += sprintf(o, "\"vectors\"");
            put_space(&o, ws);
            *o++ = ':';
            put_space(&o, ws);
            if (!single) *o++ = '[';
            for (size_t i = 0; i < n; i++) {
                if (i) *o++ = ',';
                put_space(&o, ws);
                *o++ = '[';
                for (int k = 0; k < 4; k++) {
                    if (k) *o++ = ',';
                    put_space(&o, ws);
                    o += put_number(o, component());
                    put_space(&o, ws);
                }
                *o++ = ']';
            }
            put_space(&o, ws);
            if (!single) *o++ = ']';
        } else {
            o += sprintf(o, "\"velocity\":");
            put_space(&o, ws);
            o += sprintf(o, "{\"beta\"");
            put_space(&o, ws);
            o += sprintf(o, ":[%.17g,", beta[0]);
            put_space(&o, ws);
            o += sprintf(o, "%.17g,%.17g]", beta[1], beta[2]);
            put_space(&o, ws);
            *o++ = '}';
        }
    }
    if (matrix) o += sprintf(o, ",\"matrix\":%s", matrix == 1 ? "true" : "false");
    if (cost) o += sprintf(o, ",\"cost\":%s", cost == 1 ? "true" : "false");
    put_space(&o, ws);
    *o++ = '}';
    put_space(&o, ws);
    *o = '\0';
    return b;
}

static void test_same_bytes(void)
{
    for (int t = 0; t < 400; t++) {
        const int single = t % 4 == 0;
        size_t n = single ? 1 : 1 + (size_t)(next_u64() % (t % 50 == 1 ? 3000 : 20));
        char *b = random_request(n, single, t % 3);
        compare(b, 1, 10000000);
        free(b);
    }
    /* the smallest shapes and the spelling of the catalog's example */
    compare("{\"vectors\":[1,0,0,0],\"velocity\":{\"beta\":[0,0,0]}}", 1, 1);
    compare("{\"vectors\": [[1, 0, 0, 0], [1, 1, 0, 0]], \"velocity\": {\"beta\": [0.6, 0, 0]}}", 1,
            2);
    compare("{\"velocity\":{\"beta\":[0.6,0.0,0.0]},\"vectors\":[[1e150,-1e150,0,0]],"
            "\"matrix\":true}",
            1, 100);
    compare(" \n{\"vectors\":[[-0.0,-0,0e5,-0E-7]],\"velocity\":{\"beta\":[-0.0,0.5,0]}}\r\n", 1, 1);
}

static void test_declines(void)
{
    const char *bad[] = {
        "{\"vectors\":[1,0,0,0],\"velocity\":{\"beta\":[1,0,0]}}",          /* |beta| = 1 */
        "{\"vectors\":[1,0,0,0],\"velocity\":{\"beta\":[0.8,0.6,0.1]}}",    /* |beta| > 1 */
        "{\"vectors\":[1.000000000000001e150,0,0,0],\"velocity\":{\"beta\":[0.5,0,0]}}",
        "{\"vectors\":[[1,0,0,-2e150]],\"velocity\":{\"beta\":[0.5,0,0]}}",
        "{\"vectors\":[1,0,0],\"velocity\":{\"beta\":[0.5,0,0]}}",
        "{\"vectors\":[[1,0,0,0,0]],\"velocity\":{\"beta\":[0.5,0,0]}}",
        "{\"vectors\":[],\"velocity\":{\"beta\":[0.5,0,0]}}",
        "{\"vectors\":[[1,0,0,0]],\"velocity\":{\"beta\":[0.5,0]}}",
        "{\"vectors\":[[1,0,0,0]],\"velocity\":{\"beta\":[0.5,0,0]},\"extra\":1}",
        "{\"vectors\":[[1,0,0,0]],\"velocity\":{\"beta\":[0.5,0,0]},\"vectors\":[[1,0,0,0]]}",
        "{\"vect\\u006frs\":[[1,0,0,0]],\"velocity\":{\"beta\":[0.5,0,0]}}",
        "{\"vectors\":[[1,0,0,0]],\"velocity\":{\"beta\":[0.5,0,0]}} x",
        "{\"vectors\":[[1,0,0,0]],\"velocity\":{\"beta\":[0.5,0,0]}",
        "{\"vectors\":[[1e999,0,0,0]],\"velocity\":{\"beta\":[0.5,0,0]}}",
        "{\"vectors\":[[01,0,0,0]],\"velocity\":{\"beta\":[0.5,0,0]}}",
        "{\"vectors\":[[1.,0,0,0]],\"velocity\":{\"beta\":[0.5,0,0]}}",
        "{\"vectors\":[[\"1\",0,0,0]],\"velocity\":{\"beta\":[0.5,0,0]}}",
        "{\"vectors\":[[1,0,0,0]],\"velocity\":{\"beta\":[0.5,0,0]},\"matrix\":1}",
        "{\"vectors\":[[1,0,0,0]],\"velocity\":{\"beta\":[0.5,0,0]},\"cost\":null}",
        "{\"vectors\":[[1,0,0,0]]}",
        "{\"velocity\":{\"beta\":[0.5,0,0]}}",
        "[1,0,0,0]",
        /* other velocity forms: the pipeline answers them */
        "{\"vectors\":[[1,0,0,0]],\"velocity\":{\"gamma\":2,\"direction\":[1,0,0]}}",
        "{\"vectors\":[[1,0,0,0]],\"velocity\":{\"rapidity\":1,\"direction\":[0,1,0]}}",
        "{\"vectors\":[[1,0,0,0]],\"velocity\":{\"beta\":[0.5,0,0],\"direction\":[1,0,0]}}",
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
        compare(bad[i], 0, 100);
    /* two vectors with a budget of one step: the pipeline says so */
    compare("{\"vectors\":[[1,0,0,0],[2,0,0,0]],\"velocity\":{\"beta\":[0.5,0,0]}}", 0, 1);
    /* 100,001 vectors: over the schema's maximum */
    size_t n = 100001;
    char *b = malloc(n * 10 + 100), *o = b;
    o += sprintf(o, "{\"vectors\":[");
    for (size_t i = 0; i < n; i++)
        o += sprintf(o, "%s[1,0,0,0]", i ? "," : "");
    sprintf(o, "],\"velocity\":{\"beta\":[0.5,0,0]}}");
    compare(b, 0, 10000000);
    /* 100,000 are answered */
    o = b + strlen("{\"vectors\":[") + 9 * 100000 + 99999;
    sprintf(o, "],\"velocity\":{\"beta\":[0.5,0,0]}}");
    compare(b, 1, 10000000);
    free(b);
}

/* A boost along x against the closed form, read back from the text. */
static void test_values(void)
{
    const double beta = 0.6, g = 1.25;
    const char *body = "{\"vectors\":[[2,1,3,-4],[1,1,0,0]],\"velocity\":{\"beta\":[0.6,0,0]}}";
    char *d = direct_answer(body, 100);
    CHECK(d != NULL);
    json_t *j = d ? json_loads(d, 0, NULL) : NULL;
    CHECK(j != NULL);
    const double x[2][4] = {{2, 1, 3, -4}, {1, 1, 0, 0}};
    for (int i = 0; j && i < 2; i++) {
        json_t *v = json_array_get(json_object_get(j, "vectors"), (size_t)i);
        CHECK_CLOSE(json_real_value(json_array_get(v, 0)), g * (x[i][0] - beta * x[i][1]), 1e-15, 0);
        CHECK_CLOSE(json_real_value(json_array_get(v, 1)), g * (x[i][1] - beta * x[i][0]), 1e-15, 0);
        CHECK(json_real_value(json_array_get(v, 2)) == x[i][2]);
        CHECK(json_real_value(json_array_get(v, 3)) == x[i][3]);
        const double inv = -x[i][0] * x[i][0] + x[i][1] * x[i][1] + x[i][2] * x[i][2] +
                           x[i][3] * x[i][3];
        CHECK(json_real_value(json_array_get(json_object_get(j, "invariants_before"), (size_t)i)) ==
              inv);
        CHECK_CLOSE(json_real_value(json_array_get(json_object_get(j, "invariants_after"), (size_t)i)),
                    inv, 1e-15, 1e-15);
    }
    CHECK_CLOSE(json_real_value(json_object_get(j, "gamma")), g, 1e-16, 0);
    json_decref(j);
    free(d);
}

/* Through api_handle (the route's hook): the same bytes as the pipeline. */
static void test_through_handle(void)
{
    const char *body = "{\"vectors\":[[1,0.5,0.25,-0.125]],\"velocity\":{\"beta\":[0.6,0,0]},"
                       "\"matrix\":true}";
    struct api_request req = {"POST", "/v1/relativity/boost", "application/json", body,
                              strlen(body), 1000, mech_clock_seconds() + 60, NULL};
    struct api_response resp;
    memset(&resp, 0, sizeof resp);
    api_handle(&req, &resp);
    int st = 0;
    char *g = general_answer(body, 1000, &st);
    CHECK_EQ_INT(resp.status, 200);
    CHECK(resp.body && g && !strcmp(resp.body, g));
    api_response_free(&resp);
    free(g);
}

int main(void)
{
    gsl_set_error_handler_off();
    api_install_json_allocator();
    CHECK(api_init() == 0);
    long ri = api_route_index("/v1/relativity/boost");
    CHECK(ri >= 0);
    if (ri < 0) TEST_MAIN_END();
    boost_ri = (size_t)ri;
    test_same_bytes();
    test_declines();
    test_values();
    test_through_handle();
    printf("%d requests answered directly with the pipeline's bytes, %d declined\n", n_same,
           n_declined);
    TEST_MAIN_END();
}
