/* integrator_block.c — the `integrator` block for first-order systems (see
 * api/request/integrator_block.h). */
#include "request/integrator_block.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mech/ode/accuracy.h"
#include "mech/ode/method_choice.h"

struct mech_ode_options api_integrator_settings(const json_t *block)
{
    struct mech_ode_options o = {0.0, 0.0, 0.0};
    const json_t *v;
    if (json_is_number(v = json_object_get(block, "rtol"))) o.rtol = json_number_value(v);
    if (json_is_number(v = json_object_get(block, "atol"))) o.atol = json_number_value(v);
    if (json_is_number(v = json_object_get(block, "dt"))) o.dt = json_number_value(v);
    return o;
}

int api_integrator_block_parse(struct api_call *c, const json_t *in, const char *pointer,
                               double span, const struct api_integrator_system *sys,
                               struct api_integrator_choice *out)
{
    return api_integrator_block_parse_cf(c, in, pointer, span, sys, NULL, out);
}

int api_integrator_block_parse_cf(struct api_call *c, const json_t *in, const char *pointer,
                                  double span, const struct api_integrator_system *sys,
                                  const char *closed_form_name,
                                  struct api_integrator_choice *out)
{
    return api_integrator_block_parse_hooks(c, in, pointer, span, sys, closed_form_name, NULL,
                                            out);
}

int api_integrator_block_parse_hooks(struct api_call *c, const json_t *in, const char *pointer,
                                     double span, const struct api_integrator_system *sys,
                                     const char *closed_form_name,
                                     const struct api_integrator_hooks *hooks,
                                     struct api_integrator_choice *out)
{
    static const struct api_integrator_hooks no_hooks = {0.0, 0.0, 0.0, NULL, 0.0};
    if (!hooks) hooks = &no_hooks;
    memset(out, 0, sizeof *out);
    out->requested = api_call_as_given(c, in, pointer);
    const char *method = in ? api_string(in, "method", NULL) : NULL;
    if (method) {
        const struct mech_integrator *m = mech_ode_method_find(method);
        char ptr[128];
        snprintf(ptr, sizeof ptr, "%s/method", pointer);
        if (!m) {
            api_call_invalid(c, ptr, "unknown method \"%s\" (GET /v1/integrators lists them)",
                             method);
            return 0;
        }
        struct mech_ode_method_info mi = mech_ode_method_describe(m);
        if (mi.second_order) {
            api_call_invalid(c, ptr,
                             "%s needs a second-order system q'' = a(t, q, v) and does not apply "
                             "to this first-order system (%s); use rk8pd, rkck, rkf45 or msbdf "
                             "(rtol/atol), or rk4, gauss4, gauss6 or euler (dt), or an accuracy "
                             "preset",
                             method, sys->equations);
            return 0;
        }
        out->method = method;
        out->opt = api_integrator_settings(in);
        return 1;
    }
    /* by accuracy: the one policy for first-order systems (mech/ode/method_choice.h) */
    const json_t *te = in ? json_object_get(in, "target_error") : NULL;
    const struct mech_accuracy_preset *preset = NULL;
    const double target = mech_accuracy_target(te != NULL, json_number_value(te),
                                               in ? api_string_of(in, "accuracy") : NULL, &preset);
    out->accuracy = preset ? preset->name : NULL;
    const struct mech_first_order_system fs = {
        .equations = sys->equations,
        .state = sys->state,
        .state_scale = sys->state_scale,
        .samples = sys->samples,
        .rhs_cost_s = sys->rhs_cost_s,
        .span = span,
        .cost_span = hooks->cost_span,
        .closed_form_name = closed_form_name,
        .closed_form_allowed = !(in && json_is_false(json_object_get(in, "closed_form"))),
        .closed_form_evaluations = hooks->closed_form_evaluations,
        .closed_form_cpu_per_eval = hooks->closed_form_cpu_per_eval,
        .pilot = hooks->pilot,
        .error_gain = hooks->error_gain,
        .rows = sys->rows,
        .second_order = sys->second_order,
        .defaulted = in == NULL,
    };
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_choose_first_order(&fs, target, api_dry_run_requested(c->body),
                                                  &c->budget, &out->mc, &e);
    if (st != MECH_OK) {
        if (out->mc.pilot_failed) api_call_fail_core(c, st, &e, "");
        else api_call_invalid(c, pointer, "%s", e.text);
        return 0;
    }
    out->chosen = 1;
    out->method = out->mc.method;
    out->opt = out->mc.opt;
    return 1;
}

static void settings(struct api_call *c, json_t *o, const struct api_integrator_choice *ch)
{
    const struct mech_integrator *m = mech_ode_method_find(ch->method);
    json_object_set_new_nocheck(o, "method", json_string(ch->method));
    if (m && mech_ode_method_describe(m).adaptive) {
        json_object_set_new_nocheck(o, "rtol", api_real(c, ch->opt.rtol));
        json_object_set_new_nocheck(o, "atol", api_real(c, ch->opt.atol));
    } else {
        json_object_set_new_nocheck(o, "dt", api_real(c, ch->opt.dt));
    }
}

