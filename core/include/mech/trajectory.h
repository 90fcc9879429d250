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
    const char *method;           /* any name of mech_ode_method_find(): "rk8pd", "verlet", ... */
    struct mech_ode_options opt;  /* rtol/atol (adaptive) or dt (fixed-step) */
    int error_estimate;           /* 1: when the scene has no reference, run it again at a
                                     tighter setting and report the difference */
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
    const char *name;         /* "energy" (inertial), "jacobi_integral" (rotating, earth) or
                                 "angular_momentum" (about the centre of a central scene) */
    int conserved;            /* 0 when a drag force with b > 0 dissipates it */
    double initial, final;    /* J; for angular_momentum |L| in kg m^2/s */
    double max_relative_drift;/* max |I - I0| / |I0| (|I0| = 0: over the largest |part| seen);
                                 for a vector, max |L - L0| / |L0| */
    int is_vector;            /* 1: angular momentum, the vectors below are set */
    struct mech_vec3 initial_vector, final_vector;
};

#define MECH_TRAJECTORY_MAX_INVARIANTS 2

/* Error against the scene's exact or first-order reference solution
 * (mech/reference.h), over every written sample and the stop point. */
struct mech_trajectory_reference_report {
    int kind;                     /* enum mech_reference_kind: 0 none, 1 exact, 2 first order */
    const char *name;             /* "kepler", "harmonic_oscillator", ... (static) */
    double max_position_error;    /* m: max |r - r_ref| */
    double final_position_error;  /* m: at the last sample (or the stop point) */
    double max_velocity_error;    /* m/s: max |v - v_ref| */
    double max_relative_position_error; /* max |r - r_ref| / max |r_ref| (over the samples) */
    double max_relative_velocity_error; /* max |v - v_ref| / max |v_ref| */
    double truncation_estimate;   /* m: first order only, max size of the neglected
                                     second-order terms (0 for exact references) */
};

/* A second run at a tighter setting (problem->error_estimate, no reference). */
struct mech_trajectory_error_estimate {
    int done;
    const char *method;           /* the method of the second run (static) */
    struct mech_ode_options opt;  /* its settings */
    const char *rule;             /* how it was derived, e.g. "rtol/100, atol/100" (static) */
    double max_position_difference;   /* m, over the common samples */
    double final_position_difference; /* m */
    double max_velocity_difference;   /* m/s */
    double max_position_error_estimate; /* m: Richardson-scaled for fixed steps
                                           (difference * 2^p / (2^p - 1)), the difference
                                           itself for adaptive runs */
    struct mech_ode_stats stats;  /* of the second run */
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
    struct mech_ode_stats stats;      /* of the answer's run (not the estimate's) */
    struct mech_trajectory_invariant invariant; /* = invariants[0] (kept for compatibility) */
    struct mech_trajectory_invariant invariants[MECH_TRAJECTORY_MAX_INVARIANTS];
    size_t n_invariants;
    struct mech_trajectory_reference_report reference; /* kind 0 when the scene has none */
    struct mech_trajectory_error_estimate error_estimate;
    long total_steps;                 /* steps of every run made (answer + estimate) */
};

/* Angular velocity of the frame in its own axes (rad/s): 0 for inertial,
 * omega for rotating, W (0, cos lat, sin lat) for earth. No validation. */
struct mech_vec3 mech_frame_omega(const struct mech_frame *frame);

/* ---- choosing by accuracy ---------------------------------------------------- */

enum mech_accuracy {
    MECH_ACCURACY_DRAFT = 0,
    MECH_ACCURACY_BALANCED,
    MECH_ACCURACY_PRECISE,
    MECH_ACCURACY_MACHINE,
    MECH_ACCURACY_COUNT
};

/* An accuracy preset: what it promises and what it maps to. */
struct mech_accuracy_preset {
    const char *name;         /* "draft", "balanced", "precise", "machine" */
    double promise;           /* relative error on positions and velocities it aims at */
    const char *method;       /* method for velocity-free conservative scenes */
    const char *method_other; /* method otherwise (drag, Coriolis) */
    double rtol;              /* rtol given to `method` */
    double rtol_other;        /* rtol given to `method_other` */
    const char *doc;
};

const struct mech_accuracy_preset *mech_accuracy_preset_at(enum mech_accuracy a); /* NULL if out of range */

/* The method and settings chosen for a problem. */
struct mech_trajectory_choice {
    const char *method;          /* static */
    struct mech_ode_options opt;
    double target;               /* the relative error aimed at */
    char reason[480];            /* why: scene class, scale, tolerance mapping */
};

/* Choose a method and tolerances for p (its method/opt are ignored) so that
 * positions and velocities are accurate to `target` relative (target in
 * [1e-15, 0.1]; use mech_accuracy_preset_at(a)->promise for a preset).
 * Velocity-free conservative scenes (no drag, no Coriolis) get the preset's
 * `method`, others `method_other`. The absolute tolerance is rtol times the
 * scene's smallest characteristic size of positions and velocities (from r0,
 * v0, the initial acceleration a0 and T = min(t_end, sqrt(|r0| / |a0|)):
 * max(|r0|, |v0| T, |a0| T^2/2) and max(|v0|, |a0| T)), so the choice does not
 * depend on the units.
 * Statuses: MECH_OK, MECH_EINVAL (target out of range). */
enum mech_status mech_trajectory_choose(const struct mech_trajectory_problem *p, double target,
                                        struct mech_trajectory_choice *out,
                                        struct mech_error *err);

/* Integrate the particle's motion from t = 0 to t_end (or the stop event).
 *
 * Invariant: E = 1/2 m |v|^2 + U(r) with U = -m g.r (uniform gravity),
 * -m gm / |r - c| (central), 1/2 k (|r - a| - L)^2 (spring); in a non-inertial
 * frame with the centrifugal term modelled, U also has -1/2 m |w x r|^2
 * (the Jacobi integral; Coriolis does no work). Linear drag with b > 0 makes
 * it decrease: it is still reported, with conserved = 0. In an inertial frame
 * whose every active force is central about one point c (central gravity
 * centred, springs anchored there), the angular momentum m (r - c) x v about
 * c is reported too (invariants[1]).
 *
 * Reference: when the scene has one (mech_trajectory_reference_find), the
 * error of every sample (and the stop point) against it is reported in
 * res->reference. Otherwise, with p->error_estimate, the scene is run again
 * (adaptive: same method at rtol/100 and atol/100 — but when that is below
 * what the method resolves, radau15 at rtol 1e-10, or for radau15 itself
 * below its eps floor 1e-10, rk8pd at rtol 1e-14; fixed step: dt/2, with the
 * estimate scaled by Richardson's 2^p/(2^p - 1)) with the budget the first
 * run left, and the difference goes to res->error_estimate. A Lorentz-type split (mech_ode_system.lorentz) is
 * provided whenever no drag acts, so Boris-type methods apply.
 *
 * Non-finite values (an overflowing force or state) stop the integration with
 * MECH_ENUMERIC naming t and the last finite position.
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
