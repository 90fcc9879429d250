/* trajectory_request.h — the /v1/trajectory request, shared by
 * POST /v1/trajectory and POST /v1/compare (which embeds it): its JSON Schema
 * (as C string macros, so both routes' schemas are the same text), parsing
 * into a core problem, the `integrator` block (a method, an accuracy preset
 * or a target error), and the encoding of `diagnostics`. Not thread-shared:
 * each call owns its struct api_traj_request. */
#ifndef API_TRAJECTORY_REQUEST_H
#define API_TRAJECTORY_REQUEST_H

#include "earth_rotation.h"
#include "endpoint.h"
#include "mech/closed_form.h"
#include "mech/trajectory.h"

/* ---- schema fragments -------------------------------------------------------
 * Bounds keep every intermediate finite: lengths and speeds <= 1e15,
 * accelerations <= 1e15, gm, k, b, mass <= 1e30, rotation rates <= 1e6 rad/s,
 * t_end <= 1e15 s (the step budget and deadline bound the work). */
#define API_TRAJ_NUM(lo, hi) "{\"type\":\"number\",\"minimum\":" lo ",\"maximum\":" hi "}"
#define API_TRAJ_VEC3(desc)                                                                     \
    "{\"type\":\"array\",\"minItems\":3,\"maxItems\":3,\"items\":" API_TRAJ_NUM("-1e15", "1e15") \
    ",\"description\":\"" desc "\"}"
#define API_TRAJ_OBJ(req, props) \
    "{\"type\":\"object\",\"additionalProperties\":false,\"required\":[" req "],\"properties\":{" props "}}"

/* The method lists must match the registry (checked by tests/api/test_integrators_catalog.c). */
#define API_TRAJ_ADAPTIVE_METHODS "\"rk8pd\",\"rkck\",\"rkf45\",\"radau15\",\"msbdf\""
#define API_TRAJ_FIXED_METHODS \
    "\"euler\",\"symplectic_euler\",\"rk4\",\"verlet\",\"yoshida4\",\"yoshida6\",\"gauss4\",\"gauss6\",\"boris\",\"wisdom_holman\",\"wisdom_holman_corrected\""
#define API_TRAJ_ACCURACIES "\"draft\",\"balanced\",\"precise\",\"machine\""

#define API_TRAJ_RTOL \
    "\"rtol\":{\"type\":\"number\",\"minimum\":1e-15,\"maximum\":0.1,\"default\":1e-10}"
#define API_TRAJ_ATOL "\"atol\":{\"type\":\"number\",\"minimum\":0,\"maximum\":1e15,\"default\":1e-12}"
#define API_TRAJ_DT \
    "\"dt\":{\"type\":\"number\",\"exclusiveMinimum\":0,\"maximum\":1e15,\"description\":\"fixed step, s\"}"

/* With an accuracy or a target error: may the answer come from the scene's
 * closed form (where it has one: /v1/trajectory, /v1/rigid/rotate)? */
#define API_TRAJ_CLOSED_FORM                                                                   \
    "\"closed_form\":{\"type\":\"boolean\",\"default\":true,\"description\":\"true: when the " \
    "scene has an exact solution (Kepler, harmonic oscillator, uniform gravity with or without " \
    "linear drag, free particle; torque-free rigid body) the answer is evaluated from it, "      \
    "nothing integrated (diagnostics.selection.method closed_form); false: always integrate\"}"

/* One integrator block: a method with its settings, an accuracy preset or a target error. */
#define API_TRAJ_INTEGRATOR_SCHEMA                                                               \
    "{\"description\":\"a method (adaptive: rtol/atol; fixed-step: dt), or {\\\"accuracy\\\": "  \
    "preset}, or {\\\"target_error\\\": relative error}; default {\\\"accuracy\\\": "           \
    "\\\"balanced\\\"}. GET /v1/integrators lists the methods and presets.\",\"oneOf\":["       \
    API_TRAJ_OBJ("\"method\"", "\"method\":{\"enum\":[" API_TRAJ_ADAPTIVE_METHODS "]},"         \
                 API_TRAJ_RTOL "," API_TRAJ_ATOL) ","                                            \
    API_TRAJ_OBJ("\"method\",\"dt\"", "\"method\":{\"enum\":[" API_TRAJ_FIXED_METHODS "]},"     \
                 API_TRAJ_DT) ","                                                                \
    API_TRAJ_OBJ("\"accuracy\"", "\"accuracy\":{\"enum\":[" API_TRAJ_ACCURACIES "]},"        \
                 API_TRAJ_CLOSED_FORM) ","                                                       \
    API_TRAJ_OBJ("\"target_error\"",                                                            \
                 "\"target_error\":{\"type\":\"number\",\"minimum\":1e-15,\"maximum\":0.1,"      \
                 "\"description\":\"relative error on the positions and velocities\"},"          \
                 API_TRAJ_CLOSED_FORM)                                                           \
    "]}"

