/* ep_scene_foucault.c — POST /v1/scenes/foucault: the notes' Foucault
 * pendulum (§1.4, "Example: The Foucault Pendulum") as the full nonlinear
 * spherical pendulum in the rotating Earth frame (core/pendulum.c), with the
 * measured precession of the swing plane beside the notes' W sin(lat), Airy's
 * finite-amplitude correction, the swing period beside 2 pi sqrt(l/g) and the
 * elliptic-integral period, the model terms ("auto": the centrifugal term of
 * the displacement is judged by its effect on the answer) and the evidence
 * (energy and constraint drift, a second run at half the steps). The closed
 * forms (scales, expected rate, the centrifugal term's estimated effect) are
 * core/frames/foucault_first_order.c; this file reads, chooses and encodes. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "earth_rotation.h"
#include "endpoint.h"
#include "integrator_block.h"
#include "mech/chooser_pendulum.h"
#include "mech/constants.h"
#include "mech/foucault_first_order.h"
#include "mech/pendulum.h"
#include "mech/trajectory.h"
#include "trajectory_request.h"


struct fc_run {
    struct mech_foucault_problem p;
    struct mech_foucault_result r;
};

/* How the method was picked: given, or by the chooser. */
struct fc_choice {
    int chosen;            /* 1: by the chooser (sel, reason) */
    double target;         /* relative error aimed at */
    const char *accuracy;  /* preset name or NULL */
    struct mech_selection sel;
    char reason[700];
};

/* diagnostics.selection, the shape every time-evolution operation gives it
 * (api/integrator_block.c): requested, method, steps_per_swing, dt, and when
 * chosen target_error, reason, the candidates with their predictions and,
 * after a run, achieved: the error evidence (>= 0), or -2 for none; -1 is a
 * dry run (no achieved block). New reference. */
static json_t *fc_selection(struct api_call *c, const json_t *integ, const struct fc_choice *ch,
                            const char *method, double sps, double dt, double achieved)
{
    json_t *s = json_object();
    json_object_set_new_nocheck(s, "requested", integ ? json_deep_copy(integ) : json_null());
    json_object_set_new_nocheck(s, "method", json_string(method));
    json_object_set_new_nocheck(s, "steps_per_swing", api_real(c, sps));
    json_object_set_new_nocheck(s, "dt", api_real(c, dt));
    if (!ch->chosen) {
        json_object_set_new_nocheck(s, "reason",
                                    json_string("method and steps per swing given in the request"));
        return s;
    }
    if (ch->accuracy) json_object_set_new_nocheck(s, "accuracy", json_string(ch->accuracy));
    json_object_set_new_nocheck(s, "target_error", api_real(c, ch->target));
    json_object_set_new_nocheck(s, "reason", json_string(ch->reason));
    api_selection_predictions(c, &ch->sel, s);
    if (achieved != -1.0)
        json_object_set_new_nocheck(
            s, "achieved",
            api_selection_achieved(c, &ch->sel.c[ch->sel.chosen], ch->target,
                                   achieved >= 0.0 ? achieved : -1.0,
                                   achieved >= 0.0
                                       ? "Richardson: the same method at half the steps per "
                                         "swing, max(|period difference| / period, |rate "
                                         "difference| / W) / (2^p - 1)"
                                       : "none: error_estimate is false or its run was skipped",
                                   -1.0));
    return s;
}

/* Map the core's parameter names to the request's. */
/* The sense of a precession rate (rad/s, counterclockwise positive seen from above). */
static const char *fc_sense(double rate)
{
    return rate < 0 ? "clockwise" : rate > 0 ? "counterclockwise" : "none";
}

static void fc_fix_param(struct mech_error *e, const char *run_field)
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

static json_t *fc_term(struct api_call *c, const char *name, int included, double max_acc,
                       json_t *estimate, const char *reason)
{
    json_t *t = json_object();
    json_object_set_new_nocheck(t, "term", json_string(name));
    json_object_set_new_nocheck(t, "included", json_boolean(included));
    json_object_set_new_nocheck(t, "max_acceleration", api_real(c, max_acc));
    json_object_set_new_nocheck(t, "estimated_effect", estimate ? estimate : json_null());
    json_object_set_new_nocheck(t, "reason", json_string(reason));
    return t;
}

