/* test_answer_policy.c — through api_handle_ext(), with no socket: what an
 * answer may be cached as, how large it may be, and what its problems say.
 *
 * - A batch answer that depended on the deadline (items stopped by it) sets
 *   depends_on_load and gets no ETag and Cache-Control no-store, while the
 *   same batch with time to spare gets its strong ETag and public caching.
 * - A batch asking for more samples than the answer budget is refused at once
 *   with answer-too-large naming the field where the sum passes the limit;
 *   ext->max_samples sets the budget.
 * - Problems carry instance (the request path; a batch item's
 *   /v1/batch#/operations/<i>).
 * - GET /v1 has a strong ETag, no-cache, Vary, 304 with the 200's length, and
 *   a gzip body that inflates to the identity bytes. */
#include <gsl/gsl_errno.h>
#include <stdlib.h>
#include <string.h>
#include <jansson.h>
#include <zlib.h>

#include "api.h"
#include "mech/base/budget.h"
#include "testlib.h"

static const char boost[] =
    "{\"operation\":\"/v1/relativity/boost\",\"request\":{\"vectors\":[[1,0,0,0]],"
    "\"velocity\":{\"beta\":[0.6,0,0]}}}";

static void run(const char *method, const char *path, const char *body, const char *query,
                double deadline_from_now, const struct api_request_ext *ext0,
                struct api_response *resp)
{
    struct api_request req = {method, path, "application/json", body, body ? strlen(body) : 0,
                              10000000, mech_clock_seconds() + deadline_from_now, NULL};
    struct api_request_ext ext = {0};
    if (ext0) ext = *ext0;
    ext.query_request = query;
    api_handle_ext(&req, &ext, resp);
}

static json_t *body_json(const struct api_response *r)
{
    return r->body ? json_loadb(r->body, r->body_len, 0, NULL) : NULL;
}

static const char *str_at(const json_t *j, const char *key)
{
    const char *s = json_string_value(json_object_get(j, key));
    return s ? s : "";
}

