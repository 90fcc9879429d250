/* foucault_scene.c — one POST /v1/scenes/foucault computation
 * (mech/answers/frames/foucault_scene.h): the scales and the centrifugal estimate of
 * foucault_first_order.c, the chooser of chooser_pendulum.c, the runs of
 * pendulum.c, and the Richardson estimate and expected rate beside them.
 * Moved from api/ops/scenes/foucault.c (a handler only parses, calls core once
 * and encodes) operation for operation, so the API's answers stay
 * byte-identical. */
#include "mech/answers/frames/foucault_scene.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mech/frames/chooser_pendulum.h"
#include "mech/base/constants.h"

/* What the scales and the run's length need before the scene's own checks
 * (the API's schema guarantees them; a direct caller gets EINVAL). */
static enum mech_status scene_input_ok(const struct mech_foucault_scene_request *q,
                                       struct mech_foucault_scene *o, struct mech_error *err)
{
    static const char *const field[] = {"swings", "precessions", "duration"};
    if ((unsigned)q->run_by > MECH_FOUCAULT_RUN_DURATION)
        return mech_error_set(err, MECH_EINVAL, NULL, "unknown run length kind %d", (int)q->run_by);
    if (!(isfinite(q->run_value) && q->run_value > 0.0))
        return mech_error_set(err, MECH_EINVAL, field[q->run_by], "must be finite and > 0, got %.17g",
                              q->run_value);
    if (q->explicit_integrator && !(q->steps_per_swing >= 1.0 && q->steps_per_swing <= 1e12))
        return mech_error_set(err, MECH_EINVAL, "integrator/steps_per_swing",
                              "steps per swing must be in [1, 1e12], got %.17g", q->steps_per_swing);
    if (!(isfinite(o->scales.period) && o->scales.period > 0.0))
        return mech_error_set(err, MECH_EDOMAIN, NULL,
                              "the swing period is not finite: length (0, 1e7] m, g (0, 1e4], "
                              "latitude_deg [-90, 90], omega_magnitude [0, 1], amplitude_deg "
                              "(0, 90) or azimuth_deg finite is out of range");
    return MECH_OK;
}

/* The run's length t_end (s) and the field it was given in; MECH_EDOMAIN
 * when a precession cannot be counted or fewer than 2 swings fit. */
static enum mech_status run_length(const struct mech_foucault_scene_request *q,
                                   struct mech_foucault_scene *o, struct mech_error *err)
{
    const double wz = o->scales.omega_vertical, period = o->scales.period;
    double t_end;
    if (q->run_by == MECH_FOUCAULT_RUN_PRECESSIONS) {
        o->run_field = "precessions";
        if (!(fabs(wz) > 0.0))
            return mech_error_set(err, MECH_EDOMAIN, "precessions",
                                  "the swing plane does not precess at W sin(lat) = 0 (equator "
                                  "or W = 0): give swings or duration");
        t_end = q->run_value * 2.0 * MECH_PI / fabs(wz);
    } else if (q->run_by == MECH_FOUCAULT_RUN_DURATION) {
        o->run_field = "duration";
        t_end = q->run_value;
    } else {
        o->run_field = "swings";
        t_end = q->run_value * period;
    }
    o->problem.t_end = t_end;
    o->swings_asked = t_end / period;
    if (o->swings_asked < 2.0)
        return mech_error_set(err, MECH_EDOMAIN, o->run_field,
                              "the run is %.6g swings of %.6g s: at least 2 are needed to "
                              "measure a precession",
                              o->swings_asked, period);
    return MECH_OK;
}

/* The predictive chooser's method and steps per swing, and the reason. */
static enum mech_status choose(const struct mech_foucault_scene_request *q,
                               struct mech_foucault_scene *o, struct mech_error *err)
{
    struct mech_pendulum_profile prof = {o->scales.period, o->swings_asked, o->scales.alpha,
                                         q->problem.omega_magnitude * o->problem.t_end,
                                         q->error_estimate};
    enum mech_pendulum_method cm;
    struct mech_error ce;
    mech_error_clear(&ce);
    if (mech_choose_pendulum(&prof, q->target, &o->selection, &cm, &o->steps_per_swing, &ce) !=
        MECH_OK) {
        if (err && err->code == MECH_OK) {
            *err = ce;
            err->code = MECH_EINVAL;
        }
        return MECH_EINVAL;
    }
    o->chosen = 1;
    o->problem.method = cm;
    const struct mech_candidate *k = &o->selection.c[o->selection.chosen];
    char beyond[320];
    mech_selection_beyond_text(&o->selection, beyond, sizeof beyond);
    snprintf(o->reason, sizeof o->reason,
             o->selection.beyond == 2
                 ? "%s%s at %.0f steps per swing is the cheapest of the most accurate "
                   "candidates; none is predicted to meet %.0e relative on the period and "
                   "the precession rate / W over %.6g swings (predicted %.2g, %.0f force "
                   "evaluations%s)%s"
                 : "%s%s at %.0f steps per swing is the cheapest candidate predicted to "
                   "meet %.0e relative on the period and the precession rate / W over %.6g "
                   "swings (predicted %.2g, %.0f force evaluations%s)%s",
             q->target_defaulted ? "target_error 1e-6 by default: " : "", k->method,
             o->steps_per_swing, q->target, o->swings_asked, k->predicted_error,
             k->predicted_evaluations, q->error_estimate ? " with the error estimate's run" : "",
             beyond);
    return MECH_OK;
}

/* The model's terms: Coriolis required while W > 0; the centrifugal term
 * given, or "auto" when its estimated effect exceeds target / 10. */
