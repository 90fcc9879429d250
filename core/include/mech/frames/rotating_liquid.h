/* mech/frames/rotating_liquid.h — the free surface of a liquid at rest in a frame
 * turning at w about a vertical axis (notes §1.5 homework 2: "a circular
 * container of water rotates ... what is the shape of the water?").
 *
 * In the rotating frame the liquid is in equilibrium under gravity -g z_hat
 * and the centrifugal force w² r r_hat (notes §1.2), whose potential per unit
 * mass is g z - w² r²/2. A free surface is an equipotential (the effective
 * gravity is normal to it), so
 *   z(r) = z0 + w² r² / (2 g),
 * a paraboloid of revolution with slope dz/dr = w² r / g and focal length
 * f = g / (2 w²) (r² = 4 f (z - z0): the liquid-mirror telescope).
 *
 * Fixing the volume (a cylinder of radius R filled to depth h0 at rest):
 *   covered bottom (w² R² <= 4 g h0):  z0 = h0 - w² R²/(4 g),
 *                                      rim z(R) = h0 + w² R²/(4 g)
 *   (the surface falls at the centre by as much as it rises at the rim);
 *   exposed bottom (w² R² > 4 g h0): dry for r < r0, z = w² (r² - r0²)/(2 g)
 *   beyond, with pi w²/(4 g) (R² - r0²)² = pi R² h0, i.e.
 *                                      R² - r0² = 2 R sqrt(g h0) / w,
 *                                      rim z(R) = R w sqrt(h0 / g).
 * A container of height H spills once the rim height reaches H: at
 *   w = sqrt(4 g (H - h0)) / R         if H <= 2 h0 (bottom still covered),
 *   w = H sqrt(g / h0) / R             otherwise.
 *
 * Pure functions, no allocation, thread-safe. Units SI.
 */
#ifndef MECH_ROTATING_LIQUID_H
#define MECH_ROTATING_LIQUID_H

#include "mech/base/status.h"

struct mech_rotating_liquid {
    double omega;            /* rad/s, >= 0 */
    double g;                /* m/s^2, > 0 */
    double radius;           /* container radius R, m, > 0 */
    double depth;            /* depth h0 at rest, m, > 0 */
    double container_height; /* H, m; 0: not given (no spill test), else >= depth */
};

struct mech_rotating_liquid_surface {
    double rise;          /* w² R² / (2 g): rim minus centre of the full paraboloid, m */
    double focal_length;  /* g / (2 w²), m; +inf at w = 0 */
    int bottom_exposed;   /* 1 if w² R² > 4 g h0 */
    double z_centre;      /* z0 (may be negative: the paraboloid's vertex below the bottom) */
    double centre_height; /* liquid depth on the axis: max(z0, 0), m */
    double rim_height;    /* liquid height at the wall, m */
    double dry_radius;    /* r0 (0 when the bottom is covered), m */
    double slope_rim;     /* dz/dr at the wall, w² R / g (tan of the surface's angle) */
    double omega_bottom;  /* w at which the bottom starts to show: 2 sqrt(g h0) / R */
    double omega_spill;   /* w at which a container of height H spills (0 if H not given) */
    int spills;           /* 1 if rim_height > H (H given) */
};

/* The surface for container `p`. Statuses: MECH_OK; MECH_EINVAL (NULL
 * pointers; params "omega" (< 0 or non-finite), "g", "radius", "depth" (<= 0
 * or non-finite), "container_height" (non-finite, or > 0 and < depth));
 * MECH_ENUMERIC (a non-finite result). */
enum mech_status mech_rotating_liquid_surface(const struct mech_rotating_liquid *p,
                                              struct mech_rotating_liquid_surface *out,
                                              struct mech_error *err);

/* Height of the surface above the bottom at radius r (m, 0 <= r <= R) for a
 * surface computed by mech_rotating_liquid_surface (0 on the dry disc).
 * Cannot fail; r outside [0, R] is clamped. */
double mech_rotating_liquid_height(const struct mech_rotating_liquid *p,
                                   const struct mech_rotating_liquid_surface *s, double r);

#endif
