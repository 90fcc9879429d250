/* mech/continuum/torsion.h — torsional waves in a uniform rod (the continuum chapter's
 * third kind of rod wave beside the axial and bending ones, mech/
 * continuum_waves.h).
 *
 * Saint-Venant torsion: the twist angle θ(s, t) obeys ρ J θ_tt = G K θ_ss,
 * J = ∫ r² dA the polar moment of the section (its rotational inertia per
 * length over ρ) and K the torsion constant (torque per twist rate over G).
 * The wave speed is c = sqrt(G K/(ρ J)): sqrt(G/ρ) for a circle or a circular
 * tube (K = J), slower for any other section (its warping lowers K). The end
 * conditions are those of axial waves: a clamped end holds θ = 0, a free end
 * carries no torque (θ_s = 0), so the modes are k_n L = nπ or (n − ½)π
 * (mech_rod_axial_mode).
 * Rectangle b × h (b ≥ h), Timoshenko & Goodier §109:
 *   K = (b h³/3) [1 − (192/π⁵)(h/b) Σ_{n odd} tanh(nπ b/(2h))/n⁵],
 * summed as (31/32) ζ(5) − Σ (1 − tanh)/n⁵ with 1 − tanh x = 2/(e^{2x} + 1),
 * which converges geometrically (ratio ≤ e^{−π}); J = b h (b² + h²)/12.
 * Units: SI (Pa, kg/m³, m², m⁴, m/s). Pure; thread-safe; no allocation.
 */
#ifndef MECH_TORSION_H
#define MECH_TORSION_H

#include "mech/base/status.h"

/* Polar moment J and torsion constant K (both m⁴) of a b × h rectangle
 * (b, h > 0, finite, in either order). Statuses: MECH_OK; MECH_EDOMAIN param
 * "width" or "height" (≤ 0 or not finite); MECH_ENUMERIC if J or K
 * over/underflows to a non-finite or zero value. */
enum mech_status mech_torsion_rectangle(double width, double height, double *polar_moment,
                                        double *torsion_constant, struct mech_error *err);

/* Shear modulus from Young's modulus E > 0 and Poisson's ratio ν ∈ (−1, ½]
 * of an isotropic solid: G = E/(2(1 + ν)). Statuses: MECH_OK; MECH_EDOMAIN
 * param "poisson_ratio" (outside (−1, 0.5]) or "youngs_modulus" (≤ 0). */
enum mech_status mech_shear_modulus(double youngs_modulus, double poisson_ratio, double *g,
                                    struct mech_error *err);

/* Torsional wave speed c = sqrt(G/ρ) sqrt(K/J) (m/s) for G, ρ, K, J > 0 and
 * finite, K ≤ J (a section twists no stiffer than its polar moment: equality
 * for a circle or tube). Computed as products of square roots, so the
 * quotients never overflow. Statuses: MECH_OK; MECH_EDOMAIN param
 * "shear_modulus", "density", "section/torsion_constant" or
 * "section/polar_moment" (≤ 0 or not finite; K > J is refused at
 * "section/torsion_constant"). */
enum mech_status mech_torsional_wave_speed(double shear_modulus, double density,
                                           double torsion_constant, double polar_moment,
                                           double *c, struct mech_error *err);

#endif
