/* mech/gr/geodesic.h — equatorial geodesics of the Schwarzschild metric: massive
 * particles (timelike, proper time tau) and light (null, affine parameter
 * lambda), with the exact references of the course: the periapsis advance
 * of a bound orbit and the deflection of light, both as elliptic integrals
 * and, independently, as quadratures.
 *
 * Units: geometric, G = c = 1, M = 1 (radii in GM/c^2, times in GM/c^3,
 * specific angular momentum in GM/c, specific energy E/(m c^2)). For light
 * the affine parameter is normalised so that E = 1: dt/dlambda = 1/(1 - 2/r),
 * so lambda -> t far away and L = b, the impact parameter.
 *
 * Equations (Hartle eqs. 9.21-9.22, 9.27-9.29; Carroll eqs. 5.58-5.62): with
 * kappa = 1 (timelike) or 0 (null) and the conserved E and L,
 *   dt/dtau = E / (1 - 2/r),  dphi/dtau = L / r^2,
 *   d^2r/dtau^2 = -kappa / r^2 + L^2 / r^3 - 3 L^2 / r^4   (= -V'(r)/2),
 * the second-order radial equation (no turning-point singularity, unlike
 * dr/dtau = +-sqrt(E^2 - V)). The first integral
 *   (dr/dtau)^2 + (1 - 2/r)(kappa + L^2/r^2) - E^2 = (1 - 2/r)(g(u,u) + kappa)
 * is the constraint g(u, u) = -kappa; its drift is measured at every step and
 * the run stops with MECH_ENUMERIC when it passes the requested bound.
 *
 * Internally the state is scaled to O(1) numbers: rho = r / r0, and
 * s = tau / r0^(3/2) (timelike; the Newtonian dynamical time) or
 * s = lambda / r0 (null); (rho, drho/ds, phi, t / T) with T the time unit.
 *
 * Thread-safety: reentrant; nothing global is written.
 */
#ifndef MECH_GEODESIC_H
#define MECH_GEODESIC_H

#include <stddef.h>

#include "mech/base/budget.h"
#include "mech/ode/ode.h"
#include "mech/base/status.h"

enum mech_geodesic_kind { MECH_GEODESIC_TIMELIKE = 0, MECH_GEODESIC_NULL = 1 };

/* Capture: the run stops when r falls to 2 (1 + MECH_GEODESIC_CAPTURE_MARGIN). */
#define MECH_GEODESIC_CAPTURE_MARGIN 1e-6

/* Initial state and conserved quantities (geometric units). Build it with one
 * of the mech_geodesic_init_* functions, which form E^2 - 1 without
 * cancellation and check that motion is possible. */
struct mech_geodesic_init {
    enum mech_geodesic_kind kind;
    double r0;    /* > 2 (1 + capture margin) */
    double phi0;  /* rad */
    double E;     /* timelike: E/(m c^2) > 0; null: 1 */
    double E2m1;  /* timelike: E^2 - 1, formed without cancellation; null: 0 */
    double L;     /* timelike: L/m (GM/c); null: b (GM/c^2); signed (sign of dphi) */
    double rdot0; /* dr/dtau (timelike) or dr/dlambda (null) at r0 */
};

/* From E, L and the sign of dr/dtau (dir = -1 inward, +1 outward): timelike
 * only. Statuses: MECH_EDOMAIN param "r0" (r0 <= capture radius), "energy"
 * (E <= 0, or E^2 < V(r0): no real motion at r0). */
enum mech_status mech_geodesic_init_energy(double r0, double phi0, double E, double L, int dir,
                                           struct mech_geodesic_init *out, struct mech_error *err);

/* From the velocity measured by a static observer at r0 (units of c):
 * radial vr (outward positive) and tangential vt (positive: phi increasing).
 * Timelike: vr^2 + vt^2 < 1 (else EDOMAIN "local_velocity"); E = gamma
 * sqrt(1 - 2/r0), L = gamma vt r0, dr/dtau = gamma vr sqrt(1 - 2/r0).
 * Null: (vr, vt) is a direction (normalised; zero is EDOMAIN); E = 1,
 * b = r0 sin(alpha) / sqrt(1 - 2/r0), dr/dlambda = cos(alpha). */
enum mech_status mech_geodesic_init_local(enum mech_geodesic_kind kind, double r0, double phi0,
                                          double vr, double vt, struct mech_geodesic_init *out,
                                          struct mech_error *err);

/* Light with impact parameter b >= 0 (dir = -1 inward, +1 outward):
 * (dr/dlambda)^2 = 1 - b^2 (1 - 2/r0) / r0^2 must be >= 0 (else EDOMAIN
 * "impact_parameter": the photon cannot be at r0 with this b). */
