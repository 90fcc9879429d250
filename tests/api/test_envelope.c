/* test_envelope.c — every operation takes the envelope keys (docs/design.md:
 * every operation, with or without an integrator, takes the same envelope keys).
 * The test walks the whole route table, so a route added later is covered
 * without touching this file: each POST route's catalog example with
 * "cost": false answers 200 with no "cost" member anywhere; with "cost": true
 * or without it, the routes that report cost carry cost.cpu_seconds. The same
 * holds for every operation as a /v1/batch item, and "cost": false on the
 * batch itself reaches its items. The catalog and OpenAPI document describe
 * the envelope once, and every operation's schema lists it. */
#include <gsl/gsl_errno.h>
#include <string.h>

#include "api.h"
#include "catalog/catalog.h"
#include "mech/base/budget.h"
#include "run/routes.h"
#include "testlib.h"

static json_t *call(const char *method, const char *path, const json_t *body, int *status)
{
    char *text = body ? json_dumps(body, JSON_COMPACT | JSON_REAL_PRECISION(17)) : NULL;
    struct api_request req = {method, path, "application/json", text, text ? strlen(text) : 0,
                              10000000, mech_clock_seconds() + 120, NULL};
    struct api_response resp;
    api_handle(&req, &resp);
    *status = resp.status;
    json_t *j = resp.body ? json_loads(resp.body, JSON_DECODE_INT_AS_REAL, NULL) : NULL;
    if (resp.status != 200)
        fprintf(stderr, "%s %s -> %d: %.400s\n", method, path, resp.status,
                resp.body ? resp.body : "");
    api_response_free(&resp);
    free(text);
    return j;
}

/* Whether a member named "cost" occurs anywhere in j. */
static int has_cost(const json_t *j)
{
    if (json_is_object(j)) {
        if (json_object_get(j, "cost")) return 1;
        const char *k;
        json_t *v;
        json_object_foreach((json_t *)j, k, v) if (has_cost(v)) return 1;
    } else if (json_is_array(j)) {
        size_t i;
        json_t *v;
        json_array_foreach((json_t *)j, i, v) if (has_cost(v)) return 1;
    }
    return 0;
}

/* The route's example with "cost" set to `cost` (-1: left out); new reference. */
static json_t *example_with(const struct api_route *r, int cost)
{
    json_t *ex = json_loads(r->example, JSON_DECODE_INT_AS_REAL, NULL);
    CHECK(json_is_object(ex));
    if (!ex) return json_object();
    if (cost >= 0) json_object_set_new(ex, "cost", json_boolean(cost));
    else json_object_del(ex, "cost");
    return ex;
}

static int reports_cpu(const json_t *answer)
{
    return json_is_number(json_object_get(json_object_get(answer, "cost"), "cpu_seconds")) &&
           json_number_value(json_object_get(json_object_get(answer, "cost"), "cpu_seconds")) >= 0;
}

static int nested_only(const char *path)
{
    return !strcmp(path, "/v1/batch") || !strcmp(path, "/v1/check");
}

