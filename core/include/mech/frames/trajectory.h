/* mech/frames/trajectory.h — a point particle in an inertial, rotating (optionally
 * with constant angular acceleration and an accelerating origin) or local
 * Earth frame under simple forces, integrated with any ODE method of
 * mech/ode/ode.h, with the model terms and the conserved quantity reported, and
 * the "model only what the scene requires" selection of fictitious terms
 * (mech_trajectory_model_select, mech_term_effect_estimate).
 *
 * Notes §1.2 (the general effective force, "a more general derivation"):
 * in a frame whose origin accelerates with A and whose axes rotate with
 * angular velocity w(t),
 *   m a = F - m A - 2 m w x v - m (dw/dt) x r - m w x (w x r)
 * (translational, Coriolis, Euler and centrifugal terms). Here A is constant
 * in the frame's axes and w(t) = w0 + (dw/dt) t with dw/dt constant; dw/dt is
 * the same seen from the inertial and the rotating frame (their derivatives
 * of any vector differ by w x ., and w x w = 0, notes §1.1). The Earth frame has its origin on the
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

#include "mech/ode/accuracy.h"
#include "mech/base/budget.h"
#include "mech/ode/chooser.h"
#include "mech/base/constants.h"
#include "mech/frames/earth.h"
#include "mech/frames/frame.h"
#include "mech/ode/ode.h"
#include "mech/base/status.h"
#include "mech/frames/trajectory_problem.h"
#include "mech/base/vec.h"

/* One modelled (or deliberately omitted) term. */
struct mech_trajectory_term {
    const char *term;        /* "uniform_gravity", ..., "coriolis", "centrifugal", "euler",
                                "translational" (static) */
    int force_index;         /* index into forces, or -1 for a fictitious term */
    int included;            /* 1 if it is in the equations of motion */
    double max_acceleration; /* max |a_term| over the samples and step ends (m/s^2);
                                for omitted fictitious terms: the size they would have had */
};

struct mech_trajectory_invariant {
    const char *name;         /* "energy" (inertial), "jacobi_integral" (rotating, earth) or
                                 "angular_momentum" (about the centre of a central scene) */
    int conserved;            /* 0 when a drag force with b > 0 dissipates it, or the frame's
                                 rotation changes with time (see note) */
    const char *note;         /* why it is (not) conserved (static, never NULL) */
    double initial, final;    /* J; for angular_momentum |L| in kg m^2/s */
    double max_relative_drift;/* max |I - I0| / |I0| (|I0| = 0: over the largest |part| seen);
                                 for a vector, max |L - L0| / |L0| */
    int is_vector;            /* 1: angular momentum, the vectors below are set */
    struct mech_vec3 initial_vector, final_vector;
};

#define MECH_TRAJECTORY_MAX_INVARIANTS 2

/* Error against the scene's exact or first-order reference solution
 * (mech/frames/reference.h), over every written sample and the stop point. */
