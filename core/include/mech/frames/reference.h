/* mech/frames/reference.h — exact and first-order solutions used as references for
 * the error of numerical trajectories (every numeric answer says how good it is).
 *
 *   Kepler two-body motion (universal variables, any conic),
 *   the isotropic harmonic oscillator (spring of rest length 0) with uniform
 *   gravity, uniform gravity with linear drag, and the notes' first-order
 *   Coriolis solution near the Earth / in a rotating frame.
 *
 * mech_trajectory_reference_find() recognises which of these a trajectory
 * scene is; mech_trajectory_reference_eval() evaluates it at a time.
 *
 * Units: SI. Thread-safety: reentrant, no globals, no allocation.
 */
#ifndef MECH_REFERENCE_H
#define MECH_REFERENCE_H

#include "mech/relativity/charged_motion.h"
#include "mech/ode/kepler.h"
#include "mech/base/status.h"
#include "mech/frames/trajectory_problem.h"
#include "mech/base/vec.h"

/* Kepler motion (mech_kepler_propagate, mech_kepler_propagate_residual,
 * mech_kepler_drift) is declared in mech/ode/kepler.h, included above. */

/* Isotropic harmonic oscillator about `anchor` with uniform acceleration g:
 * r'' = -omega^2 (r - anchor) + g, omega >= 0 (omega = 0: free fall). Exact:
 *   r - a = (r0 - a) cos wt + v0 sin(wt)/w + g (1 - cos wt)/w^2,
 * with sin(wt)/w = t sinc(wt) and (1 - cos wt)/w^2 = (t^2/2) sinc^2(wt/2), so
 * no cancellation for small w t. Cannot fail. */
void mech_harmonic_propagate(double omega, struct mech_vec3 anchor, struct mech_vec3 g,
                             struct mech_vec3 r0, struct mech_vec3 v0, double t,
                             struct mech_vec3 *r, struct mech_vec3 *v);

/* omega = sqrt(k/m) as a double-double: omega + omega_lo to ~1e-32 relative
 * (k > 0, m > 0 finite). Cannot fail. */
void mech_harmonic_omega_dd(double k, double m, double *omega, double *omega_lo);

/* mech_harmonic_propagate with omega given as omega + omega_lo (a double-
 * double, mech_harmonic_omega_dd): the phase omega t is carried with its
 * rounding error (fma) and omega_lo t, so after n periods the phase error is
 * ~eps, not ~n eps (1e4 periods: 1e-16 instead of 1e-11 relative). */
void mech_harmonic_propagate_dd(double omega, double omega_lo, struct mech_vec3 anchor,
                                struct mech_vec3 g, struct mech_vec3 r0, struct mech_vec3 v0,
                                double t, struct mech_vec3 *r, struct mech_vec3 *v);

/* Uniform gravity g with linear drag F = -b v (gamma = b/m >= 0), exact:
 *   v = v0 e^{-x} + g t E1(x),  r = r0 + v0 t E1(x) + g t^2 E2(x),  x = gamma t,
 * E1(x) = (1 - e^{-x})/x = -expm1(-x)/x, E2(x) = (x - 1 + e^{-x})/x^2 (a series
 * for x < 1, so no cancellation); gamma = 0 gives r0 + v0 t + g t^2/2. This is
 * the closed form r0 + (m/b)(v0 - v_term)(1 - e^{-bt/m}) + v_term t, v_term = m g/b,
 * rearranged so that neither large nor small b t/m cancels. Cannot fail. */
void mech_uniform_drag_propagate(struct mech_vec3 g, double gamma, struct mech_vec3 r0,
                                 struct mech_vec3 v0, double t, struct mech_vec3 *r,
                                 struct mech_vec3 *v);

/* First-order Coriolis solution of r'' = g - 2 w x r' (notes §1.3–1.4,
 * "Deflection of a Falling Object", "Deflection of Cannon Balls"): expanding
 * in w, r = r_0(t) + r_1(t) + O(w^2) with r_0 = r0 + v0 t + g t^2/2 and
 * r_1'' = -2 w x r_0' = -2 w x (v0 + g t), so
 *   r(t) = r0 + v0 t + g t^2/2 - w x (v0 t^2 + g t^3/3),
 *   v(t) = v0 + g t - w x (2 v0 t + g t^2).
 * For a drop from rest (v0 = 0, g = -g z, w = W (0, cos lat, sin lat)) this is
 * x_east = W g cos(lat) t^3 / 3, the notes' result. The neglected second-order
 * terms are 2 w x (w x (v0 t^3/3 + g t^4/12)) from Coriolis and, when the
 * centrifugal term of the displacement is modelled,
 * -w x (w x (r0 t^2/2 + v0 t^3/6 + g t^4/24)); *second_order (may be NULL)
 * receives their sum (its norm is the reference's own error estimate).
 * Cannot fail. */
