/* foucault.c — POST /v1/scenes/foucault: the notes' Foucault
 * pendulum (§1.4, "Example: The Foucault Pendulum") as the full nonlinear
 * spherical pendulum in the rotating Earth frame (core/frames/pendulum.c),
 * with the measured precession of the swing plane beside the notes'
 * W sin(lat), Airy's finite-amplitude correction, the swing period beside
 * 2 pi sqrt(l/g) and the elliptic-integral period, the model terms ("auto":
 * the centrifugal term of the displacement is judged by its effect on the
 * answer) and the evidence (energy and constraint drift, a second run at half
 * the steps). What it computes is one call, mech_foucault_scene()
 * (core/answers/frames/foucault_scene.c); this file reads the request and encodes
 * the answer. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "request/earth_rotation.h"
#include "run/endpoint.h"
#include "request/integrator_block.h"
#include "mech/base/constants.h"
#include "mech/answers/frames/foucault_scene.h"
#include "mech/frames/trajectory.h"
#include "request/trajectory_request.h"

/* diagnostics.selection, the shape every time-evolution operation gives it
 * (api/request/integrator_block.c): requested, method, steps_per_swing, dt, and when
 * chosen target_error, reason, the candidates with their predictions and,
 * after a run, achieved: the error evidence (>= 0), or -2 for none; -1 is a
 * dry run (no achieved block). accuracy: the preset's name or NULL. New
 * reference. */
static json_t *fc_selection(struct api_call *c, const json_t *integ, const char *accuracy,
                            const struct mech_foucault_scene_request *q,
                            const struct mech_foucault_scene *s, double achieved)
{
    json_t *o = json_object();
    json_object_set_new_nocheck(o, "requested", integ ? json_deep_copy(integ) : json_null());
    json_object_set_new_nocheck(o, "method",
                                json_string(mech_pendulum_method_name(s->problem.method)));
    json_object_set_new_nocheck(o, "steps_per_swing", api_real(c, s->steps_per_swing));
    json_object_set_new_nocheck(o, "dt", api_real(c, s->dt));
    if (!s->chosen) {
        json_object_set_new_nocheck(o, "reason",
                                    json_string("method and steps per swing given in the request"));
        return o;
    }
    const double target = q->target;
    if (accuracy) json_object_set_new_nocheck(o, "accuracy", json_string(accuracy));
    json_object_set_new_nocheck(o, "target_error", api_real(c, target));
    json_object_set_new_nocheck(o, "reason", json_string(s->reason));
    api_selection_predictions(c, &s->selection, o);
    if (achieved != -1.0)
        json_object_set_new_nocheck(
            o, "achieved",
            api_selection_achieved(c, &s->selection.c[s->selection.chosen], target,
                                   achieved >= 0.0 ? achieved : -1.0,
                                   achieved >= 0.0
                                       ? "Richardson: the same method at half the steps per "
                                         "swing, max(|period difference| / period, |rate "
                                         "difference| / W) / (2^p - 1)"
                                       : "none: error_estimate is false or its run was skipped",
                                   -1.0));
    return o;
}

/* The sense of a precession rate (rad/s, counterclockwise positive seen from above). */
static const char *fc_sense(double rate)
{
    return rate < 0 ? "clockwise" : rate > 0 ? "counterclockwise" : "none";
}

/* The request as the core takes it; 0 (the error recorded) when the
 * request combines what cannot go together. *accuracy: the preset or NULL. */
