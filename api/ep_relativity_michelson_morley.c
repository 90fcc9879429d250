/* ep_relativity_michelson_morley.c — POST /v1/relativity/michelson-morley:
 * the notes' ether analysis of the Michelson–Morley experiment (§3.2, §3.4),
 * exact beside the notes' beta^2 L, and the null result with the Lorentz
 * contraction. JSON <-> core only; the physics is core/michelson_morley.c. */
#include "endpoint.h"
#include "mech/michelson_morley.h"

/* clang-format off */
static const char schema[] =
    "{\"type\":\"object\",\"additionalProperties\":false,\"required\":[\"arm_length\"],"
    "\"properties\":{"
    "\"arm_length\":{\"type\":\"number\",\"exclusiveMinimum\":0,\"maximum\":1e20,"
    "\"description\":\"L, m (the notes: 11 m)\"},"
    "\"speed\":{\"type\":\"number\",\"minimum\":0,\"maximum\":299792457.999,\"default\":30000,"
    "\"description\":\"the apparatus' speed through the ether, m/s (the Earth's orbital speed "
    "~3e4)\"},"
    "\"wavelength\":{\"type\":\"number\",\"exclusiveMinimum\":0,\"maximum\":1,"
    "\"description\":\"light's wavelength, m: adds the fringe shift on a 90 degree rotation\"}}}";
/* clang-format on */

static const char description[] =
    "The Michelson-Morley experiment as the notes analyse it (§3.2, §3.4). If light moved at c "
    "only in an ether through which the apparatus moves at speed v (beta = v/c), the round "
    "trips along arms of length L take time_parallel = 2 gamma^2 L/c and time_perpendicular = "
    "2 gamma L/c; their difference 2 gamma (gamma - 1) L/c is a path_difference d = 2 gamma "
    "(gamma - 1) L (from the exact gamma - 1), beside the notes' approximation beta^2 L "
    "(labelled, with its relative error -(gamma - 1)(2 gamma^2 + 2 gamma + 1)/(2 gamma^3) ~ "
    "-5 beta^2/4); with a wavelength, fringe_shift = 2 d/lambda when the apparatus turns 90 "
    "degrees. relativity: with the arm along the motion contracted to L/gamma (FitzGerald, "
    "Lorentz) both round trips take 2 gamma L/c and the shift is 0, as observed.";

static const char example[] = "{\"arm_length\": 11, \"speed\": 30000, \"wavelength\": 5.5e-7}";

static json_t *mm_op(struct api_call *c, const json_t *body)
{
    struct mech_boost b;
    struct mech_error e;
    mech_error_clear(&e);
    const double v = api_number(body, "speed", 30000);
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

const struct api_route api_route_relativity_michelson_morley = {
    "POST",
    "/v1/relativity/michelson-morley",
    "Michelson-Morley: the ether's predicted path difference and fringe shift (exact beside the "
    "notes' beta^2 L) and the null result with the Lorentz contraction",
    description,
    schema,
    example,
    mm_op,
    0,
    1, /* quick */
};
