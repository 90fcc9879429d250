/* catalog.h — the self-description of the API, generated once from the route
 * table: GET /v1 (catalog) and GET /v1/openapi.json (OpenAPI 3.1). */
#ifndef API_CATALOG_H
#define API_CATALOG_H

#include <jansson.h>
#include <stddef.h>

/* Build both documents (called once from api_init). 0 on success, else -1
 * with a message in err. */
int api_catalog_init(char *err, size_t n);

/* The serialised documents (static after init; never NULL after success). */
const char *api_catalog_text(void);
const char *api_openapi_text(void);

/* Parsed schema of route i (borrowed; NULL before init). */
const json_t *api_route_schema(size_t i);

/* Compiled schema of route i, for api_schema_validate (borrowed; lives for
 * the process; NULL before init and for GET routes). */
struct api_schema;
const struct api_schema *api_route_schema_compiled(size_t i);

#endif
