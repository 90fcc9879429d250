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
    "Integrates m a = F + fictitious forces for one particle (notes §1.2-1.3). Frames: "
    "inertial (default); rotating with constant omega about the origin; earth: local axes x "
    "east, y north, z up at latitude_deg, omega = W (0, cos lat, sin lat), W default "
    "7.2921159e-5 rad/s (sidereal); the centrifugal acceleration of the origin is part of the "
    "local g you give. Fictitious terms: coriolis -2m omega x v, centrifugal "
    "-m omega x (omega x r) (default both in a non-inertial frame, none in an inertial one). "
    "Forces: uniform_gravity (m g), central_gravity (-m gm (r-c)/|r-c|^3), spring "
    "(-k (|r-a| - L) unit(r-a)), linear_drag (-b v, frame velocity). integrator: a method "
    "(adaptive rk8pd, rkck, rkf45, radau15, msbdf with rtol/atol; fixed-step euler, "
    "symplectic_euler, rk4, verlet, yoshida4, yoshida6, gauss4, gauss6, boris with dt; GET "
    "/v1/integrators describes each), or {\"accuracy\": \"draft\"|\"balanced\"|\"precise\"|"
    "\"machine\"} (relative error 1e-3, 1e-8, 1e-10, 1e-11 promised), or {\"target_error\": "
    "x} (relative, positions and velocities); the default is balanced. mechd picks radau15 for "
    "velocity-free scenes and rk8pd/rkf45 with drag or Coriolis, with atol scaled to the "
    "scene; diagnostics.selection says what it picked and why. A fixed-step run needing more "
    "steps than the budget is refused up front. Samples are evenly spaced in 0..t_end, each "
    "computed by a sub-step of the method from the start of its step (as accurate as the "
    "steps). stop: the first crossing of a coordinate value, located by Brent's method on the "
    "same sub-step solution to ~1e-15 relative in time; samples end there. model.terms lists "
    "every force and both fictitious terms, included or not, with the largest |acceleration| "
    "seen (an omitted term's size says what leaving it out neglects). Error evidence: "
    "diagnostics.invariants lists every conserved quantity of the scene - energy (inertial) or "
    "the Jacobi integral 1/2 m v^2 + U - 1/2 m |omega x r|^2 (rotating/earth; the last term "
    "only if centrifugal is modelled), conserved = false when drag dissipates it, and the "
    "angular momentum about the centre when every force is central about one point - with "
    "max_relative_drift = max |I - I0| / |I0| (diagnostics.invariant repeats the first). "
    "diagnostics.reference compares every sample with an exact solution (kepler: one "
    "central_gravity, universal-variable propagation; harmonic_oscillator: one spring of rest "
    "length 0, optional uniform gravity; uniform_gravity, optionally with linear_drag) or the "
    "notes' first-order Coriolis solution r0 + v0 t + g t^2/2 - omega x (v0 t^2 + g t^3/3) "
    "(rotating/earth frame, uniform gravity only; truncation_estimate is the size of the "
    "neglected second-order terms), in metres and relative to the largest |r| and |v| of the "
    "reference; null when the scene has none. Then error_estimate: true runs the scene again "
    "(adaptive: rtol/100, atol/100, or radau15 / rk8pd at round-off when that is beyond the "
    "method; fixed: dt/2, Richardson-scaled) within the same step "
    "budget and reports the difference. A fixed dt that does not resolve a close approach to "
    "a central mass, a particle reaching it, or any non-finite value (with the time and the "
    "last finite position) is a numerical-failure.";

static json_t *traj_op(struct api_call *c, const json_t *body)
{
    struct api_traj_request rq;
    if (!api_traj_request_parse(c, body, "", &rq)) return NULL;

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
    enum mech_status st =
        (t && pos && vel) ? mech_trajectory_integrate(&rq.p, &c->budget, &r, &e) : MECH_ENOMEM;
    if (st != MECH_OK) {
        free(t);
        free(pos);
        free(vel);
        return api_call_fail_core(c, st, &e, "");
    }

    json_t *res = json_object();
    json_t *jp = json_array(), *jv = json_array();
    json_object_set_new(res, "t", api_reals(c, t, r.n_samples));
    for (size_t i = 0; jp && jv && i < r.n_samples; i++) {
        json_array_append_new(jp, api_vec3(c, pos[i]));
        json_array_append_new(jv, api_vec3(c, vel[i]));
    }
    json_object_set_new(res, "position", jp);
    json_object_set_new(res, "velocity", jv);
    free(t);
    free(pos);
    free(vel);

    if (r.stopped) {
        json_t *s = json_object();
        json_object_set_new(s, "t", api_real(c, r.t_stop));
        json_object_set_new(s, "position", api_vec3(c, r.stop_position));
        json_object_set_new(s, "velocity", api_vec3(c, r.stop_velocity));
        json_object_set_new(res, "stopped", s);
    } else {
        json_object_set_new(res, "stopped", json_null());
    }

    json_t *terms = json_array();
    for (size_t i = 0; terms && i < r.n_terms; i++) {
        json_t *tm = json_object();
        json_object_set_new(tm, "term", json_string(r.terms[i].term));
        if (r.terms[i].force_index >= 0)
            json_object_set_new(tm, "force_index", json_integer(r.terms[i].force_index));
        json_object_set_new(tm, "included", json_boolean(r.terms[i].included));
        json_object_set_new(tm, "max_acceleration", api_real(c, r.terms[i].max_acceleration));
        json_array_append_new(terms, tm);
    }
    json_t *model = json_object();
    json_object_set_new(model, "terms", terms);
    json_object_set_new(res, "model", model);

    json_t *d = api_traj_diagnostics(c, &rq, &r);
    json_object_set_new(res, "diagnostics", d);

    if (!res || !jp || !jv || !terms || !model || !d ||
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
};
