/* api_docs.h — GET /v1 and GET /v1/openapi.json (api/catalog/api_docs.c). */
#ifndef API_API_DOCS_H
#define API_API_DOCS_H

#include "api.h"

/* Take the catalog's and the OpenAPI document's text (api/catalog/catalog.c, after
 * api_catalog_init) and their ETags. Returns 0, or -1 when either text is
 * missing. Once, at api_init. */
int api_docs_init(void);

/* Answer a GET/HEAD of /v1 (catalog) or /v1/openapi.json into resp (cleared
 * first): 200 with the document as static memory (gzip when ext's
 * Accept-Encoding admits it), or 304 for a matching If-None-Match. ext may be
 * NULL. Cannot fail: without memory for the gzip copy the identity is sent. */
void api_docs_serve_catalog(const struct api_request_ext *ext, struct api_response *resp);
void api_docs_serve_openapi(const struct api_request_ext *ext, struct api_response *resp);

#endif
