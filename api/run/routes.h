/* routes.h — the route table (defined in api/run/routes.c, expanded from the
 * build's generated ops.def: one entry per api/ops/<domain>/<operation>.json,
 * in api/ops/catalog_order.json's order). */
#ifndef API_ROUTES_H
#define API_ROUTES_H

#include <stddef.h>

#include <jansson.h>

#include "run/endpoint.h"

extern const struct api_route *const api_routes[];
extern const size_t api_route_count;

/* The envelope keys (JSON text of a "properties" object: {"cost": {...}}),
 * documented once in the catalog and the OpenAPI document. */
extern const char api_envelope_properties[];

/* Add the envelope keys to the root "properties" of a POST route's parsed
 * schema (modified in place; jansson's allocator). Returns 0, or -1 with a
 * message in msg (n bytes) when the root is not an object schema with
 * properties, declares an envelope key itself, or memory ran out. */
int api_route_schema_add_envelope(json_t *schema, char *msg, size_t n);

/* Parsed schema of route i (borrowed; NULL before api_init()). Defined in
 * api/run/api_init.c, which parses every route's schema once. */
const json_t *api_route_schema(size_t i);

/* Compiled schema of route i, for api_schema_validate (borrowed; lives for
 * the process; NULL before init and for GET routes). */
struct api_schema;
const struct api_schema *api_route_schema_compiled(size_t i);

/* Parsed answer schema of route i (its response_schema text; borrowed),
 * NULL when the route does not describe its answer or before init. */
const json_t *api_route_response_schema(size_t i);

#endif
