/* schema_pointer.c — JSON pointers (RFC 6901) for the validator's messages:
 * api_pointer_append (api/schema/schema.h). The pieces the walker calls on every key and
 * item are inline in api/schema/schema_internal.h. */
#include "schema/schema_internal.h"

#include <string.h>

void api_pointer_append(char *buf, size_t n, const char *token)
{
    pointer_append_at(buf, n, strlen(buf), token);
}
