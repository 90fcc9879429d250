/* mech/ode/ode.h — initial-value ODE driver: integrate y' = f(t, y) from t0 to
 * t_end with any registered method, write evenly spaced samples, stop at an
 * event located by root-finding, honour a compute budget.
 *
 * Methods (registry: core/ode/integrators/registry.c) are looked up by name
 * with mech_ode_method_find(): adaptive ones take rtol/atol ("rk8pd",
 * "rkck", "rkf45" and the stiff "msbdf" through GSL gsl_odeiv2; "radau15",
 * IAS15-class, written here), fixed-step ones take dt (written on libmech's
 * own stepper interface, core/ode/integrators/integrator.h). GSL's fixed-step
 * driver is never used.
 *
 * Off-grid values (samples, the event) are computed by a SUB-STEP from the
 * start of the accepted step that contains the time, of the exact length
 * needed: one step of the same method (its local error, so samples are as
 * accurate as the steps), except where a method documents otherwise —
 * radau15 iterates that step's corrector to round-off from the accepted
 * step's polynomial; msbdf, whose BDF restarted from one point would be
 * order 1, integrates the sub-interval with bsimp under the same tolerance.
 * The main step sequence never depends on the number of samples.
 *
 * Dense output (problem.dense_output = 1): for a second-order system under
 * rk8pd, rkck or rkf45, a sample is interpolated instead — q by the Hermite
 * interpolant of q, v, a at the step's ends and the previous step's start,
 * v by that of v, a — when the further Newton terms through the step before
 * that estimate both within the step's tolerance atol + rtol |y| for every
 * component; otherwise it is sub-stepped as above. It costs no evaluation;
 * the results at step ends are bit-identical either way, a sample differs
 * from its sub-stepped value by at most about the tolerance.
 *
 * Thread-safety: all functions are reentrant; nothing global is written.
 */
#ifndef MECH_ODE_H
#define MECH_ODE_H

#include <stddef.h>

#include "mech/base/budget.h"
#include "mech/base/status.h"

/* First-order right-hand side: dydt = f(t, y). Returns MECH_OK or a status
 * that stops the integration. A callback that wants its own message records
 * it in the caller's mech_error (reach it through params) before returning:
 * first error wins, so the driver's generic text never replaces it. */
typedef enum mech_status (*mech_ode_rhs_fn)(double t, const double *y, double *dydt,
                                            void *params);
/* Second-order form: y = (q, v), q' = v, v' = a(t, q, v); nq = dim / 2. */
typedef enum mech_status (*mech_ode_accel_fn)(double t, const double *q, const double *v,
                                              double *a, void *params);

/* Optional Lorentz-type split of the second-order form, for Boris-type
 * methods: a(t, q, v) = e(t, q) + v x w(t, q) exactly, with e and w
 * independent of v, one 3-vector each per particle (nq = dim/2 must be a
 * multiple of 3). Coriolis, -2 W x v = v x (2 W), is of this form; linear
 * drag is not (a system with drag leaves `lorentz` NULL). */
typedef enum mech_status (*mech_ode_lorentz_fn)(double t, const double *q, double *e, double *w,
                                                void *params);

/* Optional Kepler split of the second-order form, for Wisdom–Holman methods
 * (a scene dominated by one central body): with x = (q_0 .. q_{nd-1}),
 * nd = particle_dim (2 or 3) and nq = dim/2 = nd (ONE particle),
 *   a(t, q, v) = -gm (x - center) / |x - center|^3 + perturbation(t, q, v)
 * exactly. `perturbation` writes the other forces' acceleration (nd
 * components, same units as accel) and returns a status like accel; it must
 * agree with accel minus the Kepler term. velocity_dependent != 0 when the
 * perturbation depends on v (drag, a magnetic field). center[2] is ignored
 * when nd = 2. Owned by whoever builds the system (mech_ode_solve borrows). */
typedef enum mech_status (*mech_ode_perturbation_fn)(double t, const double *q, const double *v,
                                                     double *a, void *params);
struct mech_ode_kepler_split {
    double gm;        /* > 0, finite: G M of the central body (m^3 s^-2) */
    double center[3]; /* the fixed centre, in the system's coordinates */
    mech_ode_perturbation_fn perturbation; /* required */
    int velocity_dependent;
};

/* mech_ode_system.flags */
#define MECH_ODE_VELOCITY_FREE 0x1u /* accel does not depend on v (lets Verlet be explicit) */
/* rhs and accel return MECH_ENUMERIC themselves whenever a component they
 * write is not finite, so the driver does not test every derivative again
 * (it does for systems without the flag) */
#define MECH_ODE_FINITE_OUTPUT 0x2u

struct mech_ode_system {
    size_t dim;              /* state dimension, >= 1 (even when accel is given) */
    mech_ode_rhs_fn rhs;     /* required */
    mech_ode_accel_fn accel; /* optional second-order form; must agree with rhs */
    unsigned flags;          /* MECH_ODE_* */
    void *params;            /* passed to rhs/accel, borrowed */
    mech_ode_lorentz_fn lorentz; /* optional Lorentz-type split (Boris); NULL if none */
    /* Second-order form only: q = (q_0 .. q_{nq-1}) is a sequence of
     * "particles" of particle_dim consecutive components each, the Cartesian
     * coordinates of one point (2 for a planar scene, 3 in space). Step-size
     * control that measures accelerations per particle (radau15) takes the
     * Euclidean norm over one particle's components, so it sees |a| of a body
     * rather than a coordinate that passes through 0. 1, 2 or 3, dividing
     * nq = dim/2; 0 means 1: each component on its own, right for unrelated
     * or generalised coordinates (an angle and a length), which must never be
     * put under one norm. Ignored by first-order-only methods; a value that
     * does not fit is MECH_EINVAL from mech_ode_solve. */
    size_t particle_dim;
    /* optional Kepler split (wisdom_holman); NULL if none, borrowed */
    const struct mech_ode_kepler_split *kepler;
};

