/* michelson_morley.c — POST /v1/relativity/michelson-morley:
 * the notes' ether analysis of the Michelson–Morley experiment (§3.2, §3.4),
 * exact beside the notes' beta^2 L, and the null result with the Lorentz
 * contraction. JSON <-> core only; the physics is core/relativity/michelson_morley.c. */
#include "run/endpoint.h"
#include "mech/relativity/michelson_morley.h"

json_t *api_op_relativity_michelson_morley(struct api_call *c, const json_t *body)
{
    struct mech_boost b;
    struct mech_error e;
    mech_error_clear(&e);
    const double v = api_number_of(body, "speed");
    enum mech_status st = mech_boost_from_beta(mech_vec3_make(v / MECH_MM_C, 0, 0), &b, &e);
    if (st != MECH_OK) {
        api_call_domain(c, "/speed", "the speed must be below c");
        return NULL;
    }
    struct mech_michelson_morley m;
    st = mech_michelson_morley_compute(api_number(body, "arm_length", 1), &b,
                                       api_number(body, "wavelength", 0), &m, &e);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");
    json_t *out = json_object(), *et = json_object(), *ap = json_object(), *rel = json_object();
    if (!out || !et || !ap || !rel) {
        json_decref(out), json_decref(et), json_decref(ap), json_decref(rel);
        return api_call_fail_core(c, MECH_ENOMEM, NULL, "");
    }
    json_object_set_new_nocheck(out, "beta", api_real(c, b.beta));
    json_object_set_new_nocheck(out, "gamma_minus_one", api_real(c, b.gamma_minus_one));
    json_object_set_new_nocheck(et, "time_parallel", api_real(c, m.time_parallel));
    json_object_set_new_nocheck(et, "time_perpendicular", api_real(c, m.time_perpendicular));
    json_object_set_new_nocheck(et, "time_difference", api_real(c, m.time_difference));
    json_object_set_new_nocheck(et, "path_difference", api_real(c, m.path_difference));
    json_object_set_new_nocheck(ap, "path_difference", api_real(c, m.path_difference_approx));
    json_object_set_new_nocheck(ap, "relative_error", api_real(c, m.approx_rel_error));
    json_object_set_new_nocheck(
        ap, "label",
        json_string("approximation: the notes' d ~ beta^2 L (first order in beta^2), beside the "
                    "exact path_difference"));
    json_object_set_new_nocheck(et, "notes_approximation", ap);
    json_object_set_new_nocheck(et, "fringe_shift",
                                json_object_get(body, "wavelength") ? api_real(c, m.fringe_shift)
                                                                    : json_null());
    json_object_set_new_nocheck(out, "ether", et);
    json_object_set_new_nocheck(rel, "time_parallel", api_real(c, m.time_parallel_contracted));
    json_object_set_new_nocheck(rel, "time_perpendicular", api_real(c, m.time_perpendicular));
    json_object_set_new_nocheck(rel, "path_difference", json_real(0.0));
    json_object_set_new_nocheck(rel, "fringe_shift", json_real(0.0));
    json_object_set_new_nocheck(out, "relativity", rel);
    return out;
}

