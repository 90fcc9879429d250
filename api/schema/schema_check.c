/* schema_check.c — the supported subset of JSON Schema: its keywords and type
 * names, and api_schema_check (api/schema/schema.h), which refuses a schema that uses
 * anything else, so a route cannot silently rely on an unsupported keyword. */
#include "schema/schema_internal.h"

#include <stdio.h>
#include <string.h>

static const char *const known_keywords[] = {
    "type", "properties", "required", "additionalProperties", "items", "minItems",
    "maxItems", "uniqueItems", "minimum", "maximum", "exclusiveMinimum", "exclusiveMaximum",
    "enum", "const", "oneOf", "minProperties", "maxProperties", "title", "description",
    "default", "examples", "x-mechd-check", /* annotation for POST /v1/check (docs/grading.md) */
    NULL,
};
static const char *const type_names[] = {
    "object", "array", "string", "number", "integer", "boolean", "null", NULL,
};

static int in_list(const char *const *list, const char *s)
{
    for (; *list; list++)
        if (!strcmp(*list, s)) return 1;
    return 0;
}

static int check(const json_t *s, const char *where, int depth, char *msg, size_t n)
{
    if (!json_is_object(s)) { snprintf(msg, n, "%s: schema must be an object", where); return -1; }
    if (depth > API_SCHEMA_MAX_DEPTH) {
        snprintf(msg, n, "%s: schema nests deeper than %d levels", where, API_SCHEMA_MAX_DEPTH);
        return -1;
    }
    const char *key;
    json_t *val;
    char sub[PTR_MAX];
    json_object_foreach((json_t *)s, key, val) {
        if (!in_list(known_keywords, key)) {
            snprintf(msg, n, "%s: unsupported keyword '%s'", where, key);
            return -1;
        }
        if (!strcmp(key, "type")) {
            if (json_is_string(val)) {
                if (!in_list(type_names, json_string_value(val))) goto bad;
            } else if (json_is_array(val)) {
                size_t i;
                json_t *e;
                json_array_foreach(val, i, e)
                    if (!json_is_string(e) || !in_list(type_names, json_string_value(e))) goto bad;
            } else goto bad;
        } else if (!strcmp(key, "properties")) {
            if (!json_is_object(val)) goto bad;
            const char *pk;
            json_t *pv;
            json_object_foreach(val, pk, pv) {
                snprintf(sub, sizeof sub, "%s/properties", where);
                api_pointer_append(sub, sizeof sub, pk);
                if (check(pv, sub, depth + 1, msg, n)) return -1;
            }
        } else if (!strcmp(key, "required")) {
            size_t i;
            json_t *e;
            if (!json_is_array(val)) goto bad;
            json_array_foreach(val, i, e) if (!json_is_string(e)) goto bad;
        } else if (!strcmp(key, "additionalProperties")) {
            if (!json_is_false(val)) goto bad;
        } else if (!strcmp(key, "items")) {
            snprintf(sub, sizeof sub, "%s/items", where);
            if (check(val, sub, depth + 1, msg, n)) return -1;
        } else if (!strcmp(key, "oneOf")) {
            size_t i;
            json_t *e;
            if (!json_is_array(val) || json_array_size(val) == 0 ||
                json_array_size(val) > API_SCHEMA_MAX_BRANCHES)
                goto bad;
            json_array_foreach(val, i, e) {
                snprintf(sub, sizeof sub, "%s/oneOf/%zu", where, i);
                if (check(e, sub, depth + 1, msg, n)) return -1;
            }
        } else if (!strcmp(key, "enum")) {
            if (!json_is_array(val)) goto bad;
        } else if (!strcmp(key, "uniqueItems")) {
            if (!json_is_boolean(val)) goto bad;
        } else if (in_list((const char *const[]){"minItems", "maxItems", "minimum", "maximum",
                                                  "exclusiveMinimum", "exclusiveMaximum",
                                                  "minProperties", "maxProperties", NULL},
                           key)) {
            if (!json_is_number(val)) goto bad;
        }
        continue;
    bad:
        snprintf(msg, n, "%s: malformed value of '%s'", where, key);
        return -1;
    }
    return 0;
}

int api_schema_check(const json_t *schema, char *msg, size_t n)
{
    return check(schema, "#", 0, msg, n);
}

unsigned api_schema_type_bit(const char *t)
{
    static const unsigned bits[] = {T_OBJECT, T_ARRAY, T_STRING, T_NUMBER,
                                    T_INTEGER, T_BOOLEAN, T_NULL};
    for (size_t i = 0; type_names[i]; i++)
        if (!strcmp(type_names[i], t)) return bits[i];
    return 0;
}
