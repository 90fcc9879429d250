/* mech/frames/closed_form.h — trajectories answered from their exact solution
 * instead of an integrator (the closed form, when the scene has
 * one and the user asked by accuracy): Kepler two-body motion (universal
 * variables, any eccentricity, radial orbits included), the isotropic
 * harmonic oscillator (with uniform gravity), uniform gravity with or
 * without linear drag, the free particle — the scenes for which
 * mech_trajectory_reference_find() gives MECH_REFERENCE_EXACT.
 *
 * The cost grows with the samples, not with the simulated time: each sample
 * is one evaluation of the solution (Kepler: one solve of the universal
 * Kepler equation, after reducing the time by whole periods).
 *
 * Units: SI. Thread-safety: reentrant, no globals, no allocation.
 */
#ifndef MECH_CLOSED_FORM_H
#define MECH_CLOSED_FORM_H

#include "mech/rigid/rigid_closed_form.h"
#include "mech/base/status.h"
#include "mech/base/budget.h"
#include "mech/frames/trajectory.h"

/* The closed form's own error evidence (it has no integration error; what
 * remains is the round-off of the evaluation). */
struct mech_closed_form_evidence {
    const char *solution;        /* "kepler", "harmonic_oscillator", "uniform_gravity",
                                    "uniform_gravity_linear_drag" (static) */
    double max_invariant_drift;  /* max over the conserved invariants of their
                                    max_relative_drift over the samples (0 if none is
                                    conserved, e.g. with drag) */
    double max_kepler_residual;  /* Kepler: max relative residual of the universal Kepler
                                    equation over the samples (mech_kepler_propagate_residual);
                                    0 otherwise */
    double error_bound;          /* the relative error stated for the answer:
                                    max(drift, residual, 4 eps) */
    int evaluations;             /* evaluations of the solution (samples + event search) */
};

/* Whether p has a closed form served here (mech_trajectory_reference_find()
 * is MECH_REFERENCE_EXACT). p must be valid (mech_trajectory_check). */
int mech_trajectory_has_closed_form(const struct mech_trajectory_problem *p);

/* Evaluate the exact solution of p at its samples (t_i = t_end i/(samples-1),
 * as mech_trajectory_integrate places them), with the same result contract as
 * mech_trajectory_integrate: samples written to the caller's buffers
 * (res->t, position, velocity, each may be NULL), the stop event if p has
 * one, terms (max |a| of each force over the samples and the stop point),
 * max_radius / max_speed, invariants (energy or Jacobi integral; angular
 * momentum about the centre of a central scene) evaluated at the samples,
 * res->reference (kind exact, name, errors 0: the samples ARE the reference),
 * res->method = "closed_form", res->stats all 0 (nothing is integrated),
 * res->dimensions = 3, no error_estimate. p->method, p->opt, p->error_estimate
 * and p->reduce_planar are ignored.
 *
 * Stop event: the first time the coordinate stop_axis crosses stop_value in
 * stop_direction (crossing as the integrator defines it: from a strictly
 * positive to a non-positive value of r[axis] - value for "decreasing", and so
 * on; a start exactly on the value is no crossing). The run is cut into
 * pieces on which the coordinate is monotonic (a grid of 16 per period —
 * in the eccentric anomaly for Kepler ellipses, in t for the oscillator — and
 * the zeros of the velocity component found by bisection), the crossing is
 * bracketed on them and located by bisection with secant steps (Illinois) to
 * round-off on the closed form. Periodic motions are scanned over one period
 * at most (a crossing that never happens in one period never happens).
 *
 * Radial Kepler orbits (r0 x v0 = 0) that reach the centre before t_end (and
 * before the stop event): MECH_ENUMERIC naming the time, as the integrator.
 *
 * evidence (may be NULL) receives the answer's error evidence. budget (may
 * be NULL: tests and benches; the cost is then bounded by p->samples alone)
 * is checked for its deadline and cancel flag between samples (its step
 * limit does not apply: nothing is integrated).
 * Statuses: MECH_OK; those of mech_trajectory_check (with err->param);
 * MECH_EDEADLINE / MECH_ECANCELLED (progress.t_reached: the last sample);
 * MECH_EINVAL (p has no closed form: not an exact-reference scene; NULL
 * arguments); MECH_ENUMERIC (radial orbit through the centre; a non-finite
 * value). On failure res->n_samples says how many samples were written. */
enum mech_status mech_trajectory_closed_form_ex(const struct mech_trajectory_problem *p,
                                                struct mech_trajectory_result *res,
                                                struct mech_closed_form_evidence *evidence,
                                                const struct mech_budget *budget,
                                                struct mech_error *err);

/* mech_trajectory_closed_form_ex without the evidence or a budget. */
enum mech_status mech_trajectory_closed_form(const struct mech_trajectory_problem *p,
                                             struct mech_trajectory_result *res,
                                             struct mech_error *err);

/* The torque-free rigid body's closed form (mech_rigid_closed_form) is
 * declared in mech/rigid/rigid_closed_form.h, included above. */

#endif
