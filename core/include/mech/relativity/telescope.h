/* mech/relativity/telescope.h — the twin paradox's "reading of the distant clock through
 * a telescope" (notes §3.15): what the stay-at-home twin, at the origin,
 * sees the traveller's clock read at a given home time t. The light arriving
 * home at t left the traveller at the event (t_e, x_e) with t_e + |x_e|/c = t;
 * the traveller's clock read its proper time there. The arrival time grows
 * strictly with the traveller's progress (speed < c), so the emission is
 * found by bisection on the fraction of the leg whose image arrives at t,
 * each trial re-running the legs with mech_worldline_run (the same formulas,
 * so coasting and accelerated legs are treated alike).
 * Units: those of mech_worldline_run. Pure; thread-safe; caller-owned scratch.
 */
#ifndef MECH_TELESCOPE_H
#define MECH_TELESCOPE_H

#include <stddef.h>

#include "mech/relativity/worldline.h"

struct mech_telescope_view {
    double home_time;       /* t (T) */
    long leg;               /* the leg whose light arrives at t (−1: at t = 0, at departure) */
    double traveller_clock; /* the traveller's proper time the telescope shows (T) */
    double emission[4];     /* [t_e, x_e, y_e, z_e] where that light left (T, L) */
    double light_time;      /* |x_e|/c = t − t_e (T) */
};

/* legs[0..n−1] and run[0..n−1] (the results of mech_worldline_run on them);
 * scratch_legs and scratch_run hold n entries each (caller-owned, contents
 * ignored). t_home ≥ 0, at most run[n−1].home_receives_end (after that the
 * image depends on what the traveller does next). About 64 (k + 1) budget
 * steps for an image in leg k. Statuses: MECH_OK; MECH_EDOMAIN param
 * "telescope_home_times" (t_home < 0, not finite, or later than the last
 * image); errors of mech_worldline_run (budget, deadline). */
enum mech_status mech_telescope_home_view(const struct mech_leg *legs,
                                          const struct mech_leg_result *run, size_t n, double c,
                                          double t_home, struct mech_leg *scratch_legs,
                                          struct mech_leg_result *scratch_run,
                                          const struct mech_budget *budget,
                                          struct mech_telescope_view *out,
                                          struct mech_error *err);

#endif