json_t *api_op_scenes_foucault(struct api_call *c, const json_t *body)
{
    const double deg = MECH_PI / 180.0;
    struct mech_foucault_problem p;
    memset(&p, 0, sizeof p);
    p.latitude_deg = api_number(body, "latitude_deg", 45.0);
    p.length = api_number_of(body, "length");
    p.g = api_number_of(body, "g");
    if (!api_earth_rotation(c, body, "", "omega_magnitude", MECH_EARTH_OMEGA_SIDEREAL,
                            &p.omega_magnitude))
        return NULL;
    p.mass = api_number_of(body, "mass");
    const json_t *rel = json_object_get(body, "release");
    p.amplitude_deg = api_number(rel, "amplitude_deg", 3.0);
    p.azimuth_deg = api_number(rel, "azimuth_deg", 0.0);
    p.transverse_velocity = api_number(rel, "transverse_velocity", 0.0);
    const json_t *integ = json_object_get(body, "integrator");
    const char *method = api_string(integ, "method", "rattle_yoshida4");
    p.method = strcmp(method, "rattle") ? MECH_PENDULUM_RATTLE_YOSHIDA4 : MECH_PENDULUM_RATTLE;
    int order = p.method == MECH_PENDULUM_RATTLE ? 2 : 4;
    double sps = api_number(integ, "steps_per_swing", 200.0);
    int want_estimate = !json_is_false(json_object_get(body, "error_estimate"));
    /* the target: target_error (default 1e-6) or an accuracy preset's
     * promise; without an explicit method or steps per swing it also picks
     * them (the predictive chooser, core/chooser_pendulum.c) */
    const char *accuracy = api_string(body, "accuracy", NULL);
    /* given, not defaulted (method, steps_per_swing and target_error have defaults) */
    const int explicit_integrator = api_call_given(c, "/integrator/method") != NULL ||
                                    api_call_given(c, "/integrator/steps_per_swing") != NULL;
    if (accuracy && api_call_given(c, "/target_error")) {
        api_call_invalid(c, "/target_error", "give accuracy or target_error, not both");
        return NULL;
    }
    if (accuracy && explicit_integrator) {
        api_call_invalid(c, "/accuracy",
                         "accuracy chooses the method and the steps per swing: give it or "
                         "integrator.method / integrator.steps_per_swing, not both");
        return NULL;
    }
    double target = api_number_of(body, "target_error");
    for (int i = 0; accuracy && i < MECH_ACCURACY_COUNT; i++)
        if (!strcmp(mech_accuracy_preset_at((enum mech_accuracy)i)->name, accuracy))
            target = mech_accuracy_preset_at((enum mech_accuracy)i)->promise;

    /* ---- the scene's scales (closed forms, before integrating) ---- */
    struct mech_foucault_scales sc;
    mech_foucault_scales(&p, &sc);
    const double alpha = sc.alpha, W = p.omega_magnitude, wz = sc.omega_vertical;
    const double omega0 = sc.omega0, period = sc.period, a = sc.amplitude;

    /* ---- the run's length ---- */
    int nrun = api_call_given(c, "/swings") != NULL;
    nrun += json_object_get(body, "precessions") != NULL;
    nrun += json_object_get(body, "duration") != NULL;
    if (nrun > 1) {
        api_call_invalid(c, "", "give at most one of swings, precessions, duration");
        return NULL;
    }
    const char *run_field = "swings";
    double t_end;
    if (json_object_get(body, "precessions")) {
        run_field = "precessions";
        if (!(fabs(wz) > 0.0)) {
            api_call_domain(c, "/precessions",
                            "the swing plane does not precess at W sin(lat) = 0 (equator or W = "
                            "0): give swings or duration");
            return NULL;
        }
        t_end = api_number(body, "precessions", 1.0) * 2.0 * MECH_PI / fabs(wz);
    } else if (json_object_get(body, "duration")) {
        run_field = "duration";
        t_end = api_number(body, "duration", 1.0);
    } else {
        t_end = api_number_of(body, "swings") * period;
    }
    double swings_asked = t_end / period;
    if (swings_asked < 2.0) {
        char ptr[32];
        snprintf(ptr, sizeof ptr, "/%s", run_field);
        api_call_domain(c, ptr,
                        "the run is %.6g swings of %.6g s: at least 2 are needed to "
                        "measure a precession",
                        swings_asked, period);
        return NULL;
    }
    /* ---- the method: given, or chosen by its predicted error and cost ---- */
    struct fc_choice ch;
    memset(&ch, 0, sizeof ch);
    ch.target = target;
    ch.accuracy = accuracy;
    if (!explicit_integrator) {
        struct mech_pendulum_profile prof = {period, swings_asked, alpha, W * t_end,
                                             want_estimate};
        enum mech_pendulum_method cm;
        struct mech_error ce;
        mech_error_clear(&ce);
        if (mech_choose_pendulum(&prof, target, &ch.sel, &cm, &sps, &ce) != MECH_OK)
            return api_call_fail_core(c, MECH_EINVAL, &ce, "");
        ch.chosen = 1;
        p.method = cm;
        order = cm == MECH_PENDULUM_RATTLE ? 2 : 4;
        const struct mech_candidate *k = &ch.sel.c[ch.sel.chosen];
        char beyond[320];
        mech_selection_beyond_text(&ch.sel, beyond, sizeof beyond);
        snprintf(ch.reason, sizeof ch.reason,
                 ch.sel.beyond == 2
                     ? "%s%s at %.0f steps per swing is the cheapest of the most accurate "
                       "candidates; none is predicted to meet %.0e relative on the period and "
                       "the precession rate / W over %.6g swings (predicted %.2g, %.0f force "
                       "evaluations%s)%s"
                     : "%s%s at %.0f steps per swing is the cheapest candidate predicted to "
                       "meet %.0e relative on the period and the precession rate / W over %.6g "
                       "swings (predicted %.2g, %.0f force evaluations%s)%s",
                 accuracy ? "" : api_call_given(c, "/target_error")
                                     ? ""
                                     : "target_error 1e-6 by default: ",
                 k->method, sps, target, swings_asked, k->predicted_error,
                 k->predicted_evaluations, want_estimate ? " with the error estimate's run" : "",
                 beyond);
    }
    if (swings_asked * sps > 1e12) {
        char ptr[32];
        snprintf(ptr, sizeof ptr, "/%s", run_field);
        api_call_domain(c, ptr, "%.6g swings x %.6g steps per swing is beyond any budget",
                        swings_asked, sps);
        return NULL;
    }
    p.t_end = t_end;
    p.steps = (long)ceil(swings_asked * sps - 1e-9);
    if (p.steps < 1) p.steps = 1;

    /* ---- model terms ---- */
    const json_t *fict = json_object_get(body, "fictitious");
    int auto_mode = !json_is_array(fict);
    int given_coriolis = 0, given_centrifugal = 0;
    if (!auto_mode) {
        size_t i;
        const json_t *it;
        json_array_foreach(fict, i, it)
        {
            if (!strcmp(json_string_value(it), "coriolis")) given_coriolis = 1;
            if (!strcmp(json_string_value(it), "centrifugal")) given_centrifugal = 1;
        }
        if (!given_coriolis && W > 0.0) {
            api_call_domain(c, "/fictitious",
                            "the Coriolis term is the Foucault effect (it turns the swing plane "
                            "at W sin(lat)); it cannot be left out of this scene");
            return NULL;
        }
    }
    /* The centrifugal term's effect (core/frames/foucault_first_order.c) */
    struct mech_foucault_centrifugal_effect cf;
    mech_foucault_centrifugal_effect(&sc, W, p.length, t_end, &cf);
    const double cf_rel = cf.relative;
    int include_cf = auto_mode ? (W > 0.0 && cf_rel > target / 10.0) : given_centrifugal;
    p.centrifugal = include_cf;

    if (api_dry_run_requested(body))
        return api_dry_run_answer(c, fc_selection(c, integ, &ch, mech_pendulum_method_name(p.method),
                                                  sps, p.t_end / (double)p.steps, -1.0));

    /* ---- the run, and a second at half the steps ---- */
    struct mech_error e;
    mech_error_clear(&e);
    struct mech_foucault_result r;
    double w0 = mech_clock_seconds();
    enum mech_status st = mech_foucault_integrate(&p, &c->budget, &r, &e);
    double wall = mech_clock_seconds() - w0;
    if (st != MECH_OK) {
        fc_fix_param(&e, run_field);
        return api_call_fail_core(c, st, &e, "");
    }
    struct fc_run est;
    int est_done = 0;
    const char *est_skip = "not asked (error_estimate: false)";
    if (want_estimate) {
        est.p = p;
        est.p.steps = (p.steps + 1) / 2;
        struct mech_budget b2 = c->budget;
        b2.max_steps = c->budget.max_steps - p.steps;
        struct mech_error e2;
        mech_error_clear(&e2);
        enum mech_status st2 = MECH_EBUDGET;
        if (b2.max_steps >= est.p.steps) st2 = mech_foucault_integrate(&est.p, &b2, &est.r, &e2);
        if (st2 == MECH_OK) {
            est_done = 1;
        } else if (st2 == MECH_EBUDGET || st2 == MECH_EDEADLINE) {
            est_skip = "skipped: the step budget or the time left is too small";
        } else if (st2 == MECH_EDOMAIN || st2 == MECH_ENUMERIC) {
            est_skip = "skipped: half the steps per swing is too coarse";
        } else {
            return api_call_fail_core(c, st2, &e2, "");
        }
    }
    /* Richardson: the answer's run (N steps) errs by ~ (its result - the N/2 run's) / (2^p - 1) */
    double rich = 1.0 / (double)((1 << order) - 1);
    double num_rate = est_done ? rich * fabs(r.precession.slope - est.r.precession.slope) : 0.0;
    double num_period = est_done ? rich * fabs(r.period - est.r.period) : 0.0;

    /* ---- the answer ---- */
    json_t *res = json_object();
    json_object_set_new_nocheck(res, "scene", json_string("foucault"));

    json_t *setup = json_object();
    json_object_set_new_nocheck(setup, "length", api_real(c, p.length));
    json_object_set_new_nocheck(setup, "g", api_real(c, p.g));
    json_object_set_new_nocheck(setup, "latitude_deg", api_real(c, p.latitude_deg));
    json_object_set_new_nocheck(setup, "omega", api_vec3(c, sc.omega));
    json_object_set_new_nocheck(setup, "omega_sin_latitude", api_real(c, wz));
    json_object_set_new_nocheck(setup, "omega0", api_real(c, omega0));
    json_object_set_new_nocheck(setup, "amplitude_deg", api_real(c, p.amplitude_deg));
    json_object_set_new(setup, "release_position", api_vec3(c, sc.release_position));
    json_object_set_new_nocheck(setup, "duration", api_real(c, p.t_end));
    json_object_set_new_nocheck(res, "setup", setup);

    json_t *pr = json_object();
    double first = sc.first_order_rate;
    double tol_formula;
    double expected = mech_foucault_expected_rate(&sc, W, r.airy_rate_mean, &tol_formula);
    double tol_fit = 3.0 * r.precession.stderr_slope;
    json_object_set_new_nocheck(pr, "measured_rate", api_real(c, r.precession.slope));
    json_object_set_new_nocheck(pr, "measured_rate_deg_per_hour",
                                api_real(c, r.precession.slope * 3600.0 / deg));
    json_object_set_new_nocheck(pr, "first_order_rate", api_real(c, first));
    json_object_set_new_nocheck(pr, "difference", api_real(c, r.precession.slope - first));
    json_object_set_new_nocheck(pr, "airy_correction", api_real(c, r.airy_rate_mean));
    json_object_set_new_nocheck(pr, "airy_correction_release", api_real(c, r.airy_rate));
    json_object_set_new_nocheck(pr, "expected_rate", api_real(c, expected));
    json_object_set_new_nocheck(pr, "residual", api_real(c, r.precession.slope - expected));
    json_t *tol = json_object();
    json_object_set_new_nocheck(tol, "next_order", api_real(c, tol_formula));
    json_object_set_new_nocheck(tol, "fit", api_real(c, tol_fit));
    json_object_set_new_nocheck(tol, "numerical", api_real(c, num_rate));
    json_object_set_new_nocheck(tol, "total", api_real(c, tol_formula + tol_fit + num_rate));
    json_object_set_new_nocheck(pr, "tolerance", tol);
    json_object_set_new_nocheck(pr, "full_precession_hours",
                                fabs(wz) > 0.0
                                    ? api_real(c, mech_foucault_full_precession_time(wz) / 3600.0)
                                    : json_null());
    /* senses stated, not implied (seen from above, local axes x east, y north) */
    json_object_set_new_nocheck(pr, "sense", json_string(fc_sense(first)));
    json_object_set_new_nocheck(pr, "measured_sense", json_string(fc_sense(r.precession.slope)));
    json_object_set_new_nocheck(pr, "full_precession_basis",
                                json_string("first_order_rate: 2 pi / (W |sin lat|); "
                                            "full_precession_hours_measured uses measured_rate"));
    json_object_set_new_nocheck(pr, "full_precession_hours_measured",
                                fabs(r.precession.slope) > 0.0
                                    ? api_real(c, mech_foucault_full_precession_time(
                                                      r.precession.slope) / 3600.0)
                                    : json_null());
    json_object_set_new_nocheck(pr, "turning_points", json_integer(r.turning_points));
    json_object_set_new_nocheck(pr, "fit_standard_error", api_real(c, r.precession.stderr_slope));
    json_object_set_new_nocheck(pr, "fit_rms_residual", api_real(c, r.precession.rms_residual));
    json_object_set_new(
        pr, "definition",
        json_string("slope of the least-squares line through the swing-plane azimuth (mod pi, "
                    "unwrapped, counterclockwise from east, rad) at every turning point (maximum "
                    "of the horizontal distance) against t; rad/s, negative = clockwise"));
    json_object_set_new_nocheck(res, "precession", pr);

    json_t *sw = json_object();
    double tsmall = sc.small_amplitude_period;
    json_object_set_new_nocheck(sw, "period", api_real(c, r.period));
    json_object_set_new_nocheck(sw, "small_amplitude_period", api_real(c, tsmall));
    json_object_set_new_nocheck(sw, "finite_amplitude_period",
                                api_real(c, r.finite_amplitude_period));
    json_object_set_new_nocheck(sw, "finite_amplitude_correction",
                                api_real(c, mech_pendulum_period_correction(alpha)));
    json_object_set_new_nocheck(sw, "period_difference",
                                api_real(c, r.period - r.finite_amplitude_period));
    json_object_set_new_nocheck(sw, "swings", api_real(c, r.swings));
    json_object_set_new_nocheck(sw, "semi_major_axis", api_real(c, r.mean_apocentre));
    json_object_set_new_nocheck(sw, "semi_minor_axis", api_real(c, r.mean_pericentre));
    json_object_set_new_nocheck(sw, "semi_minor_axis_release",
                                api_real(c, fabs(r.h_vertical) / (omega0 * a)));
    json_object_set_new_nocheck(sw, "final_position", api_vec3(c, r.final_position));
    json_object_set_new_nocheck(sw, "final_velocity", api_vec3(c, r.final_velocity));
    json_object_set_new_nocheck(res, "swing", sw);

    /* model */
    json_t *model = json_object();
    json_object_set_new_nocheck(model, "mode", json_string(auto_mode ? "auto" : "given"));
    json_t *terms = json_array();
    char why[320];
    json_array_append_new(terms,
                          fc_term(c, "gravity", 1, p.g, NULL, "always: it drives the swing"));
    json_array_append_new(terms,
                          fc_term(c, "tension", 1,
                                  p.g * (3.0 - 2.0 * cos(alpha)) + 2.0 * W * r.max_speed, NULL,
                                  "always: the rod's constraint |r - (0,0,l)| = l, "
                                  "solved exactly each step (RATTLE)"));
    json_t *ce = json_object();
    json_object_set_new_nocheck(ce, "precession_rate", api_real(c, fabs(wz)));
    json_object_set_new_nocheck(ce, "relative", api_real(c, W > 0.0 ? 1.0 : 0.0));
    if (W > 0.0)
        snprintf(why, sizeof why,
                 "always: the Coriolis term is the effect (it turns the swing "
                 "plane at W sin(lat) = %.6g rad/s)",
                 fabs(wz));
    else
        snprintf(why, sizeof why, "W = 0: the frame does not rotate, the term is identically 0");
    json_array_append_new(terms, fc_term(c, "coriolis", W > 0.0, 2.0 * W * r.max_speed, ce, why));
    json_t *fe = json_object();
    json_object_set_new_nocheck(fe, "precession_rate", api_real(c, cf.rate));
    json_object_set_new_nocheck(fe, "relative_rate", api_real(c, cf.relative_rate));
    json_object_set_new_nocheck(fe, "relative_period", api_real(c, cf.relative_period));
    json_object_set_new_nocheck(fe, "relative", api_real(c, cf_rel));
    if (!auto_mode)
        snprintf(why, sizeof why, "%s by the request", include_cf ? "included" : "left out");
    else if (W == 0.0)
        snprintf(why, sizeof why, "W = 0: the frame does not rotate, the term is identically 0");
    else
        snprintf(why, sizeof why,
                 "estimated effect %.3g (rate / W, period relative) %s target "
                 "%.3g / safety 10",
                 cf_rel, include_cf ? ">" : "<=", target);
    json_array_append_new(
        terms, fc_term(c, "centrifugal", include_cf, W * W * r.max_displacement, fe, why));
    json_object_set_new_nocheck(model, "terms", terms);
    if (auto_mode) {
        json_t *au = json_object();
        json_object_set_new_nocheck(au, "target_error", api_real(c, target));
        json_object_set_new_nocheck(au, "safety_factor", api_real(c, 10.0));
        json_object_set_new(
            au, "rule",
            json_string("coriolis always; centrifugal of the displacement when max(rate effect / "
                        "W, period effect) > target / 10, rate effect W^2 cos^2(lat) / (4 omega0) "
                        "+ (3/32) (a/l)^2 W^2 cos^2(lat) min(1 / |W sin lat|, T), period effect "
                        "W^2 (1 + sin^2 lat) / (4 omega0^2), from closed forms before the run "
                        "(the generic |a| T^2 / 2 bound would be meaningless over 10^4 swings)"));
        json_object_set_new_nocheck(model, "auto", au);
    }
    json_t *state = json_object();
    json_object_set_new_nocheck(state, "dimensions", json_integer(3));
    json_object_set_new_nocheck(
        state, "reason",
        json_string("the bob's position and velocity in 3-D Cartesian axes "
                    "with the constraint |u| = l held by RATTLE (no coordinate "
                    "singularity at the bottom or anywhere)"));
    json_object_set_new_nocheck(model, "state", state);
    json_object_set_new_nocheck(res, "model", model);

    /* diagnostics */
    json_t *d = json_object();
    json_object_set_new_nocheck(d, "method", json_string(mech_pendulum_method_name(p.method)));
    json_object_set_new_nocheck(d, "order", json_integer(order));
    json_object_set_new_nocheck(d, "dt", api_real(c, p.t_end / (double)p.steps));
    json_object_set_new_nocheck(d, "steps_per_swing", api_real(c, sps));
    json_object_set_new_nocheck(d, "steps", json_integer(r.steps));
    json_object_set_new_nocheck(d, "force_evaluations", json_integer(r.force_evaluations));
    json_object_set_new(
        d, "why",
        json_string("a fixed-step symplectic, symmetric method on the exact constraint: the "
                    "energy error stays bounded over 10^4 swings, the Coriolis rotation is "
                    "exact (Cayley form), the discrete linear motion precesses at W sin(lat) "
                    "to first order in W for any step, and the work is a fixed 1 (rattle) or 3 "
                    "(rattle_yoshida4) force evaluations per step (order 4: the period to "
                    "~1e-7 at 183 steps per swing)"));
    json_t *en = json_object();
    json_object_set_new_nocheck(en, "name", json_string("jacobi_integral"));
    json_object_set_new_nocheck(en, "initial", api_real(c, r.energy_initial));
    json_object_set_new_nocheck(en, "max_relative_drift", api_real(c, r.max_relative_energy_drift));
    json_object_set_new_nocheck(d, "energy", en);
    json_object_set_new_nocheck(d, "max_constraint_error", api_real(c, r.max_constraint_error));
    json_object_set_new_nocheck(d, "max_tangency_error", api_real(c, r.max_tangency_error));
    if (est_done) {
        json_t *ee = json_object();
        json_object_set_new_nocheck(ee, "steps", json_integer(est.r.steps));
        json_object_set_new_nocheck(ee, "rule",
                                    json_string("same method at half the steps per swing; "
                                                "the difference / (2^p - 1) estimates this "
                                                "run's error (Richardson)"));
        json_object_set_new_nocheck(ee, "rate", api_real(c, num_rate));
        json_object_set_new_nocheck(ee, "period", api_real(c, num_period));
        json_object_set_new_nocheck(ee, "energy_drift_half_steps",
                                    api_real(c, est.r.max_relative_energy_drift));
        json_object_set_new_nocheck(d, "error_estimate", ee);
    } else {
        json_object_set_new_nocheck(d, "error_estimate", json_null());
        json_object_set_new_nocheck(d, "error_estimate_reason", json_string(est_skip));
    }
    {
        /* the achieved error beside the prediction: the Richardson estimates
         * of the period (relative) and the rate (relative to W) */
        double achieved = -2.0; /* no evidence */
        if (est_done)
            achieved = fmax(r.period > 0.0 ? num_period / r.period : 0.0,
                            W > 0.0 ? num_rate / W : 0.0);
        json_object_set_new_nocheck(d, "selection",
                                    fc_selection(c, integ, &ch, mech_pendulum_method_name(p.method),
                                                 sps, p.t_end / (double)p.steps, achieved));
    }
    json_object_set_new_nocheck(res, "diagnostics", d);

    json_t *cost = json_object();
    json_object_set_new_nocheck(cost, "wall_seconds", json_real(wall));
    json_object_set_new_nocheck(res, "cost", cost);
    return res;
}

