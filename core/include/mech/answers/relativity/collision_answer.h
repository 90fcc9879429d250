/* mech/answers/relativity/collision_answer.h — one POST /v1/relativity/kinematics/collision
 * answer (notes §3, problems 10 and 18): a beam on a target at rest, or two
 * beams (the target moving along -z, tilted towards +x by a crossing angle);
 * s, sqrt(s) and s - (m1 + m2)^2 without cancellation (mech/relativity/kinematics.h),
 * the available energy, the CM momentum and velocity, the fixed-target and
 * symmetric-collider equivalents, the inverse problem (the beam energy for a
 * given sqrt(s) on a target at rest) and a final state's production
 * threshold. Natural units (c = 1): every energy, mass (unit/c^2) and
 * momentum (unit/c) in one energy unit of the caller's; angles in radians.
 * Pure; thread-safe; no allocation. */
#ifndef MECH_COLLISION_ANSWER_H
#define MECH_COLLISION_ANSWER_H

#include <stddef.h>

#include "mech/relativity/kinematics.h"
#include "mech/base/status.h"

#define MECH_COLLISION_MAX_FINAL 100 /* final-state particles at most */

struct mech_collision_request {
    /* The beam (along +z): its motion, or with beam_from_sqrt_s only its
     * mass beam.mass >= 0 (the energy is solved from sqrt_s). */
    struct mech_kin_motion beam;
    int beam_from_sqrt_s;
    double sqrt_s; /* beam_from_sqrt_s: the CM energy wanted, >= m1 + m2 */
    /* The target: at rest, or a second beam along -z. */
    struct mech_kin_motion target;
    double crossing_angle;      /* rad in [0, pi]: the momenta are at pi - angle (0: head-on) */
    const double *final_masses; /* borrowed; n_final of them, each >= 0 */
    size_t n_final;             /* 0: no threshold asked; <= MECH_COLLISION_MAX_FINAL */
};

/* The production threshold of a final state. */
struct mech_collision_threshold {
    double sqrt_s; /* the final masses' sum (compensated) */
    int reached;   /* the collision's sqrt(s) >= it */
    /* target mass > 0: the beam a target at rest needs at threshold (kinetic
     * 0 when the two at rest already reach it) */
    int has_fixed_target;
    double fixed_target_beam_energy, fixed_target_beam_kinetic;
    double fixed_target_beam_momentum; /* sqrt(T (T + 2 m1)): no cancellation at small T */
    /* equal masses and sqrt_s / 2 >= m: each beam's energy in a symmetric
     * head-on collider */
    int has_symmetric_collider;
    double symmetric_collider_beam_energy;
};

struct mech_collision_answer {
    struct mech_kin_motion beam, target; /* the beam solved when beam_from_sqrt_s */
    double s, sqrt_s;                    /* s = m1^2 + m2^2 + 2 (E1 E2 - p1.p2) */
    double s_minus_threshold;            /* s - (m1 + m2)^2 >= 0, without cancellation */
    double available_energy; /* sqrt(s) - m1 - m2 = (s - (m1 + m2)^2) / (sqrt s + m1 + m2) */
    double cm_momentum;      /* p* = sqrt(lambda(s, m1^2, m2^2)) / (2 sqrt s) */
    /* the total 4-momentum; its CM velocity when cm.has_rest_frame (the
     * momentum's z from p1 - p2 formed from the beams' own inputs) */
    struct mech_kin_system cm;
    /* target mass > 0: the beam energy a target at rest of that mass needs
     * for the same sqrt(s), T = (s - (m1 + m2)^2) / (2 m2) */
    int has_fixed_target;
    double fixed_target_beam_energy, fixed_target_beam_kinetic;
    /* equal masses and sqrt(s) / 2 >= m: the symmetric collider's beam energy */
    int has_symmetric_collider;
    double symmetric_collider_beam_energy;
    int has_threshold; /* n_final > 0 */
    struct mech_collision_threshold threshold;
};

/* Answer q into *out. Statuses: MECH_OK; MECH_EINVAL param NULL (q or out
 * NULL), "crossing_angle" (not in [0, pi]), "final_state" (more than
 * MECH_COLLISION_MAX_FINAL, or NULL masses with n_final > 0), "sqrt_s" (a
 * moving target with beam_from_sqrt_s: it is solved for a target at rest);
 * MECH_EDOMAIN param "beam/particle", "target/particle" or "final_state"
 * (a mass < 0 or not finite; with beam_from_sqrt_s, "target/particle" for a
 * massless target, which cannot be at rest) or "sqrt_s" (not finite, or
 * below m1 + m2: the two at rest already carry more energy); MECH_ENUMERIC
 * "the result is not finite for this input (overflow or a singularity)"
 * when a number of the answer overflows. The motions are taken as
 * mech_kin_motion_* built them (not re-checked). out is written only in
 * part on an error. err may be NULL. */
enum mech_status mech_collision_answer(const struct mech_collision_request *q,
                                       struct mech_collision_answer *out, struct mech_error *err);

#endif
