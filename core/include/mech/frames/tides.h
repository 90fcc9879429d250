/* mech/frames/tides.h — tidal acceleration of one body at a point of the Earth, exact
 * and to first order in r/d, and the equilibrium tide (notes §1.4 "The Tides").
 *
 * Geometry. The body (gravitational parameter GM) is at distance d from the
 * Earth's centre along the unit vector e; the point is at radius r and angle
 * theta from e, r_vec = r (cos theta e + sin theta p), p the unit vector
 * perpendicular to e in the plane of e and the point. The tidal acceleration
 * is the body's pull at the point minus its pull at the centre (the Earth
 * falls freely with the latter, notes §1.4):
 *   a = GM [ (d e - r_vec) / |d e - r_vec|³ - e / d² ].
 * Exact, without cancellation. With u = r/d, c = cos theta, s = sin theta,
 * |d e - r_vec|² = d² (1 + q), q = u (u - 2c), and
 *   E = (1 + q)^(-3/2) - 1 = expm1(-3/2 log1p(q)),
 *   a = GM/d² [ E e - u (1 + E) r_hat ].
 * Subtracting the two pulls directly loses log10(d/r) digits (10 at
 * u = 1e-10). Writing R = E + 3/2 q (O(q²); a binomial series for |q| < 1/4,
 * the direct sum otherwise) gives E - 3uc = R - 3/2 u² exactly, so the
 * departure from first order is computed directly too:
 *   radial (along r_hat, up):            first u (3c² - 1),  rest c (R - 3/2 u²) - u E
 *   tangential (along theta_hat, away
 *   from the sub-body point):            first -3 u s c,     rest -s (R - 3/2 u²)
 *   along e (towards the body):          first 2 u c,        rest (R - 3/2 u²) - u c E
 *   along p:                             first -u s,         rest -u s E
 * all times GM/d²; exact = first + rest. (When |q| >= 1/2, i.e. r/d > ~0.2,
 * where first order no longer dominates, the exact components are computed
 * directly as GM/d² [P (d - r c)/d - 1, -u s P], P = (1+q)^(-3/2), with
 * 1 + q = ((d - r)/d)² + 4u sin²(theta/2), exact even for a point almost
 * touching the body, and the rest is exact - first.) The first-order column is the
 * notes' GM r/d³ [2 cos phi e_x - sin phi e_y] (their x points away from the
 * Moon and phi is measured from it: the same vector)
 * and in (radial, tangential) form GM r/d³ (3cos² theta - 1, -3/2 sin 2theta):
 * the gradient of the quadrupole potential GM r² (3 cos² theta - 1)/(2 d³).
 * Each component is right to a few ulp of its first-order size (plus the
 * inherent ill-conditioning near its own zeros, e.g. 3c² = 1 for the radial one).
 *
 * Equilibrium tide (notes §1.4, after Taylor, Classical Mechanics §9.4): the
 * ocean surface is an equipotential of Earth gravity plus the tidal
 * potential; to first order its height above the undisturbed sphere is
 *   h(theta) = GM r⁴ (3 cos² theta - 1) / (2 GM_E d³)     (g = GM_E / r²),
 * so high water (theta = 0, 180 deg) minus low water (theta = 90 deg) is the
 * notes' range  g dh = 3 GM r² / (2 d³):  0.54 m for the Moon, 0.25 m for the Sun.
 *
 * Pure functions, no allocation, thread-safe. Units SI, angles in degrees.
 */
#ifndef MECH_TIDES_H
#define MECH_TIDES_H

#include "mech/base/constants.h"
#include "mech/base/status.h"

/* The Moon's and the Sun's GM, the Moon's mass and distance, the AU and the
 * Earth's mass are in mech/base/constants.h. */

/* Tidal acceleration components (m/s^2), see the table above. */
struct mech_tide_components {
    double radial, tangential, along, perpendicular;
};

struct mech_tide_acceleration {
    double u;     /* r / d */
    double pull;  /* GM / d²: the body's pull at the centre, m/s^2 */
    double scale; /* GM r / d³: the first-order tidal scale, m/s^2 */
    struct mech_tide_components exact;
    struct mech_tide_components first_order;
    struct mech_tide_components difference; /* exact - first_order, computed directly */
    double magnitude;                       /* |exact| */
    double magnitude_first_order;           /* |first_order| = scale sqrt(1 + 3 cos² theta) */
    double relative_difference;             /* |difference| / |first_order| (~ u) */
};

/* Tidal acceleration of a body with gravitational parameter `gm` (m^3/s^2,
 * > 0) at distance `distance` (m) from the centre, at a point at radius
 * `radius` (m, > 0, < distance) and angle `theta_deg` (degrees, [0, 180]) from
 * the body's direction. Statuses: MECH_OK; MECH_EINVAL (NULL out; params
 * "gm", "distance", "radius", "angle_deg" for non-finite or out-of-range
 * values); MECH_EDOMAIN (param "distance": distance <= radius; the body must lie
 * outside the sphere through the point);
 * MECH_ENUMERIC (overflow, only for a point almost touching the body). */
enum mech_status mech_tide_acceleration(double gm, double distance, double radius, double theta_deg,
                                        struct mech_tide_acceleration *out, struct mech_error *err);

/* Equilibrium tide of one body, first order in r/d (see above). */
struct mech_tide_height {
    double height; /* h(theta) above the undisturbed sphere, m */
    double range;  /* h(0) - h(90 deg) = 3 GM r⁴ / (2 GM_E d³), m */
    double high;   /* h(0) = range * 2/3 */
    double low;    /* h(90 deg) = -range / 3 */
};

/* Equilibrium tide of a body `gm` at `distance` on an Earth of gravitational
 * parameter `gm_earth` and radius `radius`, at angle `theta_deg`.
 * Statuses: MECH_OK; MECH_EINVAL (NULL out; params "gm", "gm_earth",
 * "distance", "radius", "angle_deg"); MECH_EDOMAIN ("distance" <= radius). */
enum mech_status mech_tide_height(double gm, double gm_earth, double distance, double radius,
                                  double theta_deg, struct mech_tide_height *out,
                                  struct mech_error *err);

#endif
