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

/* ---- request schema -------------------------------------------------------
 * Bounds keep every intermediate finite: lengths and speeds <= 1e15,
 * accelerations <= 1e15, gm, k, b, mass <= 1e30, rotation rates <= 1e6 rad/s,
 * t_end <= 1e15 s (the step budget and deadline bound the work). */
#define TRAJ_NUM(lo, hi) "{\"type\":\"number\",\"minimum\":" lo ",\"maximum\":" hi "}"
#define TRAJ_VEC3(desc)                                                                     \
    "{\"type\":\"array\",\"minItems\":3,\"maxItems\":3,\"items\":" TRAJ_NUM("-1e15", "1e15") \
    ",\"description\":\"" desc "\"}"
#define TRAJ_OBJ(req, props) \
    "{\"type\":\"object\",\"additionalProperties\":false,\"required\":[" req "],\"properties\":{" props "}}"

static const char traj_schema[] =
    "{\"type\":\"object\",\"additionalProperties\":false,"
    "\"required\":[\"particle\",\"t_end\"],"
    "\"properties\":{"
    "\"particle\":" TRAJ_OBJ(
        "\"mass\",\"position\",\"velocity\"",
        "\"mass\":{\"type\":\"number\",\"exclusiveMinimum\":0,\"maximum\":1e30,"
        "\"description\":\"kg\"},"
        "\"position\":" TRAJ_VEC3("m, frame axes") ","
        "\"velocity\":" TRAJ_VEC3("m/s, relative to the frame")) ","
    "\"frame\":{\"description\":\"default {\\\"type\\\": \\\"inertial\\\"}\",\"oneOf\":["
    TRAJ_OBJ("\"type\"", "\"type\":{\"const\":\"inertial\"}") ","
    TRAJ_OBJ("\"type\",\"omega\"",
             "\"type\":{\"const\":\"rotating\"},"
             "\"omega\":{\"type\":\"array\",\"minItems\":3,\"maxItems\":3,\"items\":"
             TRAJ_NUM("-1e6", "1e6") ",\"description\":\"constant angular velocity of the "
             "frame about the origin, rad/s, frame axes\"}") ","
    TRAJ_OBJ("\"type\",\"latitude_deg\"",
             "\"type\":{\"const\":\"earth\"},"
             "\"latitude_deg\":{\"type\":\"number\",\"minimum\":-90,\"maximum\":90},"
             "\"omega_magnitude\":{\"type\":\"number\",\"minimum\":0,\"maximum\":1e6,"
             "\"default\":7.2921159e-05,\"description\":\"rad/s, default sidereal\"}")
    "]},"
    "\"forces\":{\"type\":\"array\",\"maxItems\":32,\"items\":{\"oneOf\":["
    TRAJ_OBJ("\"type\",\"g\"",
             "\"type\":{\"const\":\"uniform_gravity\"},"
             "\"g\":" TRAJ_VEC3("gravitational acceleration, m/s^2 (e.g. [0, 0, -9.80665])")) ","
    TRAJ_OBJ("\"type\",\"gm\"",
             "\"type\":{\"const\":\"central_gravity\"},"
             "\"gm\":{\"type\":\"number\",\"exclusiveMinimum\":0,\"maximum\":1e30,"
             "\"description\":\"G M, m^3/s^2\"},"
             "\"center\":" TRAJ_VEC3("m, default [0, 0, 0]")) ","
    TRAJ_OBJ("\"type\",\"k\"",
             "\"type\":{\"const\":\"spring\"},"
             "\"k\":{\"type\":\"number\",\"minimum\":0,\"maximum\":1e30,\"description\":\"N/m\"},"
             "\"anchor\":" TRAJ_VEC3("m, default [0, 0, 0]") ","
             "\"rest_length\":{\"type\":\"number\",\"minimum\":0,\"maximum\":1e15,"
             "\"default\":0}") ","
    TRAJ_OBJ("\"type\",\"b\"",
             "\"type\":{\"const\":\"linear_drag\"},"
             "\"b\":{\"type\":\"number\",\"minimum\":0,\"maximum\":1e30,"
             "\"description\":\"kg/s: F = -b v\"}")
    "]}},"
    "\"fictitious\":{\"type\":\"array\",\"maxItems\":2,\"uniqueItems\":true,"
    "\"items\":{\"enum\":[\"coriolis\",\"centrifugal\"]},"
    "\"description\":\"terms modelled in a rotating or earth frame; default both\"},"
    "\"t_end\":{\"type\":\"number\",\"exclusiveMinimum\":0,\"maximum\":1e15,\"description\":\"s\"},"
    "\"samples\":{\"type\":\"integer\",\"minimum\":2,\"maximum\":100000,\"default\":101},"
    "\"integrator\":{\"description\":\"default {\\\"method\\\": \\\"rk8pd\\\", \\\"rtol\\\": "
    "1e-10, \\\"atol\\\": 1e-12}\",\"oneOf\":["
    TRAJ_OBJ("\"method\"",
             "\"method\":{\"enum\":[\"rk8pd\",\"rkck\",\"rkf45\"]},"
             "\"rtol\":{\"type\":\"number\",\"minimum\":1e-15,\"maximum\":0.1,\"default\":1e-10},"
             "\"atol\":{\"type\":\"number\",\"minimum\":0,\"maximum\":1e15,\"default\":1e-12}") ","
    TRAJ_OBJ("\"method\",\"dt\"",
             "\"method\":{\"enum\":[\"rk4\",\"verlet\"]},"
             "\"dt\":{\"type\":\"number\",\"exclusiveMinimum\":0,\"maximum\":1e15,"
             "\"description\":\"fixed step, s\"}")
    "]},"
    "\"stop\":" TRAJ_OBJ(
        "\"coordinate\",\"crosses\"",
        "\"coordinate\":{\"enum\":[\"x\",\"y\",\"z\"]},"
        "\"crosses\":" TRAJ_NUM("-1e15", "1e15") ","
        "\"direction\":{\"enum\":[\"decreasing\",\"increasing\",\"either\"],"
        "\"default\":\"either\"}") ","
    "\"cost\":{\"type\":\"boolean\",\"default\":true,"
    "\"description\":\"false omits the cost block (byte-identical answers)\"}"
    "}}";

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
    "(-k (|r-a| - L) unit(r-a)), linear_drag (-b v, frame velocity). Methods: rk8pd, rkck, "
    "rkf45 (GSL adaptive, rtol/atol per component, default rk8pd 1e-10/1e-12) or rk4, verlet "
    "(fixed dt; verlet is symplectic without velocity-dependent forces; a run needing more "
    "steps than the server's step budget is refused up front). Samples are evenly spaced in "
    "0..t_end, each computed by a sub-step of the method from the start of its step (as "
    "accurate as the steps). stop: the first crossing of a coordinate value, located by "
    "Brent's method on the same sub-step solution to ~1e-15 relative in time; samples end "
    "there. model.terms lists every force and both fictitious terms, included or not, with "
    "the largest |acceleration| seen over the samples and steps (an omitted term's size "
    "says what leaving it out neglects). diagnostics.invariant is the energy (inertial) or "
    "the Jacobi integral 1/2 m v^2 + U - 1/2 m |omega x r|^2 (rotating/earth; the last term "
    "only if centrifugal is modelled), with conserved = false when drag dissipates it; "
    "max_relative_drift is max |I - I0| / |I0|. A fixed dt that does not resolve a close "
    "approach to a central mass, or a particle reaching it, is a numerical-failure.";

