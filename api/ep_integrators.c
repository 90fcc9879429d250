/* ep_integrators.c — GET /v1/integrators: every ODE method of the registry
 * (core/integrators/registry.c) with its properties, order, doc string and
 * citation, and the accuracy presets with what each maps to. Everything comes
 * from the const descriptors, so the catalog cannot drift from the code. */
#include "ep_integrators.h"
#include "endpoint.h"

#include "mech/ode.h"
#include "mech/trajectory.h"

static const char target_doc[] =
    "{\"target_error\": x} (relative error on positions and velocities, 1e-15..0.1) takes the "
    "loosest preset whose promise is <= x and scales its rtol by x / promise (at most 10x; "
    "radau15's eps is not loosened); velocity-free scenes (no drag, no Coriolis) get the "
    "preset's velocity_free method, others its velocity_dependent method. The rtol shown is for "
    "runs of up to 20 pi dynamical times sqrt(|r0| / |a0|); a longer run of span dynamical times "
    "gets it times 20 pi / span (squared for rk8pd on central-gravity scenes), and "
    "diagnostics.selection says when a target may be beyond the round-off floor of a long run "
    "(about 1.5e-16 x span^1.5 relative). atol = rtol x the smaller of the scene's position scale "
    "max(|r0|, |v0| T, |a0| T^2/2) and velocity scale max(|v0|, |a0| T), with T the smaller "
    "of t_end and sqrt(|r0| / |a0|).";

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

static json_t *integrators_resource(struct api_call *c, const json_t *body)
{
    (void)c;
    (void)body;
    return api_integrators_catalog();
}

const struct api_route api_route_integrators = {
    "GET",
    "/v1/integrators",
    "Every ODE method (order, properties, doc, reference) and the accuracy presets",
    "The methods the integrator block of every time-evolution operation accepts, each with its "
    "order, whether it is adaptive (rtol/atol) or fixed-step (dt), symplectic, implicit, "
    "symmetric or second-order, a paragraph on when to use it and its reference; and what the "
    "accuracy presets and target_error choose.",
    NULL,
    NULL,
    integrators_resource,
    0,
    0,
};
