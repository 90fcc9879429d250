/* schema.h — a validator for the subset of JSON Schema (2020-12) that mechd's
 * route schemas use. The same schema text is served in the catalog and the
 * OpenAPI document and enforced here, so the documentation cannot drift from
 * what the server accepts.
 *
 * Supported keywords: type (name or array of names; "integer" means a number
 * with an integral value), properties, required, additionalProperties (false
 * only), items (one schema), minItems, maxItems, uniqueItems, minimum, maximum,
 * exclusiveMinimum, exclusiveMaximum, enum, const, oneOf, minProperties,
 * maxProperties. Annotations (title, description, default, examples) are
 * ignored. Anything else is refused by api_schema_check(), so a route cannot
 * silently rely on an unsupported keyword.
 */
#ifndef API_SCHEMA_H
#define API_SCHEMA_H

#include <jansson.h>
#include <stddef.h>

/* Most errors one validation reports; more are counted but not listed. */
#define API_SCHEMA_MAX_ERRORS 20

/* Validate `instance` against `schema` (both borrowed). `pointer` is the JSON
 * pointer of instance ("" for the document root). Each violation appends
 * {"pointer", "detail"} to `errors` (a JSON array, borrowed), at most
 * API_SCHEMA_MAX_ERRORS in all. Returns the number of violations found
 * (possibly more than were appended). Reentrant; schema is only read. */
size_t api_schema_validate(const json_t *schema, const json_t *instance,
                           const char *pointer, json_t *errors);

/* Check that `schema` uses only the supported keywords with well-formed values.
 * Returns 0 if it does; otherwise -1 with a message in msg (n bytes). */
int api_schema_check(const json_t *schema, char *msg, size_t n);

/* Append the RFC 6901 escape of `token` ('~' -> "~0", '/' -> "~1") to the
 * pointer in buf (capacity n), preceded by '/'. Truncates safely. */
void api_pointer_append(char *buf, size_t n, const char *token);

#endif