struct mech_ode_options {
    double rtol; /* adaptive: relative tolerance, (0, 1) */
    double atol; /* adaptive: absolute tolerance, >= 0 (rtol + atol > 0) */
    double dt;   /* fixed-step: step size, > 0 */
};

struct mech_ode_stats {
    long steps;           /* accepted steps */
    long rejected_steps;  /* rejected trial steps (adaptive methods) */
    long rhs_evaluations; /* right-hand-side (or acceleration) evaluations, sub-steps included */
};

/* Event function: the integration stops where g(t, y) crosses 0 in the
 * requested direction. */
typedef double (*mech_ode_event_fn)(double t, const double *y, void *params);
#define MECH_ODE_EITHER 0
#define MECH_ODE_INCREASING 1
#define MECH_ODE_DECREASING (-1)

/* Observer: called at t0, at the end of every accepted step, at every sample
 * and at the stop point (in increasing t, possibly repeating a time). A
 * non-OK return stops the integration with that status. */
typedef enum mech_status (*mech_ode_observe_fn)(double t, const double *y, void *params);

/* An opaque method descriptor (defined in core/ode/integrators/integrator.h). */
struct mech_integrator;

/* Public view of a method, for catalogs. */
struct mech_ode_method_info {
    const char *name;
    int order;
    int adaptive;     /* 1: rtol/atol, 0: fixed dt */
    int symplectic;   /* 1: symplectic for velocity-independent forces */
    int implicit;     /* 1: solves implicit stage equations */
    int symmetric;    /* 1: time-reversible */
    int second_order; /* 1: needs the second-order form q' = v, v' = a(t, q, v) */
    int kepler_split; /* 1: needs the Kepler split (one body about one central mass) */
    const char *doc;
    const char *reference;
};

/* The method called `name`, or NULL. Never fails otherwise. */
const struct mech_integrator *mech_ode_method_find(const char *name);
/* Number of registered methods, and the i-th (0 <= i < count) or NULL. */
size_t mech_ode_method_count(void);
const struct mech_integrator *mech_ode_method_at(size_t i);
/* Describe a method (m non-NULL). */
struct mech_ode_method_info mech_ode_method_describe(const struct mech_integrator *m);

struct mech_ode_problem {
    const struct mech_ode_system *sys; /* borrowed */
    const struct mech_integrator *method;
    struct mech_ode_options opt;
    double t0, t_end;       /* t_end > t0, both finite */
    const double *y0;       /* dim values, finite; borrowed */
    size_t n_samples;       /* >= 2: t_i = t0 + (t_end - t0) i / (n_samples - 1) */
    double *sample_t;       /* caller-owned [n_samples] or NULL */
    double *sample_y;       /* caller-owned [n_samples * dim] (row per sample) or NULL */
    mech_ode_event_fn event;/* NULL: no stop event */
    int event_direction;    /* MECH_ODE_EITHER / _INCREASING / _DECREASING */
    void *event_params;
    mech_ode_observe_fn observe; /* NULL: none */
    void *observe_params;
    double *y_stop;         /* caller-owned [dim]; required when event != NULL */
    /* 1: a sample inside an accepted step may be interpolated instead of
     * sub-stepped (dense output; second-order systems under rk8pd, rkck and
     * rkf45 only, see below); 0: always a sub-step. */
    int dense_output;
};

struct mech_ode_result {
    size_t n_samples;   /* samples written (all, or those at t <= t_stop) */
    int stopped;        /* 1 when the event fired */
    double t_stop;      /* time of the event (NaN if none) */
    double t_reached;   /* t_end, or t_stop */
    struct mech_ode_stats stats;
};

/* Integrate. The event is located on the sub-step solution by Brent's
 * method to 4 ulp of t (so to ~1e-15 relative, well inside the 1e-10 the API
 * promises); a crossing is g(prev) > 0 >= g(next) (decreasing), or
 * g(prev) < 0 <= g(next) (increasing), between the ends of one accepted
 * step, so a start exactly on the surface does not fire, and two crossings
 * inside one step are not seen (keep steps shorter than the event's
 * features).
 *
 * Budget: budget->max_steps accepted steps and the deadline are checked in
 * the step loop (mech_budget_check); a fixed-step run that needs more steps
 * than the budget fails before starting. On MECH_EBUDGET / MECH_EDEADLINE /
 * MECH_ECANCELLED, err->progress holds steps, t_reached and t_target, and
 * res holds what was written so far.
 *
 * Statuses: MECH_OK; MECH_EINVAL (bad problem: NULLs, dim 0, t_end <= t0,
 * n_samples < 2, a method that needs sys->accel without it, a
 * sys->particle_dim that does not fit it, tolerances out of range: param
 * "integrator/rtol" etc.); MECH_EBUDGET, MECH_EDEADLINE, MECH_ECANCELLED;
 * MECH_ENUMERIC (non-finite state, step size underflow, implicit stage not
 * converging); MECH_ENOMEM; whatever the rhs/observer
 * returned. Never writes a non-finite sample. */
enum mech_status mech_ode_solve(const struct mech_ode_problem *p, const struct mech_budget *budget,
                                struct mech_ode_result *res, struct mech_error *err);

#endif
