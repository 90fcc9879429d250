/* mech/frames/trajectory_problem.h — a trajectory scene as the caller states it: one
 * point particle, its frame (mech/frames/frame.h), the forces, the fictitious terms
 * to model, the time span, the samples, the method and the stop event; its
 * validation, the plane a planar scene stays in, and the centre about which
 * it conserves angular momentum. Integrating it is mech/frames/trajectory.h's, its
 * exact or first-order reference mech/frames/reference.h's: both build on this
 * header, which needs neither.
 *
 * Units: SI (kg, m, s, C). Thread-safety: reentrant, no globals.
 */
#ifndef MECH_TRAJECTORY_PROBLEM_H
#define MECH_TRAJECTORY_PROBLEM_H

#include <stddef.h>

#include "mech/frames/frame.h"
#include "mech/ode/ode.h"
#include "mech/base/status.h"
#include "mech/base/vec.h"

#define MECH_TRAJECTORY_MAX_FORCES 32
#define MECH_TRAJECTORY_MIN_SAMPLES 2
#define MECH_TRAJECTORY_MAX_SAMPLES 100000

enum mech_force_type {
    MECH_FORCE_UNIFORM_GRAVITY = 0, /* F = m g */
    MECH_FORCE_CENTRAL_GRAVITY,     /* F = -m gm (r - c) / |r - c|^3 */
    MECH_FORCE_SPRING,              /* F = -k (|r - a| - L) (r - a) / |r - a| */
    MECH_FORCE_LINEAR_DRAG,         /* F = -b v (v: velocity in the frame) */
    MECH_FORCE_LORENTZ,             /* F = q (E + v x B), q = problem charge, frame axes */
    MECH_FORCE_THIRD_BODY_TIDE,     /* F = m gm [(d - r)/|d - r|^3 - d/|d|^3] (notes §1.4) */
};

struct mech_force {
    enum mech_force_type type;
    union {
        struct { struct mech_vec3 g; } uniform_gravity;               /* m/s^2 */
        struct { double gm; struct mech_vec3 center; } central_gravity;/* gm > 0 (m^3/s^2) */
        struct { double k; struct mech_vec3 anchor; double rest_length; } spring; /* k >= 0 N/m, L >= 0 m */
        struct { double b; } linear_drag;                             /* b >= 0 kg/s */
        /* E (V/m) and B (T), uniform and constant in the frame's axes; the
         * velocity in q v x B is the velocity relative to the frame. */
        struct { struct mech_vec3 E, B; } lorentz;
        /* A body of gm = G M > 0 (m^3/s^2) at a fixed position d != 0 of the
         * frame (the frame's origin is in free fall towards it, so only the
         * difference of its attraction at r and at the origin acts: the tidal
         * acceleration, computed without cancellation when |r| << |d|). */
        struct { double gm; struct mech_vec3 position; } third_body_tide;
    } u;
};

#define MECH_FICTITIOUS_CORIOLIS 0x1u      /* -2 m w x v */
#define MECH_FICTITIOUS_CENTRIFUGAL 0x2u   /* -m w x (w x r) */
#define MECH_FICTITIOUS_EULER 0x4u         /* -m (dw/dt) x r */
#define MECH_FICTITIOUS_TRANSLATIONAL 0x8u /* -m A */
#define MECH_FICTITIOUS_ALL 0xfu
/* The four fictitious terms, in the order model.terms lists them. */
#define MECH_TRAJECTORY_N_FICTITIOUS 4

/* Relativistic corrections (inertial frames only):
 * SPECIAL: special-relativistic dynamics dp/dt = F with p = gamma m v for
 *   every force (F as the force types above define it, m the rest mass; the
 *   state is integrated as (r, u = gamma v) with gamma = sqrt(1 + u^2/c^2),
 *   so its digits hold from beta = 1e-9 to gamma = 1e6 and beyond);
 * SCHWARZSCHILD_1PN: the first post-Newtonian correction of a test particle's
 *   acceleration about the one central mass (Schwarzschild field in harmonic
 *   coordinates; Soffel, Relativity in Astrometry, Celestial Mechanics and
 *   Geodesy, eq. 3.2.43 with the mass of the particle -> 0):
 *     a_1PN = (gm / (c^2 d^2)) [(4 gm/d - v^2) n + 4 (n.v) v],  n = d/|d|,
 *   whose periapsis advance per orbit is 6 pi gm / (c^2 a (1 - e^2)). It
 *   already holds the special-relativistic kinematics of the orbit to order
 *   v^2/c^2, so the two are not combined. */