struct mech_trajectory_reference_report {
    int kind;                     /* enum mech_reference_kind: 0 none, 1 exact, 2 first order */
    const char *name;             /* "kepler", "harmonic_oscillator", ... (static) */
    double max_position_error;    /* m: max |r - r_ref| */
    double final_position_error;  /* m: at the last sample (or the stop point) */
    double max_velocity_error;    /* m/s: max |v - v_ref| */
    double max_relative_position_error; /* max |r - r_ref| / max |r_ref - c| over the samples
                                           (c: the Kepler centre or the spring's anchor, else
                                           the origin): the orbit's or amplitude's size */
    double max_relative_velocity_error; /* max |v - v_ref| / the largest speed over the
                                           samples and every step of the run */
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
    struct mech_vec3 *proper_velocity; /* u = gamma v, written by special-relativistic runs
                                          (result.relativistic) only */
    /* Filled by the call. */
    size_t n_samples;         /* samples written (those at t <= t_stop when stopped) */
    int stopped;
    double t_stop;            /* NaN if not stopped */
    struct mech_vec3 stop_position, stop_velocity;
    struct mech_vec3 stop_proper_velocity; /* special-relativistic runs, else 0 */
    int relativistic;         /* 1: integrated with special-relativistic dynamics */
    /* "relativistic" and "schwarzschild_1pn" (mech/frames/trajectory_problem.h): included, and
     * their largest |a| along the run, measured whether modelled or not (the correction
     * to the forces' F/m at the speed reached, all of |F/m| when a Newtonian run goes at
     * or beyond c; the 1PN term about the one central mass of an inertial scene, 0 when
     * it has none); both 0 in a non-inertial frame */
    struct mech_trajectory_term relativity_terms[MECH_TRAJECTORY_N_RELATIVITY];
    /* and each one's largest size relative to the acceleration it corrects
     * (relativistic: the forces' |F/m|; schwarzschild_1pn: gm/d^2), same points */
    double relativity_ratio[MECH_TRAJECTORY_N_RELATIVITY];
    struct mech_trajectory_term terms[MECH_TRAJECTORY_MAX_FORCES + MECH_TRAJECTORY_N_FICTITIOUS];
    size_t n_terms;           /* n_forces + 4 (coriolis, centrifugal, euler, translational
                                 always listed) */
    double max_radius;        /* m: largest |r| at the samples and step ends */
    double max_speed;         /* m/s: largest |v| there */
    int dimensions;           /* 2: integrated in the plane of a planar scene; 3 otherwise */
    struct mech_vec3 plane_normal; /* unit normal of that plane (dimensions 2), else 0 */
    const char *method;       /* the method's name (static) */
    struct mech_ode_stats stats;      /* of the answer's run (not the estimate's) */
    struct mech_trajectory_invariant invariant; /* = invariants[0] (kept for compatibility) */
    struct mech_trajectory_invariant invariants[MECH_TRAJECTORY_MAX_INVARIANTS];
    size_t n_invariants;
    struct mech_trajectory_reference_report reference; /* kind 0 when the scene has none */
    struct mech_trajectory_error_estimate error_estimate;
    long total_steps;                 /* steps of every run made (answer + estimate) */
};

/* ---- choosing by accuracy ---------------------------------------------------- */

/* the presets (enum mech_accuracy, mech_accuracy_preset_at/_named): mech/ode/accuracy.h */

/* The method and settings chosen for a problem. */
struct mech_trajectory_choice {
    const char *method;          /* static */
    struct mech_ode_options opt;
    double target;               /* the relative error aimed at */
    char reason[900];             /* why: scene class, scale, tolerance mapping */
    struct mech_scene_profile profile; /* what the chooser was told about the scene */
    struct mech_selection sel;   /* every candidate with its predictions and verdict */
    int closed_form;             /* 1: the closed form was chosen (mech/frames/closed_form.h);
                                    method/opt are still the best integrator's */
};

/* Choose a method and tolerances for p (its method/opt are ignored) so that
 * positions and velocities are accurate to `target` relative (target in
 * [1e-15, 0.1]; use mech_accuracy_preset_at(a)->promise for a preset), with
 * the predictive chooser (mech/ode/chooser.h): the scene's profile (class
 * central_gravity / oscillator / uniform_field / general, span = t_end / T
 * with T = min(t_end, sqrt(|r0| / |a0|)), samples, velocity dependence, a
 * stiffness hint from drag, the exact reference as closed_form unless
 * p->closed_form_off) goes to mech_choose, which lists every candidate with
 * its predicted error and cost in out->sel and picks the cheapest predicted
 * to meet the target. The reason says when the target may be beyond the
 * round-off floor of the run. The absolute tolerance is rtol times the
 * scene's smallest characteristic size of positions and velocities
 * (max(|r0|, |v0| T, |a0| T^2/2) and max(|v0|, |a0| T)), so the choice does
 * not depend on the units. Integrates nothing.
 * Statuses: MECH_OK, MECH_EINVAL (target out of range), MECH_EINTERNAL (no
 * candidate applies). */
enum mech_status mech_trajectory_choose(const struct mech_trajectory_problem *p, double target,
                                        struct mech_trajectory_choice *out,
                                        struct mech_error *err);

