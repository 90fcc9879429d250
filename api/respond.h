/* respond.h — internal helpers of the api layer: building responses and
 * problem objects. Not for endpoints (they use endpoint.h). */
#ifndef API_RESPOND_H
#define API_RESPOND_H

#include <jansson.h>

#include "api.h"

/* Serialise `body` (borrowed; may be NULL, which gives a 500) into resp with
 * the given status and content type. Reals print with 17 significant digits.
 * On allocation failure resp becomes a fixed 500 problem. */
void api_respond_json(struct api_response *resp, int status, const char *content_type,
                      const json_t *body);

/* Copy a NUL-terminated text into resp. */
void api_respond_text(struct api_response *resp, int status, const char *content_type,
                      const char *text);

/* New problem object {type, title, status, detail} (NULL on allocation failure). */
json_t *api_problem_object(enum api_problem kind, const char *detail);

/* Longer description of a problem kind (served at GET /problems/<slug>). */
const char *api_problem_description(enum api_problem kind);

/* Problem kind whose type URI ends in slug, or API_PROBLEM_NONE. */
enum api_problem api_problem_by_slug(const char *slug);

#endif
