/* ep_relativity_particle.c — POST /v1/relativity/particle: one free
 * particle's γ, β, E, p, T and rapidity from any one of them (notes §3), the
 * notes' non-relativistic kinetic energies beside the exact one, labelled,
 * and for an unstable particle its lifetime τ with cτ, γτ and βγcτ.
 * JSON <-> core only; the numerics are core/particle_state.c. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "endpoint.h"
#include "mech/particle_state.h"
#include "mech/particles.h"

/* The forms a motion may be given in: request key and core enum, in the
 * order the description lists them. */
static const struct {
    const char *key;
    enum mech_particle_given given;
} forms[] = {
    {"beta", MECH_PARTICLE_GIVEN_BETA},
    {"speed", MECH_PARTICLE_GIVEN_SPEED},
    {"gamma", MECH_PARTICLE_GIVEN_GAMMA},
    {"gamma_minus_one", MECH_PARTICLE_GIVEN_GAMMA_MINUS_ONE},
    {"one_minus_beta", MECH_PARTICLE_GIVEN_ONE_MINUS_BETA},
    {"rapidity", MECH_PARTICLE_GIVEN_RAPIDITY},
    {"beta_gamma", MECH_PARTICLE_GIVEN_BETA_GAMMA},
    {"energy", MECH_PARTICLE_GIVEN_ENERGY},
    {"momentum", MECH_PARTICLE_GIVEN_MOMENTUM},
    {"kinetic_energy", MECH_PARTICLE_GIVEN_KINETIC},
};
#define N_FORMS (sizeof forms / sizeof forms[0])

static json_t *real_or_null(struct api_call *c, int ok, double x)
{
    return ok ? api_real(c, x) : json_null();
}

/* One labelled approximation beside the exact value. */
static json_t *approximation(struct api_call *c, double value, double exact, double rel,
                             const char *formula, const char *label)
{
    json_t *o = json_object();
    if (!o) return NULL;
    int ok = isfinite(value);
    json_object_set_new_nocheck(o, "formula", json_string(formula));
    json_object_set_new_nocheck(o, "value", real_or_null(c, ok, value));
    json_object_set_new_nocheck(o, "exact", api_real(c, exact));
    json_object_set_new_nocheck(o, "relative_error", api_real(c, rel));
    json_object_set_new_nocheck(o, "label", json_string(label));
    return o;
}

static int mass_of(struct api_call *c, const json_t *v, enum mech_energy_unit u, double *m)
{
    if (json_is_string(v)) {
        const struct mech_particle *p = mech_particle_find(json_string_value(v));
        if (!p) {
            api_call_invalid(c, "/particle", "unknown particle name \"%s\"", json_string_value(v));
            return 0;
        }
        *m = mech_energy_convert(p->mass, MECH_MEV, u);
        return 1;
    }
    *m = json_number_value(v);
    return 1;
}

