/* mech/rigid/top.h — the heavy symmetric top with a fixed tip (notes §2.10,
 * "Lagrange Equations for Top with One Fixed Point").
 *
 * Moments about the tip: I1 (= I2, perpendicular to the symmetry axis) and I3;
 * mass M, tip-to-centre-of-mass distance h, gravity g along -z of space.
 * z-x-z Euler angles (phi, theta, psi) as in the notes: theta is the tilt of
 * the symmetry axis (body z) from space z, phi the azimuth of the line of
 * nodes, psi the spin angle; R = R_psi R_theta R_phi (passive).
 *
 * The notes' Lagrangian L = 1/2 I1 (phi'^2 sin^2 theta + theta'^2)
 * + 1/2 I3 (phi' cos theta + psi')^2 - M g h cos theta has the conserved
 *   p_phi = (I1 sin^2 theta + I3 cos^2 theta) phi' + I3 cos theta psi'
 *         (= L . z_space, the angular momentum about the vertical),
 *   p_psi = I3 (psi' + phi' cos theta) = I3 w3,
 *   E = 1/2 I1 (theta'^2 + phi'^2 sin^2 theta) + 1/2 I3 w3^2 + M g h cos theta.
 * The Euler-angle equations are singular at theta = 0 (a sleeping top), so the
 * motion is integrated as a rigid body instead: Euler's equations about the
 * tip with the gravity torque G = -M g h e3 x z_body (z_body = space z in body
 * axes) and the quaternion attitude of mech/rotation/attitude.h; Euler angles are
 * extracted per sample. Nothing is singular at theta = 0.
 *
 * Turning points (derived from E and the two momenta with u = cos theta):
 *   u'^2 = f(u) = (1 - u^2)(alpha - beta u) - (b - a u)^2,
 *   alpha = 2 E' / I1, E' = E - p_psi^2 / (2 I3), beta = 2 M g h / I1,
 *   a = p_psi / I1, b = p_phi / I1,
 * a cubic beta u^3 - (alpha + a^2) u^2 + (2ab - beta) u + (alpha - b^2); theta
 * nutates between the roots u1 <= cos theta0 <= u2 next to cos theta0. It is
 * solved in x = 1 - sigma u (sigma = sign of cos theta0: the distance from the
 * nearer pole), with coefficients formed without cancellation, so turning
 * points near theta = 0 or pi keep their relative precision (in u they would
 * lose ~sqrt(eps): measured 1e-4 relative for a sleeping top at 1e-3 rad).
 * Sleeping top (theta = 0, notes §2.11 problem 11): stable when
 * I3^2 w3^2 > 4 I1 M g h.
 * Steady precession at theta0 (theta'' = 0 in the theta equation):
 * I1 cos theta phi'^2 - I3 w3 phi' + M g h = 0; the slow root tends to the
 * gyroscopic approximation M g h / (I3 w3) for a fast spin.
 *
 * Units SI. Thread-safety: reentrant; nothing global.
 */
#ifndef MECH_TOP_H
#define MECH_TOP_H

#include <stddef.h>

#include "mech/base/budget.h"
#include "mech/ode/ode.h"
#include "mech/base/status.h"
#include "mech/base/vec.h"

struct mech_top_problem {
    double I1, I3;          /* kg m^2 about the tip, > 0; physical: I3 <= 2 I1, I1 >= M h^2 */
    double mass, distance;  /* kg > 0; m >= 0 (tip to centre of mass) */
    double g;               /* m/s^2, >= 0 */
    double phi, theta, psi; /* initial Euler angles, rad (theta may be 0 or pi) */
    double phi_dot, theta_dot, psi_dot; /* rad/s */
    double t_end;           /* s, > 0 */
    size_t samples;         /* 2..100000 */
    const char *method;     /* a first-order method of mech_ode_method_find() */
    struct mech_ode_options opt; /* rtol/atol on the dimensionless state, dt in s */
};

