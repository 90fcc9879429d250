/* vectors.c — POST /v1/vectors: the vector algebra of notes ch. 0 for
 * given vectors a, b (and c): norms, unit vectors, dot and cross products,
 * the cross product's antisymmetric tensor, the angle, components and
 * projections, and the scalar and vector triple products.
 * JSON <-> core only; the mathematics is core/rotation/vector_algebra.c. */
#include "run/endpoint.h"
#include "mech/base/constants.h"
#include "mech/rotation/vector_algebra.h"


static json_t *vec_or_null(struct api_call *c, int ok, struct mech_vec3 v)
{
    return ok ? api_vec3(c, v) : json_null();
}

static json_t *real_or_null(struct api_call *c, int ok, double x)
{
    return ok ? api_real(c, x) : json_null();
}

static json_t *one_vector(struct api_call *c, struct mech_vec3 v)
{
    struct mech_vec3 u;
    int ok = mech_vector_unit(v, &u);
    json_t *o = json_object();
    if (!o) return NULL;
    json_object_set_new_nocheck(o, "norm", api_real(c, mech_vec3_norm(v)));
    json_object_set_new_nocheck(o, "unit", vec_or_null(c, ok, u));
    return o;
}

json_t *api_op_vectors(struct api_call *c, const json_t *body)
{
    const json_t *bj = json_object_get(body, "b"), *cj = json_object_get(body, "c");
    if (cj && !bj) {
        api_call_invalid(c, "/c", "c needs b: the triple products are a.(b x c) and a x (b x c)");
        return NULL;
    }
    struct mech_vec3 a = api_vec3_member(body, "a", mech_vec3_make(0, 0, 0));
    struct mech_vec3 b = api_vec3_member(body, "b", mech_vec3_make(0, 0, 0));
    struct mech_vec3 cv = api_vec3_member(body, "c", mech_vec3_make(0, 0, 0));
    struct mech_error e;
    mech_error_clear(&e);
    struct mech_vector_pair p;
    double st = 0;
    struct mech_vec3 vt = mech_vec3_make(0, 0, 0);
    enum mech_status s = MECH_OK;
    if (bj) s = mech_vector_pair(a, b, &p, &e);
    if (s == MECH_OK && cj) s = mech_vector_triple(a, b, cv, &st, &vt, &e);
    if (s != MECH_OK) return api_call_fail_core(c, s, &e, "");

    json_t *out = json_object(), *notes = json_array();
    if (!out || !notes) {
        json_decref(out);
        json_decref(notes);
        mech_error_set(&e, MECH_ENOMEM, NULL, "out of memory");
        return api_call_fail_core(c, MECH_ENOMEM, &e, "");
    }
    json_object_set_new_nocheck(out, "a", one_vector(c, a));
    if (bj) {
        int ok = p.has_angle;
        json_object_set_new_nocheck(out, "b", one_vector(c, b));
        json_object_set_new_nocheck(out, "dot", api_real(c, p.dot));
        json_object_set_new_nocheck(out, "cross", api_vec3(c, p.cross));
        json_object_set_new_nocheck(out, "cross_tensor", api_mat3(c, p.cross_tensor));
        json_object_set_new_nocheck(out, "angle", real_or_null(c, ok, p.angle));
        json_object_set_new_nocheck(out, "angle_deg", real_or_null(c, ok, p.angle * (180 / MECH_PI)));
        json_object_set_new_nocheck(out, "b_along_a", real_or_null(c, ok, p.b_along_a));
        json_object_set_new_nocheck(out, "a_along_b", real_or_null(c, ok, p.a_along_b));
        json_object_set_new_nocheck(out, "b_on_a", vec_or_null(c, ok, p.b_on_a));
        json_object_set_new_nocheck(out, "b_across_a", vec_or_null(c, ok, p.b_across_a));
        json_object_set_new_nocheck(out, "difference", api_vec3(c, p.difference));
        json_object_set_new_nocheck(out, "sum", api_vec3(c, p.sum));
        json_object_set_new_nocheck(out, "distance", api_real(c, p.distance));
        if (!ok)
            json_array_append_new(notes, json_string(
                p.norm_a == 0 ? "a is the zero vector: it has no direction, so the angle, "
                                "the components and the projections are null"
                              : "b is the zero vector: it has no direction, so the angle, "
                                "the components and the projections are null"));
    }
    if (cj) {
        json_object_set_new_nocheck(out, "c", one_vector(c, cv));
        json_object_set_new_nocheck(out, "scalar_triple", api_real(c, st));
        json_object_set_new_nocheck(out, "vector_triple", api_vec3(c, vt));
    }
    json_object_set_new_nocheck(out, "notes", notes);
    return out;
}

