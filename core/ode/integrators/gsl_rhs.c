/* integrators/gsl_rhs.c — the right-hand-side wrapper shared by the GSL
 * adapters: a numerical failure on a trial state is a rejected trial, at
 * the accepted state an error (contract in gsl_rhs.h).
 */
#include <stdio.h>
#include <string.h>

#include "ode/integrators/gsl_rhs.h"

void mech_gsl_rhs_begin(struct mech_gsl_rhs *c, const struct mech_ode_system *sys,
                        struct mech_ode_stats *stats, struct mech_error *err, int hard)
{
    c->sys = sys;
    c->stats = stats;
    c->err = err;
    c->status = MECH_OK;
    c->hard = hard;
    c->rejected_trials = 0;
    c->trial_text[0] = '\0';
}

void mech_gsl_rhs_accepted(struct mech_gsl_rhs *c, double t, const double *y)
{
    c->t_acc = t;
    memcpy(c->y_acc, y, c->dim * sizeof *y);
}

static int at_accepted(const struct mech_gsl_rhs *c, double t, const double *y)
{
    return t == c->t_acc && memcmp(y, c->y_acc, c->dim * sizeof *y) == 0;
}

static int hard_failure(struct mech_gsl_rhs *c, enum mech_status code, const char *param,
                        const char *text)
{
    c->status = mech_error_set(c->err, code, param && param[0] ? param : NULL, "%s", text);
    return GSL_EBADFUNC; /* stops the integration at once, cleanly: never abort */
}

int mech_gsl_rhs_numeric(struct mech_gsl_rhs *c, double t, const double *y, const char *text)
{
    if (c->hard || at_accepted(c, t, y)) return hard_failure(c, MECH_ENUMERIC, NULL, text);
    c->rejected_trials++;
    c->trial_t = t;
    snprintf(c->trial_text, sizeof c->trial_text, "%s", text);
    return MECH_GSL_TRIAL_REJECT;
}

/* A failed evaluation (status st, counted already): evaluate again,
 * uncounted, for its explanation. Out of line, so that the hot path below
 * keeps a small frame (no error struct on its stack). */
static __attribute__((noinline, cold)) int rhs_failed(struct mech_gsl_rhs *c, enum mech_status st,
                                                      double t, const double *y, double *dydt)
{
    struct mech_error e;
    mech_error_clear(&e);
    if (mech_ode_eval(c->sys, t, y, dydt, NULL, &e) == MECH_OK || e.code != st)
        snprintf(e.text, sizeof e.text, "the right-hand side failed at t = %.9g s", t);
    if (st == MECH_ENUMERIC) return mech_gsl_rhs_numeric(c, t, y, e.text);
    return hard_failure(c, st, e.param, e.text);
}

int mech_gsl_rhs_eval(struct mech_gsl_rhs *c, double t, const double *y, double *dydt)
{
    /* the hot path records nothing (no error struct to clear per stage) */
    const struct mech_ode_system *sys = c->sys;
    if (sys->flags & MECH_ODE_FINITE_OUTPUT) { /* mech_ode_eval's work, inlined */
        if (c->stats) c->stats->rhs_evaluations++;
        const enum mech_status st = sys->rhs(t, y, dydt, sys->params);
        return st == MECH_OK ? GSL_SUCCESS : rhs_failed(c, st, t, y, dydt);
    }
    const enum mech_status st = mech_ode_eval(sys, t, y, dydt, c->stats, NULL);
    return st == MECH_OK ? GSL_SUCCESS : rhs_failed(c, st, t, y, dydt);
}

int mech_gsl_rhs_fn(double t, const double y[], double dydt[], void *params)
{
    return mech_gsl_rhs_eval(params, t, y, dydt);
}

int mech_gsl_rhs_fn_finite(double t, const double y[], double dydt[], void *params)
{
    /* mech_gsl_rhs_eval's fast path, with only c live across the call (every
     * stage of every step comes here: callgrind, ~35 -> ~19 instructions) */
    struct mech_gsl_rhs *c = params;
    const struct mech_ode_system *sys = c->sys;
    if (c->stats) c->stats->rhs_evaluations++;
    c->call_t = t;
    c->call_y = y;
    c->call_dydt = dydt;
    const enum mech_status st = sys->rhs(t, y, dydt, sys->params);
    return st == MECH_OK ? GSL_SUCCESS : rhs_failed(c, st, c->call_t, c->call_y, c->call_dydt);
}

enum mech_status mech_gsl_rhs_unavoidable(const struct mech_gsl_rhs *c, const char *method,
                                          double t, struct mech_error *err)
{
    return mech_error_set(err, MECH_ENUMERIC, NULL,
                          "%s: %s; no step from t = %.9g s avoids it (the step cannot shrink "
                          "further)",
                          method, c->trial_text[0] ? c->trial_text : "non-finite derivative", t);
}
