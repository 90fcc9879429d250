/* interval.c — POST /v1/relativity/interval (notes §3.5, §3.6): the invariant
 * interval between two events, its kind, proper time or length, and a frame
 * that makes the events co-located or simultaneous. The numerics are
 * core/relativity/interval.c. */
#include <string.h>

#include "run/endpoint.h"
#include "mech/base/constants.h"
#include "mech/relativity/interval.h"
#include "ops/relativity/velocity_request.h"

json_t *api_op_relativity_interval(struct api_call *c, const json_t *body)
{
    const json_t *ev = json_object_get(body, "events");
    double e1[4], e2[4];
    for (size_t k = 0; k < 4; k++) {
        e1[k] = json_number_value(json_array_get(json_array_get(ev, 0), k));
        e2[k] = json_number_value(json_array_get(json_array_get(ev, 1), k));
    }
    const int ly = strcmp(api_string_of(body, "units"), "years") == 0;
    const double c_light = ly ? 1.0 : MECH_C;
    struct mech_interval iv;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_interval_compute(e1, e2, &iv, &e);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");

    static const char *const kinds[] = {"timelike", "spacelike", "lightlike"};
    json_t *res = json_object();
    json_object_set_new_nocheck(res, "delta", api_reals(c, iv.delta, 4));
    json_object_set_new_nocheck(res, "s2", api_real(c, iv.s2));
    json_object_set_new_nocheck(res, "kind", json_string(kinds[iv.kind]));
    json_object_set_new_nocheck(res, "lightlike_tolerance", api_real(c, iv.tolerance));
    json_object_set_new_nocheck(res, "s2_input_uncertainty", api_real(c, iv.input_error));
    json_object_set_new_nocheck(res, "coincident", json_boolean(iv.coincident));
    /* Every key always present: null where the quantity does not exist (a
     * spacelike pair has no proper time, a timelike one no proper length);
     * light-like pairs have both, and both are 0. */
    const int has_time = iv.kind != MECH_INTERVAL_SPACELIKE;
    const int has_length = iv.kind != MECH_INTERVAL_TIMELIKE;
    json_object_set_new_nocheck(res, "proper_time",
                                has_time ? api_real(c, iv.proper / c_light) : json_null());
    json_object_set_new_nocheck(res, "proper_time_ct",
                                has_time ? api_real(c, iv.proper) : json_null());
    json_object_set_new_nocheck(res, "proper_length",
                                has_length ? api_real(c, iv.proper) : json_null());
    json_object_set_new_nocheck(res, "time_order",
                                json_string(iv.delta[0] > 0   ? "first_before_second"
                                            : iv.delta[0] < 0 ? "second_before_first"
                                                              : "simultaneous"));
    json_object_set_new_nocheck(res, "time_order_reversible",
                                json_boolean(iv.time_order_reversible));
    if (iv.has_frame) {
        json_t *f = json_object();
        json_object_set_new(
            f, "makes_events",
            json_string(iv.kind == MECH_INTERVAL_TIMELIKE ? "co-located" : "simultaneous"));
        json_t *v = json_object();
        api_velocity_describe(c, &iv.frame, v);
        json_object_set_new_nocheck(f, "velocity", v);
        json_object_set_new_nocheck(res, "example_frame", f);
    } else {
        json_object_set_new_nocheck(res, "example_frame", json_null());
    }
    return res;
}
