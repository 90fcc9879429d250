/* case_runner.c — runs one data-driven API case through api_handle(), with no
 * network: argv[1] is a folder holding request.json and expected.json.
 *
 * request.json:  {"method", "path", "body": {...} | "body_text": "raw",
 *                 "content_type"?, "max_steps"?, "deadline_ms"?}
 * expected.json: {"why": "...", "status": N, "content_type"?, "body": {...},
 *                 "rtol"?, "atol"?, "tolerances"?: [{"pointer", "rtol", "atol"}],
 *                 "absent"?: ["/pointer", ...]}
 * Partial match: every key of expected.body must exist and match; arrays have
 * equal length and match element-wise; numbers within atol + rtol*|want|
 * (the longest matching `tolerances` pointer prefix wins); other values exactly.
 * Every 200 answer must also match its operation's response schema (its data
 * file's response_schema, shown in GET /v1 and OpenAPI), whole, so the
 * documentation of the answers cannot drift from the code.
 */
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

/* The whole answer of a 200 to `path` against the route's response schema. */
static void check_response_schema(const char *path, const json_t *got)
{
    size_t plen = strcspn(path, "?");
    for (size_t i = 0; i < api_route_count; i++) {
        if (strlen(api_routes[i]->path) != plen || strncmp(api_routes[i]->path, path, plen))
            continue;
        const json_t *rs = api_route_response_schema(i);
        char msg[200];
        struct api_schema *c = rs ? api_schema_compile(rs, msg, sizeof msg) : NULL;
        if (!c) {
            tl_failed++;
            fprintf(stderr, "%s: no usable response schema (%s)\n", path, rs ? msg : "none");
            return;
        }
        json_t *errs = json_array();
        size_t n = api_schema_validate(c, got, "", errs);
        if (n) {
            tl_failed++;
            char *e = json_dumps(errs, JSON_COMPACT);
            fprintf(stderr, "%s: the answer does not match the response schema (%zu): %.1500s\n",
                    path, n, e ? e : "");
            free(e);
        } else {
            tl_passed++;
        }
        json_decref(errs);
        api_schema_free(c);
        return;
    }
}

static const json_t *tolerances;
static double g_rtol, g_atol;

static void tolerance_for(const char *ptr, double *rtol, double *atol)
{
    size_t best = 0;
    *rtol = g_rtol;
    *atol = g_atol;
    size_t i;
    json_t *t;
    json_array_foreach(tolerances, i, t) {
        const char *p = json_string_value(json_object_get(t, "pointer"));
        size_t n = p ? strlen(p) : 0;
        if (p && n >= best && !strncmp(ptr, p, n) && (ptr[n] == '\0' || ptr[n] == '/')) {
            best = n;
            *rtol = json_number_value(json_object_get(t, "rtol"));
            *atol = json_number_value(json_object_get(t, "atol"));
        }
    }
}

static void match(const json_t *want, const json_t *got, const char *ptr)
{
    char child[512];
    if (!got) {
        tl_failed++;
        fprintf(stderr, "%s: missing\n", ptr);
        return;
    }
    if (json_is_number(want)) {
        double rtol, atol;
        tolerance_for(ptr, &rtol, &atol);
        if (!json_is_number(got)) {
            tl_failed++;
            fprintf(stderr, "%s: want a number, got another type\n", ptr);
            return;
        }
        double w = json_number_value(want), g = json_number_value(got);
        double tol = atol + rtol * fabs(w);
        if (fabs(g - w) <= tol) tl_passed++;
        else {
            tl_failed++;
            fprintf(stderr, "%s: got %.17g, want %.17g (err %.3g > tol %.3g)\n", ptr, g, w,
                    fabs(g - w), tol);
        }
    } else if (json_is_object(want)) {
        if (!json_is_object(got)) { tl_failed++; fprintf(stderr, "%s: want an object\n", ptr); return; }
        const char *k;
        json_t *v;
        json_object_foreach((json_t *)want, k, v) {
            snprintf(child, sizeof child, "%s", ptr);
            api_pointer_append(child, sizeof child, k);
            match(v, json_object_get(got, k), child);
        }
    } else if (json_is_array(want)) {
        if (!json_is_array(got) || json_array_size(got) != json_array_size(want)) {
            tl_failed++;
            fprintf(stderr, "%s: want an array of %zu items, got %zu\n", ptr,
                    json_array_size(want), json_is_array(got) ? json_array_size(got) : 0);
            return;
        }
        for (size_t i = 0; i < json_array_size(want); i++) {
            snprintf(child, sizeof child, "%s/%zu", ptr, i);
            match(json_array_get(want, i), json_array_get(got, i), child);
        }
    } else {
        if (json_equal((json_t *)want, (json_t *)got)) tl_passed++;
        else {
            char *w = json_dumps(want, JSON_ENCODE_ANY), *g = json_dumps(got, JSON_ENCODE_ANY);
            tl_failed++;
            fprintf(stderr, "%s: got %s, want %s\n", ptr, g ? g : "?", w ? w : "?");
            free(w);
            free(g);
        }
    }
}

