/* test_catalog.c — GET /v1 and GET /v1/openapi.json are generated from the
 * route table and stay true to it: every operation is listed with its schema
 * and an example; every example succeeds when POSTed; answers are
 * byte-identical when repeated (apart from cost); every problem type URI
 * resolves to its description. */
#include <gsl/gsl_errno.h>
#include <string.h>

#include "api.h"
#include "mech/base/budget.h"
#include "run/routes.h"
#include "testlib.h"

/* Is j the string want? (false for NULL or a non-string) */
static int str_is(const json_t *j, const char *want)
{
    const char *s = json_string_value(j);
    return s && !strcmp(s, want);
}

static json_t *get_json(const char *method, const char *path, const char *body, int *status)
{
    struct api_request req = {method, path, "application/json", body, body ? strlen(body) : 0,
                              10000000, mech_clock_seconds() + 120, NULL};
    struct api_response resp;
    api_handle(&req, &resp);
    *status = resp.status;
    json_t *j = resp.body ? json_loads(resp.body, 0, NULL) : NULL;
    api_response_free(&resp);
    return j;
}

/* Remove every "cost" member, at any depth: byte-identity (docs/design.md) exempts fields under
 * "cost" (measured time) from byte-identity, wherever they appear. */
static void strip_cost(json_t *j)
{
    if (json_is_object(j)) {
        json_object_del(j, "cost");
        const char *k;
        json_t *v;
        json_object_foreach(j, k, v) strip_cost(v);
    } else if (json_is_array(j)) {
        size_t i;
        json_t *v;
        json_array_foreach(j, i, v) strip_cost(v);
    }
}

static char *post_text(const char *path, const char *body)
{
    struct api_request req = {"POST", path, "application/json; charset=utf-8", body, strlen(body),
                              10000000, mech_clock_seconds() + 120, NULL};
    struct api_response resp;
    api_handle(&req, &resp);
    if (resp.status != 200) {
        fprintf(stderr, "%s example -> %d: %.500s\n", path, resp.status, resp.body);
        api_response_free(&resp);
        return NULL;
    }
    /* Drop the measured cost so the rest can be compared byte for byte. */
    json_t *j = json_loads(resp.body, JSON_DECODE_INT_AS_REAL, NULL);
    api_response_free(&resp);
    strip_cost(j);
    char *s = json_dumps(j, JSON_COMPACT | JSON_REAL_PRECISION(17));
    json_decref(j);
    return s;
}

