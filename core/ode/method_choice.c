/* method_choice.c — the method-choice policy for first-order systems
 * (mech/ode/method_choice.h): profile → predictive chooser → pilot → reason. */
#include "mech/ode/method_choice.h"

#include <math.h>
#include <stdio.h> /* snprintf, for the reason */
#include <string.h>

/* The first-order profile of s (mech/ode/chooser.h). */
static void profile_of(const struct mech_first_order_system *s, struct mech_scene_profile *prof)
{
    memset(prof, 0, sizeof *prof);
    prof->cls = MECH_SCENE_FIRST_ORDER;
    prof->span = s->span >= 0.0 && isfinite(s->span) ? s->span : 0.0;
    prof->T = 1.0;
    prof->scale = s->state_scale > 0.0 ? s->state_scale : 1.0;
    prof->samples = s->samples;
    prof->rhs_cost_s = s->rhs_cost_s;
    prof->cost_span = s->cost_span > 0.0 && isfinite(s->cost_span) ? s->cost_span : 0.0;
    prof->closed_form_evaluations = s->closed_form_evaluations;
    prof->closed_form_cpu_per_eval = s->closed_form_cpu_per_eval;
    prof->stiff = 0;
    prof->closed_form = s->closed_form_name != NULL;
    prof->closed_form_name = s->closed_form_name;
    prof->closed_form_allowed = s->closed_form_allowed;
    prof->error_gain = s->error_gain >= 1.0 && isfinite(s->error_gain) ? s->error_gain : 1.0;
    prof->rows = s->rows;
    prof->second_order = s->second_order;
}

/* out->reason for the choice made on prof. */
static void reason_of(const struct mech_first_order_system *s,
                      const struct mech_scene_profile *prof, struct mech_method_choice *out)
{
    const struct mech_candidate *k = &out->sel.c[out->sel.integrating];
    const char *lead = s->defaulted ? "no integrator block: accuracy \"balanced\" by default; " : "";
    if (out->closed_form) {
        const struct mech_candidate *cf = &out->sel.c[out->sel.chosen];
        snprintf(out->reason, sizeof out->reason,
                 "%s%s over %.3g dynamical times: the exact %s solution is the cheapest "
                 "candidate meeting %.0e relative (predicted error %.2g, %.2g s CPU for %zu "
                 "samples): answered from it, nothing integrated; the best integrator would be "
                 "%s at rtol %.3g (predicted %.2g, %.3g evaluations); {\"closed_form\": false} "
                 "runs it",
                 lead, s->equations, prof->span, s->closed_form_name, out->target,
                 cf->predicted_error, cf->predicted_cpu_s, s->samples, k->method, k->opt.rtol,
                 k->predicted_error, k->predicted_evaluations);
        return;
    }
    char beyond[320];
    mech_selection_beyond_text(&out->sel, beyond, sizeof beyond);
    snprintf(out->reason, sizeof out->reason,
             "%s%s over %.3g dynamical times: %s at rtol %.3g is the cheapest candidate "
             "predicted to meet %.0e relative (predicted %.2g, %.3g evaluations)%s; atol = rtol "
             "x %.6g on %s",
             lead, s->equations, prof->span, k->method, k->opt.rtol, out->target,
             k->predicted_error, k->predicted_evaluations, beyond, prof->scale, s->state);
}

enum mech_status mech_choose_first_order(const struct mech_first_order_system *s, double target,
                                         int dry_run, struct mech_budget *budget,
                                         struct mech_method_choice *out, struct mech_error *err)
{
    if (out) memset(out, 0, sizeof *out);
    if (!s || !out || (s->pilot && !budget))
        return mech_error_set(err, MECH_EINVAL, NULL, "NULL argument");
    struct mech_scene_profile prof;
    profile_of(s, &prof);
    out->target = target;
    struct mech_error e;
    mech_error_clear(&e);
    if (mech_choose(&prof, target, &out->sel, &e) != MECH_OK || out->sel.chosen < 0)
        return mech_error_set(err, MECH_EINVAL, NULL, "%s",
                              e.text[0] ? e.text : "no candidate method applies");
    if (out->sel.integrating < 0)
        return mech_error_set(err, MECH_EINVAL, NULL, "no integrating candidate method applies");
    /* a pilot where the table is uncertain and the run expensive; its steps
     * count against the request's budget */
    if (s->pilot) {
        enum mech_status ps = mech_choose_pilot(&prof, target, &out->sel, s->pilot, dry_run,
                                                budget, &out->pilot, err);
        if (ps != MECH_OK) {
            out->pilot_failed = 1;
            return ps;
        }
        if (out->pilot.run)
            budget->max_steps =
                budget->max_steps > out->pilot.steps ? budget->max_steps - out->pilot.steps : 1;
    }
    const struct mech_candidate *k = &out->sel.c[out->sel.integrating];
    out->closed_form = out->sel.chosen != out->sel.integrating;
    out->method = k->method;
    out->opt = k->opt;
    reason_of(s, &prof, out);
    return MECH_OK;
}
