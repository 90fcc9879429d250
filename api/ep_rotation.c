/* ep_rotation.c — POST /v1/rotation/convert, /v1/rotation/compose and
 * /v1/rotation/apply: one rotation in every representation, the product of a
 * list of rotations, and a rotation applied to vectors and rank-2 tensors.
 * JSON <-> core only: the parsing and encoding of a rotation is
 * rotation_request.c, the mathematics core/rotation.c (mech/rotation.h). */
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

static const char convert_schema[] = API_ROTATION_SCHEMA;

static const char convert_description[] =
    "Converts one rotation into every representation at once. " API_ROTATION_DOC
    "A matrix whose max |(R^T R - 1)_ij| or |det R - 1| exceeds 1e-9 (a reflection, a "
    "scaled or sheared matrix) is refused with a 422 at /matrix; so are a zero axis or "
    "quaternion (at /axis_angle/axis, /quaternion) and a request giving two forms (at the "
    "second). " API_ROTATION_ANSWER_DOC
    " Accuracy: every answer reproduces R to ~1e-15 (max entry); quaternion, axis-angle "
    "and rotation vector are accurate to round-off for any angle, including 0 and pi.";

static const char convert_example[] =
    "{\"axis_angle\":{\"axis\":[1,1,1],\"angle\":2.0943951023931957},\"sense\":\"passive\"}";

static json_t *convert(struct api_call *c, const json_t *body)
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

const struct api_route api_route_rotation_convert = {
    "POST",
    "/v1/rotation/convert",
    "A rotation in every representation: matrix, quaternion, axis-angle, rotation vector, "
    "z-x-z and all 24 Euler readings, with residuals and gimbal-lock handling",
    convert_description,
    convert_schema,
    convert_example,
    convert,
    0,
    1, /* quick */
};

/* ---- compose ------------------------------------------------------------------ */

#define MAX_FACTORS 1000

/* clang-format off */
static const char compose_schema[] =
    "{\"type\":\"object\",\"additionalProperties\":false,\"required\":[\"rotations\"],"
    "\"properties\":{"
    "\"rotations\":{\"type\":\"array\",\"minItems\":1,\"maxItems\":1000,\"items\":"
    API_ROTATION_SCHEMA ",\"description\":\"applied in order, first the first\"},"
    "\"sense\":{\"enum\":[\"passive\",\"active\"],\"default\":\"passive\",\"description\":"
    "\"how the list is applied and the product reported; also the default sense of each "
    "item\"}}}";
/* clang-format on */

static const char compose_description[] =
    "Composes a list of rotations applied in order, first the first, and answers the "
    "product in every representation (as /v1/rotation/convert). Each item is one rotation "
    "in any form; its own optional sense only says how to read its matrix (default: the "
    "request's sense); the request's sense (default passive) says how the list is applied. "
    "Passive: the axes are turned by the first rotation, then the NEW axes by the second "
    "(its axis or angles are read in the intermediate axes), and so on, so a vector's "
    "components go v -> R1 v -> R2 R1 v: R_total = R_n ... R_2 R_1 with each R_i passive; "
    "e.g. [z by phi, x by theta, z by psi] is the notes' z-x-z rotation R_psi R_theta "
    "R_phi. Active: the vector is turned by the first rotation, then by the second about "
    "the FIXED axes: v' = A_n ... A_2 A_1 v. The same list therefore names the same turn in "
    "both senses only when its turns commute: passive composition is intrinsic, active "
    "is extrinsic. The product is formed with "
    "unit quaternions (passive: q = q_1 q_2 ... q_n, active: q = q_n ... q_1, Hamilton "
    "product), renormalised every 16 factors, so 1000 factors keep R orthonormal to "
    "round-off. " API_ROTATION_DOC API_ROTATION_ANSWER_DOC
    " The residuals are those of the product's matrix; count is the number of factors.";

static const char compose_example[] =
    "{\"rotations\":[{\"axis_angle\":{\"axis\":[0,0,1],\"angle\":0.5}},"
    "{\"axis_angle\":{\"axis\":[1,0,0],\"angle\":0.3}},"
    "{\"euler\":{\"sequence\":\"ZYX\",\"intrinsic\":true,\"angles\":[0.2,0,0]}}],"
    "\"sense\":\"passive\"}";

static json_t *compose(struct api_call *c, const json_t *body)
{
    const json_t *list = json_object_get(body, "rotations");
    size_t n = json_array_size(list);
    const char *s = api_string(body, "sense", "passive");
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

const struct api_route api_route_rotation_compose = {
    "POST",
    "/v1/rotation/compose",
    "The product of a list of rotations applied in order (passive: R_n ... R_1 about the "
    "moving axes; active: about the fixed axes), in every representation",
    compose_description,
    compose_schema,
    compose_example,
    compose,
    0,
    1, /* quick */
};

/* ---- apply -------------------------------------------------------------------- */

/* clang-format off */
#define S_BIG "{\"type\":\"number\",\"minimum\":-1e150,\"maximum\":1e150}"
#define S_BIG3 "{\"type\":\"array\",\"minItems\":3,\"maxItems\":3,\"items\":" S_BIG "}"
static const char apply_schema[] =
    "{\"type\":\"object\",\"additionalProperties\":false,\"required\":[\"rotation\"],"
    "\"properties\":{"
    "\"rotation\":" API_ROTATION_SCHEMA ","
    "\"vectors\":{\"type\":\"array\",\"minItems\":1,\"maxItems\":10000,\"items\":" S_BIG3
    ",\"description\":\"3-vectors v, any units, |components| <= 1e150\"},"
    "\"tensors\":{\"type\":\"array\",\"minItems\":1,\"maxItems\":1000,\"items\":"
    "{\"type\":\"array\",\"minItems\":3,\"maxItems\":3,\"items\":" S_BIG3 "},"
    "\"description\":\"rank-2 tensors T as 3x3 rows, any units\"}}}";
/* clang-format on */

static const char apply_description[] =
    "Applies a rotation R to `vectors` (v' = R v) and to rank-2 `tensors` (T' = R T R^T), "
    "with R in the rotation's sense. Passive (default, the notes): v' are the components "
    "of the same vector in the new axes and T' those of the same tensor (e.g. an inertia "
    "tensor in scene axes goes to body axes with the body's orientation as R, the inverse "
    "of what /v1/rigid/inertia does for a part: I_scene = R^T I_body R). Active: the "
    "vector or tensor itself is turned in fixed axes (so an inertia tensor of a body "
    "rotated by R is R I R^T: give the body's orientation with sense active to get what "
    "/v1/rigid/inertia computes for the rotated body). At least one of vectors and "
    "tensors is required. " API_ROTATION_DOC
    "Answer: sense, matrix (the R used), vectors, tensors (in the order given). "
    "Accuracy: each component to ~1e-16 of the vector's norm (resp. of the tensor's "
    "largest entry); a symmetric tensor stays symmetric to round-off; the length of a "
    "vector and the trace and eigenvalues of a tensor are preserved to round-off.";

static const char apply_example[] =
    "{\"rotation\":{\"euler_zxz\":[0.5,0.3,0]},\"vectors\":[[1,0,0],[0,0,1]],"
    "\"tensors\":[[[0.25,0,0],[0,0.5,0],[0,0,0.75]]]}";

static json_t *apply(struct api_call *c, const json_t *body)
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

const struct api_route api_route_rotation_apply = {
    "POST",
    "/v1/rotation/apply",
    "A rotation applied to vectors (R v) and rank-2 tensors (R T R^T), passive or active",
    apply_description,
    apply_schema,
    apply_example,
    apply,
    0,
    1, /* quick */
};
