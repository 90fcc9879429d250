/* integrator_block.c — the `integrator` block for first-order systems (see
 * integrator_block.h). */
#include "integrator_block.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mech/trajectory.h"

int api_integrator_block_parse(struct api_call *c, const json_t *in, const char *pointer,
                               double span, const struct api_integrator_system *sys,
                               struct api_integrator_choice *out)
{
    memset(out, 0, sizeof *out);
    out->requested = in;
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
        out->opt.rtol = api_number(in, "rtol", 1e-10);
        out->opt.atol = api_number(in, "atol", 1e-12);
        out->opt.dt = api_number(in, "dt", 0);
        return 1;
    }
    const struct mech_accuracy_preset *pr = NULL;
    const json_t *te = in ? json_object_get(in, "target_error") : NULL;
    double target;
    if (te) {
        target = json_number_value(te);
        for (int a = 0; a < MECH_ACCURACY_COUNT; a++) {
            pr = mech_accuracy_preset_at((enum mech_accuracy)a);
            if (pr->promise <= target) break;
        }
    } else {
        const char *acc = in ? api_string(in, "accuracy", "balanced") : "balanced";
        pr = mech_accuracy_preset_at(MECH_ACCURACY_BALANCED);
        for (int a = 0; a < MECH_ACCURACY_COUNT; a++)
            if (!strcmp(mech_accuracy_preset_at((enum mech_accuracy)a)->name, acc))
                pr = mech_accuracy_preset_at((enum mech_accuracy)a);
        out->accuracy = pr->name;
        target = pr->promise;
    }
    /* the long-run tightening of mech_trajectory_choose (core/trajectory.c):
     * presets were calibrated on 20 pi dynamical times */
    const double calibrated_span = 62.831853071795865;
    const double length_factor = span > calibrated_span ? calibrated_span / span : 1.0;
    double rtol = pr->rtol_other * fmin(target / pr->promise, 10.0) * length_factor;
    if (rtol < 1e-15) rtol = 1e-15;
    out->chosen = 1;
    out->target = target;
    out->method = pr->method_other;
    out->opt.rtol = rtol;
    out->opt.atol = rtol * sys->state_scale;
    snprintf(out->reason, sizeof out->reason,
             "%s%s: preset \"%s\" (promise %.0e relative) -> %s at rtol %.3g%s%s; "
             "atol = rtol x %.6g on %s",
             in ? "" : "no integrator block: accuracy \"balanced\" by default; ", sys->equations,
             pr->name, pr->promise, pr->method_other, rtol,
             target < pr->promise ? " (target below every promise: round-off)" : "",
             length_factor < 1.0 ? " (tightened for a run of many dynamical times)" : "",
             sys->state_scale, sys->state);
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

json_t *api_integrator_block_selection(struct api_call *c, const struct api_integrator_choice *ch)
{
    json_t *sel = json_object();
    if (!sel) return NULL;
    json_object_set_new_nocheck(sel, "requested",
                                ch->requested ? json_deep_copy(ch->requested) : json_null());
    settings(c, sel, ch);
    if (ch->chosen) {
        json_object_set_new_nocheck(sel, "target_error", api_real(c, ch->target));
        json_object_set_new_nocheck(sel, "reason", json_string(ch->reason));
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
