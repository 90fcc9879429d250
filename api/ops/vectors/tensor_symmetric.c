/* tensor_symmetric.c — POST /v1/tensor/symmetric: a symmetric tensor given by the
 * user (an inertia tensor, a stress, a quadratic form): trace, invariants,
 * isotropic and deviatoric parts, principal values and axes, and the tensor
 * applied to a vector. JSON <-> core only; the mathematics is
 * core/rigid/sym_tensor.c, whose eigen-solver is /v1/rigid/inertia's. */
#include "run/endpoint.h"
#include "mech/rigid/sym_tensor.h"

static struct mech_mat3 mat3_of(const json_t *rows)
{
    struct mech_mat3 m;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            m.a[i][j] = json_number_value(json_array_get(json_array_get(rows, i), j));
    return m;
}

json_t *api_op_tensor_symmetric(struct api_call *c, const json_t *body)
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

