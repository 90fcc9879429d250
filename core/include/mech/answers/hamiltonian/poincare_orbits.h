/* mech/answers/hamiltonian/poincare_orbits.h — a Poincaré section of several orbits: each start
 * integrated in turn with its crossings located (mech_poincare_run) within
 * one step budget, the plane's angle reduced to [0, 2 pi) when the plane's
 * coordinate is phi, each orbit handed to the caller as it completes (so
 * only one orbit's crossings are held at a time).
 * Thread-safe; allocates one orbit's crossing arrays, freed before return. */
#ifndef MECH_POINCARE_ORBITS_H
#define MECH_POINCARE_ORBITS_H

#include <stddef.h>

#include "mech/base/budget.h"
#include "mech/hamiltonian/poincare.h"

/* Called once per orbit k, in order, with its result (arrays valid during the
 * call only; u already reduced to [0, 2 pi) for an angle plane). Return 0 to
 * go on; nonzero stops the section with MECH_ENOMEM (the caller could not keep
 * the orbit). */
typedef int (*mech_poincare_orbit_fn)(void *ctx, size_t k, const struct mech_poincare_result *r);

/* The most crossings one orbit records (the buffer is 7 doubles a crossing). */
#define MECH_POINCARE_ORBITS_MAX_CROSSINGS 100000

/* Totals over the orbits run. */
struct mech_poincare_totals {
    struct mech_ode_stats stats; /* steps, rejected steps, evaluations summed */
    int second_order;            /* the last orbit's form (all share the method) */
};

/* Run base (its y0 ignored) from starts[4 k .. 4 k + 3] for k < n_orbits;
 * orbit k gets the budget's steps less those of the orbits before it.
 * Statuses: MECH_OK; MECH_EINVAL "max_crossings" for 0 or more than
 * MECH_POINCARE_ORBITS_MAX_CROSSINGS; MECH_EBUDGET when the steps are spent
 * before an orbit starts; MECH_ENOMEM (also when visit refuses); the statuses
 * of mech_poincare_run. totals cover the orbits visited. err may be NULL. */
enum mech_status mech_poincare_orbits(const struct mech_poincare_problem *base,
                                      const double *starts, size_t n_orbits,
                                      const struct mech_budget *budget,
                                      mech_poincare_orbit_fn visit, void *ctx,
                                      struct mech_poincare_totals *totals, struct mech_error *err);

#endif