static enum mech_status model_terms(const struct mech_foucault_scene_request *q,
                                    struct mech_foucault_scene *o, struct mech_error *err)
{
    const double W = q->problem.omega_magnitude;
    if (!q->auto_terms && !q->given_coriolis && W > 0.0)
        return mech_error_set(err, MECH_EDOMAIN, "fictitious",
                              "the Coriolis term is the Foucault effect (it turns the swing plane "
                              "at W sin(lat)); it cannot be left out of this scene");
    mech_foucault_centrifugal_effect(&o->scales, W, q->problem.length, o->problem.t_end,
                                     &o->centrifugal);
    o->problem.centrifugal = q->auto_terms ? (W > 0.0 && o->centrifugal.relative > q->target / 10.0)
                                           : q->given_centrifugal;
    return MECH_OK;
}

/* The core's parameter names of the run as the request's fields. */
static void name_run_param(struct mech_error *e, const char *run_field)
{
    const char *to = NULL;
    if (!strcmp(e->param, "steps"))
        to = "integrator/steps_per_swing";
    else if (!strcmp(e->param, "t_end"))
        to = run_field;
    else if (!strcmp(e->param, "method"))
        to = "integrator/method";
    if (to) snprintf(e->param, sizeof e->param, "%s", to);
}

/* The same method at half the steps, on the steps the answer's run left;
 * budget, deadline, domain and numeric failures skip it. */
static enum mech_status estimate_run(const struct mech_budget *budget,
                                     struct mech_foucault_scene *o, struct mech_error *err)
{
    o->estimate_skip = "not asked (error_estimate: false)";
    struct mech_foucault_problem half = o->problem;
    half.steps = (o->problem.steps + 1) / 2;
    struct mech_budget b2 = *budget;
    b2.max_steps = budget->max_steps - o->problem.steps;
    struct mech_error e2;
    mech_error_clear(&e2);
    enum mech_status st2 = MECH_EBUDGET;
    if (b2.max_steps >= half.steps) st2 = mech_foucault_integrate(&half, &b2, &o->estimate, &e2);
    if (st2 == MECH_OK) {
        o->estimate_done = 1;
    } else if (st2 == MECH_EBUDGET || st2 == MECH_EDEADLINE) {
        o->estimate_skip = "skipped: the step budget or the time left is too small";
    } else if (st2 == MECH_EDOMAIN || st2 == MECH_ENUMERIC) {
        o->estimate_skip = "skipped: half the steps per swing is too coarse";
    } else {
        if (err && err->code == MECH_OK) *err = e2;
        return st2;
    }
    return MECH_OK;
}

/* Richardson: the answer's run (N steps) errs by ~ (its result - the N/2
 * run's) / (2^p - 1); the expected rate and its tolerances. */
static void compare(struct mech_foucault_scene *o)
{
    const double W = o->problem.omega_magnitude;
    const struct mech_foucault_result *r = &o->run, *h = &o->estimate;
    double rich = 1.0 / (double)((1 << o->order) - 1);
    o->numerical_rate = o->estimate_done ? rich * fabs(r->precession.slope - h->precession.slope)
                                         : 0.0;
    o->numerical_period = o->estimate_done ? rich * fabs(r->period - h->period) : 0.0;
    o->achieved = -2.0;
    if (o->estimate_done)
        o->achieved = fmax(r->period > 0.0 ? o->numerical_period / r->period : 0.0,
                           W > 0.0 ? o->numerical_rate / W : 0.0);
    o->expected_rate =
        mech_foucault_expected_rate(&o->scales, W, r->airy_rate_mean, &o->tolerance_next_order);
    o->tolerance_fit = 3.0 * r->precession.stderr_slope;
}

enum mech_status mech_foucault_scene(const struct mech_foucault_scene_request *q,
                                     const struct mech_budget *budget,
                                     struct mech_foucault_scene *out, struct mech_error *err)
{
    if (!q || !budget || !out)
        return mech_error_set(err, MECH_EINVAL, NULL, "mech_foucault_scene: NULL argument");
    struct mech_foucault_scene *o = out;
    memset(o, 0, sizeof *o);
    o->problem = q->problem;
    o->steps_per_swing = q->steps_per_swing;
    mech_foucault_scales(&q->problem, &o->scales);
    enum mech_status st = scene_input_ok(q, o, err);
    if (st == MECH_OK) st = run_length(q, o, err);
    if (st == MECH_OK && !q->explicit_integrator) st = choose(q, o, err);
    if (st != MECH_OK) return st;
    o->order = o->problem.method == MECH_PENDULUM_RATTLE ? 2 : 4;
    if (o->swings_asked * o->steps_per_swing > 1e12)
        return mech_error_set(err, MECH_EDOMAIN, o->run_field,
                              "%.6g swings x %.6g steps per swing is beyond any budget",
                              o->swings_asked, o->steps_per_swing);
    o->problem.steps = (long)ceil(o->swings_asked * o->steps_per_swing - 1e-9);
    if (o->problem.steps < 1) o->problem.steps = 1;
    o->dt = o->problem.t_end / (double)o->problem.steps;
    st = model_terms(q, o, err);
    if (st != MECH_OK || q->dry_run) return st;

    struct mech_error e;
    mech_error_clear(&e);
    double w0 = mech_clock_seconds();
    st = mech_foucault_integrate(&o->problem, budget, &o->run, &e);
    o->wall_seconds = mech_clock_seconds() - w0;
    if (st != MECH_OK) {
        name_run_param(&e, o->run_field);
        if (err && err->code == MECH_OK) *err = e;
        return st;
    }
    o->ran = 1;
    if (q->error_estimate) {
        st = estimate_run(budget, o, err);
        if (st != MECH_OK) return st;
    } else {
        o->estimate_skip = "not asked (error_estimate: false)";
    }
    compare(o);
    return MECH_OK;
}
