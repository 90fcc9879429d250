/* mech/answers/relativity/rocket_answer.h — one POST /v1/relativity/rocket answer, from the
 * request as read to everything the answer states: the exhaust speed (as a
 * fraction of c, in m/s, or the photon rocket's c), the final motion (given
 * in one of the speed forms of mech/relativity/particle_state.h, or reached by burning
 * to a mass ratio: η = β_e ln(m_i/m_f)), and the rocket's mass ratio beside
 * Tsiolkovsky's (mech/relativity/rocket.h). The API's handler parses, calls
 * mech_rocket_answer() once and encodes.
 *
 * Units: speeds over c unless the name says speed (m/s). Pure functions;
 * thread-safe; no allocation. */
#ifndef MECH_ROCKET_ANSWER_H
#define MECH_ROCKET_ANSWER_H

#include "mech/relativity/particle_state.h"
#include "mech/relativity/rocket.h"
#include "mech/base/status.h"

/* How the request gives the exhaust speed relative to the rocket. */
enum mech_rocket_exhaust {
    MECH_ROCKET_EXHAUST_PHOTON = 0, /* not given: u = c, a photon rocket */
    MECH_ROCKET_EXHAUST_BETA,       /* exhaust_beta = u/c in (0, 1] */
    MECH_ROCKET_EXHAUST_SPEED       /* exhaust_speed = u in m/s, (0, c] */
};

struct mech_rocket_request {
    enum mech_rocket_exhaust exhaust;
    double exhaust_value;           /* u/c or m/s, as `exhaust` says (unused for PHOTON) */
    int has_mass_ratio;             /* 1: mass_ratio answers the final speed */
    double mass_ratio;              /* m_i/m_f >= 1 */
    enum mech_particle_given given; /* !has_mass_ratio: the final speed's form (one of the
                                       velocity forms: BETA .. BETA_GAMMA) */
    double value;                   /* its number */
};

struct mech_rocket_answer {
    double exhaust_beta;                /* u/c as used */
    struct mech_particle_state final;   /* the final motion (mass 1: only the velocity
                                           members mean anything) */
    struct mech_rocket rocket;          /* mass ratio, fuel fraction, Tsiolkovsky's */
};

/* Compute *out for request q. Statuses, err->param naming the request's field:
 *   MECH_EINVAL (no param) for a NULL pointer or an unknown exhaust form;
 *   MECH_EDOMAIN "exhaust_beta" (outside (0, 1]) or "exhaust_speed" (outside
 *     (0, c] when given in m/s), from mech/relativity/rocket.h;
 *   MECH_EDOMAIN "mass_ratio" (< 1 or not finite), and MECH_EINVAL
 *     "mass_ratio" when the rapidity it gives is beyond the representable
 *     (η = β_e ln(m_i/m_f) > 350);
 *   mech_particle_state_from's statuses for the given form (param the form's
 *     name: "beta", "speed", "gamma", ...). The final motion is that of a
 *     unit mass, so ENERGY, MOMENTUM and KINETIC, if given, read `value` as
 *     γ, βγ and γ − 1.
 * out is written only on success.
 * err may be NULL. */
enum mech_status mech_rocket_answer(const struct mech_rocket_request *q,
                                    struct mech_rocket_answer *out, struct mech_error *err);

#endif
