/* mech/hamiltonian/small_oscillations.h — small oscillations about steady motions (notes
 * ch. 5 "Motion in a Central Potential", "A spherical pendulum"; ch. 2 for the
 * physical pendulum): near-circular orbits in a central potential (radial and
 * azimuthal frequencies, the apsidal angle), the conical pendulum's steady
 * precession, and a rigid body swinging about a fixed horizontal axis.
 *
 * Units: SI (kg, m, s, rad, J) or any consistent set. Pure, thread-safe.
 */
#ifndef MECH_SMALL_OSCILLATIONS_H
#define MECH_SMALL_OSCILLATIONS_H

#include <stddef.h>

#include "mech/base/status.h"
#include "mech/base/vec.h"

/* One term of a central potential: V = k r^n (n != 0) or V = k ln r (n = 0).
 * Kepler: n = -1, k = -GM m; isotropic oscillator: n = 2, k = m w^2/2. */
struct mech_potential_term {
    double k; /* J m^-n (J for n = 0) */
    double n; /* dimensionless exponent */
};

struct mech_orbit_oscillation {
    double v, dv, d2v;        /* V(r0) (J), V'(r0) (N), V''(r0) (N/m) */
    double angular_momentum;  /* L = sqrt(m r0^3 V'(r0)), kg m^2/s */
    double energy;            /* L^2/(2 m r0^2) + V(r0), J */
    double omega_phi;         /* sqrt(V'/(m r0)), rad/s: the orbital angular velocity */
    double k_eff;             /* V''(r0) + 3 V'(r0)/r0, N/m: the effective potential's
                                 curvature, m omega_r^2 */
    int stable;               /* k_eff > 0 */
    double omega_r;           /* sqrt(k_eff/m), rad/s (stable); 0 otherwise */
    double growth_rate;       /* sqrt(-k_eff/m), 1/s (unstable); 0 otherwise */
    double apsidal_angle;     /* pericentre to apocentre, pi omega_phi/omega_r =
                                 pi/sqrt(3 + r0 V''/V'), rad (stable); 0 otherwise */
};

/* The circular orbit of a particle of mass m (kg, finite, > 0) at radius r0
 * (m, finite, > 0) in V = sum of terms[0..n-1] (1 <= n), and small
 * oscillations about it: radial frequency omega_r, azimuthal omega_phi, the
 * apsidal angle. For V = k r^n alone, pi/sqrt(n + 2) (Kepler pi, oscillator
 * pi/2); angle between successive pericentres twice that.
 * Returns MECH_OK; MECH_EINVAL with param "terms/<i>/k" or "terms/<i>/n" for a
 * non-finite value, "mass", "r0" for a value not finite and > 0; MECH_EDOMAIN
 * with param "r0" when V'(r0) <= 0 (no circular orbit: the force there is
 * repulsive or zero); MECH_ENUMERIC if a result is not finite. */
enum mech_status mech_orbit_oscillation(const struct mech_potential_term *terms, size_t n,
                                        double mass, double r0,
                                        struct mech_orbit_oscillation *out,
                                        struct mech_error *err);

struct mech_conical_pendulum {
    double phi_dot;        /* steady precession rate sqrt(g/(l cos a)), rad/s */
    double period;         /* 2 pi / phi_dot, s */
    double omega_theta;    /* phi_dot sqrt(1 + 3 cos^2 a), rad/s: small oscillations of the
                              cone angle about a */
    double apsidal_angle;  /* pi phi_dot/omega_theta = pi/sqrt(1 + 3 cos^2 a), rad: azimuth
                              from the widest to the narrowest swing */
    double speed;          /* l sin a phi_dot, m/s */
    double radius;         /* l sin a, m */
};

/* The conical pendulum: a bob on a massless rod of length l (m, > 0) at the
 * half-angle a from the downward vertical (rad, 0 < a < pi/2) in gravity g
 * (m/s^2, > 0). Derivation: theta'' = h^2 cos t / sin^3 t - (g/l) sin t with
 * h = phi' sin^2 t conserved; linearised about t = a.
 * Returns MECH_OK; MECH_EINVAL with param "length", "g" (not finite and > 0) or
 * "angle" (not in (0, pi/2)). */
enum mech_status mech_conical_pendulum(double length, double g, double angle,
                                       struct mech_conical_pendulum *out,
                                       struct mech_error *err);

struct mech_physical_pendulum {
    struct mech_mat3 tensor_pivot; /* kg m^2, about the pivot: I_cm + m(d^2 1 - d d^T) */
    double moment_axis;            /* n.I_pivot.n, kg m^2 */
    double arm;                    /* |d - (d.n) n|, m: distance of the centre of mass from
                                      the axis */
    double omega;                  /* sqrt(m g arm / moment_axis), rad/s */
    double period;                 /* 2 pi / omega, s */
    double equivalent_length;      /* moment_axis/(m arm), m: the simple pendulum with the
                                      same period */
};

