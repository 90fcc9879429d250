/* mech/relativity/decay_estimate.h — the notes' estimate of a decay product's largest
 * energy beside the exact endpoint (notes §3.16 "Neutron Decay").
 *
 * For n → p e ν̄ the notes let the neutrino carry nothing, so the electron
 * recoils against the proton alone, and treat the proton non-relativistically:
 *   sqrt(m_e² + p²) = Δm − p²/(2 m_p),  Δm = m_n − m_p;
 * squaring, p² (1 + Δm/m_p) − p⁴/(4 m_p²) = Δm² − m_e². They drop the p⁴ term
 * (the "intermediate" estimate, p² = (Δm² − m_e²)/(1 + Δm/m_p)) and then the
 * Δm/m_p ≪ 1 correction, ending with p ≈ sqrt(Δm² − m_e²) = sqrt(1.29² −
 * 0.51²) ≈ 1.18 MeV and E_e ≈ Δm: the electron takes all the energy available,
 * T ≈ Q, the recoil none. For daughter i of any decay the same reasoning holds
 * with the others as one recoiling body of mass S_i = Σ_{j≠i} m_j (M − S_i =
 * Q + m_i plays Δm); it is good when S_i ≫ Q.
 *
 * In closed form, with T = Q (M − m_i + S_i)/(2M) the exact endpoint
 * (mech_kin_endpoint):
 *   estimate − exact:       T: Q (Q + 2 m_i)/(2M) (the recoil's kinetic energy);
 *                           p²: (Q − T)(Q + T + 2 m_i);
 *   intermediate:           p² = Q (Q + 2 m_i) S_i/M (1 + Δm/m_p = m_n/m_p),
 *                           exact p² = that × (1 + x), x = Q (Q + 2 m_i)/(4 M S_i)
 *                           (the dropped p⁴/(4 S²) term).
 * Every difference is formed from these products, never by subtracting the
 * two rounded endpoints. Pure; thread-safe; no allocation.
 */
#ifndef MECH_DECAY_ESTIMATE_H
#define MECH_DECAY_ESTIMATE_H

#include <stddef.h>

#include "mech/base/status.h"

struct mech_decay_estimate {
    double recoil_mass;            /* S_i, the other daughters as one body */
    /* the notes' final estimate: E ≈ M − S_i, T ≈ Q, p ≈ sqrt(Q (Q + 2 m_i)) */
    double energy, kinetic, momentum;
    double kinetic_minus_exact;    /* ≥ 0 */
    double momentum_minus_exact;   /* ≥ 0 */
    /* the notes' intermediate step (recoil non-relativistic, p⁴ term dropped) */
    double mid_momentum, mid_kinetic;
    double mid_kinetic_minus_exact;  /* ≤ 0 */
    double mid_momentum_minus_exact; /* ≤ 0 */
};

/* The notes' estimates for daughter i of an n-body decay (n ≥ 2) of a parent
 * of mass M > 0 into masses m[0..n−1] ≥ 0 (one energy unit, c = 1). Needs
 * S_i > 0 (a recoil with mass). Statuses: MECH_OK; MECH_EINVAL param
 * "daughters" (NULL, n < 2, i ≥ n, a negative or non-finite mass);
 * MECH_EDOMAIN param "parent/particle" (M ≤ 0), "daughters" (M below the
 * sum of the masses, or the others all massless: no recoiling body);
 * MECH_ENUMERIC if a result is not finite. */
enum mech_status mech_decay_endpoint_estimate(double parent, const double *m, size_t n, size_t i,
                                              struct mech_decay_estimate *out,
                                              struct mech_error *err);

#endif
