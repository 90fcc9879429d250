/* mech/relativity/particle_state.h — one free particle's state of motion from any one
 * of its descriptions (notes §3: γ, β, E = γmc², p = γmv, T = E − mc²,
 * rapidity η = atanh β), every other one computed without cancellation,
 * plus the notes' non-relativistic kinetic energy ½mv² beside the exact T
 * and, for an unstable particle, its lifetime τ with cτ, γτ and βγcτ.
 *
 * Units: natural (c = 1): the mass, E, p and T in one energy unit chosen by
 * the caller; β, γ, η dimensionless; lifetimes in seconds, lengths in metres.
 * Precision: γ − 1, 1 − β, βγ and η come from whichever quantity was given
 * (through mech/relativity/boost.h and mech/relativity/kinematics.h), never as 1/sqrt(1 − β²) of a
 * rounded β: T = m βγ²β/(γ + 1) is right to round-off at 1 m/s and at
 * 1 − β = 1e-15. Pure functions; thread-safe; no allocation.
 */
#ifndef MECH_PARTICLE_STATE_H
#define MECH_PARTICLE_STATE_H

#include "mech/base/constants.h"
#include "mech/base/status.h"

/* Speed of light, m/s (exact, SI 2019). */
#define MECH_PARTICLE_STATE_C MECH_C /* the speed of light of mech/base/constants.h, under the name api/ uses */

/* The quantity the caller gives (its number is taken as exact). */
enum mech_particle_given {
    MECH_PARTICLE_GIVEN_BETA,            /* β in [0, 1) */
    MECH_PARTICLE_GIVEN_SPEED,           /* v in m/s, [0, c) */
    MECH_PARTICLE_GIVEN_GAMMA,           /* γ ≥ 1 */
    MECH_PARTICLE_GIVEN_GAMMA_MINUS_ONE, /* γ − 1 ≥ 0 */
    MECH_PARTICLE_GIVEN_ONE_MINUS_BETA,  /* 1 − β in (0, 1] */
    MECH_PARTICLE_GIVEN_RAPIDITY,        /* η ≥ 0 */
    MECH_PARTICLE_GIVEN_BETA_GAMMA,      /* βγ = p/m ≥ 0 */
    MECH_PARTICLE_GIVEN_ENERGY,          /* E ≥ m */
    MECH_PARTICLE_GIVEN_MOMENTUM,        /* |p| ≥ 0 */
    MECH_PARTICLE_GIVEN_KINETIC,         /* T ≥ 0 */
};

struct mech_particle_state {
    double mass, energy, momentum, kinetic; /* m, E = γm, p = βγm, T = (γ − 1)m */
    int has_rest_frame;   /* 0 for a massless particle: the velocity members below are
                             then β = 1, 1 − β = 0, speed = c and the others 0 (they do not
                             exist: γ, γ − 1, βγ, η infinite) */
    double beta, one_minus_beta, speed;      /* β, 1 − β, v = βc in m/s */
    double gamma, gamma_minus_one, beta_gamma, rapidity;
    /* The notes' approximation T ≈ ½ m β² (m > 0) and its relative error
     * (½mβ² − T)/T = −(γ − 1)(2γ + 1)/(2γ²), 0 at rest, → −1 as β → 1. */
    double kinetic_newtonian, kinetic_newtonian_rel_error;
    /* The notes' E ≈ mc² + p²/2m (notes §3 "the momentum 4-vector", from the
     * binomial expansion of sqrt(m² + p²)): T ≈ p²/2m = ½ m (βγ)², relative
     * error (p²/2m − T)/T = (γ − 1)/2, exactly. May overflow to infinity
     * when T itself is near the double range (then it does not exist). */
    double kinetic_p2_over_2m, kinetic_p2_over_2m_rel_error;
};

/* Fill *out for a particle of mass m ≥ 0 (energy unit) and the given
 * quantity `value`. A massless particle (m = 0) takes only an energy,
 * momentum or kinetic energy (> 0). Statuses: MECH_OK; MECH_EDOMAIN with
 * param "mass" (m < 0, or m = 0 with a velocity form: a massless particle
 * moves at c), or the given quantity's name ("beta", "speed", "gamma",
 * "gamma_minus_one", "one_minus_beta", "rapidity", "beta_gamma", "energy",
 * "momentum", "kinetic_energy") when it is outside its range (β ≥ 1, γ < 1,
 * E < m, …) with a sentence saying which range; MECH_EINVAL with the same
 * params for a non-finite value or a speed too close to c to represent
 * (η > 350). out is written only on success. */
enum mech_status mech_particle_state_from(double m, enum mech_particle_given given, double value,
                                          struct mech_particle_state *out,
                                          struct mech_error *err);

/* An unstable particle's lifetime seen in the lab (notes §3.4, the muon). */
struct mech_particle_lifetime {
    double proper;       /* τ, s */
    double c_tau;        /* cτ, m */
    double lab;          /* γτ, s (τ when massless: not defined, see has_rest_frame) */
    double decay_length; /* βγcτ, m: the mean distance travelled before decaying */
};

/* The lifetime block for a state with a rest frame and τ > 0 (s). Statuses:
 * MECH_OK; MECH_EDOMAIN param "proper_lifetime" (τ ≤ 0 or not finite) or
 * "mass" (massless: no proper time). out written only on success. */
enum mech_status mech_particle_lifetime_of(const struct mech_particle_state *s, double tau,
                                           struct mech_particle_lifetime *out,
                                           struct mech_error *err);

#endif