/* A rigid body of mass m (kg, > 0) with tensor i_cm about its centre of mass
 * (kg m^2, symmetric, positive semi-definite is not checked) swinging about a
 * fixed axis through the pivot along the unit-normalised `axis` (any non-zero
 * length), d = centre of mass - pivot (m), in gravity g (m/s^2, > 0), the axis
 * horizontal (the caller's frame: only |d across the axis| matters, the body
 * hangs with its centre of mass below the axis). Small oscillations about the
 * hanging equilibrium: omega^2 = m g arm / I_axis (notes ch. 2: parallel axis).
 * Returns MECH_OK; MECH_EINVAL with param "mass", "g", "tensor", "offset",
 * "axis" (zero or non-finite); MECH_EDOMAIN with param "offset" when the centre
 * of mass lies on the axis (arm <= 1e-12 |d| or 0: no restoring torque, no
 * oscillation), "tensor" when I_axis <= 0. */
enum mech_status mech_physical_pendulum(double mass, struct mech_mat3 i_cm, struct mech_vec3 d,
                                        struct mech_vec3 axis, double g,
                                        struct mech_physical_pendulum *out,
                                        struct mech_error *err);

struct mech_ball_pendulum {
    struct mech_mat3 tensor_pivot;  /* kg m^2, about the pivot */
    double arm;                     /* |d|, m */
    double moment[2];               /* kg m^2, ascending: eigenvalues of the reduced
                                       horizontal inertia M (below) */
    struct mech_vec3 axis[2];       /* unit horizontal axes of the two modes (the body
                                       swings ABOUT axis[k]), largest component positive */
    double omega[2];                /* sqrt(m g |d| / moment[k]), rad/s, descending */
};

/* A rigid body hanging from a ball joint (free to turn about any axis through
 * the pivot): small oscillations about the hanging equilibrium, d = centre of
 * mass - pivot pointing down. With a small rotation vector (t_u, t_v, t_e)
 * (u, v horizontal, e = -d/|d| up), T = t'.I_pivot.t'/2 and V = m g |d|
 * (t_u^2 + t_v^2)/2: the turn t_e about the vertical is cyclic, and with its
 * momentum zero the horizontal motion has the inertia M = I_hh - I_he I_eh /
 * I_ee (M = I_hh when I_ee = 0, a body on the vertical line through the
 * pivot); the two normal modes swing about M's eigenvectors at omega_k =
 * sqrt(m g |d| / M_k). (For a flat body these are the swings in and out of its
 * plane.) Arguments and errors as mech_physical_pendulum without the axis;
 * MECH_EDOMAIN "offset" for d = 0, "tensor" when a reduced moment is <= 0. */
enum mech_status mech_ball_pendulum(double mass, struct mech_mat3 i_cm, struct mech_vec3 d,
                                    double g, struct mech_ball_pendulum *out,
                                    struct mech_error *err);

struct mech_foucault_modes {
    double omega0;          /* sqrt(g/l), rad/s */
    double omega_z;         /* Omega sin(latitude), rad/s: the local vertical rotation */
    double swing;           /* sqrt(omega0^2 + omega_z^2), rad/s: the swing frequency */
    double ccw, cw;         /* the two circular normal modes' angular frequencies, rad/s,
                               counterclockwise and clockwise seen from above:
                               swing - omega_z and swing + omega_z */
    double precession;      /* rad/s, counterclockwise positive: -omega_z (clockwise in the
                               north), exact in the linearised equations */
};

/* Normal modes of the linearised Foucault pendulum (notes §1.3 "Example: The
 * Foucault Pendulum"; x east, y north, z up, Coriolis with the vertical
 * component of Omega only):
 *   x'' = -omega0^2 x + 2 omega_z y',  y'' = -omega0^2 y - 2 omega_z x';
 * with q = x + i y, q'' + 2i omega_z q' + omega0^2 q = 0 and q = e^{i a t}:
 * a = -omega_z +- sqrt(omega0^2 + omega_z^2). length (m, > 0), g (m/s^2, > 0),
 * omega (rad/s, finite, >= 0), latitude (rad, in [-pi/2, pi/2]).
 * Returns MECH_OK; MECH_EINVAL with param "length", "g", "omega_earth" or
 * "latitude_deg" (the API's name). */
enum mech_status mech_foucault_modes(double length, double g, double omega, double latitude,
                                     struct mech_foucault_modes *out, struct mech_error *err);

#endif
