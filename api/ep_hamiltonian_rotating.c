/* ep_hamiltonian_rotating.c — POST /v1/hamiltonian/rotating-frame: a
 * particle's Lagrangian, canonical momentum m(v + omega x r), Hamiltonian in
 * a rotating frame and the inertial energy (notes ch. 1 homework: "calculate
 * the Hamiltonian in the rotating frame and see if it is the total energy").
 * JSON <-> core only; the physics is core/rotating_hamiltonian.c. */
#include "endpoint.h"
#include "mech/rotating_hamiltonian.h"

/* clang-format off */
#define RH_VEC(desc)                                                                               \
    "{\"type\":\"array\",\"minItems\":3,\"maxItems\":3,\"items\":{\"type\":\"number\","            \
    "\"minimum\":-1e100,\"maximum\":1e100},\"description\":\"" desc "\"}"
static const char schema[] =
    "{\"type\":\"object\",\"additionalProperties\":false,\"required\":[\"mass\",\"omega\","
    "\"position\",\"velocity\"],\"properties\":{"
    "\"mass\":{\"type\":\"number\",\"exclusiveMinimum\":0,\"maximum\":1e60,\"description\":"
    "\"mass m, kg\"},"
    "\"omega\":" RH_VEC("the frame's constant angular velocity, rad/s") ","
    "\"position\":" RH_VEC("r in the rotating frame (origin on the axis), m") ","
    "\"velocity\":" RH_VEC("v = dr/dt measured in the rotating frame, m/s") ","
    "\"potential_energy\":{\"type\":\"number\",\"minimum\":-1e100,\"maximum\":1e100,"
    "\"default\":0,\"description\":\"V at r, J\"}}}";
/* clang-format on */

static const char description[] =
    "A particle in a frame rotating with constant angular velocity omega (origin on the axis), "
    "given its position r and velocity v in that frame: L_rot = (1/2) m |v + omega x r|^2 - V; "
    "canonical_momentum p = dL/dv = m (v + omega x r), the inertial momentum (inertial_velocity "
    "= v + omega x r); hamiltonian H_rot = p.v - L = (1/2) m v^2 - (1/2) m |omega x r|^2 + V "
    "(with centrifugal_potential = -(1/2) m |omega x r|^2) and the same from p, "
    "hamiltonian_from_momentum = p^2/2m - omega.(r x p) + V, as a check; inertial_energy E = "
    "(1/2) m |v + omega x r|^2 + V; angular_momentum L = r x p and omega_dot_L = E - H_rot. "
    "H_rot is conserved (time-independent in the rotating frame) but is the total energy only "
    "when omega.L = 0: is_total_energy says which (answering the notes' chapter-1 homework).";

static const char example[] =
    "{\"mass\": 1, \"omega\": [0, 0, 0.5], \"position\": [2, 0, 0], \"velocity\": [0, 0, 0]}";

static json_t *rotating_op(struct api_call *c, const json_t *body)
{
    const struct mech_vec3 z = mech_vec3_make(0, 0, 0);
    struct mech_rotating_hamiltonian h;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_rotating_hamiltonian_compute(
        api_number(body, "mass", 1), api_vec3_member(body, "omega", z),
        api_vec3_member(body, "position", z), api_vec3_member(body, "velocity", z),
        api_number(body, "potential_energy", 0), &h, &e);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");
    json_t *out = json_object();
    if (!out) return api_call_fail_core(c, MECH_ENOMEM, NULL, "");
    json_object_set_new_nocheck(out, "inertial_velocity", api_vec3(c, h.inertial_velocity));
    json_object_set_new_nocheck(out, "canonical_momentum", api_vec3(c, h.canonical_momentum));
    json_object_set_new_nocheck(out, "angular_momentum", api_vec3(c, h.angular_momentum));
    json_object_set_new_nocheck(out, "lagrangian", api_real(c, h.lagrangian));
    json_object_set_new_nocheck(out, "hamiltonian", api_real(c, h.hamiltonian));
    json_object_set_new_nocheck(out, "hamiltonian_from_momentum",
                                api_real(c, h.hamiltonian_from_momentum));
    json_object_set_new_nocheck(out, "centrifugal_potential", api_real(c, h.centrifugal_potential));
    json_object_set_new_nocheck(out, "inertial_energy", api_real(c, h.inertial_energy));
    json_object_set_new_nocheck(out, "omega_dot_L", api_real(c, h.omega_dot_l));
    json_object_set_new_nocheck(out, "is_total_energy", json_boolean(h.omega_dot_l == 0));
    return out;
}

const struct api_route api_route_hamiltonian_rotating_frame = {
    "POST",
    "/v1/hamiltonian/rotating-frame",
    "Lagrangian, canonical momentum m(v + omega x r) and Hamiltonian in a rotating frame, "
    "beside the inertial energy (H_rot = E - omega.L)",
    description,
    schema,
    example,
    rotating_op,
    0,
    1, /* quick */
};
