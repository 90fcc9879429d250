/* boost.c — POST /v1/relativity/boost: Lorentz-boost one or many
 * 4-vectors into the frame moving with velocity βc, keeping precision at
 * 1 m/s and at β = 1 − 1e-15 (core/relativity/boost.c does the numerics). */
#include <stdio.h>
#include <stdlib.h>

#include "run/endpoint.h"
#include "mech/relativity/boost.h"
#include "ops/relativity/velocity_request.h"

/* ---- request bounds (api/ops/relativity/boost.json) ----------------------
 * Component bounds keep every intermediate finite: |x| ≤ 1e150 and γ ≤ 5e151
 * (|η| ≤ 350) give boosted components ≤ 2e302 and squares ≤ 1e301. */

static const double *vector_at(const json_t *vectors, int single, size_t i, double buf[4])
{
    const json_t *a = single ? vectors : json_array_get(vectors, i);
    for (size_t k = 0; k < 4; k++)
        buf[k] = json_number_value(json_array_get(a, k));
    return buf;
}

json_t *api_op_relativity_boost(struct api_call *c, const json_t *body)
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

