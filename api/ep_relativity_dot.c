/* ep_relativity_dot.c — POST /v1/relativity/dot: the Minkowski dot product
 * of any two 4-vectors (notes §3 "Summary of 4-Vectors"), each vector's
 * square and kind, and the relative Lorentz factor of two timelike ones.
 * JSON <-> core only; the numerics are core/four_vector.c. */
#include "endpoint.h"
#include "mech/four_vector.h"

/* clang-format off */
#define DOT_VEC4(desc)                                                                             \
    "{\"type\":\"array\",\"minItems\":4,\"maxItems\":4,\"items\":{\"type\":\"number\","            \
    "\"minimum\":-1e150,\"maximum\":1e150},\"description\":\"" desc "\"}"
static const char schema[] =
    "{\"type\":\"object\",\"additionalProperties\":false,\"required\":[\"a\",\"b\"],"
    "\"properties\":{"
    "\"a\":" DOT_VEC4("a 4-vector [x0, x1, x2, x3], x0 = ct or E/c, any one unit, |x_i| <= 1e150") ","
    "\"b\":" DOT_VEC4("a second 4-vector in the same metric (units multiply)")
    "}}";
/* clang-format on */

static const char description[] =
    "Minkowski dot product (notes §3, metric (-,+,+,+)): dot = a.b = -a0 b0 + a1 b1 + a2 b2 + "
    "a3 b3, and for each of a and b its square (x.x) and kind: timelike (x.x < 0), spacelike "
    "(> 0) or lightlike (|x.x| <= 4 eps sum x_i^2, the rounding a decimal input such as "
    "[1, 0.6, 0.8, 0] carries; the zero vector counts as lightlike). gamma_relative = -a.b / "
    "sqrt((-a.a)(-b.b)) when both are timelike and point the same way in time: the Lorentz "
    "factor of b's motion seen from a's rest frame (for 4-momenta, b's energy in a's rest "
    "frame is m_b gamma_relative; for the notes' p.x, the phase of a plane wave); null "
    "otherwise. Precision: error-free products and a compensated sum, so a dot product "
    "that cancels is right to about one rounding of the result (products near 1e16 that "
    "cancel to 2e7 keep all their digits; a naive sum loses 7).";

static const char example[] = "{\"a\": [1.25, 0.75, 0, 0], \"b\": [1.25, -0.75, 0, 0]}";

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

static json_t *dot_op(struct api_call *c, const json_t *body)
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

const struct api_route api_route_relativity_dot = {
    "POST",
    "/v1/relativity/dot",
    "Minkowski dot product of two 4-vectors, their squares and kinds, and the relative gamma "
    "of two timelike ones",
    description,
    schema,
    example,
    dot_op,
    0,
    1, /* quick */
};
