/* catalog.c — builds GET /v1 (every operation with its summary, description,
 * input JSON Schema and a working example) and GET /v1/openapi.json
 * (OpenAPI 3.1: bearerAuth, the problem+json schema, each operation's answer
 * schema) from the route table, once, at api_init(). It reads the parsed
 * schemas it is handed and calls nothing of the pipeline (api*.c), so the
 * set-up (api/run/api_init.c) calls it and no loop runs back. JSON texts are parsed
 * without JSON_DECODE_INT_AS_REAL, so an integer of a schema or an example
 * prints as an integer ("minItems": 3, "samples": 7). */
#include "catalog/catalog.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "run/routes.h"

#ifndef MECHD_VERSION
#define MECHD_VERSION "0"
#endif

static char *catalog_text;
static char *openapi_text;
/* Borrowed from api_catalog_init()'s caller for the length of the call. */
static const json_t *const *request_schemas;
static const json_t *const *response_schemas;

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
    json_t *props = json_loads(api_envelope_properties, 0, NULL);
    return json_pack("{s:s,s:s,s:o}", "type", "object", "description",
                     "Keys every operation takes in its request body, in addition to the ones "
                     "its own schema lists (each operation's schema shows them too).",
                     "properties", props);
}

/* Server-level resources that are not operations of the route table. */
static const struct {
    const char *path, *summary, *content_type, *operation_id;
} resources[] = {
    {"/v1", "This catalog: every operation with its schema and an example.", "application/json",
     "catalog"},
    {"/v1/openapi.json", "OpenAPI 3.1 description of the API.", "application/json", "openapi"},
    {"/healthz", "Liveness: {\"status\":\"ok\"}.", "application/json", "healthz"},
    {"/metrics", "Prometheus text-format metrics.", "text/plain", "metrics"},
    {"/problems/{slug}", "What a problem type URI means.", "application/json", "problem_type"},
    {"/", "The classroom front end.", "text/html", "front_end"},
};

/* The server asks for the bearer token (--token-file) on /v1 and every path
 * under it, and nowhere else (server/http_security.c, is_v1_path). */
static int needs_token(const char *path)
{
    return !strcmp(path, "/v1") || !strncmp(path, "/v1/", 4);
}