/* Resolve a JSON pointer (no escapes needed in our cases). */
static const json_t *resolve(const json_t *doc, const char *ptr)
{
    char buf[512];
    snprintf(buf, sizeof buf, "%s", ptr);
    const json_t *cur = doc;
    for (char *tok = strtok(buf, "/"); tok && cur; tok = strtok(NULL, "/")) {
        if (json_is_object(cur)) cur = json_object_get(cur, tok);
        else if (json_is_array(cur)) cur = json_array_get(cur, strtoul(tok, NULL, 10));
        else cur = NULL;
    }
    return cur;
}

int main(int argc, char **argv)
{
    gsl_set_error_handler_off();
    api_install_json_allocator(); /* process-wide, as GSL's handler */
    if (argc != 2) { fprintf(stderr, "usage: %s CASE_DIR\n", argv[0]); return 2; }
    char path[1024];
    json_error_t jerr;
    snprintf(path, sizeof path, "%s/request.json", argv[1]);
    json_t *rq = json_load_file(path, JSON_DECODE_INT_AS_REAL, &jerr);
    snprintf(path, sizeof path, "%s/expected.json", argv[1]);
    json_t *ex = json_load_file(path, JSON_DECODE_INT_AS_REAL, &jerr);
    if (!rq || !ex) { fprintf(stderr, "%s: cannot read case: %s\n", argv[1], jerr.text); return 2; }

    char *body = NULL;
    const json_t *b = json_object_get(rq, "body");
    if (b) body = json_dumps(b, JSON_COMPACT | JSON_ENCODE_ANY | JSON_REAL_PRECISION(17));
    else if (json_is_string(json_object_get(rq, "body_text")))
        body = strdup(json_string_value(json_object_get(rq, "body_text")));
    const json_t *ct = json_object_get(rq, "content_type");

    struct api_request req = {
        .method = json_string_value(json_object_get(rq, "method")),
        .path = json_string_value(json_object_get(rq, "path")),
        .content_type = json_is_null(ct) ? NULL : ct ? json_string_value(ct) : "application/json",
        .body = body,
        .body_len = body ? strlen(body) : 0,
        .max_steps = (long)(json_object_get(rq, "max_steps")
                                ? json_number_value(json_object_get(rq, "max_steps"))
                                : 10000000),
        .deadline = mech_clock_seconds() + (json_object_get(rq, "deadline_ms")
                                                ? json_number_value(json_object_get(rq, "deadline_ms"))
                                                : 120000) / 1000.0,
        .cancel = NULL,
    };
    struct api_response resp;
    api_handle(&req, &resp);

    CHECK_EQ_INT(resp.status, json_number_value(json_object_get(ex, "status")));
    if (json_object_get(ex, "content_type"))
        CHECK(resp.content_type &&
              !strcmp(resp.content_type, json_string_value(json_object_get(ex, "content_type"))));
    json_t *got = resp.body ? json_loads(resp.body, JSON_DECODE_INT_AS_REAL, &jerr) : NULL;
    if (!got) {
        tl_failed++;
        fprintf(stderr, "response body is not JSON: %.300s\n", resp.body ? resp.body : "(none)");
    } else {
        g_rtol = json_object_get(ex, "rtol") ? json_number_value(json_object_get(ex, "rtol")) : 0;
        g_atol = json_object_get(ex, "atol") ? json_number_value(json_object_get(ex, "atol")) : 0;
        tolerances = json_object_get(ex, "tolerances");
        if (json_object_get(ex, "body")) match(json_object_get(ex, "body"), got, "/body");
        if (resp.status == 200 && req.path) check_response_schema(req.path, got);
        size_t i;
        json_t *a;
        json_array_foreach(json_object_get(ex, "absent"), i, a) {
            if (resolve(got, json_string_value(a))) {
                tl_failed++;
                fprintf(stderr, "%s: present, want absent\n", json_string_value(a));
            } else tl_passed++;
        }
    }
    if (tl_failed) fprintf(stderr, "response: %.2000s\n", resp.body ? resp.body : "(none)");
    json_decref(got);
    api_response_free(&resp);
    free(body);
    json_decref(rq);
    json_decref(ex);
    TEST_MAIN_END();
}
