/* test_response_schemas.c — every operation describes its answer: each route
 * has a response schema (from its data file, api/ops/<domain>/<operation>.json)
 * that compiles, is an object schema with properties, and that the answer to
 * the catalog's example matches — with and without "cost" — as do the answers
 * of the GET routes. The API cases check their own 200 answers the same way
 * (case_runner.c), so the documentation of the answers cannot drift.
 * Negative checks show the validation can fail: an answer with a required
 * member removed, or a member of the wrong type, is refused. */
#include <gsl/gsl_errno.h>
#include <jansson.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "api.h"
#include "mech/base/budget.h"
#include "run/routes.h"
#include "schema/schema.h"
#include "testlib.h"

/* The answer (parsed) of method path body, status in *status. */
static json_t *answer(const char *method, const char *path, const char *body, int *status)
{
    struct api_request req = {method, path, body ? "application/json" : NULL, body,
                              body ? strlen(body) : 0, 10000000, mech_clock_seconds() + 300, NULL};
    struct api_response resp;
    api_handle(&req, &resp);
    *status = resp.status;
    json_t *j = resp.body ? json_loads(resp.body, JSON_DECODE_INT_AS_REAL, NULL) : NULL;
    api_response_free(&resp);
    return j;
}

static size_t violations(const struct api_schema *c, const json_t *j, const char *what)
{
    json_t *errs = json_array();
    size_t n = api_schema_validate(c, j, "", errs);
    if (n) {
        char *e = json_dumps(errs, JSON_COMPACT);
        printf("%s: %zu violation(s): %.1200s\n", what, n, e ? e : "");
        free(e);
    }
    json_decref(errs);
    return n;
}

int main(void)
{
    gsl_set_error_handler_off();
    api_install_json_allocator();
    CHECK(api_init() == 0);
    size_t checked = 0, refused = 0;
    for (size_t i = 0; i < api_route_count; i++) {
        const struct api_route *r = api_routes[i];
        const json_t *rs = api_route_response_schema(i);
        char msg[200];
        struct api_schema *c = rs ? api_schema_compile(rs, msg, sizeof msg) : NULL;
        if (!c) printf("%s: response schema missing or invalid: %s\n", r->path, rs ? msg : "none");
        CHECK(c != NULL);
        if (!c) continue;
        CHECK(json_is_object(json_object_get(rs, "properties")));
        CHECK(json_is_string(json_object_get(rs, "description")));
        char what[200];
        if (!strcmp(r->method, "GET")) {
            int st;
            json_t *a = answer("GET", r->path, NULL, &st);
            CHECK_EQ_INT(st, 200);
            snprintf(what, sizeof what, "GET %s", r->path);
            CHECK_EQ_INT((int)violations(c, a, what), 0);
            json_decref(a);
            checked++;
        } else {
            for (int nocost = 0; nocost < 2; nocost++) {
                json_t *ex = json_loads(r->example, 0, NULL);
                if (nocost) json_object_set_new(ex, "cost", json_false());
                char *body = json_dumps(ex, JSON_COMPACT | JSON_REAL_PRECISION(17));
                int st;
                json_t *a = answer("POST", r->path, body, &st);
                if (st != 200) printf("%s example: status %d\n", r->path, st);
                CHECK_EQ_INT(st, 200);
                snprintf(what, sizeof what, "POST %s example%s", r->path, nocost ? " (cost false)" : "");
                CHECK_EQ_INT((int)violations(c, a, what), 0);
                /* The check can fail: drop a required member, or break a member's type. */
                const json_t *req = json_object_get(rs, "required");
                if (!nocost && json_array_size(req) > 0 && json_is_object(a)) {
                    const char *k = json_string_value(json_array_get(req, 0));
                    json_t *broken = json_copy(a);
                    json_object_del(broken, k);
                    size_t n1 = api_schema_validate(c, broken, "", NULL);
                    json_object_set_new(broken, k, json_string("not what the schema says"));
                    size_t n2 = json_is_string(json_object_get(a, k))
                                    ? 1
                                    : api_schema_validate(c, broken, "", NULL);
                    if (!(n1 > 0 && n2 > 0))
                        printf("%s: a broken answer (%s) was not refused\n", r->path, k);
                    CHECK(n1 > 0 && n2 > 0);
                    refused++;
                    json_decref(broken);
                }
                json_decref(a);
                free(body);
                json_decref(ex);
                checked++;
            }
        }
        api_schema_free(c);
    }
    printf("%zu answers checked against %zu response schemas; %zu broken answers refused\n",
           checked, api_route_count, refused);
    CHECK(refused > 40); /* nearly every POST route names a required member */
    TEST_MAIN_END();
}
