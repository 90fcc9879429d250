/* mech/ode/chooser.h — the predictive method chooser behind {"accuracy": ...} and
 * {"target_error": ...}: it predicts each candidate's cost and error and
 * runs the cheapest predicted to meet the target.
 *
 * Given a profile of the scene (its class, the run's length in dynamical
 * times, the scale of its state, its sample count, whether it has a
 * second-order form, velocity-dependent forces, stiffness, a closed form) and
 * a target relative error, mech_choose() lists every candidate method with
 * the setting that would meet the target, its predicted error, evaluations
 * and CPU seconds, and a verdict: "chosen" (the cheapest predicted to meet
 * the target), "costlier", "misses_target" or "not_applicable", each with why.
 *
 * The model (core/ode/chooser.c, constants in core/ode/chooser_table.h, measured by
 * bench/bench_calibrate_chooser.c on this machine's build):
 *   adaptive:   error = A tol^a span^b,    evaluations = B span tol^-c
 *   fixed step: error = A (h/T)^a span^b,  evaluations = B span (h/T)^-c
 *   + evals_per_sample x samples (each sample is a sub-step),
 *   error >= F span^g (round-off accumulated over the run, F and g measured),
 *   CPU = evaluations x CPU seconds per evaluation (measured per method)
 *         + MECH_CHOOSER_REQUEST_CPU_S (the request's fixed cost).
 * It costs microseconds and integrates nothing (dry runs use it alone).
 *
 * Thread-safety: reentrant; the table is constant. */
#ifndef MECH_CHOOSER_H
#define MECH_CHOOSER_H

#include <stddef.h>

#include "mech/ode/ode.h"
#include "mech/base/status.h"

enum mech_scene_class {
    MECH_SCENE_CENTRAL_GRAVITY = 0, /* a central 1/r^2 force dominates (Kepler-like) */
    MECH_SCENE_OSCILLATOR,          /* a spring dominates */
    MECH_SCENE_UNIFORM_FIELD,       /* uniform fields only (projectiles, falls, Coriolis) */
    MECH_SCENE_FIRST_ORDER,         /* first-order systems: rigid bodies, geodesics, flows */
    MECH_SCENE_GENERAL,             /* other particle scenes: drag, magnetic fields, tides,
                                       rotating frames without a dominant force */
    MECH_SCENE_CONSTRAINED_PENDULUM,/* the Foucault pendulum on its rod, RATTLE family
                                       (mech/frames/chooser_pendulum.h; not given to mech_choose) */
    MECH_SCENE_CLASS_COUNT
};

/* "central_gravity", "oscillator", "uniform_field", "first_order", "general",
 * "constrained_pendulum"; NULL if out of range. */
const char *mech_scene_class_name(enum mech_scene_class c);

struct mech_scene_profile {
    enum mech_scene_class cls;
    double span;            /* run length in dynamical times T, >= 0 */
    double T;               /* the dynamical time, s (> 0): fixed steps are h = x T */
    double scale;           /* atol = rtol x scale (> 0) */
    size_t samples;         /* samples written (each costs a sub-step) */
    double rhs_cost_s;      /* CPU s of one right-hand side if known (0: the table's) */
    int second_order;       /* q'' = a(t, q, v) form exists (radau15, yoshida6 apply) */
    int velocity_dependent; /* forces depend on v (drag, Coriolis, magnetic): no yoshida6 */
    int stiff;              /* stiffness hint: msbdf applies */
    int closed_form;        /* the scene has an exact solution (MECH_REFERENCE_EXACT) */
    int closed_form_allowed;/* the request allows it (integrator.closed_form, default 1) */
    const char *closed_form_name; /* e.g. "kepler" (static) or NULL */
    double closed_form_evaluations; /* the closed form's predicted evaluations when its
                               cost is not one per sample (the torque-free body's
                               quadrature: mech_rigid_closed_form_predict_evaluations);
                               0: one per sample */
    double closed_form_cpu_per_eval; /* CPU s of one of those evaluations; 0: 2e-7 */
    /* Bound central-body orbits (mech_chooser_profile_orbit, core/frames/chooser_orbit.c;
     * all 0 when unknown, and then the span-based laws apply): */
    double cost_span;       /* the run in the cost law's units: dynamical times of the
                               calibration orbit (Kepler e = 0.5) that cost the same
                               evaluations; 0: span */
    double orbit_period;    /* the osculating orbit's period 2 pi sqrt(a^3 / GM), s */
    double eccentricity;    /* of that orbit, [0, 1) */
    double perturbation;    /* the other forces' acceleration relative to the central
                               one, both at distance a (Wisdom-Holman's eps); < 0:
                               unknown (no splitting is offered) */
    double error_gain;      /* >= 1: how many times more this scene amplifies an error
                               than its class's calibration scenes (light passing close to
                               the photon sphere: mech_geodesic_error_gain); 0: 1 */    const char *rows;       /* the table rows measured on this kind of scene itself
                               ("rigid_body", "heavy_top", "geodesic",
                               "hamiltonian_flow"; static); NULL or a name without rows:
                               the class's */
};