int main(void)
{
    gsl_set_error_handler_off();
    api_install_json_allocator(); /* process-wide, as GSL's handler */

    /* 5d: a batch whose deadline has passed: items 422, the answer depends on load. */
    char batch[512];
    snprintf(batch, sizeof batch, "{\"operations\":[%s,%s]}", boost, boost);
    struct api_response r;
    run("GET", "/v1/batch", NULL, batch, -1.0, NULL, &r);
    json_t *j = body_json(&r);
    json_t *item0 = json_array_get(json_object_get(j, "results"), 0);
    CHECK_EQ_INT(r.status, 200);
    CHECK_EQ_INT(json_integer_value(json_object_get(item0, "status")), 422);
    CHECK_EQ_INT(r.depends_on_load, 1);
    CHECK(r.etag[0] == '\0');
    CHECK(r.cache_control && !strcmp(r.cache_control, "no-store"));
    CHECK(!strcmp(str_at(json_object_get(item0, "problem"), "instance"),
                  "/v1/batch#/operations/0"));
    json_decref(j);
    api_response_free(&r);
    /* The same batch with time to spare: full answer, strong ETag, public. */
    run("GET", "/v1/batch", NULL, batch, 60.0, NULL, &r);
    CHECK_EQ_INT(r.status, 200);
    CHECK_EQ_INT(r.depends_on_load, 0);
    CHECK(r.etag[0] == '"');
    CHECK(r.cache_control && !strcmp(r.cache_control, "public, max-age=86400"));
    api_response_free(&r);

    /* 5b: the answer budget, checked before computing. */
    const char *geo = "{\"operation\":\"/v1/gr/geodesic\",\"request\":{\"M\":\"sun\",\"kind\":"
                      "\"timelike\",\"initial\":{\"semi_major_axis\":5.79e10,\"eccentricity\":"
                      "0.2},\"orbits\":3,\"samples\":100000}}";
    size_t cap = 100 * (strlen(geo) + 1) + 32;
    char *big = malloc(cap);
    CHECK(big != NULL);
    if (big) {
        size_t n = (size_t)snprintf(big, cap, "{\"operations\":[");
        for (int i = 0; i < 100; i++)
            n += (size_t)snprintf(big + n, cap - n, "%s%s", i ? "," : "", geo);
        snprintf(big + n, cap - n, "]}");
        double t0 = mech_clock_seconds();
        run("POST", "/v1/batch", big, NULL, 60.0, NULL, &r);
        double dt = mech_clock_seconds() - t0;
        j = body_json(&r);
        json_t *e0 = json_array_get(json_object_get(j, "errors"), 0);
        CHECK_EQ_INT(r.status, 422);
        CHECK(!strcmp(str_at(j, "type"), "/problems/answer-too-large"));
        CHECK(!strcmp(str_at(e0, "pointer"), "/operations/2/request/samples"));
        CHECK_EQ_INT(json_integer_value(json_object_get(j, "limit")), API_DEFAULT_MAX_SAMPLES);
        CHECK_EQ_INT(json_integer_value(json_object_get(j, "requested")), 10000000);
        CHECK(!strcmp(str_at(j, "instance"), "/v1/batch"));
        CHECK(dt < 5.0); /* nothing computed (generous: ASan) */
        json_decref(j);
        api_response_free(&r);
        /* A smaller budget from the server option. */
        struct api_request_ext small = {0};
        small.max_samples = 150000;
        run("POST", "/v1/batch", big, NULL, 60.0, &small, &r);
        j = body_json(&r);
        e0 = json_array_get(json_object_get(j, "errors"), 0);
        CHECK_EQ_INT(r.status, 422);
        CHECK(!strcmp(str_at(e0, "pointer"), "/operations/1/request/samples"));
        CHECK_EQ_INT(json_integer_value(json_object_get(j, "limit")), 150000);
        json_decref(j);
        api_response_free(&r);
        free(big);
    }

    /* 4a, 4e: GET of an operation without ?request=. */
    run("GET", "/v1/relativity/boost", NULL, NULL, 60.0, NULL, &r);
    j = body_json(&r);
    CHECK_EQ_INT(r.status, 400);
    CHECK(!strcmp(str_at(j, "type"), "/problems/request-missing"));
    CHECK(!strcmp(str_at(j, "instance"), "/v1/relativity/boost"));
    CHECK(r.allow == NULL);
    json_decref(j);
    api_response_free(&r);

    /* 4c: GET /v1, identity and gzip. */
    run("GET", "/v1", NULL, NULL, 60.0, NULL, &r);
    CHECK_EQ_INT(r.status, 200);
    CHECK(r.etag[0] == '"' && r.content_encoding == NULL);
    CHECK(r.cache_control && !strcmp(r.cache_control, "no-cache"));
    CHECK(r.vary && !strcmp(r.vary, "Accept-Encoding"));
    size_t ident_len = r.body_len;
    char *ident = malloc(ident_len);
    if (ident) memcpy(ident, r.body, ident_len);
    char etag[sizeof r.etag];
    memcpy(etag, r.etag, sizeof etag);
    api_response_free(&r);
    struct api_request_ext gz = {0};
    gz.accept_encoding = "deflate, gzip";
    run("GET", "/v1", NULL, NULL, 60.0, &gz, &r);
    CHECK(r.content_encoding && !strcmp(r.content_encoding, "gzip"));
    CHECK(strcmp(r.etag, etag) != 0);
    CHECK(r.body_len * 5 < ident_len);
    char *out = malloc(ident_len + 1);
    z_stream zs;
    memset(&zs, 0, sizeof zs);
    CHECK(out && inflateInit2(&zs, 15 + 16) == Z_OK);
    if (out && ident) {
        zs.next_in = (Bytef *)r.body;
        zs.avail_in = (uInt)r.body_len;
        zs.next_out = (Bytef *)out;
        zs.avail_out = (uInt)ident_len + 1;
        CHECK_EQ_INT(inflate(&zs, Z_FINISH), Z_STREAM_END);
        CHECK(zs.total_out == ident_len && !memcmp(out, ident, ident_len));
    }
    inflateEnd(&zs);
    free(out);
    free(ident);
    api_response_free(&r);
    gz.if_none_match = etag;
    gz.accept_encoding = "gzip;q=0";
    run("GET", "/v1", NULL, NULL, 60.0, &gz, &r);
    CHECK_EQ_INT(r.status, 304);
    CHECK(r.body == NULL && r.full_length == ident_len);
    api_response_free(&r);
    TEST_MAIN_END();
}
