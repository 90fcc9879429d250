/* mech/trajectory.h — a point particle in an inertial, uniformly rotating or
 * local Earth frame under simple forces, integrated with any ODE method of
 * mech/ode.h, with the model terms and the conserved quantity reported.
 *
 * Notes §1.2–1.3 (non-inertial frames, motion near the Earth): in a frame
 * rotating with constant angular velocity w about the origin,
 *   m a = F - 2 m w x v - m w x (w x r)
 * (Coriolis and centrifugal terms). The Earth frame has its origin on the
 * ground, axes x east, y north, z up, and w = W (0, cos(lat), sin(lat)).
 * There the centrifugal acceleration of the origin itself is already part of
 * the local g the caller gives (notes §1.3, "Deflection of a Falling
 * Object"); the centrifugal term here is that of the displacement r only.
 *
 * Units: SI (kg, m, s). Thread-safety: reentrant, no globals.
 */
#ifndef MECH_TRAJECTORY_H
#define MECH_TRAJECTORY_H

#include <stddef.h>

#include "mech/budget.h"
#include "mech/ode.h"
#include "mech/status.h"
#include "mech/vec.h"

/* Sidereal rotation rate of the Earth (rad/s): 2 pi / 86164.0905 s. */
#define MECH_EARTH_OMEGA_SIDEREAL 7.2921159e-5

#define MECH_TRAJECTORY_MAX_FORCES 32
#define MECH_TRAJECTORY_MIN_SAMPLES 2
#define MECH_TRAJECTORY_MAX_SAMPLES 100000

enum mech_frame_type { MECH_FRAME_INERTIAL = 0, MECH_FRAME_ROTATING, MECH_FRAME_EARTH };

struct mech_frame {
    enum mech_frame_type type;
    struct mech_vec3 omega;  /* ROTATING: angular velocity (rad/s), finite */
    double latitude_deg;     /* EARTH: latitude in [-90, 90] degrees */
    double omega_magnitude;  /* EARTH: rotation rate >= 0 (rad/s); use MECH_EARTH_OMEGA_SIDEREAL */
};

enum mech_force_type {
    MECH_FORCE_UNIFORM_GRAVITY = 0, /* F = m g */
    MECH_FORCE_CENTRAL_GRAVITY,     /* F = -m gm (r - c) / |r - c|^3 */
    MECH_FORCE_SPRING,              /* F = -k (|r - a| - L) (r - a) / |r - a| */
    MECH_FORCE_LINEAR_DRAG,         /* F = -b v (v: velocity in the frame) */
};

struct mech_force {
    enum mech_force_type type;
    union {
        struct { struct mech_vec3 g; } uniform_gravity;               /* m/s^2 */
        struct { double gm; struct mech_vec3 center; } central_gravity;/* gm > 0 (m^3/s^2) */
        struct { double k; struct mech_vec3 anchor; double rest_length; } spring; /* k >= 0 N/m, L >= 0 m */
        struct { double b; } linear_drag;                             /* b >= 0 kg/s */
    } u;
};

#define MECH_FICTITIOUS_CORIOLIS 0x1u
#define MECH_FICTITIOUS_CENTRIFUGAL 0x2u

enum mech_stop_direction {
    MECH_STOP_EITHER = MECH_ODE_EITHER,
    MECH_STOP_INCREASING = MECH_ODE_INCREASING,
    MECH_STOP_DECREASING = MECH_ODE_DECREASING,
};

