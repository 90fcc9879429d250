/* mech/frames/pendulum.h — the Foucault pendulum: the full nonlinear spherical
 * pendulum (a bob on a massless rigid rod or taut string of length l) in the
 * rotating Earth frame, integrated with a constrained symplectic method, and
 * the precession of its swing plane measured from the turning points.
 *
 * Frame (notes §1.3, "Example: The Foucault Pendulum"): origin at the bob's
 * rest point, axes x east, y north, z up (the plumb line, so the centrifugal
 * acceleration of the origin is already in g); the suspension point is fixed
 * at s = (0, 0, l); the Earth's angular velocity in these axes is
 * W = W (0, cos lat, sin lat). Per unit mass, with u = r - s, |u| = l:
 *   u'' = g + c(r) - 2 W x u' + mu u          (mu: the rod's tension / (m l))
 * with g = (0, 0, -g) and c(r) = -W x (W x r) the centrifugal acceleration
 * of the displacement r from the origin (optional; 0 at the rest point).
 * The notes linearise this to x'' = -(g/l) x + 2 W sin(lat) y', y'' =
 * -(g/l) y - 2 W sin(lat) x' and find the swing plane turning clockwise (seen
 * from above, northern hemisphere) at W sin(lat); nothing here is linearised.
 *
 * Units: SI. Thread-safety: reentrant, no globals.
 */
#ifndef MECH_PENDULUM_H
#define MECH_PENDULUM_H

#include "mech/base/budget.h"
#include "mech/base/status.h"
#include "mech/base/vec.h"

enum mech_pendulum_method {
    /* RATTLE with the Coriolis term taken at the step's mean velocity (an
     * implicit-midpoint / Cayley rotation, solved in closed form): the
     * discrete variational integrator of L = |u'|^2/2 + u'.(W x r) - V on
     * |u| = l. Order 2, symplectic, symmetric, exact constraint. */
    MECH_PENDULUM_RATTLE = 0,
    /* The same step composed as Yoshida's (1990) symmetric triple jump:
     * order 4, still symplectic and symmetric; 3 constrained sub-steps. */
    MECH_PENDULUM_RATTLE_YOSHIDA4 = 1,
};

/* Name of a method ("rattle", "rattle_yoshida4") or NULL if out of range. */
const char *mech_pendulum_method_name(enum mech_pendulum_method m);

struct mech_foucault_problem {
    double length;              /* l (m), in (0, 1e7] */
    double g;                   /* local effective gravity (m/s^2), in (0, 1e4] */
    double latitude_deg;        /* [-90, 90] */
    double omega_magnitude;     /* Earth's rotation rate W (rad/s), in [0, 1]; e.g.
                                   MECH_EARTH_OMEGA_SIDEREAL of mech/frames/trajectory.h */
    double mass;                /* bob mass (kg), (0, 1e30]: scales energies only */
    double amplitude_deg;       /* release angle of the rod from the vertical, (0, 90) */
    double azimuth_deg;         /* direction of the release point, counterclockwise from
                                   east seen from above (degrees, finite) */
    double transverse_velocity; /* horizontal speed at release, perpendicular to the release
                                   direction, counterclockwise positive (m/s); 0: the
                                   classic release from rest. |v| <= 1e6 */
    int centrifugal;            /* 1: model c(r) = -W x (W x r) */
    double t_end;               /* s, finite, > 0 */
    long steps;                 /* number of steps (composite steps for yoshida4), >= 1 */
    enum mech_pendulum_method method;
};

/* A least-squares straight line y = a + b t through (t_k, y_k). */
struct mech_pendulum_fit {
    long n;              /* points */
    double slope;        /* b */
    double stderr_slope; /* standard error of b from the residuals (0 when n < 3) */
    double rms_residual; /* of y (rad for the azimuth) */
};

struct mech_foucault_result {
    double omega_vertical;          /* W sin(lat) (rad/s) */
    double omega0;                  /* sqrt(g / l) (rad/s) */
    double small_amplitude_period;  /* 2 pi sqrt(l / g) (s) */
    double finite_amplitude_period; /* 4 sqrt(l/g) K(sin(amplitude/2)), the planar pendulum (s) */
    double h_vertical;              /* (r x (r' + W x r))_z horizontal part at release:
                                       x y' - y x' + W sin(lat) (x^2 + y^2) (m^2/s), twice the
                                       areal velocity of the swing seen from a non-rotating frame */
    double airy_rate;               /* (3/8) h_vertical / l^2 = (3/8) omega0 a b / l^2 (rad/s) */