int main(void)
{
    gsl_set_error_handler_off();
    api_install_json_allocator(); /* process-wide, as GSL's handler */
    CHECK(api_init() == 0);
    int st;

    /* The envelope, described once in the catalog and in OpenAPI. */
    json_t *cat = call("GET", "/v1", NULL, &st);
    CHECK_EQ_INT(st, 200);
    const json_t *env = json_object_get(json_object_get(cat, "envelope"), "properties");
    const json_t *env_cost = json_object_get(env, "cost");
    CHECK(json_is_object(env_cost));
    CHECK(!strcmp(json_string_value(json_object_get(env_cost, "type")) ?: "", "boolean"));
    json_t *oa = call("GET", "/v1/openapi.json", NULL, &st);
    CHECK_EQ_INT(st, 200);
    const json_t *oa_env = json_object_get(
        json_object_get(json_object_get(json_object_get(oa, "components"), "schemas"), "Envelope"),
        "properties");
    CHECK(json_equal((json_t *)oa_env, (json_t *)env));

    json_t *batch_items = json_array(), *batch_plain = json_array();
    size_t n_post = 0;
    for (size_t i = 0; i < api_route_count; i++) {
        const struct api_route *r = api_routes[i];
        if (strcmp(r->method, "POST")) continue; /* a GET resource takes no body */
        n_post++;
        /* The operation's own schema, as served, lists the envelope key. */
        const json_t *schema = api_route_schema(i);
        CHECK(json_equal(json_object_get(json_object_get(schema, "properties"), "cost"),
                         (json_t *)env_cost));

        json_t *ex = example_with(r, 0);
        json_t *a = call("POST", r->path, ex, &st);
        if (st != 200 || has_cost(a)) fprintf(stderr, "cost false: %s\n", r->path);
        CHECK_EQ_INT(st, 200);
        CHECK(a && !has_cost(a));
        json_decref(a);
        if (!nested_only(r->path)) {
            json_array_append_new(batch_items,
                                  json_pack("{s:s,s:O}", "operation", r->path, "request", ex));
            json_t *plain = example_with(r, -1);
            json_array_append_new(batch_plain,
                                  json_pack("{s:s,s:o}", "operation", r->path, "request", plain));
        }
        json_decref(ex);

        for (int cost = -1; cost <= 1; cost += 2) { /* absent, then true */
            ex = example_with(r, cost);
            a = call("POST", r->path, ex, &st);
            CHECK_EQ_INT(st, 200);
            if (r->reports_cost) {
                if (!reports_cpu(a)) fprintf(stderr, "no cost: %s (cost %d)\n", r->path, cost);
                CHECK(reports_cpu(a));
            }
            json_decref(a);
            json_decref(ex);
        }
    }
    CHECK(n_post >= 30);

    /* Every operation as a batch item with "cost": false, and the batch itself too. */
    json_t *b = json_pack("{s:o,s:b}", "operations", batch_items, "cost", 0);
    json_t *a = call("POST", "/v1/batch", b, &st);
    CHECK_EQ_INT(st, 200);
    const json_t *results = json_object_get(a, "results");
    CHECK_EQ_INT(json_array_size(results), n_post - 2);
    size_t k;
    json_t *res;
    json_array_foreach(results, k, res) {
        CHECK_EQ_INT((int)json_number_value(json_object_get(res, "status")), 200);
        if ((int)json_number_value(json_object_get(res, "status")) != 200)
            fprintf(stderr, "batch item %zu: %.300s\n", k,
                    json_dumps(res, JSON_COMPACT) ?: "");
    }
    CHECK(!has_cost(a));
    json_decref(a);
    json_decref(b);

    /* Items without the key: "cost": false on the batch reaches them; without
     * it, the items that integrate report their cost. */
    b = json_pack("{s:O,s:b}", "operations", batch_plain, "cost", 0);
    a = call("POST", "/v1/batch", b, &st);
    CHECK_EQ_INT(st, 200);
    CHECK(!has_cost(a));
    json_decref(a);
    json_decref(b);
    b = json_pack("{s:O}", "operations", batch_plain);
    a = call("POST", "/v1/batch", b, &st);
    CHECK_EQ_INT(st, 200);
    results = json_object_get(a, "results");
    size_t with_cost = 0, want_cost = 0;
    for (size_t i = 0, item = 0; i < api_route_count; i++) {
        const struct api_route *r = api_routes[i];
        if (strcmp(r->method, "POST") || nested_only(r->path)) continue;
        const json_t *body = json_object_get(json_array_get(results, item++), "body");
        want_cost += r->reports_cost != 0;
        with_cost += r->reports_cost && reports_cpu(body);
    }
    CHECK(want_cost >= 10);
    CHECK_EQ_INT(with_cost, want_cost);
    json_decref(a);
    json_decref(b);
    json_decref(batch_plain);

    json_decref(cat);
    json_decref(oa);
    TEST_MAIN_END();
}