static char *example_curl(const struct api_route *r)
{
    /* A command that works when pasted into a shell against `make run`; GET /v1
     * writes the host and port it was asked on instead (api/catalog/api_docs.c). */
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
        json_t *ex = json_loads(r->example, 0, NULL);
        char *curl = example_curl(r);
        json_t *op = json_pack("{s:s,s:s,s:s,s:s,s:O,s:o,s:s}", "method", r->method, "path",
                               r->path, "summary", r->summary, "description", r->description,
                               "schema", request_schemas[i], "example", ex, "curl",
                               curl ? curl : "");
        free(curl);
        if (!op) { json_decref(ops); json_decref(res); return NULL; }
        if (response_schemas && response_schemas[i])
            json_object_set_new(op, "response_schema", json_deep_copy(response_schemas[i]));
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

/* The 401 of a /v1 path: only when the server runs with --token-file. */
static json_t *unauthorized_response(void)
{
    return json_pack("{s:s,s:{s:{s:s,s:{s:s}}},s:{s:{s:{s:s}}}}", "description",
                     "The server runs with --token-file and the request carries no bearer "
                     "token or a wrong one.",
                     "headers", "WWW-Authenticate", "description",
                     "Bearer realm=\"mechd\" (with error=\"invalid_token\" for a wrong token)",
                     "schema", "type", "string", "content", "application/problem+json",
                     "schema", "$ref", "#/components/schemas/Problem");
}

/* The content of a 200 answer of route i: its response schema (every route
 * has one, from its data file api/ops/<domain>/<operation>.json; the
 * fallback, any JSON object, is for a table built without one). */
static json_t *answer_content(size_t i)
{
    const json_t *rs = response_schemas ? response_schemas[i] : NULL;
    json_t *schema = rs ? json_deep_copy(rs) : json_pack("{s:s}", "type", "object");
    return json_pack("{s:{s:o}}", "application/json", "schema", schema);
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
                              "application/json", "schema", request_schemas[i]);
    json_t *etag_hdr = json_pack("{s:s,s:{s:s}}", "description",
                                 "strong tag of (build, path, canonical request)", "schema",
                                 "type", "string");
    json_t *cc_hdr = json_pack("{s:s,s:{s:s}}", "description", "public, max-age=86400", "schema",
                               "type", "string");
    json_t *ok = json_pack("{s:s,s:{s:O,s:O},s:o}", "description",
                           "The result, byte-identical to the POST answer without cost. An "
                           "answer that depends on the load or the deadline (a partial "
                           "/v1/compare) has no ETag and Cache-Control: no-store.",
                           "headers", "ETag", etag_hdr, "Cache-Control", cc_hdr, "content",
                           answer_content(i));
    json_t *nm = json_pack("{s:s,s:{s:O,s:O}}", "description",
                           "If-None-Match matched the ETag: no body, the operation is not run.",
                           "headers", "ETag", etag_hdr, "Cache-Control", cc_hdr);
    json_decref(etag_hdr);
    json_decref(cc_hdr);
    json_t *responses = json_pack("{s:o,s:o,s:o,s:o,s:o,s:o,s:o}", "200", ok, "304", nm, "400",
                                  problem_response("The request parameter is not JSON."), "401",
                                  unauthorized_response(), "422", problem_response(status_422),
                                  "500", problem_response("Internal error."), "503",
                                  problem_response("Queue full or shutting down; see Retry-After."));
    return json_pack("{s:s,s:s,s:s,s:[o],s:o}", "operationId", id, "summary", r->summary,
                     "description",
                     "The same operation as a cacheable GET: the measured cost is left out, so "
                     "equal requests give equal bytes and the same ETag; If-None-Match gives 304.",
                     "parameters", param, "responses", responses);
}

/* "/v1/rigid/inertia" -> "rigid_inertia" (n bytes of out). */
static void operation_id(const char *path, char *out, size_t n)
{
    snprintf(out, n, "%s", path + (strncmp(path, "/v1/", 4) ? 0 : 4));
    for (char *p = out; *p; p++)
        if (*p == '/') *p = '_';
}

/* A read-only resource that is not an operation (GET routes of the table and
 * the server's own resources): its 200, and the 4xx it can answer. */
static json_t *resource_get(const char *path, const char *opid, const char *summary,
                            const char *description, json_t *content)
{
    json_t *responses = json_pack("{s:{s:s,s:o}}", "200", "description", summary, "content",
                                  content);
    json_t *get = json_pack("{s:s,s:s,s:o}", "operationId", opid, "summary", summary,
                            "responses", responses);
    if (!get) return NULL;
    if (description) json_object_set_new(get, "description", json_string(description));
    if (needs_token(path))
        json_object_set_new(responses, "401", unauthorized_response());
    else
        json_object_set_new(get, "security", json_array()); /* open to anyone */
    if (strchr(path, '{')) {
        json_object_set_new(responses, "404", problem_response("No problem type has this slug."));
        json_object_set_new(
            get, "parameters",
            json_pack("[{s:s,s:s,s:b,s:s,s:{s:s,s:s}}]", "name", "slug", "in", "path", "required",
                      1, "description",
                      "the last segment of a problem's type URI (\"validation-error\")", "schema",
                      "type", "string", "pattern", "^[a-z0-9-]+$"));
    }
    return get;
}

/* components/schemas/Problem: every member mechd's problem+json bodies carry
 * (api/http/problem.c, api/run/call.c, api/ops/integrators/compare.c; a check of a wrong request
 * passes its inner problem's members on, hence additionalProperties). */
