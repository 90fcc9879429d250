/* top.c — POST /v1/rigid/top: the heavy symmetric top with a fixed
 * tip (notes §2.10), integrated as a rigid body so theta = 0 is not singular,
 * with Euler angles per sample, the nutation range from the turning-point
 * cubic beside the measured one, conserved p_phi, p_psi and E, the sleeping-top
 * condition and the steady-precession rates. What it computes is one call,
 * mech_top_answer_run (core/answers/rigid/top_answer.c, on core/rigid/top.c); this
 * file reads the request, chooses the integrator (api/request/integrator_block.c)
 * and encodes the answer. */
#include <math.h>
#include <string.h>

#include "run/endpoint.h"
#include "request/integrator_block.h"
#include "mech/answers/rigid/top_answer.h"

static void set(json_t *o, const char *key, json_t *v)
{
    json_object_set_new_nocheck(o, key, v);
}

static json_t *real_or_null(struct api_call *c, double x)
{
    return isfinite(x) ? api_real(c, x) : json_null();
}

/* {initial, final, max_relative_drift} of a conserved quantity. */
static json_t *quantity(struct api_call *c, double initial, double final, double drift)
{
    json_t *j = json_object();
    set(j, "initial", api_real(c, initial));
    set(j, "final", api_real(c, final));
    set(j, "max_relative_drift", api_real(c, drift));
    return j;
}

/* The request (schema-validated: I1, I3, mass, distance, theta, t_end
 * required; g, samples, the angles phi, psi and the rates theta_dot,
 * phi_dot, psi_dot defaulted by the schema). */
static void read_problem(const json_t *body, struct mech_top_problem *p)
{
    memset(p, 0, sizeof *p);
    p->I1 = api_number_of(body, "I1");
    p->I3 = api_number_of(body, "I3");
    p->mass = api_number_of(body, "mass");
    p->distance = api_number_of(body, "distance");
    p->g = api_number_of(body, "g");
    p->theta = api_number_of(body, "theta");
    p->phi = api_number_of(body, "phi");
    p->psi = api_number_of(body, "psi");
    p->theta_dot = api_number_of(body, "theta_dot");
    p->phi_dot = api_number_of(body, "phi_dot");
    p->psi_dot = api_number_of(body, "psi_dot");
    p->t_end = api_number_of(body, "t_end");
    p->samples = (size_t)api_number_of(body, "samples");
}

/* The integrator block, priced with the top's own cost span and a pilot
 * (core/rigid/top.c). Returns 0 after recording an error. */
static int choose_method(struct api_call *c, const json_t *body, struct mech_top_problem *p,
                         struct api_integrator_choice *ch)
{
    static const struct api_integrator_system top_eqs = {
        "Euler's equations of the top with gravity's torque and a quaternion attitude",
        "the dimensionless state (quaternion and omega / rate scale)", 1.0, 0, 0.0, "heavy_top", 0};
    struct api_integrator_system sys = top_eqs;
    sys.samples = p->samples;
    const struct mech_pilot_system pilot = {mech_top_pilot_run, p};
    const struct api_integrator_hooks hooks = {mech_top_cost_span(p), 0.0, 0.0, &pilot, 0.0};
    return api_integrator_block_parse_hooks(c, json_object_get(body, "integrator"), "/integrator",
                                            p->t_end * mech_top_rate_scale(p), &sys, NULL, &hooks,
                                            ch);
}

/* t, the Euler angles, the axis, the pole samples, omega3 and initial_omega. */
static json_t *encode_samples(struct api_call *c, const struct mech_top_answer *a)
{
    const struct mech_top_result *r = &a->r;
    const size_t ns = r->n_samples;
    json_t *out = json_object();
    set(out, "t", api_reals(c, r->t, ns));
    set(out, "theta", api_reals(c, r->theta, ns));
    set(out, "phi", api_reals(c, r->phi, ns));
    set(out, "psi", api_reals(c, r->psi, ns));
    set(out, "phi_plus_psi", api_reals(c, r->phi_plus_psi, ns));
    json_t *ja = json_array(), *jp = json_array();
    for (size_t i = 0; i < ns; i++) {
        json_array_append_new(ja, api_vec3(c, r->axis[i]));
        if (r->at_pole[i]) json_array_append_new(jp, json_integer((json_int_t)i));
    }
    set(out, "axis", ja);
    set(out, "pole_samples", jp);
    set(out, "omega3", api_real(c, r->omega3));
    json_t *w0 = json_object(); /* the body (and space) omega at t = 0 from the Euler rates */
    if (a->has_initial_omega) {
        set(w0, "body", api_vec3(c, a->initial_omega_body));
        set(w0, "space", api_vec3(c, a->initial_omega_space));
        set(w0, "magnitude", api_real(c, a->initial_omega_magnitude));
    }
    set(out, "initial_omega", w0);
    return out;
}

