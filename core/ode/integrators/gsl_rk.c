/* integrators/gsl_rk.c — the adaptive explicit Runge–Kutta pairs of GSL
 * gsl_odeiv2 (rk8pd, rkck, rkf45) behind libmech's stepper interface.
 *
 * evolve() is gsl_odeiv2_evolve_apply with the standard control
 * D_i = atol + rtol |y_i| (gsl_odeiv2_control_y_new); step() is a single
 * gsl_odeiv2_step_apply on a SECOND stepper object, so sub-steps (samples,
 * event location) never disturb the main stepper's state. GSL's driver
 * (and its fixed-step driver, which fails when the error estimate is large)
 * is not used; the step budget is libmech's (ode.c), so GSL's nmax does not
 * apply. The right-hand side goes through the wrapper shared with msbdf
 * (gsl_rhs.h): a non-finite derivative on a trial stage is a rejected trial
 * (GSL halves the step), only one at the accepted state stops the run.
 * Every GSL status is mapped:
 *   GSL_SUCCESS -> MECH_OK; GSL_EBADFUNC -> the status the right-hand side
 *   returned (MECH_ENUMERIC for a non-finite value at the accepted state);
 *   MECH_GSL_TRIAL_REJECT (no smaller step avoids a non-finite trial) ->
 *   MECH_ENUMERIC; GSL_FAILURE (tolerance
 *   unreachable, step cannot shrink further) -> MECH_ENUMERIC;
 *   GSL_ENOMEM -> MECH_ENOMEM; GSL_EINVAL / GSL_EFAULT (a libmech bug) ->
 *   MECH_EINTERNAL; anything else -> MECH_ENUMERIC with gsl_strerror().
 * After any failure the caller resets the workspace (evolve, control and
 * both steppers are reset).
 *
 * References: rk8pd — P. J. Prince and J. R. Dormand, J. Comp. Appl. Math. 7
 * (1981) 67–75 (RK8(7)13M); rkck — J. R. Cash and A. H. Karp, ACM TOMS 16
 * (1990) 201–222; rkf45 — E. Fehlberg, NASA TR R-315 (1969); GSL Reference
 * Manual, "Ordinary Differential Equations".
 */
#include <math.h>
#include <stdlib.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include "ode/integrators/gsl_rhs.h"
#include "ode/integrators/integrator.h"

struct gsl_rk_ws {
    gsl_odeiv2_step *main;    /* used by evolve() */
    gsl_odeiv2_step *aux;     /* used by step() (sub-steps) */
    gsl_odeiv2_control *con;
    gsl_odeiv2_evolve *ev;
    double *yerr, *dydt_out;  /* scratch for step() */
    size_t dim;
    const char *name;
    struct mech_gsl_rhs rhs; /* per-call context seen by the GSL callback */
};

static void gsl_rk_free(void *ws)
{
    struct gsl_rk_ws *w = ws;
    if (!w) return;
    if (w->main) gsl_odeiv2_step_free(w->main);
    if (w->aux) gsl_odeiv2_step_free(w->aux);
    if (w->con) gsl_odeiv2_control_free(w->con);
    if (w->ev) gsl_odeiv2_evolve_free(w->ev);
    free(w->yerr);
    free(w->dydt_out);
    free(w->rhs.y_acc);
    free(w);
}

static enum mech_status gsl_rk_alloc_type(void **ws, size_t dim, const struct mech_ode_options *opt,
                                          const gsl_odeiv2_step_type *type, const char *name,
                                          struct mech_error *err)
{
    struct gsl_rk_ws *w = calloc(1, sizeof *w);
    if (!w) return mech_error_set(err, MECH_ENOMEM, NULL, "%s: out of memory", name);
    w->dim = dim;
    w->name = name;
    w->main = gsl_odeiv2_step_alloc(type, dim);
    w->aux = gsl_odeiv2_step_alloc(type, dim);
    w->con = gsl_odeiv2_control_y_new(opt->atol, opt->rtol);
    w->ev = gsl_odeiv2_evolve_alloc(dim);
    w->yerr = malloc(dim * sizeof *w->yerr);
    w->dydt_out = malloc(dim * sizeof *w->dydt_out);
    w->rhs.dim = dim;
    w->rhs.y_acc = malloc(dim * sizeof *w->rhs.y_acc);
    if (!w->main || !w->aux || !w->con || !w->ev || !w->yerr || !w->dydt_out || !w->rhs.y_acc) {
        gsl_rk_free(w);
        return mech_error_set(err, MECH_ENOMEM, NULL, "%s: out of memory", name);
    }
    *ws = w;
    return MECH_OK;
}