enum mech_status mech_geodesic_init_impact(double r0, double phi0, double b, int dir,
                                           struct mech_geodesic_init *out, struct mech_error *err);

/* A bound orbit given by its turning points r_p < r_a (r_p == r_a: circular),
 * starting at periapsis (dr/dtau = 0). With u1 = 1/r_a, u2 = 1/r_p and
 * u3 = 1/2 - u1 - u2 (the roots of (du/dphi)^2 = 2(u - u1)(u - u2)(u - u3)):
 * L^2 = 1 / (u1 u2 + u3 (u1 + u2)), E^2 - 1 = -2 u1 u2 u3 L^2.
 * Statuses: EDOMAIN "periapsis" (r_p <= capture radius, or u2 >= u3: no stable
 * bound orbit with these turning points), "apoapsis" (r_a < r_p). */
enum mech_status mech_geodesic_init_orbit(double r_p, double r_a, double phi0,
                                          struct mech_geodesic_init *out, struct mech_error *err);

/* Classification of a timelike motion from its radial polynomial. */
enum mech_geodesic_class {
    MECH_GEODESIC_BOUND = 0,   /* oscillates between r_p and r_a */
    MECH_GEODESIC_UNBOUND = 1, /* reaches infinity (possibly after one turn) */
    MECH_GEODESIC_PLUNGE = 2,  /* falls into the horizon */
    MECH_GEODESIC_CIRCULAR = 3 /* r_p == r_a within 1e-6 relative (from E, L the roots of a
                                  near-double root carry ~sqrt(eps) noise); no precession */
};

/* Turning points of a bound timelike orbit: u1 = M/r_a <= u2 = M/r_p < u3,
 * u1 + u2 + u3 = 1/2. */
struct mech_geodesic_bound {
    double u1, u2, u3;
};

/* Classify a timelike init; for bound (and circular) orbits fill *b with the
 * turning points (polished by Newton's method on the cubic; near-circular
 * orbits lose ~sqrt(eps) in u2 - u1, not in the orbit's advance). Null: EINVAL. */
enum mech_status mech_geodesic_classify(const struct mech_geodesic_init *in,
                                        enum mech_geodesic_class *cls,
                                        struct mech_geodesic_bound *b, struct mech_error *err);

/* Exact periapsis advance per radial period, Delta phi - 2 pi (rad):
 * Delta phi = 2 int_{u1}^{u2} du / sqrt(2 (u - u1)(u2 - u)(u3 - u))
 *           = 4 K(k) / sqrt(2 (u3 - u1)),  k^2 = (u2 - u1) / (u3 - u1)
 * (Byrd & Friedman 233.00; Chandrasekhar, "The Mathematical Theory of Black
 * Holes", §19 eq. 59 form). Formed as 4 (K - pi/2)/s + 2 pi (1 - s)/s with
 * s = sqrt(2 (u3 - u1)), 1 - s^2 = 4 u1 + 2 u2 and K - pi/2 by its series for
 * small k^2 (gsl_sf_ellint_Kcomp otherwise), so a 5e-7 rad advance (Mercury)
 * keeps full relative precision. */
enum mech_status mech_geodesic_precession_exact(const struct mech_geodesic_bound *b,
                                                double *advance, struct mech_error *err);

/* The same advance by an independent route: Gauss-Kronrod quadrature (GSL
 * qag, 61 points) of 2 int_0^pi [1/w - 1] dchi, w = sqrt(2 (u3 - u)), with
 * u = u1 + (u2 - u1)(1 - cos chi)/2 (removes both endpoint singularities),
 * 1/w - 1 formed as 2 (u1 + u2 + u) / (w (1 + w)). Also the radial periods:
 * T_tau = 2 int dchi / (L u^2 w), T_t = 2 int E dchi / ((1 - 2u) L u^2 w)
 * (GM/c^3); any output may be NULL. Statuses: MECH_ENUMERIC (quadrature). */
enum mech_status mech_geodesic_precession_quadrature(const struct mech_geodesic_bound *b, double E,
                                                     double L, double *advance, double *period_tau,
                                                     double *period_t, struct mech_error *err);

