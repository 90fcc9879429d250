/* particle.c — POST /v1/relativity/particle: one free
 * particle's γ, β, E, p, T and rapidity from any one of them (notes §3), the
 * notes' non-relativistic kinetic energies beside the exact one, labelled,
 * and for an unstable particle its lifetime τ with cτ, γτ and βγcτ. What it
 * computes is one call, mech_particle_answer()
 * (core/answers/relativity/particle_answer.c); this file reads the request and
 * encodes the answer. */
#include <math.h>
#include <stdio.h>

#include "run/endpoint.h"
#include "mech/answers/relativity/particle_answer.h"

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

/* The request as the core takes it: the particle (a name or a mass), the
 * energy unit, exactly one form of the motion, the proper lifetime if
 * given. 0 after recording the error. */
static int read_request(struct api_call *c, const json_t *body, struct mech_particle_request *q,
                        size_t *which)
{
    q->energy_unit = api_string_of(body, "energy_unit");
    const json_t *pj = json_object_get(body, "particle");
    q->particle = json_string_value(pj);
    q->mass = json_number_value(pj);
    *which = N_FORMS;
    for (size_t i = 0; i < N_FORMS; i++) {
        if (!json_object_get(body, forms[i].key)) continue;
        if (*which != N_FORMS) {
            char ptr[64];
            snprintf(ptr, sizeof ptr, "/%s", forms[i].key);
            api_call_invalid(c, ptr, "give exactly one of beta, speed, gamma, gamma_minus_one, "
                                     "one_minus_beta, rapidity, beta_gamma, energy, momentum, "
                                     "kinetic_energy (both %s and %s were given)",
                             forms[*which].key, forms[i].key);
            return 0;
        }
        *which = i;
    }
    if (*which == N_FORMS) {
        api_call_invalid(c, "", "give the motion as exactly one of beta, speed, gamma, "
                                "gamma_minus_one, one_minus_beta, rapidity, beta_gamma, energy, "
                                "momentum, kinetic_energy (none was given)");
        return 0;
    }
    q->given = forms[*which].given;
    q->value = api_number_of(body, forms[*which].key);
    const json_t *tj = json_object_get(body, "proper_lifetime");
    q->has_proper_lifetime = tj != NULL;
    q->proper_lifetime = json_number_value(tj);
    return 1;
}

/* "approximations": the notes' two non-relativistic kinetic energies. */
static json_t *approximations_json(struct api_call *c, const struct mech_particle_state *s)
{
    json_t *ap = json_object();
    json_object_set_new_nocheck(
        ap, "newtonian",
        approximation(c, s->kinetic_newtonian, s->kinetic, s->kinetic_newtonian_rel_error,
                      "m v^2 / 2",
                      "approximation: the non-relativistic kinetic energy (notes §3, "
                      "\"the rest energy plus the kinetic energy 1/2 m v^2\"), beside the "
                      "exact T = (gamma - 1) m c^2"));
    json_object_set_new_nocheck(
        ap, "momentum_expansion",
        approximation(c, s->kinetic_p2_over_2m, s->kinetic, s->kinetic_p2_over_2m_rel_error,
                      "p^2 / 2m",
                      "approximation: the notes' first term of E = sqrt(m^2 c^4 + p^2 c^2) "
                      "~ m c^2 + p^2/2m (notes §3, the momentum 4-vector), beside the exact "
                      "T = E - m c^2"));
    return ap;
}

/* "lifetime": τ, cτ, γτ, cγτ, βγcτ. */
static json_t *lifetime_json(struct api_call *c, const struct mech_particle_answer *a)
{
    json_t *lo = json_object();
    json_object_set_new_nocheck(lo, "proper", api_real(c, a->lifetime.proper));
    json_object_set_new_nocheck(lo, "c_tau", api_real(c, a->lifetime.c_tau));
    json_object_set_new_nocheck(lo, "lab", api_real(c, a->lifetime.lab));
    json_object_set_new_nocheck(lo, "lab_c_tau", api_real(c, a->lab_c_tau));
    json_object_set_new_nocheck(lo, "decay_length", api_real(c, a->lifetime.decay_length));
    return lo;
}

json_t *api_op_relativity_particle(struct api_call *c, const json_t *body)
{
    struct mech_particle_request q = {0};
    size_t which;
    if (!read_request(c, body, &q, &which)) return NULL;
    struct mech_particle_answer a;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_particle_answer(&q, &a, &e);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");

    const struct mech_particle_state *s = &a.state;
    const int v = s->has_rest_frame;
    json_t *out = json_object();
    json_object_set_new_nocheck(out, "given", json_string(forms[which].key));
    json_object_set_new_nocheck(out, "energy_unit", json_string(mech_energy_unit_name(a.unit)));
    json_object_set_new_nocheck(out, "mass", api_real(c, s->mass));
    json_object_set_new_nocheck(out, "energy", api_real(c, s->energy));
    json_object_set_new_nocheck(out, "kinetic_energy", api_real(c, s->kinetic));
    json_object_set_new_nocheck(out, "momentum", api_real(c, s->momentum));
    json_object_set_new_nocheck(out, "beta", api_real(c, s->beta));
    json_object_set_new_nocheck(out, "one_minus_beta", api_real(c, s->one_minus_beta));
    json_object_set_new_nocheck(out, "speed", api_real(c, s->speed));
    json_object_set_new_nocheck(out, "gamma", real_or_null(c, v, s->gamma));
    json_object_set_new_nocheck(out, "gamma_minus_one", real_or_null(c, v, s->gamma_minus_one));
    json_object_set_new_nocheck(out, "beta_gamma", real_or_null(c, v, s->beta_gamma));
    json_object_set_new_nocheck(out, "rapidity", real_or_null(c, v, s->rapidity));
    json_object_set_new_nocheck(out, "approximations",
                                v ? approximations_json(c, s) : json_null());
    if (a.has_lifetime) json_object_set_new_nocheck(out, "lifetime", lifetime_json(c, &a));
    json_t *notes = json_array();
    if (!v)
        json_array_append_new(notes, json_string(
            "massless: the particle moves at c, so gamma, gamma_minus_one, beta_gamma and "
            "rapidity do not exist (null), and E = p = T"));
    json_object_set_new_nocheck(out, "notes", notes);
    return out;
}
