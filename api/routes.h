/* routes.h — the route table (defined in routes.c). */
#ifndef API_ROUTES_H
#define API_ROUTES_H

#include <stddef.h>

#include "endpoint.h"

extern const struct api_route *const api_routes[];
extern const size_t api_route_count;

#endif
