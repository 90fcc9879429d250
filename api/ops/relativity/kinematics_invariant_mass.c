/* kinematics_invariant_mass.c — POST /v1/relativity/kinematics/invariant-mass:
 * the invariant mass and centre-of-momentum frame of a system of particles
 * (notes §3 "Kinematics Problems in Electron Volts").
 * Energies, masses (unit/c²) and momenta (unit/c) are in `energy_unit`
 * (eV … TeV, default MeV; c = 1); particles are a name from the PDG 2024 table
 * (core/relativity/particles.c) or a mass. The numerics live in
 * core/relativity/kinematics.c; the readers and encoders the kinematics
 * operations share are api/ops/relativity/kin_request.c. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "run/endpoint.h"
#include "mech/base/constants.h"
#include "mech/relativity/boost.h"
#include "mech/relativity/kinematics.h"
#include "mech/relativity/particles.h"
#include "ops/relativity/kin_request.h"

json_t *api_op_relativity_kinematics_invariant_mass(struct api_call *c, const json_t *body)
{
    enum mech_energy_unit u;
    if (!api_kin_unit_of(c, body, &u)) return NULL;
    const json_t *moms = json_object_get(body, "momenta");
    size_t n = json_array_size(moms);
    struct mech_kin_particle *ps = malloc(n * sizeof *ps);
    if (!ps) return api_call_fail_core(c, MECH_ENOMEM, NULL, "");
    json_t *clamped = json_array();
    int bad = 0;
    for (size_t i = 0; i < n; i++) {
        const json_t *it = json_array_get(moms, i);
        char ptr[64];
        snprintf(ptr, sizeof ptr, "/momenta/%zu", i);
        struct mech_error e;
        mech_error_clear(&e);
        enum mech_status st;
        if (json_is_array(it)) {
            double p4[4];
            for (size_t k = 0; k < 4; k++)
                p4[k] = json_number_value(json_array_get(it, k));
            int cl = 0;
            st = mech_kin_particle_from_four(p4, &ps[i], &cl, &e);
            if (st == MECH_OK && cl) json_array_append_new(clamped, json_integer((json_int_t)i));
        } else {
            char pp[80];
            double m;
            snprintf(pp, sizeof pp, "%s/particle", ptr);
            if (!api_kin_mass_of(c, json_object_get(it, "particle"), pp, u, &m)) {
                bad = 1;
                continue;
            }
            st = mech_kin_particle_from_mass(
                m, api_vec3_member(it, "momentum", mech_vec3_make(0, 0, 0)), &ps[i], &e);
        }
        if (st != MECH_OK) {
            if (st == MECH_EDOMAIN)
                api_call_domain(c, ptr, "momentum %zu: %s", i, e.text);
            else
                api_call_fail_core(c, st, &e, ptr);
            bad = 1;
        }
    }
    struct mech_kin_system s;
    struct mech_error e;
    mech_error_clear(&e);
    if (bad) {
        free(ps);
        json_decref(clamped);
        return NULL;
    }
    enum mech_status st = mech_kin_invariant_mass(ps, n, &c->budget, &s, &e);
    free(ps);
    if (st != MECH_OK) {
        json_decref(clamped);
        return api_call_fail_core(c, st, &e, "");
    }
    json_t *res = json_object();
    json_object_set_new_nocheck(res, "energy_unit", json_string(mech_energy_unit_name(u)));
    json_object_set_new_nocheck(res, "invariant_mass", api_real(c, s.mass));
    json_object_set_new_nocheck(res, "invariant_mass_squared", api_real(c, s.mass_squared));
    json_object_set_new_nocheck(res, "total_energy", api_real(c, s.energy));
    json_object_set_new_nocheck(res, "total_momentum", api_vec3(c, s.momentum));
    json_object_set_new_nocheck(res, "center_of_momentum", api_kin_describe_cm(c, &s));
    if (!s.has_rest_frame)
        json_object_set_new_nocheck(
            res, "note",
            json_string("the total 4-momentum is light-like (M = 0): no frame "
                        "has zero total momentum"));
    if (json_array_size(clamped))
        json_object_set_new_nocheck(res, "lightlike_clamped", clamped);
    else
        json_decref(clamped);
    return api_kin_finish(c, res);
}