static int fc_read(struct api_call *c, const json_t *body, struct mech_foucault_scene_request *q,
                   const char **accuracy)
{
    memset(q, 0, sizeof *q);
    struct mech_foucault_problem *p = &q->problem;
    p->latitude_deg = api_number(body, "latitude_deg", 45.0);
    p->length = api_number_of(body, "length");
    p->g = api_number_of(body, "g");
    if (!api_earth_rotation(c, body, "", "omega_magnitude", MECH_EARTH_OMEGA_SIDEREAL,
                            &p->omega_magnitude))
        return 0;
    p->mass = api_number_of(body, "mass");
    const json_t *rel = json_object_get(body, "release");
    p->amplitude_deg = api_number(rel, "amplitude_deg", 3.0);
    p->azimuth_deg = api_number(rel, "azimuth_deg", 0.0);
    p->transverse_velocity = api_number(rel, "transverse_velocity", 0.0);
    const json_t *integ = json_object_get(body, "integrator");
    const char *method = api_string(integ, "method", "rattle_yoshida4");
    p->method = strcmp(method, "rattle") ? MECH_PENDULUM_RATTLE_YOSHIDA4 : MECH_PENDULUM_RATTLE;
    q->steps_per_swing = api_number(integ, "steps_per_swing", 200.0);
    q->error_estimate = !json_is_false(json_object_get(body, "error_estimate"));
    /* the target: target_error (default 1e-6) or an accuracy preset's
     * promise; without an explicit method or steps per swing it also picks
     * them (the predictive chooser, core/frames/chooser_pendulum.c) */
    *accuracy = api_string(body, "accuracy", NULL);
    /* given, not defaulted (method, steps_per_swing and target_error have defaults) */
    q->explicit_integrator = api_call_given(c, "/integrator/method") != NULL ||
                             api_call_given(c, "/integrator/steps_per_swing") != NULL;
    const int target_given = api_call_given(c, "/target_error") != NULL;
    if (*accuracy && target_given) {
        api_call_invalid(c, "/target_error", "give accuracy or target_error, not both");
        return 0;
    }
    if (*accuracy && q->explicit_integrator) {
        api_call_invalid(c, "/accuracy",
                         "accuracy chooses the method and the steps per swing: give it or "
                         "integrator.method / integrator.steps_per_swing, not both");
        return 0;
    }
    q->target = api_number_of(body, "target_error");
    if (*accuracy) q->target = mech_accuracy_target(0, 0.0, *accuracy, NULL);
    q->target_defaulted = !*accuracy && !target_given;

    int nrun = api_call_given(c, "/swings") != NULL;
    nrun += json_object_get(body, "precessions") != NULL;
    nrun += json_object_get(body, "duration") != NULL;
    if (nrun > 1) {
        api_call_invalid(c, "", "give at most one of swings, precessions, duration");
        return 0;
    }
    if (json_object_get(body, "precessions")) {
        q->run_by = MECH_FOUCAULT_RUN_PRECESSIONS;
        q->run_value = api_number(body, "precessions", 1.0);
    } else if (json_object_get(body, "duration")) {
        q->run_by = MECH_FOUCAULT_RUN_DURATION;
        q->run_value = api_number(body, "duration", 1.0);
    } else {
        q->run_by = MECH_FOUCAULT_RUN_SWINGS;
        q->run_value = api_number_of(body, "swings");
    }
    const json_t *fict = json_object_get(body, "fictitious");
    q->auto_terms = !json_is_array(fict);
    size_t i;
    const json_t *it;
    json_array_foreach(fict, i, it)
    {
        if (!strcmp(json_string_value(it), "coriolis")) q->given_coriolis = 1;
        if (!strcmp(json_string_value(it), "centrifugal")) q->given_centrifugal = 1;
    }
    q->dry_run = api_dry_run_requested(body);
    return 1;
}

/* "setup": the scene as run. */
static json_t *fc_setup(struct api_call *c, const struct mech_foucault_scene *s)
{
    const struct mech_foucault_problem *p = &s->problem;
    json_t *o = json_object();
    json_object_set_new_nocheck(o, "length", api_real(c, p->length));
    json_object_set_new_nocheck(o, "g", api_real(c, p->g));
    json_object_set_new_nocheck(o, "latitude_deg", api_real(c, p->latitude_deg));
    json_object_set_new_nocheck(o, "omega", api_vec3(c, s->scales.omega));
    json_object_set_new_nocheck(o, "omega_sin_latitude", api_real(c, s->scales.omega_vertical));
    json_object_set_new_nocheck(o, "omega0", api_real(c, s->scales.omega0));
    json_object_set_new_nocheck(o, "amplitude_deg", api_real(c, p->amplitude_deg));
    json_object_set_new(o, "release_position", api_vec3(c, s->scales.release_position));
    json_object_set_new_nocheck(o, "duration", api_real(c, p->t_end));
    return o;
}

