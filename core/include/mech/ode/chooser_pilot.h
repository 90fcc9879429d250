/* mech/ode/chooser_pilot.h — a short pilot run where the chooser's prediction is
 * uncertain and being wrong is expensive (a short pilot run where
 * that is cheaper than being wrong).
 *
 * The calibrated table (mech/ode/chooser.h) has no closed-form estimate of the
 * step count for some systems (the heavy top, Hamiltonian flows such as
 * Henon-Heiles, geodesics in strong field): its cost law was fitted on other
 * scenes of the class. When such a run is predicted to cost more than
 * MECH_PILOT_THRESHOLD_S, mech_choose_pilot integrates the system itself over
 * a small fraction of the span with each plausible candidate at its chosen
 * setting (the pilot together costs at most MECH_PILOT_COST_FRACTION of the
 * chosen candidate's predicted evaluations), counts the evaluations,
 * extrapolates them to the whole span (evaluations per unit time are
 * constant on average over a long run of a bounded motion), and measures the
 * chosen candidate's error over the pilot against the same run at a 100x
 * tighter tolerance, extrapolated with the table's span exponent. The
 * selection is then re-made on the piloted costs, and the report says what
 * the pilot did and what it cost. A dry run never pilots: its prediction is
 * the table's, said to be unpiloted.
 *
 * Everything reported is deterministic (evaluations, not seconds).
 * Thread-safety: reentrant; the system's run function must be. */
#ifndef MECH_CHOOSER_PILOT_H
#define MECH_CHOOSER_PILOT_H

#include <stddef.h>

#include "mech/base/budget.h"
#include "mech/ode/chooser.h"
#include "mech/ode/ode.h"
#include "mech/base/status.h"

/* Pilot only runs predicted to cost more than this (CPU s, the chosen
 * candidate's predicted_cpu_s). */
#define MECH_PILOT_THRESHOLD_S 0.05
/* The pilot's evaluations, all candidates and the error estimate together,
 * at most this fraction of the chosen candidate's predicted evaluations. */
#define MECH_PILOT_COST_FRACTION 0.02
/* The largest state a pilot compares for its error estimate. */
#define MECH_PILOT_MAX_DIM 64

/* A system the chooser can pilot. run integrates the operation's own system
 * from its initial state over the first `fraction` (0 < fraction <= 1) of
 * the requested span with `method` (a first-order registry method) at `opt`
 * (the chooser's setting, in the operation's units), honouring `budget`;
 * it fills stats (steps, evaluations) and the end state y_end[0..*dim-1]
 * (*dim <= MECH_PILOT_MAX_DIM, in units where the profile's scale applies;
 * *dim = 0: no state to compare). Returns a mech_status; err may be NULL. */
struct mech_pilot_system {
    enum mech_status (*run)(void *ctx, const char *method, const struct mech_ode_options *opt,
                            double fraction, const struct mech_budget *budget,
                            struct mech_ode_stats *stats, double *y_end, size_t *dim,
                            struct mech_error *err);
    void *ctx; /* borrowed, the caller's */
};

struct mech_pilot_report {
    int considered;        /* 1: the prediction was above the threshold */
    int run;               /* 1: a pilot ran */
    int dry_run;           /* 1: a dry run: not piloted */
    double fraction;       /* of the span piloted */
    long steps;            /* the pilot's own steps and evaluations (all its runs) */
    double evaluations;
    double predicted_cpu_s;  /* its evaluations at the table's CPU per evaluation */
    double table_evaluations; /* the chosen candidate's table prediction before the pilot */
    double error;          /* the chosen candidate's error over the pilot (< 0: not measured) */
    double error_extrapolated; /* to the whole span with the table's span exponent */
    char why[400];
};

/* After mech_choose filled *sel for profile s and target: when sys is given
 * and the chosen integrating candidate's predicted CPU exceeds
 * MECH_PILOT_THRESHOLD_S, pilot it (and the other candidates predicted to
 * meet the target within 3x its cost) as described above, replace their
 * predicted_evaluations and predicted_cpu_s by the extrapolation and re-make
 * the choice among the candidates predicted to meet the target; dry_run != 0
 * runs nothing and says the prediction is unpiloted. The closed form, when
 * chosen, is never piloted. rep is always filled (considered = 0 when below
 * the threshold or no system). budget: the request's; the pilot's steps
 * count against it (the caller subtracts rep->steps from what the main run
 * may take). Statuses: MECH_OK; MECH_EINVAL (NULL s, sel or rep); a pilot
 * run's failure other than budget or numerics is returned (EDEADLINE,
 * ECANCELLED); EBUDGET and ENUMERIC in a pilot keep the table's prediction
 * and say so. */
enum mech_status mech_choose_pilot(const struct mech_scene_profile *s, double target,
                                   struct mech_selection *sel,
                                   const struct mech_pilot_system *sys, int dry_run,
                                   const struct mech_budget *budget,
                                   struct mech_pilot_report *rep, struct mech_error *err);

/* The table's row for `method` on s's class, as the pilot extrapolates
 * with it: CPU seconds per evaluation (raised to s->rhs_cost_s), the
 * evaluations each sample adds, the span exponent b of the error law.
 * Returns 1, or 0 when the table has no row (out untouched). */
struct mech_chooser_row_info {
    double cpu_per_eval, per_sample, span_exponent;
};
int mech_chooser_row_info(const struct mech_scene_profile *s, const char *method,
                          struct mech_chooser_row_info *out);

#endif
