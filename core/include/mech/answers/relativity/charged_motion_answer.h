/* mech/answers/relativity/charged_motion_answer.h — one POST /v1/relativity/charge-in-fields
 * answer: what a course asks of a charge in uniform static E and B (and a
 * constant force), from the exact motion of mech/relativity/charged_motion.h: the kind
 * of field, its invariants, the frame where E and B are parallel or one
 * vanishes (the E x B drift frame), the helix there (radius, pitch, periods)
 * or the hyperbolic motion's acceleration, and the state at given lab times
 * and proper times.
 *
 * Units: SI. Thread-safety: reentrant, no globals; the states go to the
 * caller's buffers.
 */
#ifndef MECH_CHARGED_MOTION_ANSWER_H
#define MECH_CHARGED_MOTION_ANSWER_H

#include <stddef.h>

#include "mech/relativity/charged_motion.h"
#include "mech/base/status.h"
#include "mech/base/vec.h"

#define MECH_CHARGED_MAX_TIMES 1000

struct mech_charged_question {
    double mass;                  /* kg, finite, > 0 */
    double charge;                /* C, finite (0: only the force acts) */
    struct mech_vec3 E, B;        /* V/m, T, uniform and static, finite */
    struct mech_vec3 force;       /* N: a constant extra force (an electric field F/q) */
    struct mech_vec3 position;    /* m at t = 0 */
    struct mech_vec3 proper_velocity; /* u = gamma v, m/s at t = 0 */
    const double *t;              /* lab times (s, >= 0, finite), n_t <= MECH_CHARGED_MAX_TIMES */
    size_t n_t;
    const double *tau;            /* proper times (s, >= 0, finite), n_tau <= the same */
    size_t n_tau;
};

struct mech_charged_answer {
    struct mech_charged_motion motion; /* kind, the frame S', the state there */
    double e2_minus_c2b2;         /* E_eff^2 - c^2 B^2 (V^2/m^2; E_eff = E + F/q), or, with
                                     q = 0, (m/q)-free: eps^2 - c^2 Omega^2 in (m/s^2)^2 */
    double e_dot_b;               /* E_eff . B (V T/m), or eps.Omega with q = 0 */
    /* S': moves with frame_velocity (m/s) in the lab */
    struct mech_vec3 frame_velocity;
    double frame_beta, frame_gamma;
    int has_frame_fields;         /* q != 0: the fields in S' below */
    struct mech_vec3 frame_E, frame_B; /* V/m (the effective E), T */
    const char *vanishes;         /* in S': "E", "B", "both" or "neither" (static) */
    /* the helix in S' (omega' != 0) */
    int has_helix;
    double omega_proper;          /* omega' = q B'/m, rad per second of proper time (signed
                                     along n) */
    double radius;                /* |u_perp'| / |omega'|, m (S') */
    double proper_period;         /* 2 pi / |omega'|, s of proper time */
    int has_pitch;                /* E' = 0: a helix of constant pitch */
    double period;                /* 2 pi gamma' / |omega'|, s of S' time (E' = 0) */
    double pitch;                 /* 2 pi u_n' / |omega'|, m along n per turn (E' = 0) */
    double speed_along;           /* u_n'/gamma', m/s along n in S' (E' = 0) */
    /* hyperbolic motion in S' (E' != 0) */
    int has_hyperbolic;
    double accel_proper;          /* a' = |q E'_eff|/m, m/s^2: rapidity along n grows as
                                     a' tau / c from the start */
};

/* Answer q into a; states_t[n_t] and states_tau[n_tau] (caller-owned, may be
 * NULL when the count is 0) get the states at the lab and proper times.
 * Statuses: MECH_OK; MECH_EINVAL (NULL, a non-finite input, too many times:
 * param "mass", "E", "B", "force", "position", "proper_velocity", "times",
 * "proper_times"); MECH_EDOMAIN (mass <= 0: "mass"; a time < 0: "times/i",
 * "proper_times/i"; null fields E perpendicular to B with |E| = c|B|:
 * "E"); MECH_ENUMERIC (a state overflows: "times/i", "proper_times/i"). */
enum mech_status mech_charged_answer(const struct mech_charged_question *q,
                                     struct mech_charged_answer *a,
                                     struct mech_charged_motion_state *states_t,
                                     struct mech_charged_motion_state *states_tau,
                                     struct mech_error *err);

#endif
