/* mech/hamiltonian/circular_orbit.h — the circular orbits of a given angular momentum in a
 * central potential V(r) = Σ k_i r^{n_i} (k ln r for n = 0), the potentials
 * the small-oscillation analysis and Hamilton's flow take (notes ch. 5,
 * "Motion in a Central Potential"; Kepler: n = −1, k = −GMm).
 *
 * A circular orbit of angular momentum L sits where the effective potential
 * V_eff = L²/(2 m r²) + V(r) is stationary: m r³ V'(r) = L². With x = ln r
 * that is an exponential sum Σ c_i e^{(n_i + 2) x} = L²/m, c_i = k_i n_i (k_i
 * for n = 0); terms with equal exponents are merged, and n = −2 terms join
 * the constant. Two exponentials (one power law, or one power law beside an
 * n = −2 term) are solved in closed form, x = ln(−c2/c1)/(a1 − a2); more are
 * bracketed on a fixed grid of 4096 points over the interval outside which
 * one term outweighs all others (so no root lies there), then bisected to
 * round-off. A root where two circular orbits merge (a tangency, e.g. an
 * innermost stable orbit hit exactly) can be missed: its neighbours on either
 * side have no sign change. Each radius then goes through
 * mech_orbit_oscillation for the energy, the frequencies and the stability.
 *
 * Units: SI (kg, m, s, J) or any consistent set. Pure, thread-safe, no
 * allocation.
 */
#ifndef MECH_CIRCULAR_ORBIT_H
#define MECH_CIRCULAR_ORBIT_H

#include <stddef.h>

#include "mech/hamiltonian/small_oscillations.h"
#include "mech/base/status.h"

/* At most one root per sign change of the merged coefficients (Descartes'
 * rule for exponential sums): 16 terms and the constant give at most 16. */
#define MECH_CIRCULAR_ORBIT_MAX 17

struct mech_circular_orbits {
    size_t count;                                       /* 0 … MECH_CIRCULAR_ORBIT_MAX */
    double radius[MECH_CIRCULAR_ORBIT_MAX];             /* ascending, m */
    double residual[MECH_CIRCULAR_ORBIT_MAX];           /* m r³ V'(r)/L² − 1 at the radius */
    struct mech_orbit_oscillation orbit[MECH_CIRCULAR_ORBIT_MAX]; /* at each radius */
    size_t out_of_range;  /* roots whose radius is not a finite double > 0 (left out) */
    int closed_form;      /* 1: solved in closed form (two exponentials) */
};

/* The circular orbits of angular momentum L (kg m²/s, finite, > 0) of a
 * particle of mass m (kg, finite, > 0) in V = Σ terms[0..n−1] (1 ≤ n ≤ 16).
 * count = 0 is a valid answer (no circular orbit has this L: the force is
 * nowhere attractive enough, or V' ≤ 0 everywhere). Returns MECH_OK;
 * MECH_EINVAL with param "terms" (NULL, n = 0 or n > 16), "terms/<i>/k" or
 * "terms/<i>/n" (not finite), "mass" or "angular_momentum" (not finite and
 * > 0); MECH_ENUMERIC when a result at a found radius is not finite. */
enum mech_status mech_circular_orbits_for_l(const struct mech_potential_term *terms, size_t n,
                                            double mass, double angular_momentum,
                                            struct mech_circular_orbits *out,
                                            struct mech_error *err);

#endif
