/* particle_answer.c — the POST /v1/relativity/particle answer (see
 * mech/answers/relativity/particle_answer.h): the unit and the mass resolved (particles.c),
 * the state of motion (particle_state.c) and the lifetime in the lab. */
#include <stdio.h>
#include <string.h>

#include "mech/answers/relativity/particle_answer.h"

/* The core's "mass" is the request's "particle" (a name or a mass). */
static enum mech_status rename_mass(enum mech_status st, struct mech_error *err)
{
    if (st != MECH_OK && err && !strcmp(err->param, "mass"))
        snprintf(err->param, sizeof err->param, "particle");
    return st;
}

enum mech_status mech_particle_answer(const struct mech_particle_request *q,
                                      struct mech_particle_answer *out, struct mech_error *err)
{
    if (!q || !out) return mech_error_set(err, MECH_EINVAL, NULL, "NULL argument");
    struct mech_particle_answer a;
    enum mech_status st = mech_energy_unit_parse(q->energy_unit, &a.unit, err);
    if (st != MECH_OK) return st;
    double m = q->mass;
    if (q->particle) {
        const struct mech_particle *p = mech_particle_find(q->particle);
        if (!p)
            return mech_error_set(err, MECH_EINVAL, "particle", "unknown particle name \"%s\"",
                                  q->particle);
        m = mech_energy_convert(p->mass, MECH_MEV, a.unit);
    }
    st = mech_particle_state_from(m, q->given, q->value, &a.state, err);
    if (st != MECH_OK) return rename_mass(st, err);
    a.has_lifetime = q->has_proper_lifetime;
    if (a.has_lifetime) {
        st = mech_particle_lifetime_of(&a.state, q->proper_lifetime, &a.lifetime, err);
        if (st != MECH_OK) return rename_mass(st, err);
        a.lab_c_tau = a.lifetime.lab * MECH_PARTICLE_STATE_C;
    }
    *out = a;
    return MECH_OK;
}