static int axis_of(const char *s) { return s[0] - 'x'; }

static enum mech_force_type force_type_of(const char *s)
{
    if (strcmp(s, "central_gravity") == 0) return MECH_FORCE_CENTRAL_GRAVITY;
    if (strcmp(s, "spring") == 0) return MECH_FORCE_SPRING;
    if (strcmp(s, "linear_drag") == 0) return MECH_FORCE_LINEAR_DRAG;
    return MECH_FORCE_UNIFORM_GRAVITY;
}

/* Parse the schema-validated body into p (forces into the caller's array).
 * Returns 0 after recording a validation error. */
static int parse(struct api_call *c, const json_t *body, struct mech_trajectory_problem *p,
                 struct mech_force *forces)
{
    const struct mech_vec3 zero = mech_vec3_make(0, 0, 0);
    memset(p, 0, sizeof *p);
    const json_t *part = json_object_get(body, "particle");
    p->mass = api_number(part, "mass", 0);
    p->position = api_vec3_member(part, "position", zero);
    p->velocity = api_vec3_member(part, "velocity", zero);

    const json_t *frame = json_object_get(body, "frame");
    const char *ft = frame ? api_string(frame, "type", "inertial") : "inertial";
    if (strcmp(ft, "rotating") == 0) {
        p->frame.type = MECH_FRAME_ROTATING;
        p->frame.omega = api_vec3_member(frame, "omega", zero);
    } else if (strcmp(ft, "earth") == 0) {
        p->frame.type = MECH_FRAME_EARTH;
        p->frame.latitude_deg = api_number(frame, "latitude_deg", 0);
        p->frame.omega_magnitude = api_number(frame, "omega_magnitude", MECH_EARTH_OMEGA_SIDEREAL);
    } else {
        p->frame.type = MECH_FRAME_INERTIAL;
    }

