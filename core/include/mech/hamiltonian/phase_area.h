/* mech/hamiltonian/phase_area.h — the phase-space area enclosed by an energy contour of
 * a one-dimensional system (notes "Phase Space and Liouville's Theorem"),
 * A(E) = ∮ p dq, with the period as its energy derivative T = dA/dE and the
 * action J = A/2π. Closed forms:
 *   oscillator H = p²/2m + m ω² q²/2:  A = 2π E/ω, T = 2π/ω;
 *   pendulum   H = p²/(2 m l²) + m g l (1 − cos θ), ω0 = sqrt(g/l),
 *     E = 2 m g l k² (θ_max = 2 asin k):
 *     libration (k < 1): A = 16 m l² ω0 [E(k) − (1 − k²) K(k)], T = 4 K(k)/ω0
 *                        (→ 2πE/ω0 for small k);
 *     rotation  (k > 1): A = ∫_{−π}^{π} p dθ = 8 m l² ω0 k E(1/k) (one branch),
 *                        T = 2 K(1/k)/(k ω0) (one full turn);
 *     separatrix (k = 1): A = 16 m l² ω0 (both branches), T infinite.
 * K, E: complete elliptic integrals of modulus k (GSL). For k² < 1/2,
 * E − (1 − k²)K is summed as (π/2) Σ_{n≥1} a_{n−1} k^{2n}/(2n), a_n =
 * ((2n)!/(4^n n!²))², which has no cancellation (the closed form loses
 * 1/k² digits: all of them at k = 1e-8).
 * Units: SI (kg, m, s, J, J s). Pure; thread-safe; no allocation.
 */
#ifndef MECH_PHASE_AREA_H
#define MECH_PHASE_AREA_H

#include "mech/base/status.h"

enum mech_phase_motion {
    MECH_PHASE_LIBRATION = 0,
    MECH_PHASE_ROTATION = 1,
    MECH_PHASE_SEPARATRIX = 2,
};

struct mech_phase_area {
    enum mech_phase_motion motion;
    double area;      /* A, J s */
    double period;    /* T = dA/dE, s (+inf on the separatrix) */
    double modulus;   /* k (pendulum; 0 for the oscillator) */
    double amplitude; /* q_max: m for the oscillator, θ_max rad for a libration; NaN for a
                         rotation */
};

/* Oscillator of mass m > 0, angular frequency omega > 0 at energy E ≥ 0.
 * Statuses: MECH_OK; MECH_EDOMAIN param "mass", "omega" or "energy". */
enum mech_status mech_phase_area_oscillator(double m, double omega, double energy,
                                            struct mech_phase_area *out, struct mech_error *err);

/* Pendulum of mass m > 0, length l > 0, gravity g > 0 at energy E ≥ 0 above
 * the bottom. Statuses: MECH_OK; MECH_EDOMAIN param "mass", "length", "g",
 * "energy"; MECH_ENUMERIC if GSL's elliptic integrals fail. */
enum mech_status mech_phase_area_pendulum(double m, double l, double g, double energy,
                                          struct mech_phase_area *out, struct mech_error *err);

#endif