struct mech_top_turning {
    int steady;             /* 1: theta_min = theta_max (a double root: no nutation) */
    double u_min, u_max;    /* turning points in u = cos theta (u_min <= cos theta0 <= u_max) */
    double theta_min, theta_max; /* acos(u_max), acos(u_min) */
    double roots[3];        /* real roots of f found (polished), ascending */
    int n_roots;
    /* The motion in x = 1 - sigma u (sigma = sign of cos theta0; x is the
     * distance of u from the nearer pole, 1 - u^2 = x (2 - x)):
     * x'^2 = cubic[3] x^3 + cubic[2] x^2 + cubic[1] x + cubic[0] (1/s^2), x in
     * [x_lo, x_hi], and phi' = (phi_d + phi_c x) / (x (2 - x)) (rad/s). */
    double sigma, x_lo, x_hi, cubic[4], phi_d, phi_c;
    /* One full nutation, x_lo -> x_hi -> x_lo (s): 4 K(k) / sqrt(|c3| d) with d the
     * distance of the cubic's third root from the far end of [x_lo, x_hi] and
     * k^2 = (x_hi - x_lo)/d; 2 pi / sqrt(-c2) without a gravity torque (the free
     * symmetric top). For a steady precession (x_lo = x_hi) the limit: the
     * period of a small nutation about it. NaN on a degenerate cubic. */
    double nutation_period;
    /* phi' averaged over one nutation, (phi advance per nutation) / period
     * (rad/s): complete elliptic integrals of the third kind (GSL's Carlson
     * forms); for a steady precession the steady rate. NaN as the period. */
    double precession_mean;
};

struct mech_top_result {
    /* Caller-owned buffers of `samples` entries; any may be NULL. */
    double *t, *theta, *phi, *psi, *phi_plus_psi; /* phi, psi unwrapped continuously
                               (followed through every step, not just the samples) */
    struct mech_vec3 *axis; /* symmetry axis in space axes */
    int *at_pole;           /* 1 where theta = 0 or pi exactly (only phi +- psi is determined) */
    /* Filled by the call. */
    size_t n_samples;
    struct mech_ode_stats stats;
    double rate_scale;
    double omega3;                         /* spin w3 = phi' cos theta + psi' (conserved) */
    double p_phi0, p_psi0, E0;             /* at t = 0 */
    double p_phi_final, p_psi_final, E_final;
    double max_p_phi_drift, max_p_psi_drift, max_E_drift; /* relative to the scales below */
    double L_scale, E_scale;               /* |L0| (or I1 W) and T0 + M g h */
    double theta_min_measured, theta_max_measured; /* over every step end and sample */
    double max_quaternion_norm_drift;
    struct mech_top_turning turning;
    /* sleeping top: I3^2 w3^2 vs 4 I1 M g h */
    double sleep_lhs, sleep_rhs, critical_omega3;
    int sleep_stable;
    /* steady precession at theta0: rates (NaN when there is none) */
    double precession_slow, precession_fast, precession_gyroscopic;
    double precession_measured;            /* (phi_end - phi_0) / t_end from the unwrapped phi */
};

/* Turning points of the nutation from the initial state (see above): roots of
 * f (in x) with gsl_poly_solve_cubic (gsl_poly_solve_quadratic when g = 0 or
 * M h = 0), each polished by Newton's method; when theta0' sin theta0 = 0
 * the known root cos theta0 is divided out first so the other turning point
 * comes from a quadratic (no ill-conditioned triple solve).
 * Statuses: MECH_OK; MECH_EINVAL / MECH_EDOMAIN as mech_top_integrate. */
enum mech_status mech_top_turning_points(const struct mech_top_problem *p,
                                         struct mech_top_turning *out, struct mech_error *err);

/* The nutation period and the precession averaged over a nutation of a
 * turning-point record already filled by mech_top_turning_points (which calls
 * this): sets t->nutation_period and t->precession_mean from x_lo, x_hi,
 * cubic, phi_d, phi_c (see struct mech_top_turning). The cubic's third root
 * comes from Vieta's product (no cancellation) when x_lo x_hi phi_d != 0,
 * else from the sum. Pure, cannot fail: NaN where the integrals are not
 * defined. */