struct mech_trajectory_problem {
    double mass;                  /* kg, finite, > 0 */
    struct mech_vec3 position;    /* m, in the frame */
    struct mech_vec3 velocity;    /* m/s, relative to the frame */
    struct mech_frame frame;
    const struct mech_force *forces; /* n_forces entries (borrowed), may be NULL if 0 */
    size_t n_forces;              /* <= MECH_TRAJECTORY_MAX_FORCES */
    unsigned fictitious;          /* MECH_FICTITIOUS_* modelled; ignored in an inertial frame */
    double t_end;                 /* s, finite, > 0 */
    size_t samples;               /* MECH_TRAJECTORY_MIN_SAMPLES..MAX_SAMPLES, evenly spaced 0..t_end */
    const char *method;           /* "rk8pd", "rkck", "rkf45", "rk4", "verlet" */
    struct mech_ode_options opt;  /* rtol/atol (adaptive) or dt (fixed-step) */
    int has_stop;                 /* 1: stop when coordinate stop_axis crosses stop_value */
    int stop_axis;                /* 0 = x, 1 = y, 2 = z */
    double stop_value;            /* m */
    enum mech_stop_direction stop_direction;
};

/* One modelled (or deliberately omitted) term. */
struct mech_trajectory_term {
    const char *term;        /* "uniform_gravity", ..., "coriolis", "centrifugal" (static) */
    int force_index;         /* index into forces, or -1 for a fictitious term */
    int included;            /* 1 if it is in the equations of motion */
    double max_acceleration; /* max |a_term| over the samples and step ends (m/s^2);
                                for omitted fictitious terms: the size they would have had */
};

struct mech_trajectory_invariant {
    const char *name;         /* "energy" (inertial) or "jacobi_integral" (rotating, earth) */
    int conserved;            /* 0 when a drag force with b > 0 dissipates it */
    double initial, final;    /* J */
    double max_relative_drift;/* max |I - I0| / |I0| (|I0| = 0: over the largest |part| seen) */
};

struct mech_trajectory_result {
    /* Caller-owned output buffers, each with room for problem->samples
     * entries; set them before the call. Any may be NULL (not written). */
    double *t;
    struct mech_vec3 *position;
    struct mech_vec3 *velocity;
    /* Filled by the call. */
    size_t n_samples;         /* samples written (those at t <= t_stop when stopped) */
    int stopped;
    double t_stop;            /* NaN if not stopped */
    struct mech_vec3 stop_position, stop_velocity;
    struct mech_trajectory_term terms[MECH_TRAJECTORY_MAX_FORCES + 2];
    size_t n_terms;           /* n_forces + 2 (coriolis, centrifugal always listed) */
    const char *method;       /* the method's name (static) */
    struct mech_ode_stats stats;
    struct mech_trajectory_invariant invariant;
};

/* Angular velocity of the frame in its own axes (rad/s): 0 for inertial,
 * omega for rotating, W (0, cos lat, sin lat) for earth. No validation. */
struct mech_vec3 mech_frame_omega(const struct mech_frame *frame);

/* Integrate the particle's motion from t = 0 to t_end (or the stop event).
 *
 * Invariant: E = 1/2 m |v|^2 + U(r) with U = -m g.r (uniform gravity),
 * -m gm / |r - c| (central), 1/2 k (|r - a| - L)^2 (spring); in a non-inertial
 * frame with the centrifugal term modelled, U also has -1/2 m |w x r|^2
 * (the Jacobi integral; Coriolis does no work). Linear drag with b > 0 makes
 * it decrease: it is still reported, with conserved = 0.
 *
 * Statuses: MECH_OK; MECH_EINVAL / MECH_EDOMAIN with err->param as the API
 * path ("particle/mass", "forces/1/gm", "integrator/dt", "samples", ...);
 * MECH_EBUDGET / MECH_EDEADLINE / MECH_ECANCELLED with err->progress
 * (t_reached, t_target; a fixed-step run needing more than budget->max_steps
 * steps fails before it starts, t_reached = how far the budget would go);
 * MECH_ENUMERIC (the particle reaches a central mass, r = 0, or any
 * non-finite value; never a NaN in the output); MECH_ENOMEM.
 * On failure, the output buffers hold the samples written so far
 * (res->n_samples) and nothing else of res is meaningful. */
enum mech_status mech_trajectory_integrate(const struct mech_trajectory_problem *p,
                                           const struct mech_budget *budget,
                                           struct mech_trajectory_result *res,
                                           struct mech_error *err);

#endif
