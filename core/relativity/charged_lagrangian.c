/* charged_lagrangian.c — L, P and H of a charged particle (see
 * mech/relativity/charged_lagrangian.h). */
#include "mech/relativity/charged_lagrangian.h"

#include <math.h>

static int finite3(struct mech_vec3 v)
{
    return isfinite(v.x) && isfinite(v.y) && isfinite(v.z);
}

void mech_charged_uniform_potentials(struct mech_vec3 e, struct mech_vec3 bfield,
                                     struct mech_vec3 r, double *phi, struct mech_vec3 *a)
{
    *phi = -mech_vec3_dot(e, r);
    *a = mech_vec3_scale(mech_vec3_cross(bfield, r), 0.5);
}

enum mech_status mech_charged_state_compute(double m, double q, const struct mech_boost *b,
                                            double phi, struct mech_vec3 a,
                                            struct mech_charged_state *out,
                                            struct mech_error *err)
{
    if (!isfinite(m) || !(m > 0))
        return mech_error_set(err, MECH_EDOMAIN, "mass", "a mass is a finite number > 0 kg");
    if (!isfinite(q)) return mech_error_set(err, MECH_EINVAL, "charge", "must be finite");
    if (!isfinite(phi)) return mech_error_set(err, MECH_EINVAL, "scalar_potential", "must be finite");
    if (!finite3(a)) return mech_error_set(err, MECH_EINVAL, "vector_potential", "must be finite");
    const double c = MECH_C, g = b->gamma, gm1 = b->gamma_minus_one;
    const double mc2 = m * c * c;
    const struct mech_vec3 v = mech_vec3_scale(b->beta_vec, c);
    const double qav = q * mech_vec3_dot(a, v), qphi = q * phi;
    struct mech_charged_state o;
    o.energy = g * mc2;
    o.potential_energy = qphi;
    /* −mc²/γ + mc² = mc²(γ − 1)/γ */
    o.lagrangian_plus_rest = mc2 * (gm1 / g) + qav - qphi;
    o.lagrangian = -mc2 / g + qav - qphi;
    o.lagrangian_newtonian_plus_rest = 0.5 * m * mech_vec3_dot(v, v) + qav - qphi;
    o.kinetic_momentum = mech_vec3_scale(v, g * m);
    o.canonical_momentum = mech_vec3_add(o.kinetic_momentum, mech_vec3_scale(a, q));
    o.hamiltonian_minus_rest = mc2 * gm1 + qphi;
    o.hamiltonian = o.energy + qphi;
    /* H from P: |P − qA| c = γ m v c, recomputed from P as given. */
    const struct mech_vec3 pk = mech_vec3_sub(o.canonical_momentum, mech_vec3_scale(a, q));
    o.hamiltonian_from_momentum = hypot(mc2, mech_vec3_norm(pk) * c) + qphi;
    o.legendre_residual = (mech_vec3_dot(o.canonical_momentum, v) - o.lagrangian) - o.hamiltonian;
    if (!isfinite(o.hamiltonian) || !isfinite(o.lagrangian) || !finite3(o.canonical_momentum) ||
        !isfinite(o.legendre_residual) || !isfinite(o.hamiltonian_from_momentum))
        return mech_error_set(err, MECH_ENUMERIC, NULL, "a result overflows the double range");
    *out = o;
    return MECH_OK;
}
