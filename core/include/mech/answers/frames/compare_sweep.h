/* mech/answers/frames/compare_sweep.h — the runs of POST /v1/compare: one trajectory scene
 * run with several integrator settings, each measured against the best
 * reference available, sharing one step budget and deadline. The reference
 * is the scene's exact solution when it has one (mech/frames/reference.h: kepler,
 * harmonic oscillator, uniform gravity with or without linear drag);
 * otherwise a radau15 run at its round-off setting (rtol 1e-10, the floor of
 * its eps; core/ode/integrators/radau15.c). A first-order reference (the
 * Coriolis formulas) is not used: its own O(W^2) error would hide the
 * differences between methods. SI units throughout. Thread-safe. */
#ifndef MECH_COMPARE_SWEEP_H
#define MECH_COMPARE_SWEEP_H

#include <stddef.h>

#include "mech/base/budget.h"
#include "mech/base/status.h"
#include "mech/frames/trajectory.h"

#define MECH_COMPARE_MAX_RUNS 64
#define MECH_COMPARE_REFERENCE_METHOD "radau15"
#define MECH_COMPARE_REFERENCE_RTOL 1e-10

/* One configuration: the scene with its method and opt set (borrowed; its
 * samples, t_end and forces those of the base scene), and whether it is
 * answered from the closed form (mech_trajectory_closed_form_ex, 0 steps)
 * instead of integrated. */
struct mech_compare_config {
    const struct mech_trajectory_problem *p;
    int closed_form;
};

enum mech_compare_state {
    MECH_COMPARE_RUN_OK = 0, /* ran to its end: errors, invariants and stats set */
    MECH_COMPARE_RUN_FAILED, /* failed numerically (ENUMERIC) or its method does not apply
                                (EINVAL/EDOMAIN on an "integrator..." parameter): status, err */
    MECH_COMPARE_RUN_NOT_RUN /* the shared budget ran out during it (the run at
                                mech_compare_result.stopped_run: status, err with its
                                progress) or before it started (every later run) */
};

struct mech_compare_row {
    enum mech_compare_state state;
    enum mech_status status; /* the run's status (MECH_OK when it ran to its end) */
    struct mech_error err;   /* failed, stopped: the core's words and progress */
    /* RUN_OK: against the reference, over the common samples and the stop point */
    double max_position_error;          /* m */
    double final_position_error;        /* m, at the last common sample or the stop */
    double max_velocity_error;          /* m/s */
    double max_relative_position_error; /* / max |r_ref| (0 when that is 0) */
    double max_relative_velocity_error; /* / max |v_ref| (0 when that is 0) */
    struct mech_trajectory_invariant invariants[MECH_TRAJECTORY_MAX_INVARIANTS];
    size_t n_invariants;
    struct mech_ode_stats stats;
    double cpu_seconds; /* measured: RUN_OK and the stopped run; 0 otherwise */
};

struct mech_compare_result {
    int reference_exact;                   /* 1: the scene's exact solution; 0: the radau15 run */
    const char *reference_name;            /* the solution's or the method's name (static) */
    struct mech_ode_stats reference_stats; /* the radau15 run's (zero when exact) */
    double reference_cpu_seconds;          /* the radau15 run's; -1 when exact */
    int partial;                           /* 1: the budget ran out after a run finished */
    size_t stopped_run;                    /* partial: the run that was stopped */
    long total_steps; /* every step taken (reference, runs, stopped progress) */
    long failed_run;  /* on a failing status: the run it belongs to, -1 the
                         reference run, -2 none (EINVAL "samples", ENOMEM) */
};

/* Run the scene `base` (method and opt ignored; samples >= 2) under each of
 * the n <= MECH_COMPARE_MAX_RUNS configurations in order, after the
 * reference, all within *budget (mandatory): each run gets the steps the
 * earlier ones left, and the deadline is the request's. rows (caller-owned,
 * n entries) are all filled on MECH_OK; the reference's description and the
 * totals go to *out (always initialised).
 * Returns MECH_OK, with out->partial = 1 when the budget (EBUDGET,
 * EDEADLINE) ran out during run k after at least one run finished (run k
 * and the later ones are RUN_NOT_RUN). Otherwise the failing status, with
 * err (may be NULL) and out->failed_run naming the run: any failure of the
 * reference run (-1); a run's failure that is not RUN_FAILED, or its budget
 * running out before any run finished (k, out->total_steps counting its
 * progress); EINVAL "samples" when the sample buffers' size would overflow
 * and ENOMEM (-2). The configurations' problems are not modified. */
enum mech_status mech_compare_sweep(const struct mech_trajectory_problem *base,
                                    const struct mech_compare_config *runs, size_t n,
                                    const struct mech_budget *budget, struct mech_compare_row *rows,
                                    struct mech_compare_result *out, struct mech_error *err);

#endif
