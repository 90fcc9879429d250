/* trajectory_request.h — the /v1/trajectory request, shared by
 * POST /v1/trajectory and POST /v1/compare (which embeds it; the request
 * schema is in api/ops/frames/trajectory.json): its parsing into a core
 * problem, the `integrator` block (a method, an accuracy preset
 * or a target error), and the encoding of `diagnostics`. Not thread-shared:
 * each call owns its struct api_traj_request. */
#ifndef API_TRAJECTORY_REQUEST_H
#define API_TRAJECTORY_REQUEST_H

#include "request/earth_rotation.h"
#include "run/endpoint.h"
#include "mech/frames/closed_form.h"
#include "mech/frames/trajectory.h"
#include "mech/frames/trajectory_plan.h"

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
     * closed form (mech/frames/closed_form.h): answer from it, integrate nothing */
    int closed_form;
    struct mech_closed_form_evidence evidence; /* filled by the closed-form run */
    int dry_run;             /* 1: "dry_run": true (select, predict, integrate nothing) */
    double cpu_s;            /* CPU seconds of the answer's integration (set by the caller) */
    /* "fictitious": "auto" */
    int auto_model;                       /* 1: the terms were chosen by the estimate */
    struct mech_trajectory_model model;   /* its evidence (when auto_model) */
    double model_target;     /* the relative accuracy the model is chosen for */
    /* "relativity" (api/request/trajectory_relativity.h) */
    int rel_auto;                         /* 1: "auto" (the default) */
    unsigned rel_on, rel_off;             /* MECH_RELATIVITY_* forced in / out */
    struct mech_relativity_model rel_model; /* the decision (rel_model.judged: made) */
    int rel_rerun;                        /* 1: the answer is a second run */
    const char *rel_first_method;         /* the first run's method (static) */
    struct mech_ode_stats rel_first_stats;
};

/* The relative accuracy an integrator block asks for (NULL: balanced): a
 * preset's promise, target_error, an adaptive method's rtol (clamped to
 * [1e-15, 0.1]), or for a fixed step the balanced promise. */
double api_traj_block_target(const json_t *block);

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
