/* schema.h — a validator for the subset of JSON Schema (2020-12) that mechd's
 * route schemas use. The same schema text is served in the catalog and the
 * OpenAPI document and enforced here, so the documentation cannot drift from
 * what the server accepts.
 *
 * Supported keywords: type (name or array of names; "integer" means a number
 * with an integral value), properties, required, additionalProperties (false
 * only), items (one schema), minItems, maxItems, uniqueItems, minimum, maximum,
 * exclusiveMinimum, exclusiveMaximum, enum, const, oneOf (at most
 * API_SCHEMA_MAX_BRANCHES branches), minProperties, maxProperties.
 * Annotations (title, description, examples) are ignored by validation;
 * "default" is applied by api_schema_apply_defaults. Anything
 * else is refused by api_schema_check(), so a route cannot silently rely on
 * an unsupported keyword.
 *
 * A schema is compiled once (api_schema_compile, at api_init) into a tree of
 * C structures: keyword values as doubles and flags, property names as
 * (pointer, length) pairs, the messages that depend only on the schema (type
 * names, allowed keys, const/enum text) formatted in advance, and for each
 * oneOf branch what tells it apart from its siblings (the properties that
 * hold a `const`, the JSON types of it and of its items, the keys it knows).
 * Validating a request then walks that tree and the instance only; it never
 * looks a keyword up in the schema's jansson objects.
 *
 * This header is the validator's only face. Behind it, one file a concept
 * (api/schema/schema_internal.h lists them and their one-way arrows): the subset and the
 * self-check (api/schema/schema_check.c), compilation (api/schema/schema_compile.c), the walker
 * (api/schema/schema_validate.c), the choice among oneOf branches (api/schema/schema_branch.c),
 * the error list (api/schema/schema_error.c), defaults (api/schema/schema_defaults.c) and JSON
 * pointers (api/schema/schema_error.c).
 */
#ifndef API_SCHEMA_H
#define API_SCHEMA_H

#include <jansson.h>
#include <stddef.h>

/* Most errors one validation reports; more are counted but not listed. */
#define API_SCHEMA_MAX_ERRORS 20

/* Deepest nesting of subschemas (properties / items / oneOf, the root being
 * depth 0) that api_schema_check and api_schema_compile accept. Validation
 * recurses only along the compiled tree, so this bounds its recursion whatever
 * the instance (whose own depth jansson's parser caps at
 * JSON_PARSER_MAX_DEPTH, 2048). mechd's deepest route schema is far below. */
#define API_SCHEMA_MAX_DEPTH 32

/* Most branches of one oneOf that api_schema_check accepts. */
#define API_SCHEMA_MAX_BRANCHES 64

/* A compiled schema (opaque). Immutable after api_schema_compile, so one tree
 * may be used by any number of threads at once. */
struct api_schema;

/* Check `schema` (as api_schema_check does) and compile it. Returns a new tree
 * (free with api_schema_free), or NULL with a message in msg (n bytes) when
 * the schema is malformed, nests deeper than API_SCHEMA_MAX_DEPTH, or memory
 * ran out. Ownership: the tree BORROWS from `schema` (property names, required
 * names, const and enum values point into it), so `schema` must stay alive and
 * unchanged for as long as the tree is used; mechd's route schemas live for
 * the whole process. Allocates with malloc (not jansson's allocator). */
struct api_schema *api_schema_compile(const json_t *schema, char *msg, size_t n);

/* Free a tree from api_schema_compile (NULL is allowed). `schema` is not
 * touched. */
void api_schema_free(struct api_schema *s);

/* Validate `instance` (borrowed) against the compiled schema `s`. `pointer`
 * is the JSON pointer of instance ("" or NULL for the document root). Each
 * violation appends {"pointer", "detail"} to `errors` (a JSON array, borrowed),
 * at most API_SCHEMA_MAX_ERRORS entries in the array in all. With errors ==
 * NULL only counts: no message or pointer is formatted. Returns the number of
 * violations found (possibly more than were appended). Reentrant; s is only
 * read. When an instance matches no branch of a oneOf, the branch it was
 * meant to be is chosen by what tells the branches apart — its JSON type, the
 * value of a discriminator key (a property a branch requires to be a const:
 * "type", "shape"), the JSON type of an array's items, the keys only some
 * branches know (a velocity's "beta" or "rapidity") — then by the fewest
 * errors, and that branch's errors are reported; when the choice itself is
 * wrong the error says so: "must be a string or an object, got number",
 * "unknown type \"foo\"; expected one of ...", "matches none of the allowed
 * forms; give one of {beta}, {rapidity, direction}, ..." (api/schema/schema_branch.c
 * has the rules in order). s == NULL
 * acts as the empty schema (returns 0); callers pass a compiled route schema,
 * which every POST route has once api_init succeeded. */
size_t api_schema_validate(const struct api_schema *s, const json_t *instance,
                           const char *pointer, json_t *errors);

/* Check that `schema` uses only the supported keywords with well-formed values
 * and nests at most API_SCHEMA_MAX_DEPTH deep. Returns 0 if it does; otherwise
 * -1 with a message in msg (n bytes). */
int api_schema_check(const json_t *schema, char *msg, size_t n);

/* Append the RFC 6901 escape of `token` ('~' -> "~0", '/' -> "~1") to the
 * pointer in buf (capacity n), preceded by '/'. Truncates safely. */
void api_pointer_append(char *buf, size_t n, const char *token);

/* The instance with every default of the schema filled in: for each object
 * the schema describes (through properties, items and the matching oneOf
 * branch), each property that is absent and whose schema states a "default"
 * is added with that default — an integer default as a real, as the request
 * parser reads numbers (api/json/json_read.h), so a handler sees what an explicit
 * request would give. `instance` (borrowed) must have passed
 * api_schema_validate against the same schema, and is never modified: the
 * result is a new reference, the instance itself when nothing was missing
 * (no copy), else a copy sharing every unchanged member. Root keys named in
 * skip_root (NULL-terminated, or NULL) are not filled (the envelope keys,
 * which the framework reads itself). Returns NULL only when memory ran out
 * (jansson's allocator). Reentrant; s is only read. */
json_t *api_schema_apply_defaults(const struct api_schema *s, const json_t *instance,
                                  const char *const *skip_root);

#endif
