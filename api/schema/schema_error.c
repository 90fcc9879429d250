/* schema_error.c — the validator's error list: every violation is counted,
 * and the first API_SCHEMA_MAX_ERRORS are listed as {"pointer", "detail"}
 * (api_error_entry, api/http/respond.h), and the JSON pointers (RFC 6901) that
 * name where: api_pointer_append (api/schema/schema.h); the pieces the walker
 * calls on every key and item are inline in api/schema/schema_internal.h. */
#include "schema/schema_internal.h"

#include <stdarg.h>
#include <stdio.h>

#include "http/respond.h"
#include <string.h>

void api_schema_add_error(struct vctx *v, const char *pointer, const char *fmt, ...)
{
    v->count++;
    if (!v->errors || json_array_size(v->errors) >= API_SCHEMA_MAX_ERRORS) return;
    char detail[400];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(detail, sizeof detail, fmt, ap);
    va_end(ap);
    json_array_append_new(v->errors, api_error_entry(pointer, detail));
}

const char *api_schema_type_name(const json_t *j)
{
    switch (json_typeof(j)) {
    case JSON_OBJECT: return "object";
    case JSON_ARRAY: return "array";
    case JSON_STRING: return "string";
    case JSON_INTEGER:
    case JSON_REAL: return "number";
    case JSON_TRUE:
    case JSON_FALSE: return "boolean";
    case JSON_NULL: return "null";
    }
    return "unknown";
}

void api_pointer_append(char *buf, size_t n, const char *token)
{
    pointer_append_at(buf, n, strlen(buf), token);
}