static void gsl_rk_reset(void *ws)
{
    struct gsl_rk_ws *w = ws;
    if (!w) return;
    gsl_odeiv2_step_reset(w->main);
    gsl_odeiv2_step_reset(w->aux);
    gsl_odeiv2_evolve_reset(w->ev); /* the control object keeps no history */
}

/* The GSL callback for sys: the shorter one when sys tests its own output. */
static int (*rhs_fn_of(const struct mech_ode_system *sys))(double, const double[], double[], void *)
{
    return (sys->flags & MECH_ODE_FINITE_OUTPUT) ? mech_gsl_rhs_fn_finite : mech_gsl_rhs_fn;
}

/* Map a GSL status (after a call that may have run our rhs) to mech_status. */
static enum mech_status gsl_rk_map(struct gsl_rk_ws *w, int gs, double t, double h,
                                   struct mech_error *err)
{
    switch (gs) {
    case GSL_SUCCESS:
        return MECH_OK;
    case MECH_GSL_TRIAL_REJECT:
        return mech_gsl_rhs_unavoidable(&w->rhs, w->name, t, err);
    case GSL_EBADFUNC:
        if (w->rhs.status != MECH_OK)
            return mech_error_set(err, w->rhs.status, NULL,
                                  "%s: the right-hand side failed at t = %.9g s", w->name, t);
        return mech_error_set(err, MECH_ENUMERIC, NULL, "%s: bad function value at t = %.9g s",
                              w->name, t);
    case GSL_FAILURE:
        return mech_error_set(err, MECH_ENUMERIC, NULL,
                              "%s: cannot reach the requested tolerance at t = %.9g s (step size "
                              "%.3g s cannot shrink further)",
                              w->name, t, h);
    case GSL_ENOMEM:
        return mech_error_set(err, MECH_ENOMEM, NULL, "%s: out of memory", w->name);
    case GSL_EINVAL:
    case GSL_EFAULT:
        return mech_error_set(err, MECH_EINTERNAL, NULL, "%s: GSL rejected its arguments: %s",
                              w->name, gsl_strerror(gs));
    default:
        return mech_error_set(err, MECH_ENUMERIC, NULL, "%s: GSL failed at t = %.9g s: %s",
                              w->name, t, gsl_strerror(gs));
    }
}

static enum mech_status gsl_rk_step(void *ws, const struct mech_ode_system *sys, double t,
                                    double h, double *y, struct mech_ode_stats *stats,
                                    struct mech_error *err)
{
    struct gsl_rk_ws *w = ws;
    mech_gsl_rhs_begin(&w->rhs, sys, stats, err, 1); /* one fixed step: no retry */
    gsl_odeiv2_system gsys = {rhs_fn_of(sys), NULL, w->dim, &w->rhs};
    gsl_odeiv2_step_reset(w->aux);
    int gs = gsl_odeiv2_step_apply(w->aux, t, h, y, w->yerr, NULL, w->dydt_out, &gsys);
    return gsl_rk_map(w, gs, t, h, err);
}

static enum mech_status gsl_rk_evolve(void *ws, const struct mech_ode_system *sys, double *t,
                                      double t1, double *h, double *y,
                                      struct mech_ode_stats *stats, struct mech_error *err)
{
    struct gsl_rk_ws *w = ws;
    mech_gsl_rhs_begin(&w->rhs, sys, stats, err, 0);
    mech_gsl_rhs_accepted(&w->rhs, *t, y);
    gsl_odeiv2_system gsys = {rhs_fn_of(sys), NULL, w->dim, &w->rhs};
    const unsigned long failed_before = w->ev->failed_steps;
    const double t_before = *t;
    int gs = gsl_odeiv2_evolve_apply(w->ev, w->con, w->main, &gsys, t, t1, h, y);
    stats->rejected_steps += (long)(w->ev->failed_steps - failed_before);
    enum mech_status st = gsl_rk_map(w, gs, *t, *h, err);
    if (st != MECH_OK) return st;
    if (!(*t > t_before) || !isfinite(*h) || !(*h > 0.0))
        return mech_error_set(err, MECH_ENUMERIC, NULL,
                              "%s: step size underflow at t = %.9g s", w->name, t_before);
    return MECH_OK;
}

