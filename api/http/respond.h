/* respond.h — internal helpers of the api layer: building responses and
 * problem objects. Not for endpoints (they use api/run/endpoint.h). */
#ifndef API_RESPOND_H
#define API_RESPOND_H

#include <jansson.h>

#include "api.h"

/* Serialise `body` (borrowed; an object or array; NULL or anything else gives
 * a 500) compactly into resp, plus a trailing newline, with the given status
 * and content type, through api_json_write_compact() (api/json/json_write.h):
 * byte for byte json_dumps(JSON_COMPACT | JSON_REAL_PRECISION(17)), reals
 * with 17 significant digits (api/json/real_format.h), several times faster.
 * On allocation failure resp becomes the fixed 500 problem. */
void api_respond_json(struct api_response *resp, int status, const char *content_type,
                      const json_t *body);

/* Replace whatever resp holds (its body is freed) with the fixed 500
 * internal-error problem saying memory ran out; built without jansson, so it
 * works when allocation does not (body NULL if even the copy fails: the
 * server then sends the 500 with an empty body). */
void api_respond_out_of_memory(struct api_response *resp);

/* Copy a NUL-terminated text into resp. */
void api_respond_text(struct api_response *resp, int status, const char *content_type,
                      const char *text);

/* A JSON string of text that may hold bytes from the client (a path, a key,
 * truncated by a "%.Ns" format inside a multi-byte character): json_string()
 * refuses invalid UTF-8 and returns NULL, which would silently drop the member
 * it was meant for. Bytes that do not form valid UTF-8 become '?'. New
 * reference; NULL only when out of memory. */
json_t *api_json_text(const char *text);

/* {"pointer": ..., "detail": ...} with both made safe by api_json_text(). */
json_t *api_error_entry(const char *pointer, const char *detail);

/* New problem object {type, title, status, detail} (NULL on allocation failure). */
json_t *api_problem_object(enum api_problem kind, const char *detail);

/* Longer description of a problem kind (served at GET /problems/<slug>). */
const char *api_problem_description(enum api_problem kind);

/* Problem kind whose type URI ends in slug, or API_PROBLEM_NONE. */
enum api_problem api_problem_by_slug(const char *slug);

#endif
