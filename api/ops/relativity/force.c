/* force.c — POST /v1/relativity/force: Newton's second law in
 * special relativity, F = dp/dt = gamma m a_perp + gamma^3 m a_par, either
 * way round, with the power and the 4-force (notes §3 "The Force 4-Vector").
 * JSON <-> core only; the physics is core/relativity/relativistic_force.c. */
#include "run/endpoint.h"
#include "mech/relativity/relativistic_force.h"
#include "ops/relativity/velocity_request.h"

json_t *api_op_relativity_force(struct api_call *c, const json_t *body)
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
    const double m = api_number_of(body, "mass");
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

