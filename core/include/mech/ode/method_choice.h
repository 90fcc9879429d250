/* mech/ode/method_choice.h — the method-choice policy for first-order systems
 * y' = f(t, y) (Euler's equations, tops, Hamilton's equations, geodesics):
 * the one function that turns a target relative error into a method and its
 * settings, with the system's profile handed to the predictive chooser
 * (mech/ode/chooser.h), an optional pilot run (mech/ode/chooser_pilot.h) and the
 * reason the answer shows. Trajectories have their own profile and pipeline
 * (mech_trajectory_choose, mech_trajectory_plan in mech/frames/trajectory.h). */
#ifndef MECH_METHOD_CHOICE_H
#define MECH_METHOD_CHOICE_H

#include <stddef.h>

#include "mech/base/budget.h"
#include "mech/ode/chooser.h"
#include "mech/ode/chooser_pilot.h"
#include "mech/ode/ode.h"
#include "mech/base/status.h"

/* What a first-order system tells the chooser. Strings are static or
 * outlive the call. */
struct mech_first_order_system {
    const char *equations;  /* for the reason, e.g. "Euler's equations with ..." */
    const char *state;      /* for the reason: what atol is relative to */
    double state_scale;     /* atol = rtol x state_scale (<= 0: 1) */
    size_t samples;         /* samples written (each costs a sub-step); 0 if unknown */
    double rhs_cost_s;      /* CPU s of one right-hand side if known, else 0 */
    double span;            /* the run in dynamical times (< 0 or not finite: 0) */
    double cost_span;       /* the run in the cost law's units when span misstates the
                               work (the heavy top); <= 0: span */
    const char *closed_form_name;   /* the exact solution's name, NULL: none */
    int closed_form_allowed;        /* 0: the request said "closed_form": false */
    double closed_form_evaluations; /* predicted evaluations of the closed form (0: one
                                       per sample) and CPU s of one (0: the default) */
    double closed_form_cpu_per_eval;
    const struct mech_pilot_system *pilot; /* NULL: never piloted */
    double error_gain;      /* mech_scene_profile.error_gain (0: 1) */
    const char *rows;       /* mech_scene_profile.rows (NULL: the first_order class's) */
    int second_order;       /* 1: the system also has the form q'' = a(q) (separable
                               Hamiltonians; the caller integrates it so when radau15 is
                               chosen) */
    int defaulted;          /* 1: the request had no integrator block (the reason says
                               that "balanced" was the default) */
};

/* The choice. */
struct mech_method_choice {
    const char *method;          /* the best integrating candidate's method (static),
                                    even when the closed form is chosen */
    struct mech_ode_options opt; /* its rtol, atol (or dt) */
    double target;
    int closed_form;             /* 1: answer from the closed form, integrate nothing */
    struct mech_selection sel;   /* every candidate with its predictions */
    struct mech_pilot_report pilot;
    int pilot_failed;            /* 1: the status came from the pilot run (a run
                                    error), 0: from the choice (a request error) */
    char reason[900];
};

/* Choose how to integrate the system s to `target` relative (in [1e-15,
 * 0.1]): mech_choose on its first-order profile (class first_order, T = 1 so
 * the span is in dynamical times), then, when s->pilot is given and dry_run
 * is 0, mech_choose_pilot, whose steps are taken off budget->max_steps
 * (never below 1; budget may be NULL only when s->pilot is NULL). out is
 * filled on MECH_OK; the reason says what was chosen and why, in the words
 * the answers show.
 * Statuses: MECH_OK; MECH_EINVAL (NULL argument, target out of range, or no
 * candidate applies: err says which, out->pilot_failed = 0); the pilot's
 * run statuses (MECH_EBUDGET, MECH_EDEADLINE, MECH_ENUMERIC, ...) with
 * out->pilot_failed = 1. */
enum mech_status mech_choose_first_order(const struct mech_first_order_system *s, double target,
                                         int dry_run, struct mech_budget *budget,
                                         struct mech_method_choice *out, struct mech_error *err);

#endif
