/* mech/ode/kepler.h — two-body Kepler motion about a fixed centre,
 * r'' = -gm r / |r|^3, by universal variables: a bracketed propagator for
 * any conic and any time, and the fast per-step drift of a splitting method.
 *
 * Units: any consistent set (SI: m, s, m^3/s^2). Pure, reentrant, no
 * allocation.
 */
#ifndef MECH_KEPLER_H
#define MECH_KEPLER_H

#include "mech/base/status.h"
#include "mech/base/vec.h"

/* Propagate a Kepler orbit about a fixed centre (at the origin of r0) by t
 * seconds: r'' = -gm r / |r|^3. Universal-variable formulation with
 * Stiefel–Scheifele G-functions (Danby, Fundamentals of Celestial Mechanics,
 * 2nd ed., §6.9; Vallado, Fundamentals of Astrodynamics and Applications,
 * 4th ed., Algorithm 8 "KEPLER"), valid for elliptic, parabolic and
 * hyperbolic orbits alike. The universal Kepler equation
 *   t = r0 G1(s) + (r0.v0) G2(s) + gm G3(s)
 * is solved for s by Newton's method safeguarded by bisection on a bracket
 * (its derivative is r(s) > 0, so it is monotonic), to round-off. Bound
 * orbits are first reduced by whole periods (fmod, exact), so 1e5 orbits cost
 * the same as one; the reduction's error is that of the period computed from
 * the initial state (~n eps for n orbits; beta = 2 gm/r0 - v0^2 is formed in
 * double-double, so near e = 1 its cancellation costs no digits).
 * gm > 0 finite; r0 != 0 finite; v0 finite; t finite (either sign).
 * Statuses: MECH_OK; MECH_EINVAL (bad arguments); MECH_ENUMERIC (a radial
 * orbit through the centre before t, or a non-finite result). */
enum mech_status mech_kepler_propagate(double gm, struct mech_vec3 r0, struct mech_vec3 v0,
                                       double t, struct mech_vec3 *r, struct mech_vec3 *v,
                                       struct mech_error *err);

/* The same, and *residual (may be NULL) = |F(s)| / (|r0 G1| + |r0.v0 G2| +
 * |gm G3| + |t'|): the relative residual of the universal Kepler equation at
 * the solution s (t' the time after the reduction by whole periods), the
 * evidence that the equation was solved to round-off. */
enum mech_status mech_kepler_propagate_residual(double gm, struct mech_vec3 r0,
                                                struct mech_vec3 v0, double t,
                                                struct mech_vec3 *r, struct mech_vec3 *v,
                                                double *residual, struct mech_error *err);

/* Kepler drift for splitting methods (core/ode/integrators/wisdom_holman.c): the
 * same motion as mech_kepler_propagate (centre at the origin of r0; r0, v0,
 * r, v are 3-arrays; r, v may not alias r0, v0 partially but may be the same
 * arrays), built for one call per step of a small fraction of an orbit:
 * Stumpff c2, c3 by series (Horner), a second-order series first guess of
 * the universal anomaly s ~ dt/r0 - (r0.v0) dt^2/(2 r0^3), Halley's method
 * until a correction is below 1e-7 |s| (the next would be below round-off),
 * at most 12 evaluations (3 for a step of 1/100 orbit). A step that does not
 * settle (a long step, a near-radial pericentre passage) is handed to
 * mech_kepler_propagate's bracketed solver, so any dt, any conic gets the
 * round-off answer or a status, never an unconverged one. A radial orbit
 * (no angular momentum) that reaches the centre within dt is MECH_ENUMERIC
 * (not continued as the universal variables' reflection). The result
 * depends on (gm, r0, v0, dt) only. *newton_iterations (may be NULL) gets
 * the evaluations used (bookkeeping for tests and benches).
 * Statuses: MECH_OK; those of mech_kepler_propagate (MECH_EINVAL bad
 * arguments, MECH_ENUMERIC radial orbit through the centre / non-finite). */
enum mech_status mech_kepler_drift(double gm, const double r0[3], const double v0[3], double dt,
                                   double r[3], double v[3], int *newton_iterations,
                                   struct mech_error *err);

#endif
