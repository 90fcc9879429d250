/* mech/frames/effective_force.h — the effective force in an accelerating, rotating
 * frame, term by term (notes §1.2, "Calculating the Effective Force (a more
 * general derivation)").
 *
 * Derivation (the notes' PDF text lost its minus signs; rebuilt here). Write
 * the inertial position as x_I = X + x_j u_j, X the frame's origin, u_j its
 * unit vectors, x_j the coordinates in the frame. With du_j/dt = w x u_j and
 * d²u_j/dt² = (dw/dt) x u_j + w x (w x u_j), differentiating twice gives
 *   a_I = A + a_A + 2 w x v_A + (dw/dt) x x_A + w x (w x x_A),
 * A = d²X/dt², and m a_I = F (Newton in the inertial frame), so
 *   m a_A = F - m A - 2 m w x v_A - m (dw/dt) x x_A - m w x (w x x_A)
 *         = F + F_translational + F_Coriolis + F_Euler + F_centrifugal.
 * Every vector here is written in the frame's axes: w, dw/dt (the same seen
 * from either frame, since their derivatives of a vector differ by w x . and
 * w x w = 0), A (the origin's acceleration, components on the frame axes),
 * r = x_A and v = v_A (position and velocity measured in the frame) and the
 * real force F (components on the frame axes).
 * Checks: a particle at rest in the inertial frame at radius r on a table
 * turning at w is seen circling: F_eff = m w² r (Coriolis -2 m w² r plus
 * centrifugal + m w² r) points inward (notes §1.1, second puck experiment).
 *
 * Pure function, no allocation, thread-safe. Units SI.
 */
#ifndef MECH_EFFECTIVE_FORCE_H
#define MECH_EFFECTIVE_FORCE_H

#include "mech/base/status.h"
#include "mech/base/vec.h"

/* How a frame moves relative to an inertial one, all in the frame's axes. */
struct mech_frame_motion {
    struct mech_vec3 omega;        /* angular velocity of the axes, rad/s */
    struct mech_vec3 omega_dot;    /* its time derivative, rad/s^2 */
    struct mech_vec3 acceleration; /* acceleration of the origin, m/s^2 */
};

/* The terms of m a_A = F + sum of fictitious forces (newtons, frame axes). */
struct mech_effective_force {
    struct mech_vec3 translational; /* -m A */
    struct mech_vec3 euler;         /* -m (dw/dt) x r */
    struct mech_vec3 coriolis;      /* -2 m w x v */
    struct mech_vec3 centrifugal;   /* -m w x (w x r) = m (w² r - (w.r) w), away from the axis */
    struct mech_vec3 fictitious;    /* sum of the four */
    struct mech_vec3 effective;     /* F + fictitious: the force seen in the frame */
    struct mech_vec3 acceleration;  /* effective / m: acceleration seen in the frame, m/s^2 */
    struct mech_vec3 inertial_acceleration; /* F / m, the inertial acceleration (frame axes) */
};

/* Effective force on a particle of mass `mass` (kg, finite, > 0) at
 * `position` r (m) moving with `velocity` v (m/s), both measured in the frame,
 * under the real force `force` (N), in a frame moving as `frame` says.
 * Each sum is accumulated with compensated (Neumaier) summation, so the total
 * is right to about one rounding even when terms cancel.
 * Statuses: MECH_OK; MECH_EINVAL (NULL frame/out; a non-finite input, param
 * "frame/omega", "frame/omega_dot", "frame/acceleration", "particle/position",
 * "particle/velocity", "force"); MECH_EDOMAIN (param "particle/mass": mass <= 0);
 * MECH_ENUMERIC (a term overflowed). */
enum mech_status mech_effective_force(const struct mech_frame_motion *frame, double mass,
                                      struct mech_vec3 position, struct mech_vec3 velocity,
                                      struct mech_vec3 force, struct mech_effective_force *out,
                                      struct mech_error *err);

#endif
