/* json_write.h — compact serialisation of a jansson tree for responses:
 * the text json_dumps(JSON_COMPACT) writes, byte for byte, except that reals
 * are printed by api_real_format() (the shortest text that reads back as the
 * same double) instead of jansson's %.17g. */
#ifndef API_JSON_WRITE_H
#define API_JSON_WRITE_H

#include <jansson.h>
#include <stddef.h>

/* Deepest nesting written without asking json_dumps() first (the root is
 * depth 0); a deeper tree is written only when json_dumps() accepts it (no
 * reference cycle), with the same text, slower. */
#define API_JSON_WRITE_MAX_DEPTH 128

/* Serialise j (borrowed; any type, as with JSON_ENCODE_ANY) compactly, then
 * append suffix (may be NULL). Returns a NUL-terminated text allocated with
 * malloc() (the caller frees it with free()) and its length without the NUL
 * in *len (len may be NULL); NULL when memory runs out, and in the cases
 * where json_dumps() itself fails (j NULL, a string that is not valid UTF-8,
 * a reference cycle).
 *
 * Output: byte-identical to json_dumps(j, JSON_COMPACT | JSON_ENCODE_ANY)
 * (jansson 2.14) for every tree without reals: objects in jansson's
 * iteration order (insertion order), strings escaped as jansson does without
 * JSON_ENSURE_ASCII / JSON_ESCAPE_SLASH (\" \\ \b \f \n \r \t, other controls
 * as \u00XX upper-case, UTF-8 as is), integers as JSON_INTEGER_FORMAT; reals
 * as api_real_format() (api/json/real_format.h: shortest round-trip digits, laid out
 * as %.17g lays them out). Where json_dumps() fails, so does this.
 * The buffer grows geometrically (realloc, doubling). Thread-safe for trees
 * no other thread modifies. */
char *api_json_write_compact(const json_t *j, const char *suffix, size_t *len);

#endif
