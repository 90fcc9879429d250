/* catalog.c — builds GET /v1 (every operation with its summary, description,
 * input JSON Schema and a working example) and GET /v1/openapi.json
 * (OpenAPI 3.1) from the route table, once, at api_init(). */
#include "catalog.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "api.h"
#include "routes.h"

#ifndef MECHD_VERSION
#define MECHD_VERSION "0"
#endif

static char *catalog_text;
static char *openapi_text;

static const char service_description[] =
    "mechd answers physics questions from a university mechanics course (rotations, "
    "non-inertial frames, rigid bodies, special relativity) as JSON over HTTP. SI units "
    "unless a field says otherwise; 4-vectors are [ct, x, y, z] with metric (-,+,+,+); "
    "rotations are passive. Errors are application/problem+json (RFC 9457). Every POST "
    "operation also answers GET with ?request=<url-encoded JSON body>: the same bytes without "
    "the measured cost, a strong ETag and Cache-Control, and 304 for a matching If-None-Match "
    "(an answer that depended on load, such as a batch item stopped by the deadline, gets "
    "Cache-Control: no-store and no ETag). The URL and headers must fit in about 32 KB "
    "(longer gets 414): POST longer requests. Every problem carries instance, the request "
    "path. A request may ask for at most --max-samples samples in all (default 200000). "
    "Every operation also takes the envelope keys (envelope in GET /v1, "
    "#/components/schemas/Envelope in OpenAPI), whatever its own schema: \"cost\": false leaves "
    "out measured time so that equal requests give byte-identical answers.";

/* The envelope keys as a schema object (new reference, or NULL). */
static json_t *envelope_schema(void)
{
    json_t *props = json_loads(api_envelope_properties, JSON_DECODE_INT_AS_REAL, NULL);
    return json_pack("{s:s,s:s,s:o}", "type", "object", "description",
                     "Keys every operation takes in its request body, in addition to the ones "
                     "its own schema lists (each operation's schema shows them too).",
                     "properties", props);
}

/* Server-level resources that are not operations of the route table. */
static const struct {
    const char *path, *summary, *content_type;
} resources[] = {
    {"/v1", "This catalog: every operation with its schema and an example.", "application/json"},
    {"/v1/openapi.json", "OpenAPI 3.1 description of the API.", "application/json"},
    {"/healthz", "Liveness: {\"status\":\"ok\"}.", "application/json"},
    {"/metrics", "Prometheus text-format metrics.", "text/plain"},
    {"/problems/{slug}", "What a problem type URI means.", "application/json"},
    {"/", "The classroom front end.", "text/html"},
};

static char *example_curl(const struct api_route *r)
{
    /* A command that works when pasted into a shell against `make run`. */
    size_t n = strlen(r->example) + strlen(r->path) + 128;
    char *s = malloc(n);
    if (s)
        snprintf(s, n, "curl -s http://127.0.0.1:8080%s --json '%s'", r->path, r->example);
    return s;
}

static json_t *build_catalog(void)
{
    json_t *ops = json_array();
    json_t *res = json_array();
    for (size_t i = 0; i < api_route_count; i++) {
        const struct api_route *r = api_routes[i];
        if (!strcmp(r->method, "GET")) {
            json_array_append_new(res, json_pack("{s:s,s:s,s:s}", "method", "GET", "path",
                                                 r->path, "summary", r->summary));
            continue;
        }
        json_t *ex = json_loads(r->example, JSON_DECODE_INT_AS_REAL, NULL);
        char *curl = example_curl(r);
        json_t *op = json_pack("{s:s,s:s,s:s,s:s,s:O,s:o,s:s}", "method", r->method, "path",
                               r->path, "summary", r->summary, "description", r->description,
                               "schema", api_route_schema(i), "example", ex, "curl",
                               curl ? curl : "");
        free(curl);
        if (!op) { json_decref(ops); json_decref(res); return NULL; }
        json_array_append_new(ops, op);
    }
    for (size_t i = 0; i < sizeof resources / sizeof resources[0]; i++)
        json_array_append_new(res, json_pack("{s:s,s:s,s:s}", "method", "GET", "path",
                                             resources[i].path, "summary", resources[i].summary));
    return json_pack("{s:s,s:s,s:s,s:o,s:o,s:o}", "name", "mechd", "version", MECHD_VERSION,
                     "description", service_description, "envelope", envelope_schema(),
                     "operations", ops, "resources", res);
}

