/* api_init.c — the route table made ready, once (api_init, api.h): every
 * route's schema parsed, given the envelope keys, checked and compiled, its
 * example validated, its answer schema parsed, its samples default noted; the
 * catalog and the OpenAPI document written (api/catalog/catalog.c, api/catalog/api_docs.c). Also the
 * lookups of the table that the pipeline and the server make (api.h,
 * api/run/routes.h, api/run/api_init.h). */
#include "run/api_init.h"

#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <jansson.h>

#include "api.h"
#include "json/api_alloc.h"
#include "catalog/api_docs.h"
#include "catalog/catalog.h"
#include "run/routes.h"
#include "schema/schema.h"

/* Parsed route schemas, index-aligned with api_routes; read-only after init.
 * route_compiled[i] is route_schemas[i] compiled (it borrows from it); both
 * live for the whole process (api.h has no shutdown: they stay reachable
 * through these pointers, which leak checkers do not report). */
static json_t **route_schemas;
static struct api_schema **route_compiled;
/* Parsed answer schemas (each route's response_schema, from its data file). */
static json_t **route_responses;
/* Per route: its schema's default for a top-level "samples" (0 if none), and
 * whether its requests can ask for samples at all (its schema names samples,
 * or it runs other operations: /v1/batch, /v1/check). */
static double *route_default_samples;
static unsigned char *route_counts_samples;
static int init_status = -1;
static char init_error[300] = "api_init not run";
static pthread_once_t init_once = PTHREAD_ONCE_INIT;

static int init_routes(void)
{
    route_schemas = calloc(api_route_count, sizeof *route_schemas);
    route_compiled = calloc(api_route_count, sizeof *route_compiled);
    route_default_samples = calloc(api_route_count, sizeof *route_default_samples);
    route_counts_samples = calloc(api_route_count, sizeof *route_counts_samples);
    route_responses = calloc(api_route_count, sizeof *route_responses);
    if (!route_schemas || !route_compiled || !route_default_samples || !route_counts_samples ||
        !route_responses) {
        snprintf(init_error, sizeof init_error, "out of memory");
        return -1;
    }
    for (size_t i = 0; i < api_route_count; i++) {
        const struct api_route *r = api_routes[i];
        json_error_t jerr;
        char msg[200];
        /* Parsed as written (integers stay integers in the documents). */
        if (r->response_schema) {
            route_responses[i] = json_loads(r->response_schema, 0, &jerr);
            if (!json_is_object(route_responses[i])) {
                snprintf(init_error, sizeof init_error,
                         "%s: response_schema is not a JSON object (line %d: %s)", r->path,
                         jerr.line, route_responses[i] ? "not an object" : jerr.text);
                return -1;
            }
        }
        if (!strcmp(r->method, "GET")) {
            /* A read-only resource: no body, so no schema or example. */
            if (r->schema || r->example) {
                snprintf(init_error, sizeof init_error, "%s: a GET route takes no body", r->path);
                return -1;
            }
            continue;
        }
        /* Parsed as written: the validator reads numbers with
         * json_number_value(), and the catalog prints integers as integers. */
        json_t *s = json_loads(r->schema, 0, &jerr);
        if (!s) {
            snprintf(init_error, sizeof init_error, "%s: schema is not JSON (line %d: %s)",
                     r->path, jerr.line, jerr.text);
            return -1;
        }
        route_schemas[i] = s;
        /* Every operation takes the envelope keys ("cost"): added here, once. */
        if (api_route_schema_add_envelope(s, msg, sizeof msg)) {
            snprintf(init_error, sizeof init_error, "%s: schema: %s", r->path, msg);
            return -1;
        }
        json_t *def = json_object_get(
            json_object_get(json_object_get(s, "properties"), "samples"), "default");
        route_default_samples[i] = json_is_number(def) ? json_number_value(def) : 0;
        route_counts_samples[i] =
            strstr(r->schema, "\"samples\"") != NULL || strstr(r->schema, "\"operation\"") != NULL;
        /* Checked and compiled once; requests are validated against the tree. */
        route_compiled[i] = api_schema_compile(s, msg, sizeof msg);
        if (!route_compiled[i]) {
            snprintf(init_error, sizeof init_error, "%s: schema: %s", r->path, msg);
            return -1;
        }
        /* The catalog's example must be a request the schema accepts. */
        json_t *ex = json_loads(r->example, JSON_DECODE_INT_AS_REAL, &jerr);
        size_t nerr = ex ? api_schema_validate(route_compiled[i], ex, "", NULL) : 1;
        json_decref(ex);
        if (nerr) {
            snprintf(init_error, sizeof init_error, "%s: example does not match its schema",
                     r->path);
            return -1;
        }
    }
    if (api_catalog_init((const json_t *const *)route_schemas,
                         (const json_t *const *)route_responses, init_error, sizeof init_error))
        return -1;
    if (api_docs_init()) {
        snprintf(init_error, sizeof init_error, "the catalog or OpenAPI text is missing");
        return -1;
    }
    return 0;
}

