/* mech/base/budget.h — compute budgets every integration must honour.
 *
 * A budget is a mandatory input of every loop whose length a client controls:
 * a step limit, an absolute deadline on the monotonic clock, and an optional
 * cancel flag raised by another thread. Never unlimited: max_steps must be > 0
 * and deadline finite.
 */
#ifndef MECH_BUDGET_H
#define MECH_BUDGET_H

#include "mech/base/status.h"

struct mech_budget {
    long max_steps;             /* > 0: steps allowed for the whole computation */
    double deadline;            /* absolute time in mech_clock_seconds() units */
    const volatile int *cancel; /* may be NULL; nonzero means stop now */
};

/* Monotonic clock in seconds (CLOCK_MONOTONIC). Thread-safe. */
double mech_clock_seconds(void);

/* Thread CPU time in seconds (CLOCK_THREAD_CPUTIME_ID). Thread-safe. */
double mech_cpu_seconds(void);

/* A budget of max_steps steps and `seconds` of wall time from now. */
struct mech_budget mech_budget_make(long max_steps, double seconds);

/* Check a budget after `steps` steps. Cheap: reads the clock and the cancel
 * flag only when steps is a multiple of 256 (or force != 0). Returns MECH_OK,
 * MECH_EBUDGET, MECH_EDEADLINE or MECH_ECANCELLED (and records it in err with
 * progress.steps = steps; the caller fills t_reached/t_target).
 * A NULL budget or max_steps <= 0 is MECH_EINVAL. */
enum mech_status mech_budget_check(const struct mech_budget *b, long steps, int force,
                                   struct mech_error *err);

#endif
