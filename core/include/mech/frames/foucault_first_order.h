/* mech/frames/foucault_first_order.h — the Foucault pendulum's closed forms (notes
 * §1.4, "Example: The Foucault Pendulum"), computed before and after the
 * integration of mech/frames/pendulum.h: the scene's scales, the first-order
 * precession rate -W sin(lat), the Airy-corrected expected rate with its
 * next-order tolerance, and the estimated effect of the centrifugal term of
 * the displacement (what "auto" judges the term by).
 *
 * Local axes x east, y north, z up; rates counterclockwise positive seen
 * from above. Units SI, angles in radians unless the name says _deg. Pure
 * functions: no allocation, no globals, reentrant. */
#ifndef MECH_FOUCAULT_FIRST_ORDER_H
#define MECH_FOUCAULT_FIRST_ORDER_H

#include "mech/frames/pendulum.h"
#include "mech/base/vec.h"

struct mech_foucault_scales {
    double latitude;               /* rad */
    double alpha;                  /* release angle of the rod from the vertical, rad */
    double omega_vertical;         /* W sin(lat), rad/s: exactly +-W at the poles */
    double cos_latitude;           /* cos(lat): exactly 0 at the poles */
    struct mech_vec3 omega;        /* the Earth's w = (0, W cos lat, W sin lat), rad/s */
    double omega0;                 /* sqrt(g / l), rad/s */
    double period;                 /* the planar finite-amplitude period 4 sqrt(l/g) K(sin(alpha/2)),
                                      s (mech_pendulum_period) */
    double small_amplitude_period; /* 2 pi / omega0, s */
    double amplitude;              /* a = l sin(alpha), the horizontal release distance, m */
    struct mech_vec3 release_position; /* m from the rest point: (a cos az, a sin az,
                                          2 l sin^2(alpha/2)) */
    double first_order_rate;       /* the notes' -W sin(lat), rad/s */
};

/* The scales of problem p (its length, g, latitude_deg, omega_magnitude,
 * amplitude_deg and azimuth_deg, in the ranges of struct
 * mech_foucault_problem; other members unused). Out-of-range input gives
 * NaN members. Neither pointer may be NULL. */
void mech_foucault_scales(const struct mech_foucault_problem *p, struct mech_foucault_scales *out);

/* The estimated effect of the centrifugal term of the displacement over a
 * run of t_end seconds (see core/frames/foucault_first_order.c): */
struct mech_foucault_centrifugal_effect {
    double rate;          /* rad/s: W^2 cos^2(lat) / (4 omega0) + (3/8) dh / l^2,
                             dh = (W^2 cos^2(lat) a^2 / 4) min(1 / |W sin lat|, t_end) */
    double relative_rate; /* rate / W (0 at W = 0) */
    double relative_period; /* W^2 (1 + sin^2 lat) / (4 omega0^2) */
    double relative;      /* max(relative_rate, relative_period) */
};

/* Fill *out for scales s (from mech_foucault_scales), W = omega_magnitude
 * (rad/s, [0, 1]), the pendulum's length l (m, (0, 1e7]) and the run's
 * t_end (s, finite, > 0). Out-of-range input gives NaN members. Neither
 * pointer may be NULL. */
void mech_foucault_centrifugal_effect(const struct mech_foucault_scales *s, double omega_magnitude,
                                      double length, double t_end,
                                      struct mech_foucault_centrifugal_effect *out);

/* The rate the swing plane should turn at, given the measured mean Airy
 * correction airy_rate (rad/s, struct mech_foucault_result.airy_rate_mean):
 * -W sin(lat) + airy_rate. *next_order (rad/s, may be NULL) is the size of
 * the terms neglected, |airy_rate| (alpha^2 / 4 + W^2 / omega0^2). A
 * non-finite airy_rate gives NaN. */
double mech_foucault_expected_rate(const struct mech_foucault_scales *s, double omega_magnitude,
                                   double airy_rate, double *next_order);

/* The time of one full turn of the swing plane at rate (rad/s): 2 pi / |rate|
 * in seconds; +inf for rate 0, NaN for a non-finite rate. */
double mech_foucault_full_precession_time(double rate);

#endif