/* nutation, conserved, sleeping_top, precession and rate_scale into out. */
static void encode_closed_forms(struct api_call *c, const struct mech_top_result *r, json_t *out)
{
    json_t *nu = json_object(), *co = json_object(), *sl = json_object(), *pr = json_object();
    set(nu, "theta_min", api_real(c, r->turning.theta_min));
    set(nu, "theta_max", api_real(c, r->turning.theta_max));
    set(nu, "steady", json_boolean(r->turning.steady));
    set(nu, "measured_theta_min", api_real(c, r->theta_min_measured));
    set(nu, "measured_theta_max", api_real(c, r->theta_max_measured));
    set(nu, "cubic_roots_u", api_reals(c, r->turning.roots, (size_t)r->turning.n_roots));
    set(nu, "period", real_or_null(c, r->turning.nutation_period));
    set(out, "nutation", nu);
    set(co, "p_phi", quantity(c, r->p_phi0, r->p_phi_final, r->max_p_phi_drift));
    set(co, "p_psi", quantity(c, r->p_psi0, r->p_psi_final, r->max_p_psi_drift));
    set(co, "energy", quantity(c, r->E0, r->E_final, r->max_E_drift));
    set(out, "conserved", co);
    set(sl, "lhs_I3sq_omega3sq", api_real(c, r->sleep_lhs));
    set(sl, "rhs_4_I1_M_g_h", api_real(c, r->sleep_rhs));
    set(sl, "stable", json_boolean(r->sleep_stable));
    set(sl, "critical_omega3", api_real(c, r->critical_omega3));
    set(out, "sleeping_top", sl);
    set(pr, "steady_precession_rate_slow", real_or_null(c, r->precession_slow));
    set(pr, "steady_precession_rate_fast", real_or_null(c, r->precession_fast));
    set(pr, "steady_slow", real_or_null(c, r->precession_slow)); /* deprecated alias */
    set(pr, "steady_fast", real_or_null(c, r->precession_fast)); /* deprecated alias */
    set(pr, "nutation_averaged_rate", real_or_null(c, r->turning.precession_mean));
    set(pr, "gyroscopic_approximation", real_or_null(c, r->precession_gyroscopic));
    set(pr, "measured_mean_rate", real_or_null(c, r->precession_measured));
    set(out, "precession", pr);
    set(out, "rate_scale", api_real(c, r->rate_scale));
}

json_t *api_op_rigid_top(struct api_call *c, const json_t *body)
{
    struct mech_top_problem p;
    struct api_integrator_choice ch;
    read_problem(body, &p);
    if (!choose_method(c, body, &p, &ch)) return NULL;
    if (api_dry_run_requested(body))
        return api_dry_run_answer(c, api_integrator_block_selection(c, &ch));
    p.method = ch.method;
    p.opt = ch.opt;
    struct mech_top_answer a;
    struct mech_error e;
    mech_error_clear(&e);
    enum mech_status st = mech_top_answer_run(&p, &c->budget, &a, &e);
    json_t *out = NULL;
    if (st == MECH_OK) {
        out = encode_samples(c, &a);
        encode_closed_forms(c, &a.r, out);
        json_t *d = json_object();
        api_integrator_block_stats(c, d, &ch, &a.r.stats);
        set(d, "quaternion_norm_drift", api_real(c, a.r.max_quaternion_norm_drift));
        set(d, "selection", api_integrator_block_selection_run(c, &ch, -1.0, NULL, 0));
        set(out, "diagnostics", d);
        set(out, "cost", json_object());
    } else {
        api_call_fail_core(c, st, &e, "");
    }
    mech_top_answer_free(&a);
    return out;
}
