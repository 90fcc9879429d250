/* mech/hamiltonian/apsides.h — the pericentres of an orbit in a central power law
 * H = p_r^2/(2m) + p_phi^2/(2 m r^2) + k r^n, located as upward crossings of
 * p_r = 0 by root-finding on the flow (mech/hamiltonian/poincare.h), and the apsidal
 * angle measured from them beside its near-circular limit pi/sqrt(n + 2)
 * (Goldstein §3.6). SI units.
 * Thread-safe; allocates the pericentre arrays (mech_apsides_free). */
#ifndef MECH_APSIDES_H
#define MECH_APSIDES_H

#include <stddef.h>

#include "mech/base/budget.h"
#include "mech/hamiltonian/hamiltonian.h"
#include "mech/ode/ode.h"

/* The most pericentres one search locates. */
#define MECH_APSIDES_MAX 1000

struct mech_apsides {
    int radial;                 /* p_phi = 0: radial motion, no apsides (nothing else set) */
    size_t n;                   /* pericentres found (<= MECH_APSIDES_MAX) */
    double *t, *r, *phi;        /* n each: time (s), radius (m), unwrapped angle (rad); owned */
    int has_measured;           /* n >= 2 */
    double angle_measured;      /* (phi_last - phi_first) / (2 (n - 1)): the mean
                                   pericentre-to-pericentre angle / 2, rad (NaN without) */
    int has_near_circular;      /* the exponent s->power > -2 */
    double angle_near_circular; /* pi / sqrt(power + 2), rad (NaN without) */
};

/* Locate the pericentres of the orbit from y0 = (r, phi, p_r, p_phi) over
 * [0, t_end] with method and opt, within `budget` less `steps_used` steps
 * already spent (the flow's).
 * Statuses: MECH_OK; MECH_EINVAL "system" for a system that is not central;
 * MECH_EBUDGET when no steps are left or they run out; MECH_ENOMEM; the
 * statuses of mech_poincare_run (MECH_ENUMERIC, MECH_EDEADLINE, ...).
 * out is always initialised (safe to free); err may be NULL. */
enum mech_status mech_apsides_find(const struct mech_ham_system *s, const double *y0, double t_end,
                                   const struct mech_integrator *method,
                                   struct mech_ode_options opt, const struct mech_budget *budget,
                                   long steps_used, struct mech_apsides *out,
                                   struct mech_error *err);

/* Free the arrays (safe on an initialised or failed answer). */
void mech_apsides_free(struct mech_apsides *a);

#endif