json_t *api_op_relativity_particle(struct api_call *c, const json_t *body)
{
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_energy_unit unit;
    enum mech_status st = mech_energy_unit_parse(api_string_of(body, "energy_unit"), &unit, &e);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");
    double m;
    if (!mass_of(c, json_object_get(body, "particle"), unit, &m)) return NULL;

    size_t which = N_FORMS;
    for (size_t i = 0; i < N_FORMS; i++) {
        if (!json_object_get(body, forms[i].key)) continue;
        if (which != N_FORMS) {
            char ptr[64];
            snprintf(ptr, sizeof ptr, "/%s", forms[i].key);
            api_call_invalid(c, ptr, "give exactly one of beta, speed, gamma, gamma_minus_one, "
                                     "one_minus_beta, rapidity, beta_gamma, energy, momentum, "
                                     "kinetic_energy (both %s and %s were given)",
                             forms[which].key, forms[i].key);
            return NULL;
        }
        which = i;
    }
    if (which == N_FORMS) {
        api_call_invalid(c, "", "give the motion as exactly one of beta, speed, gamma, "
                                "gamma_minus_one, one_minus_beta, rapidity, beta_gamma, energy, "
                                "momentum, kinetic_energy (none was given)");
        return NULL;
    }
    struct mech_particle_state s;
    st = mech_particle_state_from(m, forms[which].given, api_number(body, forms[which].key, 0), &s,
                                  &e);
    if (st != MECH_OK) {
        if (!strcmp(e.param, "mass")) snprintf(e.param, sizeof e.param, "particle");
        return api_call_fail_core(c, st, &e, "");
    }
    const json_t *tj = json_object_get(body, "proper_lifetime");
    struct mech_particle_lifetime life;
    if (tj && (st = mech_particle_lifetime_of(&s, json_number_value(tj), &life, &e)) != MECH_OK) {
        if (!strcmp(e.param, "mass")) snprintf(e.param, sizeof e.param, "particle");
        return api_call_fail_core(c, st, &e, "");
    }

    json_t *out = json_object();
    if (!out) return api_call_fail_core(c, MECH_ENOMEM, NULL, "");
    const int v = s.has_rest_frame;
    json_object_set_new_nocheck(out, "given", json_string(forms[which].key));
    json_object_set_new_nocheck(out, "energy_unit", json_string(mech_energy_unit_name(unit)));
    json_object_set_new_nocheck(out, "mass", api_real(c, s.mass));
    json_object_set_new_nocheck(out, "energy", api_real(c, s.energy));
    json_object_set_new_nocheck(out, "kinetic_energy", api_real(c, s.kinetic));
    json_object_set_new_nocheck(out, "momentum", api_real(c, s.momentum));
    json_object_set_new_nocheck(out, "beta", api_real(c, s.beta));
    json_object_set_new_nocheck(out, "one_minus_beta", api_real(c, s.one_minus_beta));
    json_object_set_new_nocheck(out, "speed", api_real(c, s.speed));
    json_object_set_new_nocheck(out, "gamma", real_or_null(c, v, s.gamma));
    json_object_set_new_nocheck(out, "gamma_minus_one", real_or_null(c, v, s.gamma_minus_one));
    json_object_set_new_nocheck(out, "beta_gamma", real_or_null(c, v, s.beta_gamma));
    json_object_set_new_nocheck(out, "rapidity", real_or_null(c, v, s.rapidity));
    if (v) {
        json_t *ap = json_object();
        json_object_set_new_nocheck(
            ap, "newtonian",
            approximation(c, s.kinetic_newtonian, s.kinetic, s.kinetic_newtonian_rel_error,
                          "m v^2 / 2",
                          "approximation: the non-relativistic kinetic energy (notes §3, "
                          "\"the rest energy plus the kinetic energy 1/2 m v^2\"), beside the "
                          "exact T = (gamma - 1) m c^2"));
        json_object_set_new_nocheck(
            ap, "momentum_expansion",
            approximation(c, s.kinetic_p2_over_2m, s.kinetic, s.kinetic_p2_over_2m_rel_error,
                          "p^2 / 2m",
                          "approximation: the notes' first term of E = sqrt(m^2 c^4 + p^2 c^2) "
                          "~ m c^2 + p^2/2m (notes §3, the momentum 4-vector), beside the exact "
                          "T = E - m c^2"));
        json_object_set_new_nocheck(out, "approximations", ap);
    } else {
        json_object_set_new_nocheck(out, "approximations", json_null());
    }
    if (tj) {
        json_t *lo = json_object();
        json_object_set_new_nocheck(lo, "proper", api_real(c, life.proper));
        json_object_set_new_nocheck(lo, "c_tau", api_real(c, life.c_tau));
        json_object_set_new_nocheck(lo, "lab", api_real(c, life.lab));
        json_object_set_new_nocheck(lo, "lab_c_tau", api_real(c, life.lab * MECH_PARTICLE_STATE_C));
        json_object_set_new_nocheck(lo, "decay_length", api_real(c, life.decay_length));
        json_object_set_new_nocheck(out, "lifetime", lo);
    }
    json_t *notes = json_array();
    if (!v)
        json_array_append_new(notes, json_string(
            "massless: the particle moves at c, so gamma, gamma_minus_one, beta_gamma and "
            "rapidity do not exist (null), and E = p = T"));
    json_object_set_new_nocheck(out, "notes", notes);
    return out;
}