static const char problem_schema_text[] =
    "{\"type\":\"object\",\"description\":\"RFC 9457 problem details.\","
    "\"required\":[\"type\",\"title\",\"status\",\"detail\"],"
    "\"properties\":{"
    "\"type\":{\"type\":\"string\",\"format\":\"uri-reference\",\"description\":"
    "\"/problems/<slug>: GET it for what the problem means\"},"
    "\"title\":{\"type\":\"string\"},"
    "\"status\":{\"type\":\"integer\",\"minimum\":400,\"maximum\":599},"
    "\"detail\":{\"type\":\"string\",\"description\":\"what was wrong with this request\"},"
    "\"instance\":{\"type\":\"string\",\"format\":\"uri-reference\",\"description\":"
    "\"the request path\"},"
    "\"errors\":{\"type\":\"array\",\"description\":\"one entry per offending field\","
    "\"items\":{\"type\":\"object\",\"required\":[\"pointer\",\"detail\"],\"properties\":{"
    "\"pointer\":{\"type\":\"string\",\"description\":\"RFC 6901 JSON pointer into the "
    "request body\"},\"detail\":{\"type\":\"string\"}}}},"
    "\"progress\":{\"type\":\"object\",\"description\":\"compute-budget-exceeded and some "
    "numerical failures: how far the computation got\",\"properties\":{"
    "\"limit\":{\"type\":\"string\",\"enum\":[\"max_steps\",\"deadline\"]},"
    "\"steps\":{\"type\":\"integer\",\"minimum\":0},"
    "\"run_steps\":{\"type\":\"integer\",\"minimum\":0},"
    "\"samples_written\":{\"type\":\"integer\",\"minimum\":0},"
    "\"t_reached\":{\"type\":\"number\"},\"t_target\":{\"type\":\"number\"},"
    "\"fraction_done\":{\"type\":\"number\"}}},"
    "\"run\":{\"type\":\"string\",\"description\":\"/v1/compare: JSON pointer of the run that "
    "stopped\"}}}";

static const char bearer_description[] =
    "Only when the server runs with --token-file (MECHD_TOKEN_FILE): every request to /v1 and "
    "the paths under it must then carry Authorization: Bearer TOKEN, or gets 401. /healthz, "
    "/metrics, /problems/{slug} and the front end never ask for it. Without --token-file no "
    "request needs a token.";

/* Schema pieces the grading operations share, named in components/schemas so
 * that generated clients (openapi-typescript, @hey-api/openapi-ts) give them
 * one type each: a nested operation's request (any JSON object: its own
 * operation's schema validates it), and /v1/check's answer and tolerance.
 * name: where a member of an object schema moves to. */
static const struct shared_piece {
    const char *route, *pointer, *name;
} shared_pieces[] = {
    {"/v1/check", "/properties/request", "OperationRequest"},
    {"/v1/check", "/properties/answer", "CheckAnswer"},
    {"/v1/check", "/properties/tolerance", "CheckTolerance"},
    {"/v1/batch", "/properties/operations/items/properties/request", "OperationRequest"},
    {"/v1/batch", "/properties/operations/items", "BatchItem"},
};

/* The request schema of route i as the OpenAPI document shows it (new
 * reference): the route's own, or for the grading operations a copy whose
 * shared pieces are $refs into components (moved into `components`). */