/* Integrate the particle's motion from t = 0 to t_end (or the stop event).
 *
 * Invariant: E = 1/2 m |v|^2 + U(r) with U = -m g.r (uniform gravity),
 * -m gm / |r - c| (central), 1/2 k (|r - a| - L)^2 (spring); in a non-inertial
 * frame with the centrifugal term modelled, U also has -1/2 m |w x r|^2
 * (the Jacobi integral; Coriolis does no work), and with the translational
 * term +m A.r. Lorentz forces: q v x B does no work (it is perpendicular to
 * v, like Coriolis), and a uniform static E in the frame has the potential
 * -q E.r, so the energy (or Jacobi integral) including -q E.r is conserved.
 * Third-body tide: U = -m gm [1/|d - r| - 1/|d| - d.r/|d|^3] (evaluated
 * without cancellation). Linear drag with b > 0 makes it decrease: it is
 * still reported, with conserved = 0. When the frame's rotation changes with
 * time (dw/dt != 0 with any rotation term modelled) the equations depend
 * explicitly on t and NOTHING is conserved: the Jacobi integral (with w(t))
 * is reported with conserved = 0 and a note saying so. In an inertial frame
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
 * Planar scenes (p->reduce_planar and mech_trajectory_plane): integrated in
 * the plane's two coordinates (a 4-component state instead of 6), the
 * samples mapped back to the frame's axes; res->dimensions says which. Not
 * for Boris-type methods (their Lorentz split rotates 3-vectors): those stay
 * in three dimensions.
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

/* ---- modelling only what the scene requires ---------------------------------- */

/* The estimate for one candidate term. */
struct mech_term_estimate {
    const char *term;        /* "coriolis", "centrifugal", "euler", "translational" (static) */
    int applicable;          /* 0: identically zero in this frame (not carried, not estimated) */
    int included;            /* 1: modelled */
    double accel_bound;      /* m/s^2: bound on |a_term| along the trajectory */
    double position_effect;  /* m: accel_bound T^2 / 2 */
    double velocity_effect;  /* m/s: accel_bound T */
    double relative_effect;  /* max(position_effect / L, velocity_effect / V) */
    char reason[320];        /* why included or left out (with the numbers) */
};

/* The rule behind "fictitious": "auto", reusable by any scene that knows a
 * bound on a term's acceleration: leaving out a term whose acceleration stays
 * below accel_bound for a time T moves the positions by at most
 * accel_bound T^2/2 and the velocities by at most accel_bound T (the term
 * integrated twice / once; an upper bound for secular effects, conservative
 * for oscillating ones). The term is included iff
 *   max(accel_bound T^2/2 / L, accel_bound T / V) > target / safety
 * (a scale that is 0 is skipped; both 0: included iff accel_bound > 0).
 * L (m) and V (m/s) are the scene's position and velocity scales (e.g. the
 * largest |r| and |v| of the motion), target the relative accuracy asked for
 * (e.g. 1e-8), safety >= 1 the margin for several omitted terms adding up and
 * for the bound's slack (mech_trajectory_model_select uses 10). Fills out
 * (term is stored as given, borrowed: pass a static string), including the
 * reason, e.g. "estimated effect 3e-12 m < target 1e-8 x 100 m / safety 10".
 * All inputs finite and >= 0 (T > 0, target > 0). Cannot fail. */
void mech_term_effect_estimate(const char *term, double accel_bound, double T, double L, double V,
                               double target, double safety, struct mech_term_estimate *out);

#define MECH_TRAJECTORY_AUTO_SAFETY 10.0

/* The fictitious terms chosen for a scene, with the evidence. */
struct mech_trajectory_model {
    double target;             /* relative accuracy asked for */
    double safety;             /* MECH_TRAJECTORY_AUTO_SAFETY */
    double time_scale;         /* T (s): t_end, or the stop time of the first pass */
    double position_scale;     /* L (m): max |r| over the first pass */
    double velocity_scale;     /* V (m/s): max |v| over the first pass */
    unsigned fictitious;       /* the MECH_FICTITIOUS_* mask chosen */
    struct mech_term_estimate terms[MECH_TRAJECTORY_N_FICTITIOUS]; /* coriolis, centrifugal,
                                                                     euler, translational */
    /* the cheap first pass that bounds |a_term|, |r| and |v| (not run when no
     * term is applicable) */
    int first_pass_done;
    const char *first_pass_method; /* static */
    struct mech_ode_options first_pass_opt;
    struct mech_ode_stats first_pass_stats;
};

