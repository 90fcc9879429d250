/* lagrangian.c — POST /v1/relativity/lagrangian: the
 * relativistic Lagrangian, canonical momentum and Hamiltonian of a charged
 * particle in given potentials or uniform fields (notes §3, L = −mc²/γ − V,
 * H = E + V). JSON <-> core only; the physics is core/relativity/charged_lagrangian.c. */
#include <string.h>

#include "run/endpoint.h"
#include "mech/relativity/charged_lagrangian.h"
#include "ops/relativity/velocity_request.h"

json_t *api_op_relativity_lagrangian(struct api_call *c, const json_t *body)
{
    const json_t *fj = json_object_get(body, "fields");
    /* given, not defaulted: the potentials default to 0 */
    if (fj && (api_call_given(c, "/scalar_potential") || api_call_given(c, "/vector_potential"))) {
        api_call_invalid(c, "/fields", "give potentials or uniform fields, not both");
        return NULL;
    }
    struct mech_boost b;
    if (!api_velocity_parse(c, json_object_get(body, "velocity"), "/velocity", &b)) return NULL;
    const double m = api_number_of(body, "mass"), q = api_number_of(body, "charge");
    const struct mech_vec3 zero = mech_vec3_make(0, 0, 0);
    double phi = api_number_of(body, "scalar_potential");
    struct mech_vec3 a = api_vec3_of(json_object_get(body, "vector_potential"));
    struct mech_vec3 ef = zero, bf = zero;
    if (fj) {
        ef = api_vec3_member(fj, "E", zero);
        bf = api_vec3_member(fj, "B", zero);
        mech_charged_uniform_potentials(ef, bf, api_vec3_member(fj, "position", zero), &phi, &a);
    }
    struct mech_charged_state s;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_charged_state_compute(m, q, &b, phi, a, &s, &e);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");
    json_t *out = json_object(), *ap = json_object(), *ln = json_object();
    if (!out || !ap || !ln) {
        json_decref(out), json_decref(ap), json_decref(ln);
        return api_call_fail_core(c, MECH_ENOMEM, NULL, "");
    }
    json_object_set_new_nocheck(out, "gamma", api_real(c, b.gamma));
    json_object_set_new_nocheck(out, "scalar_potential", api_real(c, phi));
    json_object_set_new_nocheck(out, "vector_potential", api_vec3(c, a));
    json_object_set_new_nocheck(out, "lagrangian", api_real(c, s.lagrangian));
    json_object_set_new_nocheck(out, "lagrangian_plus_rest_energy",
                                api_real(c, s.lagrangian_plus_rest));
    json_object_set_new_nocheck(out, "kinetic_momentum", api_vec3(c, s.kinetic_momentum));
    json_object_set_new_nocheck(out, "canonical_momentum", api_vec3(c, s.canonical_momentum));
    json_object_set_new_nocheck(out, "hamiltonian", api_real(c, s.hamiltonian));
    json_object_set_new_nocheck(out, "hamiltonian_minus_rest_energy",
                                api_real(c, s.hamiltonian_minus_rest));
    json_object_set_new_nocheck(out, "energy", api_real(c, s.energy));
    json_object_set_new_nocheck(out, "potential_energy", api_real(c, s.potential_energy));
    json_object_set_new_nocheck(out, "hamiltonian_from_momentum",
                                api_real(c, s.hamiltonian_from_momentum));
    json_object_set_new_nocheck(out, "legendre_residual", api_real(c, s.legendre_residual));
    if (fj) {
        const struct mech_vec3 v = mech_vec3_scale(b.beta_vec, MECH_CHARGED_C);
        const struct mech_vec3 f = mech_vec3_scale(mech_vec3_add(ef, mech_vec3_cross(v, bf)), q);
        json_object_set_new_nocheck(out, "lorentz_force", api_vec3(c, f));
    }
    json_object_set_new_nocheck(ln, "value", api_real(c, s.lagrangian_newtonian_plus_rest));
    json_object_set_new_nocheck(ln, "exact", api_real(c, s.lagrangian_plus_rest));
    json_object_set_new_nocheck(
        ln, "label",
        json_string("approximation: the notes' non-relativistic L + m c^2 = (1/2) m v^2 + q A.v "
                    "- q phi (L = T - V), beside the exact lagrangian_plus_rest_energy"));
    json_object_set_new_nocheck(ap, "lagrangian_newtonian", ln);
    json_object_set_new_nocheck(out, "approximations", ap);
    return out;
}

