/* rotating_hamiltonian.c — L, p, H in a rotating frame and the inertial
 * energy (see mech/hamiltonian/rotating_hamiltonian.h). */
#include "mech/hamiltonian/rotating_hamiltonian.h"

#include <math.h>

static int finite3(struct mech_vec3 v)
{
    return isfinite(v.x) && isfinite(v.y) && isfinite(v.z);
}

enum mech_status mech_rotating_hamiltonian_compute(double m, struct mech_vec3 omega,
                                                   struct mech_vec3 r, struct mech_vec3 v,
                                                   double potential,
                                                   struct mech_rotating_hamiltonian *out,
                                                   struct mech_error *err)
{
    if (!isfinite(m) || !(m > 0))
        return mech_error_set(err, MECH_EDOMAIN, "mass", "a mass is a finite number > 0 kg");
    if (!finite3(omega)) return mech_error_set(err, MECH_EINVAL, "omega", "must be finite");
    if (!finite3(r)) return mech_error_set(err, MECH_EINVAL, "position", "must be finite");
    if (!finite3(v)) return mech_error_set(err, MECH_EINVAL, "velocity", "must be finite");
    if (!isfinite(potential))
        return mech_error_set(err, MECH_EINVAL, "potential_energy", "must be finite");
    struct mech_rotating_hamiltonian o;
    const struct mech_vec3 wr = mech_vec3_cross(omega, r);
    o.inertial_velocity = mech_vec3_add(v, wr);
    o.canonical_momentum = mech_vec3_scale(o.inertial_velocity, m);
    o.angular_momentum = mech_vec3_cross(r, o.canonical_momentum);
    const double u2 = mech_vec3_dot(o.inertial_velocity, o.inertial_velocity);
    o.inertial_energy = 0.5 * m * u2 + potential;
    o.lagrangian = 0.5 * m * u2 - potential;
    o.centrifugal_potential = -0.5 * m * mech_vec3_dot(wr, wr);
    o.hamiltonian = 0.5 * m * mech_vec3_dot(v, v) + o.centrifugal_potential + potential;
    o.omega_dot_l = mech_vec3_dot(omega, o.angular_momentum);
    const struct mech_vec3 p = o.canonical_momentum;
    o.hamiltonian_from_momentum = mech_vec3_dot(p, p) / (2 * m) - o.omega_dot_l + potential;
    if (!isfinite(o.hamiltonian) || !isfinite(o.inertial_energy) ||
        !isfinite(o.hamiltonian_from_momentum) || !finite3(o.angular_momentum))
        return mech_error_set(err, MECH_ENUMERIC, NULL, "a result overflows the double range");
    *out = o;
    return MECH_OK;
}
