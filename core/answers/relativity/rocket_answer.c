/* rocket_answer.c — the POST /v1/relativity/rocket answer (see
 * mech/answers/relativity/rocket_answer.h): the exhaust speed as used, the final motion given
 * or reached from a mass ratio (particle_state.c), and the mass ratio beside
 * Tsiolkovsky's (rocket.c). */
#include <stdio.h>
#include <string.h>

#include "mech/answers/relativity/rocket_answer.h"

/* The request names its field differently from the core it calls: the
 * exhaust as given in m/s is "exhaust_speed". */
static enum mech_status rename_exhaust(const struct mech_rocket_request *q, enum mech_status st,
                                       struct mech_error *err)
{
    if (st != MECH_OK && err && q->exhaust == MECH_ROCKET_EXHAUST_SPEED &&
        !strcmp(err->param, "exhaust_beta"))
        snprintf(err->param, sizeof err->param, "exhaust_speed");
    return st;
}

enum mech_status mech_rocket_answer(const struct mech_rocket_request *q,
                                    struct mech_rocket_answer *out, struct mech_error *err)
{
    if (!q || !out) return mech_error_set(err, MECH_EINVAL, NULL, "NULL argument");
    struct mech_rocket_answer a;
    switch (q->exhaust) {
    case MECH_ROCKET_EXHAUST_PHOTON:
        a.exhaust_beta = 1.0;
        break;
    case MECH_ROCKET_EXHAUST_BETA:
        a.exhaust_beta = q->exhaust_value;
        break;
    case MECH_ROCKET_EXHAUST_SPEED:
        a.exhaust_beta = q->exhaust_value / MECH_PARTICLE_STATE_C;
        break;
    default:
        return mech_error_set(err, MECH_EINVAL, NULL, "unknown exhaust form %d", (int)q->exhaust);
    }
    enum mech_status st;
    if (q->has_mass_ratio) {
        /* Ackeret's rocket: eta = beta_e ln(m_i/m_f) (mech/relativity/rocket.h) */
        double eta;
        st = mech_rocket_rapidity(q->mass_ratio, a.exhaust_beta, &eta, err);
        if (st == MECH_OK)
            st = mech_particle_state_from(1.0, MECH_PARTICLE_GIVEN_RAPIDITY, eta, &a.final, err);
        /* a rapidity out of range is the mass ratio's doing */
        if (st != MECH_OK && err && !strcmp(err->param, "rapidity"))
            snprintf(err->param, sizeof err->param, "mass_ratio");
    } else {
        st = mech_particle_state_from(1.0, q->given, q->value, &a.final, err);
    }
    if (st == MECH_OK)
        st = mech_rocket_for_rapidity(a.final.rapidity, a.final.beta, a.exhaust_beta, &a.rocket,
                                      err);
    if (st != MECH_OK) return rename_exhaust(q, st, err);
    *out = a;
    return MECH_OK;
}
