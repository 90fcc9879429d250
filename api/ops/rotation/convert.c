/* convert.c — POST /v1/rotation/convert: one rotation, given in any form, in
 * every representation. JSON <-> core only: the parsing and encoding of a rotation is
 * api/request/rotation_request.c, the mathematics core/rotation/rotation.c
 * (mech/rotation/rotation.h). */
#include <stdlib.h>
#include <string.h>

#include "run/endpoint.h"
#include "request/rotation_request.h"

json_t *api_op_rotation_convert(struct api_call *c, const json_t *body)
{
    struct api_rotation r;
    if (api_rotation_read(c, body, "", MECH_ROTATION_PASSIVE, &r) != 0) return NULL;
    json_t *out = json_object();
    if (!out) return api_call_out_of_memory(c, NULL);
    if (api_rotation_encode(c, out, &r) != 0) {
        json_decref(out);
        return NULL;
    }
    return out;
}