static json_t *problem_response(const char *description)
{
    return json_pack("{s:s,s:{s:{s:{s:s}}}}", "description", description, "content",
                     "application/problem+json", "schema", "$ref",
                     "#/components/schemas/Problem");
}

/* What an operation's 422 may be. */
static const char status_422[] =
    "Validation, domain, compute-budget or answer-too-large (more samples in all than the "
    "server's --max-samples) error.";

/* The GET ?request= form of POST operation i (see api.h, api_handle_ext). */
static json_t *get_variant(size_t i, const char *opid)
{
    const struct api_route *r = api_routes[i];
    char id[160];
    snprintf(id, sizeof id, "%s_get", opid);
    json_t *param = json_pack("{s:s,s:s,s:b,s:s,s:{s:{s:O}}}", "name", "request", "in", "query",
                              "required", 1, "description",
                              "the request body as URL-encoded JSON; the URL and headers must "
                              "fit in about 32 KB (longer gets 414 from libmicrohttpd): POST "
                              "longer requests", "content",
                              "application/json", "schema", api_route_schema(i));
    json_t *etag_hdr = json_pack("{s:s,s:{s:s}}", "description",
                                 "strong tag of (build, path, canonical request)", "schema",
                                 "type", "string");
    json_t *cc_hdr = json_pack("{s:s,s:{s:s}}", "description", "public, max-age=86400", "schema",
                               "type", "string");
    json_t *ok = json_pack("{s:s,s:{s:O,s:O},s:{s:{s:{s:s}}}}", "description",
                           "The result, byte-identical to the POST answer without cost. An "
                           "answer that depends on the load or the deadline (a partial "
                           "/v1/compare) has no ETag and Cache-Control: no-store.",
                           "headers", "ETag", etag_hdr, "Cache-Control", cc_hdr, "content",
                           "application/json", "schema", "type", "object");
    json_t *nm = json_pack("{s:s,s:{s:O,s:O}}", "description",
                           "If-None-Match matched the ETag: no body, the operation is not run.",
                           "headers", "ETag", etag_hdr, "Cache-Control", cc_hdr);
    json_decref(etag_hdr);
    json_decref(cc_hdr);
    json_t *responses = json_pack("{s:o,s:o,s:o,s:o,s:o,s:o}", "200", ok, "304", nm, "400",
                                  problem_response("The request parameter is not JSON."), "422",
                                  problem_response(status_422),
                                  "500", problem_response("Internal error."), "503",
                                  problem_response("Queue full or shutting down; see Retry-After."));
    return json_pack("{s:s,s:s,s:s,s:[o],s:o}", "operationId", id, "summary", r->summary,
                     "description",
                     "The same operation as a cacheable GET: the measured cost is left out, so "
                     "equal requests give equal bytes and the same ETag; If-None-Match gives 304.",
                     "parameters", param, "responses", responses);
}

