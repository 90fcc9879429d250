/* kin_request.c — request readers and answer encoders shared by the
 * particle-kinematics operations (api/ops/relativity/kinematics_*.c): the
 * energy unit, a particle's mass from its name or a number, a state of
 * motion given by one of energy, kinetic_energy, momentum or velocity, an
 * angle in radians or degrees; a particle's and a system's motion encoded. */
#include "ops/relativity/kin_request.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mech/relativity/boost.h"
#include "mech/base/constants.h"
#include "ops/relativity/velocity_request.h"

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

/* ---- shared angle reader and answer encoders ---------------------------------- */

/* Angle from key (radians) or key_deg (degrees), at most one. Returns 1 if
 * present (value in *rad), 0 if absent, -1 after recording an error. */
int api_kin_angle_of(struct api_call *c, const json_t *obj, const char *key, const char *ptr,
                     double *rad)
{
    char kdeg[64];
    snprintf(kdeg, sizeof kdeg, "%s_deg", key);
    const json_t *r = json_object_get(obj, key), *d = json_object_get(obj, kdeg);
    if (r && d) {
        api_call_invalid(c, ptr, "give %s (radians) or %s (degrees), not both", key, kdeg);
        return -1;
    }
    if (r) *rad = json_number_value(r);
    if (d) *rad = json_number_value(d) / 180.0 * MECH_PI;
    return r || d;
}

/* mass, energy, kinetic_energy, momentum and (massive) the precise speed. */
json_t *api_kin_describe_motion(struct api_call *c, const struct mech_kin_motion *k)
{
    json_t *o = json_object();
    json_object_set_new_nocheck(o, "mass", api_real(c, k->mass));
    json_object_set_new_nocheck(o, "energy", api_real(c, k->energy));
    json_object_set_new_nocheck(o, "kinetic_energy", api_real(c, k->kinetic));
    json_object_set_new_nocheck(o, "momentum", api_real(c, k->momentum));
    struct mech_boost b;
    if (k->mass > 0 && mech_kin_motion_boost(k, mech_vec3_make(0, 0, 1), &b, NULL) == MECH_OK) {
        json_object_set_new_nocheck(o, "gamma", api_real(c, b.gamma));
        json_object_set_new_nocheck(o, "gamma_minus_one", api_real(c, b.gamma_minus_one));
        json_object_set_new_nocheck(o, "beta", api_real(c, b.beta));
        json_object_set_new_nocheck(o, "one_minus_beta", api_real(c, b.one_minus_beta));
        json_object_set_new_nocheck(o, "beta_gamma", api_real(c, b.beta_gamma));
        json_object_set_new_nocheck(o, "rapidity", api_real(c, b.rapidity));
    } else if (k->mass == 0) {
        json_object_set_new_nocheck(o, "beta", json_real(1.0));
        json_object_set_new_nocheck(o, "one_minus_beta", json_real(0.0));
    }
    return o;
}

/* The CM velocity block of a system (null when the total is light-like). */
json_t *api_kin_describe_cm(struct api_call *c, const struct mech_kin_system *s)
{
    if (!s->has_rest_frame) return json_null();
    json_t *o = json_object();
    json_object_set_new_nocheck(o, "gamma", api_real(c, s->gamma));
    json_object_set_new_nocheck(o, "gamma_minus_one", api_real(c, s->gamma_minus_one));
    json_object_set_new_nocheck(o, "beta", api_vec3(c, s->beta));
    json_object_set_new_nocheck(o, "rapidity", api_real(c, s->rapidity));
    json_object_set_new_nocheck(o, "one_minus_beta", api_real(c, s->one_minus_beta));
    json_object_set_new_nocheck(o, "beta_gamma", api_real(c, s->beta_gamma));
    return o;
}

json_t *api_kin_finish(struct api_call *c, json_t *res)
{
    if (!res) return api_call_fail_core(c, MECH_ENOMEM, NULL, "");
    return res;
}

/* The *_deg companion of an angle in radians (the description's promise). */
json_t *api_kin_deg_of(struct api_call *c, double rad)
{
    return api_real(c, rad * (180.0 / MECH_PI));
}
