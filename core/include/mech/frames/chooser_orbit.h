/* mech/frames/chooser_orbit.h — what the chooser needs to know about a scene's
 * dominant central-body orbit (core/frames/chooser_orbit.c): its period,
 * eccentricity, the relative size of the other forces (Wisdom-Holman's
 * eps) and the run's length in the units of the calibrated cost law.
 * Thread-safety: reentrant. */
#ifndef MECH_CHOOSER_ORBIT_H
#define MECH_CHOOSER_ORBIT_H

#include "mech/ode/chooser.h"
#include "mech/frames/trajectory.h"

/* For a central_gravity profile s of the trajectory problem p whose initial
 * state is on a bound orbit (0 <= e < 1) about its central body (the one
 * with the shortest pericentre time, as the span is counted), set
 * s->orbit_period, s->eccentricity, s->perturbation and s->cost_span:
 *   cost_span = orbits x 17.77 x ((1 + e) / (3 (1 - e)))^(1/3),
 * the evaluations of an adaptive method per orbit growing as
 * (r_apo / r_peri)^(1/3) (measured 2026-11-27 with rk8pd, radau15 and
 * rkf45 over e = 0 .. 0.99 within 1.6x; tests/core/ode/test_chooser.c), where
 * 17.77 = 2 pi / 0.5^1.5 is the span per orbit of the calibration scene
 * (Kepler e = 0.5, span counted in pericentre times). The old law (span in
 * pericentre times) over-predicted e = 0.9 by 4-6x and e = 0.99 by 50x.
 * perturbation: |a_other| a^2 / GM with a_other the sum of the other forces
 * (uniform gravity, springs, drag, Lorentz, tides) at the initial position
 * moved to distance a along the same direction, with the initial velocity
 * (the tide of a body at distance D is then ~eps as in
 * bench/bench_wisdom_holman.c); -1 (unknown) in a non-inertial frame or
 * with several central bodies, where no Kepler splitting is offered.
 * Leaves s unchanged for other classes, unbound or degenerate orbits, or
 * NULL arguments. Never fails. */
void mech_chooser_profile_orbit(struct mech_scene_profile *s,
                                const struct mech_trajectory_problem *p);

#endif
