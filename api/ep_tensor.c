/* ep_tensor.c — POST /v1/tensor/symmetric: a symmetric tensor given by the
 * user (an inertia tensor, a stress, a quadratic form): trace, invariants,
 * isotropic and deviatoric parts, principal values and axes, and the tensor
 * applied to a vector. JSON <-> core only; the mathematics is
 * core/sym_tensor.c, whose eigen-solver is /v1/rigid/inertia's. */
#include "endpoint.h"
#include "mech/sym_tensor.h"

/* clang-format off */
#define S_ENTRY "{\"type\":\"number\",\"minimum\":-1e102,\"maximum\":1e102}"
#define S_ROW "{\"type\":\"array\",\"minItems\":3,\"maxItems\":3,\"items\":" S_ENTRY "}"
static const char schema[] =
    "{\"type\":\"object\",\"additionalProperties\":false,\"required\":[\"tensor\"],"
    "\"properties\":{"
    "\"tensor\":{\"type\":\"array\",\"minItems\":3,\"maxItems\":3,\"items\":" S_ROW ","
    "\"description\":\"[[t11,t12,t13],[t21,t22,t23],[t31,t32,t33]], any units, symmetric "
    "(t_ij and t_ji may differ by 1e-12 of the largest |entry|), |entries| <= 1e102 (so that det T stays in the double range)\"},"
    "\"vector\":{\"type\":\"array\",\"minItems\":3,\"maxItems\":3,\"items\":"
    "{\"type\":\"number\",\"minimum\":-1e100,\"maximum\":1e100},"
    "\"description\":\"optional v: answers T v and v.T.v (omega for an inertia tensor: L "
    "= I omega, 2 T_rot = omega.I.omega)\"}"
    "}}";
/* clang-format on */

static const char description[] =
    "Trace, invariants and eigen-decomposition of a symmetric 3x3 tensor T given by the user "
    "(notes ch. 2, principal axes). Answers tensor (the input symmetrised, (T + T^T)/2), "
    "asymmetry (max |T_ij - T_ji| of the input; more than 1e-12 of the largest entry is "
    "refused with a 422 at /tensor/i/j, i > j), trace, invariants {I1 = trace, I2 = sum of "
    "the principal 2x2 minors = (I1^2 - tr T^2)/2, I3 = det T}, determinant, isotropic = "
    "I1/3 and deviator = T - (I1/3) 1, and principal: values ascending (real: T is "
    "symmetric), axes as unit rows (row k belongs to values[k]; right-handed; rows 0 and 1 "
    "have their largest-magnitude component positive, row 2 = row 0 x row 1), degenerate = "
    "two values agree within 1e-10 of the largest |value| (then the axes are one "
    "orthonormal basis of the degenerate subspace; the scene axes if all three agree), "
    "exactly as /v1/rigid/inertia's principal block. With vector v: times_vector = T v and "
    "quadratic_form = v.T.v. Precision: eigenvalues to ~1e-15 of the largest |value| "
    "(residuals |T e - l e|); the invariants are computed on T scaled by a power of two, "
    "so entries from 1e-100 to 1e102 lose nothing to overflow or underflow.";

static const char example[] =
    "{\"tensor\":[[0.6666666666666666,-0.25,-0.25],[-0.25,0.6666666666666666,-0.25],"
    "[-0.25,-0.25,0.6666666666666666]],\"vector\":[1,1,1]}";

static struct mech_mat3 mat3_of(const json_t *rows)
{
    struct mech_mat3 m;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            m.a[i][j] = json_number_value(json_array_get(json_array_get(rows, i), j));
    return m;
}

static json_t *symmetric(struct api_call *c, const json_t *body)
{
    struct mech_mat3 t = mat3_of(json_object_get(body, "tensor"));
    struct mech_error e;
    mech_error_clear(&e);
    struct mech_sym_tensor r;
    enum mech_status st = mech_sym_tensor_analyse(t, &r, &e);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");
    json_t *out = json_object(), *inv = json_object(), *pr = json_object(),
           *notes = json_array();
    if (!out || !inv || !pr || !notes) {
        json_decref(out);
        json_decref(inv);
        json_decref(pr);
        json_decref(notes);
        mech_error_set(&e, MECH_ENOMEM, NULL, "out of memory");
        return api_call_fail_core(c, MECH_ENOMEM, &e, "");
    }
    json_object_set_new_nocheck(out, "tensor", api_mat3(c, r.tensor));
    json_object_set_new_nocheck(out, "asymmetry", api_real(c, r.asymmetry));
    json_object_set_new_nocheck(out, "trace", api_real(c, r.trace));
    json_object_set_new_nocheck(inv, "I1", api_real(c, r.invariants[0]));
    json_object_set_new_nocheck(inv, "I2", api_real(c, r.invariants[1]));
    json_object_set_new_nocheck(inv, "I3", api_real(c, r.invariants[2]));
    json_object_set_new_nocheck(out, "invariants", inv);
    json_object_set_new_nocheck(out, "determinant", api_real(c, r.invariants[2]));
    json_object_set_new_nocheck(out, "isotropic", api_real(c, r.isotropic));
    json_object_set_new_nocheck(out, "deviator", api_mat3(c, r.deviator));
    json_object_set_new_nocheck(pr, "values", api_reals(c, r.principal.moments, 3));
    json_object_set_new_nocheck(pr, "axes", api_mat3(c, r.principal.axes));
    json_object_set_new_nocheck(pr, "degenerate", json_boolean(r.principal.degenerate));
    json_object_set_new_nocheck(out, "principal", pr);
    const json_t *vj = json_object_get(body, "vector");
    if (vj) {
        struct mech_vec3 v = api_vec3_of(vj), tv = mech_mat3_mul_vec(r.tensor, v);
        json_object_set_new_nocheck(out, "times_vector", api_vec3(c, tv));
        json_object_set_new_nocheck(out, "quadratic_form", api_real(c, mech_vec3_dot(v, tv)));
    }
    if (r.principal.degenerate)
        json_array_append_new(notes, json_string(
            "two or three principal values agree (within 1e-10 of the largest): the axes of "
            "the repeated value are not unique; principal.axes gives one orthonormal basis of "
            "their subspace"));
    json_object_set_new_nocheck(out, "notes", notes);
    return out;
}

const struct api_route api_route_tensor_symmetric = {
    "POST",
    "/v1/tensor/symmetric",
    "A symmetric tensor's trace, invariants, isotropic and deviatoric parts, principal "
    "values and axes (with the degeneracy flag), and T v",
    description,
    schema,
    example,
    symmetric,
    0,
    1, /* quick */
};
