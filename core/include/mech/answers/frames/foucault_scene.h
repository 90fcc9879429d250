/* mech/answers/frames/foucault_scene.h — one POST /v1/scenes/foucault computation, from
 * the request as read to everything its answer states: the scene's scales
 * (mech/frames/foucault_first_order.h), the run's length, the method given or
 * chosen (mech/frames/chooser_pendulum.h), the model's centrifugal term (given, or
 * "auto" by its estimated effect), the run (mech/frames/pendulum.h), a second run
 * at half the steps for the Richardson error estimate, and the expected
 * rate with its tolerances. The API's handler parses, calls
 * mech_foucault_scene() once and encodes.
 *
 * Units SI, angles in radians unless the name says _deg; rates
 * counterclockwise positive seen from above (local x east, y north, z up). */
#ifndef MECH_FOUCAULT_SCENE_H
#define MECH_FOUCAULT_SCENE_H

#include "mech/base/budget.h"
#include "mech/ode/chooser.h"
#include "mech/frames/foucault_first_order.h"
#include "mech/frames/pendulum.h"
#include "mech/base/status.h"

/* How the run's length is given (one per request). */
enum mech_foucault_run_by {
    MECH_FOUCAULT_RUN_SWINGS = 0, /* run_value swings of the finite-amplitude period */
    MECH_FOUCAULT_RUN_PRECESSIONS, /* run_value turns at W |sin lat| (not at the equator, W = 0) */
    MECH_FOUCAULT_RUN_DURATION     /* run_value seconds */
};

struct mech_foucault_scene_request {
    /* the scene: length, g, latitude_deg, omega_magnitude, mass, amplitude_deg,
     * azimuth_deg, transverse_velocity and method in the ranges of struct
     * mech_foucault_problem (checked by mech_foucault_integrate); centrifugal,
     * t_end and steps are set here */
    struct mech_foucault_problem problem;
    enum mech_foucault_run_by run_by;
    double run_value;          /* swings, precessions or s (finite, > 0) */
    int explicit_integrator;   /* 1: problem.method and steps_per_swing as given;
                                  0: the chooser picks both */
    double steps_per_swing;    /* explicit: >= 1 */
    double target;             /* relative error aimed at, [1e-15, 0.1] (the chooser's range) */
    int target_defaulted;      /* 1: target is the default (named in the choice's reason) */
    int error_estimate;        /* 1: run again at half the steps (Richardson) */
    int auto_terms;            /* 1: "auto": the centrifugal term by its estimated effect */
    int given_coriolis, given_centrifugal; /* !auto_terms: the terms the request lists */
    int dry_run;               /* 1: stop after the choice, before integrating */
};

struct mech_foucault_scene {
    struct mech_foucault_problem problem; /* as run: method, centrifugal, t_end, steps */
    struct mech_foucault_scales scales;
    const char *run_field;     /* "swings", "precessions" or "duration" (static) */
    double swings_asked;       /* t_end / scales.period */
    int order;                 /* 2 (rattle) or 4 (rattle_yoshida4) */
    double steps_per_swing;
    double dt;                 /* t_end / steps, s */
    int chosen;                /* 1: by the chooser (selection, reason) */
    struct mech_selection selection;
    char reason[700];
    struct mech_foucault_centrifugal_effect centrifugal;
    /* the run (ran == 0 for a dry run: nothing below is set) */
    int ran;
    struct mech_foucault_result run;
    double wall_seconds;       /* the answer's run alone */
    int estimate_done;         /* 1: the half-steps run succeeded (estimate) */
    const char *estimate_skip; /* why not (static), when !estimate_done */
    struct mech_foucault_result estimate;
    double numerical_rate;     /* Richardson |rate - rate_half| / (2^p - 1), rad/s (0: none) */
    double numerical_period;   /* the same for the period, s */
    double achieved;           /* max(numerical_period / period, numerical_rate / W); -2: none */
    double expected_rate;      /* -W sin(lat) + run.airy_rate_mean, rad/s */
    double tolerance_next_order, tolerance_fit; /* rad/s: the formula's neglected terms,
                                                   3 x the fit's standard error */
};

/* Compute *out for request q under budget (the answer's run gets the budget,
 * the estimate what is left of its steps; the deadline is shared).
 * Statuses, err->param naming the request's field:
 *   MECH_EINVAL for a NULL pointer, an unknown run_by, a run_value not finite
 *     and > 0 (the run field), an explicit steps_per_swing outside [1, 1e12];
 *   MECH_EDOMAIN (no param) when the scales are not finite (a scene member
 *     out of range: length, g, latitude_deg, omega_magnitude, amplitude_deg,
 *     azimuth_deg);
 *   MECH_EDOMAIN "precessions" (W sin(lat) = 0), the run field (fewer than 2
 *     swings; swings x steps per swing > 1e12), "fictitious" (Coriolis left
 *     out while W > 0);
 *   MECH_EINVAL from the chooser (its param), or from mech_foucault_integrate
 *     with "steps" -> "integrator/steps_per_swing", "t_end" -> the run field,
 *     "method" -> "integrator/method", its other params unchanged;
 *   MECH_EBUDGET / MECH_EDEADLINE / MECH_ECANCELLED / MECH_ENUMERIC of the
 *     answer's run; a failure of the estimate's run other than budget,
 *     deadline, domain or numeric (those skip the estimate, estimate_skip says).
 * err may be NULL. No allocation; reentrant. */
enum mech_status mech_foucault_scene(const struct mech_foucault_scene_request *q,
                                     const struct mech_budget *budget,
                                     struct mech_foucault_scene *out, struct mech_error *err);

#endif