json_t *api_dry_run_answer(struct api_call *c, json_t *selection)
{
    (void)c;
    json_t *res = json_object(), *d = json_object();
    json_object_set_new_nocheck(res, "dry_run", json_true());
    json_object_set_new_nocheck(d, "steps", json_integer(0));
    json_object_set_new_nocheck(d, "rhs_evaluations", json_integer(0));
    json_object_set_new_nocheck(d, "selection", selection);
    json_object_set_new_nocheck(res, "diagnostics", d);
    if (!res || !d || !selection) {
        json_decref(res);
        return api_call_fail_core(c, MECH_ENOMEM, NULL, "");
    }
    return res;
}

int api_dry_run_requested(const json_t *body)
{
    return json_is_true(json_object_get(body, "dry_run"));
}

/* selection.pilot: what the pilot did and cost (mech/ode/chooser_pilot.h). */
static json_t *pilot_json(struct api_call *c, const struct mech_pilot_report *r)
{
    json_t *o = json_object();
    json_object_set_new_nocheck(o, "run", json_boolean(r->run));
    if (r->run) {
        json_object_set_new_nocheck(o, "fraction_of_span", api_real(c, r->fraction));
        json_object_set_new_nocheck(o, "steps", json_integer(r->steps));
        json_object_set_new_nocheck(o, "evaluations", api_real(c, r->evaluations));
        json_object_set_new_nocheck(o, "predicted_cpu_s", api_real(c, r->predicted_cpu_s));
        json_object_set_new_nocheck(o, "table_evaluations", api_real(c, r->table_evaluations));
        json_object_set_new_nocheck(o, "error_over_pilot",
                                    r->error >= 0.0 ? api_real(c, r->error) : json_null());
        json_object_set_new_nocheck(o, "error_extrapolated",
                                    r->error_extrapolated >= 0.0 && isfinite(r->error_extrapolated)
                                        ? api_real(c, r->error_extrapolated)
                                        : json_null());
    }
    json_object_set_new_nocheck(o, "why", json_string(r->why));
    return o;
}

json_t *api_integrator_block_selection(struct api_call *c, const struct api_integrator_choice *ch)
{
    return api_integrator_block_selection_achieved(c, ch, -1.0, NULL, -1.0);
}

json_t *api_integrator_block_selection_run(struct api_call *c,
                                           const struct api_integrator_choice *ch, double error,
                                           const char *evidence, int at_least_law)
{
    if (!ch->chosen || ch->mc.sel.chosen < 0) return api_integrator_block_selection(c, ch);
    const double law = ch->mc.sel.c[ch->mc.sel.chosen].predicted_error;
    if (at_least_law && error >= 0.0 && isfinite(error)) {
        error = fmax(error, law);
    } else if (!(error >= 0.0) || !isfinite(error)) {
        error = law;
        evidence = "no exact reference for this run: the chooser's calibrated law at the setting "
                   "run (its rows measured on this operation's own scene, where the measured "
                   "error lies within 0.3 .. 3x of the law), a prediction, not a measurement";
    }
    return api_integrator_block_selection_achieved(c, ch, error, evidence, 0.0);
}

json_t *api_integrator_block_selection_achieved(struct api_call *c,
                                                const struct api_integrator_choice *ch,
                                                double error, const char *evidence,
                                                double cpu_s)
{
    json_t *sel = json_object();
    if (!sel) return NULL;
    json_object_set_new_nocheck(sel, "requested",
                                ch->requested ? json_deep_copy(ch->requested) : json_null());
    if (ch->mc.closed_form)
        json_object_set_new_nocheck(sel, "method", json_string("closed_form"));
    else
        settings(c, sel, ch);
    if (ch->chosen) {
        json_object_set_new_nocheck(sel, "target_error", api_real(c, ch->mc.target));
        json_object_set_new_nocheck(sel, "reason", json_string(ch->mc.reason));
        api_selection_predictions(c, &ch->mc.sel, sel);
        if (ch->mc.pilot.considered) json_object_set_new_nocheck(sel, "pilot", pilot_json(c, &ch->mc.pilot));
        if (cpu_s >= 0.0 && ch->mc.sel.chosen >= 0)
            json_object_set_new_nocheck(
                sel, "achieved",
                api_selection_achieved(c, &ch->mc.sel.c[ch->mc.sel.chosen], ch->mc.target, error,
                                       evidence ? evidence
                                                : "none: this operation has no exact reference "
                                                  "or second run",
                                       cpu_s));
    } else {
        json_object_set_new_nocheck(sel, "reason",
                                    json_string("method and settings given in the request"));
    }
    return sel;
}

