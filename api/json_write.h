/* json_write.h — compact serialisation of a jansson tree for responses:
 * the text json_dumps(JSON_COMPACT | JSON_REAL_PRECISION(17)) writes, byte
 * for byte, with reals printed by api_real_format() instead of glibc's
 * exact %.17g conversion. */
#ifndef API_JSON_WRITE_H
#define API_JSON_WRITE_H

#include <jansson.h>
#include <stddef.h>

/* Deepest nesting written directly (the root is depth 0); a deeper tree is
 * handed to json_dumps() and its text copied (same bytes, slower). */
#define API_JSON_WRITE_MAX_DEPTH 128

/* Serialise j (borrowed; any type, as with JSON_ENCODE_ANY) compactly, then
 * append suffix (may be NULL). Returns a NUL-terminated text allocated with
 * malloc() (the caller frees it with free()) and its length without the NUL
 * in *len (len may be NULL); NULL when memory runs out, and in the cases
 * where json_dumps() itself fails (j NULL, a string that is not valid UTF-8,
 * a reference cycle).
 *
 * Output: byte-identical to json_dumps(j, JSON_COMPACT | JSON_ENCODE_ANY |
 * JSON_REAL_PRECISION(17)) (jansson 2.14) for every tree: objects in jansson's iteration order (insertion order), strings
 * escaped as jansson does without JSON_ENSURE_ASCII / JSON_ESCAPE_SLASH
 * (\" \\ \b \f \n \r \t, other controls as \u00XX upper-case, UTF-8 as is),
 * integers as JSON_INTEGER_FORMAT, reals as api_real_format() (jansson's
 * %.17g text). Strings that are not valid UTF-8
 * and trees deeper than API_JSON_WRITE_MAX_DEPTH go through json_dumps().
 * The buffer grows geometrically (realloc, doubling). Thread-safe for trees
 * no other thread modifies. */
char *api_json_write_compact(const json_t *j, const char *suffix, size_t *len);

#endif
