/* integrators/gsl_rhs.h — the right-hand-side wrapper shared by the GSL
 * adapters (gsl_rk.c: rk8pd, rkck, rkf45; gsl_msbdf.c: msbdf, bsimp).
 *
 * GSL's evolve (gsl_odeiv2_evolve_apply) stops at once when the function
 * returns GSL_EBADFUNC, and halves the step and retries on any other
 * non-success status. The wrapper uses that split:
 *   - a non-numerical failure of the right-hand side (cancel, deadline,
 *     budget, domain, memory) is hard: recorded in the caller's error,
 *     GSL_EBADFUNC;
 *   - a numerical failure (a non-finite derivative, or the rhs's own
 *     MECH_ENUMERIC) on a TRIAL state is a rejected trial: nothing is
 *     recorded, MECH_GSL_TRIAL_REJECT is returned and GSL shrinks the step
 *     like a failed error test (a trial step overshooting into a region
 *     where the force is undefined is not the run's fault);
 *   - the same failure at the ACCEPTED state (the (t, y) evolve started
 *     from, registered with mech_gsl_rhs_accepted) is hard: no smaller step
 *     can avoid it.
 * When GSL cannot shrink the step any further it returns
 * MECH_GSL_TRIAL_REJECT itself; mech_gsl_rhs_unavoidable() turns that into
 * MECH_ENUMERIC naming the last failed trial.
 * Not thread-shared: one context per workspace.
 */
#ifndef MECH_INTEGRATORS_GSL_RHS_H
#define MECH_INTEGRATORS_GSL_RHS_H

#include <stddef.h>

#include <gsl/gsl_errno.h>

#include "ode/integrators/integrator.h"

/* The status handed to GSL for a rejected trial (any code GSL's evolve
 * treats as "retry with a smaller step", and that neither adapter gives
 * another meaning). */
#define MECH_GSL_TRIAL_REJECT GSL_ERANGE

struct mech_gsl_rhs {
    const struct mech_ode_system *sys;
    struct mech_ode_stats *stats;
    struct mech_error *err;
    enum mech_status status; /* the hard failure's status; MECH_OK if none */
    int hard;                /* every failure is hard (fixed sub-steps) */
    size_t dim;
    double t_acc;            /* the accepted state (see header) */
    double *y_acc;           /* dim values, owned by the adapter's workspace */
    long rejected_trials;    /* trials rejected as non-finite since begin */
    double trial_t;          /* time of the last rejected trial */
    char trial_text[200];    /* its explanation */
    /* the arguments of the evaluation in progress (mech_gsl_rhs_fn's fast
     * path keeps them here rather than in registers across the call) */
    double call_t;
    const double *call_y;
    double *call_dydt;
};

/* Start a call: bind the system, statistics and error (borrowed for the
 * call); hard != 0 makes every failure hard (a single fixed step, where
 * there is no smaller step to retry with). Clears the recorded status. */
void mech_gsl_rhs_begin(struct mech_gsl_rhs *c, const struct mech_ode_system *sys,
                        struct mech_ode_stats *stats, struct mech_error *err, int hard);

/* Register the accepted state (t, y) evolve starts from; copies y into
 * c->y_acc (c->dim values). */
void mech_gsl_rhs_accepted(struct mech_gsl_rhs *c, double t, const double *y);

/* Evaluate the right-hand side at (t, y) into dydt through mech_ode_eval
 * (counted in the statistics). Returns GSL_SUCCESS, MECH_GSL_TRIAL_REJECT
 * or GSL_EBADFUNC (header). */
int mech_gsl_rhs_eval(struct mech_gsl_rhs *c, double t, const double *y, double *dydt);

/* Classify a numerical failure found by the adapter itself at (t, y) (e.g.
 * a non-finite Jacobian): text is the explanation. Returns
 * MECH_GSL_TRIAL_REJECT on a trial state, GSL_EBADFUNC (recorded as
 * MECH_ENUMERIC) at the accepted state or in hard mode. */
int mech_gsl_rhs_numeric(struct mech_gsl_rhs *c, double t, const double *y, const char *text);

/* The GSL callback form of mech_gsl_rhs_eval (params is the context). */
int mech_gsl_rhs_fn(double t, const double y[], double dydt[], void *params);
/* The same for a system flagged MECH_ODE_FINITE_OUTPUT (and only for one):
 * fewer instructions per evaluation, the same results. */
int mech_gsl_rhs_fn_finite(double t, const double y[], double dydt[], void *params);

/* MECH_GSL_TRIAL_REJECT came back from GSL (the step cannot shrink any
 * further): record MECH_ENUMERIC naming the method, t and the last failed
 * trial; returns MECH_ENUMERIC. */
enum mech_status mech_gsl_rhs_unavoidable(const struct mech_gsl_rhs *c, const char *method,
                                          double t, struct mech_error *err);

#endif
