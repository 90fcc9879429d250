/* integrators.c — GET /v1/integrators: every ODE method of the registry
 * (core/ode/integrators/registry.c) with its properties, order, doc string and
 * citation, and the accuracy presets with what each maps to. Everything comes
 * from the const descriptors, so the catalog cannot drift from the code. */
#include "ops/integrators/integrators.h"
#include "run/endpoint.h"

#include "mech/ode/ode.h"
#include "mech/frames/trajectory.h"

static const char target_doc[] =
    "{\"target_error\": x} (relative error on positions and velocities, or on the operation's "
    "state, 1e-15..0.1) and the presets (their promise is the target) go to the predictive "
    "chooser (core/chooser.c): every candidate method (closed_form when the scene has an exact "
    "solution, radau15, rk8pd, rkf45, gauss6, yoshida6, wisdom_holman when built, msbdf for "
    "stiff scenes) with the setting predicted to meet the target, its predicted error, "
    "evaluations and CPU seconds from a model calibrated by bench/bench_calibrate_chooser "
    "(error = A tol^a span^b above a round-off floor, span = the run in dynamical times), and a "
    "verdict; the cheapest predicted to meet the target runs. diagnostics.selection lists the "
    "candidates and, after the run, the achieved error beside the prediction; it says when a "
    "target may be beyond the round-off floor of a long run. The velocity_free / "
    "velocity_dependent methods shown per preset are what it typically picks on a 10-orbit "
    "Kepler scene, not a fixed mapping. \"dry_run\": true answers the selection alone. "
    "atol = rtol x the smaller of the scene's position scale max(|r0|, |v0| T, |a0| T^2/2) "
    "and velocity scale max(|v0|, |a0| T), with T the smaller of t_end and sqrt(|r0| / |a0|).";

json_t *api_integrators_catalog(void)
{
    json_t *methods = json_array();
    for (size_t i = 0; methods && i < mech_ode_method_count(); i++) {
        struct mech_ode_method_info mi = mech_ode_method_describe(mech_ode_method_at(i));
        json_t *settings = mi.adaptive ? json_pack("[s,s]", "rtol", "atol") : json_pack("[s]", "dt");
        json_array_append_new(
            methods, json_pack("{s:s,s:i,s:b,s:b,s:b,s:b,s:b,s:o,s:s,s:s}", "name", mi.name,
                               "order", mi.order, "adaptive", mi.adaptive, "symplectic",
                               mi.symplectic, "implicit", mi.implicit, "symmetric", mi.symmetric,
                               "second_order", mi.second_order, "settings", settings, "doc",
                               mi.doc ? mi.doc : "", "reference",
                               mi.reference ? mi.reference : ""));
    }
    json_t *presets = json_array();
    for (int a = 0; presets && a < MECH_ACCURACY_COUNT; a++) {
        const struct mech_accuracy_preset *p = mech_accuracy_preset_at((enum mech_accuracy)a);
        json_array_append_new(
            presets, json_pack("{s:s,s:f,s:{s:s,s:f},s:{s:s,s:f},s:s}", "name", p->name,
                               "promise", p->promise, "velocity_free", "method", p->method,
                               "rtol", p->rtol, "velocity_dependent", "method",
                               p->method_other, "rtol", p->rtol_other, "doc", p->doc));
    }
    return json_pack("{s:o,s:o,s:s,s:s}", "methods", methods, "accuracy_presets", presets,
                     "target_error", target_doc, "default",
                     "no integrator block means {\"accuracy\": \"balanced\"}");
}

json_t *api_op_integrators(struct api_call *c, const json_t *body)
{
    (void)c;
    (void)body;
    return api_integrators_catalog();
}

