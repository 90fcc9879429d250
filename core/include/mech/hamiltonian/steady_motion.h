/* mech/hamiltonian/steady_motion.h — the steady motions the flow's answer names
 * beside a run: the spherical pendulum's conical motion at the start's polar
 * angle and the circular orbit of a central power law at the start's radius
 * (Goldstein §3.6, Taylor §8.6 and ex. 11.38). SI units; closed forms.
 * Pure; thread-safe; no allocation. */
#ifndef MECH_HAM_STEADY_MOTION_H
#define MECH_HAM_STEADY_MOTION_H

#include "mech/hamiltonian/hamiltonian.h"

/* The conical pendulum: theta'' = 0 needs p_phi^2 cos/(m l^2 sin^3) = m g l sin,
 * so phi' = sqrt(g/(l cos theta)). */
struct mech_ham_conical {
    double theta;   /* rad, the start's polar angle from the downward vertical */
    double phi_dot; /* rad/s */
    double p_phi;   /* m l^2 sin^2(theta) phi', J s */
    int has_period; /* phi' > 0 */
    double period;  /* 2 pi / phi', s (NaN without) */
};

/* The conical motion of a spherical pendulum at polar angle theta.
 * Returns 1 and fills out for s->kind == MECH_HAM_SPHERICAL_PENDULUM and
 * 0 < theta < pi/2 (below the pivot, off the vertical); returns 0 and leaves
 * out alone otherwise. s checked by mech_ham_system_check. */
int mech_ham_conical_motion(const struct mech_ham_system *s, double theta,
                            struct mech_ham_conical *out);

/* The circular orbit of H = p_r^2/(2m) + p_phi^2/(2 m r^2) + k r^n at radius r:
 * dH/dr = 0 with p_r = 0 gives p_phi^2 = m k n r^(n+2); period 2 pi m r^2/p_phi. */
struct mech_ham_central_circular {
    double r;      /* m */
    double p_phi;  /* J s */
    double period; /* s */
    int stable;    /* n > -2 */
};

/* The circular orbit at radius r > 0 of a central power law. Returns 1 and
 * fills out for s->kind == MECH_HAM_CENTRAL with an attractive force
 * (k n > 0); returns 0 and leaves out alone otherwise. */
int mech_ham_central_circular(const struct mech_ham_system *s, double r,
                              struct mech_ham_central_circular *out);

#endif
