/* ep_trajectory.c — POST /v1/trajectory: integrate a particle in an
 * inertial, rotating or local Earth frame (notes §1.2–1.3) with a chosen ODE
 * method, sampled evenly in time, optionally stopped at a coordinate
 * crossing; answers the samples, the stop event, the model terms with their
 * sizes, and diagnostics (steps, evaluations, energy / Jacobi drift).
 * core/trajectory.c does the physics, core/ode.c the integration. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "endpoint.h"
#include "mech/trajectory.h"
#include "trajectory_request.h"

static const char traj_schema[] = API_TRAJ_REQUEST_SCHEMA;

static const char traj_example[] =
    "{\"particle\": {\"mass\": 1, \"position\": [0, 0, 100], \"velocity\": [0, 0, 0]}, "
    "\"frame\": {\"type\": \"earth\", \"latitude_deg\": 32}, "
    "\"forces\": [{\"type\": \"uniform_gravity\", \"g\": [0, 0, -9.80665]}], "
    "\"fictitious\": [\"coriolis\"], \"t_end\": 10, \"samples\": 11, "
    "\"stop\": {\"coordinate\": \"z\", \"crosses\": 0, \"direction\": \"decreasing\"}}";

static const char traj_description[] =
    "Integrates m a = F + fictitious forces for one particle (notes §1.2-1.4). Frames: "
    "inertial (default); rotating about the origin with omega at t = 0, an optional constant "
    "angular acceleration omega_dot (omega(t) = omega + omega_dot t, the same seen from either "
    "frame) and an optional constant acceleration of the origin (frame axes; omega = [0, 0, 0] "
    "gives a purely accelerating frame); earth: local axes x east, y north, z up at "
    "latitude_deg, omega = W (0, cos lat, sin lat), W default 7.292115e-5 rad/s (IERS 2010, the Earth's rotation relative to inertial space); "
    "the centrifugal acceleration of the origin is part of the local g you give. Fictitious "
    "terms (notes §1.2): coriolis -2m omega x v, centrifugal -m omega x (omega x r), euler "
    "-m omega_dot x r, translational -m A; a list (default all four in a non-inertial frame, "
    "none in an inertial one), or \"auto\": mechd bounds each term's acceleration along the "
    "motion with a first pass at draft accuracy and keeps a term only when |a| T^2/2 (relative "
    "to the largest |r|) or |a| T (relative to the largest |v|) exceeds target/10 (T the "
    "duration; target from the integrator block); terms identically zero in the frame are not "
    "carried. model.terms lists every force and the four fictitious terms with included, the "
    "largest |acceleration| seen, and under auto estimated_effect and the reason; model.auto "
    "gives the rule, scales and the first pass; model.state says whether the scene was "
    "integrated in two dimensions (a planar scene: r0, v0, every force and modelled term keep "
    "it in one plane through the origin) or three. Forces: uniform_gravity (m g), "
    "central_gravity (-m gm (r-c)/|r-c|^3), spring (-k (|r-a| - L) unit(r-a)), linear_drag (-b "
    "v, frame velocity), lorentz (q (E + v x B), E in V/m, B in T, frame axes, q = "
    "particle.charge in C; velocity dependent: Boris applies it through its rotation, w = qB/m "
    "+ 2 omega), third_body_tide (a body of mass M or gm = GM fixed at position d in the frame: "
    "GM [(d - r)/|d - r|^3 - d/|d|^3], computed without cancellation for |r| << |d|). "
    "integrator: a method (adaptive rk8pd, rkck, rkf45, radau15, msbdf with rtol/atol; "
    "fixed-step euler, symplectic_euler, rk4, verlet, yoshida4, yoshida6, gauss4, gauss6, boris "
    "with dt; GET /v1/integrators describes each), or {\"accuracy\": \"draft\"|\"balanced\"|"
    "\"precise\"|\"machine\"} (relative error 1e-3, 1e-8, 1e-10, 1e-11 promised), or "
    "{\"target_error\": x} (relative, positions and velocities); the default is balanced. mechd "
    "picks rk8pd (draft) or radau15 for velocity-free scenes and rk8pd/rkf45 with drag, Coriolis "
    "or a magnetic field, with atol scaled to the scene; diagnostics.selection says what it picked and why. "
    "Closed form: when the request selects by accuracy (not an explicit method) and the scene "
    "has an exact solution (kepler, harmonic_oscillator, uniform_gravity[_linear_drag], the free "
    "particle), the answer is evaluated from it, nothing integrated: diagnostics.method and "
    "selection.method closed_form, steps 0, evaluations = the samples (+ the stop search), the "
    "stop crossing located on the closed form to round-off, selection.achieved the evidence "
    "(invariant drift, universal Kepler equation residual); {\"closed_form\": false} in the "
    "integrator block integrates instead. A "
    "fixed-step run needing more steps than the budget is refused up front. Samples are evenly "
    "spaced in 0..t_end, each computed by a sub-step of the method from the start of its step "
    "(as accurate as the steps). stop: the first crossing of a coordinate value, located by "
    "Brent's method on the same sub-step solution to ~1e-15 relative in time; samples end "
    "there. Error evidence: diagnostics.invariants lists every conserved quantity of the scene "
    "with a note - energy (inertial) or the Jacobi integral 1/2 m v^2 + U - 1/2 m |omega x r|^2 "
    "+ m A.r (non-inertial; the last terms only if modelled), U including -q E.r for a static "
    "uniform E (v x B and Coriolis do no work) and the tidal potential; conserved = false when "
    "drag dissipates it or when omega changes with time (then no energy-like integral exists), "
    "and the angular momentum about the centre when every force is central about one point - "
    "with max_relative_drift = max |I - I0| / |I0| (diagnostics.invariant repeats the first). "
    "diagnostics.reference compares every sample with an exact solution (kepler: one "
    "central_gravity, universal-variable propagation; harmonic_oscillator: one spring of rest "
    "length 0, optional uniform gravity; uniform_gravity (minus a modelled A), optionally with "
    "linear_drag) or the notes' first-order Coriolis solution r0 + v0 t + g t^2/2 - omega x (v0 "
    "t^2 + g t^3/3) (rotating/earth frame with constant omega, uniform gravity only; "
    "truncation_estimate is the size of the neglected second-order terms), in metres and "
    "relative to the largest |r| and |v| of the reference; null when the scene has none. Then "
    "error_estimate: true runs the scene again (adaptive: rtol/100, atol/100, or radau15 / "
    "rk8pd at round-off when that is beyond the method; fixed: dt/2, Richardson-scaled) within "
    "the same step budget and reports the difference. A fixed dt that does not resolve a close "
    "approach to a central mass, a particle reaching it, or any non-finite value (with the time "
    "and the last finite position) is a numerical-failure.";

static json_t *traj_op(struct api_call *c, const json_t *body)
{
    struct api_traj_request rq;
    if (!api_traj_request_parse(c, body, "", &rq)) return NULL;
    if (rq.dry_run) return api_traj_dry_run(c, &rq);

    /* Output buffers, owned here: samples x (t, position, velocity). */
    const size_t n = rq.p.samples;
    double *t = malloc(n * sizeof *t);
    struct mech_vec3 *pos = malloc(n * sizeof *pos);
    struct mech_vec3 *vel = malloc(n * sizeof *vel);
    struct mech_trajectory_result r;
    memset(&r, 0, sizeof r);
    r.t = t;
    r.position = pos;
    r.velocity = vel;
    struct mech_error e;
    mech_error_clear(&e);
    const double cpu0 = mech_cpu_seconds();
    enum mech_status st =
        !(t && pos && vel) ? MECH_ENOMEM
        : rq.closed_form   ? mech_trajectory_closed_form_ex(&rq.p, &r, &rq.evidence, &c->budget, &e)
                           : mech_trajectory_integrate(&rq.p, &c->budget, &r, &e);
    rq.cpu_s = mech_cpu_seconds() - cpu0;
    if (st != MECH_OK) {
        free(t);
        free(pos);
        free(vel);
        return api_call_fail_core(c, st, &e, "");
    }

    json_t *res = json_object();
    json_t *jp = json_array(), *jv = json_array();
    json_object_set_new_nocheck(res, "t", api_reals(c, t, r.n_samples));
    for (size_t i = 0; jp && jv && i < r.n_samples; i++) {
        json_array_append_new(jp, api_vec3(c, pos[i]));
        json_array_append_new(jv, api_vec3(c, vel[i]));
    }
    json_object_set_new_nocheck(res, "position", jp);
    json_object_set_new_nocheck(res, "velocity", jv);
    free(t);
    free(pos);
    free(vel);

    if (r.stopped) {
        json_t *s = json_object();
        json_object_set_new_nocheck(s, "t", api_real(c, r.t_stop));
        json_object_set_new_nocheck(s, "position", api_vec3(c, r.stop_position));
        json_object_set_new_nocheck(s, "velocity", api_vec3(c, r.stop_velocity));
        json_object_set_new_nocheck(res, "stopped", s);
    } else {
        json_object_set_new_nocheck(res, "stopped", json_null());
    }

    json_t *model = api_traj_model(c, &rq, &r);
    json_object_set_new_nocheck(res, "model", model);

    json_t *d = api_traj_diagnostics(c, &rq, &r);
    json_object_set_new_nocheck(res, "diagnostics", d);

    if (!res || !jp || !jv || !model || !d ||
        json_array_size(jp) != r.n_samples) {
        json_decref(res);
        return api_call_fail_core(c, MECH_ENOMEM, NULL, "");
    }
    return res;
}

const struct api_route api_route_trajectory = {
    "POST",
    "/v1/trajectory",
    "Integrate a particle in an inertial, rotating or Earth frame, with model terms and drift",
    traj_description,
    traj_schema,
    traj_example,
    traj_op,
    1,
    0,
};