/* Deflection of light with impact parameter b > 3 sqrt(3) (EDOMAIN "impact_parameter"
 * otherwise: captured). With w = b u, eps = 1/b and the roots w3 < 0 < w1 < w2
 * of 1 - w^2 + 2 eps w^3 (Hartle eq. 11.14, Carroll eq. 5.104 in u):
 *   delta = 2 int_0^{w1} dw / sqrt(1 - w^2 + 2 eps w^3) - pi
 *         = 2 g F(phi, k) / sqrt(2 eps) - pi, g = 2 / sqrt(w2 - w3),
 *   k^2 = (w1 - w3)/(w2 - w3), sin^2 phi = (w2 - w3) w1 / ((w1 - w3) w2)
 * (Byrd & Friedman 233.00, gsl_sf_ellint_F). r_min = b / w1 (GM/c^2). The final
 * "- pi" cancels: relative precision ~4e-16 pi / delta (use the quadrature for weak
 * fields). */
enum mech_status mech_geodesic_deflection_exact(double b, double *delta, double *r_min,
                                                struct mech_error *err);

/* The deflection by an independent quadrature: w = w1 sin(theta),
 * delta = 2 int_0^{pi/2} (f - 1) dtheta with f - 1 formed without
 * cancellation from 1 - w^2 + 2 eps w^3 = (w1 - w) G(w),
 * G = w + w1 - 2 eps (w^2 + w w1 + w1^2) (only w1 is shared with the
 * elliptic route). Full relative precision for tiny deflections. */
enum mech_status mech_geodesic_deflection_quadrature(double b, double *delta,
                                                     struct mech_error *err);

struct mech_geodesic_problem {
    struct mech_geodesic_init init;
    double param_end;           /* tau_end (timelike) or lambda_end (null), GM/c^3 or GM/c^2, > 0 */
    double r_escape;            /* > r0: escape when r passes it moving outward */
    double constraint_bound;    /* relative drift of the constraint that stops the run, (0, 1) */
    double periapsis_lookahead; /* >= 0 (tau units): after a run that reached param_end, look
                                   this far beyond it for one more periapsis (a run of whole
                                   radial periods from periapsis ends on one); 0: none */
    size_t samples;             /* >= 2 */
    const char *method;         /* a first-order method of mech_ode_method_find() */
    struct mech_ode_options opt; /* rtol/atol on the scaled O(1) state; dt in scaled time */
};

struct mech_geodesic_result {
    /* caller-owned arrays of problem.samples, or NULL; filled up to n_samples */
    double *param; /* tau or lambda (GM/c^3 / GM/c^2) */
    double *t;     /* coordinate time (GM/c^3) */
    double *r;     /* GM/c^2 */
    double *phi;   /* rad */
    size_t n_samples;
    int captured, escaped;
    double end_param, end_t, end_r, end_phi, end_rdot; /* where it stopped */
    /* periapses (dr/dparam crossing 0 upward, located by the driver's event on
     * a sub-step; the start counts when it is one) */
    long n_periapses;
    double first_periapsis_phi, last_periapsis_phi, first_periapsis_param, last_periapsis_param;
    double first_periapsis_t, last_periapsis_t;
    /* measured from the run: (phi_last - phi_first) / (n - 1) - 2 pi, sign of L removed;
     * NaN with fewer than 2 periapses */
    double measured_advance;
    /* light that came in from r0 and escaped: the total deflection, the integrated
     * Delta phi plus the asymptotic tails beyond r0 and r_escape (quadrature of
     * dphi/dw from w = 0); NaN otherwise */
    double measured_deflection;
    double constraint_max_abs;      /* max |g(u,u) + kappa| (timelike: per unit mass c^2) */
    double constraint_max_relative; /* max |residual| / (sum of the terms' sizes) */
    double constraint_final_relative;
    struct mech_ode_stats stats;
    double time_unit; /* the scaled time unit T (GM/c^3): tau = s T */
};

/* The scaled time unit T of a run (GM/c^3): r0^(3/2) (timelike) or r0 (null);
 * a fixed step dt (GM/c^3) is dt / T in the problem's opt.dt. Cannot fail. */
double mech_geodesic_time_unit(const struct mech_geodesic_init *in);

/* Integrate. Statuses: MECH_OK; MECH_EINVAL (bad problem: param names
 * "samples", "integrator/..."; r_escape <= r0 is "r_escape"); MECH_EBUDGET /
 * MECH_EDEADLINE / MECH_ECANCELLED (progress in scaled time converted to the
 * parameter); MECH_ENUMERIC (constraint drift beyond the bound, text says by
 * how much, param "constraint_bound"; or the driver's numeric failures);
 * MECH_ENOMEM. Never writes a non-finite sample. */
enum mech_status mech_geodesic_integrate(const struct mech_geodesic_problem *p,
                                         const struct mech_budget *budget,
                                         struct mech_geodesic_result *res, struct mech_error *err);

#endif
