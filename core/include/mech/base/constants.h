/* constants.h — the one home of the physical constants the core, the server,
 * the tests and the benchmarks share: pi, the speed of light, G, the GM
 * values, and the constants of the Earth, the Moon and the Sun. Each is
 * defined once, with its source; nothing else in core/, server/, tests/core/
 * or bench/ restates one (a header may keep an old name as an alias of the
 * value here, for its callers). Model parameters that are part of one
 * formula (the 1980 International Gravity Formula's series, a solver's
 * tolerance) stay with that formula. */
#ifndef MECH_CONSTANTS_H
#define MECH_CONSTANTS_H

/* ---- mathematics ------------------------------------------------------------ */

/* pi, rounded to double (the literal carries more digits than a double). */
#define MECH_PI 3.14159265358979323846
/* pi/2, the double nearest (exactly MECH_PI / 2). */
#define MECH_PI_2 1.57079632679489661923
/* pi and 2 pi rounded to long double (for long-double reference solutions). */
#define MECH_PI_L 3.141592653589793238462643383279502884L
#define MECH_TWO_PI_L 6.283185307179586476925286766559L

/* ---- fundamental constants -------------------------------------------------- */

/* Speed of light in vacuum, m/s (SI 2019: exact). */
#define MECH_C 299792458.0
/* Newtonian constant of gravitation, m^3 kg^-1 s^-2 (CODATA 2018). */
#define MECH_GRAVITATIONAL_CONSTANT 6.67430e-11

/* ---- the Earth -------------------------------------------------------------- */

/* Geocentric gravitational constant incl. atmosphere, m^3/s^2
 * (IERS Conventions 2010, Table 1.1; WGS 84 value of TR8350.2 Table 3.1). */
#define MECH_EARTH_GM 3.986004418e14
/* Mean radius R1 = (2a + b)/3 of the IUGG (Moritz, Geodetic Reference System
 * 1980, Bull. Géod. 54 (1980) 395), m: the sphere's default radius. */
#define MECH_EARTH_RADIUS_MEAN 6371008.8
/* The one default rotation rate of the Earth, rad/s: the nominal mean angular
 * velocity relative to inertial space (IERS Conventions 2010 Table 1.1; the
 * WGS 84 and GRS 80 defining constant). 2 pi / W = 86164.0989 s, the stellar
 * day; the sidereal day (86164.0905 s, relative to the precessing equinox)
 * gives 7.2921159e-5, which mechd used in some operations before: that rate
 * includes the precession of the equinox and is 1.2e-7 relative too fast for
 * the Earth's rotation in an inertial frame. Every operation defaults to this. */
#define MECH_EARTH_OMEGA 7.292115e-5

/* WGS 84 defining and derived constants (NIMA TR8350.2, 3rd ed., Tables 3.1-3.4). */
#define MECH_WGS84_A 6378137.0             /* semi-major axis, m */
#define MECH_WGS84_B 6356752.3142          /* semi-minor axis, m */
#define MECH_WGS84_F (1.0 / 298.257223563) /* flattening */
#define MECH_WGS84_E2 6.69437999014e-3     /* first eccentricity squared */
#define MECH_WGS84_GAMMA_E 9.7803253359    /* normal gravity at the equator, m/s^2 */
#define MECH_WGS84_GAMMA_P 9.8321849378    /* normal gravity at the poles, m/s^2 */
#define MECH_WGS84_K 0.00193185265241      /* Somigliana's k = b gamma_p/(a gamma_e) - 1 */
#define MECH_WGS84_M 0.00344978650684      /* m = W² a² b / GM */
/* The Earth's rotation rate under its older name (kept for its callers). */
#define MECH_EARTH_OMEGA_SIDEREAL MECH_EARTH_OMEGA

/* ---- the Moon and the Sun --------------------------------------------------- */

/* GM of the Moon, m^3/s^2 (JPL DE440, Park et al. 2021, AJ 161:105, Table 8:
 * 4902.800118 km^3/s^2; DE430 had 4902.800066). GM is what the ephemerides
 * measure; the mass is GM/G (G known to 2e-5). */
#define MECH_MOON_GM 4.902800118e12
/* Mass of the Moon, kg: MECH_MOON_GM / G = 7.3458e22 (the fact sheet's rounded
 * 7.342e22 kg, used before, gave a GM 0.05 % low). */
#define MECH_MOON_MASS (MECH_MOON_GM / MECH_GRAVITATIONAL_CONSTANT)
/* Mean Earth-Moon distance, m (semi-major axis of the lunar orbit, 384 400 km). */
#define MECH_MOON_DISTANCE 3.844e8
/* Heliocentric gravitational constant GM_sun, m^3/s^2 (JPL DE440, Park et al.
 * 2021, Table 8: 132712440041.279419 km^3/s^2, TDB-compatible; the value used
 * before, 1.32712440018e20, was DE405's). The Sun's mass is GM_sun / G =
 * 1.98841e30 kg. */
#define MECH_SUN_GM 1.32712440041279419e20
/* Astronomical unit, m (IAU 2012 Resolution B2, exact): the mean Sun distance. */
#define MECH_AU 1.495978707e11
/* Mass of the Earth, kg (IAU 2015 nominal / CODATA: 5.9722e24); only reported:
 * the tide height uses GM_E = MECH_EARTH_GM above. */
#define MECH_EARTH_MASS 5.9722e24
/* Mean radii, m: the Moon 1737.4 km (IAU Working Group on Cartographic
 * Coordinates 2015), the Sun 695 700 km (IAU 2015 Resolution B3, nominal). */
#define MECH_MOON_RADIUS 1.7374e6
#define MECH_SUN_RADIUS 6.957e8
/* The named bodies' earlier ("legacy") set, kept selectable so that answers a
 * client had do not change: the Sun's GM of JPL DE405, m^3/s^2, and the
 * Moon's mass from the JPL planetary fact sheet, kg (rounded; GM = G m). */
#define MECH_LEGACY_SUN_GM 1.32712440018e20
#define MECH_LEGACY_MOON_MASS 7.342e22

#endif