static void init_once_fn(void)
{
    if (!api_json_allocator_installed()) {
        /* Process-wide set-up belongs to main(), before any thread starts. */
        snprintf(init_error, sizeof init_error,
                 "api_install_json_allocator() was not called before api_init() (main's set-up)");
        init_status = -1;
        return;
    }
    init_status = init_routes();
}

int api_init(void)
{
    pthread_once(&init_once, init_once_fn);
    return init_status;
}

const char *api_init_error(void)
{
    return init_status == 0 ? NULL : init_error;
}

const json_t *api_route_schema(size_t i)
{
    return i < api_route_count && route_schemas ? route_schemas[i] : NULL;
}

const struct api_schema *api_route_schema_compiled(size_t i)
{
    return i < api_route_count && route_compiled ? route_compiled[i] : NULL;
}

const json_t *api_route_response_schema(size_t i)
{
    return i < api_route_count && route_responses ? route_responses[i] : NULL;
}

long api_route_index(const char *path)
{
    for (size_t i = 0; i < api_route_count; i++)
        if (!strcmp(api_routes[i]->path, path)) return (long)i;
    return -1;
}

int api_is_inline(const char *method, const char *path)
{
    /* Only POST operations compute; GET routes return precomputed or cheap
     * descriptions and answer on the I/O thread. */
    return !(method && path && !strcmp(method, "POST") && api_route_index(path) >= 0);
}

long api_quick_route(const char *method, const char *path, size_t body_len)
{
    (void)body_len; /* any size: the server decides from the predicted cost */
    if (!method || !path || strcmp(method, "POST") != 0) return -1;
    long ri = api_route_index(path);
    return ri >= 0 && api_routes[ri]->quick ? ri : -1;
}

long api_gated_route(const char *method, const char *path)
{
    /* The operations whose handlers call api_call_cost_gate before they
     * integrate: the trajectory's chooser predicts its CPU. */
    static const char *const gated[] = {"/v1/trajectory"};
    if (!method || !path || strcmp(method, "POST") != 0) return -1;
    for (size_t i = 0; i < sizeof gated / sizeof gated[0]; i++)
        if (!strcmp(path, gated[i])) return api_route_index(path);
    return -1;
}

size_t api_operation_count(void)
{
    return api_route_count;
}

const char *api_operation_path(size_t i)
{
    return i < api_route_count ? api_routes[i]->path : NULL;
}

const char *api_operation_method(size_t i)
{
    return i < api_route_count ? api_routes[i]->method : NULL;
}

int api_operation_quick(size_t i)
{
    return i < api_route_count && api_routes[i]->quick;
}

double api_route_default_samples(size_t ri)
{
    return ri < api_route_count && route_default_samples ? route_default_samples[ri] : 0;
}

int api_route_counts_samples(size_t ri)
{
    return ri < api_route_count && route_counts_samples ? route_counts_samples[ri] : 0;
}
