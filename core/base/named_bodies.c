/* named_bodies.c — the versioned sets of named bodies (mech/base/named_bodies.h). */
#include "mech/base/named_bodies.h"

#include <stddef.h>
#include <string.h>

#include "mech/base/constants.h"

/* The legacy Moon was given by its mass; its GM is G times it. */
#define LEGACY_MOON_MASS MECH_LEGACY_MOON_MASS
#define LEGACY_SUN_GM MECH_LEGACY_SUN_GM
#define MOON_RADIUS MECH_MOON_RADIUS
#define SUN_RADIUS MECH_SUN_RADIUS
#define EARTH_RADIUS MECH_EARTH_RADIUS_MEAN

static const struct mech_named_body de440[] = {
    {"sun", MECH_SUN_GM, MECH_SUN_GM / MECH_GRAVITATIONAL_CONSTANT, SUN_RADIUS, MECH_AU,
     "sun (DE440): GM = 1.32712440041279419e20 m^3/s^2 (JPL DE440, Park et al. 2021), mass = "
     "GM/G, radius 6.957e8 m (IAU 2015 B3), distance 1 au = 1.495978707e11 m (IAU 2012 B2)"},
    {"moon", MECH_MOON_GM, MECH_MOON_GM / MECH_GRAVITATIONAL_CONSTANT, MOON_RADIUS,
     MECH_MOON_DISTANCE,
     "moon (DE440): GM = 4.902800118e12 m^3/s^2 (JPL DE440, Park et al. 2021), mass = GM/G, "
     "radius 1.7374e6 m (IAU mean), mean distance 3.844e8 m (semi-major axis)"},
    {"earth", MECH_EARTH_GM, MECH_EARTH_GM / MECH_GRAVITATIONAL_CONSTANT, EARTH_RADIUS, 0.0,
     "earth (DE440 set): GM = 3.986004418e14 m^3/s^2 (IERS Conventions 2010, WGS 84), mass = "
     "GM/G, radius 6371008.8 m (IUGG mean)"},
};

static const struct mech_named_body legacy[] = {
    {"sun", LEGACY_SUN_GM, LEGACY_SUN_GM / MECH_GRAVITATIONAL_CONSTANT, SUN_RADIUS, MECH_AU,
     "sun (legacy): GM = 1.32712440018e20 m^3/s^2 (JPL DE405, the value mechd used before "
     "DE440), mass = GM/G, radius 6.957e8 m (IAU 2015 B3), distance 1 au = 1.495978707e11 m"},
    {"moon", MECH_GRAVITATIONAL_CONSTANT * LEGACY_MOON_MASS, LEGACY_MOON_MASS, MOON_RADIUS,
     MECH_MOON_DISTANCE,
     "moon (legacy): mass = 7.342e22 kg (JPL planetary fact sheet, rounded; the value mechd "
     "used before DE440), GM = G mass with G = 6.67430e-11, radius 1.7374e6 m, mean distance "
     "3.844e8 m"},
    {"earth", MECH_EARTH_GM, MECH_EARTH_GM / MECH_GRAVITATIONAL_CONSTANT, EARTH_RADIUS, 0.0,
     "earth (legacy set): GM = 3.986004418e14 m^3/s^2 (IERS Conventions 2010, WGS 84), mass = "
     "GM/G, radius 6371008.8 m (IUGG mean)"},
};

const char *mech_body_set_name(enum mech_body_set set)
{
    switch (set) {
    case MECH_BODY_SET_DE440: return "DE440";
    case MECH_BODY_SET_LEGACY: return "legacy";
    }
    return NULL;
}

int mech_body_set_parse(const char *name, enum mech_body_set *set)
{
    if (!name) return 0;
    if (!strcmp(name, "DE440")) *set = MECH_BODY_SET_DE440;
    else if (!strcmp(name, "legacy")) *set = MECH_BODY_SET_LEGACY;
    else return 0;
    return 1;
}

const struct mech_named_body *mech_named_body(enum mech_body_set set, const char *name)
{
    const struct mech_named_body *t = set == MECH_BODY_SET_DE440    ? de440
                                      : set == MECH_BODY_SET_LEGACY ? legacy
                                                                    : NULL;
    if (!t || !name) return NULL;
    for (size_t i = 0; i < 3; i++)
        if (!strcmp(t[i].name, name)) return &t[i];
    return NULL;
}