/* A full turn's time in hours at rate (rad/s), null at rate 0. */
static json_t *fc_hours(struct api_call *c, double rate)
{
    return fabs(rate) > 0.0 ? api_real(c, mech_foucault_full_precession_time(rate) / 3600.0)
                            : json_null();
}

/* "precession": measured beside the notes' first order and Airy's correction. */
static json_t *fc_precession(struct api_call *c, const struct mech_foucault_scene *s)
{
    const double deg = MECH_PI / 180.0;
    const struct mech_foucault_result *r = &s->run;
    const double first = s->scales.first_order_rate, rate = r->precession.slope;
    json_t *o = json_object();
    json_object_set_new_nocheck(o, "measured_rate", api_real(c, rate));
    json_object_set_new_nocheck(o, "measured_rate_deg_per_hour", api_real(c, rate * 3600.0 / deg));
    json_object_set_new_nocheck(o, "first_order_rate", api_real(c, first));
    json_object_set_new_nocheck(o, "difference", api_real(c, rate - first));
    json_object_set_new_nocheck(o, "airy_correction", api_real(c, r->airy_rate_mean));
    json_object_set_new_nocheck(o, "airy_correction_release", api_real(c, r->airy_rate));
    json_object_set_new_nocheck(o, "expected_rate", api_real(c, s->expected_rate));
    json_object_set_new_nocheck(o, "residual", api_real(c, rate - s->expected_rate));
    json_t *tol = json_object();
    json_object_set_new_nocheck(tol, "next_order", api_real(c, s->tolerance_next_order));
    json_object_set_new_nocheck(tol, "fit", api_real(c, s->tolerance_fit));
    json_object_set_new_nocheck(tol, "numerical", api_real(c, s->numerical_rate));
    json_object_set_new_nocheck(
        tol, "total",
        api_real(c, s->tolerance_next_order + s->tolerance_fit + s->numerical_rate));
    json_object_set_new_nocheck(o, "tolerance", tol);
    json_object_set_new_nocheck(o, "full_precession_hours",
                                fc_hours(c, s->scales.omega_vertical));
    /* senses stated, not implied (seen from above, local axes x east, y north) */
    json_object_set_new_nocheck(o, "sense", json_string(fc_sense(first)));
    json_object_set_new_nocheck(o, "measured_sense", json_string(fc_sense(rate)));
    json_object_set_new_nocheck(o, "full_precession_basis",
                                json_string("first_order_rate: 2 pi / (W |sin lat|); "
                                            "full_precession_hours_measured uses measured_rate"));
    json_object_set_new_nocheck(o, "full_precession_hours_measured", fc_hours(c, rate));
    json_object_set_new_nocheck(o, "turning_points", json_integer(r->turning_points));
    json_object_set_new_nocheck(o, "fit_standard_error", api_real(c, r->precession.stderr_slope));
    json_object_set_new_nocheck(o, "fit_rms_residual", api_real(c, r->precession.rms_residual));
    json_object_set_new(
        o, "definition",
        json_string("slope of the least-squares line through the swing-plane azimuth (mod pi, "
                    "unwrapped, counterclockwise from east, rad) at every turning point (maximum "
                    "of the horizontal distance) against t; rad/s, negative = clockwise"));
    return o;
}