/* The top-level "dry_run" key of every time-evolution operation. */
#define API_DRY_RUN_PROP                                                                       \
    "\"dry_run\":{\"type\":\"boolean\",\"default\":false,\"description\":\"true: answer only "     \
    "diagnostics.selection (every candidate method with its predicted error, evaluations and "  \
    "CPU seconds from the calibrated model) without integrating: no samples, no pilot run\"}"

/* The trajectory request; `extra` is appended to its properties (a schema
 * that embeds it adds the envelope keys the route table adds at the root). */
#define API_TRAJ_REQUEST_SCHEMA API_TRAJ_REQUEST_SCHEMA_WITH("")
#define API_TRAJ_REQUEST_SCHEMA_WITH(extra)                                                   \
    "{\"type\":\"object\",\"additionalProperties\":false,"                                     \
    "\"required\":[\"particle\",\"t_end\"],"                                                   \
    "\"properties\":{"                                                                         \
    "\"particle\":" API_TRAJ_OBJ(                                                              \
        "\"mass\",\"position\",\"velocity\"",                                                  \
        "\"mass\":{\"type\":\"number\",\"exclusiveMinimum\":0,\"maximum\":1e30,"               \
        "\"description\":\"kg\"},"                                                             \
        "\"charge\":{\"type\":\"number\",\"minimum\":-1e15,\"maximum\":1e15,\"default\":0,"  \
        "\"description\":\"C (lorentz forces)\"},"                                            \
        "\"position\":" API_TRAJ_VEC3("m, frame axes") ","                                     \
        "\"velocity\":" API_TRAJ_VEC3("m/s, relative to the frame")) ","                       \
    "\"frame\":{\"description\":\"default {\\\"type\\\": \\\"inertial\\\"}\",\"oneOf\":["      \
    API_TRAJ_OBJ("\"type\"", "\"type\":{\"const\":\"inertial\"}") ","                          \
    API_TRAJ_OBJ("\"type\",\"omega\"",                                                         \
             "\"type\":{\"const\":\"rotating\"},"                                              \
             "\"omega\":{\"type\":\"array\",\"minItems\":3,\"maxItems\":3,\"items\":"          \
             API_TRAJ_NUM("-1e6", "1e6") ",\"description\":\"angular velocity of the "        \
             "frame about the origin at t = 0, rad/s, frame axes\"},"                          \
             "\"omega_dot\":{\"type\":\"array\",\"minItems\":3,\"maxItems\":3,\"items\":"      \
             API_TRAJ_NUM("-1e6", "1e6") ",\"description\":\"constant angular acceleration, "  \
             "rad/s^2: omega(t) = omega + omega_dot t; default 0\"},"                          \
             "\"acceleration\":" API_TRAJ_VEC3("constant acceleration of the origin, m/s^2, "  \
                                              "frame axes; default 0")) ","                  \
    API_TRAJ_OBJ("\"type\",\"latitude_deg\"",                                                  \
             "\"type\":{\"const\":\"earth\"},"                                                 \
             "\"latitude_deg\":{\"type\":\"number\",\"minimum\":-90,\"maximum\":90},"          \
             "\"omega_magnitude\":{\"type\":\"number\",\"minimum\":0,\"maximum\":1e6,"         \
             "\"default\":7.292115e-05,\"description\":\"rad/s, default IERS 2010\"},"        \
             API_SIDEREAL_DAY_PROP)                                                            \
    "]},"                                                                                      \
    "\"forces\":{\"type\":\"array\",\"maxItems\":32,\"items\":{\"oneOf\":["                    \
    API_TRAJ_OBJ("\"type\",\"g\"",                                                             \
             "\"type\":{\"const\":\"uniform_gravity\"},"                                       \
             "\"g\":" API_TRAJ_VEC3("gravitational acceleration, m/s^2 (e.g. [0, 0, -9.80665])")) "," \
    API_TRAJ_OBJ("\"type\",\"gm\"",                                                            \
             "\"type\":{\"const\":\"central_gravity\"},"                                       \
             "\"gm\":{\"type\":\"number\",\"exclusiveMinimum\":0,\"maximum\":1e30,"            \
             "\"description\":\"G M, m^3/s^2\"},"                                              \
             "\"center\":" API_TRAJ_VEC3("m, default [0, 0, 0]")) ","                          \
    API_TRAJ_OBJ("\"type\",\"k\"",                                                             \
             "\"type\":{\"const\":\"spring\"},"                                                \
             "\"k\":{\"type\":\"number\",\"minimum\":0,\"maximum\":1e30,\"description\":\"N/m\"}," \
             "\"anchor\":" API_TRAJ_VEC3("m, default [0, 0, 0]") ","                           \
             "\"rest_length\":{\"type\":\"number\",\"minimum\":0,\"maximum\":1e15,"            \
             "\"default\":0}") ","                                                             \
    API_TRAJ_OBJ("\"type\",\"b\"",                                                             \
             "\"type\":{\"const\":\"linear_drag\"},"                                           \
             "\"b\":{\"type\":\"number\",\"minimum\":0,\"maximum\":1e30,"                      \
             "\"description\":\"kg/s: F = -b v\"}") ","                                          \
    API_TRAJ_OBJ("\"type\"",                                                                  \
             "\"type\":{\"const\":\"lorentz\"},"                                              \
             "\"E\":" API_TRAJ_VEC3("electric field, V/m, frame axes; default 0") ","         \
             "\"B\":" API_TRAJ_VEC3("magnetic field, T, frame axes; default 0")) ","          \
    API_TRAJ_OBJ("\"type\",\"position\"",                                                     \
             "\"type\":{\"const\":\"third_body_tide\"},"                                      \
             "\"mass\":{\"type\":\"number\",\"exclusiveMinimum\":0,\"maximum\":1e40,"          \
             "\"description\":\"kg (GM = 6.67430e-11 M); give mass or gm\"},"                 \
             "\"gm\":{\"type\":\"number\",\"exclusiveMinimum\":0,\"maximum\":1e30,"            \
             "\"description\":\"G M, m^3/s^2; give mass or gm\"},"                           \
             "\"position\":" API_TRAJ_VEC3("m, fixed in the frame, not the origin"))          \
    "]}},"                                                                                     \
    "\"fictitious\":{\"description\":\"terms modelled in a rotating or earth frame: a list, " \
    "or \\\"auto\\\" (model only the terms that matter at the requested accuracy); "           \
    "default all four\",\"oneOf\":["                                                         \
    "{\"type\":\"array\",\"maxItems\":4,\"uniqueItems\":true,"                                \
    "\"items\":{\"enum\":[\"coriolis\",\"centrifugal\",\"euler\",\"translational\"]}},"        \
    "{\"const\":\"auto\"}]},"                                                                 \
    "\"t_end\":{\"type\":\"number\",\"exclusiveMinimum\":0,\"maximum\":1e15,\"description\":\"s\"}," \
    "\"samples\":{\"type\":\"integer\",\"minimum\":2,\"maximum\":100000,\"default\":101},"     \
    API_DRY_RUN_PROP ","                                                                       \
    "\"integrator\":" API_TRAJ_INTEGRATOR_SCHEMA ","                                           \
    "\"error_estimate\":{\"type\":\"boolean\",\"default\":false,\"description\":\"when the "   \
    "scene has no exact or first-order reference, run it again at a tighter setting "          \
    "(adaptive: rtol/100, atol/100, or radau15/rk8pd at round-off when that is beyond the "  \
    "method; fixed step: dt/2, Richardson-scaled) and report the difference\"},"          \
    "\"stop\":" API_TRAJ_OBJ(                                                                  \
        "\"coordinate\",\"crosses\"",                                                          \
        "\"coordinate\":{\"enum\":[\"x\",\"y\",\"z\"]},"                                       \
        "\"crosses\":" API_TRAJ_NUM("-1e15", "1e15") ","                                       \
        "\"direction\":{\"enum\":[\"decreasing\",\"increasing\",\"either\"],"                 \
        "\"default\":\"either\"}")                                                             \
    extra "}}"

