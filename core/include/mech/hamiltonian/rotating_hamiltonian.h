/* mech/hamiltonian/rotating_hamiltonian.h — a particle's Lagrangian and Hamiltonian in a
 * frame rotating with constant angular velocity ω (notes ch. 1 homework:
 * "calculate the Hamiltonian in the rotating frame and see if it is the
 * total energy"; Landau & Lifshitz, Mechanics §39):
 *   L_rot = ½ m |v + ω × r|² − V          (v, r measured in the rotating frame)
 *   p     = ∂L/∂v = m (v + ω × r)          (the canonical momentum is the
 *                                           inertial momentum)
 *   H_rot = p·v − L = p²/2m − ω·(r × p) + V = ½ m v² − ½ m |ω × r|² + V
 *   E     = ½ m |v + ω × r|² + V = H_rot + ω·L,  L = r × p,
 * so H_rot is conserved but is not the inertial energy unless ω·L = 0.
 * Units: SI. Pure functions; thread-safe; cannot fail on finite input.
 */
#ifndef MECH_ROTATING_HAMILTONIAN_H
#define MECH_ROTATING_HAMILTONIAN_H

#include "mech/base/status.h"
#include "mech/base/vec.h"

struct mech_rotating_hamiltonian {
    struct mech_vec3 inertial_velocity;  /* v + ω × r, m/s */
    struct mech_vec3 canonical_momentum; /* m (v + ω × r), kg m/s */
    struct mech_vec3 angular_momentum;   /* r × p, kg m²/s */
    double lagrangian;                   /* L_rot, J */
    double hamiltonian;                  /* H_rot = ½ m v² − ½ m |ω × r|² + V, J */
    double hamiltonian_from_momentum;    /* p²/2m − ω·(r × p) + V: the same H, a check */
    double inertial_energy;              /* E = ½ m |v + ω × r|² + V, J */
    double omega_dot_l;                  /* ω·L = E − H_rot, J */
    double centrifugal_potential;        /* −½ m |ω × r|², J */
};

/* Statuses: MECH_OK; MECH_EDOMAIN param "mass" (m ≤ 0 or not finite);
 * MECH_EINVAL param "omega", "position", "velocity" or "potential_energy"
 * (non-finite). out written only on success. */
enum mech_status mech_rotating_hamiltonian_compute(double m, struct mech_vec3 omega,
                                                   struct mech_vec3 r, struct mech_vec3 v,
                                                   double potential,
                                                   struct mech_rotating_hamiltonian *out,
                                                   struct mech_error *err);

#endif