int main(void)
{
    gsl_set_error_handler_off();
    api_install_json_allocator(); /* process-wide, as GSL's handler */
    CHECK(api_init() == 0);
    int st;
    json_t *cat = get_json("GET", "/v1", NULL, &st);
    CHECK_EQ_INT(st, 200);
    json_t *ops = json_object_get(cat, "operations");
    size_t n_post = 0;
    for (size_t i = 0; i < api_route_count; i++) n_post += !strcmp(api_routes[i]->method, "POST");
    CHECK_EQ_INT(json_array_size(ops), n_post);
    CHECK(api_route_count >= 3);
    const char *want[] = {"/v1/rigid/inertia", "/v1/relativity/boost", "/v1/trajectory"};
    for (int w = 0; w < 3; w++) {
        int found = 0;
        size_t i;
        json_t *op;
        json_array_foreach(ops, i, op) {
            if (strcmp(json_string_value(json_object_get(op, "path")), want[w])) continue;
            found = 1;
            CHECK(json_is_object(json_object_get(op, "schema")));
            CHECK(json_is_object(json_object_get(op, "example")));
            CHECK(strlen(json_string_value(json_object_get(op, "summary"))) > 10);
            CHECK(strstr(json_string_value(json_object_get(op, "curl")), want[w]) != NULL);
        }
        CHECK(found);
    }

    /* Every example succeeds, and twice gives the same bytes. GET routes
     * (read-only resources) answer 200 with a JSON object and refuse POST. */
    for (size_t i = 0; i < api_route_count; i++) {
        if (!strcmp(api_routes[i]->method, "GET")) {
            json_t *j = get_json("GET", api_routes[i]->path, NULL, &st);
            CHECK_EQ_INT(st, 200);
            CHECK(json_is_object(j));
            json_decref(j);
            j = get_json("POST", api_routes[i]->path, "{}", &st);
            CHECK_EQ_INT(st, 405);
            json_decref(j);
            continue;
        }
        char *a = post_text(api_routes[i]->path, api_routes[i]->example);
        char *b = post_text(api_routes[i]->path, api_routes[i]->example);
        CHECK(a && b && !strcmp(a, b));
        free(a);
        free(b);
        /* GET without ?request= is a 400 that says what is needed (GET is
         * allowed, with ?request=); another method is a 405. */
        json_t *j = get_json("GET", api_routes[i]->path, NULL, &st);
        CHECK_EQ_INT(st, 400);
        const char *type = json_string_value(json_object_get(j, "type"));
        const char *inst = json_string_value(json_object_get(j, "instance"));
        CHECK(type && !strcmp(type, "/problems/request-missing"));
        CHECK(inst && !strcmp(inst, api_routes[i]->path));
        json_decref(j);
        j = get_json("PUT", api_routes[i]->path, NULL, &st);
        CHECK_EQ_INT(st, 405);
        json_decref(j);
    }

    /* OpenAPI 3.1 lists the same operations with the same schemas. */
    json_t *oa = get_json("GET", "/v1/openapi.json", NULL, &st);
    CHECK_EQ_INT(st, 200);
    CHECK(!strcmp(json_string_value(json_object_get(oa, "openapi")), "3.1.0"));
    for (size_t i = 0; i < api_route_count; i++) {
        json_t *p = json_object_get(json_object_get(oa, "paths"), api_routes[i]->path);
        if (!strcmp(api_routes[i]->method, "GET")) {
            CHECK(json_object_get(p, "get") != NULL);
            continue;
        }
        json_t *schema = json_object_get(json_object_get(json_object_get(json_object_get(
            json_object_get(json_object_get(p, "post"), "requestBody"), "content"),
            "application/json"), "schema"), "type");
        CHECK(schema && !strcmp(json_string_value(schema), "object"));
        CHECK(json_object_get(json_object_get(json_object_get(p, "post"), "responses"), "422"));
    }
    /* The bearer token (--token-file) is declared, and asked for on /v1 only. */
    json_t *bearer = json_object_get(
        json_object_get(json_object_get(oa, "components"), "securitySchemes"), "bearerAuth");
    CHECK(str_is(json_object_get(bearer, "type"), "http"));
    CHECK(str_is(json_object_get(bearer, "scheme"), "bearer"));
    CHECK(json_is_array(json_object_get(json_array_get(json_object_get(oa, "security"), 0),
                                        "bearerAuth")));
    CHECK(json_array_size(json_object_get(oa, "servers")) >= 1);
    /* The problem+json schema names what mechd's problems carry. */
    json_t *pprops = json_object_get(json_object_get(json_object_get(json_object_get(
        oa, "components"), "schemas"), "Problem"), "properties");
    const char *members[] = {"type", "title", "status", "detail", "instance", "errors",
                             "progress", "run"};
    for (size_t m = 0; m < sizeof members / sizeof members[0]; m++)
        CHECK(json_object_get(pprops, members[m]) != NULL);
    CHECK(json_object_get(json_object_get(json_object_get(json_object_get(pprops, "errors"),
                                                          "items"), "properties"), "pointer"));
    /* Every operation: an operationId; every 4xx/5xx a Problem; a 401 exactly
     * where the server asks for the token (/v1 and under); a declared {slug}. */
    const char *path;
    json_t *item;
    size_t n_ops = 0;
    json_object_foreach(json_object_get(oa, "paths"), path, item) {
        int v1 = !strcmp(path, "/v1") || !strncmp(path, "/v1/", 4);
        const char *method;
        json_t *op;
        json_object_foreach(item, method, op) {
            n_ops++;
            CHECK(json_is_string(json_object_get(op, "operationId")));
            json_t *responses = json_object_get(op, "responses");
            CHECK((json_object_get(responses, "401") != NULL) == v1);
            if (!v1) CHECK(json_array_size(json_object_get(op, "security")) == 0 &&
                           json_is_array(json_object_get(op, "security")));
            const char *code;
            json_t *resp;
            json_object_foreach(responses, code, resp) {
                if (code[0] < '4') continue;
                const char *r = json_string_value(json_object_get(json_object_get(
                    json_object_get(json_object_get(resp, "content"), "application/problem+json"),
                    "schema"), "$ref"));
                CHECK(r && !strcmp(r, "#/components/schemas/Problem"));
            }
            if (strchr(path, '{')) {
                json_t *param = json_array_get(json_object_get(op, "parameters"), 0);
                CHECK(str_is(json_object_get(param, "name"), "slug"));
                CHECK(str_is(json_object_get(param, "in"), "path"));
                CHECK(json_is_true(json_object_get(param, "required")));
            }
        }
    }
    CHECK(n_ops > api_route_count);
    /* Integers print as integers: schema sizes and example counts. */
    const char *docs[2] = {"/v1", "/v1/openapi.json"};
    for (int d = 0; d < 2; d++) {
        struct api_request req = {"GET", docs[d], NULL, NULL, 0, 1, mech_clock_seconds() + 60,
                                  NULL};
        struct api_response resp;
        api_handle(&req, &resp);
        CHECK_EQ_INT(resp.status, 200);
        CHECK(resp.body && strstr(resp.body, "\"minItems\": 3,") != NULL);
        CHECK(resp.body && strstr(resp.body, "\"minItems\": 3.0") == NULL);
        CHECK(resp.body && strstr(resp.body, "\"samples\": 7.0") == NULL);
        CHECK(resp.body && strstr(resp.body, ".0,\n") == NULL && strstr(resp.body, ".0\n") == NULL);
        api_response_free(&resp);
    }

    json_decref(oa);
    json_decref(cat);

    /* Every problem type URI resolves (RFC 9457 §3.1.1: type is a dereferenceable URI). */
    for (int k = 1; k < API_PROBLEM_COUNT; k++) {
        json_t *d = get_json("GET", api_problem_type((enum api_problem)k), NULL, &st);
        CHECK_EQ_INT(st, 200);
        CHECK_EQ_INT(json_integer_value(json_object_get(d, "status")),
                     api_problem_status((enum api_problem)k));
        json_decref(d);
    }
    json_t *d = get_json("GET", "/problems/nope", NULL, &st);
    CHECK_EQ_INT(st, 404);
    json_decref(d);

    CHECK(api_is_inline("GET", "/v1"));
    CHECK(!api_is_inline("POST", "/v1/trajectory"));
    CHECK(api_is_inline("POST", "/v1/nothing"));
    TEST_MAIN_END();
}
