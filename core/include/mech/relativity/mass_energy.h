/* mech/relativity/mass_energy.h — rest energy and rest mass, E = m c^2 either way, and
 * the rest mass a radiating body loses, dm/dt = L / c^2, from its luminosity
 * L or from the flux F measured at a distance d (L = 4 pi d^2 F, isotropic
 * emission). SI units throughout: kg, J, W, W/m^2, m, s. */
#ifndef MECH_MASS_ENERGY_H
#define MECH_MASS_ENERGY_H

#include "mech/base/status.h"

/* Which quantity the request gives. */
enum mech_mass_energy_form {
    MECH_MASS_ENERGY_MASS = 0,   /* value: a rest mass m, kg */
    MECH_MASS_ENERGY_ENERGY,     /* value: an energy E, J */
    MECH_MASS_ENERGY_LUMINOSITY, /* value: a luminosity L, W */
    MECH_MASS_ENERGY_FLUX,       /* value: a flux F, W/m^2, at `distance` */
};

/* Valid ranges (every input is refused outside them, so every answer is a
 * normal, finite double). */
#define MECH_MASS_ENERGY_MIN 1e-250 /* mass, energy, luminosity */
#define MECH_MASS_ENERGY_MAX 1e200
#define MECH_MASS_ENERGY_FLUX_MIN 1e-100
#define MECH_MASS_ENERGY_FLUX_MAX 1e100
#define MECH_MASS_ENERGY_DISTANCE_MIN 1e-20
#define MECH_MASS_ENERGY_DISTANCE_MAX 1e50
#define MECH_MASS_ENERGY_DURATION_MIN 1e-30
#define MECH_MASS_ENERGY_DURATION_MAX 1e30

struct mech_mass_energy_request {
    enum mech_mass_energy_form form;
    double value;    /* the given quantity, in the form's unit */
    double distance; /* m, FLUX only */
    int has_duration;
    double duration; /* s, rates only: adds the mass lost over it */
};

struct mech_mass_energy_answer {
    int rate;               /* 1: a luminosity (the rate members are set), 0: mass/energy */
    double mass, energy;    /* kg, J (rate = 0) */
    double luminosity;      /* W (rate = 1; 4 pi d^2 F for a flux) */
    double mass_loss_rate;  /* kg/s, L / c^2 */
    double mass_loss_per_year; /* kg per Julian year (365.25 d), L yr / c^2 */
    double mass_lost;       /* kg over duration (has_duration) */
};

/* Fill out from q. Statuses: MECH_OK; MECH_EDOMAIN with param "mass",
 * "energy", "luminosity", "flux", "distance" or "duration" naming a value
 * outside its range above (or a duration given with a mass or energy);
 * MECH_EINVAL for a NULL argument or an unknown form. */
enum mech_status mech_mass_energy(const struct mech_mass_energy_request *q,
                                  struct mech_mass_energy_answer *out, struct mech_error *err);

#endif
