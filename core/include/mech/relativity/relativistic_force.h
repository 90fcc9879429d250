/* mech/relativity/relativistic_force.h — Newton's second law in special relativity
 * (notes §3 "The Force 4-Vector": F = dp/dt with p = γ m v, and the 4-force
 * K = dp^μ/dτ = γ (F·v/c, F)). Since dγ/dt = γ³ (v·a)/c²,
 *   F = γ m a⊥ + γ³ m a∥,
 * the parts of the acceleration across and along v, with the "transverse
 * mass" γ m and the "longitudinal mass" γ³ m; the power is F·v = γ³ m v·a =
 * d(γ m c²)/dt. The inverse: a∥ = F∥/(γ³ m), a⊥ = F⊥/(γ m).
 *
 * Units: SI (kg, m/s, m/s², N, W); the velocity as a struct mech_boost (its
 * γ comes from the form the caller gave, mech/relativity/boost.h).
 * Pure functions; thread-safe; no allocation.
 */
#ifndef MECH_RELATIVISTIC_FORCE_H
#define MECH_RELATIVISTIC_FORCE_H

#include "mech/base/constants.h"
#include "mech/relativity/boost.h"
#include "mech/base/status.h"
#include "mech/base/vec.h"

struct mech_rel_force {
    struct mech_vec3 force, force_parallel, force_perpendicular;              /* N */
    struct mech_vec3 acceleration, acceleration_parallel, acceleration_perpendicular; /* m/s² */
    double transverse_mass;   /* γ m, kg */
    double longitudinal_mass; /* γ³ m, kg */
    double power;             /* F·v, W */
    double four_force[4];     /* γ (F·v/c, F), N */
};

/* From the acceleration a (m/s²) of a particle of mass m > 0 (kg) moving with
 * velocity b (the boost's β n; at rest the split is along +x, with no
 * parallel part unless a has one). Statuses: MECH_OK; MECH_EDOMAIN param
 * "mass" (m ≤ 0 or not finite); MECH_EINVAL param "acceleration"
 * (non-finite); MECH_ENUMERIC when a result overflows. */
enum mech_status mech_rel_force_from_acceleration(double m, const struct mech_boost *b,
                                                  struct mech_vec3 a, struct mech_rel_force *out,
                                                  struct mech_error *err);

/* From the force F (N): the same members, with a = F∥/(γ³ m) + F⊥/(γ m).
 * Statuses as above with param "force". */
enum mech_status mech_rel_force_from_force(double m, const struct mech_boost *b,
                                           struct mech_vec3 f, struct mech_rel_force *out,
                                           struct mech_error *err);

#endif
