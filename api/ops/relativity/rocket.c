/* rocket.c — POST /v1/relativity/rocket: the relativistic
 * rocket's mass ratio for a final speed or rapidity (or the speed a mass
 * ratio gives), beside Tsiolkovsky's, labelled. What it computes is one
 * call, mech_rocket_answer() (core/answers/relativity/rocket_answer.c); this file
 * reads the request and encodes the answer. */
#include <math.h>
#include <stdio.h>

#include "run/endpoint.h"
#include "mech/answers/relativity/rocket_answer.h"

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
};
#define N_FORMS (sizeof forms / sizeof forms[0])

static json_t *real_or_null(struct api_call *c, double x)
{
    return isfinite(x) ? api_real(c, x) : json_null();
}

/* The request as the core takes it: the exhaust (exhaust_beta or
 * exhaust_speed; neither: a photon rocket, the description's default 1),
 * and the final speed in exactly one form or a mass_ratio. 0 after
 * recording the error. */
static int read_request(struct api_call *c, const json_t *body, struct mech_rocket_request *q)
{
    const json_t *eb = json_object_get(body, "exhaust_beta"), *es = json_object_get(body, "exhaust_speed");
    if (eb && es) {
        api_call_invalid(c, "/exhaust_speed", "give exhaust_beta or exhaust_speed, not both");
        return 0;
    }
    q->exhaust = eb ? MECH_ROCKET_EXHAUST_BETA : es ? MECH_ROCKET_EXHAUST_SPEED : MECH_ROCKET_EXHAUST_PHOTON;
    q->exhaust_value = json_number_value(eb ? eb : es);
    size_t which = N_FORMS;
    const json_t *mr = json_object_get(body, "mass_ratio");
    for (size_t i = 0; i < N_FORMS; i++) {
        if (!json_object_get(body, forms[i].key)) continue;
        if (which != N_FORMS || mr) {
            char ptr[64];
            snprintf(ptr, sizeof ptr, "/%s", forms[i].key);
            api_call_invalid(c, ptr, "give the final speed in exactly one form, or a "
                                     "mass_ratio (%s was given too)",
                             mr ? "mass_ratio" : forms[which].key);
            return 0;
        }
        which = i;
    }
    if (which == N_FORMS && !mr) {
        api_call_invalid(c, "", "give the final speed (beta, speed, gamma, gamma_minus_one, "
                                "one_minus_beta, rapidity or beta_gamma) or a mass_ratio");
        return 0;
    }
    q->has_mass_ratio = mr != NULL;
    q->mass_ratio = json_number_value(mr);
    if (!mr) {
        q->given = forms[which].given;
        q->value = api_number_of(body, forms[which].key);
    }
    return 1;
}

/* "final": the speed reached, in every form. */
static json_t *final_json(struct api_call *c, const struct mech_particle_state *s)
{
    json_t *fin = json_object();
    json_object_set_new_nocheck(fin, "beta", api_real(c, s->beta));
    json_object_set_new_nocheck(fin, "one_minus_beta", api_real(c, s->one_minus_beta));
    json_object_set_new_nocheck(fin, "gamma", api_real(c, s->gamma));
    json_object_set_new_nocheck(fin, "gamma_minus_one", api_real(c, s->gamma_minus_one));
    json_object_set_new_nocheck(fin, "rapidity", api_real(c, s->rapidity));
    json_object_set_new_nocheck(fin, "beta_gamma", api_real(c, s->beta_gamma));
    json_object_set_new_nocheck(fin, "speed", api_real(c, s->speed));
    return fin;
}

json_t *api_op_relativity_rocket(struct api_call *c, const json_t *body)
{
    struct mech_rocket_request q = {0};
    if (!read_request(c, body, &q)) return NULL;
    struct mech_rocket_answer a;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_rocket_answer(&q, &a, &e);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");
    const struct mech_rocket *r = &a.rocket;
    json_t *out = json_object(), *nw = json_object();
    json_object_set_new_nocheck(out, "final", final_json(c, &a.final));
    json_object_set_new_nocheck(out, "exhaust_beta", api_real(c, a.exhaust_beta));
    json_object_set_new_nocheck(out, "mass_ratio", real_or_null(c, r->mass_ratio));
    json_object_set_new_nocheck(out, "log_mass_ratio", api_real(c, r->log_mass_ratio));
    json_object_set_new_nocheck(out, "fuel_fraction", api_real(c, r->fuel_fraction));
    json_object_set_new_nocheck(nw, "formula", json_string("m_i/m_f = exp(v/u) (Tsiolkovsky)"));
    json_object_set_new_nocheck(nw, "mass_ratio", real_or_null(c, r->newtonian_mass_ratio));
    json_object_set_new_nocheck(nw, "log_mass_ratio", api_real(c, r->newtonian_log_mass_ratio));
    json_object_set_new_nocheck(nw, "relative_error", api_real(c, r->newtonian_rel_error));
    json_object_set_new_nocheck(
        nw, "label",
        json_string("approximation: the non-relativistic rocket equation, beside the exact "
                    "mass_ratio; it underestimates the fuel needed"));
    json_object_set_new_nocheck(out, "newtonian", nw);
    return out;
}