static json_t *openapi_request_schema(size_t i, json_t *components)
{
    const char *path = api_routes[i]->path;
    json_t *copy = NULL;
    for (size_t k = 0; k < sizeof shared_pieces / sizeof shared_pieces[0]; k++) {
        const struct shared_piece *sp = &shared_pieces[k];
        if (strcmp(sp->route, path)) continue;
        if (!copy) copy = json_deep_copy(request_schemas[i]);
        /* walk to the parent of the piece */
        char buf[160];
        snprintf(buf, sizeof buf, "%s", sp->pointer);
        char *last = strrchr(buf, '/');
        if (!copy || !last) break;
        *last = '\0';
        json_t *parent = copy;
        char *save = NULL;
        for (char *tok = strtok_r(buf + 1, "/", &save); tok && parent;
             tok = strtok_r(NULL, "/", &save))
            parent = json_object_get(parent, tok);
        json_t *piece = json_object_get(parent, last + 1);
        if (!piece) continue;
        if (!json_object_get(components, sp->name)) {
            json_t *c = json_deep_copy(piece);
            /* any members: typed clients get an open object, not an empty one */
            if (!strcmp(sp->name, "OperationRequest") && !json_object_get(c, "additionalProperties"))
                json_object_set_new(c, "additionalProperties", json_object());
            json_object_set_new(components, sp->name, c);
        }
        char ref[96];
        snprintf(ref, sizeof ref, "#/components/schemas/%s", sp->name);
        json_object_set_new(parent, last + 1, json_pack("{s:s}", "$ref", ref));
    }
    return copy ? copy : json_incref((json_t *)request_schemas[i]);
}

static json_t *build_openapi(void)
{
    json_t *paths = json_object();
    json_t *shared = json_object(); /* components/schemas of the shared pieces */
    for (size_t i = 0; i < api_route_count; i++) {
        const struct api_route *r = api_routes[i];
        char opid[128];
        operation_id(r->path, opid, sizeof opid);
        if (!strcmp(r->method, "GET")) {
            json_t *get = resource_get(r->path, opid, r->summary, r->description,
                                       answer_content(i));
            json_object_set_new(paths, r->path, json_pack("{s:o}", "get", get));
            continue;
        }
        json_t *ex = json_loads(r->example, 0, NULL);
        json_t *responses = json_pack(
            "{s:{s:s,s:o},s:o,s:o,s:o,s:o,s:o,s:o,s:o,s:o}", "200", "description",
            "The result.", "content", answer_content(i), "400",
            problem_response("Malformed JSON."), "401", unauthorized_response(), "413",
            problem_response("Body too large."), "415", problem_response("Not application/json."),
            "422", problem_response(status_422), "500", problem_response("Internal error."),
            "503", problem_response("Queue full or shutting down; see Retry-After."), "405",
            problem_response("Wrong method."));
        json_t *op = json_pack("{s:s,s:s,s:s,s:{s:b,s:{s:{s:o,s:o}}},s:o}", "operationId", opid,
                               "summary", r->summary, "description", r->description,
                               "requestBody", "required", 1, "content", "application/json",
                               "schema", openapi_request_schema(i, shared), "example", ex,
                               "responses", responses);
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
        json_t *get = resource_get(resources[i].path, resources[i].operation_id,
                                   resources[i].summary, NULL,
                                   json_pack("{s:{}}", resources[i].content_type));
        json_object_set_new(paths, resources[i].path, json_pack("{s:o}", "get", get));
    }
    json_t *problem_schema = json_loads(problem_schema_text, 0, NULL);
    json_t *doc = json_pack("{s:s,s:{s:s,s:s,s:s},s:[{s:s,s:s}],s:[{s:[]}],s:o,"
                     "s:{s:{s:o,s:o},s:{s:{s:s,s:s,s:s}}}}",
                     "openapi", "3.1.0", "info", "title", "mechd", "version", MECHD_VERSION,
                     "description", service_description, "servers", "url", "/", "description",
                     "the server that serves this document", "security", "bearerAuth", "paths",
                     paths, "components", "schemas", "Problem", problem_schema, "Envelope",
                     envelope_schema(), "securitySchemes", "bearerAuth", "type", "http",
                     "scheme", "bearer", "description", bearer_description);
    json_t *schemas = json_object_get(json_object_get(doc, "components"), "schemas");
    if (schemas) json_object_update(schemas, shared);
    json_decref(shared);
    return doc;
}

