/* mech/frames/earth.h — effective gravity on a rotating spherical Earth (notes §1.3,
 * "Motion Near the Earth") beside the WGS 84 normal gravity of the ellipsoid.
 *
 * Spherical model. A point at latitude L and height h above a sphere of
 * radius R is at r = R + h from the centre; gravitation there is g0 = GM/r²
 * towards the centre. The centrifugal acceleration -w x (w x r) has magnitude
 * W² r cos L and points away from the axis, i.e. along cos L up - sin L north
 * (local axes x east, y north, z up). So the effective g is
 *   g_eff = (0, -W² r cos L sin L, -(g0 - W² r cos² L))     (east, north, up)
 * with the radial (downward) component g0 - W² r cos² L (the notes'
 * g = g0 - W² r cos² L) and the horizontal one W² r cos L |sin L| towards the
 * equator. The plumb line hangs along g_eff: it deviates from the direction to
 * the centre by alpha with tan alpha = k sin L cos L / (1 - k cos² L),
 * k = W² r / g0. With t = tan L this is k t / (1 + t² - k), largest at
 * t = sqrt(1 - k), i.e. L* = atan(sqrt(1 - k)) (just below 45 deg), where
 * tan alpha* = k / (2 sqrt(1 - k)) (about k/2 = W² r / (2 g0) rad, 0.099 deg).
 *
 * Ellipsoid. WGS 84 normal gravity on the ellipsoid (Somigliana's closed
 * formula, NIMA TR8350.2, 3rd ed. 2000, eq. 4-1):
 *   gamma0 = gamma_e (1 + k_s sin² L) / sqrt(1 - e² sin² L)
 * and above it the free-air series to second order in h (TR8350.2 eq. 4-3):
 *   gamma = gamma0 [1 - 2/a (1 + f + m - 2 f sin² L) h + 3 h²/a²].
 * Here L is the geodetic latitude (the angle of the ellipsoid's normal).
 *
 * Pure functions, no allocation, thread-safe. Units SI; angles in degrees
 * where the name says _deg, otherwise radians.
 */
#ifndef MECH_EARTH_H
#define MECH_EARTH_H

#include "mech/base/constants.h"
#include "mech/base/status.h"

/* The Earth's constants (MECH_EARTH_GM, MECH_EARTH_RADIUS_MEAN,
 * MECH_EARTH_OMEGA, the WGS 84 ellipsoid MECH_WGS84_*) are in mech/base/constants.h. */

/* Lowest and highest heights the functions accept (m): the deepest ocean
 * trench to the Kármán line (the free-air series' next term is ~(h/a)^3). */
#define MECH_EARTH_HEIGHT_MIN (-12000.0)
#define MECH_EARTH_HEIGHT_MAX 100000.0

/* A spherical, rigidly rotating Earth. */
struct mech_earth_sphere {
    double gm;     /* m^3/s^2, > 0 */
    double radius; /* m, > 0 */
    double omega;  /* rad/s, >= 0 */
};

/* Effective gravity on the sphere at one point. Components are of the
 * acceleration g_eff (m/s^2) in local axes east, north, up. */
struct mech_earth_gravity {
    double r;                 /* distance from the centre R + h, m */
    double gravitation;       /* GM / r², towards the centre */
    double centrifugal;       /* W² r cos L, away from the axis */
    double centrifugal_up;    /* its up component W² r cos² L */
    double centrifugal_north; /* its north component -W² r cos L sin L */
    double radial;     /* downward (towards the centre) component of g_eff: g0 - W² r cos² L */
    double horizontal; /* horizontal component of g_eff towards the equator, >= 0 */
    double north;      /* signed north component of g_eff (= centrifugal_north) */
    double magnitude;  /* |g_eff| */
    double reduction;  /* g0 - |g_eff| (computed without cancellation); W² r at the equator */
    double deviation;  /* plumb line vs direction to the centre, rad, >= 0, towards the equator */
    double k;          /* W² r / g0 */
    double deviation_max;          /* largest deviation over latitude at this r, rad */
    double deviation_max_latitude; /* where it occurs, rad (> 0; and its mirror in the south) */
};

/* The 1980 International Gravity Formula (the GRS 80 series, Moritz 1980,
 * Bull. Géod. 54, 395; IAG 1980): gamma = 9.780327 (1 + 0.0053024 sin² L
 * - 0.0000058 sin² 2L) m/s², sea level, geodetic latitude; within 1e-6 m/s²
 * (0.1 mGal) of GRS 80's closed Somigliana formula. */
#define MECH_IGF1980_GAMMA_E 9.780327
#define MECH_IGF1980_B1 0.0053024
#define MECH_IGF1980_B2 0.0000058

/* WGS 84 normal gravity at geodetic latitude L and height h. */
struct mech_normal_gravity {
    double igf1980;  /* 1980 International Gravity Formula at sea level (L only), m/s^2 */
    double surface;  /* Somigliana gamma0 on the ellipsoid, m/s^2 */
    double free_air; /* gamma - gamma0 (the free-air correction, < 0 above the ellipsoid) */
    double gamma;    /* normal gravity at height h */
};

/* Sine and cosine of an angle in degrees, exact at multiples of 90 deg and
 * symmetric (argument reduced to |x| <= 45 deg first). Cannot fail. */
void mech_sincos_deg(double deg, double *s, double *c);

/* Effective gravity on the sphere `e` at latitude `latitude_deg` (degrees,
 * [-90, 90]) and height `height` (m, [MECH_EARTH_HEIGHT_MIN, MECH_EARTH_HEIGHT_MAX]).
 * Statuses: MECH_OK; MECH_EINVAL (NULL pointers; params "latitude_deg",
 * "height", "radius", "gm", "omega" for non-finite or out-of-range values);
 * MECH_EDOMAIN (param "radius": the centrifugal term reaches gravitation,
 * W² r >= g0, so nothing hangs down); MECH_ENUMERIC (a non-finite result). */
enum mech_status mech_earth_gravity_sphere(const struct mech_earth_sphere *e, double latitude_deg,
                                           double height, struct mech_earth_gravity *out,
                                           struct mech_error *err);

/* WGS 84 normal gravity (Somigliana + free-air, see above) at geodetic
 * latitude `latitude_deg` ([-90, 90]) and ellipsoidal height `height` (m, same
 * range as above). Statuses: MECH_OK; MECH_EINVAL (NULL out; params
 * "latitude_deg", "height"). */
enum mech_status mech_earth_normal_gravity(double latitude_deg, double height,
                                           struct mech_normal_gravity *out, struct mech_error *err);

#endif
