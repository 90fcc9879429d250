/* test_openapi_doc.c — api/catalog/catalog.c on a small route table of its own: the
 * OpenAPI document takes each 200 answer's schema from the route's
 * response_schema (any JSON object when it has none), and both documents
 * print numbers as written: integers as integers, reals in their shortest
 * round-trip form. The table here replaces api/run/routes.c's (api/catalog/catalog.c reads only
 * api_routes, api_route_count and api_envelope_properties), so the test does
 * not depend on which operations describe their answers today. */
#include <gsl/gsl_errno.h>
#include <string.h>

#include "catalog/catalog.h"
#include "run/routes.h"
#include "testlib.h"

static json_t *demo_fn(struct api_call *c, const json_t *body)
{
    (void)c;
    (void)body;
    return NULL;
}

#define DEMO_SCHEMA                                                                        \
    "{\"type\":\"object\",\"properties\":{\"n\":{\"type\":\"integer\",\"minimum\":1,"      \
    "\"maximum\":1e6,\"default\":3},\"x\":{\"type\":\"number\",\"default\":0.1,"          \
    "\"maximum\":3.141592653589793},\"v\":{\"type\":\"array\",\"minItems\":3,"            \
    "\"maxItems\":3,\"items\":{\"type\":\"number\"}}}}"
#define DEMO_ANSWER                                                                        \
    "{\"type\":\"object\",\"required\":[\"y\"],\"properties\":{\"y\":{\"type\":\"number\"," \
    "\"minimum\":0},\"count\":{\"type\":\"integer\",\"maximum\":1e15}}}"

static const struct api_route described = {
    "POST", "/v1/demo/described", "A demo operation that describes its answer.",
    "Demo.", DEMO_SCHEMA, "{\"n\":7,\"x\":0.1,\"v\":[1,2.5,-3e-20]}", demo_fn, 1, 1,
    DEMO_ANSWER};
static const struct api_route undescribed = {
    "POST", "/v1/demo/undescribed", "A demo operation that does not describe its answer.",
    "Demo.", DEMO_SCHEMA, "{\"n\":7}", demo_fn, 0, 1, NULL};
static const struct api_route resource = {
    "GET", "/v1/demo/resource", "A demo read-only resource.", "Demo.", NULL, NULL, demo_fn, 0,
    0, "{\"type\":\"object\",\"properties\":{\"count\":{\"type\":\"integer\"}}}"};

const struct api_route *const api_routes[] = {&described, &undescribed, &resource};
const size_t api_route_count = 3;
const char api_envelope_properties[] = "{\"cost\":{\"type\":\"boolean\",\"default\":true}}";

/* JSON equality where numbers compare by value (the documents print an
 * integral real as an integer: 1e15 as 1000000000000000). */
static int same_json(const json_t *a, const json_t *b)
{
    if (json_is_number(a) && json_is_number(b)) return json_number_value(a) == json_number_value(b);
    if (!a || !b || json_typeof(a) != json_typeof(b)) return 0;
    if (json_is_object(a)) {
        if (json_object_size(a) != json_object_size(b)) return 0;
        const char *k;
        json_t *v;
        json_object_foreach((json_t *)a, k, v) if (!same_json(v, json_object_get(b, k))) return 0;
        return 1;
    }
    if (json_is_array(a)) {
        if (json_array_size(a) != json_array_size(b)) return 0;
        for (size_t i = 0; i < json_array_size(a); i++)
            if (!same_json(json_array_get(a, i), json_array_get(b, i))) return 0;
        return 1;
    }
    return json_equal((json_t *)a, (json_t *)b);
}

/* doc[path][method].responses[status].content[media].schema, or NULL. */
static json_t *response_schema_at(json_t *doc, const char *path, const char *method,
                                  const char *status, const char *media)
{
    json_t *op = json_object_get(json_object_get(json_object_get(doc, "paths"), path), method);
    json_t *resp = json_object_get(json_object_get(op, "responses"), status);
    return json_object_get(json_object_get(json_object_get(resp, "content"), media), "schema");
}

