/* json_read.h — request-body parser: json_loadb(JSON_DECODE_INT_AS_REAL |
 * JSON_REJECT_DUPLICATES) with a fast path for plain documents and jansson
 * itself for everything else (see api/json/json_read.c). */
#ifndef API_JSON_READ_H
#define API_JSON_READ_H

#include <jansson.h>
#include <stddef.h>

/* Deepest nesting the fast path parses (the root container is depth 1); a
 * deeper document goes to json_loadb(). */
#define API_JSON_READ_MAX_DEPTH 64

/* Longest number token the fast path converts; a longer one goes to
 * json_loadb(). */
#define API_JSON_READ_MAX_NUMBER 96

/* Parse len bytes at text (need not be NUL-terminated; NULL as with
 * json_loadb). Same contract as json_loadb(text, len, JSON_DECODE_INT_AS_REAL |
 * JSON_REJECT_DUPLICATES, err) in jansson 2.14: a new reference to the
 * top-level object or array (the caller owns it), or NULL with err (may be
 * NULL) holding jansson's error — identical text, line, column, position,
 * source and code. On success err is left as json_loadb leaves it (text "",
 * line and column -1, position len, source "<buffer>").
 *
 * Only difference: when memory runs out in the fast path, the answer is NULL
 * with err text "out of memory", code json_error_out_of_memory, line and
 * column -1 (jansson 2.14 reports nothing in that case). Every allocation
 * goes through jansson's allocator (json_set_alloc_funcs). Thread-safe;
 * recursion bounded by API_JSON_READ_MAX_DEPTH. */
json_t *api_json_read(const char *text, size_t len, json_error_t *err);

/* The fast path alone: 1 = parsed (*out a new reference, err as on success
 * above), 0 = not a plain document (nothing built, *out NULL, err untouched:
 * api_json_read() would hand it to json_loadb()), -1 = memory ran out (*out
 * NULL, err as above). For tests and the allocation sweep. */
int api_json_read_plain(const char *text, size_t len, json_t **out, json_error_t *err);

/* One JSON number token at text (bytes up to stop, exclusive; text < stop),
 * valued exactly as api_json_read() values it (strtod() on the token, as
 * jansson with JSON_DECODE_INT_AS_REAL): the end of the token, *value set,
 * or NULL when the bytes at text do not start a number in JSON's grammar
 * -?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?, the token is longer than
 * API_JSON_READ_MAX_NUMBER, or it overflows (the cases api_json_read() hands
 * to jansson). What follows the token is not looked at. Thread-safe. */
const char *api_json_number_scan(const char *text, const char *stop, double *value);

#endif
