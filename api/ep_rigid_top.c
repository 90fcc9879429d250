/* ep_rigid_top.c — POST /v1/rigid/top: the heavy symmetric top with a fixed
 * tip (notes §2.10), integrated as a rigid body so theta = 0 is not singular,
 * with Euler angles per sample, the nutation range from the turning-point
 * cubic beside the measured one, conserved p_phi, p_psi and E, the sleeping-top
 * condition and the steady-precession rates. Physics: core/top.c. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "endpoint.h"
#include "integrator_block.h"
#include "mech/euler_rates.h"
#include "mech/top.h"
#include "trajectory_request.h"

static json_t *quantity(struct api_call *c, double initial, double final, double drift)
{
    json_t *j = json_object();
    json_object_set_new_nocheck(j, "initial", api_real(c, initial));
    json_object_set_new_nocheck(j, "final", api_real(c, final));
    json_object_set_new_nocheck(j, "max_relative_drift", api_real(c, drift));
    return j;
}

static json_t *real_or_null(struct api_call *c, double x)
{
    return isfinite(x) ? api_real(c, x) : json_null();
}

json_t *api_op_rigid_top(struct api_call *c, const json_t *body)
{
    struct mech_top_problem p;
    memset(&p, 0, sizeof p);
    p.I1 = api_number(body, "I1", 0);
    p.I3 = api_number(body, "I3", 0);
    p.mass = api_number(body, "mass", 0);
    p.distance = api_number(body, "distance", 0);
    p.g = api_number_of(body, "g");
    p.theta = api_number(body, "theta", 0);
    p.phi = api_number(body, "phi", 0);
    p.psi = api_number(body, "psi", 0);
    p.theta_dot = api_number(body, "theta_dot", 0);
    p.phi_dot = api_number(body, "phi_dot", 0);
    p.psi_dot = api_number(body, "psi_dot", 0);
    p.t_end = api_number(body, "t_end", 1);
    p.samples = (size_t)api_number_of(body, "samples");
    struct mech_error e;
    mech_error_clear(&e);
    struct api_integrator_choice ch;
    static const struct api_integrator_system top_eqs = {
        "Euler's equations of the top with gravity's torque and a quaternion attitude",
        "the dimensionless state (quaternion and omega / rate scale)", 1.0, 0, 0.0};
    /* the cost law's own span, the samples and a pilot for long runs (core/rigid/top.c) */
    struct api_integrator_system sys = top_eqs;
    sys.samples = p.samples;
    const struct mech_pilot_system pilot = {mech_top_pilot_run, &p};
    const struct api_integrator_hooks hooks = {mech_top_cost_span(&p), 0.0, 0.0, &pilot};
    if (!api_integrator_block_parse_hooks(c, json_object_get(body, "integrator"), "/integrator",
                                          p.t_end * mech_top_rate_scale(&p), &sys, NULL, &hooks,
                                          &ch))
        return NULL;
    if (api_dry_run_requested(body)) return api_dry_run_answer(c, api_integrator_block_selection(c, &ch));
    p.method = ch.method;
    p.opt = ch.opt;

    const size_t n = p.samples;
    double *buf = malloc(5 * n * sizeof *buf);
    struct mech_vec3 *ax = malloc(n * sizeof *ax);
    int *pole = malloc(n * sizeof *pole);
    json_t *out = NULL;
    if (!buf || !ax || !pole) {
        mech_error_set(&e, MECH_ENOMEM, NULL, "out of memory for %zu samples", n);
        api_call_fail_core(c, MECH_ENOMEM, &e, "");
        goto done;
    }
    struct mech_top_result r;
    memset(&r, 0, sizeof r);
    r.t = buf;
    r.theta = buf + n;
    r.phi = buf + 2 * n;
    r.psi = buf + 3 * n;
    r.phi_plus_psi = buf + 4 * n;
    r.axis = ax;
    r.at_pole = pole;
    enum mech_status st = mech_top_integrate(&p, &c->budget, &r, &e);
    if (st != MECH_OK) {
        api_call_fail_core(c, st, &e, "");
        goto done;
    }
    const size_t ns = r.n_samples;
    out = json_object();
    json_object_set_new_nocheck(out, "t", api_reals(c, r.t, ns));
    json_object_set_new_nocheck(out, "theta", api_reals(c, r.theta, ns));
    json_object_set_new_nocheck(out, "phi", api_reals(c, r.phi, ns));
    json_object_set_new_nocheck(out, "psi", api_reals(c, r.psi, ns));
    json_object_set_new_nocheck(out, "phi_plus_psi", api_reals(c, r.phi_plus_psi, ns));
    json_t *ja = json_array(), *jp = json_array();
    for (size_t i = 0; i < ns; i++) {
        json_array_append_new(ja, api_vec3(c, ax[i]));
        if (pole[i]) json_array_append_new(jp, json_integer((json_int_t)i));
    }
    json_object_set_new_nocheck(out, "axis", ja);
    json_object_set_new_nocheck(out, "pole_samples", jp);
    json_object_set_new_nocheck(out, "omega3", api_real(c, r.omega3));
    {
        /* the body (and space) angular velocity at t = 0 from the Euler rates */
        const double ang[3] = {p.phi, p.theta, p.psi}, rt[3] = {p.phi_dot, p.theta_dot, p.psi_dot};
        struct mech_euler_kinematics k;
        json_t *w0 = json_object();
        if (mech_euler_kinematics(ang, rt, &k, NULL) == MECH_OK) {
            json_object_set_new_nocheck(w0, "body", api_vec3(c, k.omega_body));
            json_object_set_new_nocheck(w0, "space", api_vec3(c, k.omega_space));
            json_object_set_new_nocheck(w0, "magnitude", api_real(c, mech_vec3_norm(k.omega_body)));
        }
        json_object_set_new_nocheck(out, "initial_omega", w0);
    }

    json_t *nu = json_object();
    json_object_set_new_nocheck(nu, "theta_min", api_real(c, r.turning.theta_min));
    json_object_set_new_nocheck(nu, "theta_max", api_real(c, r.turning.theta_max));
    json_object_set_new_nocheck(nu, "steady", json_boolean(r.turning.steady));
    json_object_set_new_nocheck(nu, "measured_theta_min", api_real(c, r.theta_min_measured));
    json_object_set_new_nocheck(nu, "measured_theta_max", api_real(c, r.theta_max_measured));
    json_object_set_new_nocheck(nu, "cubic_roots_u",
                                api_reals(c, r.turning.roots, (size_t)r.turning.n_roots));
    json_object_set_new_nocheck(out, "nutation", nu);

    json_t *co = json_object();
    json_object_set_new_nocheck(co, "p_phi",
                                quantity(c, r.p_phi0, r.p_phi_final, r.max_p_phi_drift));
    json_object_set_new_nocheck(co, "p_psi",
                                quantity(c, r.p_psi0, r.p_psi_final, r.max_p_psi_drift));
    json_object_set_new_nocheck(co, "energy", quantity(c, r.E0, r.E_final, r.max_E_drift));
    json_object_set_new_nocheck(out, "conserved", co);

    json_t *sl = json_object();
    json_object_set_new_nocheck(sl, "lhs_I3sq_omega3sq", api_real(c, r.sleep_lhs));
    json_object_set_new_nocheck(sl, "rhs_4_I1_M_g_h", api_real(c, r.sleep_rhs));
    json_object_set_new_nocheck(sl, "stable", json_boolean(r.sleep_stable));
    json_object_set_new_nocheck(sl, "critical_omega3", api_real(c, r.critical_omega3));
    json_object_set_new_nocheck(out, "sleeping_top", sl);

    json_t *pr = json_object();
    json_object_set_new_nocheck(pr, "steady_slow", real_or_null(c, r.precession_slow));
    json_object_set_new_nocheck(pr, "steady_fast", real_or_null(c, r.precession_fast));
    json_object_set_new_nocheck(pr, "gyroscopic_approximation",
                                real_or_null(c, r.precession_gyroscopic));
    json_object_set_new_nocheck(pr, "measured_mean_rate", real_or_null(c, r.precession_measured));
    json_object_set_new_nocheck(out, "precession", pr);
    json_object_set_new_nocheck(out, "rate_scale", api_real(c, r.rate_scale));

    json_t *d = json_object();
    api_integrator_block_stats(c, d, &ch, &r.stats);
    json_object_set_new_nocheck(d, "quaternion_norm_drift",
                                api_real(c, r.max_quaternion_norm_drift));
    json_object_set_new_nocheck(d, "selection", api_integrator_block_selection(c, &ch));
    json_object_set_new_nocheck(out, "diagnostics", d);
    json_object_set_new_nocheck(out, "cost", json_object());
done:
    free(buf);
    free(ax);
    free(pole);
    return out;
}