void mech_top_nutation(struct mech_top_turning *t);

/* The closed forms of the initial state, no run: fills res->sleep_lhs
 * (I3^2 w3^2, kg^2 m^4 / s^2), sleep_rhs (4 I1 M g h, same unit),
 * sleep_stable (lhs > rhs), critical_omega3 (2 sqrt(I1 M g h) / I3, rad/s),
 * precession_gyroscopic (M g h / (I3 w3), rad/s; NaN at w3 = 0) and the
 * steady-precession rates at theta0 (rad/s), the roots of
 * I1 cos(theta0) x^2 - I3 w3 x + M g h = 0: with B = I3 w3 and
 * q = (B + sgn(B) sqrt(B^2 - 4 I1 cos(theta0) M g h)) / 2 (no cancellation)
 * they are q / (I1 cos theta0) and M g h / q (Vieta's product), so the slow
 * one keeps its digits at a fast spin where (B - sqrt(...)) / 2 would not;
 * precession_slow is the root of smaller |x|, precession_fast the other.
 * Both NaN when the discriminant is negative (no steady precession at this
 * spin) or q = 0; where |cos theta0| < 1e-300 the equation is linear: slow =
 * M g h / (I3 w3), fast NaN. w3 = phi' cos theta0 + psi'. Nothing else of
 * *res is touched. p as mech_top_integrate accepts it (not checked here);
 * pure, cannot fail; mech_top_integrate calls it. */
void mech_top_closed_forms(const struct mech_top_problem *p, struct mech_top_result *res);

/* Integrate the top from t = 0 to t_end. Statuses: MECH_OK; MECH_EDOMAIN with
 * param "I1", "I3", "mass", "distance", "g" (non-positive or unphysical:
 * I3 > 2 I1 or I1 < M h^2, 1e-12 slack); MECH_EINVAL with param "theta", ...,
 * "t_end", "samples", "integrator/method" (second-order-only methods);
 * MECH_EBUDGET / MECH_EDEADLINE / MECH_ECANCELLED (progress in s);
 * MECH_ENUMERIC; MECH_ENOMEM. */
enum mech_status mech_top_integrate(const struct mech_top_problem *p,
                                    const struct mech_budget *budget,
                                    struct mech_top_result *res, struct mech_error *err);

/* The rate scale W (1/s): max(|w0|, sqrt(M g h / I1)), or 1 / t_end if both are 0. */
double mech_top_rate_scale(const struct mech_top_problem *p);

/* The chooser's cost hook (mech/ode/chooser.h, cost_span): the run in the cost
 * law's units, t_end x (w_perp,max + |w3| / 2) where w_perp,max is the
 * largest body rate about a transverse axis the energy allows (w_perp^2 =
 * w_perp0^2 + 2 M g h (cos theta0 - u_min) / I1, u_min the lower turning
 * point of cos theta, -1 when unknown) and |w3| / 2 the rate at which the
 * spin turns the attitude quaternion. Measured (2026-11-27, rk8pd and rkf45,
 * rtol 1e-7 .. 1e-13, 0.5 .. 50 s, spins 0 .. 100 rad/s, I3/I1 0.1 .. 1.9):
 * the first-order class's cost law with this span counts the evaluations
 * within 1.5x, where t_end x W (the error law's span) over-predicted a fast
 * top 1.7 .. 2.4x and under-predicted a falling one 2x. 0 if p is invalid. */
double mech_top_cost_span(const struct mech_top_problem *p);

/* The chooser's pilot hook (mech/ode/chooser_pilot.h, struct mech_pilot_system's
 * run with ctx = a const struct mech_top_problem *): the top over the first
 * fraction of t_end with method and opt, two samples; y_end = (theta, phi,
 * psi) at the end (rad), *dim = 3. Statuses as mech_top_integrate. */
enum mech_status mech_top_pilot_run(void *ctx, const char *method,
                                    const struct mech_ode_options *opt, double fraction,
                                    const struct mech_budget *budget,
                                    struct mech_ode_stats *stats, double *y_end, size_t *dim,
                                    struct mech_error *err);

#endif
