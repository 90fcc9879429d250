/* mech/gr/gr_units.h — the units of the general-relativity operations: a
 * request in SI (m, s, m^2/s, m/s) or in geometric units (G = c = M = 1:
 * lengths in GM/c^2, times in GM/c^3, specific angular momentum in GM/c,
 * speeds in c), converted through GM/c^2 and GM/c^3 to the geometric units
 * core/gr/ computes in (mech/gr/schwarzschild.h, mech/gr/geodesic.h).
 * The constants are mech/base/constants.h's: c exact, G CODATA 2018, the Sun's GM
 * JPL DE440, the Earth's GM WGS 84 / IERS.
 * The conversions are pure inline functions; thread-safe; no allocation. */
#ifndef MECH_GR_UNITS_H
#define MECH_GR_UNITS_H

#include "mech/base/constants.h"
#include "mech/base/status.h"

/* How the central mass is given. */
enum mech_gr_mass {
    MECH_GR_MASS_NONE = 0, /* not given (allowed only with geometric units) */
    MECH_GR_MASS_KG,       /* value is a mass in kg: GM = G value */
    MECH_GR_MASS_GM,       /* value is GM itself, m^3/s^2 */
    MECH_GR_MASS_SUN,      /* the Sun: GM = MECH_SUN_GM (value ignored) */
    MECH_GR_MASS_EARTH     /* the Earth: GM = MECH_EARTH_GM (value ignored) */
};

struct mech_gr_units {
    int geometric; /* 1: the caller's quantities are already geometric */
    int has_mass;  /* 1 when GM is known */
    double GM;     /* m^3/s^2 (NaN when unknown) */
    double m;      /* GM/c^2 in m (NaN when unknown) */
    double s;      /* GM/c^3 in s (NaN when unknown) */
};

/* Set up the units of one request: geometric (nonzero) or SI, and the mass
 * given as `mass` with `value` (kg or m^3/s^2; ignored for NONE, SUN, EARTH).
 * Valid range: any double; the result is checked, not assumed.
 * Statuses: MECH_OK; MECH_EINVAL param "M" (SI units without a mass: nothing
 * converts metres to GM/c^2); MECH_EDOMAIN param "M" (GM/c^2 is not a positive
 * finite length: a zero, negative, NaN or overflowing mass), the text
 * "GM/c^2 = <%.6g> m is not a usable length". out is always written (NaN
 * fields where unknown); err may be NULL. */
enum mech_status mech_gr_units_init(int geometric, enum mech_gr_mass mass, double value,
                                    struct mech_gr_units *out, struct mech_error *err);

/* Conversions between the caller's units and geometric ones (M = 1). With
 * geometric units they are the identity; with SI they need has_mass (the
 * init above guarantees it). Lengths: m <-> GM/c^2; times: s <-> GM/c^3;
 * specific angular momentum: m^2/s <-> GM/c (1 GM/c = m c m^2/s); speeds:
 * m/s -> c. */
static inline double mech_gr_len_in(const struct mech_gr_units *u, double x)
{
    return u->geometric ? x : x / u->m;
}
static inline double mech_gr_len_out(const struct mech_gr_units *u, double r)
{
    return u->geometric ? r : r * u->m;
}
static inline double mech_gr_time_in(const struct mech_gr_units *u, double x)
{
    return u->geometric ? x : x / u->s;
}
static inline double mech_gr_time_out(const struct mech_gr_units *u, double t)
{
    return u->geometric ? t : t * u->s;
}
static inline double mech_gr_ang_in(const struct mech_gr_units *u, double L)
{
    return u->geometric ? L : L / (u->m * MECH_C);
}
static inline double mech_gr_ang_out(const struct mech_gr_units *u, double L)
{
    return u->geometric ? L : L * u->m * MECH_C;
}
static inline double mech_gr_speed_in(const struct mech_gr_units *u, double v)
{
    return u->geometric ? v : v / MECH_C;
}

#endif
