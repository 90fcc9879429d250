/* ep_relativity_force.c — POST /v1/relativity/force: Newton's second law in
 * special relativity, F = dp/dt = gamma m a_perp + gamma^3 m a_par, either
 * way round, with the power and the 4-force (notes §3 "The Force 4-Vector").
 * JSON <-> core only; the physics is core/relativistic_force.c. */
#include "endpoint.h"
#include "mech/relativistic_force.h"
#include "velocity_request.h"

/* clang-format off */
#define F_VEC(desc)                                                                                \
    "{\"type\":\"array\",\"minItems\":3,\"maxItems\":3,\"items\":{\"type\":\"number\","            \
    "\"minimum\":-1e100,\"maximum\":1e100},\"description\":\"" desc "\"}"
static const char schema[] =
    "{\"type\":\"object\",\"additionalProperties\":false,\"required\":[\"mass\",\"velocity\"],"
    "\"properties\":{"
    "\"mass\":{\"type\":\"number\",\"exclusiveMinimum\":0,\"maximum\":1e60,\"description\":"
    "\"rest mass m, kg\"},"
    "\"velocity\":" API_VELOCITY_SCHEMA ","
    "\"acceleration\":" F_VEC("the acceleration dv/dt, m/s^2 (or give force)") ","
    "\"force\":" F_VEC("the force F = dp/dt, N (or give acceleration)")
    "}}";
/* clang-format on */

static const char description[] =
    "Newton's second law in special relativity (notes §3, the force 4-vector): F = dp/dt with "
    "p = gamma m v, so F = gamma m a_perp + gamma^3 m a_par, the parts of the acceleration "
    "across and along v (transverse mass gamma m, longitudinal mass gamma^3 m). Give the mass "
    "(kg), the velocity (any of the shared forms: beta, rapidity, gamma, one_minus_beta with a "
    "direction) and exactly one of acceleration (m/s^2) or force (N); the other follows "
    "(a_par = F_par/(gamma^3 m), a_perp = F_perp/(gamma m)). Answers gamma, force, "
    "force_parallel, force_perpendicular, acceleration and its two parts (vectors), "
    "transverse_mass, longitudinal_mass, power = F.v = d(gamma m c^2)/dt (W) and four_force "
    "K = gamma (F.v/c, F) (N), which is orthogonal to the 4-velocity. At rest the split has "
    "no meaning beyond gamma = 1: everything is Newton's.";

static const char example[] =
    "{\"mass\": 9.1093837015e-31, \"velocity\": {\"beta\": [0.6, 0, 0]}, "
    "\"acceleration\": [1e15, 2e15, 0]}";

static json_t *force_op(struct api_call *c, const json_t *body)
{
    const json_t *aj = json_object_get(body, "acceleration"), *fj = json_object_get(body, "force");
    if (aj && fj) {
        api_call_invalid(c, "/force", "give acceleration or force, not both");
        return NULL;
    }
    if (!aj && !fj) {
        api_call_invalid(c, "", "give the acceleration (m/s^2) or the force (N)");
        return NULL;
    }
    struct mech_boost b;
    if (!api_velocity_parse(c, json_object_get(body, "velocity"), "/velocity", &b)) return NULL;
    const double m = api_number(body, "mass", 1);
    struct mech_rel_force f;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = aj ? mech_rel_force_from_acceleration(m, &b, api_vec3_of(aj), &f, &e)
                             : mech_rel_force_from_force(m, &b, api_vec3_of(fj), &f, &e);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");
    json_t *out = json_object();
    if (!out) return api_call_fail_core(c, MECH_ENOMEM, NULL, "");
    json_object_set_new_nocheck(out, "gamma", api_real(c, b.gamma));
    json_object_set_new_nocheck(out, "force", api_vec3(c, f.force));
    json_object_set_new_nocheck(out, "force_parallel", api_vec3(c, f.force_parallel));
    json_object_set_new_nocheck(out, "force_perpendicular", api_vec3(c, f.force_perpendicular));
    json_object_set_new_nocheck(out, "acceleration", api_vec3(c, f.acceleration));
    json_object_set_new_nocheck(out, "acceleration_parallel", api_vec3(c, f.acceleration_parallel));
    json_object_set_new_nocheck(out, "acceleration_perpendicular",
                                api_vec3(c, f.acceleration_perpendicular));
    json_object_set_new_nocheck(out, "transverse_mass", api_real(c, f.transverse_mass));
    json_object_set_new_nocheck(out, "longitudinal_mass", api_real(c, f.longitudinal_mass));
    json_object_set_new_nocheck(out, "power", api_real(c, f.power));
    json_object_set_new_nocheck(out, "four_force", api_reals(c, f.four_force, 4));
    return out;
}

const struct api_route api_route_relativity_force = {
    "POST",
    "/v1/relativity/force",
    "F = dp/dt split along and across v (gamma^3 m a and gamma m a), either way round, with "
    "the power and the 4-force",
    description,
    schema,
    example,
    force_op,
    0,
    1, /* quick */
};