/* A parsed trajectory request. p.forces points into forces: after copying
 * the struct, call api_traj_request_fix(). */
struct api_traj_request {
    struct mech_trajectory_problem p;
    struct mech_force forces[MECH_TRAJECTORY_MAX_FORCES];
    /* how p.method / p.opt were set */
    const json_t *requested; /* the integrator block (borrowed from the body) or NULL */
    int chosen;              /* 1: by an accuracy preset, a target error or the default */
    const char *accuracy;    /* preset name, or NULL */
    struct mech_trajectory_choice choice; /* when chosen */
    /* chosen, the block does not say "closed_form": false, and the scene has a
     * closed form (mech/closed_form.h): answer from it, integrate nothing */
    int closed_form;
    struct mech_closed_form_evidence evidence; /* filled by the closed-form run */
    int dry_run;             /* 1: "dry_run": true (select, predict, integrate nothing) */
    double cpu_s;            /* CPU seconds of the answer's integration (set by the caller) */
    /* "fictitious": "auto" */
    int auto_model;                       /* 1: the terms were chosen by the estimate */
    struct mech_trajectory_model model;   /* its evidence (when auto_model) */
};

/* The relative accuracy an integrator block asks for (NULL: balanced): a
 * preset's promise, target_error, an adaptive method's rtol (clamped to
 * [1e-15, 0.1]), or for a fixed step the balanced promise. */
