/* mech/gr/radial_infall.h — radial free fall from rest into a Schwarzschild
 * black hole (the notes' "The Singularity in Schwarzschild Coordinates";
 * Hartle §9.4 "Radial plunge orbits", Misner–Thorne–Wheeler §31.4): the
 * proper time from r0 to the horizon, to r = 0, and from the horizon to
 * r = 0, along the cycloid r = (r0/2)(1 + cos η), τ = sqrt(r0³/8)(η + sin η).
 *
 * Units: geometric, G = c = 1 with M = 1 (r in GM/c², τ in GM/c³).
 * The proper time to r = 0, (π/2) sqrt(r0³/2), equals the Newtonian free-fall
 * time from rest at r0: a second method the tests use. The coordinate time to
 * reach the horizon is infinite.
 * Pure functions; thread-safe; no allocation.
 */
#ifndef MECH_RADIAL_INFALL_H
#define MECH_RADIAL_INFALL_H

#include "mech/base/status.h"

struct mech_radial_infall {
    double to_horizon;               /* τ(r0 → 2M) */
    double to_singularity;           /* τ(r0 → 0) = π sqrt(r0³/8) */
    double horizon_to_singularity;   /* τ(2M → 0) = sqrt(r0³/8) · 2 (asin s − s sqrt(1 − s²)),
                                        s = sqrt(2/r0), by its series for s ≤ 1/2 (no
                                        cancellation): → (4/3) M as r0 → ∞, π M as r0 → 2M */
    int on_horizon;                  /* 1: r0 was the horizon (within 1e-12): the limit of a
                                        fall from just outside, τ(→ 2M) = 0, τ(→ 0) = π M */
};

/* Proper times of a radial fall from rest at r0 >= 2 (GM/c²; r0 ≤ 1e200, so r0^{3/2} stays
 * finite). A start on the horizon, r0 in [2 (1 - 1e-12), 2] (a radius given in metres,
 * 2GM/c² rounded, lands within that of 2), is answered as the limit r0 → 2 from
 * outside: on_horizon set, to_horizon 0, to_singularity = horizon_to_singularity = π.
 * Statuses: MECH_OK; MECH_EDOMAIN param "infall_from" (r0 below the horizon: no rest
 * there, or not finite). out written only on success. */
enum mech_status mech_radial_infall_from_rest(double r0, struct mech_radial_infall *out,
                                              struct mech_error *err);

#endif
