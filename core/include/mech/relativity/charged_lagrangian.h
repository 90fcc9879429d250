/* mech/relativity/charged_lagrangian.h — the relativistic Lagrangian and Hamiltonian of
 * a charged particle in given potentials (notes §3 "The Lagrangian and
 * Hamiltonian in Relativity": L = −mc²/γ − V, p = ∂L/∂v = γ m v, H = E + V;
 * with electromagnetic potentials, e.g. Jackson §12.1, Goldstein §7.9):
 *   L = −m c²/γ + q A·v − q φ,
 *   P = ∂L/∂v = γ m v + q A           (canonical momentum),
 *   H = P·v − L = sqrt(m²c⁴ + |P − qA|² c²) + q φ = γ m c² + q φ.
 * Uniform fields E, B at a position r are given potentials in the gauge
 * φ = −E·r, A = ½ B × r (then also the Lorentz force q(E + v × B)).
 *
 * Precision: L + mc² = mc²(γ − 1)/γ + qA·v − qφ and H − mc² = mc²(γ − 1) + qφ
 * are formed from γ − 1 (mech/relativity/boost.h), so a slow particle keeps its digits;
 * the notes' non-relativistic L ≈ −mc² + ½mv² + qA·v − qφ is given beside it.
 * Units: SI (kg, C, m/s, V, T m, J, kg m/s). Pure; thread-safe; no allocation.
 */
#ifndef MECH_CHARGED_LAGRANGIAN_H
#define MECH_CHARGED_LAGRANGIAN_H

#include "mech/base/constants.h"
#include "mech/relativity/boost.h"
#include "mech/base/status.h"
#include "mech/base/vec.h"

#define MECH_CHARGED_C MECH_C /* the speed of light of mech/base/constants.h, under the name api/ uses */

struct mech_charged_state {
    double lagrangian;                 /* L, J */
    double lagrangian_plus_rest;       /* L + mc², J (precise at low speed) */
    double lagrangian_newtonian_plus_rest; /* ½mv² + qA·v − qφ, the notes' non-relativistic
                                              L + mc² (an approximation) */
    struct mech_vec3 kinetic_momentum;   /* γ m v */
    struct mech_vec3 canonical_momentum; /* γ m v + q A */
    double hamiltonian;                /* H = γ m c² + q φ, J */
    double hamiltonian_minus_rest;     /* H − mc² = mc²(γ − 1) + qφ */
    double hamiltonian_from_momentum;  /* sqrt(m²c⁴ + |P − qA|²c²) + qφ: the same H from P, a
                                          check (equal to round-off) */
    double legendre_residual;          /* (P·v − L) − H, 0 to round-off: H is the Legendre
                                          transform of L */
    double energy;                     /* γ m c² */
    double potential_energy;           /* q φ */
};

/* For mass m > 0 (kg), charge q (C), velocity b (a boost: γ, β n precise),
 * scalar potential phi (V) and vector potential a (T m) at the particle.
 * Statuses: MECH_OK; MECH_EDOMAIN param "mass"; MECH_EINVAL param "charge",
 * "scalar_potential" or "vector_potential" (non-finite); MECH_ENUMERIC when a
 * result overflows. out written only on success. */
enum mech_status mech_charged_state_compute(double m, double q, const struct mech_boost *b,
                                            double phi, struct mech_vec3 a,
                                            struct mech_charged_state *out,
                                            struct mech_error *err);

/* Potentials of uniform fields E (V/m), B (T) at r (m) in the gauge
 * φ = −E·r, A = ½ B × r. Cannot fail. */
void mech_charged_uniform_potentials(struct mech_vec3 e, struct mech_vec3 bfield,
                                     struct mech_vec3 r, double *phi, struct mech_vec3 *a);

#endif
