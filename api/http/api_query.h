/* api_query.h — GET ?request= (api/http/api_query.c). */
#ifndef API_API_QUERY_H
#define API_API_QUERY_H

#include <stddef.h>

#include "api.h"

struct api_full_request; /* api/run/api_run.h */

/* Run POST operation ri on ext->query_request (the request JSON, decoded;
 * not NULL) and answer into resp, with its ETag and Cache-Control. */
void api_run_query(size_t ri, struct api_full_request *req, const struct api_request_ext *ext,
                   struct api_response *resp);

#endif
