/* mech/relativity/michelson_morley.h — the Michelson–Morley experiment analysed as the
 * notes do (§3.2, §3.4): with an ether at rest in one frame and the
 * apparatus moving through it at βc, the round trips along two arms of
 * length L take t∥ = 2γ²L/c and t⊥ = 2γL/c; their difference is
 * Δt = 2γ(γ − 1)L/c, a path difference d = cΔt = 2γ(γ − 1)L, which the notes
 * approximate as β²L (110 nm for L = 11 m, β = 1e-4); rotating the apparatus
 * by 90° swaps the arms and shifts the pattern by 2d/λ fringes. With the
 * Lorentz (FitzGerald) contraction L∥ = L/γ, t∥ = 2γL/c = t⊥: no shift.
 *
 * Precision: γ − 1 from mech/relativity/boost.h (no cancellation at β = 1e-4 or 1e-8).
 * Units: SI. Pure; thread-safe; no allocation.
 */
#ifndef MECH_MICHELSON_MORLEY_H
#define MECH_MICHELSON_MORLEY_H

#include "mech/base/constants.h"
#include "mech/relativity/boost.h"
#include "mech/base/status.h"

#define MECH_MM_C MECH_C /* the speed of light of mech/base/constants.h, under the name api/ uses */

struct mech_michelson_morley {
    double time_parallel;        /* 2γ²L/c, s (ether) */
    double time_perpendicular;   /* 2γL/c, s (ether) */
    double time_difference;      /* 2γ(γ − 1)L/c, s */
    double path_difference;      /* 2γ(γ − 1)L, m */
    double path_difference_approx; /* the notes' β²L, m */
    double approx_rel_error;     /* (β²L − d)/d = −(γ − 1)(2γ² + 2γ + 1)/(2γ³), → −5β²/4 */
    double fringe_shift;         /* 2d/λ on a 90° rotation (0 when no wavelength) */
    double time_parallel_contracted; /* 2γL/c with L∥ = L/γ: equal to time_perpendicular */
};

/* For an arm length L > 0 (m), the speed through the ether b (|β| < 1) and a
 * wavelength λ > 0 (m; 0: no fringe count). Statuses: MECH_OK; MECH_EDOMAIN
 * param "arm_length" or "wavelength". out written only on success. */
enum mech_status mech_michelson_morley_compute(double arm_length, const struct mech_boost *b,
                                               double wavelength,
                                               struct mech_michelson_morley *out,
                                               struct mech_error *err);

#endif