    const json_t *fs = json_object_get(body, "forces");
    p->n_forces = json_array_size(fs);
    for (size_t i = 0; i < p->n_forces; i++) {
        const json_t *f = json_array_get(fs, i);
        struct mech_force *mf = &forces[i];
        memset(mf, 0, sizeof *mf);
        mf->type = force_type_of(api_string(f, "type", ""));
        switch (mf->type) {
        case MECH_FORCE_UNIFORM_GRAVITY:
            mf->u.uniform_gravity.g = api_vec3_member(f, "g", zero);
            break;
        case MECH_FORCE_CENTRAL_GRAVITY:
            mf->u.central_gravity.gm = api_number(f, "gm", 0);
            mf->u.central_gravity.center = api_vec3_member(f, "center", zero);
            break;
        case MECH_FORCE_SPRING:
            mf->u.spring.k = api_number(f, "k", 0);
            mf->u.spring.anchor = api_vec3_member(f, "anchor", zero);
            mf->u.spring.rest_length = api_number(f, "rest_length", 0);
            break;
        case MECH_FORCE_LINEAR_DRAG:
            mf->u.linear_drag.b = api_number(f, "b", 0);
            break;
        }
    }
    p->forces = forces;

    const json_t *fic = json_object_get(body, "fictitious");
    if (fic) {
        if (p->frame.type == MECH_FRAME_INERTIAL && json_array_size(fic) > 0) {
            api_call_invalid(c, "/fictitious",
                             "fictitious terms need a rotating or earth frame; an inertial "
                             "frame has none");
            return 0;
        }
        for (size_t i = 0; i < json_array_size(fic); i++) {
            const char *s = json_string_value(json_array_get(fic, i));
            p->fictitious |= strcmp(s, "coriolis") == 0 ? MECH_FICTITIOUS_CORIOLIS
                                                        : MECH_FICTITIOUS_CENTRIFUGAL;
        }
    } else {
        p->fictitious = MECH_FICTITIOUS_CORIOLIS | MECH_FICTITIOUS_CENTRIFUGAL;
    }

    p->t_end = api_number(body, "t_end", 0);
    p->samples = (size_t)api_number(body, "samples", 101);
    const json_t *in = json_object_get(body, "integrator");
    p->method = in ? api_string(in, "method", "rk8pd") : "rk8pd";
    p->opt.rtol = api_number(in, "rtol", 1e-10);
    p->opt.atol = api_number(in, "atol", 1e-12);
    p->opt.dt = api_number(in, "dt", 0);

    const json_t *stop = json_object_get(body, "stop");
    if (stop) {
        p->has_stop = 1;
        p->stop_axis = axis_of(api_string(stop, "coordinate", "z"));
        p->stop_value = api_number(stop, "crosses", 0);
        const char *d = api_string(stop, "direction", "either");
        p->stop_direction = strcmp(d, "decreasing") == 0   ? MECH_STOP_DECREASING
                            : strcmp(d, "increasing") == 0 ? MECH_STOP_INCREASING
                                                           : MECH_STOP_EITHER;
    }
    return 1;
}

static json_t *traj_op(struct api_call *c, const json_t *body)
{
    struct mech_force forces[MECH_TRAJECTORY_MAX_FORCES];
    struct mech_trajectory_problem p;
    if (!parse(c, body, &p, forces)) return NULL;

    /* Output buffers, owned here: samples x (t, position, velocity). */
    const size_t n = p.samples;
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
        (t && pos && vel) ? mech_trajectory_integrate(&p, &c->budget, &r, &e) : MECH_ENOMEM;
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

    json_t *d = json_object();
    json_object_set_new(d, "method", json_string(r.method));
    struct mech_ode_method_info mi = mech_ode_method_describe(mech_ode_method_find(r.method));
    if (mi.adaptive) {
        json_object_set_new(d, "rtol", api_real(c, p.opt.rtol));
        json_object_set_new(d, "atol", api_real(c, p.opt.atol));
    } else {
        json_object_set_new(d, "dt", api_real(c, p.opt.dt));
    }
    json_object_set_new(d, "order", json_integer(mi.order));
    json_object_set_new(d, "steps", json_integer(r.stats.steps));
    json_object_set_new(d, "rejected_steps", json_integer(r.stats.rejected_steps));
    json_object_set_new(d, "rhs_evaluations", json_integer(r.stats.rhs_evaluations));
    json_t *inv = json_object();
    json_object_set_new(inv, "name", json_string(r.invariant.name));
    json_object_set_new(inv, "conserved", json_boolean(r.invariant.conserved));
    json_object_set_new(inv, "initial", api_real(c, r.invariant.initial));
    json_object_set_new(inv, "final", api_real(c, r.invariant.final));
    json_object_set_new(inv, "max_relative_drift", api_real(c, r.invariant.max_relative_drift));
    json_object_set_new(d, "invariant", inv);
    json_object_set_new(res, "diagnostics", d);

    if (!res || !jp || !jv || !terms || !model || !d || !inv ||
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