/* GSL's evolve evaluates f at the step's start (dydt_in, for the steppers
 * that take it: rk8pd, rkck, rkf45 all do) and hands every trial the buffer
 * dydt_out, which these steppers fill with f at the new state; after a
 * successful evolve both belong to the accepted step. */
static int gsl_rk_step_derivs(void *ws, const double **f_start, const double **f_end)
{
    const struct gsl_rk_ws *w = ws;
    if (!w->main->type->can_use_dydt_in) return 0;
    *f_start = w->ev->dydt_in;
    *f_end = w->ev->dydt_out;
    return 1;
}

static enum mech_status rk8pd_alloc(void **ws, size_t dim, const struct mech_ode_options *opt,
                                    struct mech_error *err)
{
    return gsl_rk_alloc_type(ws, dim, opt, gsl_odeiv2_step_rk8pd, "rk8pd", err);
}
static enum mech_status rkck_alloc(void **ws, size_t dim, const struct mech_ode_options *opt,
                                   struct mech_error *err)
{
    return gsl_rk_alloc_type(ws, dim, opt, gsl_odeiv2_step_rkck, "rkck", err);
}
static enum mech_status rkf45_alloc(void **ws, size_t dim, const struct mech_ode_options *opt,
                                    struct mech_error *err)
{
    return gsl_rk_alloc_type(ws, dim, opt, gsl_odeiv2_step_rkf45, "rkf45", err);
}

const struct mech_integrator mech_integrator_rk8pd = {
    .name = "rk8pd",
    .order = 8,
    .flags = MECH_INTEGRATOR_ADAPTIVE | MECH_INTEGRATOR_EXPLICIT,
    .doc = "Adaptive explicit Runge-Kutta-Prince-Dormand 8(7), 13 stages, error control "
           "atol + rtol |y| per component (GSL gsl_odeiv2_step_rk8pd). The reference method for "
           "tight tolerances.",
    .reference = "P. J. Prince, J. R. Dormand, J. Comp. Appl. Math. 7 (1981) 67-75 (GSL "
                 "ode-initval2/rk8pd.c).",
    .alloc = rk8pd_alloc,
    .reset = gsl_rk_reset,
    .free = gsl_rk_free,
    .step = gsl_rk_step,
    .evolve = gsl_rk_evolve,
    .step_derivs = gsl_rk_step_derivs,
};

const struct mech_integrator mech_integrator_rkck = {
    .name = "rkck",
    .order = 5,
    .flags = MECH_INTEGRATOR_ADAPTIVE | MECH_INTEGRATOR_EXPLICIT,
    .doc = "Adaptive explicit Runge-Kutta Cash-Karp 5(4), 6 stages (GSL "
           "gsl_odeiv2_step_rkck).",
    .reference = "J. R. Cash, A. H. Karp, ACM Trans. Math. Softw. 16 (1990) 201-222 (GSL "
                 "ode-initval2/rkck.c).",
    .alloc = rkck_alloc,
    .reset = gsl_rk_reset,
    .free = gsl_rk_free,
    .step = gsl_rk_step,
    .evolve = gsl_rk_evolve,
    .step_derivs = gsl_rk_step_derivs,
};

const struct mech_integrator mech_integrator_rkf45 = {
    .name = "rkf45",
    .order = 5,
    .flags = MECH_INTEGRATOR_ADAPTIVE | MECH_INTEGRATOR_EXPLICIT,
    .doc = "Adaptive explicit Runge-Kutta-Fehlberg 4(5), 6 stages (GSL gsl_odeiv2_step_rkf45); "
           "a general-purpose method for moderate tolerances.",
    .reference = "E. Fehlberg, NASA Technical Report R-315 (1969) (GSL ode-initval2/rkf45.c).",
    .alloc = rkf45_alloc,
    .reset = gsl_rk_reset,
    .free = gsl_rk_free,
    .step = gsl_rk_step,
    .evolve = gsl_rk_evolve,
    .step_derivs = gsl_rk_step_derivs,
};