/* "swing": the period beside the small- and finite-amplitude closed forms. */
static json_t *fc_swing(struct api_call *c, const struct mech_foucault_scene *s)
{
    const struct mech_foucault_result *r = &s->run;
    json_t *o = json_object();
    json_object_set_new_nocheck(o, "period", api_real(c, r->period));
    json_object_set_new_nocheck(o, "small_amplitude_period",
                                api_real(c, s->scales.small_amplitude_period));
    json_object_set_new_nocheck(o, "finite_amplitude_period",
                                api_real(c, r->finite_amplitude_period));
    json_object_set_new_nocheck(o, "finite_amplitude_correction",
                                api_real(c, mech_pendulum_period_correction(s->scales.alpha)));
    json_object_set_new_nocheck(o, "period_difference",
                                api_real(c, r->period - r->finite_amplitude_period));
    json_object_set_new_nocheck(o, "swings", api_real(c, r->swings));
    json_object_set_new_nocheck(o, "semi_major_axis", api_real(c, r->mean_apocentre));
    json_object_set_new_nocheck(o, "semi_minor_axis", api_real(c, r->mean_pericentre));
    json_object_set_new_nocheck(
        o, "semi_minor_axis_release",
        api_real(c, fabs(r->h_vertical) / (s->scales.omega0 * s->scales.amplitude)));
    json_object_set_new_nocheck(o, "final_position", api_vec3(c, r->final_position));
    json_object_set_new_nocheck(o, "final_velocity", api_vec3(c, r->final_velocity));
    return o;
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

/* The Coriolis and centrifugal terms' estimated effects. */
static json_t *fc_fictitious_terms(struct api_call *c, const struct mech_foucault_scene_request *q,
                                   const struct mech_foucault_scene *s, json_t *terms)
{
    const double W = s->problem.omega_magnitude, wz = s->scales.omega_vertical;
    const struct mech_foucault_centrifugal_effect *cf = &s->centrifugal;
    const int include_cf = s->problem.centrifugal;
    char why[320];
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
    json_array_append_new(terms,
                          fc_term(c, "coriolis", W > 0.0, 2.0 * W * s->run.max_speed, ce, why));
    json_t *fe = json_object();
    json_object_set_new_nocheck(fe, "precession_rate", api_real(c, cf->rate));
    json_object_set_new_nocheck(fe, "relative_rate", api_real(c, cf->relative_rate));
    json_object_set_new_nocheck(fe, "relative_period", api_real(c, cf->relative_period));
    json_object_set_new_nocheck(fe, "relative", api_real(c, cf->relative));
    if (!q->auto_terms)
        snprintf(why, sizeof why, "%s by the request", include_cf ? "included" : "left out");
    else if (W == 0.0)
        snprintf(why, sizeof why, "W = 0: the frame does not rotate, the term is identically 0");
    else
        snprintf(why, sizeof why,
                 "estimated effect %.3g (rate / W, period relative) %s target "
                 "%.3g / safety 10",
                 cf->relative, include_cf ? ">" : "<=", q->target);
    json_array_append_new(terms, fc_term(c, "centrifugal", include_cf,
                                         W * W * s->run.max_displacement, fe, why));
    return terms;
}

/* "model": the terms, the auto rule, the state. */
static json_t *fc_model(struct api_call *c, const struct mech_foucault_scene_request *q,
                        const struct mech_foucault_scene *s)
{
    const double W = s->problem.omega_magnitude, g = s->problem.g;
    json_t *model = json_object();
    json_object_set_new_nocheck(model, "mode", json_string(q->auto_terms ? "auto" : "given"));
    json_t *terms = json_array();
    json_array_append_new(terms, fc_term(c, "gravity", 1, g, NULL, "always: it drives the swing"));
    json_array_append_new(
        terms, fc_term(c, "tension", 1,
                       g * (3.0 - 2.0 * cos(s->scales.alpha)) + 2.0 * W * s->run.max_speed, NULL,
                       "always: the rod's constraint |r - (0,0,l)| = l, "
                       "solved exactly each step (RATTLE)"));
    json_object_set_new_nocheck(model, "terms", fc_fictitious_terms(c, q, s, terms));
    if (q->auto_terms) {
        json_t *au = json_object();
        json_object_set_new_nocheck(au, "target_error", api_real(c, q->target));
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
    return model;
}

/* diagnostics.error_estimate (or its null and reason) into d. */
static void fc_error_estimate(struct api_call *c, const struct mech_foucault_scene *s, json_t *d)
{
    if (!s->estimate_done) {
        json_object_set_new_nocheck(d, "error_estimate", json_null());
        json_object_set_new_nocheck(d, "error_estimate_reason", json_string(s->estimate_skip));
        return;
    }
    json_t *ee = json_object();
    json_object_set_new_nocheck(ee, "steps", json_integer(s->estimate.steps));
    json_object_set_new_nocheck(ee, "rule",
                                json_string("same method at half the steps per swing; "
                                            "the difference / (2^p - 1) estimates this "
                                            "run's error (Richardson)"));
    json_object_set_new_nocheck(ee, "rate", api_real(c, s->numerical_rate));
    json_object_set_new_nocheck(ee, "period", api_real(c, s->numerical_period));
    json_object_set_new_nocheck(ee, "energy_drift_half_steps",
                                api_real(c, s->estimate.max_relative_energy_drift));
    json_object_set_new_nocheck(d, "error_estimate", ee);
}

/* "diagnostics": the method, the conserved quantities, the error evidence. */
static json_t *fc_diagnostics(struct api_call *c, const json_t *integ, const char *accuracy,
                              const struct mech_foucault_scene_request *q,
                              const struct mech_foucault_scene *s)
{
    const struct mech_foucault_result *r = &s->run;
    json_t *d = json_object();
    json_object_set_new_nocheck(d, "method",
                                json_string(mech_pendulum_method_name(s->problem.method)));
    json_object_set_new_nocheck(d, "order", json_integer(s->order));
    json_object_set_new_nocheck(d, "dt", api_real(c, s->dt));
    json_object_set_new_nocheck(d, "steps_per_swing", api_real(c, s->steps_per_swing));
    json_object_set_new_nocheck(d, "steps", json_integer(r->steps));
    json_object_set_new_nocheck(d, "force_evaluations", json_integer(r->force_evaluations));
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
    json_object_set_new_nocheck(en, "initial", api_real(c, r->energy_initial));
    json_object_set_new_nocheck(en, "max_relative_drift", api_real(c, r->max_relative_energy_drift));
    json_object_set_new_nocheck(d, "energy", en);
    json_object_set_new_nocheck(d, "max_constraint_error", api_real(c, r->max_constraint_error));
    json_object_set_new_nocheck(d, "max_tangency_error", api_real(c, r->max_tangency_error));
    fc_error_estimate(c, s, d);
    json_object_set_new_nocheck(d, "selection", fc_selection(c, integ, accuracy, q, s, s->achieved));
    return d;
}

json_t *api_op_scenes_foucault(struct api_call *c, const json_t *body)
{
    struct mech_foucault_scene_request q;
    const char *accuracy;
    if (!fc_read(c, body, &q, &accuracy)) return NULL;
    const json_t *integ = json_object_get(body, "integrator");

    struct mech_foucault_scene s;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_foucault_scene(&q, &c->budget, &s, &e);
    if (st != MECH_OK) return api_call_fail_core(c, st, &e, "");
    if (q.dry_run) return api_dry_run_answer(c, fc_selection(c, integ, accuracy, &q, &s, -1.0));

    json_t *res = json_object();
    json_object_set_new_nocheck(res, "scene", json_string("foucault"));
    json_object_set_new_nocheck(res, "setup", fc_setup(c, &s));
    json_object_set_new_nocheck(res, "precession", fc_precession(c, &s));
    json_object_set_new_nocheck(res, "swing", fc_swing(c, &s));
    json_object_set_new_nocheck(res, "model", fc_model(c, &q, &s));
    json_object_set_new_nocheck(res, "diagnostics", fc_diagnostics(c, integ, accuracy, &q, &s));
    json_t *cost = json_object();
    json_object_set_new_nocheck(cost, "wall_seconds", json_real(s.wall_seconds));
    json_object_set_new_nocheck(res, "cost", cost);
    return res;
}
