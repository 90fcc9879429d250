/* apply.c — POST /v1/rotation/apply: a rotation applied to vectors and rank-2
 * tensors. JSON <-> core only: the parsing and encoding of a rotation is
 * api/request/rotation_request.c, the mathematics core/rotation/rotation.c
 * (mech/rotation/rotation.h). */
#include <stdlib.h>
#include <string.h>

#include "run/endpoint.h"
#include "request/rotation_request.h"

json_t *api_op_rotation_apply(struct api_call *c, const json_t *body)
{
    const json_t *vj = json_object_get(body, "vectors");
    const json_t *tj = json_object_get(body, "tensors");
    if (!vj && !tj) {
        api_call_invalid(c, "", "nothing to rotate: give vectors and/or tensors");
        return NULL;
    }
    struct api_rotation r;
    if (api_rotation_read(c, json_object_get(body, "rotation"), "/rotation", MECH_ROTATION_PASSIVE,
                          &r) != 0)
        return NULL;
    json_t *out = json_object();
    if (!out) return api_call_out_of_memory(c, NULL);
    json_object_set_new_nocheck(
        out, "sense", json_string(r.sense == MECH_ROTATION_ACTIVE ? "active" : "passive"));
    json_object_set_new_nocheck(out, "matrix", api_mat3(c, r.matrix));
    if (vj) {
        json_t *vs = json_array();
        if (!vs) return api_call_out_of_memory(c, out);
        for (size_t i = 0; i < json_array_size(vj); i++)
            json_array_append_new(
                vs, api_vec3(c, mech_mat3_mul_vec(r.matrix, api_vec3_of(json_array_get(vj, i)))));
        json_object_set_new_nocheck(out, "vectors", vs);
    }
    if (tj) {
        json_t *ts = json_array();
        if (!ts) return api_call_out_of_memory(c, out);
        for (size_t i = 0; i < json_array_size(tj); i++) {
            const json_t *rows = json_array_get(tj, i);
            struct mech_mat3 t;
            for (int a = 0; a < 3; a++) {
                struct mech_vec3 row = api_vec3_of(json_array_get(rows, (size_t)a));
                t.a[a][0] = row.x;
                t.a[a][1] = row.y;
                t.a[a][2] = row.z;
            }
            json_array_append_new(ts, api_mat3(c, mech_rotation_apply_tensor(r.matrix, t)));
        }
        json_object_set_new_nocheck(out, "tensors", ts);
    }
    return out;
}