void mech_coriolis_first_order(struct mech_vec3 w, struct mech_vec3 g, int centrifugal,
                               struct mech_vec3 r0, struct mech_vec3 v0, double t,
                               struct mech_vec3 *r, struct mech_vec3 *v,
                               struct mech_vec3 *second_order);

enum mech_reference_kind {
    MECH_REFERENCE_NONE = 0,
    MECH_REFERENCE_EXACT,       /* exact to round-off */
    MECH_REFERENCE_FIRST_ORDER, /* first order in the frame rotation rate */
};

/* A recognised reference solution of a trajectory scene. */
struct mech_trajectory_reference {
    enum mech_reference_kind kind;
    const char *name; /* "kepler", "harmonic_oscillator", "uniform_gravity",
                         "uniform_gravity_linear_drag", "coriolis_first_order" (static) */
    /* parameters (internal) */
    double gm, omega, omega_lo, gamma; /* omega + omega_lo: double-double */
    struct mech_vec3 center, g, w;
    int centrifugal;
    struct mech_vec3 r0, v0;
    struct mech_charged_motion charged; /* "relativistic_uniform_fields" */
    /* exact references seen from a frame turning at the constant rate
     * `spin` (rad/s, frame axes; 0: none): the inertial solution through the
     * inertial initial state (r0, v0 + spin x r0), turned back by spin t.
     * No closed form answers such a scene (mech_trajectory_has_closed_form
     * is 0): it is a reference for the error evidence only. */
    struct mech_vec3 spin;
    int rotated;
    /* 1: a reference for the error evidence only, never a closed-form answer
     * ("uniform_fields_newtonian": g holds q E / m + g, w holds q B / m) */
    int evidence_only;
};

/* Which reference, if any, the scene p has (fills ref; ref->kind NONE if
 * none). Recognised (forces with no effect — g = 0, k = 0, b = 0 — are
 * ignored):
 *   exact "kepler": inertial frame, exactly one central_gravity, nothing else;
 *   exact "harmonic_oscillator": inertial, one spring with rest_length 0,
 *     optionally uniform gravity;
 *   exact "uniform_gravity" / "uniform_gravity_linear_drag": inertial (or a
 *     frame whose fictitious terms are all absent or zero), only uniform
 *     gravity and linear drag (no forces at all is the free particle);
 *   the same three exact ones seen from a rotating frame (type rotating,
 *     constant omega, Coriolis and centrifugal both modelled, no Euler or
 *     translational term acting): when every force is the same in the
 *     inertial frame — central_gravity's centre and a spring's anchor on the
 *     rotation axis, uniform gravity along it, no drag — the inertial motion
 *     turned back by omega t (ref->rotated = 1; names "kepler_rotating",
 *     "harmonic_oscillator_rotating", "uniform_gravity_rotating");
 *   first-order "coriolis_first_order": rotating or earth frame with
 *     Coriolis modelled, only uniform gravity (centrifugal modelled or not).
 * With a relativistic term modelled (p->relativity) none of these: only
 *   exact "relativistic_uniform_fields": special relativity in an inertial
 *   frame, only Lorentz forces and uniform gravity (a constant force m g),
 *   not null fields (mech/relativity/charged_motion.h).
 * A modelled translational term -A joins g (a uniform field). A rotation
 * that changes with time (omega_dot != 0 with a rotation term modelled), a
 * lorentz force beside a central body, spring or drag, or a third-body tide:
 * no reference.
 * p must be valid (as mech_trajectory_integrate checks). Cannot fail. */
enum mech_reference_kind mech_trajectory_reference_find(const struct mech_trajectory_problem *p,
                                                        struct mech_trajectory_reference *ref);

/* Evaluate the reference at time t (s); *second_order (may be NULL) gets the
 * size of the neglected second-order terms (0 for exact references).
 * Statuses: MECH_OK, MECH_EINVAL (kind NONE), those of mech_kepler_propagate. */
enum mech_status mech_trajectory_reference_eval(const struct mech_trajectory_reference *ref,
                                                double t, struct mech_vec3 *r,
                                                struct mech_vec3 *v, double *second_order,
                                                struct mech_error *err);

#endif