double api_traj_block_target(const json_t *block);

/* "fictitious": "auto": choose p.fictitious with mech_trajectory_model_select
 * at `target`, spending c->budget's steps (what the first pass used is taken
 * off c->budget.max_steps). Returns 0 after recording an error. */
int api_traj_request_auto(struct api_call *c, struct api_traj_request *rq, double target,
                          const char *prefix);

/* model: {"mode": "auto"|"given", "terms": [...], "state": {...}, ...}.
 * New reference. */
json_t *api_traj_model(struct api_call *c, const struct api_traj_request *rq,
                       const struct mech_trajectory_result *r);

/* Parse a schema-validated trajectory body into rq (including its integrator
 * block and error_estimate). `prefix` is prepended to error pointers ("" or
 * "/request"). Returns 0 after recording an error in c. */
int api_traj_request_parse(struct api_call *c, const json_t *body, const char *prefix,
                           struct api_traj_request *rq);

/* Apply an integrator block (NULL: the default, accuracy "balanced") to a
 * parsed request: sets p.method and p.opt, directly or through
 * mech_trajectory_choose(). `pointer` names the block for errors. Returns 0
 * after recording an error. */
int api_traj_request_set_integrator(struct api_call *c, struct api_traj_request *rq,
                                    const json_t *block, const char *pointer);

/* Re-point rq->p.forces at rq->forces (after a struct copy). */
void api_traj_request_fix(struct api_traj_request *rq);

/* The settings actually used: {"method", "rtol", "atol"} or {"method", "dt"}. New reference. */
json_t *api_traj_settings(struct api_call *c, const struct mech_trajectory_problem *p);

/* diagnostics: method, settings, order, steps, rejected_steps, rhs_evaluations,
 * invariant (= invariants[0]), invariants, reference, error_estimate (if
 * asked), selection. New reference, or NULL on allocation failure. */
json_t *api_traj_diagnostics(struct api_call *c, const struct api_traj_request *rq,
                             const struct mech_trajectory_result *r);

/* diagnostics.selection (SELECTION.md): requested, settings, target_error,
 * scene_class, span, model, candidates, method, reason and, when r is not
 * NULL, achieved (the error evidence of r beside the prediction: exact
 * reference, the error estimate's second run, or none). New reference. */
json_t *api_traj_selection(struct api_call *c, const struct api_traj_request *rq,
                           const struct mech_trajectory_result *r);

/* {"dry_run": true, "diagnostics": {"selection", "steps": 0, "rhs_evaluations": 0}}
 * for a request parsed with dry_run: nothing integrated. New reference. */
json_t *api_traj_dry_run(struct api_call *c, const struct api_traj_request *rq);

/* One invariant as JSON. New reference. */
json_t *api_traj_invariant(struct api_call *c, const struct mech_trajectory_invariant *inv);

#endif
