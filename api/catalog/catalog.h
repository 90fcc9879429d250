/* catalog.h — the self-description of the API, generated once from the route
 * table: GET /v1 (catalog) and GET /v1/openapi.json (OpenAPI 3.1). */
#ifndef API_CATALOG_H
#define API_CATALOG_H

#include <jansson.h>
#include <stddef.h>

/* Build both documents (called once from api_init). request[i] and
 * response[i] are route i's parsed request and answer schemas (api_routes
 * order; NULL for none), borrowed for the call. 0 on success, else -1 with a
 * message in err. */
int api_catalog_init(const json_t *const *request, const json_t *const *response, char *err,
                     size_t n);

/* The serialised documents (static after init; never NULL after success). */
const char *api_catalog_text(void);
const char *api_openapi_text(void);

#endif
