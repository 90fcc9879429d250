/* ep_relativity.c — POST /v1/relativity/boost: Lorentz-boost one or many
 * 4-vectors into the frame moving with velocity βc, keeping precision at
 * 1 m/s and at β = 1 − 1e-15 (core/boost.c does the numerics). */
#include <stdio.h>
#include <stdlib.h>

#include "endpoint.h"
#include "mech/boost.h"
#include "velocity_request.h"

/* ---- request schema -------------------------------------------------------
 * Component bounds keep every intermediate finite: |x| ≤ 1e150 and γ ≤ 5e151
 * (|η| ≤ 350) give boosted components ≤ 2e302 and squares ≤ 1e301. */
#define BOOST_NUM4 "{\"type\":\"number\",\"minimum\":-1e150,\"maximum\":1e150}"
#define BOOST_VEC4                                                                                 \
    "{\"type\":\"array\",\"minItems\":4,\"maxItems\":4,\"items\":" BOOST_NUM4                      \
    ",\"description\":\"a 4-vector [x0, x1, x2, x3] with x0 = ct (or E/c), any one unit, "         \
    "each |component| <= 1e150\"}"
static const char boost_schema[] =
    "{\"type\":\"object\",\"additionalProperties\":false,"
    "\"required\":[\"vectors\",\"velocity\"],"
    "\"properties\":{"
    "\"vectors\":{\"description\":\"one 4-vector, or a list of 1 to 100000; the answer has "
    "the same shape\",\"oneOf\":["
    "{\"type\":\"array\",\"minItems\":1,\"maxItems\":100000,\"items\":" BOOST_VEC4 "}," BOOST_VEC4
    "]},"
    "\"velocity\":" API_VELOCITY_SCHEMA ","
    "\"matrix\":{\"type\":\"boolean\",\"default\":false,\"description\":\"true adds matrix, "
    "the 4x4 Lorentz matrix of the boost (x' = matrix x, rows and columns in the order ct, x, "
    "y, z)\"}}}";

static const char boost_example[] =
    "{\"vectors\": [[1, 0, 0, 0], [1, 1, 0, 0]], \"velocity\": {\"beta\": [0.6, 0, 0]}}";

static const char boost_description[] =
    "Passive Lorentz boost (notes §3.3): the components of the same events in the frame "
    "moving with velocity beta*c, x' = gamma(x - beta ct), ct' = gamma(ct - beta x), "
    "transverse components unchanged. Metric (-,+,+,+), x0 = ct. The velocity is given as "
    "beta, as a rapidity, as gamma or as 1 - beta, each with a direction; the answer's "
    "gamma, gamma_minus_one, rapidity (>= 0) and one_minus_beta describe the speed |beta|, "
    "and beta is the velocity vector. All are computed from the form given without "
    "cancellation (gamma - 1 right to round-off at 1 m/s, gamma right at 1 - beta = 1e-15 "
    "and rapidity 35). Vectors are boosted with light-cone components x0 -+ x_par, which "
    "scale by exp(+-eta), or the gamma - 1 form, whichever is more accurate: a light-like "
    "vector along the boost keeps full relative precision. invariants_before is "
    "-x0^2 + |x|^2 of each input (compensated); invariants_after is the same invariant of "
    "the boosted vector from its light-cone product -u'v' + |x_perp|^2, since recomputing "
    "it from large boosted components would cancel. |beta| >= 1, gamma < 1, "
    "1 - beta outside (0, 2) or a zero direction is a 422 naming the field. With "
    "\"matrix\": true the answer adds matrix, the 4x4 Lorentz matrix Lambda (notes §3, a "
    "boost in an arbitrary direction): Lambda00 = gamma, Lambda0i = Lambdai0 = -beta_i gamma, "
    "Lambdaij = delta_ij + (gamma - 1) n_i n_j, from the exact gamma - 1 and beta gamma.";

static const double *vector_at(const json_t *vectors, int single, size_t i, double buf[4])
{
    const json_t *a = single ? vectors : json_array_get(vectors, i);
    for (size_t k = 0; k < 4; k++)
        buf[k] = json_number_value(json_array_get(a, k));
    return buf;
}

static json_t *boost_op(struct api_call *c, const json_t *body)
{
    const json_t *vel = json_object_get(body, "velocity");
    const json_t *vectors = json_object_get(body, "vectors");
    struct mech_boost b;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st;
    if (!api_velocity_parse(c, vel, "/velocity", &b)) return NULL;

    /* The schema's oneOf: either one 4-vector (numbers) or a list of them. */
    const int single = json_is_number(json_array_get(vectors, 0));
    const size_t n = single ? 1 : json_array_size(vectors);
    double *x = malloc(10 * n * sizeof *x); /* x, out: 4n each; invariants: n each */
    if (!x) return api_call_fail_core(c, MECH_ENOMEM, NULL, "");
    double *out = x + 4 * n, *ib = x + 8 * n, *ia = x + 9 * n;
    for (size_t i = 0; i < n; i++)
        vector_at(vectors, single, i, x + 4 * i);

    st = mech_boost_apply_batch(&b, x, out, ib, ia, n, &c->budget, &e);
    if (st != MECH_OK) {
        if (single && e.param[0]) snprintf(e.param, sizeof e.param, "vectors");
        free(x);
        return api_call_fail_core(c, st, &e, "");
    }

    json_t *res = json_object();
    json_t *vs;
    if (single) {
        vs = api_reals(c, out, 4);
    } else {
        vs = json_array();
        for (size_t i = 0; vs && i < n; i++)
            json_array_append_new(vs, api_reals(c, out + 4 * i, 4));
    }
    json_object_set_new_nocheck(res, "vectors", vs);
    api_velocity_describe(c, &b, res);
    json_object_set_new_nocheck(res, "invariants_before",
                                single ? api_real(c, ib[0]) : api_reals(c, ib, n));
    json_object_set_new_nocheck(res, "invariants_after",
                                single ? api_real(c, ia[0]) : api_reals(c, ia, n));
    if (json_is_true(json_object_get(body, "matrix"))) {
        double m[4][4];
        mech_boost_matrix(&b, m);
        json_t *rows = json_array();
        for (int i = 0; rows && i < 4; i++)
            json_array_append_new(rows, api_reals(c, m[i], 4));
        json_object_set_new_nocheck(res, "matrix", rows);
    }
    free(x);
    if (!res || !vs) {
        json_decref(res);
        return api_call_fail_core(c, MECH_ENOMEM, NULL, "");
    }
    return res;
}

const struct api_route api_route_relativity_boost = {
    "POST",
    "/v1/relativity/boost",
    "Lorentz-boost 4-vectors, precise from 1 m/s to gamma = 1e15",
    boost_description,
    boost_schema,
    boost_example,
    boost_op,
    0,
    1, /* quick */
};
