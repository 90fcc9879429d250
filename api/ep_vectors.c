/* ep_vectors.c — POST /v1/vectors: the vector algebra of notes ch. 0 for
 * given vectors a, b (and c): norms, unit vectors, dot and cross products,
 * the cross product's antisymmetric tensor, the angle, components and
 * projections, and the scalar and vector triple products.
 * JSON <-> core only; the mathematics is core/vector_algebra.c. */
#include "endpoint.h"
#include "mech/vector_algebra.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* clang-format off */
#define S_VEC(desc)                                                                     \
    "{\"type\":\"array\",\"minItems\":3,\"maxItems\":3,\"items\":{\"type\":\"number\","    \
    "\"minimum\":-1e153,\"maximum\":1e153},\"description\":\"" desc "\"}"
static const char schema[] =
    "{\"type\":\"object\",\"additionalProperties\":false,\"required\":[\"a\"],"
    "\"properties\":{"
    "\"a\":" S_VEC("[x, y, z], any units (r for r x p); |components| <= 1e153") ","
    "\"b\":" S_VEC("[x, y, z], optional (p for r x p)") ","
    "\"c\":" S_VEC("[x, y, z], optional, needs b: the triple products a.(b x c), a x (b x c)")
    "}}";
/* clang-format on */

static const char description[] =
    "Vector algebra of notes ch. 0 for vectors a (required), b and c (optional; c needs b). "
    "Answers a.norm and a.unit (null for the zero vector), the same for b and c, and with b: "
    "dot = a.b, cross = a x b (r x p = L when a = r, b = p), cross_tensor T_ij = a_i b_j - "
    "a_j b_i (the antisymmetric tensor form, notes §0.2: [[0, L_z, -L_y], [-L_z, 0, L_x], "
    "[L_y, -L_x, 0]], L_k = eps_ijk T_ij / 2), angle (rad, in [0, pi]) and angle_deg, "
    "b_along_a = a.b/|a| (the signed component of b along a) and a_along_b = a.b/|b|, "
    "b_on_a = (a.b/|a|^2) a (the projection) and b_across_a = b - b_on_a; with c: "
    "scalar_triple = a.(b x c) (the determinant of the rows a, b, c) and vector_triple = "
    "a x (b x c) = b (a.c) - c (a.b). Where a or b is the zero vector the angle, components "
    "and projections do not exist: they are null, and notes says why. Precision: every "
    "vector is scaled by a power of two before it is multiplied, so nothing overflows or "
    "underflows on the way (components from 1e-300 to 1e153); the angle is atan2(|a x b|, "
    "a.b), never acos, so nearly parallel and antiparallel vectors keep their relative "
    "digits (b = (1, 1e-12, 0) against a = (1, 0, 0) gives 1e-12 rad to 1e-16). A product "
    "beyond the double range (|a| |b| |c| > ~1e308) is refused with a 422 at /c (or /b).";

static const char example[] = "{\"a\":[1,3,-2],\"b\":[2,1,1]}";

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

static json_t *vectors(struct api_call *c, const json_t *body)
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
        json_object_set_new_nocheck(out, "angle_deg", real_or_null(c, ok, p.angle * (180 / M_PI)));
        json_object_set_new_nocheck(out, "b_along_a", real_or_null(c, ok, p.b_along_a));
        json_object_set_new_nocheck(out, "a_along_b", real_or_null(c, ok, p.a_along_b));
        json_object_set_new_nocheck(out, "b_on_a", vec_or_null(c, ok, p.b_on_a));
        json_object_set_new_nocheck(out, "b_across_a", vec_or_null(c, ok, p.b_across_a));
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

const struct api_route api_route_vectors = {
    "POST",
    "/v1/vectors",
    "Vector algebra: norms, dot and cross products (with the antisymmetric tensor form), "
    "angle, components, projections, scalar and vector triple products",
    description,
    schema,
    example,
    vectors,
    0,
    1, /* quick */
};