/* "fictitious": "auto". Decide which fictitious terms the scene p needs for
 * relative accuracy `target` (in [1e-15, 0.1]) BEFORE the answer's run
 * (p->fictitious and p->method/opt are ignored; nothing of p is changed):
 *  1. terms identically zero in p's frame (no rotation: Coriolis, centrifugal
 *     and Euler; dw/dt = 0: Euler; A = 0: translational; an inertial frame:
 *     all) are not applicable: not carried, no estimate;
 *  2. if any term is applicable, a cheap first pass integrates the scene with
 *     every applicable term at the "draft" setting of mech_trajectory_choose
 *     (1e-3 relative; at most 101 samples, same stop event) and records the
 *     largest |a_term| of each term at every step end and sample, the largest
 *     |r| (L) and |v| (V) and the duration T (t_end or the stop time). A 1e-3
 *     error in the first pass changes these bounds by ~1e-3 relative, far
 *     inside the safety factor, so the bound is honest;
 *  3. each term is then judged by mech_term_effect_estimate with safety
 *     MECH_TRAJECTORY_AUTO_SAFETY.
 * The first pass uses `budget` (its steps are reported in m->first_pass_stats;
 * the caller should give the answer's run what is left).
 * Statuses: MECH_OK; MECH_EINVAL (target out of range, invalid p: those of
 * mech_trajectory_integrate); MECH_EBUDGET / MECH_EDEADLINE /
 * MECH_ECANCELLED / MECH_ENUMERIC / MECH_ENOMEM from the first pass. */
enum mech_status mech_trajectory_model_select(const struct mech_trajectory_problem *p,
                                              double target, const struct mech_budget *budget,
                                              struct mech_trajectory_model *m,
                                              struct mech_error *err);

/* ---- the relativistic corrections a scene needs -------------------------------- */

/* The relativistic corrections chosen for a scene, with the evidence. */
struct mech_relativity_model {
    int judged;                /* 1: estimated from a run (0: a dry run, nothing known) */
    double target;             /* relative accuracy asked for */
    double safety;             /* MECH_TRAJECTORY_AUTO_SAFETY */
    double time_scale;         /* T (s): t_end, or the stop time of the run judged */
    double position_scale;     /* L (m): max |r| of that run */
    double velocity_scale;     /* V (m/s): max |v| of that run */
    unsigned forced_on, forced_off; /* MECH_RELATIVITY_* as requested (auto: 0, 0) */
    unsigned relativity;       /* the MECH_RELATIVITY_* mask chosen */
    /* "relativistic", "schwarzschild_1pn"; applicable = could be modelled here */
    struct mech_term_estimate terms[MECH_TRAJECTORY_N_RELATIVITY];
};

/* Decide the relativistic corrections of p at relative accuracy `target`
 * ([1e-15, 0.1]) from `run`, a finished answer of p (integrated or closed
 * form, with p->relativity as it was run: its relativity_terms hold each
 * correction's largest |a| along the run, measured whether modelled or not).
 * Each correction's estimate: eps, its largest size relative to the
 * acceleration it corrects, over the run's phase V T / L (T its duration,
 * L and V its largest |r| and |v|: the radians of an orbit or gyration, ~2
 * for a fall from rest), which a correction of relative size eps shifts by
 * ~eps per radian: relative effect eps (1 + V T / L), included above
 * target / MECH_TRAJECTORY_AUTO_SAFETY (the safety of "fictitious": "auto").
 *   relativistic: dv/dt - F/m of p = gamma m v at the speed reached, against
 *     the forces' |F/m| (~1.5 beta^2; 1 when the Newtonian run reached c). Not
 *     applicable when every force is central gravity (motion about masses is
 *     the 1PN term's) and not modellable outside an inertial frame;
 *   schwarzschild_1pn: |a_1PN| / (gm/d^2) measured along the run about the one
 *     central mass of an inertial scene (for a Kepler closed form at least its
 *     value at the pericentre of the osculating orbit, which the samples may
 *     miss); with several central masses or a rotating frame, the bound
 *     4 gm / (c^2 d) + 5 beta^2, d = sqrt(gm / max gm/d^2), and not modellable.
 * A term in forced_on is included, in forced_off left out (each with its
 * estimate); otherwise included iff its estimate exceeds target / safety.
 * m->relativity is the mask to run with (== p->relativity: nothing to redo).
 * Statuses: MECH_OK; MECH_EINVAL (NULL, target out of range); MECH_EDOMAIN
 * (param "relativity": a correction the accuracy needs and mechd cannot
 * model here — a rotating frame, several central masses, or both
 * corrections at once — named with its estimate; m is filled). */
enum mech_status mech_trajectory_relativity_select(const struct mech_trajectory_problem *p,
                                                   const struct mech_trajectory_result *run,
                                                   double target, unsigned forced_on,
                                                   unsigned forced_off,
                                                   struct mech_relativity_model *m,
                                                   struct mech_error *err);

#endif
