/* gr_units.c — the GR operations' unit set-up: GM from the request's mass,
 * then GM/c^2 (a length) and GM/c^3 (a time), checked usable
 * (mech/gr/gr_units.h). */
#include <math.h>

#include "mech/gr/gr_units.h"

enum mech_status mech_gr_units_init(int geometric, enum mech_gr_mass mass, double value,
                                    struct mech_gr_units *out, struct mech_error *err)
{
    out->geometric = geometric != 0;
    out->has_mass = 0;
    out->GM = out->m = out->s = NAN;
    if (mass == MECH_GR_MASS_NONE) {
        if (out->geometric) return MECH_OK;
        return mech_error_set(err, MECH_EINVAL, "M",
                              "M is required with units SI (a mass in kg, \"sun\" or \"earth\")");
    }
    switch (mass) {
    case MECH_GR_MASS_SUN:
        out->GM = MECH_SUN_GM;
        break;
    case MECH_GR_MASS_EARTH:
        out->GM = MECH_EARTH_GM;
        break;
    case MECH_GR_MASS_GM:
        out->GM = value;
        break;
    default: /* MECH_GR_MASS_KG */
        out->GM = MECH_GRAVITATIONAL_CONSTANT * value;
        break;
    }
    out->has_mass = 1;
    out->m = out->GM / (MECH_C * MECH_C);
    out->s = out->m / MECH_C;
    if (!(out->m > 0) || !isfinite(out->m))
        return mech_error_set(err, MECH_EDOMAIN, "M", "GM/c^2 = %.6g m is not a usable length",
                              out->m);
    return MECH_OK;
}