#define MECH_RELATIVITY_SPECIAL 0x1u
#define MECH_RELATIVITY_SCHWARZSCHILD_1PN 0x2u
#define MECH_TRAJECTORY_N_RELATIVITY 2

enum mech_stop_direction {
    MECH_STOP_EITHER = MECH_ODE_EITHER,
    MECH_STOP_INCREASING = MECH_ODE_INCREASING,
    MECH_STOP_DECREASING = MECH_ODE_DECREASING,
};

struct mech_trajectory_problem {
    double mass;                  /* kg, finite, > 0 */
    double charge;                /* C, finite (used by lorentz forces only) */
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
    int reduce_planar;            /* 1: integrate a planar scene in two dimensions (see
                                     mech_trajectory_plane); 0: always in three */
    int closed_form_off;          /* 1: the chooser must not pick the closed form
                                     (integrator.closed_form false) */
    unsigned relativity;          /* MECH_RELATIVITY_* modelled (0: Newtonian) */
    int has_proper_velocity;      /* 1: proper_velocity is the initial state (SPECIAL) and
                                     velocity is only its u / gamma */
    struct mech_vec3 proper_velocity; /* u0 = gamma v0, m/s (when has_proper_velocity) */
};

/* The Schwarzschild 1PN acceleration correction (m/s^2) of a test particle
 * at displacement d (m, d != 0) from a mass of gm (m^3/s^2) with velocity v
 * (m/s), harmonic coordinates (MECH_RELATIVITY_SCHWARZSCHILD_1PN):
 * (gm / (c^2 |d|^2)) [(4 gm/|d| - v^2) n + 4 (n.v) v], n = d/|d|. Cannot fail. */
struct mech_vec3 mech_schwarzschild_1pn_accel(double gm, struct mech_vec3 d, struct mech_vec3 v);

/* The initial proper velocity u0 = gamma0 v0 of p (m/s): proper_velocity
 * when given, else v0 / sqrt((1 - beta)(1 + beta)) (|v0| < c; p checked). */
struct mech_vec3 mech_trajectory_proper_velocity0(const struct mech_trajectory_problem *p);

/* Whether the scene p (with its fictitious mask as given) stays in a plane
 * through the origin: every vector that must lie in the plane (r0, v0, g of
 * uniform gravity, centres and anchors, E, the tide body's position, the
 * translational acceleration A when modelled) is perpendicular to one unit
 * normal n, and every vector that must be normal to it (w and dw/dt when a
 * rotation term is modelled, B when the charge is non-zero) is parallel to n
 * (or zero). "Perpendicular" means |n.u| <= 1e-15 |u|: out-of-plane
 * components below round-off are dropped. Forces that are null (g = 0, k = 0,
 * b = 0, E = B = 0 or q = 0) impose nothing. Then the motion never leaves the
 * plane (every acceleration term maps the plane into itself). Returns 1 and
 * the normal (deterministic: the normalised cross product of the first two
 * independent in-plane vectors, or the given normal, or for a line or a point
 * the coordinate axis least aligned with it crossed with it), else 0. */
int mech_trajectory_plane(const struct mech_trajectory_problem *p, struct mech_vec3 *normal);

/* The in-plane axes of a planar scene of unit normal n (as mech_trajectory_plane
 * gives it): e1 = the coordinate axis least aligned with n, crossed with n and
 * normalised; e2 = n x e1, so (e1, e2, n) is right-handed and orthonormal to
 * round-off. Deterministic. n must be a finite unit vector. Cannot fail. */
void mech_trajectory_plane_axes(struct mech_vec3 n, struct mech_vec3 *e1, struct mech_vec3 *e2);

/* Whether the scene's forces conserve angular momentum about one point: at
 * least one central force (central gravity, a spring with k != 0), every
 * active force central about the same point (uniform gravity and drag of
 * zero size and a Lorentz force on no charge or with no field are ignored),
 * and no frame term acting (rotation_active: a rotation term with a non-zero
 * rate; translation_active: a translational acceleration, both as the
 * caller's frame model decides). Returns 1 with *center set (m), else 0
 * (also for NULL arguments). The one rule for the integrator's and the
 * closed forms' angular-momentum invariant. */
int mech_trajectory_angular_center(const struct mech_trajectory_problem *p, int rotation_active,
                                   int translation_active, struct mech_vec3 *center);

/* Validate p as mech_trajectory_integrate does (everything but the method
 * and its settings): MECH_OK, or MECH_EINVAL / MECH_EDOMAIN with err->param
 * the API path of the offending field ("particle/mass", "forces/1/gm", ...). */
enum mech_status mech_trajectory_check(const struct mech_trajectory_problem *p,
                                       struct mech_error *err);

#endif
