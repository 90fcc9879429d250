/* mech/frames/chooser_pendulum.h — the predictive chooser for the Foucault pendulum
 * (mech/frames/pendulum.h; the Foucault scene's answer asks it): the same selection as
 * mech_choose() (mech/ode/chooser.h) over the pendulum's own candidates, the
 * constrained symplectic methods rattle (order 2, one force evaluation per
 * step) and rattle_yoshida4 (order 4, three), each at the fewest steps per
 * swing predicted to meet the target.
 *
 * The error is that of the answer's measured quantities: the swing period
 * (relative) and the precession rate (relative to W). Model (measured
 * 2026-11-27, bench/bench_calibrate_chooser.c --pendulum: l = 67 m, latitudes
 * 32 .. 80 deg, amplitudes 3 .. 30 deg, 100 and 1000 swings, against
 * rattle_yoshida4 at 12800 steps per swing):
 *   error = C_p (2 pi / n)^p (1 + 3 alpha^2),  n = steps per swing,
 *   C_2 = 0.07 (rattle), C_4 = 0.07 (rattle_yoshida4), the largest measured
 *   (rattle 0.032 .. 0.069: the period's 0.0415 at small amplitude, the
 *   rate's wobble at 30 deg; rattle_yoshida4 0.064 .. 0.071), the same over
 *   100 and 1000 swings; the rate's error relative to W is ~0.6 alpha^2 of
 *   the period's for rattle_yoshida4;
 *   floor: max(1e-14, 1e-13 / (W t_end)) — the period, and the swing
 *   plane's azimuth round-off (~1e-13 rad at the turning points) over the
 *   angle W t_end the Earth turns in the run.
 * Evaluations are exact, not fitted: steps = ceil(swings n), evaluations =
 * steps x (1 or 3) + 1, plus the error-estimate run at half the steps when
 * asked. CPU = evaluations x 5.3e-8 s (yoshida4) or 5.85e-8 s (rattle)
 * + MECH_CHOOSER_REQUEST_CPU_S.
 * Thread-safety: reentrant. */
#ifndef MECH_CHOOSER_PENDULUM_H
#define MECH_CHOOSER_PENDULUM_H

#include "mech/ode/chooser.h"
#include "mech/frames/pendulum.h"

struct mech_pendulum_profile {
    double period;        /* the swing period P, s (> 0, finite) */
    double swings;        /* the run, in swings (>= 0, finite) */
    double amplitude;     /* release angle alpha, rad, [0, pi/2] */
    double turn_angle;    /* W t_end, rad, >= 0 (0: no rotation, the period alone) */
    int error_estimate;   /* 1: the half-steps second run is counted in the cost */
};

/* The error model above for `method` at n steps per swing (n >= 1). */
double mech_pendulum_predict_error(const struct mech_pendulum_profile *s,
                                   enum mech_pendulum_method method, double n);

/* Fill *out (cls MECH_SCENE_CONSTRAINED_PENDULUM, span = swings) with the
 * two candidates at `target` (relative, [1e-15, 0.1]) and choose the
 * cheapest predicted to meet target / 10; none: the most accurate (at most
 * 100000 steps per swing), out->beyond = 2 (1 near the floor), as
 * mech_choose. The chosen method and its steps per swing (an integer in
 * [8, 100000]) go to *method and *steps_per_swing; each candidate's
 * opt.dt = P / n. Statuses: MECH_OK, MECH_EINVAL (NULL argument, target or
 * profile out of range). */
enum mech_status mech_choose_pendulum(const struct mech_pendulum_profile *s, double target,
                                      struct mech_selection *out,
                                      enum mech_pendulum_method *method,
                                      double *steps_per_swing, struct mech_error *err);

#endif
