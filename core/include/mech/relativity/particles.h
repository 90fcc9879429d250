/* mech/relativity/particles.h — particle names → rest masses, and the energy units of
 * particle kinematics (eV … TeV, c = 1).
 *
 * Masses are central values in MeV/c² from the Review of Particle Physics,
 * 2024 edition: S. Navas et al. (Particle Data Group), Phys. Rev. D 110,
 * 030001 (2024), as distributed in its Monte-Carlo mass table
 * (mass_width_2024.mcd, generated 31 May 2024). Light nuclei (deuteron,
 * triton, helion, alpha), which that table does not list, are the CODATA 2018
 * mass-energy equivalents (E. Tiesinga et al., Rev. Mod. Phys. 93, 025010
 * (2021)); PDG 2024 quotes the same CODATA 2018 electron mass. Neutrinos are
 * taken massless (PDG 2024: m < 0.8 eV, negligible at these scales); the
 * photon is massless. Antiparticles have their particle's mass (CPT).
 *
 * The table is an X-macro so the API can build its schema enum and catalog
 * text from the same entries the lookup uses (one const table,
 * no runtime registration): MECH_PARTICLE_TABLE(X, SEP) expands to
 * X(name, mass_MeV, source) SEP X(...) ..., name and source string literals,
 * mass a numeric literal.
 */
#ifndef MECH_PARTICLES_H
#define MECH_PARTICLES_H

#include <stddef.h>

#include "mech/base/status.h"

#define MECH_PARTICLE_EDITION                                                                      \
    "PDG 2024 (S. Navas et al., Particle Data Group, Phys. Rev. D 110, 030001 (2024)); "           \
    "light nuclei CODATA 2018"

/* clang-format off */
#define MECH_PARTICLE_TABLE(X, SEP)                                                                \
    X("photon", 0.0, "massless") SEP                                                               \
    X("gamma", 0.0, "massless (alias of photon)") SEP                                              \
    X("electron", 0.51099895000, "PDG 2024") SEP                                                   \
    X("e-", 0.51099895000, "PDG 2024") SEP                                                         \
    X("positron", 0.51099895000, "PDG 2024") SEP                                                   \
    X("e+", 0.51099895000, "PDG 2024") SEP                                                         \
    X("muon", 105.6583755, "PDG 2024") SEP                                                         \
    X("mu-", 105.6583755, "PDG 2024") SEP                                                          \
    X("mu+", 105.6583755, "PDG 2024") SEP                                                          \
    X("tau", 1776.93, "PDG 2024") SEP                                                              \
    X("tau-", 1776.93, "PDG 2024") SEP                                                             \
    X("tau+", 1776.93, "PDG 2024") SEP                                                             \
    X("neutrino", 0.0, "taken massless (PDG 2024: m < 0.8 eV)") SEP                                \
    X("antineutrino", 0.0, "taken massless (PDG 2024: m < 0.8 eV)") SEP                            \
    X("nu_e", 0.0, "taken massless (PDG 2024: m < 0.8 eV)") SEP                                    \
    X("nu_mu", 0.0, "taken massless (PDG 2024: m < 0.8 eV)") SEP                                   \
    X("nu_tau", 0.0, "taken massless (PDG 2024: m < 0.8 eV)") SEP                                  \
    X("pi0", 134.9768, "PDG 2024") SEP                                                             \
    X("pi+", 139.57039, "PDG 2024") SEP                                                            \
    X("pi-", 139.57039, "PDG 2024") SEP                                                            \
    X("K+", 493.677, "PDG 2024") SEP                                                               \
    X("K-", 493.677, "PDG 2024") SEP                                                               \
    X("K0", 497.611, "PDG 2024") SEP                                                               \
    X("eta", 547.862, "PDG 2024") SEP                                                              \
    X("proton", 938.27208816, "PDG 2024") SEP                                                      \
    X("p", 938.27208816, "PDG 2024") SEP                                                           \
    X("antiproton", 938.27208816, "PDG 2024") SEP                                                  \
    X("pbar", 938.27208816, "PDG 2024") SEP                                                        \
    X("neutron", 939.5654205, "PDG 2024") SEP                                                      \
    X("n", 939.5654205, "PDG 2024") SEP                                                            \
    X("antineutron", 939.5654205, "PDG 2024") SEP                                                  \
    X("Lambda", 1115.683, "PDG 2024") SEP                                                          \
    X("J/psi", 3096.900, "PDG 2024") SEP                                                           \
    X("deuteron", 1875.61294257, "CODATA 2018") SEP                                                \
    X("triton", 2808.92113298, "CODATA 2018") SEP                                                  \
    X("helion", 2808.39160743, "CODATA 2018") SEP                                                  \
    X("alpha", 3727.3794066, "CODATA 2018") SEP                                                    \
    X("W+", 80369.0, "PDG 2024") SEP                                                               \
    X("W-", 80369.0, "PDG 2024") SEP                                                               \
    X("Z", 91188.0, "PDG 2024") SEP                                                                \
    X("Higgs", 125200.0, "PDG 2024")
/* clang-format on */

struct mech_particle {
    const char *name;   /* e.g. "pi0", "proton" */
    double mass;        /* MeV/c², ≥ 0 */
    const char *source; /* "PDG 2024", "CODATA 2018", "massless", ... */
};

/* Number of entries of the table (aliases included). */
size_t mech_particle_count(void);

/* Entry i (0 ≤ i < count) or NULL. Static storage, never freed. */
const struct mech_particle *mech_particle_at(size_t i);

/* The entry named `name` (exact, case-sensitive), or NULL. Thread-safe. */
const struct mech_particle *mech_particle_find(const char *name);

/* Energy units of particle kinematics; each is 1000 times the previous. */
enum mech_energy_unit {
    MECH_EV = 0,
    MECH_KEV,
    MECH_MEV,
    MECH_GEV,
    MECH_TEV,
    MECH_ENERGY_UNIT_COUNT
};

/* "eV", "keV", "MeV", "GeV", "TeV"; "?" for an out-of-range value. */
const char *mech_energy_unit_name(enum mech_energy_unit u);

/* Parse a unit name (exact spelling above). Statuses: MECH_OK;
 * MECH_EINVAL (param "energy_unit") for an unknown name or NULL. */
enum mech_status mech_energy_unit_parse(const char *name, enum mech_energy_unit *out,
                                        struct mech_error *err);

/* x (an energy, mass·c² or momentum·c in unit `from`) expressed in unit `to`:
 * one multiplication or division by an exact power of ten (10^3k, k ≤ 4), so
 * the result is correctly rounded; converting back returns x to within one
 * rounding. Cannot fail (overflow gives ±inf; callers bound their inputs). */
double mech_energy_convert(double x, enum mech_energy_unit from, enum mech_energy_unit to);

/* hc in (unit)·m, for wavelengths λ = hc/E: h, c and e are exact in the SI
 * since 2019, hc = 1.2398419843320026e-6 eV·m (1.239841984332002622e-6 exactly rounded). */
double mech_energy_hc(enum mech_energy_unit unit);

#endif
