/* dot.c — POST /v1/relativity/dot: the Minkowski dot product
 * of any two 4-vectors (notes §3 "Summary of 4-Vectors"), each vector's
 * square and kind, and the relative Lorentz factor of two timelike ones.
 * JSON <-> core only; the numerics are core/relativity/four_vector.c. */
#include "run/endpoint.h"
#include "mech/relativity/four_vector.h"

static void read4(const json_t *arr, double x[4])
{
    for (size_t k = 0; k < 4; k++)
        x[k] = json_number_value(json_array_get(arr, k));
}

static json_t *one(struct api_call *c, const double x[4])
{
    static const char *const kinds[] = {"timelike", "spacelike", "lightlike"};
    json_t *o = json_object();
    if (!o) return NULL;
    json_object_set_new_nocheck(o, "square", api_real(c, mech_four_dot(x, x)));
    json_object_set_new_nocheck(o, "kind", json_string(kinds[mech_four_kind_of(x)]));
    return o;
}

json_t *api_op_relativity_dot(struct api_call *c, const json_t *body)
{
    double a[4], b[4], g;
    read4(json_object_get(body, "a"), a);
    read4(json_object_get(body, "b"), b);
    json_t *out = json_object();
    if (!out) return api_call_fail_core(c, MECH_ENOMEM, NULL, "");
    json_object_set_new_nocheck(out, "dot", api_real(c, mech_four_dot(a, b)));
    json_object_set_new_nocheck(out, "a", one(c, a));
    json_object_set_new_nocheck(out, "b", one(c, b));
    int ok = mech_four_relative_gamma(a, b, &g);
    json_object_set_new_nocheck(out, "gamma_relative", ok ? api_real(c, g) : json_null());
    return out;
}

