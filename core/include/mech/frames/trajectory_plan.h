/* mech/frames/trajectory_plan.h — the model → choose pipeline of a trajectory, in
 * one function: which fictitious terms the scene needs ("fictitious":
 * "auto", mech_trajectory_model_select), then the method and tolerances for
 * the target (mech_trajectory_choose), leaving p ready for
 * mech_trajectory_integrate or the exact reference. Used by a single
 * trajectory, by the integrator comparison (mech/answers/frames/compare_sweep.h)
 * and by the scenes (core/frames/scenes.c), so the
 * pipeline exists once. */
#ifndef MECH_TRAJECTORY_PLAN_H
#define MECH_TRAJECTORY_PLAN_H

#include "mech/base/budget.h"
#include "mech/base/status.h"
#include "mech/frames/trajectory.h"

/* What to decide. */
struct mech_trajectory_plan_request {
    int auto_model;      /* 1: "fictitious": "auto" (p->fictitious is then set here) */
    int dry_run;         /* 1: integrate nothing; "auto" keeps every applicable term */
    double model_target; /* relative accuracy the model is chosen for, [1e-15, 0.1] */
    int by_accuracy;     /* 1: choose p->method/opt; 0: they are given in p */
    double target;       /* the chooser's target when by_accuracy, [1e-15, 0.1] */
};

/* Which stage a failure came from. */
enum mech_trajectory_plan_stage {
    MECH_PLAN_OK = 0,
    MECH_PLAN_MODEL,  /* the first pass of "auto" (a run: budget, deadline, numerics) */
    MECH_PLAN_CHOICE, /* the chooser (the request: target out of range, no candidate) */
};

/* What was decided. */
struct mech_trajectory_plan {
    int modelled;                         /* 1: model holds the "auto" decision */
    struct mech_trajectory_model model;
    int chosen;                           /* 1: choice holds the chooser's decision */
    struct mech_trajectory_choice choice;
    int closed_form;                      /* 1: answer from the exact reference (chosen,
                                             and p has one: mech/frames/closed_form.h) */
    enum mech_trajectory_plan_stage failed; /* MECH_PLAN_OK on success */
};

/* Plan p's run for q: with q->auto_model, p->fictitious becomes every
 * applicable term for a dry run, else the terms mech_trajectory_model_select
 * keeps at q->model_target, whose first pass runs on *budget and whose steps
 * are then taken off budget->max_steps (never below 1); with q->by_accuracy,
 * p->method and p->opt become the chooser's for q->target (the best
 * integrator's even when the closed form is chosen: out->closed_form says
 * so). p is changed in place and must stay valid (its forces are borrowed);
 * out is filled on every return.
 * Statuses: MECH_OK; MECH_EINVAL (NULL argument); otherwise those of
 * mech_trajectory_model_select (out->failed = MECH_PLAN_MODEL) or of
 * mech_trajectory_choose (MECH_PLAN_CHOICE), err saying why. */
enum mech_status mech_trajectory_plan(struct mech_trajectory_problem *p,
                                      const struct mech_trajectory_plan_request *q,
                                      struct mech_budget *budget,
                                      struct mech_trajectory_plan *out, struct mech_error *err);

#endif