void api_integrator_block_stats(struct api_call *c, json_t *d,
                                const struct api_integrator_choice *ch,
                                const struct mech_ode_stats *stats)
{
    settings(c, d, ch);
    const struct mech_integrator *m = mech_ode_method_find(ch->method);
    json_object_set_new_nocheck(d, "order",
                                json_integer(m ? mech_ode_method_describe(m).order : 0));
    json_object_set_new_nocheck(d, "steps", json_integer(stats->steps));
    json_object_set_new_nocheck(d, "rejected_steps", json_integer(stats->rejected_steps));
    json_object_set_new_nocheck(d, "rhs_evaluations", json_integer(stats->rhs_evaluations));
}

/* The stated factor within which the achieved error should fall of the
 * predicted one (tests/core/ode/test_chooser.c, docs/accuracy.md). */
#define API_PREDICTION_FACTOR 30.0

static json_t *candidate_json(struct api_call *c, const struct mech_candidate *k)
{
    json_t *o = json_object();
    json_object_set_new_nocheck(o, "method", json_string(k->method));
    if (k->has_settings) {
        json_t *st = json_object();
        if (k->adaptive) {
            json_object_set_new_nocheck(st, "rtol", api_real(c, k->opt.rtol));
            json_object_set_new_nocheck(st, "atol", api_real(c, k->opt.atol));
        } else {
            json_object_set_new_nocheck(st, "dt", api_real(c, k->opt.dt));
        }
        json_object_set_new_nocheck(o, "settings", st);
    }
    if (k->predicted) {
        json_object_set_new_nocheck(o, "predicted_error", api_real(c, k->predicted_error));
        json_object_set_new_nocheck(o, "predicted_evaluations",
                                    api_real(c, k->predicted_evaluations));
        json_object_set_new_nocheck(o, "predicted_cpu_s", api_real(c, k->predicted_cpu_s));
    }
    json_object_set_new_nocheck(o, "verdict", json_string(mech_verdict_name(k->verdict)));
    json_object_set_new_nocheck(o, "why", json_string(k->why));
    return o;
}

json_t *api_selection_predictions(struct api_call *c, const struct mech_selection *sel,
                                  json_t *into)
{
    json_object_set_new_nocheck(into, "scene_class",
                                json_string(mech_scene_class_name(sel->cls)));
    json_object_set_new_nocheck(into, "span", api_real(c, sel->span));
    json_object_set_new_nocheck(into, "model", json_string(sel->model));
    json_object_set_new_nocheck(into, "roundoff_floor", api_real(c, sel->roundoff_floor));
    json_t *cands = json_array();
    for (size_t i = 0; i < sel->n; i++) json_array_append_new(cands, candidate_json(c, &sel->c[i]));
    json_object_set_new_nocheck(into, "candidates", cands);
    return into;
}

json_t *api_selection_achieved(struct api_call *c, const struct mech_candidate *pred,
                               double target, double error, const char *evidence,
                               double cpu_s)
{
    json_t *a = json_object();
    const int known = error >= 0.0;
    json_object_set_new_nocheck(a, "error", known ? api_real(c, error) : json_null());
    json_object_set_new_nocheck(a, "evidence", json_string(evidence));
    json_object_set_new_nocheck(a, "predicted_error", api_real(c, pred->predicted_error));
    json_object_set_new_nocheck(a, "predicted_cpu_s", api_real(c, pred->predicted_cpu_s));
    /* the measured CPU is the answer's cost.cpu_seconds (left out with
     * "cost": false): kept out of the selection so that equal requests give
     * byte-identical answers apart from "cost" */
    (void)cpu_s;
    char note[300];
    if (!known) {
        json_object_set_new_nocheck(a, "met_target", json_null());
        json_object_set_new_nocheck(a, "within_prediction", json_null());
        snprintf(note, sizeof note,
                 "no error evidence for this run: the scene has no exact reference; ask "
                 "\"error_estimate\": true for a second run");
    } else {
        const int met = error <= target;
        const int within = error <= API_PREDICTION_FACTOR * fmax(pred->predicted_error, 1e-16);
        json_object_set_new_nocheck(a, "met_target", json_boolean(met));
        json_object_set_new_nocheck(a, "within_prediction", json_boolean(within));
        if (met && within)
            snprintf(note, sizeof note, "met: achieved %.2g <= target %.2g (predicted %.2g)",
                     error, target, pred->predicted_error);
        else
            snprintf(note, sizeof note,
                     "%s%s: achieved %.2g against target %.2g and predicted %.2g (the stated "
                     "factor is %g)",
                     met ? "" : "MISSED the target", !met && !within ? " and " : "",
                     error, target, pred->predicted_error, API_PREDICTION_FACTOR);
        if (met && !within) {
            size_t n = strlen(note);
            snprintf(note + n, sizeof note - n, "; the prediction was too optimistic");
        }
    }
    json_object_set_new_nocheck(a, "note", json_string(note));
    return a;
}

