/* ep_rotation.c — POST /v1/rotation/convert, /v1/rotation/compose and
 * /v1/rotation/apply: one rotation in every representation, the product of a
 * list of rotations, and a rotation applied to vectors and rank-2 tensors.
 * JSON <-> core only: the parsing and encoding of a rotation is
 * rotation_request.c, the mathematics core/rotation/rotation.c (mech/rotation/rotation.h). */
#include <stdlib.h>
#include <string.h>

#include "endpoint.h"
#include "rotation_request.h"

static json_t *out_of_memory(struct api_call *c, json_t *partial)
{
    struct mech_error e;
    json_decref(partial);
    mech_error_clear(&e);
    mech_error_set(&e, MECH_ENOMEM, NULL, "out of memory");
    return api_call_fail_core(c, MECH_ENOMEM, &e, "");
}

/* ---- convert ------------------------------------------------------------------ */

json_t *api_op_rotation_convert(struct api_call *c, const json_t *body)
{
    struct api_rotation r;
    if (api_rotation_read(c, body, "", MECH_ROTATION_PASSIVE, &r) != 0) return NULL;
    json_t *out = json_object();
    if (!out) return out_of_memory(c, NULL);
    if (api_rotation_encode(c, out, &r) != 0) {
        json_decref(out);
        return NULL;
    }
    return out;
}

/* ---- compose ------------------------------------------------------------------ */

#define MAX_FACTORS 1000

json_t *api_op_rotation_compose(struct api_call *c, const json_t *body)
{
    const json_t *list = json_object_get(body, "rotations");
    size_t n = json_array_size(list);
    const char *s = api_string_of(body, "sense");
    enum mech_rotation_sense sense =
        strcmp(s, "active") == 0 ? MECH_ROTATION_ACTIVE : MECH_ROTATION_PASSIVE;
    double(*qs)[4] = calloc(n ? n : 1, sizeof *qs);
    if (!qs) return out_of_memory(c, NULL);
    int bad = 0;
    for (size_t i = 0; i < n && i < MAX_FACTORS; i++) {
        char ptr[48];
        snprintf(ptr, sizeof ptr, "/rotations/%zu", i);
        struct api_rotation r;
        if (api_rotation_read(c, json_array_get(list, i), ptr, sense, &r) != 0) {
            bad = 1;
            continue; /* report every bad item, not only the first */
        }
        memcpy(qs[i], r.q, sizeof r.q);
    }
    if (bad) {
        free(qs);
        return NULL;
    }
    struct api_rotation prod;
    memset(&prod, 0, sizeof prod);
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st =
        mech_rotation_compose((const double(*)[4])qs, n, sense, prod.q, &c->budget, &e);
    free(qs);
    if (st == MECH_OK) st = mech_rotation_matrix_of_quaternion(prod.q, sense, &prod.matrix, &e);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");
    prod.sense = sense;
    mech_rotation_residuals(prod.matrix, &prod.orth, &prod.det);
    json_t *out = json_pack("{s:i}", "count", (json_int_t)n);
    if (!out) return out_of_memory(c, NULL);
    if (api_rotation_encode(c, out, &prod) != 0) {
        json_decref(out);
        return NULL;
    }
    return out;
}

/* ---- apply -------------------------------------------------------------------- */

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
    if (!out) return out_of_memory(c, NULL);
    json_object_set_new_nocheck(
        out, "sense", json_string(r.sense == MECH_ROTATION_ACTIVE ? "active" : "passive"));
    json_object_set_new_nocheck(out, "matrix", api_mat3(c, r.matrix));
    if (vj) {
        json_t *vs = json_array();
        if (!vs) return out_of_memory(c, out);
        for (size_t i = 0; i < json_array_size(vj); i++)
            json_array_append_new(
                vs, api_vec3(c, mech_mat3_mul_vec(r.matrix, api_vec3_of(json_array_get(vj, i)))));
        json_object_set_new_nocheck(out, "vectors", vs);
    }
    if (tj) {
        json_t *ts = json_array();
        if (!ts) return out_of_memory(c, out);
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