    /* Measured. Turning points are the maxima of the horizontal distance
     * rho = sqrt(x^2 + y^2) (where x x' + y y' falls through 0), located on the
     * step's cubic Hermite interpolant by Newton iteration. */
    long turning_points;                 /* apocentres found (two per swing) */
    long pericentres;                    /* minima of rho found */
    double period;                       /* 2 (t_last - t_first) / (turning_points - 1) (s) */
    double swings;                       /* t_end / period */
    struct mech_pendulum_fit precession; /* fit of the swing-plane azimuth psi (mod pi,
                                   unwrapped, counterclockwise from east) against t at the
                                   turning points: slope = the precession rate (rad/s),
                                   negative = clockwise */
    double airy_rate_mean;  /* (3/8) <h>/l^2 with <h> the slope of the least-squares line
                               through H(t) = integral of h(t) dt at the turning points:
                               the Airy precession of the ellipse actually swung (h is
                               exactly conserved only when W is vertical and no
                               centrifugal anisotropy acts; see mech_foucault_integrate) */
    double mean_apocentre;  /* mean rho at the turning points (m): the semi-major axis a */
    double mean_pericentre; /* mean rho at the minima (m): the semi-minor axis b (0 if none) */

    /* Conservation. E = m (|u'|^2/2 + g z - [centrifugal] |W x r|^2 / 2) is the
     * Jacobi integral (Coriolis and the rod's tension do no work). */
    double energy_initial;            /* J, with z measured from the rest point */
    double max_relative_energy_drift; /* max |E - E0| / |E0| over the step ends */
    double max_constraint_error;      /* max ||u| - l| / l over the step ends */
    double max_tangency_error;        /* max |u.u'| / (l V), V = sqrt(2 g l (1 - cos alpha))
                                         + |transverse_velocity| (the swing's speed scale) */

    double max_speed;                /* max |u'| over the step ends (m/s) */
    double max_displacement;         /* max |r| from the rest point over the step ends (m) */
    struct mech_vec3 final_position; /* r at t_end (m, from the rest point) */
    struct mech_vec3 final_velocity; /* m/s */
    long steps;                      /* steps taken */
    long force_evaluations;          /* force evaluations */
};

/* The planar pendulum's period 4 sqrt(l/g) K(k), k = sin(alpha/2), by the
 * arithmetic-geometric mean K(k) = pi / (2 AGM(1, cos(alpha/2))) (Abramowitz
 * & Stegun 17.6). alpha in [0, pi) radians, l > 0, g > 0 (not checked; a
 * non-finite result means bad input). */
double mech_pendulum_period(double length, double g, double alpha);

/* The finite-amplitude correction T(alpha)/T0 - 1 = 2K(k)/pi - 1 (T0 = 2 pi sqrt(l/g);
 * alpha^2/16 + 11 alpha^4/3072 + ... for small alpha) without forming T/T0 - 1, which
 * keeps only ~1e-16/correction of it (1.8e-5 relative at alpha = 1e-5 rad). Formed
 * from the AGM's positive differences: 1 - AGM(1, k') = sum d_n/2 with d_0 = 1 - k' =
 * 2 sin^2(alpha/4), d_(n+1) = d_n^2 / (2 (sqrt(a_n) + sqrt(b_n))^2). alpha in [0, pi)
 * radians (not checked; a non-finite result means bad input). */
double mech_pendulum_period_correction(double alpha);

/* Integrate the Foucault pendulum p from its release for p->steps steps of
 * t_end / steps and measure it (see struct mech_foucault_result).
 *
 * What to expect (derivations in core/frames/pendulum.c): the swing plane turns at
 * -W sin(lat) + (3/8) h / l^2 (counterclockwise positive) to leading order in
 * the amplitude; the second term is Airy's precession of a spherical
 * pendulum's ellipse, (3/8) omega0 a b / l^2, in the sense it is traversed.
 * Released from rest, h = W sin(lat) a^2, so the rate is
 * -W sin(lat) (1 - (3/8) a^2 / l^2). With the centrifugal term the
 * horizontal potential is anisotropic (east softer by W^2 cos^2(lat)); its
 * torque changes h by up to W^2 cos^2(lat) a^2 / (4 W sin(lat)) over a
 * precession, so the Airy term changes by up to (3/32) (a/l)^2 W cos^2(lat) /
 * sin(lat): airy_rate_mean measures it along the run.
 *
 * Budget: p->steps must be <= budget->max_steps (else MECH_EBUDGET before
 * starting, progress.t_reached = how far the budget would go); the deadline
 * and the cancel flag are checked during the run.
 * Statuses: MECH_OK; MECH_EINVAL / MECH_EDOMAIN with err->param "length", "g",
 * "latitude_deg", "omega_magnitude", "mass", "release/amplitude_deg",
 * "release/azimuth_deg", "release/transverse_velocity", "t_end", "steps",
 * "method"; MECH_EBUDGET / MECH_EDEADLINE / MECH_ECANCELLED with progress;
 * MECH_ENUMERIC (a step too long for the constraint to be solved, or a
 * non-finite value). On failure nothing of res is meaningful. */
enum mech_status mech_foucault_integrate(const struct mech_foucault_problem *p,
                                         const struct mech_budget *budget,
                                         struct mech_foucault_result *res, struct mech_error *err);

#endif
