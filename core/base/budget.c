/* budget.c — monotonic/CPU clocks and the budget check used by every loop
 * whose length a client controls. */
#include "mech/base/budget.h"

#include <math.h>
#include <time.h>

double mech_clock_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

double mech_cpu_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

struct mech_budget mech_budget_make(long max_steps, double seconds)
{
    struct mech_budget b = {max_steps, mech_clock_seconds() + seconds, NULL};
    return b;
}

enum mech_status mech_budget_check(const struct mech_budget *b, long steps, int force,
                                   struct mech_error *err)
{
    if (!b || b->max_steps <= 0 || !isfinite(b->deadline))
        return mech_error_set(err, MECH_EINVAL, NULL, "no compute budget given");
    enum mech_status st = MECH_OK;
    if (steps > b->max_steps) {
        st = mech_error_set(err, MECH_EBUDGET, NULL,
                            "step budget of %ld steps exhausted", b->max_steps);
    } else if (force || (steps & 255) == 0) {
        /* The flag is raised by another thread (hang-up watcher, shutdown) with an
         * atomic store; a plain read would be a data race (C11 5.1.2.4). */
        if (b->cancel && __atomic_load_n(b->cancel, __ATOMIC_RELAXED))
            st = mech_error_set(err, MECH_ECANCELLED, NULL, "computation cancelled");
        else if (mech_clock_seconds() > b->deadline)
            st = mech_error_set(err, MECH_EDEADLINE, NULL, "deadline passed");
    }
    if (st != MECH_OK && err && err->code == st) err->progress.steps = steps;
    return st;
}
