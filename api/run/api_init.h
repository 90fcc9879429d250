/* api_init.h — the route table's lookups that the pipeline's files share
 * (api/run/api_init.c; the public ones are in api.h and api/run/routes.h). */
#ifndef API_API_INIT_H
#define API_API_INIT_H

#include <stddef.h>

/* The index of the route at path (NUL-terminated, borrowed), or -1. */
long api_route_index(const char *path);

/* Route ri's schema default for a top-level "samples" (0 if none or out of
 * range), and whether its requests can ask for samples at all (its schema
 * names samples, or it runs other operations: /v1/batch, /v1/check). Both 0
 * before api_init. */
double api_route_default_samples(size_t ri);
int api_route_counts_samples(size_t ri);

#endif
