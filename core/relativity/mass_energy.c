/* mass_energy.c — E = m c^2 both ways and the rest-mass loss rate L / c^2 of
 * a luminosity (mech/relativity/mass_energy.h). */
#include "mech/relativity/mass_energy.h"

#include <math.h>
#include <string.h>

#include "mech/base/constants.h"

static const double C2 = MECH_C * MECH_C; /* c^2 = 8.987551787368176e16, one rounding */
static const double JULIAN_YEAR = 365.25 * 86400.0;

static enum mech_status in_range(const char *name, double v, double lo, double hi, const char *unit,
                                 struct mech_error *err)
{
    if (isfinite(v) && v >= lo && v <= hi) return MECH_OK;
    return mech_error_set(err, MECH_EDOMAIN, name, "%s must be in [%g, %g] %s, got %.17g", name,
                          lo, hi, unit, v);
}

enum mech_status mech_mass_energy(const struct mech_mass_energy_request *q,
                                  struct mech_mass_energy_answer *out, struct mech_error *err)
{
    if (!q || !out) return mech_error_set(err, MECH_EINVAL, NULL, "NULL argument");
    memset(out, 0, sizeof *out);
    enum mech_status st;
    const double lo = MECH_MASS_ENERGY_MIN, hi = MECH_MASS_ENERGY_MAX;
    switch (q->form) {
    case MECH_MASS_ENERGY_MASS:
    case MECH_MASS_ENERGY_ENERGY: {
        const int m = q->form == MECH_MASS_ENERGY_MASS;
        if ((st = in_range(m ? "mass" : "energy", q->value, lo, hi, m ? "kg" : "J", err)) != MECH_OK)
            return st;
        if (q->has_duration)
            return mech_error_set(err, MECH_EDOMAIN, "duration",
                                  "duration goes with a luminosity or a flux, not a %s",
                                  m ? "mass" : "energy");
        out->mass = m ? q->value : q->value / C2;
        out->energy = m ? q->value * C2 : q->value;
        return MECH_OK;
    }
    case MECH_MASS_ENERGY_LUMINOSITY:
        if ((st = in_range("luminosity", q->value, lo, hi, "W", err)) != MECH_OK) return st;
        out->luminosity = q->value;
        break;
    case MECH_MASS_ENERGY_FLUX:
        if ((st = in_range("flux", q->value, MECH_MASS_ENERGY_FLUX_MIN, MECH_MASS_ENERGY_FLUX_MAX,
                           "W/m^2", err)) != MECH_OK ||
            (st = in_range("distance", q->distance, MECH_MASS_ENERGY_DISTANCE_MIN,
                           MECH_MASS_ENERGY_DISTANCE_MAX, "m", err)) != MECH_OK)
            return st;
        /* isotropic emission: the flux through a sphere of radius d */
        out->luminosity = 4.0 * MECH_PI * q->distance * q->distance * q->value;
        break;
    default:
        return mech_error_set(err, MECH_EINVAL, NULL, "unknown form %d", (int)q->form);
    }
    out->rate = 1;
    out->mass_loss_rate = out->luminosity / C2;
    out->mass_loss_per_year = out->mass_loss_rate * JULIAN_YEAR;
    if (q->has_duration) {
        if ((st = in_range("duration", q->duration, MECH_MASS_ENERGY_DURATION_MIN,
                           MECH_MASS_ENERGY_DURATION_MAX, "s", err)) != MECH_OK)
            return st;
        out->mass_lost = out->mass_loss_rate * q->duration;
    }
    return MECH_OK;
}