enum mech_verdict {
    MECH_VERDICT_CHOSEN = 0,
    MECH_VERDICT_COSTLIER,
    MECH_VERDICT_MISSES_TARGET,
    MECH_VERDICT_NOT_APPLICABLE
};

/* "chosen", "costlier", "misses_target", "not_applicable". */
const char *mech_verdict_name(enum mech_verdict v);

#define MECH_CHOOSER_MAX_CANDIDATES 10

/* The fixed CPU of a request beside its method's evaluations (parsing, the
 * model's first pass, references, encoding the samples), added to every
 * candidate's predicted_cpu_s: measured 0.08 .. 0.15 ms on the scene set
 * (bench_workprecision, 2026-11-27: the falling object's 44 evaluations
 * cost 0.09 ms, closed forms 0.10 .. 0.15 ms). */
#define MECH_CHOOSER_REQUEST_CPU_S 1e-4

struct mech_candidate {
    const char *method;           /* registry name or "closed_form" (static) */
    int adaptive;                 /* 1: opt.rtol/atol; 0: opt.dt (fixed step) */
    int has_settings;             /* 0 for closed_form and not_applicable methods */
    struct mech_ode_options opt;  /* the setting predicted to meet the target */
    double predicted_error;       /* relative, on positions and velocities (or the state) */
    double predicted_evaluations; /* right-hand-side evaluations (0 if no prediction) */
    double predicted_cpu_s;       /* CPU seconds */
    int predicted;                /* 1: the three predictions above are set */
    enum mech_verdict verdict;
    char why[300];
};

struct mech_selection {
    double target;                /* relative error aimed at */
    enum mech_scene_class cls;
    double span;                  /* dynamical times */
    double roundoff_floor;        /* predicted round-off floor over the run */
    int beyond;                   /* 1: the target is within the model's margin of the
                                     round-off floor (may not be kept); 2: no candidate
                                     is predicted to meet it */
    size_t n;
    struct mech_candidate c[MECH_CHOOSER_MAX_CANDIDATES];
    int chosen;                   /* index into c, or -1 (none applicable) */
    int integrating;              /* index of the chosen integrating candidate (the
                                     chosen one unless the closed form is), or -1 */
    char model[200];              /* which model made the predictions */
};

/* Fill *out with the candidates for scene s at `target` (relative error, in
 * [1e-15, 0.1]) and choose the cheapest predicted to meet it; when none is,
 * the candidate with the smallest predicted error is chosen and out->beyond
 * is 2 (1 when the target is within the margin of the round-off floor).
 * closed_form is listed when s->closed_form and competes on predicted cost
 * when s->closed_form_allowed (it is then chosen: its cost grows with the
 * samples only); out->integrating is the best integrating candidate all the
 * same, for callers that cannot evaluate the closed form. wisdom_holman when the registry
 * has it, on a central_gravity scene with a bound orbit and a perturbation
 * (s->orbit_period > 0, s->perturbation > 0: its measured law in eps). For a
 * bound orbit the cost law counts s->cost_span when set. Statuses: MECH_OK,
 * MECH_EINVAL (NULL argument, target out of range, span/T/scale invalid, the
 * constrained_pendulum class: mech_choose_pendulum serves it). */
enum mech_status mech_choose(const struct mech_scene_profile *s, double target,
                             struct mech_selection *out, struct mech_error *err);

/* The figure a preset's promise is re-stated to when round-off (or every
 * candidate's best setting) cannot keep sel->target: max(round-off floor,
 * the chosen integrator's predicted error) when that exceeds the target and
 * the selection is beyond (sel->beyond, or target below the floor); 0 when
 * the promise stands. Relative error, like the target. */
double mech_selection_restated(const struct mech_selection *sel);

/* The sentence an answer's selection reason appends about the round-off
 * floor, into buf (n bytes, NUL-terminated, "" when nothing is to be said):
 * "; beyond what the preset can keep: ... can reach about X relative ...
 * re-stated as about X" (X = mech_selection_restated) or "; close to the
 * round-off floor ...". One wording for every operation (clients and
 * tests/api/scene_set.h read "about X"). */
void mech_selection_beyond_text(const struct mech_selection *sel, char *buf, size_t n);

/* The predicted relative error of `method` at setting x (rtol, or h/T for
 * fixed step) on scene s, from the calibrated model; -1 if the table has no
 * row for it. For tests and benches. */
double mech_chooser_predict_error(const struct mech_scene_profile *s, const char *method,
                                  double x);

#endif
