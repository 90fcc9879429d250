/* particles.c — the particle mass table (PDG 2024, CODATA 2018 for light
 * nuclei; see mech/relativity/particles.h for the citation) and energy-unit conversion. */
#include "mech/relativity/particles.h"

#include <string.h>

#define MECH_PARTICLE_ENTRY(name, mass, source)                                                    \
    {                                                                                              \
        name, mass, source                                                                         \
    }
#define MECH_PARTICLE_COMMA ,

static const struct mech_particle particles[] = {
    MECH_PARTICLE_TABLE(MECH_PARTICLE_ENTRY, MECH_PARTICLE_COMMA)};

size_t mech_particle_count(void)
{
    return sizeof particles / sizeof particles[0];
}

const struct mech_particle *mech_particle_at(size_t i)
{
    return i < mech_particle_count() ? &particles[i] : NULL;
}

const struct mech_particle *mech_particle_find(const char *name)
{
    if (!name) return NULL;
    for (size_t i = 0; i < mech_particle_count(); i++)
        if (strcmp(particles[i].name, name) == 0) return &particles[i];
    return NULL;
}

static const char *const unit_names[MECH_ENERGY_UNIT_COUNT] = {"eV", "keV", "MeV", "GeV", "TeV"};

const char *mech_energy_unit_name(enum mech_energy_unit u)
{
    return (unsigned)u < MECH_ENERGY_UNIT_COUNT ? unit_names[u] : "?";
}

enum mech_status mech_energy_unit_parse(const char *name, enum mech_energy_unit *out,
                                        struct mech_error *err)
{
    for (int i = 0; name && i < MECH_ENERGY_UNIT_COUNT; i++) {
        if (strcmp(name, unit_names[i]) == 0) {
            if (out) *out = (enum mech_energy_unit)i;
            return MECH_OK;
        }
    }
    return mech_error_set(err, MECH_EINVAL, "energy_unit",
                          "energy_unit must be one of eV, keV, MeV, GeV, TeV");
}

double mech_energy_convert(double x, enum mech_energy_unit from, enum mech_energy_unit to)
{
    /* 1e3, 1e6, 1e9, 1e12 are exact doubles: one correctly rounded operation. */
    static const double pow1000[] = {1.0, 1e3, 1e6, 1e9, 1e12};
    int k = (int)from - (int)to;
    if (k > 4 || k < -4) k = k > 0 ? 4 : -4; /* unreachable for valid units */
    return k >= 0 ? x * pow1000[k] : x / pow1000[-k];
}

double mech_energy_hc(enum mech_energy_unit unit)
{
    /* h c / e with h = 6.62607015e-34 J s, c = 299792458 m/s, e = 1.602176634e-19 C
     * (exact SI values): 1.239841984332002622e-6 eV m. */
    return mech_energy_convert(1.2398419843320026e-6, MECH_EV, unit);
}