static json_t *build_openapi(void)
{
    json_t *paths = json_object();
    for (size_t i = 0; i < api_route_count; i++) {
        const struct api_route *r = api_routes[i];
        if (!strcmp(r->method, "GET")) {
            json_t *get = json_pack("{s:s,s:s,s:{s:{s:s,s:{s:{s:{s:s}}}}}}", "summary", r->summary,
                                    "description", r->description, "responses", "200",
                                    "description", r->summary, "content", "application/json",
                                    "schema", "type", "object");
            json_object_set_new(paths, r->path, json_pack("{s:o}", "get", get));
            continue;
        }
        char opid[128];
        snprintf(opid, sizeof opid, "%s", r->path + (strncmp(r->path, "/v1/", 4) ? 0 : 4));
        for (char *p = opid; *p; p++)
            if (*p == '/') *p = '_';
        json_t *ex = json_loads(r->example, JSON_DECODE_INT_AS_REAL, NULL);
        json_t *responses = json_pack(
            "{s:{s:s,s:{s:{s:{s:s}}}},s:o,s:o,s:o,s:o,s:o,s:o,s:o}", "200", "description",
            "The result.", "content", "application/json", "schema", "type", "object", "400",
            problem_response("Malformed JSON."), "413", problem_response("Body too large."),
            "415", problem_response("Not application/json."), "422",
            problem_response(status_422), "500",
            problem_response("Internal error."), "503",
            problem_response("Queue full or shutting down; see Retry-After."), "405",
            problem_response("Wrong method."));
        json_t *op = json_pack("{s:s,s:s,s:s,s:{s:b,s:{s:{s:O,s:o}}},s:o}", "operationId", opid,
                               "summary", r->summary, "description", r->description,
                               "requestBody", "required", 1, "content", "application/json",
                               "schema", api_route_schema(i), "example", ex, "responses",
                               responses);
        if (!op) { json_decref(paths); return NULL; }
        char method[16];
        snprintf(method, sizeof method, "%s", r->method);
        for (char *p = method; *p; p++) *p = (char)(*p - 'A' + 'a');
        json_t *item = json_pack("{s:o}", method, op);
        if (item && !strcmp(r->method, "POST"))
            json_object_set_new_nocheck(item, "get", get_variant(i, opid));
        json_object_set_new(paths, r->path, item);
    }
    for (size_t i = 0; i < sizeof resources / sizeof resources[0]; i++) {
        json_t *get = json_pack("{s:s,s:{s:{s:s,s:{s:{}}}}}", "summary", resources[i].summary,
                                "responses", "200", "description", resources[i].summary,
                                "content", resources[i].content_type);
        json_object_set_new(paths, resources[i].path, json_pack("{s:o}", "get", get));
    }
    json_t *problem_schema = json_pack(
        "{s:s,s:[s,s,s,s],s:{s:{s:s},s:{s:s},s:{s:s},s:{s:s},s:{s:s,s:{s:s,s:{s:{s:s},s:{s:s}}}}}}",
        "type", "object", "required", "type", "title", "status", "detail", "properties", "type",
        "type", "string", "title", "type", "string", "status", "type", "integer", "detail",
        "type", "string", "errors", "type", "array", "items", "type", "object", "properties",
        "pointer", "type", "string", "detail", "type", "string");
    return json_pack("{s:s,s:{s:s,s:s,s:s},s:o,s:{s:{s:o,s:o}}}", "openapi", "3.1.0", "info",
                     "title", "mechd", "version", MECHD_VERSION, "description",
                     service_description, "paths", paths, "components", "schemas", "Problem",
                     problem_schema, "Envelope", envelope_schema());
}

int api_catalog_init(char *err, size_t n)
{
    json_t *c = build_catalog();
    json_t *o = build_openapi();
    catalog_text = c ? json_dumps(c, JSON_INDENT(2) | JSON_REAL_PRECISION(17)) : NULL;
    openapi_text = o ? json_dumps(o, JSON_INDENT(2) | JSON_REAL_PRECISION(17)) : NULL;
    json_decref(c);
    json_decref(o);
    if (!catalog_text || !openapi_text) {
        snprintf(err, n, "could not build the catalog / OpenAPI document");
        return -1;
    }
    return 0;
}

const char *api_catalog_text(void)
{
    return catalog_text ? catalog_text : "{}";
}

const char *api_openapi_text(void)
{
    return openapi_text ? openapi_text : "{}";
}
