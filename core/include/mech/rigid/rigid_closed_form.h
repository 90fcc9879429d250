/* mech/rigid/rigid_closed_form.h — the torque-free rigid body answered from its
 * exact solution (Jacobi elliptic functions) instead of an
 * integrator, with the same result as mech_rigid_rotate (mech/rigid/rigid_rotation.h).
 * The trajectories' closed forms are mech/frames/closed_form.h's.
 *
 * Units: SI. Thread-safety: reentrant, no globals, no allocation.
 */
#ifndef MECH_RIGID_CLOSED_FORM_H
#define MECH_RIGID_CLOSED_FORM_H

#include "mech/base/budget.h"
#include "mech/rigid/rigid_rotation.h"
#include "mech/base/status.h"

/* ---- the torque-free rigid body --------------------------------------------- */

struct mech_rigid_closed_form_evidence {
    const char *solution;       /* "steady", "symmetric", "elliptic" (static) */
    double max_invariant_drift; /* max of the drifts of T, |L| and the L vector in space
                                   over the samples (all conserved) */
    double error_bound;         /* max(drift, 4 eps) */
    int evaluations;            /* evaluations of omega(t) (samples and quadrature nodes) */
};

/* Whether p (torque-free, valid moments and omega) has the closed form below:
 * not on the separatrix (L^2 = 2 E I2 of an asymmetric body). */
int mech_rigid_has_closed_form(const struct mech_rigid_problem *p);

/* The torque-free body from its exact solution, with the same result
 * contract as mech_rigid_rotate (samples t_i = t_end i/(samples-1) of omega
 * (body), the passive quaternion (continuous in sign from q0/|q0|), L in space
 * axes, T; drifts; exact (the solution used); max_omega_error 0 (omega IS the
 * exact solution); flips and measured_period from the samples; stats all 0;
 * p->method and p->opt ignored).
 * Attitude (Landau & Lifshitz §37): L is fixed in space; in the frame with z
 * along L the body's passive ZXZ Euler angles are cos theta = J_c w_c/|L|,
 * tan psi = J_a w_a/(J_b w_b) and phi' = |L| (J_a w_a^2 + J_b w_b^2) /
 * (J_a^2 w_a^2 + J_b^2 w_b^2) for a cyclic relabelling (a, b, c) of the sorted
 * axes with c the dn axis (elliptic: the largest-moment axis when
 * L^2 > 2 E I2, the smallest when L^2 < 2 E I2 — both modes) or the symmetry
 * axis (symmetric top: phi' = |L|/J_a, regular precession); phi by adaptive
 * 16-point Gauss–Legendre quadrature over one period of phi' (2K/lambda),
 * reused for whole periods, plus the remainder, pieces accepted when their
 * halves agree to 1e-15. Steady rotations (a sphere, omega = 0, omega along a
 * principal axis): the rotation about the constant omega by |omega| t.
 * Cost: per sample one omega evaluation and at most one sixteenth of a
 * period's quadrature (the integral is tabulated at 16 points of the period
 * once), independent of t_end: ~50 evaluations of omega per sample.
 * Statuses: MECH_OK; MECH_EDOMAIN / MECH_EINVAL with param ("moments",
 * "omega", "orientation", "t_end", "samples"); MECH_EINVAL "torque/value" for a
 * non-zero torque (no closed form); MECH_EDOMAIN "omega" on the separatrix
 * (use an integrator); MECH_ENUMERIC (GSL's elliptic functions failed);
 * MECH_EDEADLINE / MECH_ECANCELLED from budget (may be NULL: tests and
 * benches), checked between samples for its deadline and cancel flag only
 * (up to 100,000 samples cost ~0.7 s).
 * evidence may be NULL. */
/* The closed form's cost model for the chooser (mech/ode/chooser.h,
 * closed_form_evaluations): the predicted number of omega(t) evaluations
 * mech_rigid_closed_form will count for p, from the same plan the run
 * follows, without evaluating anything: steady rotations one per sample;
 * a symmetric body one per sample plus one; an asymmetric body one per
 * sample plus the quadrature of phi' (16 pieces of a period tabulated once,
 * then per sample the pieces of T/16 between it and the previous sample in
 * the same period, or one piece from the table), each piece costing
 * RCF_EVALS_PER_PIECE = 48 evaluations (a 16-point rule and its two halves).
 * Exact away from the separatrix; near it (m > 0.99) a few pieces take a
 * halving (64 more each, not predicted): within 1.11x on 1:2:3 bodies with
 * m = 0.995 and 0.999998 (tests/core/rigid/test_rigid_closed_form.c; stated
 * factor 1.5).
 * Returns > 0, or -1 when p has no closed form (torque, separatrix,
 * invalid input). Reentrant; microseconds. */
double mech_rigid_closed_form_predict_evaluations(const struct mech_rigid_problem *p);

/* Measured CPU seconds of one counted evaluation of the closed form (omega
 * by Jacobi elliptic functions, the quadrature's phi', the attitude per
 * sample): 1.1e-7 s on the build machine (rigid/rotate 1:2:3, 11 .. 1001
 * samples, 1 .. 1e4 s, 2026-11-27: 1.1 .. 1.4e-7 beside the request's fixed
 * cost). */
#define MECH_RIGID_CLOSED_FORM_CPU_PER_EVAL 1.1e-7

enum mech_status mech_rigid_closed_form(const struct mech_rigid_problem *p,
                                        struct mech_rigid_result *res,
                                        struct mech_rigid_closed_form_evidence *evidence,
                                        const struct mech_budget *budget,
                                        struct mech_error *err);

#endif