/* ---- numbers as a reader expects them ----------------------------------------------
 *
 * The documents hold numbers as their authors wrote them, but jansson prints a
 * real with %.17g plus ".0" when that has no '.' or 'e': 1e6 as 1000000.0 and
 * 0.1 as 0.10000000000000001. The documents (never an answer: answers' numbers
 * are reals on purpose) are tidied before printing: a real with an integral
 * value of at most 2^53 becomes an integer, and each real prints as the
 * shortest of %.15g, %.16g, %.17g that reads back as the same double (0.1,
 * 3.141592653589793). Every number reads back as the same double. */

/* Turn integral reals of j (an owned tree) into integers. */
static json_t *tidy_number(json_t *v)
{
    double x = json_real_value(v);
    if (json_is_real(v) && fabs(x) <= 9007199254740992.0 && x == (double)(json_int_t)x)
        return json_integer((json_int_t)x);
    return NULL;
}

static void tidy_numbers(json_t *j)
{
    if (json_is_object(j)) {
        const char *k;
        json_t *v, *n;
        json_object_foreach(j, k, v) {
            if ((n = tidy_number(v)))
                json_object_set_new_nocheck(j, k, n);
            else
                tidy_numbers(v);
        }
    } else if (json_is_array(j)) {
        for (size_t i = 0; i < json_array_size(j); i++) {
            json_t *v = json_array_get(j, i), *n;
            if ((n = tidy_number(v)))
                json_array_set_new(j, i, n);
            else
                tidy_numbers(v);
        }
    }
}

/* Rewrite, in place, every number token of the JSON text s that holds a '.'
 * or an exponent as the shortest %.15g/%.16g/%.17g text that reads back as
 * the same double (never longer than jansson's %.17g text it replaces).
 * Strings are copied untouched. */
static void shorten_reals(char *s)
{
    char *out = s;
    int in_string = 0;
    for (const char *p = s; *p;) {
        if (in_string) {
            if (*p == '\\' && p[1]) { *out++ = *p++; *out++ = *p++; continue; }
            if (*p == '"') in_string = 0;
            *out++ = *p++;
            continue;
        }
        if (*p == '"') { in_string = 1; *out++ = *p++; continue; }
        if (*p != '-' && (*p < '0' || *p > '9')) { *out++ = *p++; continue; }
        size_t len = strspn(p, "0123456789+-.eE");
        char tok[48], best[48];
        if (len >= sizeof tok || (!memchr(p, '.', len) && !memchr(p, 'e', len))) {
            memmove(out, p, len);
            out += len;
            p += len;
            continue;
        }
        memcpy(tok, p, len);
        tok[len] = '\0';
        double x = strtod(tok, NULL);
        snprintf(best, sizeof best, "%s", tok);
        for (int digits = 15; digits <= 17; digits++) {
            char t[48];
            snprintf(t, sizeof t, "%.*g", digits, x);
            if (strtod(t, NULL) == x) {
                if (strlen(t) < strlen(best)) snprintf(best, sizeof best, "%s", t);
                break;
            }
        }
        size_t bl = strlen(best);
        memcpy(out, best, bl);
        out += bl;
        p += len;
    }
    *out = '\0';
}

/* doc printed with tidy numbers (malloc'd text, or NULL); doc is not changed
 * (it shares the validator's schema trees). */
static char *dump_tidy(const json_t *doc)
{
    json_t *copy = doc ? json_deep_copy(doc) : NULL;
    if (!copy) return NULL;
    tidy_numbers(copy);
    char *text = json_dumps(copy, JSON_INDENT(2) | JSON_REAL_PRECISION(17));
    json_decref(copy);
    if (text) shorten_reals(text);
    return text;
}

int api_catalog_init(const json_t *const *request, const json_t *const *response, char *err,
                     size_t n)
{
    request_schemas = request;
    response_schemas = response;
    json_t *c = build_catalog();
    json_t *o = build_openapi();
    request_schemas = response_schemas = NULL;
    catalog_text = dump_tidy(c);
    openapi_text = dump_tidy(o);
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
