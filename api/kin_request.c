/* kin_request.c — request readers shared by the particle-kinematics
 * operations (ep_relativity_kinematics.c, ep_relativity_elastic.c): the
 * energy unit, a particle's mass from its name or a number, and a state of
 * motion given by one of energy, kinetic_energy, momentum or velocity. */
#include "kin_request.h"

#include <stdio.h>
#include <string.h>

#include "velocity_request.h"

int api_kin_unit_of(struct api_call *c, const json_t *body, enum mech_energy_unit *u)
{
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_energy_unit_parse(api_string_of(body, "energy_unit"), u, &e);
    if (st != MECH_OK) {
        api_call_fail_core(c, st, &e, "");
        return 0;
    }
    return 1;
}

/* Mass of a particle field (name or number) in unit u; 0 after recording an error. */
int api_kin_mass_of(struct api_call *c, const json_t *v, const char *ptr, enum mech_energy_unit u,
                   double *m)
{
    if (json_is_string(v)) {
        const struct mech_particle *p = mech_particle_find(json_string_value(v));
        if (!p) {
            api_call_invalid(c, ptr, "unknown particle name \"%s\"", json_string_value(v));
            return 0;
        }
        *m = mech_energy_convert(p->mass, MECH_MEV, u);
        return 1;
    }
    double x = json_number_value(v);
    if (x < 0) {
        api_call_domain(c, ptr,
                        "a mass cannot be negative (m c^2 is the rest energy, >= 0), got %.17g", x);
        return 0;
    }
    *m = x;
    return 1;
}

/* State of motion of a KIN_MOVING object with mass m. *given says whether any
 * motion was given (else the particle is at rest). 0 after recording an error. */
int api_kin_motion_of(struct api_call *c, const json_t *obj, const char *ptr, double m,
                     struct mech_kin_motion *k, int *given)
{
    static const char *const keys[] = {"energy", "kinetic_energy", "momentum", "velocity"};
    const char *which = NULL;
    char p[160];
    for (int i = 0; i < 4; i++) {
        if (!json_object_get(obj, keys[i])) continue;
        if (which) {
            snprintf(p, sizeof p, "%s/%s", ptr, keys[i]);
            api_call_invalid(c, p,
                             "give only one of energy, kinetic_energy, momentum, velocity "
                             "(both %s and %s were given)",
                             which, keys[i]);
            return 0;
        }
        which = keys[i];
    }
    *given = which != NULL;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st;
    if (!which) {
        st = mech_kin_motion_at_rest(m, k, &e);
    } else if (!strcmp(which, "velocity")) {
        struct mech_boost b;
        snprintf(p, sizeof p, "%s/velocity", ptr);
        if (!api_velocity_parse(c, json_object_get(obj, "velocity"), p, &b)) return 0;
        st = mech_kin_motion_from_boost(m, &b, k, &e);
    } else {
        double x = api_number(obj, which, 0);
        if (!strcmp(which, "energy"))
            st = mech_kin_motion_from_energy(m, x, k, &e);
        else if (!strcmp(which, "kinetic_energy"))
            st = mech_kin_motion_from_kinetic(m, x, k, &e);
        else
            st = mech_kin_motion_from_momentum(m, x, k, &e);
    }
    if (st != MECH_OK) {
        if (!strcmp(e.param, "mass")) snprintf(e.param, sizeof e.param, "particle");
        api_call_fail_core(c, st, &e, ptr);
        return 0;
    }
    return 1;
}
