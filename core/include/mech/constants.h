/* constants.h — physical constants the core shares (one definition each).
 * Domain constants that belong to one model (the Earth's ellipsoid, the Moon)
 * stay in that model's header. */
#ifndef MECH_CONSTANTS_H
#define MECH_CONSTANTS_H

/* Newtonian constant of gravitation, m^3 kg^-1 s^-2 (CODATA 2018). */
#define MECH_GRAVITATIONAL_CONSTANT 6.67430e-11

#endif
