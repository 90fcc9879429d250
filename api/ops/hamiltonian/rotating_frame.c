/* rotating_frame.c — POST /v1/hamiltonian/rotating-frame: a
 * particle's Lagrangian, canonical momentum m(v + omega x r), Hamiltonian in
 * a rotating frame and the inertial energy (notes ch. 1 homework: "calculate
 * the Hamiltonian in the rotating frame and see if it is the total energy").
 * JSON <-> core only; the physics is core/hamiltonian/rotating_hamiltonian.c. */
#include "run/endpoint.h"
#include "mech/hamiltonian/rotating_hamiltonian.h"

json_t *api_op_hamiltonian_rotating_frame(struct api_call *c, const json_t *body)
{
    const struct mech_vec3 z = mech_vec3_make(0, 0, 0);
    struct mech_rotating_hamiltonian h;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_rotating_hamiltonian_compute(
        api_number_of(body, "mass"), api_vec3_member(body, "omega", z),
        api_vec3_member(body, "position", z), api_vec3_member(body, "velocity", z),
        api_number_of(body, "potential_energy"), &h, &e);
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

