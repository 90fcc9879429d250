/* velocity_request.c — parsing and describing the shared velocity input
 * (see api/ops/relativity/velocity_request.h). */
#include "ops/relativity/velocity_request.h"

int api_velocity_parse(struct api_call *c, const json_t *vel, const char *pointer,
                       struct mech_boost *out)
{
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st;
    const json_t *j;
    struct mech_vec3 dir = api_vec3_member(vel, "direction", mech_vec3_make(0, 0, 0));
    if ((j = json_object_get(vel, "beta")))
        st = mech_boost_from_beta(api_vec3_of(j), out, &e);
    else if ((j = json_object_get(vel, "rapidity")))
        st = mech_boost_from_rapidity(json_number_value(j), dir, out, &e);
    else if ((j = json_object_get(vel, "gamma")))
        st = mech_boost_from_gamma(json_number_value(j), dir, out, &e);
    else
        st = mech_boost_from_one_minus_beta(api_number(vel, "one_minus_beta", 0), dir, out, &e);
    if (st != MECH_OK) {
        api_call_fail_core(c, st, &e, pointer);
        return 0;
    }
    return 1;
}

void api_velocity_describe(struct api_call *c, const struct mech_boost *b, json_t *into)
{
    json_object_set_new_nocheck(into, "gamma", api_real(c, b->gamma));
    json_object_set_new_nocheck(into, "gamma_minus_one", api_real(c, b->gamma_minus_one));
    json_object_set_new_nocheck(into, "beta", api_vec3(c, b->beta_vec));
    json_object_set_new_nocheck(into, "rapidity", api_real(c, b->rapidity));
    json_object_set_new_nocheck(into, "one_minus_beta", api_real(c, b->one_minus_beta));
}