int main(void)
{
    gsl_set_error_handler_off();
    /* Parsed as api/run/api_init.c parses them: as written. */
    json_t *req[3] = {json_loads(DEMO_SCHEMA, 0, NULL), json_loads(DEMO_SCHEMA, 0, NULL), NULL};
    json_t *ans[3] = {json_loads(DEMO_ANSWER, 0, NULL), NULL,
                      json_loads(resource.response_schema, 0, NULL)};
    CHECK(req[0] && req[1] && ans[0] && ans[2]);
    char err[200] = "";
    CHECK(api_catalog_init((const json_t *const *)req, (const json_t *const *)ans, err,
                           sizeof err) == 0);

    json_t *oa = json_loads(api_openapi_text(), 0, NULL);
    json_t *cat = json_loads(api_catalog_text(), 0, NULL);
    CHECK(oa && cat);

    /* responses.200: the route's answer schema, on the POST and on its GET form. */
    json_t *want = json_loads(DEMO_ANSWER, 0, NULL);
    CHECK(same_json(response_schema_at(oa, "/v1/demo/described", "post", "200",
                                        "application/json"), want));
    CHECK(same_json(response_schema_at(oa, "/v1/demo/described", "get", "200",
                                        "application/json"), want));
    json_t *any = json_pack("{s:s}", "type", "object");
    CHECK(same_json(response_schema_at(oa, "/v1/demo/undescribed", "post", "200",
                                        "application/json"), any));
    CHECK(same_json(response_schema_at(oa, "/v1/demo/resource", "get", "200",
                                        "application/json"), ans[2]));
    /* The catalog lists the answer schema beside the request schema. */
    json_t *op0 = json_array_get(json_object_get(cat, "operations"), 0);
    CHECK(same_json(json_object_get(op0, "response_schema"), want));
    CHECK(json_object_get(json_array_get(json_object_get(cat, "operations"), 1),
                          "response_schema") == NULL);
    json_decref(any);
    json_decref(want);

    /* /v1 paths may answer 401 (bearer token); the 401 is a problem. */
    json_t *problem_ref = json_pack("{s:s}", "$ref", "#/components/schemas/Problem");
    CHECK(same_json(response_schema_at(oa, "/v1/demo/resource", "get", "401",
                                        "application/problem+json"),
                     problem_ref));
    json_decref(problem_ref);

    /* Numbers as written: no "3.0", no "1000000.0", no "0.10000000000000001". */
    const char *texts[2] = {api_catalog_text(), api_openapi_text()};
    for (int t = 0; t < 2; t++) {
        const char *s = texts[t];
        CHECK(strstr(s, "\"minItems\": 3,") != NULL);
        CHECK(strstr(s, "\"minItems\": 3.0") == NULL);
        CHECK(strstr(s, "\"maximum\": 1000000") != NULL);
        CHECK(strstr(s, "1000000.0") == NULL);
        CHECK(strstr(s, "\"default\": 0.1\n") != NULL || strstr(s, "\"default\": 0.1,") != NULL);
        CHECK(strstr(s, "0.10000000000000001") == NULL);
        CHECK(strstr(s, "3.141592653589793\n") != NULL);
        CHECK(strstr(s, "\"n\": 7,") != NULL);
        CHECK(strstr(s, "-3e-20") != NULL);
        CHECK(strstr(s, "2.5") != NULL);
    }
    CHECK(strstr(api_openapi_text(), "\"maximum\": 1000000000000000\n") != NULL);
    /* ... and every one reads back as the same double. */
    json_t *v = json_object_get(json_object_get(op0, "example"), "v");
    CHECK(json_number_value(json_array_get(v, 2)) == -3e-20);
    CHECK(json_number_value(json_object_get(json_object_get(json_object_get(
              json_object_get(op0, "schema"), "properties"), "x"), "maximum")) ==
          3.141592653589793);
    /* The curl line keeps the example as its author wrote it. */
    CHECK(strstr(json_string_value(json_object_get(op0, "curl")), "\"x\":0.1") != NULL);

    json_decref(oa);
    json_decref(cat);
    for (int i = 0; i < 3; i++) {
        json_decref(req[i]);
        json_decref(ans[i]);
    }
    TEST_MAIN_END();
}
